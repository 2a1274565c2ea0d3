#!/usr/bin/env python3
"""The licences of the workbook and the notices of everything it ships from others.

The site (and both SCORM packages, which zip it) carries files that other projects wrote:
Pyodide and the CPython it runs, the packages of Pyodide's lock that learners may import
(NumPy), KaTeX, the npm packages esbuild bundles into the page's JavaScript (CodeMirror and
its parts), and mkdocs-material's theme files with what its own bundles hold. Nothing here
is typed by hand: each component, its version, its licence and its licence text are read at
build time from what the build itself used:

- Pyodide: ``node_modules/pyodide/package.json``; its licence (MPL-2.0) ships without its text
  in that package, so the text is the Mozilla Public License 2.0 file of a Python package of
  the locks that carries the same licence (found by its first line);
- CPython's standard library: ``LICENSE.txt`` of the Python 3.12 that builds the site (the
  Python Pyodide runs), the version from ``pyodide-lock.json``;
- each wheel of ``docs/assets/vendor/pyodide`` that the lock names (NumPy): its METADATA and
  every licence file inside it;
- KaTeX and every npm package the bundles hold: the package's own ``package.json`` and LICENSE
  file; which packages a bundle holds is read from its source map;
- mkdocs-material: its installed distribution (METADATA, licence file, and the theme's files);
  the packages its minified bundles hold are named from their source maps; the Material Design
  Icons (the logo drawn in every page) from the licence the theme ships beside them.

``docs/hooks/notices_page.py`` puts the result on the site at ``notices/`` (never committed);
``unexplained(site)`` names every shipped file that is neither the workbook's own nor covered
by a notice (``tests/unit/test_notices.py``). ``python scripts/notices.py [SITE]`` prints the
page's Markdown, or with ``--check SITE`` lists the files without a notice (status 1 if any).
"""

from __future__ import annotations

import email.parser
import fnmatch
import html
import importlib.util
import json
import re
import sys
import sysconfig
import zipfile
from dataclasses import dataclass, field
from functools import cache
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"
NODE = ROOT / "node_modules"
VENDOR = DOCS / "assets" / "vendor"
DIST = DOCS / "assets" / "dist"
PAGE = "notices.md"  # the page's place in docs/ (generated; built at notices/)
LICENCE_FILE = re.compile(r"^(LICEN[CS]E|COPYING|NOTICE)([.-].*)?$", re.I)


@dataclass
class Component:
    """One third-party work the site ships: what it is, its licence, and the shipped files it is in."""

    name: str
    version: str
    licence: str
    texts: list[tuple[str, str]]  # (where the text comes from, the text)
    covers: list[str] = field(default_factory=list)  # site paths (fnmatch patterns) that carry it
    holds: list[str] = field(default_factory=list)  # packages bundled inside its files (from source maps)
    note: str = ""

    @property
    def anchor(self) -> str:
        return re.sub(r"[^a-z0-9]+", "-", self.name.lower()).strip("-")


def _read(path: Path) -> str:
    return path.read_text(encoding="utf-8", errors="replace").strip("\n")


def _licence_files(folder: Path) -> list[Path]:
    return sorted(p for p in folder.iterdir() if p.is_file() and LICENCE_FILE.match(p.name))


def _npm(folder: Path, covers: list[str]) -> Component:
    meta = json.loads((folder / "package.json").read_text(encoding="utf-8"))
    licence = meta.get("license") or (meta.get("licenses") or [{}])[0].get("type", "")
    texts = [(f"node_modules/{meta['name']}/{p.name}", _read(p)) for p in _licence_files(folder)]
    return Component(meta["name"], meta.get("version", ""), licence, texts, covers)


def _site_packages() -> Path:
    return Path(sysconfig.get_paths()["purelib"])


@cache
def _mpl2_text() -> tuple[str, str] | None:
    """The Mozilla Public License 2.0, from a distribution of the locks that ships its text."""
    for path in sorted(_site_packages().glob("*.dist-info/**/*")):
        if path.is_file() and LICENCE_FILE.match(path.name):
            text = _read(path)
            if text.startswith("Mozilla Public License Version 2.0"):
                return (f"the MPL 2.0 text as {path.parent.relative_to(_site_packages())} ships it", text)
    return None


