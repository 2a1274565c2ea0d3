"""Browser tests: the built site (``site/``) served on 127.0.0.1 under a
sub-path, as on a GitHub Pages project site, driven by Playwright in Chromium.

Every request to any other origin fails (the browser resolves no other host) and
is counted; a test fails if one was made. Every context a test opens (new_context) watches the
site's Content-Security-Policy (``policy_watch.py``): a test fails if the policy
blocked anything while it ran. Tests marked ``uncached`` (the offline
ones) also route every request, which turns the browser's HTTP cache off. The browser is Playwright's own where installed, else Debian's
chromium (see scripts/find_browser.py).
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

import pytest
from playwright.sync_api import Page

ROOT = Path(__file__).resolve().parents[2]
SITE = ROOT / "site"
sys.path.insert(0, str(ROOT / "scripts"))

from find_browser import find_browser  # noqa: E402  (from scripts/, on the path above)
from helpers import CHAPTERS, go_instantly, keep_to_origin, open_chapter, record_leaving  # noqa: E402
from policy_watch import BLOCKED, watch_every_context  # noqa: E402
from site_server import SUBPATH, Link, SiteServer  # noqa: E402,F401  (SUBPATH: for the tests)


@pytest.fixture(scope="session")
def site_url():
    if not (SITE / "index.html").exists():
        pytest.fail("site/ is not built: run `make site` (make test does)")
    with SiteServer(SITE) as server:
        yield server.url


@pytest.fixture
def slow_site():
    """The site behind an emulated 8 Mbps link with a 40 ms round trip (gzip as GitHub Pages sends it)."""
    with SiteServer(SITE, link=Link("test-8mbps", 8e6, 40)) as server:
        server.precompress()
        yield server


@pytest.fixture(scope="session")
def browser_type_launch_args(browser_type_launch_args):
    path = find_browser()
    if not path:
        pytest.fail("no Chromium found: `make test` installs Debian's chromium, or run `playwright install chromium`")
    return {
        **browser_type_launch_args,
        "executable_path": path,
        # --liftoff-only: V8 runs WebAssembly with its baseline compiler and never recompiles hot
        # functions with its optimising one in the background. Learners' pages live for minutes and
        # gain from that; a test's page lives seconds, and each new Python (a page's grader, every
        # replaced sandbox) paid for recompiling before it could gain: a page's start, its sandbox's
        # and three Build runs took 8.3 CPU-s, 6.7 with this flag (the same results; the suite is
        # bound by its CPU). `make bench` measures with the browser's defaults, as learners have it.
        "args": ["--no-sandbox", "--disable-gpu", "--disable-background-networking", "--disable-component-update",
                 "--disable-sync", "--no-first-run", "--disable-quic", "--js-flags=--liftoff-only",
                 "--host-resolver-rules=MAP * ~NOTFOUND , EXCLUDE 127.0.0.1 , EXCLUDE localhost"],
    }


@pytest.fixture(scope="session")
def browser_context_args(browser_context_args):
    """Contexts made by the ``context`` and ``page`` fixtures run no service worker, so no offline
    copy (the whole site, fetched in the background after ready) competes with what a test does
    and times. The offline tests, and any test that reads the offline state, opt back in with
    ``@pytest.mark.browser_context_args(service_workers="allow")`` (or a module's ``pytestmark``);
    contexts a test makes itself with ``browser.new_context()`` keep the browser's default."""
    return {**browser_context_args, "service_workers": "block"}


def pytest_configure(config):
    config.addinivalue_line("markers", "uncached: route every request (no HTTP cache), as the offline tests need")
    config.addinivalue_line("markers", "xdist_group(name): run in one test process (pytest-xdist's mark)")


# The longest files first, so that the processes end together (longest job first); a file
# that sets ``SPREAD = True`` has tests that share nothing, and they are shared out one by one.
LONGEST_FIRST = ("test_a11y", "test_sandbox", "test_offline", "test_chapters", "test_skeleton", "test_course",
                 "test_progress_kept", "test_first_hour", "test_nothing_undone", "test_offline_truth", "test_progress",
                 "test_code_the_robot", "test_scorm", "test_offline_state", "test_answer_kinds", "test_page_keeps")  # as measured (summed test time per file)


def pytest_collection_modifyitems(config, items):
    """Group each file's tests for ``pytest -n 3 --dist loadgroup`` (a file's tests share its
    module fixtures and run in one process), except in files that spread, and order the files
    longest first."""
    def rank(item):
        name = item.module.__name__.rsplit(".", 1)[-1]
        return LONGEST_FIRST.index(name) if name in LONGEST_FIRST else len(LONGEST_FIRST)

    items.sort(key=rank)  # stable: a file keeps its own order
    for item in items:
        spread = getattr(item.module, "SPREAD", False)
        item.add_marker(pytest.mark.xdist_group(item.nodeid if spread else item.nodeid.split("::")[0]))


watch_every_context()


@pytest.fixture(autouse=True)
def policy_kept():
    """No test may see the site's policy block anything in a page of any context it opened."""
    BLOCKED.clear()
    yield BLOCKED
    found = list(BLOCKED)
    BLOCKED.clear()
    assert found == [], "the Content-Security-Policy blocked:\n  " + "\n  ".join(found)


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


@pytest.fixture(scope="module")
def _tour_tab(browser, site_url, browser_context_args):
    """The one tab of a test module's ``tour``, with the checks the ``page`` fixture makes, in a
    context made as the module's ``page`` is (its viewport, touch), with no offline copy."""
    context = browser.new_context(**{**browser_context_args, "service_workers": "block"})
    leaving = (keep_to_origin if os.environ.get("WORKBOOK_ROUTE_ALL") else record_leaving)(context, site_url)
    tab = context.new_page()
    tab.set_default_timeout(30_000)
    errors: list[str] = []
    tab.on("pageerror", lambda err: errors.append(str(err)))
    tab.js_errors, tab.leaving = errors, leaving
    yield tab
    context.close()


@pytest.fixture
def tour(_tour_tab, site_url):
    """``tour(n)`` opens chapter n in the test module's one tab and returns the page: the first
    chapter by loading it, the next ones by instant navigation (chapter n again, if the tab is on
    it, by loading it), so the module's tests share one booted grader instead of booting Python
    each. Only for tests that change nothing another test reads (what one grades stays in the
    tab's progress: no test of the module may read those records); each test still fails on an
    uncaught error in the page or a request that leaves the site's origin, as with ``page``."""
    tab = _tour_tab
    tab.js_errors.clear()
    tab.leaving.clear()

    def visit(n: int):
        if tab.url.startswith(site_url) and tab.url != site_url + CHAPTERS[n]:
            go_instantly(tab, site_url, n)
        else:
            open_chapter(tab, site_url, n)
        return tab

    yield visit
    assert tab.leaving == [], f"requests left the site's origin: {tab.leaving}"
    assert tab.js_errors == [], f"uncaught errors in the page: {tab.js_errors}"


# A page's wait_for_function polls its predicate every 50 ms instead of on every animation frame
# (Playwright's default): polling by frame makes the page draw 60 frames a second for as long as a
# test waits, about 0.09 CPU-s per second waited against 0.01, and the suite is bound by its CPU.
# (What must be seen the moment it happens is recorded by the page itself, as test_start_* do.)
POLL_MS = 50
_wait_for_function = Page.wait_for_function


def _wait_for_function_polling(self, expression, *, arg=None, timeout=None, polling=None):
    return _wait_for_function(self, expression, arg=arg, timeout=timeout, polling=POLL_MS if polling is None else polling)


Page.wait_for_function = _wait_for_function_polling  # type: ignore[method-assign]
