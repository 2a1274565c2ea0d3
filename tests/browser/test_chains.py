"""Error carried forward in the page: a wrong 9.2, then a 9.3 that follows from it (CONTRACT.md, "Chains")."""

import json
import re

from playwright.sync_api import expect

from helpers import answer_derive, exercise, open_chapter, role, wait_runtime
from workbook import bank
from workbook.contract import ATTR, STATE, TAG
from workbook.number_format import fmt


def test_an_answer_that_follows_from_a_wrong_earlier_one_is_carried_and_links_back(page, site_url):
    open_chapter(page, site_url, 9)
    first, later = exercise(page, "9.2"), exercise(page, "9.3")
    assert later.get_attribute(ATTR.uses) == "9.2"
    assert answer_derive(first, "6.5") == STATE.incorrect

    mine = bank.get("9.3").carried_answer({"x": 6.5})  # the range from the learner's own x′
    later.scroll_into_view_if_needed()
    assert answer_derive(later, fmt(mine.key)) == STATE.incorrect
    assert later.get_attribute(ATTR.tag) == TAG.carried and later.get_attribute(ATTR.carried) == "9.2"
    expect(later.locator(role("feedback"))).to_contain_text("exercise 9.2")
    link = later.locator(role("carried-from"))
    expect(link).to_have_text("Back to exercise 9.2")
    assert link.get_attribute("href").endswith("#" + first.get_attribute("id"))
    link.click()
    # The address names 9.2; the theme's anchor tracking may then say its heading (…-title) instead.
    page.wait_for_url(re.compile("#" + re.escape(first.get_attribute("id")) + "(-title)?$"))
    expect(first).to_be_in_viewport()

    # an answer that follows from neither is plain wrong; the right one is still right
    assert answer_derive(later, fmt(mine.key + 1.3)) == STATE.incorrect
    assert later.get_attribute(ATTR.carried) is None and later.get_attribute(ATTR.tag) != TAG.carried
    assert answer_derive(later, bank.get("9.3").worked_text()) == STATE.correct

    page.reload()
    wait_runtime(page)
    record = page.evaluate("workbook.progress.get('9.3')")
    assert record["carried"] == [0] and record["clean"] == [0]
    assert page.evaluate("workbook.progress.get('9.2')")["missed"] == [0]
    exported = page.evaluate("JSON.stringify(workbook.progress.exportData())")
    data = json.loads(exported)
    assert data["version"] == 5 and data["exercises"]["9.3"]["carried"] == [0]


def test_a_wrong_matrix_carried_into_the_next_matrix(page, site_url):
    open_chapter(page, site_url, 3)
    first, later = exercise(page, "3.7"), exercise(page, "3.8")
    F = [list(row) for row in bank.get("3.7").answer.cleaned]
    F[0][2] = -2.0  # a wrong F(1,3)
    first.scroll_into_view_if_needed()
    for i, row in enumerate(F, 1):
        for j, v in enumerate(row, 1):
            first.locator(role("entry", f'[data-row="{i}"][data-col="{j}"]')).fill(fmt(v))
    first.locator(role("check")).click()
    page.wait_for_function("el => el.dataset.state === 'incorrect'", arg=first.element_handle())

    mine = bank.get("3.8").carried_answer({"F": tuple(map(tuple, F))})
    later.scroll_into_view_if_needed()
    for i, row in enumerate(mine.cleaned, 1):
        for j, v in enumerate(row, 1):
            later.locator(role("entry", f'[data-row="{i}"][data-col="{j}"]')).fill(fmt(v))
    later.locator(role("check")).click()
    page.wait_for_function("el => el.dataset.state === 'incorrect'", arg=later.element_handle())
    assert later.get_attribute(ATTR.carried) == "3.7"
    expect(later.locator(role("carried-from"))).to_have_text("Back to exercise 3.7")


def test_carried_answers_travel_through_export_and_import(page, site_url):
    from test_progress import import_file, open_progress_page

    open_progress_page(page, site_url)
    v3 = {"format": "robotics-math-workbook-progress", "version": 3, "exported": "2025-01-01T00:00:00Z",
          "exercises": {"9.6": {"carried": [0, 4], "attempts": 2, "updated": 1_700_000_000_000}}}
    import_file(page, json.dumps(v3))
    page.wait_for_function("() => (workbook.progress.get('9.6').carried || []).length === 2")
    assert page.evaluate("workbook.progress.get('9.6')")["carried"] == [0, 4]
    assert page.evaluate("workbook.progress.exportData()")["exercises"]["9.6"]["carried"] == [0, 4]
    # a version-2 file (before carried existed) still imports, and merges with what is there
    v2 = {**v3, "version": 2, "exercises": {"9.6": {"missed": [1], "attempts": 3, "updated": 1_700_000_000_001}}}
    import_file(page, json.dumps(v2))
    page.wait_for_function("() => (workbook.progress.get('9.6').missed || []).length === 1")
    record = page.evaluate("workbook.progress.get('9.6')")
    assert record["carried"] == [0, 4] and record["missed"] == [1] and record["attempts"] == 3
