"""Issue 48, an app a learner can install: the site has a web app manifest (docs/hooks/app.py)
with icons (a maskable one among them), names and colours, its start URL and scope at the
site root wherever that is (the test server serves it under a project path, as GitHub Pages
does); Chromium finds the page installable, and the installed start URL opens offline on the
last page read."""

from __future__ import annotations

import json
import struct

import pytest

from conftest import SITE, SUBPATH
from helpers import CHAPTERS, exercise, network_is_off, wait_runtime
from test_offline import LONG, precache_list, wait_offline_ready

pytestmark = [pytest.mark.uncached, pytest.mark.browser_context_args(service_workers="allow")]


def png_size(path) -> tuple[int, int]:
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path
    return struct.unpack(">II", data[16:24])


def test_the_manifest_and_its_icons():
    manifest = json.loads((SITE / "manifest.webmanifest").read_text())
    assert manifest["name"] == "Robotics Math Workbook" and 0 < len(manifest["short_name"]) <= 15
    assert manifest["start_url"].startswith("./") and manifest["scope"] == "./"  # relative: any base path
    assert manifest["display"] == "standalone" and manifest["theme_color"] and manifest["background_color"]
    purposes = {}
    for icon in manifest["icons"]:
        path = SITE / icon["src"]
        if icon["type"] == "image/png":
            w, h = png_size(path)
            assert icon["sizes"] == f"{w}x{h}"
            purposes.setdefault(icon["purpose"], set()).add(w)
        else:
            assert path.read_text().startswith("<svg")
    assert {192, 512} <= purposes["any"] and 512 in purposes["maskable"]
    page = (SITE / CHAPTERS[3] / "index.html").read_text()
    assert '<link rel="manifest" href="../../manifest.webmanifest">' in page
    assert 'name="theme-color" media="(prefers-color-scheme: light)"' in page
    assert 'name="theme-color" media="(prefers-color-scheme: dark)"' in page
    stored = [u for u, *_ in precache_list((SITE / "sw.js").read_text())]
    assert "manifest.webmanifest" in stored and all(i["src"] in stored for i in manifest["icons"])


def test_chromium_finds_it_installable_and_the_app_opens_offline_on_the_last_page_read(page, context, site_url):
    assert SUBPATH.strip("/") in site_url  # served under a project path
    page.goto(site_url + CHAPTERS[2])
    wait_runtime(page, timeout=LONG)
    wait_offline_ready(page)
    cdp = context.new_cdp_session(page)
    app = cdp.send("Page.getAppManifest")
    assert app["url"] == site_url + "manifest.webmanifest" and app["errors"] == [], app
    assert cdp.send("Page.getInstallabilityErrors")["installabilityErrors"] == []
    start = json.loads(app["data"])["start_url"]

    page.goto(site_url + CHAPTERS[5])  # the last page read
    exercise(page, "5.1").wait_for()
    context.set_offline(True)
    app_page = context.new_page()
    app_page.goto(site_url + start.removeprefix("./"))
    app_page.wait_for_url(site_url + CHAPTERS[5])
    exercise(app_page, "5.1").wait_for()
    wait_runtime(app_page, timeout=LONG)
    assert network_is_off(app_page)

    # Opened again from another page's visit: the app follows the learner.
    app_page.goto(site_url + CHAPTERS[1])
    exercise(app_page, "1.1").wait_for()
    again = context.new_page()
    again.goto(site_url + start.removeprefix("./"))
    again.wait_for_url(site_url + CHAPTERS[1])
    context.set_offline(False)
