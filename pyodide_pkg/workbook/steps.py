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
answers to the steps so far (``"steps": {"FP": ..., ...}``). A step whose answer
is wrong but follows from the learner's own wrong earlier step is *carried*
(tag ``carried``, ``data.carried.step`` names the step it follows from); a final
answer checked with steps does the same, and when it is wrong
``data.steps.first`` names the first step the learner has not got right (the one
to look at first), or the first step when none were tried.

>>> from workbook import bank
>>> ex = bank.get("3.8")
>>> [s.name for s in ex.steps]
['FP', 'FPF']
>>> fp = ex.step_answers["FP"]
>>> grade_step(ex, "FP", fp.typed(fp.key), {}).status
'correct'
>>> wrong = [[2 * x for x in row] for row in fp.key]
>>> later = ex.carried_steps({"FP": wrong})["FPF"]
>>> v = grade_step(ex, "FPF", later.typed(later.key), {"FP": fp.typed(wrong)})
>>> v.status, v.tag, v.data["carried"]["step"]
('incorrect', 'carried', 'FP')
>>> off = ex.answer.typed([[x + 1 for x in row] for row in ex.answer.key])
>>> grade_final(ex, off, {"FP": fp.typed(fp.key)}, ex.check(off)).data["steps"]
{'first': 'FPF', 'number': 2, 'label': 'F P Fᵀ'}
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from . import chains
from .answer_kinds.base import AnswerKind, AnswerSpec
from .chains import value_of
from .contract import TAG
from .verdict import GradingError, Verdict, quote

Derive = Any  # a workbook.kinds.derive.Derive (which imports this module, so not imported here)

PREFIX = "step_"  # the derivation's placeholder for a step's value: {{step_FP}}
MAX_STEPS = 12  # steps a request may carry


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
    return {s.name: s.answer.build(f"{ex_id} (step {s.name})", **made[s.name]) for s in declared}


def number_of(ex: Derive, name: str) -> int:
    """A step's number as the page shows it (1-based)."""
    return 1 + [s.name for s in ex.steps].index(name)


def _step(ex: Derive, name: object) -> Step:
    for s in ex.steps:
        if s.name == name:
            return s
    if not ex.steps:
        raise GradingError("bad-request", f"Exercise {ex.id} has no steps.")
    raise GradingError("bad-request", f"Exercise {ex.id} has no step {quote(name)} "
                       f"(its steps: {', '.join(s.name for s in ex.steps)}).")


def answer_of(ex: Derive, name: object) -> AnswerKind:
    """Step ``name``'s answer kind (for the ``split`` and ``read`` ops)."""
    return ex.step_answers[_step(ex, name).name]


def _status(kind: AnswerKind, answer: object) -> tuple[str, Any]:
    """How ``answer`` stands against ``kind``: its status and the value read (None when unreadable)."""
    reading = kind.reader.read(kind, answer)
    if isinstance(reading, Verdict):
        return "invalid", None
    return kind.marker.mark(kind, reading).status, value_of(reading)


def wrong_steps(ex: Derive, sent: Mapping[str, Any], before: str | None = None) -> dict[str, Any]:
    """The learner's step values that are wrong, by name, for the steps before ``before`` (all when
    None); make() then carries each of them, as the learner did, into the later ones. A step left
    out or unreadable ends the walk."""
    wrong: dict[str, Any] = {}
    for s in ex.steps:
        if s.name == before or s.name not in sent:
            break
        status, value = _status(ex.step_answers[s.name], sent[s.name])
        if status == "invalid":
            break
        if status != "correct":
            wrong[s.name] = value
    return wrong


def first_step(ex: Derive, sent: Mapping[str, Any]) -> str:
    """The first step the learner has not got right, or the first step when none was tried."""
    for s in ex.steps:
        if s.name not in sent or _status(ex.step_answers[s.name], sent[s.name])[0] != "correct":
            return s.name
    return ex.steps[0].name


def _step_carried(ex: Derive, name: str) -> Verdict:
    step = _step(ex, name)
    n = number_of(ex, name)
    return Verdict("incorrect", f"This follows correctly from your {step.label} in step {n}, but that step is "
                   f"wrong: the slip is in step {n}. Fix it there, and this will follow.",
                   tag=TAG.carried, data={"carried": {"step": name, "link": f"Back to step {n}"}})


def _follows(check: Any, answer: object) -> bool:
    try:
        return check().check(answer).status == "correct"
    except (ValueError, ArithmeticError, TypeError, KeyError):
        return False


def grade_step(ex: Derive, name: object, answer: object, sent: Mapping[str, Any],
               chain: tuple[dict, dict] = ({}, {})) -> Verdict:
    """The verdict on step ``name``: carried when it follows from the learner's wrong earlier steps,
    or from the wrong earlier exercises' values ``chain`` (``chains.wrong_values``: values, links)."""
    step = _step(ex, name)
    verdict = ex.step_answers[step.name].check(answer)
    values, links = chain
    if verdict.status != "incorrect":
        return verdict
    wrong = wrong_steps(ex, sent, before=step.name)
    if not wrong and not values:
        return verdict
    if not _follows(lambda: ex.carried_steps({**values, **wrong})[step.name], answer):
        return verdict
    return _step_carried(ex, next(iter(wrong))) if wrong else chains.carried_verdict(values, links)


def grade_final(ex: Derive, answer: object, sent: Mapping[str, Any], verdict: Verdict,
                chain: tuple[dict, dict] = ({}, {})) -> Verdict:
    """The final answer's ``verdict`` (from :func:`chains.follow`) with the learner's steps: carried
    when the answer follows from a wrong step; when wrong, ``data.steps`` names the step to look at."""
    if verdict.status != "incorrect" or verdict.tag == TAG.carried or not ex.steps:
        return verdict
    values = chain[0]
    wrong = wrong_steps(ex, sent)
    if wrong and _follows(lambda: ex.carried_answer({**values, **wrong}), answer):
        return _step_carried(ex, next(iter(wrong)))
    first = first_step(ex, sent)
    return Verdict(verdict.status, verdict.message, tag=verdict.tag,
                   data={**verdict.data, "steps": {"first": first, "number": number_of(ex, first),
                                                   "label": _step(ex, first).label}})


def check_sent(sent: object) -> None:
    """``steps`` in a request: at most a few answers by step name."""
    if not isinstance(sent, dict):
        raise GradingError("bad-request", "This request's steps are not {name: answer}.")
    if len(sent) > MAX_STEPS:
        raise GradingError("bad-request", f"This request carries {len(sent)} steps; at most {MAX_STEPS}.")