def pyodide() -> Component:
    comp = _npm(NODE / "pyodide", ["assets/vendor/pyodide/pyodide.js", "assets/vendor/pyodide/pyodide.asm.js",
                                   "assets/vendor/pyodide/pyodide.asm.wasm", "assets/vendor/pyodide/pyodide-lock*.json",
                                   "assets/vendor/pyodide/*.snapshot.gz"])
    if not comp.texts and comp.licence == "MPL-2.0" and _mpl2_text():
        comp.texts.append(_mpl2_text())  # type: ignore[arg-type]
    comp.note = ("The WebAssembly interpreter (pyodide.asm.wasm and .js) is Pyodide's build of CPython with "
                 "Emscripten's runtime; the memory snapshots are that interpreter's memory after start-up.")
    return comp


def cpython() -> Component:
    lock = json.loads((VENDOR / "pyodide" / "pyodide-lock.json").read_text(encoding="utf-8"))
    # The licence of the Python 3.12 that builds the site (Debian keeps it under /usr/share/doc).
    version = f"python{sys.version_info[0]}.{sys.version_info[1]}"
    places = [Path(sysconfig.get_paths()["stdlib"]) / "LICENSE.txt", *(Path("/usr/share/doc") / name / "copyright"
              for name in (version, f"{version}-minimal", f"lib{version}-stdlib"))]
    texts = [(f"{place} (the Python {sys.version.split()[0]} that builds the site)", _read(place))
             for place in places if place.is_file()][:1]
    return Component("CPython (the Python interpreter and its standard library)", lock["info"]["python"],
                     "PSF-2.0", texts,
                     ["assets/vendor/pyodide/python_stdlib.*.zip", "assets/vendor/pyodide/pyodide.asm.wasm",
                      "assets/vendor/pyodide/pyodide.asm.js", "assets/vendor/pyodide/*.snapshot.gz"])


def _wheel_licence(meta) -> str:
    """A wheel's licence as its METADATA names it: the expression, a short License field, or the classifier."""
    if meta.get("License-Expression"):
        return meta["License-Expression"]
    field_text = (meta.get("License") or "").strip()
    if field_text and "\n" not in field_text and len(field_text) < 40 and not field_text.startswith("Copyright"):
        return field_text
    classifiers = [c.split("::")[-1].strip() for c in meta.get_all("Classifier") or [] if c.startswith("License ::")]
    return ", ".join(classifiers)


def lock_packages() -> list[Component]:
    """Every wheel of Pyodide's lock that the site ships, but the workbook's own."""
    lock = json.loads((VENDOR / "pyodide" / "pyodide-lock.json").read_text(encoding="utf-8"))
    out = []
    for entry in sorted(lock["packages"].values(), key=lambda e: e["name"]):
        wheel = VENDOR / "pyodide" / entry["file_name"]
        if entry["name"] == "robotics-workbook" or not wheel.exists():
            continue
        with zipfile.ZipFile(wheel) as zf:
            meta_name = next(n for n in zf.namelist() if n.endswith(".dist-info/METADATA"))
            meta = email.parser.Parser().parsestr(zf.read(meta_name).decode("utf-8"))
            texts = [(f"{entry['file_name']}: {n}", zf.read(n).decode("utf-8", "replace").strip("\n"))
                     for n in sorted(zf.namelist()) if LICENCE_FILE.match(n.rsplit("/", 1)[-1])]
        licence = _wheel_licence(meta)
        out.append(Component(meta["Name"], meta["Version"], licence, texts, [f"assets/vendor/pyodide/{wheel.name}"]))
    return out


def katex() -> Component:
    return _npm(NODE / "katex", ["assets/vendor/katex/*"])


def _package_of(source: Path) -> Path | None:
    """The npm package folder a bundled source file belongs to (the innermost node_modules/NAME)."""
    parts = source.parts
    if "node_modules" not in parts:
        return None
    at = len(parts) - 1 - parts[::-1].index("node_modules")
    name = parts[at + 1:at + 3] if parts[at + 1].startswith("@") else parts[at + 1:at + 2]
    return Path(*parts[:at + 1], *name)


