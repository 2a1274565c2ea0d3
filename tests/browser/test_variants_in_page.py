"""Variants in the page: draw, solve, go back, reload, link; and the review queue.

Each drawn variant is cross-checked against the grading package natively: the
page's numbers and worked answer must be the ones ``bank.get(id).variant(n)``
gives.
"""

from __future__ import annotations

import re

from playwright.sync_api import expect

from helpers import (
    CHAPTERS,
    before_the_widget,
    check,
    entry_values,
    exercise,
    fill_matrix,
    graded,
    open_chapter,
    reveal,
    role,
    settle,
    solve,
    wait_runtime,
    widget_ready,
)
from workbook import bank
from workbook.contract import ATTR
from workbook.number_format import fmt

EX = "0.1"


def variant_of(el) -> int:
    return int(el.get_attribute(ATTR.variant))


def draw(el) -> int:
    """Press New numbers; wait until the new variant is on screen; return its number."""
    before = el.get_attribute(ATTR.variant)
    el.locator(role("new-variant")).click()
    el.page.wait_for_function("([el, a, v]) => el.getAttribute(a) !== v",
                              arg=[el.element_handle(), ATTR.variant, before])
    return variant_of(el)


def numbers_back(el, n: int) -> None:
    """Wait until variant ``n`` is on screen again (after a reload) and drawn."""
    el.page.wait_for_function("([el, a, v]) => el.getAttribute(a) === v && !el.hasAttribute('aria-busy')",
                              arg=[el.element_handle(), ATTR.variant, str(n)], timeout=120_000)


def shows(el, n: int) -> None:
    """The statement on screen is variant ``n``'s, as the package draws it."""
    v = bank.get(EX).variant(n)
    tex = el.locator(".wb-prompt annotation").all_text_contents()  # KaTeX keeps each formula's TeX source
    assert f"({v.values['x']}, {v.values['y']})" in tex, (n, tex)


def test_a_drawn_variant_is_solved_with_its_own_worked_answer(page, site_url):
    open_chapter(page, site_url, 0)
    el = exercise(page, EX)
    assert variant_of(el) == 0
    n = draw(el)
    assert n != 0
    shows(el, n)
    worked = reveal(el).locator(role("worked-answer")).inner_text()
    assert worked == bank.get(EX).variant(n).worked_text()
    el.locator(role("answer")).fill(worked)
    el.locator(role("check")).click()
    assert settle(el) == "correct"
    assert el.locator(role("original-variant")).is_visible()
    assert page.js_errors == []


def test_back_to_the_workbooks_numbers(page, site_url):
    open_chapter(page, site_url, 0)
    el = exercise(page, EX)
    original = el.locator(".wb-prompt").inner_html()
    draw(el)
    assert el.locator(".wb-prompt").inner_html() != original
    el.locator(role("original-variant")).click()
    page.wait_for_function("([el, a]) => el.getAttribute(a) === '0'", arg=[el.element_handle(), ATTR.variant])
    expect(el.locator(role("original-variant"))).to_be_hidden()
    shows(el, 0)
    assert "?variant" not in page.url
    assert solve(page, bank.get(EX)) == "correct"


def test_a_reload_keeps_the_variant_and_a_link_opens_it(page, site_url, context):
    open_chapter(page, site_url, 0)
    el = exercise(page, EX)
    n = draw(el)
    assert re.search(rf"[?&]variant={re.escape(EX)}-{n}\b", page.url), page.url
    link = el.locator(role("variant-link")).get_attribute("href")
    page.reload()
    wait_runtime(page)
    el = exercise(page, EX)
    page.wait_for_function("([el, a, v]) => el.getAttribute(a) === v", arg=[el.element_handle(), ATTR.variant, str(n)])
    shows(el, n)

    other = context.new_page()  # a fresh page, as a shared link would be opened
    other.goto(site_url + CHAPTERS[0] + "?variant=0.1-4242#ex-0-1")
    wait_runtime(other)
    el = exercise(other, EX)
    other.wait_for_function("([el, a]) => el.getAttribute(a) === '4242'", arg=[el.element_handle(), ATTR.variant])
    shows(el, 4242)
    assert link.endswith(f"variant={EX}-{n}#ex-0-1")


