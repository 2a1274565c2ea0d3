"""What the browser tests audit and how: the site's pages (every page, the decision records audited),
axe-core's audit in the light and dark palettes, and the 360 px overflow check. Used by test_a11y.py
and by the tests of the course pages, the class page, the checked steps and the page policy.

axe-core comes from node_modules and is injected by the test only; the site never ships it."""

from __future__ import annotations

from playwright.sync_api import Page

from conftest import ROOT
from helpers import CHAPTERS, role

AXE = ROOT / "node_modules" / "axe-core" / "axe.min.js"
PAGES = ["", *CHAPTERS.values(), "related/", "progress/"]
TEACHING = ["teaching/", "teaching/hosting/", "teaching/assignments/", "teaching/class-page/", "teaching/scorm/",
            "teaching/privacy/"]  # the teacher's guide (its two tools, teach/ and class/, are test_course's)
EVERY_PAGE = [*PAGES, "practise/", *TEACHING, "notices/", "performance/"]  # the last two: out of the menu
# The decision records (docs/decisions/, out of the menu, linked from the performance page): Markdown
# of one shape with no HTML of its own (tests/unit/test_decisions.py), so one template: the index,
# the first and the last record, and the two whose Decision is a list are audited for all of them
# (every page here starts the grader's worker, and 42 of them took 200 s).
DECISIONS = ["decisions/", *(f"decisions/{p.stem}/" for p in sorted((ROOT / "docs" / "decisions").glob("[0-9]*.md")))]
DECISIONS_AUDITED = [DECISIONS[0], DECISIONS[1], DECISIONS[17], DECISIONS[28], DECISIONS[-1]]


COLOUR_RULES = ["color-contrast", "link-in-text-block"]  # axe's rules whose outcome depends on the palette


def load_axe(page: Page) -> None:
    """axe into the page (once), and the theme's colour transitions off."""
    if not page.evaluate("typeof window.axe === 'object'"):
        page.evaluate(AXE.read_text())  # not a <script> element: the page's policy would block it
        # Colours are measured as they are, not halfway through the theme's colour transitions.
        page.add_style_tag(content="*, *::before, *::after { transition: none !important; }")


def audit(page: Page, rules: list[str] | None = None) -> list[str]:
    """axe's violations on the page: of every rule (best-practice included), or of ``rules`` only."""
    # The page checks its scrolling boxes (focusable when they overflow) a moment after each change;
    # a box just revealed is checked now, so that axe measures the page as it settles.
    page.evaluate("() => window.workbook?.checkScrollRegionsNow?.()")
    # Every exercise laid out as on screen. Off screen, an exercise (content-visibility: auto) keeps the
    # size it last had on screen, so what opened in it since then lies past its box, over the next one:
    # axe stacks the boxes as laid out and found 12.4's hint title over 12.5's "Derive" badge (3.1:1),
    # where no learner ever sees it (on screen, the exercise is laid out again, at its own size).
    page.evaluate("""() => {
      if (document.getElementById('wb-audit-laid-out')) return;
      const style = document.createElement('style');
      style.id = 'wb-audit-laid-out';
      style.textContent = '.wb-exercise { content-visibility: visible !important; }';
      document.head.append(style);
    }""")
    load_axe(page)
    result = page.evaluate("""async (rules) => {
      const only = rules ? { runOnly: { type: 'rule', values: rules } } : {};
      const r = await axe.run(document, { resultTypes: ['violations'], ...only });
      return r.violations
        .map(v => `${v.id} (${v.impact}): ${v.help} — ` +
                  v.nodes.slice(0, 4).map(n => `${n.target.join(' ')} ${n.any.map(a => a.message).join('; ')}`).join(' | '));
    }""", rules)
    return result


SCHEME = {"light": "default", "dark": "slate"}  # the OS preference -> mkdocs-material's palette


def set_scheme(page: Page, scheme: str) -> None:
    """Switch the palette as the theme's toggle does (no reload), and wait until the page shows it.

    The theme answers a change of the OS preference with a palette of its own choosing, in a task
    of its own after the change is reported (in the next rendering step). Setting the palette at
    once raced with that task, which then put the light palette back: the "dark" audits ran on
    the light page (the class page's dark screenshot was light). So the theme's answer is awaited
    first, then the palette is set, and the page's background is checked to be that palette's."""
    page.emulate_media(color_scheme=scheme)
    frames = "() => new Promise(r => requestAnimationFrame(() => requestAnimationFrame(() => setTimeout(r, 0))))"
    page.evaluate(frames)
    page.evaluate("s => document.body.setAttribute('data-md-color-scheme', s)", SCHEME[scheme])
    page.evaluate(frames)
    shown = page.evaluate("""() => [document.body.getAttribute('data-md-color-scheme'),
      getComputedStyle(document.body).backgroundColor.match(/\\d+/g).slice(0, 3).map(Number)]""")
    dark = sum(shown[1]) < 3 * 128
    assert shown[0] == SCHEME[scheme] and dark == (scheme == "dark"), f"the page did not take the {scheme} palette: {shown}"


OVERFLOW = ("""() => {
  const doc = document.scrollingElement;
  const out = [];
  if (doc.scrollWidth > doc.clientWidth) out.push(`page scrolls sideways: ${doc.scrollWidth} > ${doc.clientWidth}`);
  const width = doc.clientWidth;
  for (const el of document.querySelectorAll('.wb-exercise, .cm-editor, """ + role("figure") + """, .md-content img, .md-content svg, .wb-progress-panel')) {
    const r = el.getBoundingClientRect();
    if (!r.width) continue;
    // Inside a box that scrolls sideways on purpose (wide formulas, tables, code): fine.
    let p = el.parentElement, scrolls = false;
    while (p && p !== document.body) {
      const o = getComputedStyle(p).overflowX;
      if ((o === 'auto' || o === 'scroll') && p.getBoundingClientRect().right <= width + 0.5) { scrolls = true; break; }
      p = p.parentElement;
    }
    if (!scrolls && (r.left < -0.5 || r.right > width + 0.5)) out.push(`${el.tagName.toLowerCase()}.${el.className}: ${Math.round(r.left)}..${Math.round(r.right)} of ${width}`);
  }
  return out;
}""")
