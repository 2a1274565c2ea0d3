"""Wide formulas are never cut without a cue: a check the page walks of test_a11y make on
every page, at 1280 px (with the axe audit) and at 360 px (with the fit check).

Every typeset formula (display or inline) is checked against the nearest box that clips
it. Cut means: its ink reaches past that box's edge. A cut formula passes only if the box
scrolls, takes the keyboard focus, and shows its cue on that side (data-wb-overflow, with
the drawn arrow visible)."""

from __future__ import annotations

from playwright.sync_api import Page

CLIPPED = """() => {
  const bad = [];
  let cued = 0;
  for (const f of document.querySelectorAll('.md-content .katex')) {
    if (!f.getClientRects().length || f.closest('[hidden]')) continue;
    const r = f.getBoundingClientRect();
    let box = f.parentElement;
    while (box && box !== document.body && getComputedStyle(box).overflowX === 'visible') box = box.parentElement;
    if (!box || box === document.body) continue;
    const b = box.getBoundingClientRect();
    const left = r.left < b.left + box.clientLeft - 0.5, right = r.right > b.left + box.clientLeft + box.clientWidth + 0.5;
    if (!left && !right) continue;
    const sides = (box.dataset.wbOverflow || '').split(' ');
    const shown = (side, pseudo) => !sides.includes(side) || getComputedStyle(box, pseudo).visibility === 'visible';
    const ok = /auto|scroll/.test(getComputedStyle(box).overflowX) && box.tabIndex === 0
      && (!left || sides.includes('start')) && (!right || sides.includes('end'))
      && shown('start', '::before') && shown('end', '::after');
    if (ok) cued++;
    else bad.push(`${f.textContent.slice(0, 40)} (${left ? 'left ' : ''}${right ? 'right' : ''} of ${box.tagName.toLowerCase()}.${box.className}, cue "${box.dataset.wbOverflow ?? ''}")`);
  }
  return { bad, cued };
}"""


def formulas_ready(page: Page) -> None:
    page.wait_for_function("() => [...document.querySelectorAll('.md-content .arithmatex')].every(e => e.dataset.rendered || e.closest('[hidden]'))")


def check_formulas(page: Page) -> dict:
    """The formulas' state once the page's scroll boxes are marked (a11y.js does it a moment after a
    change, when the page is idle; the page is asked to do it now)."""
    page.evaluate("() => window.workbook?.checkScrollRegionsNow?.()")
    result = page.evaluate(CLIPPED)
    for _ in range(40):
        if not result["bad"]:
            break
        page.wait_for_timeout(250)
        result = page.evaluate(CLIPPED)
    return result


# At 1280 px no display formula of a chapter's text is wider than its box at all (issue 28):
# the desktop reader never scrolls a formula. (Checked by test_a11y's axe walk, on the page as
# loaded, before any panel is opened.)
WIDER_THAN_BOX = """() => [...document.querySelectorAll('.md-typeset .katex-display')]
  .filter((d) => d.getClientRects().length && !d.closest('[hidden], details:not([open])'))
  .map((d) => { const box = d.closest('div.arithmatex') || d; const k = d.querySelector('.katex');
                return [box.clientWidth, k.scrollWidth, d.textContent.slice(0, 60)]; })
  .filter(([room, width]) => width > room + 1)
  .map(([room, width, text]) => `${text} (${width} px in ${room} px)`)"""
