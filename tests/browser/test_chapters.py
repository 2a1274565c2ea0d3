"""Every chapter page renders all its exercises, and at least one exercise of
every kind on it is solved in the browser, using answers from the grading
package (the same source of truth the page grades against).

The tests share the module's one tab (``tour``): each grades only its own chapter's
exercises, whose records no other test here reads, and one grader serves them all."""

from __future__ import annotations

import pytest

from helpers import solve
from workbook import bank


@pytest.mark.parametrize("chapter", bank.chapters())
def test_chapter_page_solves_one_of_each_kind(tour, chapter):
    page = tour(chapter)
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


def test_every_derive_key_is_accepted_in_the_page(tour):
    """Every Derive answer, typed as the derivation's worked answer, graded by the worker."""
    for chapter in bank.chapters():
        page = tour(chapter)
        for ex in bank.chapter(chapter):
            if ex.kind == "derive":
                assert solve(page, ex) == "correct", ex.id
