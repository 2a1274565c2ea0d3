"""The SCORM packages (scripts/scorm_package.py): the manifest parses, lists every
file of the zip and nothing else, one SCO per chapter launching its page, links to
folders name their index.html, and the pages' inline scripts (allowed by their
hash) are untouched. Built from a small site in a temporary folder, so `make scorm`
is not needed.
"""

from __future__ import annotations

import html
import json
import re
import xml.etree.ElementTree as ET
import zipfile
from pathlib import Path
from urllib.parse import unquote

import pytest

import scorm_package
from csp import inline_scripts, script_hash

NS = {
    "1.2": {"cp": "http://www.imsproject.org/xsd/imscp_rootv1p1p2", "adlcp": "http://www.adlnet.org/xsd/adlcp_rootv1p2"},
    "2004": {"cp": "http://www.imsglobal.org/xsd/imscp_v1p1", "adlcp": "http://www.adlnet.org/xsd/adlcp_v1p3"},
}
SCORM_TYPE = {"1.2": "scormtype", "2004": "scormType"}
PAGE = """<!doctype html><html><head><meta charset="utf-8"><title>{title} - Robotics Math Workbook</title>
<link rel="canonical" href="http://127.0.0.1:8000/chapters/x/">
<script>var u = new URL("../../", location); var h = 'href="../x/"';</script></head>
<body><a href="../01-b/">next</a> <a href="../../">home</a> <a href="..#top">up</a> <a href="https://example.org/">out</a>
<a href="../01-b/index.html">as is</a> <a href="#sec">here</a><div data-exercise-id="{id}"></div></body></html>"""


@pytest.fixture
def site(tmp_path: Path) -> Path:
    root = tmp_path / "site"
    chapters = [("00-a", "0 · Rotations & frames", ["0.1", "0.2"]), ("01-b", "1 · Transforms <2D>", ["1.1"])]
    for folder, title, ids in chapters:
        page = root / "chapters" / folder / "index.html"
        page.parent.mkdir(parents=True)
        page.write_text(PAGE.format(title=title, id=ids[0]), encoding="utf-8")
    (root / "index.html").write_text(PAGE.format(title="Home", id="x"), encoding="utf-8")
    (root / "assets" / "vendor" / "pyodide").mkdir(parents=True)
    (root / "assets" / "vendor" / "pyodide" / "pyodide.asm.wasm").write_bytes(b"\0asm" + bytes(100))
    (root / "assets" / "a file with spaces & more.js").write_text("1", encoding="utf-8")
    (root / "assets" / "dist").mkdir()
    (root / "assets" / "dist" / "lms-launch.js").write_text("// launch", encoding="utf-8")
    (root / "sw.js").write_text("// sw", encoding="utf-8")
    (root / ".stamp").write_text("", encoding="utf-8")
    (root / "assets" / "exercises.json").write_text(json.dumps({"version": 2, "chapters": [
        {"url": f"chapters/{folder}/", "title": title, "ids": ids} for folder, title, ids in chapters]}), encoding="utf-8")
    return root


@pytest.fixture
def packages(site: Path, tmp_path: Path) -> dict[str, Path]:
    written = scorm_package.build(site, tmp_path / "dist")
    return {"1.2": written[0], "2004": written[1]}


@pytest.mark.parametrize("version", ["1.2", "2004"])
def test_manifest_names_every_file_and_no_other(packages, site, version):
    with zipfile.ZipFile(packages[version]) as zf:
        names = set(zf.namelist())
        root = ET.fromstring(zf.read("imsmanifest.xml"))
    ns = NS[version]
    listed = {unquote(f.get("href")) for f in root.iterfind(".//cp:resource/cp:file", ns)}
    assert names - {"imsmanifest.xml"} == listed  # every file in the zip is listed, none listed is missing
    launchers = {"launch/ch00.html", "launch/ch01.html"}
    assert names - {"imsmanifest.xml"} - launchers == {
        p.relative_to(site).as_posix() for p in site.rglob("*") if p.is_file()} - {".stamp"}
    assert root.findtext("cp:metadata/cp:schemaversion", namespaces=ns) == {"1.2": "1.2", "2004": "2004 4th Edition"}[version]


