"""Browser tests: the built site (``site/``) served on 127.0.0.1 under a
sub-path, as on a GitHub Pages project site, driven by Playwright in Chromium.

Every request to any other origin fails (the browser resolves no other host) and
is counted; a test fails if one was made. Tests marked ``uncached`` (the offline
ones) also route every request, which turns the browser's HTTP cache off. The browser is Playwright's own where installed, else Debian's
chromium (see scripts/find_browser.py).
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
SITE = ROOT / "site"
sys.path.insert(0, str(ROOT / "scripts"))

from find_browser import find_browser  # noqa: E402  (from scripts/, on the path above)
from helpers import keep_to_origin, record_leaving  # noqa: E402
from site_server import SUBPATH, SiteServer  # noqa: E402,F401  (SUBPATH: for the tests)


@pytest.fixture(scope="session")
def site_url():
    if not (SITE / "index.html").exists():
        pytest.fail("site/ is not built: run `make site` (make test does)")
    with SiteServer(SITE) as server:
        yield server.url


@pytest.fixture(scope="session")
def browser_type_launch_args(browser_type_launch_args):
    path = find_browser()
    if not path:
        pytest.fail("no Chromium found: `make test` installs Debian's chromium, or run `playwright install chromium`")
    return {
        **browser_type_launch_args,
        "executable_path": path,
        "args": ["--no-sandbox", "--disable-gpu", "--disable-background-networking", "--disable-component-update",
                 "--disable-sync", "--no-first-run", "--disable-quic",
                 "--host-resolver-rules=MAP * ~NOTFOUND , EXCLUDE 127.0.0.1 , EXCLUDE localhost"],
    }


def pytest_configure(config):
    config.addinivalue_line("markers", "uncached: route every request (no HTTP cache), as the offline tests need")


@pytest.fixture
def external_requests(request, context, site_url):
    """Record (and, with ``uncached``, abort) every request that leaves the site's origin."""
    if request.node.get_closest_marker("uncached") or os.environ.get("WORKBOOK_ROUTE_ALL"):
        blocked = keep_to_origin(context, site_url)
    else:
        blocked = record_leaving(context, site_url)
    yield blocked
    assert blocked == [], f"requests left the site's origin: {blocked}"


@pytest.fixture
def page(page, external_requests):
    page.set_default_timeout(30_000)
    errors: list[str] = []
    page.on("pageerror", lambda err: errors.append(str(err)))
    page.js_errors = errors
    yield page
    assert errors == [], f"uncaught errors in the page: {errors}"
