"""Every chapter page renders all its exercises, and at least one exercise of
every kind on it is solved in the browser, using answers from the grading
package (the same source of truth the page grades against)."""

from __future__ import annotations

import pytest
from helpers import (role, answer_debug, answer_derive, answer_trace, arrange_design, exercise, open_chapter, run_build,
                     set_editor)

from workbook import bank
from workbook.kinds.derive import fmt


def solve(page, ex) -> str:
    el = exercise(page, ex.id)
    el.scroll_into_view_if_needed()
    if ex.kind == "derive":
        return answer_derive(el, fmt(ex.key) + ("°" if ex.angle == "deg" else ""))
    if ex.kind == "trace":
        return answer_trace(el, ex.answer)
    if ex.kind == "debug":
        return answer_debug(el, ex.bug_line)
    if ex.kind == "design":
        arrange_design(el, list(ex.solution))
        el.locator(role("check")).click()
        page.wait_for_function("el => el.dataset.state !== 'pending'", arg=el.element_handle())
        return el.get_attribute("data-state")
    set_editor(page, el, ex.solution)
    return run_build(el)


@pytest.mark.parametrize("chapter", range(10))
def test_chapter_page_solves_one_of_each_kind(page, site_url, chapter):
    open_chapter(page, site_url, chapter)
    exercises = bank.chapter(chapter)
    ids = page.locator("[data-exercise-id]").evaluate_all("els => els.map(e => e.dataset.exerciseId)")
    assert ids == [e.id for e in exercises]
    # Math is typeset (KaTeX), not left as TeX source.
    assert page.locator(".katex").count() > 0
    first_of_kind = {}
    for ex in exercises:
        first_of_kind.setdefault(ex.kind, ex)
    for kind, ex in first_of_kind.items():
        assert solve(page, ex) == "correct", f"{ex.id} ({kind}) was not accepted"


def test_every_derive_key_is_accepted_in_the_page(page, site_url):
    """All 39 Derive answers, as the derivations print them, graded by the worker."""
    for chapter in range(10):
        open_chapter(page, site_url, chapter)
        for ex in bank.chapter(chapter):
            if ex.kind == "derive":
                assert solve(page, ex) == "correct", ex.id
