"""The rest of the standard library, mounted on first use (workbook/lazy_stdlib.py).

A fake "rest" zip holds a package and a module; the finder must fetch it only
when an import names one of them, exactly once, and then let the normal import
machinery load them (a package's submodules included).
"""

from __future__ import annotations

import io
import sys
import zipfile

import pytest

from workbook import lazy_stdlib


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

