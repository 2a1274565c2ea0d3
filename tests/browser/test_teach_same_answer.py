"""The teach page says which exercises have the same right answer for every student (per-student
numbers do not stop copying there), with the bank's reason, and says nothing of the others."""

from __future__ import annotations

from playwright.sync_api import Page

from workbook import bank, copying


def test_teach_page_labels_the_exercises_whose_answer_cannot_vary(page: Page, site_url):
    page.goto(site_url + "teach/")
    page.wait_for_selector("[data-wb-teach] form")
    labelled = page.evaluate("""() => Object.fromEntries([...document.querySelectorAll('[data-wb-exercise]')]
      .map(box => [box.value, document.querySelector(`label[for="${box.id}"] [data-wb-same-answer]`)?.textContent ?? null]))""")
    expected = {ex.id: copying.same_answer(ex) for ex in bank.all_exercises()}
    assert set(labelled) == set(expected)
    for ex_id, why in expected.items():
        if why:
            assert labelled[ex_id] == f" (students may share this answer: {why})", ex_id
        else:
            assert labelled[ex_id] is None, ex_id
    assert expected["0.6"] and expected["0.3"] and not expected["0.1"]  # a Derive that cannot vary, a Trace, one that does
