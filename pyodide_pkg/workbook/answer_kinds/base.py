"""What every answer kind shares: its options, its slips, and what a Derive exercise asks of it.

An answer kind (``number``, ``matrix``, ``expression``) is a package of its own:
``__init__.py`` (the options, as the fields of a frozen dataclass), ``read.py``
(text to values, through :mod:`workbook.expr`), ``mark.py`` (values to a
verdict, slips included) and ``show.py`` (the worked answer, the Answer line's
TeX, the label and the input's HTML). A Derive exercise holds one
(``spec=number(label=...)``); the bank writes the kind's factory, and the
exercise builds it, so an option the kind does not have fails the build with
the exercise's id.

>>> spec = AnswerSpec(AnswerKind, {"label": "x"})
>>> spec.build("0.1", key=2.0).key
2.0
>>> spec.build("0.1", periodic=True)
Traceback (most recent call last):
...
ValueError: exercise 0.1: an answer of kind '' has no option 'periodic' (its options: key, label, slips)
"""

from __future__ import annotations

import dataclasses
import re
from collections.abc import Mapping
from dataclasses import dataclass
from types import ModuleType
from typing import Any, ClassVar

from ..verdict import GradingError, Verdict

SLIP_NAME = re.compile(r"[a-z0-9]+(?:-[a-z0-9]+)*")  # a slip's stable name: lower case words joined by hyphens


@dataclass(frozen=True)
class Slip:
    """A known wrong answer with its own message, matched like the key (a number, rows, or a function).

    ``name`` is its stable name within the exercise (``"cos-minus-one"``): the class page counts it by
    :attr:`id`, ``"6.3/cos-minus-one"``, which no change of wording moves. ``exercise`` is set when the
    exercise builds its answer kind (:meth:`AnswerSpec.build`).
    """

    value: Any
    message: str
    name: str = ""
    exercise: str = ""

    @property
    def id(self) -> str:
        """``exercise/name`` (``"6.3/cos-minus-one"``), or "" for a slip without a name."""
        return f"{self.exercise}/{self.name}" if self.name and self.exercise else ""


def slip_data(slip: Slip) -> dict[str, str]:
    """What a slip's verdict carries besides its message: ``{"slipId": "6.3/cos-minus-one"}`` (none without a name)."""
    return {"slipId": slip.id} if slip.id else {}


@dataclass(frozen=True)
class AnswerKind:
    """Base of the answer kinds; a subclass's fields are its options, and it honours every one.

    A subclass names its package's modules: ``reader`` (``read(ans, answer)`` to values
    or an ``invalid`` verdict, and ``reply(values)`` for the ``read`` op), ``marker``
    (``mark(ans, values)``) and ``shower`` (``worked_text``, ``worked_tex``,
    ``worked_html``, ``typed``, ``label_html``, ``widget``, ``attributes``).
    """

    key: Any = None
    label: str = ""
    slips: tuple[Slip, ...] = ()
    kind: ClassVar[str] = ""
    reader: ClassVar[ModuleType]
    marker: ClassVar[ModuleType]
    shower: ClassVar[ModuleType]

    def check(self, answer: object) -> Verdict:
        values = self.reader.read(self, answer)
        return values if isinstance(values, Verdict) else self.marker.mark(self, values)

    def read(self, answer: object) -> dict:
        """How ``answer`` is read before it is checked (the ``read`` op): ``{value}``, ``{latex}`` or ``{message}``."""
        values = self.reader.read(self, answer)
        return {"message": values.message} if isinstance(values, Verdict) else self.reader.reply(values)

    def split(self, text: object) -> dict:
        """A pasted vector or matrix (the ``split`` op); only shaped answers have entries."""
        raise GradingError("wrong-op", "This exercise takes one value, not a vector or matrix.")

    def worked_text(self) -> str:
        """The answer as a learner would type it."""
        return self.shower.worked_text(self)

    def worked_tex(self) -> str:
        """The answer in TeX, for the derivation's Answer line (the ``{{worked}}`` placeholder)."""
        return self.shower.worked_tex(self)

    def worked_html(self) -> str:
        """The end of the revealed derivation: the answer, typed out (``worked-answer``)."""
        return self.shower.worked_html(self)

    def typed(self, value: Any) -> Any:
        """A value (the key or a slip) as a learner would type it."""
        return self.shower.typed(self, value)

    def label_html(self) -> str:
        return self.shower.label_html(self)

    def widget(self, base: str, page: Any) -> str:
        return self.shower.widget(self, base)

    def attributes(self) -> dict[str, str]:
        return self.shower.attributes(self)

    def degenerate(self) -> str | None:
        """Why these numbers do not make a fair question (the worked answer refused, a slip
        that cannot be told apart), or None."""
        verdict = self.check(self.typed(self.key))
        if verdict.status != "correct":
            return f"its worked answer {self.typed(self.key)!r} is graded {verdict.status}"
        for slip in self.slips:
            said = self.check(self.typed(slip.value))
            if said.message != slip.message:
                return f"the slip {str(self.typed(slip.value))[:60]!r} is graded {said.status}: {said.message!r}"
        return None


@dataclass(frozen=True)
class AnswerSpec:
    """What the bank writes: an answer kind and some of its options; the exercise builds it."""

    cls: type[AnswerKind]
    options: Mapping[str, Any]

    @property
    def kind(self) -> str:
        return self.cls.kind

    def build(self, exercise_id: str, slips_of: str | None = None, **more: Any) -> AnswerKind:
        """The answer kind with these options and ``more`` (a variant's ``make()``); unknown names are errors.
        Its slips are the exercise's, ``slips_of`` (``exercise_id`` unless a step's says otherwise)."""
        names = [f.name for f in dataclasses.fields(self.cls)]
        for name in list(self.options) + list(more):
            if name not in names:
                raise ValueError(f"exercise {exercise_id}: an answer of kind {self.cls.kind!r} has no option "
                                 f"{name!r} (its options: {', '.join(names)})")
        options = {**self.options, **more}
        if options.get("slips"):
            owner = slips_of or exercise_id
            options["slips"] = tuple(dataclasses.replace(s, exercise=owner) if isinstance(s, Slip) else s
                                     for s in options["slips"])
        try:
            return self.cls(**options)
        except (TypeError, ValueError) as err:
            raise ValueError(f"exercise {exercise_id}: {err}") from None