def test_a_reload_keeps_the_answer_and_step_work_given_to_new_numbers(page, site_url):
    """What a learner typed to drawn numbers comes back with them: a number answer (0.1), and the
    answer and checked steps of a matrix exercise worked in steps (3.8). Leaving the numbers for
    others drops them (they answered numbers no longer on screen)."""
    open_chapter(page, site_url, 0)
    el = exercise(page, EX)
    n = draw(el)
    el.locator(role("answer")).fill("12.5")
    assert check(el) == "incorrect"
    page.reload()
    wait_runtime(page)
    el = exercise(page, EX)
    numbers_back(el, n)
    widget_ready(el)
    assert el.locator(role("answer")).input_value() == "12.5"
    assert record(page, EX)["last"] == "12.5"
    other = draw(el)  # other numbers: the answer to the old ones goes
    assert el.locator(role("answer")).input_value() == "" and record(page, EX)["last"] is None and other != n

    steps = bank.get("3.8")
    open_chapter(page, site_url, 3)
    el = exercise(page, "3.8")
    m = draw(el)
    v = steps.variant(m)
    el.locator(role("work-steps-open")).click()
    first = el.locator(role("work-step", f'[{ATTR.stepName}="FP"]'))
    wrong = [[fmt(x + 1) for x in row] for row in v.step_answers["FP"].cleaned]
    fill_matrix(first, wrong)
    first.locator(role("work-step-check")).click()
    page.wait_for_function("el => el.dataset.state && el.dataset.state !== 'pending'", arg=first.element_handle())
    own = el.locator("form").first
    answer = [[fmt(x) for x in row] for row in v.answer.cleaned]
    fill_matrix(own, answer)
    own.locator(role("check")).click()
    assert settle(el) == "correct"
    page.reload()
    wait_runtime(page)
    el = exercise(page, "3.8")
    numbers_back(el, m)
    el.locator("form[data-wb-ready]").first.wait_for(state="attached")  # the exercise's own form (its steps have theirs)
    assert entry_values(el.locator("form").first) == answer, "the answer to the drawn numbers was lost"
    assert record(page, "3.8")["stepWork"], "the step work on the drawn numbers was lost"
    el.locator(role("work-steps-open")).click()
    first = el.locator(role("work-step", f'[{ATTR.stepName}="FP"]'))
    assert entry_values(first) == wrong
    assert page.js_errors == []


def test_an_answer_comes_back_with_the_numbers_it_answered_whatever_another_tab_drew(page, site_url, context):
    """Tab A draws new numbers; tab B, still on the workbook's numbers, answers those. The record
    names the numbers of its answer, so the chapter opened again shows that answer with the numbers
    it answered, not under tab A's."""
    other = context.new_page()  # tab B, open on the workbook's numbers
    open_chapter(other, site_url, 0)
    theirs = exercise(other, EX)
    widget_ready(theirs)
    open_chapter(page, site_url, 0)  # tab A
    el = exercise(page, EX)
    draw(el)
    assert theirs.get_attribute(ATTR.variant) == "0"
    worked = bank.get(EX).worked_text()
    theirs.locator(role("answer")).fill(worked)
    assert check(theirs) == "correct"
    other.close()
    page.goto(site_url + CHAPTERS[0])  # the chapter's address: its numbers come from the record
    wait_runtime(page)
    el = exercise(page, EX)
    widget_ready(el)
    page.wait_for_function("el => !el.hasAttribute('aria-busy')", arg=el.element_handle())
    assert el.get_attribute(ATTR.variant) == "0", "the answer's numbers were not the ones shown"
    assert el.locator(role("answer")).input_value() == worked
    assert el.get_attribute(ATTR.state) == "correct"
    assert page.js_errors == []


def test_an_answer_typed_before_the_widget_starts_is_the_one_checked(page, site_url):
    """A learner who types and presses Check before the exercise's script has loaded, on a page
    that holds an earlier answer, has what they typed checked: the earlier answer does not come
    back over it."""
    open_chapter(page, site_url, 0)
    el = exercise(page, EX)
    el.locator(role("answer")).fill("12345")
    assert check(el) == "incorrect"
    worked = bank.get(EX).worked_text()

    def type_and_check():
        el.locator(role("answer")).fill(worked)
        el.locator(role("answer")).press("Enter")

    before_the_widget(page, "derive", page.reload, type_and_check)
    assert graded(page, el) == "correct", "the earlier answer was checked, not the one typed"
    assert el.locator(role("answer")).input_value() == worked
    assert record(page, EX)["last"] == worked


def test_a_check_before_the_widget_starts_is_not_graded_against_numbers_it_did_not_answer(page, site_url):
    """On a page that brings back drawn numbers, the page first shows the workbook's numbers: an
    answer typed and checked before the exercise's script starts answered those. It is not graded
    against the drawn numbers that then come back; the exercise says so and shows the answer
    last checked to them."""
    open_chapter(page, site_url, 0)
    el = exercise(page, EX)
    n = draw(el)
    el.locator(role("answer")).fill("12.5")
    assert check(el) == "incorrect"
    attempts = record(page, EX)["attempts"]

    def type_and_check():
        assert el.get_attribute(ATTR.variant) == "0"
        el.locator(role("answer")).fill(bank.get(EX).worked_text())  # right for the numbers on screen now
        el.locator(role("answer")).press("Enter")

    # the chapter's address: its numbers come from the record
    before_the_widget(page, "derive", lambda: page.goto(site_url + CHAPTERS[0]), type_and_check)
    numbers_back(el, n)
    expect(el.locator(role("feedback"))).to_contain_text("Not checked")
    assert record(page, EX)["attempts"] == attempts, "the answer was graded against numbers it did not answer"
    assert el.locator(role("answer")).input_value() == "12.5"
    assert page.js_errors == []


