"""A learner's first hour (issue 19, items 2, 3 and 5 to 7): one chapter
numbering everywhere, wide formulas never cut without a cue, a keyboard path to
any exercise, a progress page that says what it counts, and the smaller things
(search snippets, test tables at 360 px, exercises named by title, the Practise
page's controls, the developers' page out of the menu, the chapter list above
the fold)."""

from __future__ import annotations

import json
import re

import pytest
from playwright.sync_api import Page, expect

from conftest import SITE
from helpers import (
    CHAPTERS,
    answer_derive,
    answer_trace,
    exercise,
    go_instantly,
    open_chapter,
    role,
    run_build,
    set_editor,
    wait_runtime,
)
from workbook import bank
from workbook.contract import ATTR, ROLE


def chapter_titles_in_menu(page: Page) -> list[str]:
    links = page.locator(".md-nav--primary a.md-nav__link[href*='chapters/']")
    texts = links.evaluate_all("els => els.map(e => e.textContent)")  # a collapsed section is hidden: its text still counts
    return [" ".join(t.replace("✓", "").replace("(finished)", "").split()) for t in texts]


def test_one_numbering_on_home_menu_titles_progress_and_practise(page, site_url):
    page.goto(site_url)
    home = [t.strip() for t in page.locator(".wb-chapter-list li > a").all_inner_texts()]
    assert len(home) == len(bank.chapters())
    assert [t.split(" · ")[0] for t in home] == [str(n) for n in bank.chapters()]  # 0-9, as the ids
    assert chapter_titles_in_menu(page) == home
    by_number = {int(t.split(" · ")[0]): t for t in home}  # the numbers need not be consecutive
    for n in CHAPTERS:  # through the menu's own kind of link: instant navigation, one grader for the tour
        go_instantly(page, site_url, n)
        h1 = page.locator("h1").evaluate("h => h.firstChild.textContent").strip()
        assert h1 == by_number[n], (h1, by_number[n])
        first = page.locator("[data-exercise-id]").first.get_attribute("data-exercise-id")
        assert first.split(".")[0] == str(n)
    page.goto(site_url + "progress/")
    table = page.locator("[data-wb-progress-table] tbody th a")
    expect(table).to_have_count(len(home))
    assert [t.strip() for t in table.all_inner_texts()] == home
    page.goto(site_url + "practise/")
    page.get_by_role("button", name="Practise another").click()
    source = page.locator(".wb-practise-from a")
    expect(source).to_be_visible()
    assert source.inner_text().strip() in home


def test_the_cue_follows_the_scroll(page, site_url):
    # At 360 px every display formula fits (test_phone_layout); a folded phone's outer screen is 280 px wide,
    # where the widest still scroll.
    page.set_viewport_size({"width": 280, "height": 800})
    page.goto(site_url + CHAPTERS[4])
    box = page.locator(".md-content div.arithmatex[data-wb-overflow]").first
    expect(box).to_have_attribute("data-wb-overflow", "end")
    box.focus()
    box.evaluate("b => { b.scrollLeft = b.scrollWidth; }")
    expect(box).to_have_attribute("data-wb-overflow", "start")
    assert box.evaluate("b => getComputedStyle(b, '::before').visibility") == "visible"
    assert box.evaluate("b => getComputedStyle(b, '::after').visibility") == "hidden"


# ---- Keyboard ----------------------------------------------------------------------
def focused(page: Page, selector: str) -> bool:
    return page.evaluate("s => !!document.activeElement?.matches(s)", selector)


def test_from_page_load_to_the_first_cell_of_0_7_in_at_most_10_key_presses(page, site_url):
    page.goto(site_url + CHAPTERS[0])
    page.wait_for_function("() => [...document.querySelectorAll('[data-exercise-id]')].every(e => e.dataset.wbReady)")
    presses = 0

    def press(key: str) -> None:
        nonlocal presses
        presses += 1
        page.keyboard.press(key)

    press("Tab")
    assert focused(page, "a[data-wb-skip]"), "the first Tab does not reach 'Skip to exercises'"
    expect(page.locator("a[data-wb-skip]")).to_be_visible()
    press("Enter")
    while not focused(page, 'a[data-wb-jump="0.7"]'):
        assert presses < 10, "too many presses"
        press("Tab")
    outline = page.evaluate("() => getComputedStyle(document.activeElement).outlineStyle")
    assert outline != "none"
    press("Enter")
    target = f'[{ATTR.exercise}="0.7"] ' + role("entry", f'[{ATTR.row}="1"][{ATTR.col}="1"]')
    assert focused(page, target), page.evaluate("() => document.activeElement.outerHTML.slice(0, 120)")
    assert presses <= 10, presses
    print(f"key presses from page load to 0.7's first cell: {presses}")
    page.keyboard.type("0.5")
    assert exercise(page, "0.7").locator(role("entry")).first.input_value() == "0.5"
    wait_runtime(page, timeout=120_000)