def _map_packages(source_map: Path) -> set[Path]:
    data = json.loads(source_map.read_text(encoding="utf-8"))
    base = (source_map.parent / data.get("sourceRoot", "")).resolve()
    found = set()
    for src in data.get("sources", []):
        package = _package_of(Path((base / src).as_posix().replace("/./", "/")).resolve())
        if package is not None:
            found.add(package)
    return found


def bundled_npm() -> list[Component]:
    """Each npm package the page's bundles hold, with the bundle files (and their maps) that hold it."""
    holders: dict[Path, list[str]] = {}
    for source_map in sorted(DIST.rglob("*.js.map")):
        shipped = "assets/dist/" + source_map.relative_to(DIST).as_posix()[: -len(".map")]
        for package in _map_packages(source_map):
            holders.setdefault(package, []).extend([shipped, shipped + ".map"])
    return sorted((_npm(package, files) for package, files in holders.items()), key=lambda c: c.name)


def _material_dir() -> Path:
    """Where the theme the build uses (mkdocs-material) is installed."""
    spec = importlib.util.find_spec("material")
    assert spec is not None and spec.origin, "mkdocs-material is not installed (make installs it)"
    return Path(spec.origin).parent


def theme_files() -> list[str]:
    """The site paths of the theme's own files (what MkDocs copies from the theme's templates)."""
    assets = _material_dir() / "templates"
    return sorted(p.relative_to(assets).as_posix() for p in (assets / "assets").rglob("*") if p.is_file())


def material() -> list[Component]:
    dist = next(_site_packages().glob("mkdocs_material-*.dist-info"))
    meta = email.parser.Parser().parsestr((dist / "METADATA").read_text(encoding="utf-8"))
    texts = [(f"{dist.name}/{p.relative_to(dist).as_posix()}", _read(p)) for p in sorted(dist.rglob("*"))
             if p.is_file() and LICENCE_FILE.match(p.name)]
    holds = set()
    for source_map in sorted((_material_dir() / "templates" / "assets").rglob("*.js.map")):
        holds |= {p.name if not p.parent.name.startswith("@") else f"{p.parent.name}/{p.name}"
                  for p in _map_packages(source_map)}
    theme = Component("mkdocs-material (the site's theme)", meta["Version"], meta.get("License-Expression", ""),
                      texts, theme_files(), sorted(holds))
    theme.note = ("Every page is rendered through the theme's templates. Its minified bundles also hold the "
                  "packages listed here, named from the theme's source maps; the theme's distribution does not "
                  "carry their licence texts, which their own projects publish. The search's word splitters "
                  "and stemmers for other languages (assets/javascripts/lunr/) come with the theme and are "
                  "never loaded by this English-only site.")
    icons = _material_dir() / "templates" / ".icons" / "material"
    texts = [(f"mkdocs-material's .icons/material/{p.name}", _read(p)) for p in _licence_files(icons)]
    logo = Component("Material Design Icons (the logo)", "", texts[0][1].split("\n")[0].strip() if texts else "", texts)
    logo.note = "The robot logo in every page's header is the icon material/robot-industrial, drawn inline."
    return [theme, logo]


def components() -> list[Component]:
    return [pyodide(), cpython(), *lock_packages(), katex(), *bundled_npm(), *material()]


# ---- The workbook's own files --------------------------------------------------------------
GENERATED = ("sitemap.xml", "sitemap.xml.gz", "sw.js", "search/search_index.json", "search/search_index.docs.json",
             "assets/exercises.json",
             "404.html", "notices/index.html", "assets/vendor/pyodide/robotics_workbook-*.whl",
             "assets/vendor/pyodide/workbook.compiled*.zip",  # the grading package compiled (split_stdlib.py)
             "assets/dist/*", "assets/dist/chunks/*",
             "manifest.webmanifest", "assets/icons/*")  # the app (docs/hooks/app.py: icons drawn in code)
# Built by the workbook's scripts from the runtime's files (the notices of those are above): the
# standard library split and compiled, the snapshots, the lock rewritten; the sandbox's zip also
# holds the workbook's own sandbox package.
DERIVED = ("assets/vendor/pyodide/python_stdlib.*.zip", "assets/vendor/pyodide/*.snapshot.gz",
           "assets/vendor/pyodide/pyodide-lock*.json")


