#!/usr/bin/env python3
"""The README's picture (docs/images/workbook.png): a chapter's exercise answered with a known slip.

It serves the built site as the tests do (scripts/site_server.py), opens chapter 0 in the tests'
Chromium (scripts/find_browser.py) with Playwright, types the answer to exercise 0.1 that turns the
point clockwise (the slip the bank names for it, so the grader's own message shows), checks it,
and saves the exercise as it then looks. Run it after `make site`, when the page's look changes:

    .venv/bin/python scripts/screenshot.py [OUT.png]

The answer typed is read from the bank (variant 0's slip), never typed in here.
"""

from __future__ import annotations

import sys
from pathlib import Path

from playwright.sync_api import sync_playwright

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT / "scripts"), str(ROOT / "pyodide_pkg")]

from find_browser import find_browser  # noqa: E402  (scripts/ is on the path above)
from site_server import SiteServer  # noqa: E402
from workbook import bank  # noqa: E402
from workbook.kinds.derive import Derive  # noqa: E402
from workbook.number_format import fmt  # noqa: E402

EXERCISE = "0.1"
OUT = ROOT / "docs" / "images" / "workbook.png"


def main(out: Path = OUT) -> int:
    ex = bank.get(EXERCISE)
    assert isinstance(ex, Derive), f"{EXERCISE} is a Derive exercise"
    slip = ex.answer.slips[0]  # variant 0's first named slip: the clockwise turn
    browser_path = find_browser()
    if not browser_path or not (ROOT / "site" / "index.html").is_file():
        print("screenshot: needs the built site (make site) and a Chromium (make browser)", file=sys.stderr)
        return 1
    with SiteServer(ROOT / "site") as server, sync_playwright() as p:
        browser = p.chromium.launch(executable_path=browser_path)
        page = browser.new_page(viewport={"width": 900, "height": 900}, device_scale_factor=1, color_scheme="light")
        page.goto(server.url + "chapters/00-rotations-2d/")
        page.wait_for_function("() => document.documentElement.dataset.workbookRuntime === 'ready'", timeout=180_000)
        box = page.locator(f'[data-exercise-id="{EXERCISE}"]')
        box.scroll_into_view_if_needed()
        box.locator('[data-role="answer"]').fill(fmt(slip.value))
        box.locator('[data-role="check"]').click()
        page.wait_for_function(f"""() => document.querySelector('[data-exercise-id="{EXERCISE}"]')
          .getAttribute('data-state') === 'incorrect'""", timeout=60_000)
        page.wait_for_timeout(300)  # the feedback's fade-in (a picture, not a test)
        out.parent.mkdir(parents=True, exist_ok=True)
        box.screenshot(path=str(out))
        browser.close()
    print(f"screenshot: {out.relative_to(ROOT) if out.is_relative_to(ROOT) else out} ({out.stat().st_size:,} bytes)")
    return 0


if __name__ == "__main__":
    sys.exit(main(Path(sys.argv[1]) if len(sys.argv) > 1 else OUT))
