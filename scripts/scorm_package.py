"""The workbook as SCORM packages any LMS can host: ``make scorm``.

    python scripts/scorm_package.py [--site site] [--out dist]

writes ``dist/robotics-workbook-scorm12.zip`` and ``dist/robotics-workbook-scorm2004.zip``
from the built (and tested) ``site/``: the whole site, Pyodide and the grader
included, with an ``imsmanifest.xml`` (``scripts/scorm/imsmanifest-*.xml.j2``) at
the top. One SCO per chapter, each launched by a small page of its own
(``launch/chNN.html``, from ``scripts/scorm/launch.html.j2``) that holds the launch's
one LMS session and shows the workbook's pages in a frame (docs/assets/js/lms/launch.js).
Every path is relative; the pages fetch nothing from elsewhere (their
Content-Security-Policy says so).

With ``--chapters``, also one package per chapter and version, with that chapter's
SCO alone (``dist/chapters/robotics-workbook-chNN-scorm12.zip``...): for an LMS that
gives a whole package one grade item (Moodle: one per SCORM activity).

Changes to the copy, none to ``site/``:

- links to a folder (``../04-ekf-update/``) name its ``index.html``: an LMS serves
  the package's files, not folder indexes (the pages' inline scripts, which the
  Content-Security-Policy allows by their hash, are left as they are);
- the pages' ``<link rel="canonical">`` (the build host's address) is left out;
- ``sw.js`` stays (the page does not register it inside an LMS frame).
"""

from __future__ import annotations

import argparse
import json
import re
import shutil
import sys
import zipfile
from pathlib import Path
from urllib.parse import quote

from jinja2 import Environment, FileSystemLoader

ROOT = Path(__file__).resolve().parent.parent
TEMPLATES = Path(__file__).resolve().parent / "scorm"
VERSIONS = {"1.2": "robotics-workbook-scorm12.zip", "2004": "robotics-workbook-scorm2004.zip"}
TITLE = "Robotics Math Workbook"
IDENTIFIER = "robotics-math-workbook"
SCRIPT = re.compile(r"<script\b.*?</script\s*>", re.S | re.I)
HREF = re.compile(r'(\bhref=")([^"]*)(")', re.I)
CANONICAL = re.compile(r'<link\b[^>]*\brel="canonical"[^>]*>\n?', re.I)
# The launchers' policy: the site's (docs/hooks/csp.py) without inline scripts, with the frame of the package's pages.
LAUNCH_POLICY = ("default-src 'self'; script-src 'self'; frame-src 'self'; style-src 'self' 'unsafe-inline'; "
                 "img-src 'self' data:; object-src 'none'; base-uri 'self'; form-action 'self'")
LAUNCH_SCRIPT = "assets/dist/lms-launch.js"  # what launch.html.j2 loads
STORED = (".zip", ".whl", ".gz", ".wasm", ".png", ".jpg", ".woff2")  # already compressed: stored as they are
ELSEWHERE = re.compile(r"^(?:[a-z][a-z0-9+.-]*:|/|#|$)", re.I)  # a scheme, an absolute path, a fragment only, empty


def folder_link(href: str) -> str:
    """A relative link to a folder (``../x/``, ``.``, ``..#top``) as one to its index.html; any other link as it is."""
    if ELSEWHERE.match(href):
        return href
    cut = min([i for i in (href.find("?"), href.find("#")) if i >= 0], default=len(href))
    path, rest = href[:cut], href[cut:]
    if not (path in (".", "..") or path.endswith(("/", "/.", "/.."))):
        return href
    return f"{path.rstrip('/') or '.'}/index.html{rest}"


def folder_links(text: str) -> str:
    """``text`` (a page) with every relative link to a folder pointing at its index.html and no canonical
    link (the build host's address); scripts untouched."""
    def fix(part: str) -> str:
        return HREF.sub(lambda m: m.group(1) + folder_link(m.group(2)) + m.group(3), CANONICAL.sub("", part))

    out, at = [], 0
    for script in SCRIPT.finditer(text):
        out.append(fix(text[at:script.start()]))
        out.append(script.group(0))
        at = script.end()
    out.append(fix(text[at:]))
    return "".join(out)


def chapters(site: Path) -> list[dict]:
    """One SCO per chapter of the site's exercise manifest (assets/exercises.json), in its order."""
    listed = json.loads((site / "assets" / "exercises.json").read_text(encoding="utf-8"))["chapters"]
    scos = []
    for chapter in listed:
        href = chapter["url"].rstrip("/") + "/index.html"
        if not chapter["ids"] or not (site / href).is_file():
            raise SystemExit(f"scorm: chapter {chapter['title']!r} has no page {href} or no exercises in {site}")
        scos.append({"key": "ch" + href.split("/")[-2].split("-")[0], "title": chapter["title"], "href": href,
                     "ids": chapter["ids"]})
    if not scos:
        raise SystemExit(f"scorm: {site}/assets/exercises.json lists no chapters")
    return scos