def ours(path: str) -> bool:
    """Whether the site file ``path`` (relative to the site root) is the workbook's own work."""
    if any(fnmatch.fnmatchcase(path, p) for p in GENERATED + DERIVED):
        return True
    if path.startswith(("assets/vendor/", "assets/javascripts/", "assets/stylesheets/")):
        return False
    if path.endswith("index.html"):  # a page built from our Markdown
        stem = path[: -len("index.html")].rstrip("/")
        return not stem or (DOCS / f"{stem}.md").exists() or (DOCS / stem / "index.md").exists()
    return (DOCS / path).is_file()  # copied from docs/ as it is (the stylesheets, the images)


def covering(path: str, comps: list[Component]) -> list[Component]:
    return [c for c in comps if any(fnmatch.fnmatchcase(path, p) for p in c.covers)]


def shipped(site: Path) -> list[str]:
    return sorted(p.relative_to(site).as_posix() for p in site.rglob("*") if p.is_file() and not p.name.startswith("."))


def unexplained(site: Path, comps: list[Component] | None = None) -> list[str]:
    """Every file the site ships that is not the workbook's own and that no notice covers."""
    comps = components() if comps is None else comps
    return [path for path in shipped(site) if not covering(path, comps) and not ours(path)]


# ---- The page ---------------------------------------------------------------------------------
def _fence(text: str) -> str:
    """A licence text as preformatted HTML: not a code block, which the theme would give a copy
    button in a landmark of its own per block (dozens of unnamed landmarks on one page)."""
    return f'<pre class="wb-licence-text">{html.escape(text, quote=False)}</pre>'



def _own_licences() -> str:
    text = _read(ROOT / "LICENSE-text.md").split("\n", 1)[1].strip("\n")
    text = re.sub(r"^## ", "### ", text, flags=re.M).replace("[LICENSE](LICENSE)", "the MIT licence (above)")
    return ("## The workbook's own licences\n\n"
            "### The code: the MIT licence\n\n" + _fence(_read(ROOT / "LICENSE")) + "\n\n"
            "### The text: Creative Commons Attribution 4.0 International\n\n" + text)


def markdown(comps: list[Component] | None = None) -> str:
    comps = components() if comps is None else comps
    out = ["---", "search:", "  exclude: true", "---", "", "# Licences and third-party notices", "",
           "The Robotics Math Workbook's code is under the MIT licence and its text under Creative Commons "
           "Attribution 4.0. The site also ships the work of the projects below, each under its own licence, "
           "whose text follows it. This page is written by the build from the files it used "
           "(`scripts/notices.py`), so it lists exactly what this copy of the site carries.", "",
           _own_licences(), "", "## Third-party software", "",
           "| component | version | licence |", "| --- | --- | --- |"]
    out += [f"| [{c.name}](#{c.anchor}) | {c.version} | {c.licence or 'see its text'} |" for c in comps]
    for c in comps:
        out += ["", f"### {c.name} {{#{c.anchor}}}", "", f"Version {c.version}, licence {c.licence}." if c.version
                else f"Licence {c.licence}."]
        if c.note:
            out += ["", c.note]
        if c.holds:
            out += ["", "Its files also hold: " + ", ".join(f"`{h}`" for h in c.holds) + "."]
        files = sorted(c.covers)
        if files:
            out += ["", "Shipped in: " + ", ".join(f"`{p}`" for p in files[:12])
                    + (f" and {len(files) - 12} more of its files." if len(files) > 12 else ".")]
        for where, text in c.texts:
            out += ["", f"From {where}:", "", _fence(text)]
        if not c.texts:
            out += ["", "Its package ships no licence text."]
    return "\n".join(out) + "\n"


def main(argv: list[str]) -> int:
    if argv[:1] == ["--check"]:
        site = Path(argv[1]) if len(argv) > 1 else ROOT / "site"
        missing = unexplained(site)
        for path in missing:
            print(f"{path}: a third-party file without a notice (scripts/notices.py)")
        return 1 if missing else 0
    sys.stdout.write(markdown())
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
