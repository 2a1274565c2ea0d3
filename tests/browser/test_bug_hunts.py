"""Bug hunts in the page, and Build and Debug in progress and review.

* A new Debug exercise solved by clicking, and one by keyboard: the explanation and
  the symptom's figure appear (the figure hidden before, and again after a wrong pick).
* A Build exercise whose tests pass counts in its chapter's Solved bar.
* A Build exercise due for review comes back on the Practise page, with a fresh
  variant (new hidden tests); passing them moves it up the review boxes.

The tests on chapter pages share the module's one tab (``tour``): each answers an exercise of its
own, in a chapter where no other test here answers one, so the records and bars each reads are its own.
"""

from __future__ import annotations

from playwright.sync_api import expect

from helpers import exercise, feedback, role, run_build, set_editor, settle, wait_runtime, widget_ready
from workbook import bank


def records(page) -> dict:
    return page.evaluate("() => workbook.progress.all()")


def test_a_bug_hunt_solved_by_clicking_shows_the_explanation_and_the_symptom(tour):
    ex = bank.get("6.8")
    page = tour(6)
    el = exercise(page, ex.id)
    el.scroll_into_view_if_needed()
    widget_ready(el)
    symptom = el.locator(role("symptom"))
    expect(symptom).to_be_hidden()
    wrong = next(iter(ex.notes))
    el.locator(role("line", f'[data-line="{wrong}"]')).click()
    el.locator(role("check")).click()
    assert settle(el) == "incorrect"
    expect(symptom).to_be_hidden()
    el.locator(role("line", f'[data-line="{ex.bug_line}"]')).click()
    el.locator(role("check")).click()
    assert settle(el) == "correct"
    assert feedback(el).strip() == ex.bug
    expect(symptom).to_be_visible()
    assert symptom.locator("svg title").count() == 1
    assert "What the bug does" in symptom.locator("figcaption").inner_text()
    record = records(page)[ex.id]
    assert record["done"] == [0] and not record.get("clean")  # found after a wrong line: solved with help
    assert record["box"] == 1  # Debug joins the review queue; the first answer missed: box 1


def test_a_bug_hunt_solved_by_keyboard(tour):
    ex = bank.get("8.9")
    page = tour(8)
    el = exercise(page, ex.id)
    el.scroll_into_view_if_needed()
    widget_ready(el)
    el.locator(role("line", '[data-line="1"]')).focus()
    for _ in range(ex.bug_line - 1):
        page.keyboard.press("ArrowDown")
    expect(el.locator(role("line", f'[data-line="{ex.bug_line}"]'))).to_be_focused()
    page.keyboard.press("Enter")  # selects the line and checks
    assert settle(el) == "correct"
    assert el.locator(role("line", f'[data-line="{ex.bug_line}"]')).get_attribute("aria-selected") == "true"
    assert feedback(el).strip() == ex.bug
    expect(el.locator(role("symptom"))).to_be_visible()
    assert records(page)[ex.id]["clean"] == [0]  # found at the first try: clean


def test_a_bug_hunt_found_by_clicking_every_line_is_not_solved_clean(tour):
    ex = bank.get("3.11")
    page = tour(3)
    total = len(bank.chapter(3))
    el = exercise(page, ex.id)
    el.scroll_into_view_if_needed()
    widget_ready(el)
    for n in range(1, len(ex.lines) + 1):  # one line after another, until the bug is found
        el.locator(role("line", f'[data-line="{n}"]')).click()
        el.locator(role("check")).click()
        if settle(el) == "correct":
            break
    assert n == ex.bug_line > 1
    record = records(page)[ex.id]
    assert record["done"] == [0] and not record.get("clean") and record["missed"] == [0]
    bar = page.locator('[data-wb-chapter-progress] [data-wb-bar="solved"]')
    expect(bar).to_contain_text(f"0 of {total} exercises (+1 with help)")


def solved_bar(page) -> str:
    return page.locator('[data-wb-chapter-progress] [data-wb-bar="solved"]').inner_text()


def test_a_build_solved_counts_in_the_chapter_bar(tour):
    ex = bank.get("0.5")
    page = tour(0)
    total = len(bank.chapter(0))
    expect(page.locator('[data-wb-chapter-progress] [data-wb-bar="solved"]')).to_contain_text(f"0 of {total} exercises")
    el = exercise(page, ex.id)
    el.scroll_into_view_if_needed()
    set_editor(page, el, ex.solution)
    assert run_build(el) == "correct"
    expect(page.locator('[data-wb-chapter-progress] [data-wb-bar="solved"]')).to_contain_text(f"1 of {total} exercises")
    record = records(page)[ex.id]
    assert record["clean"] == [0] and record["box"] == 2  # solved, and in the review queue


def test_a_build_due_for_review_comes_back_on_the_practise_page_with_new_hidden_tests(page, site_url):
    ex = bank.get("4.5")  # its statement has formulas: on the card they are typeset as on the chapter page
    page.goto(site_url)
    page.wait_for_function("() => window.workbook && window.workbook.progress")
    page.evaluate("""([id, code]) => workbook.progress.update(id, {
        solved: true, attempts: 1, done: [0], clean: [0], code,
        box: 2, due: Date.now() - 60_000, reviewed: Date.now() - 86_400_000 })""", [ex.id, ex.solution])
    expect(page.locator("[data-wb-due]").first).to_contain_text("1 exercise is due for review")
    page.goto(site_url + "practise/")
    wait_runtime(page)
    el = page.locator(f'.wb-practise-card [data-exercise-id="{ex.id}"]')
    el.wait_for()
    expect(page.locator(".wb-practise-from")).to_contain_text("with new hidden tests")
    expect(el).to_have_attribute("data-wb-ready", "true")
    expect(el.locator(".katex").first).to_be_visible()
    assert el.locator(".arithmatex").evaluate_all("els => els.filter(e => !e.dataset.rendered).map(e => e.textContent)") == []
    assert run_build(el) == "correct"
    record = records(page)[ex.id]
    fresh = [v for v in record["done"] if v != 0]
    assert len(fresh) == 1 and fresh[0] in record["clean"]  # the review ran a fresh variant's hidden tests
    assert record["box"] == 3
    assert record["due"] > page.evaluate("() => Date.now()")
    expect(page.locator(".wb-practise-status")).to_contain_text("Nothing is due for review")