def test_the_editor_shows_a_focus_ring_and_how_to_leave(page, site_url):
    open_chapter(page, site_url, 0)
    build = exercise(page, "0.5")
    build.locator(f'{role("code")}, .cm-content').first.focus()  # the page may build the editor on its own meanwhile
    if not build.locator(".cm-content:focus").count():
        page.keyboard.press("Enter")
    build.locator(".cm-content:focus").wait_for()
    host = build.locator(role("editor"))
    assert host.evaluate("h => getComputedStyle(h).outlineStyle") == "solid"
    hint = host.locator(".wb-editor-hint")
    expect(hint).to_be_visible()
    expect(hint).to_contain_text("Esc, then Tab")
    described = build.locator(".cm-content").get_attribute("aria-describedby")
    assert page.locator(f"#{described}").inner_text() == hint.inner_text()
    page.keyboard.press("Escape")
    page.keyboard.press("Tab")
    assert page.evaluate("() => document.activeElement.dataset.role") == ROLE.run
    assert host.evaluate("h => getComputedStyle(h).outlineStyle") == "none"


# ---- Progress worth looking at ---------------------------------------------------------
@pytest.mark.parametrize("scheme", ["light", "dark"])
def test_the_progress_page_says_what_it_counts(page, site_url, scheme):
    page.emulate_media(color_scheme=scheme)
    open_chapter(page, site_url, 0)
    assert answer_derive(exercise(page, "0.1"), "3") == "correct"
    assert answer_trace(exercise(page, "0.3"), bank.get("0.3").answer) == "correct"
    assert answer_derive(exercise(page, "0.6"), "7") == "incorrect"
    page.goto(site_url + "progress/")
    overall = page.locator("[data-wb-overall-progress]")
    expect(overall.locator('[data-wb-bar="solved"]')).to_contain_text(f"Solved2 of {len(bank.all_exercises())} exercises")
    expect(overall.locator('[data-wb-bar="mastered"]')).to_contain_text("Mastered0 of")
    expect(overall).to_contain_text("only the exercises that draw new numbers (the Derive ones)")
    bar = overall.locator('[data-wb-bar="solved"] progress')
    assert bar.evaluate("b => document.getElementById(b.getAttribute('aria-labelledby')).textContent") == "Solved"
    table = page.locator("[data-wb-progress-table]")
    expect(table.locator("thead")).to_contain_text("ChapterSolvedMasteredReview")
    first = table.locator("tbody tr").nth(0)
    expect(first).to_contain_text(f"2 of {len(bank.chapter(0))}")
    expect(first).to_contain_text(f"0 of {sum(1 for e in bank.chapter(0) if getattr(e, 'vary', None))}")
    expect(first.locator("td").nth(2)).to_contain_text("next review in")
    expect(table.locator("tfoot")).to_contain_text("All chapters")
    # Drawn in the palette: the bars' fill is the scheme's own colour.
    fill = first.locator(".wb-mini-fill").first
    colour = fill.evaluate("f => getComputedStyle(f).backgroundColor")
    want = page.evaluate("""s => { const p = document.createElement('span'); p.style.color = getComputedStyle(document.body)
        .getPropertyValue(s === 'dark' ? '--md-typeset-a-color' : '--md-primary-fg-color'); document.body.append(p);
        const c = getComputedStyle(p).color; p.remove(); return c; }""", scheme)
    assert colour == want
    assert first.locator(".wb-mini-fill").first.evaluate("f => f.getBoundingClientRect().width") > 0


# ---- The smaller things ------------------------------------------------------------------
def test_the_practise_page_offers_no_way_back_to_the_workbooks_numbers(page, site_url):
    page.goto(site_url + "practise/")
    wait_runtime(page, timeout=120_000)
    el = page.locator(".wb-practise-card [data-exercise-id]")
    for _ in range(40):  # Build and Debug exercises come up too; this is about a Derive one's numbers
        page.get_by_role("button", name="Practise another").click()
        el.wait_for()
        if el.get_attribute("data-kind") == "derive":
            break
    page.wait_for_function("el => Number(el.getAttribute('data-variant')) > 0", arg=el.element_handle())
    expect(el.locator(role("original-variant"))).to_be_hidden()
    expect(el.locator(role("variant-link"))).to_be_hidden()
    assert "variant" not in el.locator(role("variant-label")).inner_text().lower()


