"""Every chapter page renders all its exercises, and at least one exercise of
every kind on it is solved in the browser, using answers from the grading
package (the same source of truth the page grades against)."""

from __future__ import annotations

import pytest

from helpers import go_instantly, open_chapter, solve
from workbook import bank


@pytest.mark.parametrize("chapter", bank.chapters())
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
    """Every Derive answer, typed as the derivation's worked answer, graded by the worker."""
    for i, chapter in enumerate(bank.chapters()):
        if i == 0:
            open_chapter(page, site_url, chapter)
        else:  # one grader for the whole tour: the next chapter by instant navigation
            go_instantly(page, site_url, chapter)
        for ex in bank.chapter(chapter):
            if ex.kind == "derive":
                assert solve(page, ex) == "correct", ex.id
