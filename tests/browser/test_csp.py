"""Content-Security-Policy: every built page carries the policy (docs/hooks/csp.py)
before any script, and nothing the site does breaks it.

Every browser test watches the policy (conftest.py, ``policy_watch.py``): a test that
grades, runs a Build exercise in the editor and the sandbox, moves a figure's slider,
opens a derivation (KaTeX and its fonts), searches (the theme's search worker),
navigates instantly or stores the site for offline use fails if the policy blocked
anything on the way. Here: the policy itself, proof that the watcher sees a
violation when there is one, and proof that every page of the sitemap is opened by a
test (so under the watcher)."""

from __future__ import annotations

import re

from conftest import SITE
from helpers import CHAPTERS
from site_audit import DECISIONS, EVERY_PAGE
from test_course import COURSE_PAGES

CSP_META = re.compile(r'<meta http-equiv="Content-Security-Policy" content="([^"]+)">')


def site_pages() -> list[str]:
    """Every page of the built site, relative to its root: the sitemap's, and the 404 page."""
    locs = re.findall(r"<loc>(.*?)</loc>", (SITE / "sitemap.xml").read_text())
    home = locs[0]
    assert all(loc.startswith(home) for loc in locs)
    return [loc[len(home):] for loc in locs] + ["404.html"]


def test_every_built_page_has_the_policy_before_any_script():
    pages = sorted(SITE.rglob("*.html"))
    assert len(pages) >= len(site_pages())
    policies = set()
    for path in pages:
        html = path.read_text()
        meta = CSP_META.search(html)
        assert meta, f"{path.relative_to(SITE)} has no Content-Security-Policy meta"
        first_script = html.find("<script")
        assert first_script < 0 or meta.start() < first_script, f"{path.relative_to(SITE)}: a script precedes the policy"
        policies.add(meta.group(1))
    assert len(policies) == 1  # one policy: instant navigation keeps the first page's
    directives = dict(d.split(" ", 1) for d in policies.pop().split("; "))
    assert directives["default-src"] == "'self'"
    assert directives["script-src"].startswith("'self' 'wasm-unsafe-eval' 'sha256-")
    assert "'unsafe-inline'" not in directives["script-src"] and "'unsafe-eval'" not in directives["script-src"]
    assert directives["object-src"] == "'none'"
    for name in ("connect-src", "font-src", "base-uri", "form-action"):
        assert directives[name] == "'self'", name
    assert directives["worker-src"] == "'self' blob:"  # the sandbox starts from a blob: URL, to inherit this policy


def test_the_policy_is_enforced_and_the_watcher_reports_it(page, site_url, policy_kept):
    """A script injected into the page is blocked, and the watcher every test has sees it (so a
    violation anywhere in the suite fails its test)."""
    page.goto(site_url)
    page.evaluate("""() => {
      const s = document.createElement('script');
      s.textContent = 'window.__wbInjected = true';
      document.head.append(s);
    }""")
    page.wait_for_function("() => window.__wbPolicySeen > 0")
    assert page.evaluate("window.__wbInjected") is None  # (and the report, sent before this reply, is in)
    seen = list(policy_kept)
    policy_kept.clear()  # expected here: the test passes
    assert any("script-src" in v for v in seen), seen


def test_every_page_of_the_site_is_loaded_under_the_watcher():
    """Every page of the sitemap is opened in full by an axe audit (test_a11y's pages, in both
    palettes, and at 360 px; test_course's course pages), and the 404 page by test_not_found,
    online and offline: all under the watcher. The service worker's registration and the whole
    offline copy are watched in the offline tests. A page added to the site without an audit
    fails here."""
    # The decision records are one template of plain Markdown: test_a11y audits a sample (DECISIONS_AUDITED).
    audited = {path.split("#")[0] for path in (*EVERY_PAGE, *COURSE_PAGES, *DECISIONS)}
    missing = [path for path in site_pages() if path not in audited and path != "404.html"]
    assert missing == [], f"pages no browser test opens: {missing}"
    assert CHAPTERS[0] in audited and "progress/" in audited and "" in audited and "teach/" in audited
