"""Error carried forward: a Derive answer judged against the learner's own earlier values.

A Derive exercise may build on earlier exercises' results (:mod:`workbook.chains`)
and be worked in checked steps (:mod:`workbook.steps`). When an answer (or a step)
is wrong, the grader asks whether it follows from what the learner wrote before:

- the learner's values are used **as typed**: every readable step before the one
  graded (right or wrong), and the learner's wrong answers to the earlier
  exercises; a step left out is recomputed by the generator;
- the key is recomputed by the exercise's own generator, ``make(p, given=...)``,
  and each entry is compared as a direct answer's entry is (``tolerance.agrees``),
  except an entry that cancels to near 0 on the question's scale (no larger than
  1e-3 of its largest entry): that one is within that much, as a key of 0 is,
  not judged on figures;
- when it follows, the verdict names the **last** of the learner's wrong values it
  follows from (replacing that value by the right one would break it), and where
  that value's slip started: a step of this exercise, an earlier exercise, or,
  through a chain of chains, the exercise where the first slip was made;
- when the learner's values leave the quantity undefined (an offset of (0, 0) has
  no bearing, a division by zero, a singular matrix), it says so in words, names
  where the slip is, and credits nothing; a named slip of the exercise still wins.

>>> from workbook import bank
>>> ex = bank.get("4.1")
>>> d = ex.step_answers["d"]
>>> wrong_d = d.typed(((300.0,), (400.0,)))
>>> grade(ex, "500", {}, {"d": wrong_d}, None, bank.variant).tag     # q recomputed from d
'carried'
>>> grade(ex, "500", {}, {"d": wrong_d, "q": "25"}, None, bank.variant).tag  # q typed: √25 = 5
''
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any, Protocol

from .answer_kinds.base import AnswerKind
from .chains import Uses, value_of
from .contract import TAG
from .number_format import prose
from .reference.domain import Undefined
from .steps import Step
from .tolerance import FIGURES, REL, agrees, clean
from .typed_rounding import half_units, spread
from .verdict import Verdict


class Worked(Protocol):
    """What error carried forward needs of a Derive exercise (a variant of it)."""

    @property
    def id(self) -> str: ...

    @property
    def uses(self) -> tuple[Uses, ...]: ...

    @property
    def steps(self) -> tuple[Step, ...]: ...

    @property
    def step_answers(self) -> Mapping[str, AnswerKind]: ...

    @property
    def params(self) -> Mapping[str, Any]: ...

    @property
    def answer(self) -> AnswerKind: ...

    def carried_answer(self, given: Mapping[str, Any]) -> AnswerKind: ...

    def carried_steps(self, given: Mapping[str, Any]) -> dict[str, AnswerKind]: ...

    def grade(self, answer: object, given: Mapping[str, Any] | None = None, steps: Mapping[str, Any] | None = None,
              step: str | None = None, lookup: Callable[[str, int], Any] | None = None) -> Verdict: ...


Lookup = Callable[[str, int], Worked]
# What a generator raises when a learner's value takes it off its model (a root of a negative, a missing key)
OFF_THE_MODEL = (ArithmeticError, ValueError, TypeError, KeyError)  # an exercise's variant, by id and seed


@dataclass(frozen=True)
class Place:
    """Where a slip is: step ``step`` of this exercise, or exercise ``exercise`` (at ``variant``)."""

    step: str = ""
    exercise: str = ""
    variant: int = 0


@dataclass(frozen=True)
class Value:
    """One of the learner's values that ``make()`` takes by ``name``: ``value`` as typed, ``wrong``
    or not, ``says`` (how to name it), ``home`` (the step or exercise it was typed in), ``place``
    (where its slip is: ``home``, or where the value it follows from went wrong) and, for a step,
    ``right``: its key."""

    name: str
    value: Any
    wrong: bool
    says: str
    home: Place
    place: Place
    right: Any = None
    half: Any = None  # a typed step's half units (workbook.typed_rounding), 0 where taken as exact

    def corrected(self, values: list[Value]) -> list[Value]:
        """``values`` with this one made right: a step's key in its place, an earlier exercise's
        value left out (the generator then uses the printed one)."""
        if self.home.exercise:
            return [v for v in values if v is not self]
        return [Value(v.name, v.right, False, v.says, v.home, v.home) if v is self else v for v in values]


def _shown(value: Any) -> str:
    if isinstance(value, float) and math.isfinite(value):
        return prose(clean(value))
    if isinstance(value, tuple) and all(len(row) == 1 for row in value):
        entries = [v for (v,) in value]
        if all(isinstance(v, float) and math.isfinite(v) for v in entries):
            return "(" + ", ".join(prose(clean(v)) for v in entries) + ")"
    return ""


def _number(ex: Worked, name: str) -> int:
    return 1 + [s.name for s in ex.steps].index(name)


def _label(ex: Worked, name: str) -> str:
    return next(s.label for s in ex.steps if s.name == name)


def _step_says(ex: Worked, name: str) -> str:
    return f"your {_label(ex, name)} in step {_number(ex, name)}"


# ---- the learner's values ---------------------------------------------------------------------------
def earlier_values(ex: Worked, sent: Mapping[str, Any], lookup: Lookup) -> list[Value]:
    """The learner's wrong answers to the earlier exercises this one uses, each with where its slip
    started (an earlier answer that itself followed from a wrong one points to that one's place)."""
    out = []
    for link in ex.uses:
        earlier = sent.get(link.source)
        variant = link.variant(ex.params)
        if not isinstance(earlier, Mapping) or variant is None or earlier.get("variant", 0) != variant:
            continue
        source = lookup(link.source, variant)
        reading = source.answer.reader.read(source.answer, earlier.get("answer"))
        if isinstance(reading, Verdict) or source.answer.marker.mark(source.answer, reading).status == "correct":
            continue
        own = source.grade(earlier.get("answer"), given=sent, lookup=lookup)
        back = own.data.get("carried", {}) if own.tag in (TAG.carried, TAG.undefined) else {}
        place = (Place(exercise=back["from"], variant=back.get("variant", 0)) if back.get("from")
                 else Place(exercise=link.source, variant=variant))
        value = value_of(reading)
        shown = _shown(value)
        says = f"your {link.what}" + (f" = {shown}" if shown else "") + f" from exercise {link.source}"
        out.append(Value(link.name, value, True, says, Place(exercise=link.source, variant=variant), place))
    return out


def step_values(ex: Worked, mine: Mapping[str, Any], before: str | None, earlier: list[Value],
                lookup: Lookup) -> list[Value]:
    """The learner's readable steps before ``before`` (all, when None), as typed; a wrong one's
    place is where the value it follows from went wrong, or the step itself."""
    out: list[Value] = []
    for s in ex.steps:
        if s.name == before:
            break
        if s.name not in mine:
            continue
        kind = ex.step_answers[s.name]
        reading = kind.reader.read(kind, mine[s.name])
        if isinstance(reading, Verdict):
            continue
        value, half = value_of(reading), half_units(reading)
        home = Place(step=s.name)
        if kind.marker.mark(kind, reading).status == "correct":
            out.append(Value(s.name, value, False, _step_says(ex, s.name), home, home, half=half))
            continue
        found = _follows_from(ex, s.name, mine[s.name], earlier + out)
        place = found.place if isinstance(found, Value) else home
        out.append(Value(s.name, value, True, _step_says(ex, s.name), home, place, right=kind.key, half=half))
    return out


# ---- does an answer follow from them? --------------------------------------------------------------
def _carried_kind(ex: Worked, step: str | None, given: Mapping[str, Any]) -> AnswerKind:
    if step is None:
        return ex.carried_answer(given)
    return ex.carried_steps(given)[step]


def _entries(key: Any) -> list[float]:
    return [float(v) for row in key for v in row] if isinstance(key, tuple) else [float(key)]


def _agrees(kind: AnswerKind, answer: object, target: AnswerKind, room: list[float] | None = None) -> bool:
    """``answer`` (read as ``kind`` reads it) agrees with ``target``'s key, entry by entry as a
    direct answer does. The scale of the question (the largest of the right key's and the
    recomputed key's entries) sets a floor for the entries that cancel only: an entry of the
    recomputed key within 1e-3 of that scale of 0 takes any value within as much of it. Every
    other entry is held to its own figures: a floor for all of them would credit 0.101 for 0.1
    beside an entry of 3.8, which a direct answer's check refuses."""
    reading = kind.reader.read(kind, answer)
    if isinstance(reading, Verdict):
        return False
    wanted = _entries(target.key)
    if not all(math.isfinite(w) for w in wanted):
        raise Undefined("the result is not a finite number")
    floors = [REL * scale for scale in _scales(kind.key, target.key)]
    rows = reading if isinstance(reading, list) else [[reading]]
    got = [
        (r.value, r.half_unit if r.figures is not None and r.figures >= FIGURES else None) for row in rows for r in row
    ]
    if len(got) != len(wanted):
        return False
    turn = (
        {"deg": 360.0, "rad": math.tau}.get(getattr(kind, "angle", None) or "")
        if getattr(kind, "periodic", False)
        else None
    )
    for (value, half), want, floor, moves in zip(got, wanted, floors, room or [0.0] * len(wanted)):
        want = clean(want)
        if turn:
            value = want + math.remainder(value - want, turn)
        floor = max(floor if abs(want) <= floor else 0.0, moves)  # an entry that cancels; the inputs' rounding
        if not agrees(value, want, rel=getattr(kind, "rel_tol", REL), half_unit=half, floor=floor):
            return False
    return True


def _scales(right: Any, recomputed: Any) -> list[float]:
    """Each entry's scale, for the floor of an entry that cancels: a number's is the larger of the right key and
    the recomputed one; a matrix entry's is the largest recomputed entry in its row and its column, the terms
    that meet in it. An entry far from the others (5.7's Ω₃₃ = 1000 beside an x–y block of 0.02) lends its
    size to none of them, so a block made small by a wrong determinant is held to its own figures.

    >>> _scales(2.0, 3e-9), _scales(((1.0, 0.0), (0.0, 1000.0)), ((0.02, 0.0), (0.0, 1000.0)))
    ([2.0], [0.02, 1000.0, 1000.0, 1000.0])
    """
    if not isinstance(recomputed, tuple):
        return [max(abs(float(right)), abs(float(recomputed)))]
    rows = [[abs(float(v)) for v in row] for row in recomputed]
    return [max(max(row), max(r[j] for r in rows)) for row in rows for j in range(len(row))]


def _follows(ex: Worked, step: str | None, answer: object, values: list[Value]) -> bool:
    """``answer`` agrees with the key worked from ``values``, or with one the typed steps' own rounding
    allows (:mod:`workbook.typed_rounding`)."""
    kind = ex.answer if step is None else ex.step_answers[step]
    given = {v.name: v.value for v in values}
    target = _carried_kind(ex, step, given)
    if _agrees(kind, answer, target):
        return True
    halves = {v.name: v.half for v in values if v.half is not None}
    room = spread(lambda g: _entries(_carried_kind(ex, step, g).key), given, halves) if halves else None
    return room is not None and _agrees(kind, answer, target, room)


def _follows_from(ex: Worked, step: str | None, answer: object, values: list[Value]) -> Value | Undefined | None:
    """The last wrong value ``answer`` follows from (None: it follows from none of them), or the
    :class:`Undefined` the learner's values lead to."""
    wrong = [v for v in values if v.wrong]
    if not wrong:
        return None
    try:
        if not _follows(ex, step, answer, values):
            return None
    except Undefined as err:
        return err
    except ZeroDivisionError:
        return Undefined("the formula divides by zero")
    except OverflowError:
        return Undefined("a value in the formula grows without bound")
    except ValueError as err:
        text = str(err)
        if "singular" in text:
            return Undefined("the matrix it must invert is singular")
        if "out of reach" in text:
            return Undefined(f"the {text}")
        return Undefined("it takes a square root or an inverse cosine outside its domain")
    for v in reversed(wrong):
        try:
            if not _follows(ex, step, answer, v.corrected(values)):
                return v
        except OFF_THE_MODEL:
            return v
    right = values
    for v in wrong:
        right = v.corrected(right)
    try:  # no one value is needed: the answer follows from them together, or from none (it is near the key)
        return None if _follows(ex, step, answer, right) else wrong[-1]
    except OFF_THE_MODEL:
        return wrong[-1]


# ---- the verdicts ------------------------------------------------------------------------------------
def _place_says(ex: Worked, place: Place) -> str:
    return f"step {_number(ex, place.step)}" if place.step else f"exercise {place.exercise}"


def _link(ex: Worked, place: Place) -> dict[str, Any]:
    if place.step:
        n = _number(ex, place.step)
        return {"step": place.step, "link": f"Back to step {n}"}
    return {"from": place.exercise, "variant": place.variant, "link": f"Back to exercise {place.exercise}"}


def _origin_says(ex: Worked, place: Place) -> str:
    return _step_says(ex, place.step) if place.step else f"your answer to exercise {place.exercise}"


def carried_verdict(ex: Worked, value: Value) -> Verdict:
    """Right given the learner's wrong ``value``: say which value, and where its slip is."""
    where = _place_says(ex, value.place)
    if value.place == value.home:
        what = "step" if value.place.step else "value"
        fix = "this will follow" if value.place.step else "carry the right value here"
        text = (f"This follows correctly from {value.says}, but that {what} is wrong: the slip is in {where}. "
                f"Fix it there, and {fix}.")
    else:
        text = (f"This follows correctly from {value.says}, which follows from {_origin_says(ex, value.place)}: "
                f"the slip is in {where}. Fix it there, and the rest will follow.")
    return Verdict("incorrect", text, tag=TAG.carried, data={"carried": _link(ex, value.place)})


def undefined_verdict(ex: Worked, value: Value | None, why: Undefined) -> Verdict:
    """The learner's own values leave this quantity undefined: nothing can follow from them."""
    if value is None:
        return Verdict("incorrect", f"With your values, this is not defined: {why}. Check your earlier work.",
                       tag=TAG.undefined)
    return Verdict("incorrect", f"With {value.says}, {why}: nothing here can follow from it. "
                   f"The slip is in {_place_says(ex, value.place)}: fix it there first.",
                   tag=TAG.undefined, data={"carried": _link(ex, value.place)})


def _first_step(ex: Worked, mine: Mapping[str, Any]) -> str | None:
    """The first step the learner has not got right (the first step when none was tried); None
    when every step is typed and right, so the slip is in the last line."""
    for s in ex.steps:
        if s.name not in mine or ex.step_answers[s.name].check(mine[s.name]).status != "correct":
            return s.name
    return None


def grade(ex: Worked, answer: object, given: Mapping[str, Any], mine: Mapping[str, Any], step: str | None,
          lookup: Lookup) -> Verdict:
    """The verdict on ``answer`` to the exercise (``step`` None) or to one of its steps."""
    kind = ex.answer if step is None else ex.step_answers[step]
    verdict = kind.check(answer)
    if verdict.status != "incorrect":
        return verdict
    earlier = earlier_values(ex, given, lookup) if given and ex.uses else []
    values = earlier + (step_values(ex, mine, step, earlier, lookup) if ex.steps else [])
    found = _follows_from(ex, step, answer, values)
    if isinstance(found, Value):
        return carried_verdict(ex, found)
    if isinstance(found, Undefined) and verdict.tag in ("", TAG.close, TAG.sign):
        wrong = [v for v in values if v.wrong]
        return undefined_verdict(ex, _undefining(ex, step, answer, values, wrong), found)
    first = _first_step(ex, mine) if step is None and ex.steps else None
    if first is not None:
        data = {"first": first, "number": _number(ex, first), "label": _label(ex, first)}
        return Verdict(verdict.status, verdict.message, tag=verdict.tag, data={**verdict.data, "steps": data})
    return verdict


def _undefining(ex: Worked, step: str | None, answer: object, values: list[Value], wrong: list[Value]) -> Value | None:
    """The last wrong value without which the quantity is defined again (None: no single one)."""
    for v in reversed(wrong):
        try:
            _follows(ex, step, answer, v.corrected(values))
            return v
        except OFF_THE_MODEL:
            continue
    return wrong[-1] if wrong else None
