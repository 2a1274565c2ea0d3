"""Each stylesheet of a page is parsed once (docs/overrides/main.html).

As it starts, the theme makes every relative href of the page absolute, for its instant
navigation. On a stylesheet's <link> that starts the sheet again: parsed a second time, and the
whole page styled again, inside the theme's start-up task (20-45 ms on a chapter). The page's
head makes each stylesheet's href absolute as the parser adds the link, before the sheet has
come, so the theme finds nothing to change. Seen in the browser's own trace: one parse of each
sheet, and every sheet's href already absolute when the theme's script runs."""

from __future__ import annotations

import json
from collections import Counter

from helpers import CHAPTERS, wait_runtime

SEEN_BY_THEME = """
(() => {
  window.__hrefsAtTheme = null;
  new MutationObserver((records, observer) => {
    for (const r of records) for (const n of r.addedNodes) {
      if (n.nodeName === "SCRIPT" && /javascripts\\/bundle\\./.test(n.src)) {
        window.__hrefsAtTheme = [...document.querySelectorAll("link[rel=stylesheet]")].map((l) => l.getAttribute("href"));
        observer.disconnect();
      }
    }
  }).observe(document, { childList: true, subtree: true });
})();
"""


def test_each_stylesheet_is_parsed_once_and_the_theme_finds_nothing_to_change(browser, site_url):
    context = browser.new_context()
    page = context.new_page()
    try:
        page.add_init_script(SEEN_BY_THEME)
        browser.start_tracing(page=page, categories=["devtools.timeline"])
        page.goto(site_url + CHAPTERS[0])
        wait_runtime(page)
        trace = json.loads(browser.stop_tracing())
        events = trace["traceEvents"] if isinstance(trace, dict) else trace
        parsed = Counter(e["args"]["data"]["styleSheetUrl"] for e in events if e.get("name") == "ParseAuthorStyleSheet")
        sheets = page.evaluate("() => [...document.querySelectorAll('link[rel=stylesheet]')].map((l) => l.href)")
        assert len(sheets) >= 5, sheets
        assert {url: parsed[url] for url in sheets} == dict.fromkeys(sheets, 1), parsed
        hrefs = page.evaluate("() => window.__hrefsAtTheme")
        assert hrefs and all(h.startswith(site_url.split("/workbook")[0]) for h in hrefs), hrefs
    finally:
        context.close()
