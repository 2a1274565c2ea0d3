"""The workbook as SCORM packages any LMS can host: ``make scorm``.

    python scripts/scorm_package.py [--site site] [--out dist]

writes ``dist/robotics-workbook-scorm12.zip`` and ``dist/robotics-workbook-scorm2004.zip``
from the built (and tested) ``site/``: the whole site, Pyodide and the grader
included, with an ``imsmanifest.xml`` (``scripts/scorm/imsmanifest-*.xml.j2``) at
the top. One SCO per chapter: each LMS lists, launches, scores and keeps the
progress of each chapter on its own, and every LMS handles that (a launch
parameter to pick a chapter is dropped by some). Every path is relative; the pages
fetch nothing from elsewhere (their Content-Security-Policy says so).

Two changes to the copy, none to ``site/``:

- links to a folder (``../04-ekf-update/``) name its ``index.html``: an LMS serves
  the package's files, not folder indexes (the pages' inline scripts, which the
  Content-Security-Policy allows by their hash, are left as they are);
- ``sw.js`` stays (the page does not register it inside an LMS frame).
"""

from __future__ import annotations

import argparse
import json
import re
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
    """``text`` (a page) with every relative link to a folder pointing at its index.html; scripts untouched."""
    def fix(part: str) -> str:
        return HREF.sub(lambda m: m.group(1) + folder_link(m.group(2)) + m.group(3), part)

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


def manifest(version: str, scos: list[dict], files: list[str], package_version: str) -> str:
    env = Environment(loader=FileSystemLoader(TEMPLATES), autoescape=True, keep_trailing_newline=True)
    template = env.get_template(f"imsmanifest-{version}.xml.j2")
    hrefs = [quote(f, safe="/") for f in files]
    return template.render(identifier=IDENTIFIER, version=package_version, title=TITLE,
                           scos=[{**s, "href": quote(s["href"], safe="/")} for s in scos], files=hrefs)


def build(site: Path, out: Path, package_version: str = "1") -> list[Path]:
    site, out = Path(site), Path(out)
    if not (site / "index.html").is_file():
        raise SystemExit(f"scorm: {site} is not a built site (run `make site`)")
    scos = chapters(site)
    files = site_files(site)
    out.mkdir(parents=True, exist_ok=True)
    written = []
    for version, name in VERSIONS.items():
        target = out / name
        tmp = target.with_suffix(".zip.part")
        with zipfile.ZipFile(tmp, "w", compression=zipfile.ZIP_DEFLATED, compresslevel=6) as zf:
            zf.writestr("imsmanifest.xml", manifest(version, scos, files, package_version))
            for rel in files:
                path = site / rel
                if path.suffix == ".html":
                    zf.writestr(rel, folder_links(path.read_text(encoding="utf-8")))
                else:
                    # Already-compressed files are stored as they are.
                    kind = (
                        zipfile.ZIP_STORED
                        if path.suffix in (".zip", ".whl", ".gz", ".wasm", ".png", ".jpg", ".woff2")
                        else zipfile.ZIP_DEFLATED
                    )
                    zf.write(path, rel, compress_type=kind)
        tmp.replace(target)
        written.append(target)
    return written


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--site", default=str(ROOT / "site"))
    parser.add_argument("--out", default=str(ROOT / "dist"))
    args = parser.parse_args(argv)
    for path in build(Path(args.site), Path(args.out)):
        print(f"scorm: {path} ({path.stat().st_size / 1e6:.1f} MB)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
