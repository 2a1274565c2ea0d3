"""The page keeps what the learner did, and the keyboard never gets lost (issue 28).

- A link to a place on the same page (the table of contents, a carried answer's
  "Back to exercise 3.7") moves there and changes nothing else: every exercise
  element, verdict and explanation is the same one as before (not rebuilt by the
  theme's instant navigation), and "Back to exercise N" focuses that exercise's answer
  with its heading below the sticky header.
- Tabbing through the code editor leaves the code as it was; Tab indents once the
  learner types; Esc then Tab leaves. On a phone the editor takes the whole width
  (a longer line scrolls: listings never wrap).
- A ?variant= link for an exercise of another chapter links to it there.
"""

from __future__ import annotations

from playwright.sync_api import expect

from helpers import CHAPTERS, editor_code, exercise, open_all_editors, open_chapter, open_editor, role, wait_runtime
from workbook import bank
from workbook.number_format import fmt

MARK = "() => { for (const el of document.querySelectorAll('[data-exercise-id]')) el.wbKept = true; }"
KEPT = "() => [...document.querySelectorAll('[data-exercise-id]')].every((el) => el.wbKept === true)"


# The theme's table of contents marks the section the page is at (and, with navigation.tracking,
# writes it in the address): true once that is `t` in both. It marks the section before a
# heading that stops too low under the header, and the address follows it.
TOC_AT = """t => location.hash === '#' + t && [...document.querySelectorAll('.md-sidebar--secondary .md-nav__link--active')]
  .map((a) => a.hash).join() === '#' + t"""


def fill(ex, rows):
    for i, row in enumerate(rows, 1):
        for j, v in enumerate(row, 1):
            ex.locator(role("entry", f'[data-row="{i}"][data-col="{j}"]')).fill(fmt(v))


def test_in_page_links_keep_every_verdict_and_back_to_exercise_focuses_its_answer(page, site_url):
    page.set_viewport_size({"width": 1280, "height": 800})
    open_chapter(page, site_url, 3)
    first, later = exercise(page, "3.7"), exercise(page, "3.8")
    F = [list(row) for row in bank.get("3.7").answer.cleaned]
    F[0][2] = -2.0  # a wrong F(1,3), carried into 3.8
    first.scroll_into_view_if_needed()
    fill(first, F)
    first.locator(role("check")).click()
    page.wait_for_function("el => el.dataset.state === 'incorrect'", arg=first.element_handle())
    later.scroll_into_view_if_needed()
    fill(later, bank.get("3.8").carried_answer({"F": tuple(map(tuple, F))}).cleaned)
    later.locator(role("check")).click()
    page.wait_for_function("el => el.dataset.state === 'incorrect'", arg=later.element_handle())
    first_says = first.locator(role("feedback")).inner_text()
    later_says = later.locator(role("feedback")).inner_text()
    assert first_says and later_says
    page.evaluate(MARK)

    # "Back to exercise 3.7": the same page, 3.7's answer focused, its heading below the header
    later.locator(role("carried-from")).click()
    page.wait_for_function("el => el.contains(document.activeElement)", arg=first.element_handle())
    assert page.evaluate(KEPT), "the exercises were rebuilt"
    assert page.evaluate("() => document.activeElement.dataset.role") == "entry"
    assert first.locator(role("feedback")).inner_text() == first_says
    assert later.locator(role("feedback")).inner_text() == later_says
    assert first.get_attribute("data-state") == "incorrect"
    header_bottom = page.evaluate("() => document.querySelector('.md-header').getBoundingClientRect().bottom")
    heading_top = page.evaluate("() => document.getElementById('ex-3-7-title').getBoundingClientRect().top")
    assert header_bottom <= heading_top < 800, (header_bottom, heading_top)

    # The theme's table of contents agrees: 3.7's section is the one reached (and named in the address)
    page.wait_for_function(TOC_AT, arg="ex-3-7-title")

    # The table of contents, twice: still the same exercises, the same verdicts, and the section
    # reached is the one clicked (the theme marks it and puts it in the address once the page stops)
    for target in ("ex-3-8-title", "ex-3-7-title"):
        link = page.locator(f'.md-sidebar--secondary a[href$="#{target}"]').first
        link.click()
        page.wait_for_function(TOC_AT, arg=target)
        assert page.evaluate(KEPT), f"the exercises were rebuilt after the link to {target}"
        assert first.locator(role("feedback")).inner_text() == first_says
        assert later.locator(role("feedback")).inner_text() == later_says


BUILD = "1.7"


def in_editor(page):
    return page.evaluate("() => !!document.activeElement?.closest('.cm-editor')")