def site_files(site: Path) -> list[str]:
    return sorted(p.relative_to(site).as_posix() for p in site.rglob("*") if p.is_file() and p.name != ".stamp")


def launch_page(sco: dict) -> str:
    return f"launch/{sco['key']}.html"


def render(name: str, **values) -> str:
    env = Environment(loader=FileSystemLoader(TEMPLATES), autoescape=True, keep_trailing_newline=True)
    return env.get_template(name).render(**values)


def manifest(version: str, scos: list[dict], files: list[str], package_version: str, identifier: str = IDENTIFIER,
             title: str = TITLE) -> str:
    hrefs = [quote(f, safe="/") for f in files]
    return render(f"imsmanifest-{version}.xml.j2", identifier=identifier, version=package_version, title=title,
                  scos=[{**s, "href": quote(launch_page(s), safe="/")} for s in scos], files=hrefs)


def launchers(scos: list[dict]) -> dict[str, str]:
    """Each SCO's launcher page, by its path in the package."""
    return {launch_page(s): render("launch.html.j2", policy=LAUNCH_POLICY, title=s["title"], href=s["href"],
                                   ids=s["ids"]) for s in scos}


def site_zip(site: Path, files: list[str], target: Path) -> None:
    """The site's files as the packages carry them (pages with their links fixed), without a manifest."""
    with zipfile.ZipFile(target, "w", compression=zipfile.ZIP_DEFLATED, compresslevel=6) as zf:
        for rel in files:
            path = site / rel
            if path.suffix == ".html":
                zf.writestr(rel, folder_links(path.read_text(encoding="utf-8")))
            else:
                zf.write(path, rel, compress_type=zipfile.ZIP_STORED if path.suffix in STORED else zipfile.ZIP_DEFLATED)


def package(base: Path, target: Path, version: str, scos: list[dict], files: list[str], package_version: str,
            identifier: str = IDENTIFIER, title: str = TITLE) -> Path:
    """The site's zip (`base`) with `scos`' launchers and the manifest for `version` added, written to `target`."""
    target.parent.mkdir(parents=True, exist_ok=True)
    tmp = target.with_suffix(".zip.part")
    shutil.copyfile(base, tmp)
    pages = launchers(scos)
    with zipfile.ZipFile(tmp, "a", compression=zipfile.ZIP_DEFLATED, compresslevel=6) as zf:
        for rel, text in pages.items():
            zf.writestr(rel, text)
        listed = sorted([*files, *pages])
        zf.writestr("imsmanifest.xml", manifest(version, scos, listed, package_version, identifier, title))
    tmp.replace(target)
    return target


def suffix(version: str) -> str:
    return VERSIONS[version].removeprefix("robotics-workbook-").removesuffix(".zip")


def build(site: Path, out: Path, package_version: str = "1", per_chapter: bool = False) -> list[Path]:
    """The whole book's packages (1.2, then 2004); with `per_chapter`, one per chapter and version (out/chapters/)."""
    site, out = Path(site), Path(out)
    if not (site / "index.html").is_file():
        raise SystemExit(f"scorm: {site} is not a built site (run `make site`)")
    if not (site / LAUNCH_SCRIPT).is_file():
        raise SystemExit(f"scorm: {site} has no {LAUNCH_SCRIPT} (the launchers' script; run `make site`)")
    scos = chapters(site)
    files = site_files(site)
    out.mkdir(parents=True, exist_ok=True)
    base = out / ".site.zip.part"
    site_zip(site, files, base)
    try:
        written = [package(base, out / name, version, scos, files, package_version)
                   for version, name in VERSIONS.items()]
        if per_chapter:
            for sco in scos:
                for version in VERSIONS:
                    name = f"robotics-workbook-{sco['key']}-{suffix(version)}.zip"
                    written.append(package(base, out / "chapters" / name, version, [sco], files, package_version,
                                           identifier=f"{IDENTIFIER}-{sco['key']}", title=f"{TITLE}: {sco['title']}"))
    finally:
        base.unlink(missing_ok=True)
    return written


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--site", default=str(ROOT / "site"))
    parser.add_argument("--out", default=str(ROOT / "dist"))
    parser.add_argument("--chapters", action="store_true", help="also one package per chapter (out/chapters/)")
    args = parser.parse_args(argv)
    for path in build(Path(args.site), Path(args.out), per_chapter=args.chapters):
        print(f"scorm: {path} ({path.stat().st_size / 1e6:.1f} MB)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
