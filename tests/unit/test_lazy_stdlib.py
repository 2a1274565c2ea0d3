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


def test_a_chapter_core_lists_the_package_s_other_modules_and_they_import_and_register(tmp_path, monkeypatch):
    """A chapter's compiled core leaves out the grading package's other modules and lists them
    (scripts/split_stdlib.py); install_package_rest puts a finder for them, which fetches the sources'
    core on first use. The registries see those modules before they are fetched (registry.py asks the
    finder, ``modules_of``), so another chapter's exercise is known, and grades, from a chapter's page."""
    from workbook import registry

    core = tmp_path / "core.zip"
    with zipfile.ZipFile(core, "w") as z:
        z.writestr("wbtest_pkg/__init__.py", "")
        z.writestr("wbtest_pkg/ch0_here.py", "EXERCISES = ('ch0_here',)\n")
        z.writestr(lazy_stdlib.PACKAGE_INDEX, "wbtest_pkg.ch5_there\nwbtest_pkg.ch9_far\n")
    sources = io.BytesIO()
    with zipfile.ZipFile(sources, "w") as z:
        z.writestr("wbtest_pkg/__init__.py", "")
        for name in ("ch0_here", "ch5_there", "ch9_far"):
            z.writestr(f"wbtest_pkg/{name}.py", f"EXERCISES = ({name!r},)\n")
    calls = []
    monkeypatch.setattr(sys, "path", [str(core), *sys.path])
    monkeypatch.setattr(sys, "meta_path", list(sys.meta_path))
    monkeypatch.setattr(lazy_stdlib, "SOURCES", str(tmp_path / "sources.zip"))
    try:
        assert lazy_stdlib.install_package_rest("https://example.invalid/core.zip",
                                                fetch=lambda url: calls.append(url) or sources.getvalue())
        assert lazy_stdlib.finder() is None  # the standard library's finder is another one
        chapters = registry.Registry("wbtest_pkg", "EXERCISES", "chapter module", prefix="ch", own="")
        assert chapters.names() == ["ch0-here", "ch5-there", "ch9-far"] and calls == []
        assert chapters.get("ch0-here") == ("ch0_here",) and calls == []
        assert chapters.get("ch5-there") == ("ch5_there",) and chapters.get("ch9-far") == ("ch9_far",)
        assert calls == ["https://example.invalid/core.zip"]  # once
    finally:
        for name in [m for m in sys.modules if m.split(".")[0] == "wbtest_pkg"]:
            sys.modules.pop(name)
        registry._found.cache_clear()


def test_a_core_that_leaves_nothing_out_installs_no_package_finder(monkeypatch):
    monkeypatch.setattr(sys, "meta_path", list(sys.meta_path))
    assert not lazy_stdlib.install_package_rest("https://example.invalid/core.zip")
    assert not any(isinstance(f, lazy_stdlib.RestOfPackage) for f in sys.meta_path)


def test_a_finder_installed_without_an_address_gets_one_later(monkeypatch):
    """The grader's snapshot holds the finder installed with no address (scripts/build_snapshot.mjs: the
    site's address is not known at build time); the worker gives it one after the restore. Until then a
    module of the rest is an ImportError that says why."""
    monkeypatch.setattr(sys, "meta_path", [f for f in sys.meta_path if type(f) is not lazy_stdlib.RestOfStdlib])
    found = lazy_stdlib.install(None, names={"wbtest_rest_nowhere"}, fetch=lambda url: b"")
    with pytest.raises(ImportError, match="no address"):
        import wbtest_rest_nowhere  # noqa: F401
    assert lazy_stdlib.install("https://example.invalid/rest.zip") is found and found.url.endswith("rest.zip")
    assert sum(type(f) is lazy_stdlib.RestOfStdlib for f in sys.meta_path) == 1
