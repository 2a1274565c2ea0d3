"""The SCORM packages (scripts/scorm_package.py): the manifest parses, lists every
file of the zip and nothing else, one SCO per chapter launching its page, links to
folders name their index.html, and the pages' inline scripts (allowed by their
hash) are untouched. Built from a small site in a temporary folder, so `make scorm`
is not needed.
"""

from __future__ import annotations

import json
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
    assert names - {"imsmanifest.xml"} == {p.relative_to(site).as_posix() for p in site.rglob("*") if p.is_file()} - {".stamp"}
    assert root.findtext("cp:metadata/cp:schemaversion", namespaces=ns) == {"1.2": "1.2", "2004": "2004 4th Edition"}[version]


@pytest.mark.parametrize("version", ["1.2", "2004"])
def test_one_sco_per_chapter_launching_its_page(packages, version):
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
        "chapters/00-a/index.html", "chapters/01-b/index.html"]
    assert resources["site"].get(attr) == "asset"
    assert root.find("cp:organizations", ns).get("default") == root.find(".//cp:organization", ns).get("identifier")


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
