"""Per-student numbers mean per-student answers: over 100 students of one class, at most 1 % of
the pairs share the right answer of any exercise the teach page offers, unless the exercise says
why its answer is the same for everyone (then that is true: the share is above 1 %). Two
students share an answer when one's printed worked answer is graded right for the other's
numbers (workbook.copying). ``python tests/unit/test_copying.py`` prints the table."""

from __future__ import annotations

import sys

import pytest

from workbook import bank, copying

EXERCISES = bank.all_exercises()  # every exercise has a page (the build fails otherwise): the teach page offers all
CLASSES = ("ROB101", "ME-2027 week 3")


@pytest.mark.parametrize("ex", EXERCISES, ids=lambda ex: ex.id)
def test_students_of_a_class_rarely_share_an_answer(ex):
    why = copying.same_answer(ex)
    shares = [copying.exercise_share(ex.id, code) for code in CLASSES]
    if why:
        assert min(shares) > copying.MOST, f"{ex.id} says its answer is the same for everyone ({why}), " \
                                           f"but only {max(shares):.2%} of pairs share it"
    else:
        assert max(shares) <= copying.MOST, f"{ex.id}: {max(shares):.2%} of student pairs share the right answer"


@pytest.mark.parametrize("exercise_id", ["0.7", "2.3", "4.2", "5.2"])  # a matrix, either sign, periodic, steps
def test_the_quick_filter_never_hides_a_shared_answer(exercise_id):
    ids = copying.students(40)
    assert copying.exercise_share(exercise_id, ids=ids) == copying.exercise_share(exercise_id, ids=ids, quick=False)


def test_a_shared_answer_is_found_across_printed_forms():
    # 0.6 prints det R(θ) = 1 for every θ: every pair shares it, whatever the variants.
    assert copying.exercise_share("0.6") == 1.0
    assert copying.same_answer(bank.get("0.6")).startswith("det R(θ) is 1")
    assert copying.same_answer(bank.get("0.3")) == copying.KIND_REASONS["trace"]
    assert copying.same_answer(bank.get("0.1")) == ""


if __name__ == "__main__":
    for ex in EXERCISES:
        print(f"{ex.id:6} {ex.kind:7} {copying.exercise_share(ex.id):7.2%}  {copying.same_answer(ex)}")
    sys.exit(0)
