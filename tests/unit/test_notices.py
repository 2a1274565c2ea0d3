"""Every third-party file the site ships has its notice, with its licence's text (scripts/notices.py).

The site, and both SCORM packages that zip it, carry Pyodide, CPython's standard library, NumPy,
KaTeX, the npm packages bundled into the page's JavaScript and mkdocs-material's theme files. The
page notices/ is written at build time from the files the build used; here the built site is
walked file by file: a file that is neither the workbook's own nor covered by a component of that
page fails, and so does a component whose licence text the page lacks.
"""

from __future__ import annotations

import html
import re
import shutil
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
SITE = ROOT / "site"
sys.path.insert(0, str(ROOT / "scripts"))
import notices  # noqa: E402  (scripts/ is no package; tests/conftest.py puts it on the path too)
from tracked import tracked  # noqa: E402

needs_site = pytest.mark.skipif(not (SITE / "index.html").is_file(),
                                reason="the site is built by `make site` (make test builds it first)")


@pytest.fixture(scope="module")
def components():
    return notices.components()


@pytest.fixture(scope="module")
def page_text():
    raw = (SITE / "notices" / "index.html").read_text(encoding="utf-8")
    return html.unescape(re.sub(r"<[^>]+>", "", raw))


@needs_site
def test_every_shipped_file_is_ours_or_has_a_notice(components):
    assert notices.unexplained(SITE, components) == [], "shipped files without a notice (scripts/notices.py)"


@needs_site
def test_every_component_on_the_page_with_its_licence_text(components, page_text):
    shipped = notices.shipped(SITE)
    named = {"pyodide", "CPython", "numpy", "katex", "@codemirror/view", "mkdocs-material"}
    for comp in components:
        assert any(notices.covering(path, [comp]) for path in shipped) or not comp.covers, (
            f"{comp.name}: a notice for files the site does not ship")
        assert comp.name in page_text and comp.licence and comp.licence in page_text, comp.name
        assert comp.texts, f"{comp.name}: no licence text found for it"
        for _, text in comp.texts:
            first = next(line for line in text.splitlines() if line.strip()).strip()
            assert first in page_text, f"{comp.name}: its licence text is not on the page"
        named = {n for n in named if not comp.name.startswith(n)}
    assert named == set(), f"no notice for {named}"


@needs_site
def test_the_bundles_npm_packages_are_read_from_their_source_maps(components):
    npm = {c.name for c in components if any(p.startswith("assets/dist/") for p in c.covers)}
    assert {"@codemirror/state", "@codemirror/view", "@lezer/python", "codemirror"} <= npm
    assert not npm & {"eslint", "esbuild", "axe-core", "scorm-again"}  # tools and test pages: never shipped


@needs_site
def test_the_own_licences_and_the_footer_link(page_text):
    assert "Permission is hereby granted, free of charge" in page_text  # LICENSE, the code's
    assert "Creative Commons Attribution 4.0" in page_text
    chapter = (SITE / "chapters" / "00-rotations-2d" / "index.html").read_text(encoding="utf-8")
    footer = chapter[chapter.index('class="md-copyright"'):]
    assert 'href="../../notices/#third-party-software"' in footer and "MIT licence" in footer and "CC BY 4.0" in footer


@needs_site
def test_a_third_party_file_without_a_notice_is_found(tmp_path, components):
    site = tmp_path / "site"
    shutil.copytree(SITE, site, ignore=shutil.ignore_patterns("*.wasm", "*.gz", "*.whl", "*.zip"))
    (site / "assets" / "vendor" / "leaflet").mkdir()
    (site / "assets" / "vendor" / "leaflet" / "leaflet.js").write_text("/* someone else's */", encoding="utf-8")
    (site / "assets" / "javascripts" / "extra.js").write_text("/* not the theme's */", encoding="utf-8")
    assert notices.unexplained(site, components) == ["assets/javascripts/extra.js", "assets/vendor/leaflet/leaflet.js"]


def test_the_page_is_generated_never_committed():
    assert not [p for p in tracked("docs", "site") if "notices" in p and p != "docs/hooks/notices_page.py"]


@needs_site
def test_both_scorm_packages_carry_the_notices():
    import scorm_package  # scripts/scorm_package.py: the packages zip these files of site/

    files = scorm_package.site_files(SITE)
    assert "notices/index.html" in files and set(notices.shipped(SITE)) <= set(files)
