"""Checked steps: a long Derive exercise worked one intermediate quantity at a time.

An exercise declares its steps in the bank, next to its generator, in the order
they are worked::

    steps=(Step("FP", "F P", matrix(label="F P")),
           Step("FPF", "F P Fᵀ", matrix(label="F P Fᵀ"))),

Its ``make(p, given=None)`` returns, beside the final answer's options, each
step's options under ``"steps"`` (``{"FP": {"key": ..., "slips": (...)}, ...}``),
and when ``given`` holds a step's name it uses the learner's value for that
intermediate in every later step and in the final key
(``chains.given(given, "FP", FP)``), exactly as it does for an earlier exercise's
value (:mod:`workbook.chains`). So a step's key comes from the same ``make()`` as
the final answer, and error is carried forward from step to step by the
generator itself, never by a copied formula.

The derivation prints each step's value through the placeholder
``{{step_NAME}}``, which the step's answer kind fills with its worked answer (as
``{{worked}}`` is filled for the final answer): what the derivation prints for a
step is what that step accepts.

A grade request for a step names it (``"step": "FP"``) and carries the learner's
answers to the steps so far (``"steps": {"FP": ..., ...}``); the exercise grades
it (``Derive.grade``, :mod:`workbook.carried`): a step whose answer is wrong but
follows from the learner's own wrong earlier step is *carried* (tag ``carried``,
``data.carried.step`` names the step where the slip is); a wrong final answer
checked with steps says in ``data.steps.first`` which step to look at first.

>>> from workbook import bank
>>> ex = bank.get("3.8")
>>> [s.name for s in ex.steps]
['FP', 'FPF']
>>> fp = ex.step_answers["FP"]
>>> ex.grade(fp.typed(fp.key), step="FP").status
'correct'
>>> wrong = [[2 * x for x in row] for row in fp.key]
>>> later = ex.carried_steps({"FP": wrong})["FPF"]
>>> v = ex.grade(later.typed(later.key), steps={"FP": fp.typed(wrong)}, step="FPF")
>>> v.status, v.tag, v.data["carried"]["step"]
('incorrect', 'carried', 'FP')
>>> off = ex.answer.typed([[x + 1 for x in row] for row in ex.answer.key])
>>> ex.grade(off, steps={"FP": fp.typed(fp.key)}).data["steps"]
{'first': 'FPF', 'number': 2, 'label': 'F P Fᵀ'}
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from .answer_kinds.base import AnswerKind, AnswerSpec
from .contract import LIMIT
from .verdict import GradingError

PREFIX = "step_"  # the derivation's placeholder for a step's value: {{step_FP}}
MAX_STEPS = LIMIT.steps  # steps a request may carry


@dataclass(frozen=True)
class Step:
    """One intermediate quantity: ``name`` is ``make()``'s (in ``given`` and under ``"steps"``),
    ``label`` says what it is in the learner's words (plain text, Unicode: ``F P Fᵀ``)."""

    name: str
    label: str
    answer: AnswerSpec


def placeholder(name: str) -> str:
    return PREFIX + name


def build(ex_id: str, declared: tuple[Step, ...], made: Mapping[str, Any] | None) -> dict[str, AnswerKind]:
    """Each declared step's answer kind, built from ``make()``'s ``"steps"``; the names must agree."""
    made = dict(made or {})
    names = [s.name for s in declared]
    if sorted(made) != sorted(names):
        raise ValueError(f"exercise {ex_id}: its steps are {names}, but make() returns steps {sorted(made)}")
    return {s.name: s.answer.build(f"{ex_id} (step {s.name})", slips_of=ex_id, **made[s.name]) for s in declared}


def check_sent(sent: object) -> None:
    """``steps`` in a request: at most a few answers by step name."""
    if not isinstance(sent, dict):
        raise GradingError("bad-request", "This request's steps are not {name: answer}.")
    if len(sent) > MAX_STEPS:
        raise GradingError("bad-request", f"This request carries {len(sent)} steps; at most {MAX_STEPS}.")
