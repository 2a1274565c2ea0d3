"""The rest of the standard library, fetched the first time it is needed (in the page).

Both workers start Pyodide with a *core* standard library: the grader's holds the
modules Pyodide's start-up and the grader import, and the grading package
(``scripts/split_stdlib.py`` writes it from the official ``python_stdlib.zip``);
the sandbox's is the same core without the grading package
(``scripts/sandbox_files.py``). Both hold this module, in ``workbook_sandbox``,
the one package they share. Everything else is in a second zip, the *rest*,
which grading never needs and a learner's code rarely does (``import
statistics``, or NumPy's loader). ``install`` puts a finder at the end of
``sys.meta_path``: when an import names a module of the rest (its names are
listed in the core zip, so a typo costs nothing), the rest is fetched once,
written next to the core and mounted, and the import goes on as usual. The
sandbox writes it there itself ahead of a Build run whose imports need it
(:func:`needs`, then :func:`mount`), so a run's time limit never pays for the
download; the finder's own fetch is for imports no one saw coming
(``__import__``).

A chapter's page may start the grader from a compiled core that holds only its
own part of the grading package (``scripts/split_stdlib.py``); the names of the
package's other modules are listed in that core, and :func:`install_package_rest`
puts a second finder for them, which mounts the sources' core (the whole package)
the same way on first use.

Natively nothing is installed; the tests drive the finder with a fake fetch.
"""

from __future__ import annotations

import importlib.machinery
import sys
import zipfile
from collections.abc import Callable, Iterable

INDEX = "stdlib-rest.txt"  # in the core zip: one module name per line
REST = "/lib/python_stdlib.rest.zip"
PACKAGE_INDEX = "package-rest.txt"  # in a chapter's compiled core: the grading package's modules it leaves out
SOURCES = "/lib/python_stdlib.core.zip"  # where the sources' core (the whole package) is written


def _fetch_sync(url: str) -> bytes:
    """GET ``url`` synchronously (allowed in a Web Worker) and return its bytes."""
    from js import XMLHttpRequest  # Pyodide only

    request = XMLHttpRequest.new()
    request.open("GET", url, False)
    request.responseType = "arraybuffer"
    request.send(None)
    if request.status != 200:
        raise OSError(f"HTTP {request.status}")
    return request.response.to_bytes()


class RestOfStdlib:
    """A meta path finder for the modules in the rest of the standard library."""

    what = "the part of Python's standard library that is loaded on first use"

    def __init__(self, names: set[str], url: str | None, fetch: Callable[[str], bytes] = _fetch_sync,
                 dest: str = REST) -> None:
        self.names, self.url, self.fetch, self.dest = names, url, fetch, dest
        self.mounted = False

    def mount(self) -> None:
        """Make the rest importable: fetched here, unless the page already wrote it to ``dest``.
        A package's submodules in the rest are found by ``find_spec``, which adds the rest's folder
        to the package's ``__path__``."""
        if self.mounted:
            return
        if not _exists(self.dest):
            if not self.url:
                raise ImportError("the rest of the standard library has no address")
            try:
                data = self.fetch(self.url)
            except Exception as err:  # offline without the stored copy, a server error, ...
                raise ImportError(f"this module is in {self.what}, and it could not be loaded ({err})") from None
            with open(self.dest, "wb") as f:
                f.write(data.to_bytes() if hasattr(data, "to_bytes") else data)  # a JS typed array, in the sandbox
        sys.path.append(self.dest)
        self.mounted = True
        importlib.invalidate_caches()

    def modules_of(self, package: str) -> list[str]:
        """The modules (not packages) of ``package`` this finder imports, by their own names."""
        return [name.rpartition(".")[2] for name in self.names if name.rpartition(".")[0] == package
                and not any(other.startswith(name + ".") for other in self.names)]

    def find_spec(self, fullname: str, path=None, target=None):
        if fullname not in self.names:
            return None
        self.mount()
        parent, _, _ = fullname.rpartition(".")
        if parent:
            package = sys.modules.get(parent)
            search = list(getattr(package, "__path__", []) or [])
            folder = f"{self.dest}/{parent.replace('.', '/')}"
            if folder not in search:
                search.append(folder)
                if package is not None and isinstance(getattr(package, "__path__", None), list):
                    package.__path__.append(folder)
        else:
            search = [self.dest]
        return importlib.machinery.PathFinder.find_spec(fullname, search, target)


class RestOfPackage(RestOfStdlib):
    """A meta path finder for the grading package's modules that a chapter's compiled core leaves out."""

    what = "the part of the grader that is loaded on first use"


def _core_index(index: str = INDEX) -> set[str]:
    """The names listed in ``index`` of the core (the first zip on ``sys.path``)."""
    for entry in sys.path:
        if entry.endswith(".zip"):
            try:
                with zipfile.ZipFile(entry) as z:
                    return set(z.read(index).decode("utf-8").split())
            except (OSError, KeyError, zipfile.BadZipFile):
                continue
    return set()


def finder() -> RestOfStdlib | None:
    return next((f for f in sys.meta_path if type(f) is RestOfStdlib), None)


def install(url: str | None, names: set[str] | None = None,
            fetch: Callable[[str], bytes] = _fetch_sync) -> RestOfStdlib:
    """Add the finder (once; a second call updates the address: the snapshot has it installed with none).
    Returns it."""
    found = finder()
    if found is None:
        found = RestOfStdlib(_core_index() if names is None else names, url, fetch)
        sys.meta_path.append(found)
    found.url = url
    return found


def install_package_rest(url: str, fetch: Callable[[str], bytes] = _fetch_sync) -> bool:
    """When the core leaves out modules of the grading package (it lists them), add a finder that
    imports them from the sources' core at ``url``, fetched on first use. Whether it did."""
    names = _core_index(PACKAGE_INDEX)
    if not names:
        return False
    if not any(isinstance(f, RestOfPackage) for f in sys.meta_path):
        sys.meta_path.append(RestOfPackage(names, url, fetch, dest=SOURCES))
    return True


def needs(names: Iterable[str], packages: Iterable[str] = ()) -> bool:
    """Whether a run that imports these top-level modules needs the rest first (not yet mounted):
    one of them is in the rest, or is one of ``packages`` (what the lock's packages provide:
    NumPy imports modules of the rest as it loads)."""
    found = finder()
    if found is None or found.mounted:
        return False
    loaded = set(packages)
    return any(name in found.names or name in loaded for name in names)


def mount() -> None:
    """The page has written the rest to ``REST``: mount it now."""
    found = finder()
    if found is not None:
        found.mount()


def _exists(path: str) -> bool:
    try:
        with open(path, "rb"):
            return True
    except OSError:
        return False
