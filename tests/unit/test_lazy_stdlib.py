"""The rest of the standard library, mounted on first use (workbook_sandbox/lazy_stdlib.py).

A fake "rest" zip holds a package and a module; the finder must fetch it only
when an import names one of them, exactly once, and then let the normal import
machinery load them (a package's submodules included).
"""

from __future__ import annotations

import io
import sys
import zipfile

import pytest

from workbook_sandbox import lazy_stdlib


@pytest.fixture
def rest(tmp_path, monkeypatch):
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w") as z:
        z.writestr("wbtest_rest_mod.py", "VALUE = 42\n")
        z.writestr("wbtest_rest_pkg/__init__.py", "")
        z.writestr("wbtest_rest_pkg/sub.py", "NAME = 'sub'\n")
    calls = []

    def fetch(url):
        calls.append(url)
        return buf.getvalue()

    names = {"wbtest_rest_mod", "wbtest_rest_pkg", "wbtest_rest_pkg.sub"}
    finder = lazy_stdlib.RestOfStdlib(names, "https://example.invalid/rest.zip", fetch, dest=str(tmp_path / "rest.zip"))
    monkeypatch.setattr(sys, "meta_path", [*sys.meta_path, finder])
    monkeypatch.setattr(sys, "path", list(sys.path))
    yield finder, calls
    for name in names:
        sys.modules.pop(name, None)


def test_an_import_of_the_rest_fetches_it_once(rest):
    finder, calls = rest
    assert not finder.mounted
    import wbtest_rest_mod
    from wbtest_rest_pkg import sub

    assert wbtest_rest_mod.VALUE == 42 and sub.NAME == "sub"
    assert calls == ["https://example.invalid/rest.zip"] and finder.mounted


def test_other_misses_do_not_fetch(rest):
    finder, calls = rest
    with pytest.raises(ImportError):
        import wbtest_no_such_module  # noqa: F401
    assert calls == [] and not finder.mounted


def test_a_failed_fetch_is_an_import_error_with_a_reason(rest):
    finder, _ = rest
    finder.fetch = lambda url: (_ for _ in ()).throw(OSError("offline"))
    with pytest.raises(ImportError, match=r"could not be loaded .*offline"):
        import wbtest_rest_mod  # noqa: F401
    assert not finder.mounted



def test_a_run_needs_the_rest_when_it_imports_from_it_or_loads_a_package(rest):
    """The sandbox mounts the rest ahead of a run (so its time limit never pays for the download)
    exactly when the run imports a module of the rest, or a package of the lock (NumPy, whose own
    imports reach into the rest); not for the core, a builtin, a typo, or once mounted."""
    finder, calls = rest
    assert lazy_stdlib.needs(["wbtest_rest_mod"])
    assert lazy_stdlib.needs(["math", "numpy"], ["numpy"])
    assert not lazy_stdlib.needs(["math", "json", "no_such_module"], ["numpy"])
    assert not lazy_stdlib.needs([])
    finder.mount()
    assert not lazy_stdlib.needs(["wbtest_rest_mod"], ["numpy"]) and calls == ["https://example.invalid/rest.zip"]


def test_a_typed_array_from_the_page_is_written_as_bytes(rest):
    """In the sandbox the finder's fetch is the page's, and returns a JS typed array (to_bytes)."""
    finder, _ = rest
    data = finder.fetch("x")

    class TypedArray:
        def to_bytes(self):
            return data

    finder.fetch = lambda url: TypedArray()
    import wbtest_rest_mod

    assert wbtest_rest_mod.VALUE == 42