def test_a_trace_option_picked_before_the_widget_starts_is_the_one_checked(page, site_url):
    """The same for a Trace exercise (0.3): a stored pick does not come back over the learner's."""
    ex = bank.get("0.3")
    wrong = next(option.key for option in ex.options if option.key != ex.answer)
    open_chapter(page, site_url, 0)
    el = exercise(page, ex.id)
    widget_ready(el)
    el.locator(f'[data-role="choice"][value="{wrong}"]').check()
    assert check(el) == "incorrect"

    def pick_and_check():
        el.locator(f'[data-role="choice"][value="{ex.answer}"]').check()
        el.locator(role("check")).click()

    before_the_widget(page, "trace", page.reload, pick_and_check)
    assert graded(page, el) == "correct", "the stored pick was checked, not the one made"
    assert record(page, ex.id)["last"] == ex.answer


def test_a_bad_variant_in_a_link_says_so_in_the_page(page, site_url):
    page.goto(site_url + CHAPTERS[0] + "?variant=0.1-abc&variant=9.9-12&variant=0.4-99999999")
    wait_runtime(page)
    el = exercise(page, EX)
    assert variant_of(el) == 0
    expect(el.locator(role("feedback"))).to_contain_text("“abc”")
    expect(el.locator(role("feedback"))).to_contain_text("the workbook's numbers are shown")
    expect(exercise(page, "0.4").locator(role("feedback"))).to_contain_text("“99999999”")
    expect(page.locator('[data-wb-notice="variant-link"]')).to_contain_text("exercise “9.9”, which is not on this page")
    assert page.js_errors == []


def test_new_numbers_are_named_in_words_and_the_contents_follow_the_title(page, site_url):
    open_chapter(page, site_url, 0)
    el = exercise(page, "0.4")
    n = draw(el)
    label = el.locator(role("variant-label")).inner_text()
    assert str(n) not in label and "variant" not in label.lower(), label
    title = page.locator("#ex-0-4-name").inner_text().strip()
    toc = page.locator('.md-nav--secondary a[href$="#ex-0-4-title"]').first.inner_text().strip()
    assert toc == title, (toc, title)
    jump = page.locator('#wb-exercises a[data-wb-jump="0.4"]').inner_text()
    assert title.split(" · ", 1)[1] in jump


def record(page, ex_id: str) -> dict:
    return page.evaluate("id => window.workbook.progress.get(id)", ex_id)


def test_the_review_queue_after_a_miss_and_after_a_solve(page, site_url):
    open_chapter(page, site_url, 0)
    el = exercise(page, EX)
    el.locator(role("answer")).fill("12345")
    el.locator(role("check")).click()
    assert settle(el) == "incorrect"
    r = record(page, EX)
    assert r["box"] == 1 and r["missed"] == [0]

    page.goto(site_url + "practise/")
    status = page.locator(".wb-practise-status")
    expect(status).to_contain_text("comes back in 10 minutes")
    # Ten minutes pass: the miss is due.
    page.evaluate("id => window.workbook.progress.update(id, {due: Date.now() - 1})", EX)
    page.reload()
    wait_runtime(page)
    expect(page.locator(".wb-practise-status")).to_contain_text("1 exercise is due")
    el = exercise(page, EX)
    page.wait_for_function("([el, a]) => Number(el.getAttribute(a)) > 0", arg=[el.element_handle(), ATTR.variant])
    n = variant_of(el)
    el.locator(role("answer")).fill(bank.get(EX).variant(n).worked_text())
    el.locator(role("check")).click()
    assert settle(el) == "correct"
    r = record(page, EX)
    assert r["box"] == 2 and n in r["clean"] and n in r["done"]
    # The chapter's last answer (to its own numbers, 0: chains carry it as such) is still the miss.
    assert r["last"] == "12345" and r.get("variant", 0) == 0
    expect(page.locator(".wb-practise-status")).to_contain_text("comes back in 24 hours")
    assert "variant" not in page.url  # the Practise page does not change the chapter's numbers
    page.goto(site_url)
    expect(page.locator("[data-wb-due]")).to_contain_text("Nothing is due")
    assert page.js_errors == []