@pytest.mark.parametrize("version", ["1.2", "2004"])
def test_one_sco_per_chapter_launched_by_its_launcher(packages, version):
    with zipfile.ZipFile(packages[version]) as zf:
        root = ET.fromstring(zf.read("imsmanifest.xml"))
        names = set(zf.namelist())
    ns = NS[version]
    attr = f"{{{ns['adlcp']}}}{SCORM_TYPE[version]}"
    resources = {r.get("identifier"): r for r in root.iterfind(".//cp:resource", ns)}
    items = root.findall(".//cp:organization/cp:item", ns)
    assert [i.findtext("cp:title", namespaces=ns) for i in items] == ["0 · Rotations & frames", "1 · Transforms <2D>"]
    for item in items:
        sco = resources[item.get("identifierref")]
        assert sco.get(attr) == "sco"
        assert unquote(sco.get("href")) in names
        assert [d.get("identifierref") for d in sco.iterfind("cp:dependency", ns)] == ["site"]
    assert [unquote(r.get("href")) for r in resources.values() if r.get(attr) == "sco"] == [
        "launch/ch00.html", "launch/ch01.html"]
    assert resources["site"].get(attr) == "asset"
    assert root.find("cp:organizations", ns).get("default") == root.find(".//cp:organization", ns).get("identifier")


@pytest.mark.parametrize("version", ["1.2", "2004"])
def test_each_launcher_frames_its_chapter_with_no_inline_script(packages, version):
    with zipfile.ZipFile(packages[version]) as zf:
        page = zf.read("launch/ch00.html").decode()
        assert "assets/dist/lms-launch.js" in zf.namelist()
    assert inline_scripts(page) == []
    assert '<script src="../assets/dist/lms-launch.js" defer></script>' in page
    assert 'data-src="../chapters/00-a/index.html"' in page and 'data-ids="0.1 0.2"' in page
    policy = html.unescape(re.search(r'http-equiv="Content-Security-Policy" content="([^"]*)"', page).group(1))
    assert "script-src 'self';" in policy and "frame-src 'self'" in policy and "unsafe-eval" not in policy
    assert "<title>0 · Rotations &amp; frames · Robotics Math Workbook</title>" in page


def test_per_chapter_packages_hold_one_sco_each(site, tmp_path):
    written = scorm_package.build(site, tmp_path / "dist", per_chapter=True)
    chapters = sorted(p.relative_to(tmp_path / "dist").as_posix() for p in written[2:])
    assert chapters == ["chapters/robotics-workbook-ch00-scorm12.zip", "chapters/robotics-workbook-ch00-scorm2004.zip",
                        "chapters/robotics-workbook-ch01-scorm12.zip", "chapters/robotics-workbook-ch01-scorm2004.zip"]
    ns = NS["1.2"]
    with zipfile.ZipFile(tmp_path / "dist" / "chapters" / "robotics-workbook-ch01-scorm12.zip") as zf:
        root = ET.fromstring(zf.read("imsmanifest.xml"))
        names = set(zf.namelist())
    items = root.findall(".//cp:organization/cp:item", ns)
    assert [i.findtext("cp:title", namespaces=ns) for i in items] == ["1 · Transforms <2D>"]
    assert root.get("identifier") == "robotics-math-workbook-ch01-scorm12"
    assert "launch/ch01.html" in names and "launch/ch00.html" not in names
    assert "chapters/00-a/index.html" in names  # the whole site: links to other chapters still work
    assert not list((tmp_path / "dist").glob("*.part"))


def test_packaged_pages_carry_no_canonical_link_to_the_build_host(packages, site):
    with zipfile.ZipFile(packages["2004"]) as zf:
        pages = [zf.read(n).decode() for n in zf.namelist() if n.endswith(".html")]
    assert "canonical" in (site / "chapters/00-a/index.html").read_text(encoding="utf-8")
    assert pages and not any("canonical" in p or "127.0.0.1" in p for p in pages)


def test_links_to_folders_name_their_index_and_scripts_keep_their_hash(packages, site):
    with zipfile.ZipFile(packages["1.2"]) as zf:
        page = zf.read("chapters/00-a/index.html").decode()
    original = (site / "chapters/00-a/index.html").read_text(encoding="utf-8")
    assert 'href="../01-b/index.html">next' in page
    assert 'href="../../index.html">home' in page
    assert 'href="../index.html#top">up' in page
    for kept in ('href="https://example.org/"', 'href="../01-b/index.html">as is', 'href="#sec"'):
        assert kept in page
    assert [script_hash(s) for s in inline_scripts(page)] == [script_hash(s) for s in inline_scripts(original)]
    assert 'var h = \'href="../x/"\'' in page  # text inside a script is never rewritten


def test_refuses_a_site_that_is_not_built(tmp_path):
    with pytest.raises(SystemExit, match="not a built site"):
        scorm_package.build(tmp_path / "nothing", tmp_path / "dist")
