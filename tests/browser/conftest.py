"""Browser tests: the built site (``site/``) served on 127.0.0.1 under a
sub-path, as on a GitHub Pages project site, driven by Playwright in Chromium.

Every request to any other origin is aborted and counted; a test fails if one
was made. The browser is Playwright's own where installed, else Debian's
chromium (see scripts/find_browser.py).
"""

from __future__ import annotations

import functools
import http.server
import re
import sys
import threading
from pathlib import Path
from urllib.parse import urlsplit

import pytest

ROOT = Path(__file__).resolve().parents[2]
SITE = ROOT / "site"
SUBPATH = "/workbook/"
sys.path.insert(0, str(ROOT / "scripts"))

from find_browser import find_browser  # noqa: E402


class _SiteHandler(http.server.SimpleHTTPRequestHandler):
    extensions_map = {**http.server.SimpleHTTPRequestHandler.extensions_map, ".wasm": "application/wasm",
                      ".js": "text/javascript", ".mjs": "text/javascript"}

    def translate_path(self, path):
        parts = urlsplit(path).path
        if not parts.startswith(SUBPATH):
            return str(SITE / "__not_found__")
        return super().translate_path("/" + parts[len(SUBPATH):])

    def do_GET(self):
        # As if deployed at this address: the sitemap lists absolute URLs built from
        # site_url, and mkdocs-material's instant navigation follows only those.
        if urlsplit(self.path).path == SUBPATH + "sitemap.xml":
            text = (SITE / "sitemap.xml").read_text()
            home = re.search(r"<loc>(.*?)</loc>", text).group(1)
            body = text.replace(home, f"http://{self.headers['Host']}{SUBPATH}").encode()
            self.send_response(200)
            self.send_header("Content-Type", "application/xml")
            self.send_header("Content-Length", str(len(body)))
            self.end_headers()
            self.wfile.write(body)
            return
        super().do_GET()

    def log_message(self, *args):  # keep test output quiet
        pass

    def handle(self):
        try:
            super().handle()
        except (ConnectionResetError, BrokenPipeError):
            pass  # the browser went away mid-response (a test ended): not an error


@pytest.fixture(scope="session")
def site_url():
    if not (SITE / "index.html").exists():
        pytest.fail("site/ is not built: run `make site` (make test does)")
    handler = functools.partial(_SiteHandler, directory=str(SITE))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    yield f"http://127.0.0.1:{server.server_address[1]}{SUBPATH}"
    server.shutdown()


@pytest.fixture(scope="session")
def browser_type_launch_args(browser_type_launch_args):
    path = find_browser()
    if not path:
        pytest.fail("no Chromium found: `make test` installs Debian's chromium, or run `playwright install chromium`")
    return {
        **browser_type_launch_args,
        "executable_path": path,
        "args": ["--no-sandbox", "--disable-gpu", "--disable-background-networking", "--disable-component-update",
                 "--disable-sync", "--no-first-run", "--disable-quic"],
    }


@pytest.fixture
def external_requests(context, site_url):
    """Abort (and record) every request that leaves the site's origin."""
    origin = "{0.scheme}://{0.netloc}".format(urlsplit(site_url))
    blocked: list[str] = []

    def guard(route):
        url = route.request.url
        if url.startswith(origin) or url.startswith(("data:", "blob:")):
            route.continue_()
        else:
            blocked.append(url)
            route.abort()

    context.route("**/*", guard)
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
