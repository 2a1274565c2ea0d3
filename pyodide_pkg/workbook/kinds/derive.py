"""Derive: work a number, a vector, a matrix or a formula out by hand; graded against a key from the reference code.

A Derive exercise holds its answer kind (``spec=number(...)``, ``matrix(...)``
or ``formula(...)``, :mod:`workbook.answer_kinds`), which reads, marks and
shows the answer, and its generator (``vary=Vary(make, ...)``,
:mod:`workbook.variants`), which draws the numbers. ``make(p)`` returns the
answer's options for that draw (``key``, ``slips``, ``label``, ...), perhaps a
``title``, and the ``values`` that fill the chapter's ``{{name}}``
placeholders; ``{{worked}}`` is filled by the answer kind itself, so the
derivation's Answer line is the worked answer. A name ``make()`` returns that
neither the exercise nor its answer kind has fails the build with the id.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field, replace
from functools import cached_property
from types import MappingProxyType
from typing import Any, ClassVar

from .. import carried
from .. import steps as stepwise
from ..answer_kinds.base import AnswerKind, AnswerSpec
from ..chains import Uses
from ..contract import ATTR
from ..number_format import fmt
from ..reference.domain import Undefined
from ..variants import VariantError, Vary, check_seed
from ..verdict import GradingError, Verdict, quote
from .base import Exercise

WORKED = "worked"  # the placeholder the answer kind fills: the Answer line's value, in TeX
# what make(p, given=...) returns in place of the key when the learner's values leave the answer undefined (a
# θ2 of ±180° reaches no θ1): why, in their words, beside the steps that those values still define
UNDEFINED = "undefined"


@dataclass(frozen=True)
class _Draw:
    """One draw's exercise: what ``make(p)`` gave, built (frozen, and read through read-only views:
    variants that drew the same numbers share it)."""

    title: str | None
    steps: Mapping[str, AnswerKind]
    answer: AnswerKind
    values: Mapping[str, str]
    problem: str | None  # why the draw is not a fair question, or None
    params: Mapping[str, Any]  # the draw's parameters


def _view(mapping: Mapping[str, Any]) -> Mapping[str, Any]:
    """A read-only copy: a draw is shared by the variants that drew it, so none may change it."""
    return MappingProxyType(dict(mapping))


def _degenerate_step(kinds: Mapping[str, AnswerKind]) -> str | None:
    for name, kind in kinds.items():
        problem = kind.degenerate()
        if problem:
            return f"step {name}: {problem}"
    return None


_DRAWS: dict[Vary, dict[Any, _Draw]] = {}  # each generator's draws made so far
_DRAWS_KEPT = 4096  # per generator; a full memory starts again


@dataclass(frozen=True)
class Derive(Exercise):
    """A Derive exercise: its answer kind, its generator and the variant on screen.

    The fields are what the bank writes, and they never change: what the variant's draw gives (its
    answer, its steps' answer kinds, the template's values, the parameters) is computed once, when the
    exercise is made, kept in :attr:`drawn` (read-only) and handed out as copies. :meth:`variant` makes
    another exercise, with the other draw's title, by :func:`dataclasses.replace`.
    """

    spec: AnswerSpec | None = None  # what the bank writes: spec=number(...), matrix(...) or formula(...)
    vary: Vary | None = field(default=None, compare=False, repr=False)
    seed: int = 0  # the variant: 0 is the workbook's numbers
    uses: tuple[Uses, ...] = field(default=(), compare=False, repr=False)  # the earlier results it builds on
    steps: tuple[stepwise.Step, ...] = field(default=(), compare=False, repr=False)  # its checked steps, in order
    kind: ClassVar[str] = "derive"
    reveal_label: ClassVar[str] = "Show derivation"

    def __post_init__(self) -> None:
        if self.spec is None:
            raise ValueError(f"exercise {self.id}: a Derive exercise needs spec=number(...), matrix(...) "
                             "or formula(...)")
        if self.vary is None and self.steps:
            raise ValueError(f"exercise {self.id}: steps need a generator (vary=Vary(make, ...))")
        self.drawn  # noqa: B018  (the draw is made now: a variant with no fair draw fails here, with its id)

    @cached_property
    def drawn(self) -> _Draw:
        """This variant's draw: the first well-posed one of the generator's candidates for the seed."""
        spec = self.spec
        assert spec is not None  # __post_init__
        if self.vary is None:
            answer = spec.build(self.id)
            return _Draw(None, _view({}), answer, _view({WORKED: answer.worked_tex()}), None, _view({}))
        for p in self.vary.candidates(self.id, self.seed):
            draw = self._draw(spec, p)
            if draw.problem is None:
                return draw
            if self.seed == 0:
                raise VariantError(f"exercise {self.id}: the workbook's own numbers are degenerate: {draw.problem}")
        raise VariantError(f"exercise {self.id}: no well-posed draw for variant {self.seed}")

    @property
    def answer(self) -> AnswerKind:
        """This variant's answer kind, built from ``spec`` with the draw's options."""
        return self.drawn.answer

    @property
    def step_answers(self) -> Mapping[str, AnswerKind]:
        return dict(self.drawn.steps)  # a copy of its own: the draw is shared, and the copy is plain data

    @property
    def values(self) -> Mapping[str, str]:
        """The template's fill: the draw's values and the worked answers."""
        return dict(self.drawn.values)  # a copy of its own: the draw is shared, and the copy is plain data

    @property
    def params(self) -> Mapping[str, Any]:
        """This variant's parameters (empty without a generator)."""
        return dict(self.drawn.params)  # a copy of its own: the draw is shared, and the copy is plain data

    def _draw(self, spec: AnswerSpec, p: Mapping[str, Any]) -> _Draw:
        """What the draw ``p`` makes: the same parameters always make the same exercise, so a
        draw made before (another seed drew the same numbers) is taken from the generator's memory."""
        assert self.vary is not None
        try:
            key: Any = (self.id, id(spec), tuple(sorted(p.items())))
            hash(key)
        except TypeError:
            return self._make(spec, p)
        memory = _DRAWS.setdefault(self.vary, {})
        if key not in memory:
            if len(memory) >= _DRAWS_KEPT:
                memory.clear()
            memory[key] = self._make(spec, p)
        return memory[key]

    def _make(self, spec: AnswerSpec, p: Mapping[str, Any]) -> _Draw:
        assert self.vary is not None
        made = dict(self.vary.make(p))
        values = {name: fmt(v) if isinstance(v, (int, float)) and not isinstance(v, bool) else str(v)
                  for name, v in p.items()}
        values.update(made.pop("values", {}))
        if WORKED in values:
            raise VariantError(f"exercise {self.id}: {{{{{WORKED}}}}} is filled by the answer kind, not by make()")
        if UNDEFINED in made:
            raise VariantError(f"exercise {self.id}: the draw {dict(p)} leaves the answer undefined: {made[UNDEFINED]}")
        title = made.pop("title", None)
        steps = self._step_kinds(made.pop("steps", None), values)
        answer = spec.build(self.id, **made)
        problem = answer.degenerate() or _degenerate_step(steps)
        return _Draw(title, _view(steps), answer, _view({**values, WORKED: answer.worked_tex()}), problem, _view(p))

    def _step_kinds(self, made: Mapping[str, Any] | None, values: dict[str, str]) -> dict[str, AnswerKind]:
        """Build the steps' answer kinds; ``{{step_NAME}}`` prints each one's worked answer."""
        if not self.steps and made is None:
            return {}
        kinds = stepwise.build(self.id, self.steps, made)
        for name, kind in kinds.items():
            key = stepwise.placeholder(name)
            if key in values:
                raise VariantError(f"exercise {self.id}: {{{{{key}}}}} is filled by the step's answer kind, not by "
                                   "make()")
            values[key] = kind.worked_tex()
        return kinds

    def variant(self, seed: object) -> Derive:
        """This exercise with variant ``seed``'s numbers (0: the workbook's own)."""
        seed = check_seed(seed)
        if self.vary is None or seed == self.seed:
            return self
        other = replace(self, seed=seed)
        title = other.drawn.title
        return other if title is None or title == other.title else replace(other, title=title)

    def carried_answer(self, given: Mapping[str, Any]) -> AnswerKind:
        """This variant's answer with ``given`` (the learner's earlier values, by the names
        ``make()`` takes) in place of the printed ones: the key recomputed by the generator."""
        vary, spec = self._generator()
        made = dict(vary.make(self.params, given=given))
        for name in ("values", "title", "steps"):
            made.pop(name, None)
        if UNDEFINED in made:  # the learner's values leave the answer undefined, though their steps stand
            raise Undefined(made[UNDEFINED])
        return spec.build(self.id, **made)

    def carried_steps(self, given: Mapping[str, Any]) -> dict[str, AnswerKind]:
        """The steps' answer kinds with ``given`` in place of the printed values, by the generator."""
        vary, _ = self._generator()
        return stepwise.build(self.id, self.steps, vary.make(self.params, given=given).get("steps"))

    def _generator(self) -> tuple[Vary, AnswerSpec]:
        """The generator and the answer's spec (an exercise that carries values forward has both)."""
        if self.vary is None or self.spec is None:
            raise ValueError(f"exercise {self.id}: a carried value needs a generator (vary=Vary(make, ...))")
        return self.vary, self.spec

    # ---- what the page and the worker ask: the answer kind answers ----------------
    @property
    def answer_kind(self) -> str:
        return self.answer.kind

    def attributes(self) -> dict[str, str]:
        uses = {ATTR.uses: " ".join(dict.fromkeys(u.source for u in self.uses))} if self.uses else {}
        steps = {ATTR.steps: " ".join(s.name for s in self.steps)} if self.steps else {}
        return {ATTR.answerKind: self.answer.kind, **self.answer.attributes(), **uses, **steps}

    def check(self, answer: object) -> Verdict:
        return self.answer.check(answer)

    def grade(self, answer: object, given: Mapping[str, Any] | None = None, steps: Mapping[str, Any] | None = None,
              step: str | None = None, lookup: Callable[[str, int], Derive] | None = None) -> Verdict:
        """The verdict on ``answer`` to this exercise, or to its step ``step``, with error carried
        forward (:mod:`workbook.carried`) from the learner's answers to the earlier exercises it
        builds on (``given``: {ID: {answer, variant}}, found with ``lookup(id, seed)``) and to its
        steps (``steps``: {name: answer})."""
        if step is not None:
            self.step_kind(step)  # a step it has, or a bad-request
        if given and lookup is None:
            raise ValueError("grading with the learner's earlier answers needs lookup(id, seed)")
        return carried.grade(self, answer, given or {}, steps or {}, step, lookup or _no_lookup)

    def step_kind(self, name: object) -> AnswerKind:
        """Step ``name``'s answer kind; a ``bad-request`` naming the exercise's steps when it has none such."""
        if isinstance(name, str) and name in self.step_answers:
            return self.step_answers[name]
        if not self.steps:
            raise GradingError("bad-request", f"Exercise {self.id} has no steps.")
        raise GradingError("bad-request", f"Exercise {self.id} has no step {quote(name)} "
                           f"(its steps: {', '.join(s.name for s in self.steps)}).")

    def read(self, answer: object) -> dict:
        return self.answer.read(answer)

    def split(self, text: object) -> dict:
        return self.answer.split(text)

    def worked_text(self) -> str:
        return self.answer.worked_text()

    def worked_html(self) -> str:
        return self.answer.worked_html()

    def label_html(self) -> str:
        return self.answer.label_html()

    def widget(self, base: str, page: Any) -> str:
        return self.answer.widget(base, page)


def _no_lookup(exercise_id: str, seed: int) -> Derive:
    raise KeyError(exercise_id)


EXERCISE = Derive