def test_tabbing_through_the_editor_leaves_the_code_and_tab_indents_once_typing(page, site_url):
    open_chapter(page, site_url, int(BUILD.split(".")[0]))
    ex = exercise(page, BUILD)
    open_editor(ex)
    starter = editor_code(ex)
    content = ex.locator(".cm-content")
    for _ in range(2):  # passing through, twice
        content.focus()
        assert in_editor(page)
        page.keyboard.press("Tab")
        assert not in_editor(page), "Tab did not leave an editor the learner only passed through"
        assert editor_code(ex) == starter
    page.keyboard.press("Shift+Tab")
    assert in_editor(page)
    page.keyboard.press("Shift+Tab")
    assert not in_editor(page)
    assert editor_code(ex) == starter

    # Typing: now Tab indents (and stays in the editor)
    content.focus()
    page.keyboard.press("Control+End")
    page.keyboard.press("Enter")
    typed = editor_code(ex)
    assert typed != starter
    page.keyboard.press("Tab")
    assert in_editor(page)
    assert editor_code(ex) != typed and editor_code(ex).startswith(typed.rstrip(" "))
    # Esc, then Tab: out, the code as it was
    indented = editor_code(ex)
    page.keyboard.press("Escape")
    page.keyboard.press("Tab")
    assert not in_editor(page)
    assert editor_code(ex) == indented


COLUMNS = """el => {
  const line = [...el.querySelectorAll('.cm-line')].find((l) => l.textContent.trim()), pad = getComputedStyle(line);
  const text = document.createRange();
  text.selectNodeContents(line);
  const char = text.getBoundingClientRect().width / line.textContent.length;
  const room = el.closest('.cm-scroller').getBoundingClientRect().right - line.getBoundingClientRect().left
    - parseFloat(pad.paddingLeft) - parseFloat(pad.paddingRight);
  return Math.floor(room / char);
}"""


def test_the_editor_takes_a_phone_s_whole_width_and_never_wraps(page, site_url):
    page.set_viewport_size({"width": 360, "height": 740})
    open_chapter(page, site_url, int(BUILD.split(".")[0]))
    ex = exercise(page, BUILD)
    open_editor(ex)
    host = ex.locator(role("editor"))
    host.scroll_into_view_if_needed()
    box = host.evaluate("el => { const r = el.getBoundingClientRect(); return [r.left, r.right]; }")
    assert box == [0, 360], f"the editor spans {box}, not the screen's 0 to 360 px"
    # as many columns of code beside the line numbers as the screen holds (the page's margins left 27)
    columns = ex.locator(".cm-content").evaluate(COLUMNS)
    assert columns >= 32, columns
    # A longer line scrolls sideways, on one line: the code's columns stay as they are
    ex.evaluate("el => el.querySelector('[data-role=editor]').wbEditor.setCode('x = ' + '1 + '.repeat(40) + '1\\n')")
    scroller = ex.locator(".cm-scroller")
    sizes = scroller.evaluate("el => [el.scrollWidth, el.clientWidth]")
    assert sizes[0] > sizes[1], f"a 165-character line does not scroll: {sizes}"
    assert ex.locator(".cm-lineWrapping").count() == 0
    assert page.evaluate("() => document.documentElement.scrollWidth") == 360


def test_a_variant_link_for_another_chapter_links_to_it_there(page, site_url):
    page.goto(site_url + CHAPTERS[0] + "?variant=7.7-5")
    wait_runtime(page)
    notice = page.locator('[data-wb-notice="variant-link"]')
    expect(notice).to_contain_text("exercise “7.7”, which is not on this page")
    link = notice.locator("a")
    expect(link).to_have_count(1)
    href = link.get_attribute("href")
    assert CHAPTERS[7] in href and "variant=7.7-5" in href and href.endswith("#ex-7-7"), href
    link.click()
    page.wait_for_url(f"**/{CHAPTERS[7]}?variant=7.7-5#ex-7-7")
    wait_runtime(page)
    page.wait_for_function("() => document.querySelector('[data-exercise-id=\"7.7\"]')?.dataset.variant === '5'")


FOCUSED = """() => {
  const focused = document.activeElement;
  if (!focused || focused === document.body) return null;
  // A visually hidden option (the palette switch) shows through its visible label; the code
  // editor draws its ring on its frame.
  const hiddenInput = focused.matches('input') && focused.getBoundingClientRect().width <= 1;
  const label = hiddenInput ? [...(focused.form || document).querySelectorAll('label')].find((l) => l.getClientRects().length) : null;
  const el = label || focused.closest('.cm-editor') || focused;
  const r = el.getBoundingClientRect();
  const s = getComputedStyle(el);
  const shown = r.width > 0 && r.height > 0 && r.bottom > 0 && r.right > 0
    && r.top < innerHeight && r.left < innerWidth && s.visibility !== 'hidden' && Number(s.opacity) > 0;
  const ring = (s.outlineStyle !== 'none' && parseFloat(s.outlineWidth) > 0) || s.boxShadow !== 'none';
  return { what: focused.outerHTML.slice(0, 120), shown, ring };
}"""


def test_every_tab_stop_is_visible_and_ringed(page, site_url):
    lost = {}
    for width, height in ((360, 740), (1280, 800)):
        page.set_viewport_size({"width": width, "height": height})
        open_chapter(page, site_url, 0)
        # the page drawn to its end first (editors built), so nothing moves under the focus
        open_all_editors(page)
        # measured as they are, not halfway through the theme's transitions (the skip link fades in)
        page.add_style_tag(content="*, *::before, *::after { transition: none !important; }")
        for stop in range(60):
            page.keyboard.press("Tab")
            got = page.evaluate(FOCUSED)
            if got and not (got["shown"] and got["ring"]):
                lost.setdefault(width, []).append((stop + 1, got))
    assert lost == {}, lost