def test_the_developers_page_is_out_of_the_learners_menu(page, site_url):
    page.goto(site_url)
    menu = page.locator(".md-nav--primary").first.inner_text()
    assert "Performance" not in menu
    assert (SITE / "performance" / "index.html").exists()
    readme = (SITE.parent / "README.md").read_text(encoding="utf-8")
    assert "docs/performance.md" in readme


WRAPPED_NUMBERS = """(cells) => {
  const broken = [];
  for (const code of cells) {
    const text = code.textContent;
    for (const m of text.matchAll(/-?\\d+(\\.\\d+)?(e-?\\d+)?/g)) {
      const walk = document.createTreeWalker(code, NodeFilter.SHOW_TEXT);
      let node = walk.nextNode(), at = m.index;
      while (node && at >= node.length) { at -= node.length; node = walk.nextNode(); }
      if (!node || at + m[0].length > node.length) continue;
      const range = document.createRange();
      range.setStart(node, at);
      range.setEnd(node, at + m[0].length);
      const tops = new Set([...range.getClientRects()].map((r) => Math.round(r.top)));
      if (tops.size > 1) broken.push(m[0]);
    }
  }
  return broken;
}"""


def test_the_build_test_table_never_breaks_a_number_at_360_px(page, site_url):
    page.set_viewport_size({"width": 360, "height": 800})
    open_chapter(page, site_url, 0)
    build = exercise(page, "0.5")
    set_editor(page, build, "import math\n\ndef rotate_2d(x, y, theta):\n    return (x * math.cos(theta) + 1e-7, y / 3)\n")
    assert run_build(build) == "incorrect"
    cells = build.locator(role("test-result") + " code")
    assert cells.count() >= 6
    assert page.evaluate(WRAPPED_NUMBERS, cells.element_handles()) == []


def test_exercises_are_regions_named_by_their_titles(page, site_url):
    page.goto(site_url + CHAPTERS[2])
    for ex in bank.chapter(2):
        heading = page.locator(f"#ex-{ex.id.replace('.', '-')}-title").inner_text().replace("¶", "").strip()
        expect(page.get_by_role("region", name=heading, exact=True)).to_have_attribute(ATTR.exercise, ex.id)


def test_the_home_page_shows_every_chapter_above_the_fold(page, site_url):
    page.set_viewport_size({"width": 1280, "height": 800})
    page.goto(site_url)
    items = page.locator(".wb-chapter-list li")
    expect(items).to_have_count(len(bank.chapters()))
    assert items.last.evaluate("li => li.getBoundingClientRect().bottom") <= 800


RAW_TEX = re.compile(r"\\\(|\\\[|\\(theta|frac|begin|cos|sin|mathbf|top)\b")


def test_search_shows_formulas_as_text_and_a_visible_focus(page, site_url):
    docs = json.loads((SITE / "search" / "search_index.docs.json").read_text(encoding="utf-8"))
    raw = [d["location"] for d in docs if RAW_TEX.search(d["text"]) or RAW_TEX.search(d["title"])]
    assert raw == [], raw[:5]
    page.goto(site_url + CHAPTERS[0])
    page.locator(".md-search__input").click()
    # The whole query, then one key press: the theme searches on key presses, and typed letter by
    # letter a slower answer to a shorter query could replace the list after ArrowDown had focused
    # one of its links (the focus then falls back to the page: a flaky "outline none").
    page.locator(".md-search__input").fill("rotation matrix")
    page.keyboard.press("End")
    results = page.locator(".md-search-result__item")
    expect(results.first).to_be_visible()
    texts = " ".join(page.locator(".md-search-result").all_inner_texts())
    assert "θ" in texts and not RAW_TEX.search(texts), texts[:300]
    page.keyboard.press("ArrowDown")
    # The focused link's outline, read in the same moment as the focus.
    outline = page.wait_for_function("""() => {
      const el = document.activeElement;
      return el?.classList.contains('md-search-result__link') ? getComputedStyle(el).outlineStyle : false;
    }""").json_value()
    assert outline == "solid"
    page.wait_for_timeout(300)  # and the focus stays there (nothing re-renders the list under it)
    assert page.evaluate("() => document.activeElement?.classList.contains('md-search-result__link')")

