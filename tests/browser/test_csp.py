"""Content-Security-Policy: every built page carries the policy (docs/hooks/csp.py)
before any script, and nothing the site does breaks it. One browser page walks
every page of the site and, on the way, grades one exercise of each kind, runs
a Build exercise (the CodeMirror editor and Pyodide in the worker), moves a
figure's slider, opens a derivation (KaTeX), searches (the theme's search
worker), follows a link by instant navigation and waits for the service worker
to store the site; no policy violation may be reported, by the document's
``securitypolicyviolation`` events or by the console."""

from __future__ import annotations

import re
from urllib.parse import urlsplit

import pytest
from playwright.sync_api import expect

from conftest import SITE
from helpers import (
    CHAPTERS,
    answer_debug,
    answer_derive,
    answer_trace,
    check,
    exercise,
    feedback,
    role,
    run_build,
    set_editor,
    wait_runtime,
)
from workbook import bank
from workbook.contract import ATTR

ROTATE_OK = "import math\n\ndef rotate_2d(x, y, theta):\n    c, s = math.cos(theta), math.sin(theta)\n    return (c * x - s * y, s * x + c * y)\n"
REPORT = """
window.__wbCspSeen = [];
document.addEventListener("securitypolicyviolation", (e) => {
  window.__wbCspSeen.push(e.effectiveDirective);
  window.__wbCspViolation(`${e.effectiveDirective} blocked ${e.blockedURI || "?"} at ${e.sourceFile}:${e.lineNumber} ` +
                          `(${e.sample})`);
});
"""
CSP_META = re.compile(r'<meta http-equiv="Content-Security-Policy" content="([^"]+)">')
LONG = 120_000


def site_pages() -> list[str]:
    """Every page of the built site, relative to its root: the sitemap's, and the 404 page."""
    locs = re.findall(r"<loc>(.*?)</loc>", (SITE / "sitemap.xml").read_text())
    home = locs[0]
    assert all(loc.startswith(home) for loc in locs)
    return [loc[len(home):] for loc in locs] + ["404.html"]


@pytest.fixture
def violations(page):
    """Policy violations reported while the test runs, from any page of the context."""
    found: list[str] = []
    page.context.expose_binding("__wbCspViolation", lambda source, text: found.append(f"{source['page'].url}: {text}"))
    page.context.add_init_script(REPORT)
    page.on("console", lambda msg: found.append(f"{page.url}: console: {msg.text}")
            if "Content Security Policy" in msg.text or "Content-Security-Policy" in msg.text else None)
    return found


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


def test_the_policy_is_enforced_and_reported(page, site_url, violations):
    """The listener sees a violation when there is one (else the next test could not fail)."""
    page.goto(site_url)
    page.evaluate("""() => {
      const s = document.createElement('script');
      s.textContent = 'window.__wbInjected = true';
      document.head.append(s);
    }""")
    page.wait_for_function("() => window.__wbCspSeen.length > 0")
    assert page.evaluate("window.__wbInjected") is None
    assert any("script-src" in v for v in violations), violations


@pytest.mark.browser_context_args(service_workers="allow")  # the offline copy is made under the policy too
def test_no_violation_on_any_page_while_using_the_site(page, site_url, violations):
    pages = site_pages()
    assert CHAPTERS[0] in pages and "progress/" in pages and "" in pages
    for path in pages:
        page.goto(site_url + path)
        if page.locator(f"[{ATTR.exercise}]").count():
            wait_runtime(page, timeout=LONG)
        if path == "":
            # The service worker registers and stores the whole site under the policy.
            page.wait_for_function("([a, s]) => document.documentElement.getAttribute(a) === s",
                                   arg=[ATTR.offline, "ready"], timeout=LONG)
        elif path == CHAPTERS[0]:
            work_chapter_0(page)
        elif path == CHAPTERS[1]:
            design = exercise(page, "1.5")
            assert check(design) in ("correct", "incorrect")
        elif path == CHAPTERS[3]:
            assert answer_debug(exercise(page, "3.5"), bank.get("3.5").bug_line) == "correct"
        elif path == "404.html":
            expect(page.locator("h1")).to_contain_text("404")
        assert page.evaluate("a => document.documentElement.getAttribute(a)", ATTR.runtime) != "failed", path

    # Instant navigation (the theme swaps the next page in, under the first page's policy).
    page.goto(site_url + CHAPTERS[0])
    with page.expect_request(lambda r: urlsplit(r.url).path.endswith(CHAPTERS[1])):
        page.locator("a.md-footer__link--next").click()
    exercise(page, "1.1").wait_for()
    page.wait_for_function("() => !!document.querySelector('.arithmatex .katex')")

    # The theme's search runs in a worker of its own.
    page.locator("input.md-search__input").click()
    page.locator("input.md-search__input").press_sequentially("quaternion", delay=20)
    expect(page.locator(".md-search-result__item").first).to_be_visible(timeout=LONG)
    page.keyboard.press("Escape")

    assert page.evaluate("window.__wbCspSeen") == []
    assert violations == []


def work_chapter_0(page) -> None:
    assert answer_derive(exercise(page, "0.1"), "3") == "correct"
    trace = bank.get("0.3")
    assert answer_trace(exercise(page, "0.3"), trace.answer) == "correct"
    build = exercise(page, "0.5")
    set_editor(page, build, ROTATE_OK)  # CodeMirror writes its styles into a <style> element
    assert run_build(build, timeout=LONG) == "correct", feedback(build)

    figure = page.locator(role("figure")).first
    readouts = figure.locator(role("readout")).all_inner_texts()
    figure.locator('input[type="range"]').first.focus()
    page.keyboard.press("ArrowRight")
    page.wait_for_function("([fig, sel, before]) => [...fig.querySelectorAll(sel)].map(r => r.textContent).join('|') "
                           "!== before", arg=[figure.element_handle(), role("readout"), "|".join(readouts)])

    derivation = exercise(page, "0.2")
    derivation.locator(role("reveal")).click()
    panel = derivation.locator(role("solution-panel"))
    expect(panel).to_be_visible()
    expect(panel.locator(".katex").first).to_be_attached()
    # KaTeX's fonts come from the site (font-src 'self').
    page.evaluate("document.fonts.ready")
    loaded = page.evaluate("[...document.fonts].filter(f => f.family.includes('KaTeX') && f.status === 'loaded').length")
    assert loaded >= 1
