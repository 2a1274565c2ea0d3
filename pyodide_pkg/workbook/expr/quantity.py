"""Read a learner's typed answer as a quantity: a number, a small math expression, with units.

The text is normalised (unicode minus and degree signs, ×, π, √, superscripts,
subscripts, a leading ``θ2 =``), split into tokens and parsed by a small
recursive-descent parser into a tree of tuples. Nothing is ever passed to
``eval``: only the nodes of :mod:`workbook.expr.parsing` exist, limits on
length, nesting, node count and exponents are checked while parsing, and all
arithmetic is done in floats, so no input can run for long or use much memory.
:mod:`.formula` uses the same parser with variables.

:func:`read_quantity` is what marking uses: the value in the unit asked for,
with how precisely it was typed (:class:`Reading`) and, for ``cos(90)``, the
value with the bare angle read as degrees (:mod:`.degrees`).

Units are part of the evaluation: every value carries a dimension (see
:mod:`workbook.units`), products and quotients combine dimensions, and sums
need equal ones.

How units bind (so that each reading is the one people mean):

- A unit after a number or a closing parenthesis applies to the whole product
  or quotient before it: ``pi/2 rad`` is (π/2) rad, ``1/2 m`` is half a metre,
  ``180°/2`` is 90°. The exception: when the numerator already has a unit, a
  unit after a divisor belongs to the divisor, so ``10 m / 5 s`` is 2 m/s.
- ``m/s``, ``km/h``, ``cm/s`` (a unit, a slash, a unit) are one unit.
- ``s ms min h m cm mm km`` are units only after a number or a parenthesis.
- A bare number added to a quantity with a unit is refused (invalid, with a
  message): in ``45 + 45°`` the 45 could be degrees or radians, so the learner
  is asked to write the unit on every term. Quantities whose units cancel
  (``2 m / 1 m``) are plain numbers and mix freely.
- sin, cos and tan take an angle in radians (its SI value) or a bare number,
  read as radians; their result has no unit. Inverse trig functions return a
  bare number (radians). sind, cosd, tand read a bare number as degrees.
- A function may be written without parentheses when its argument is one
  number, name or number-with-unit: ``cos 45°``, ``√2/2``. Anything longer
  (``cos 2x``, ``sin x^2``) must use parentheses, and so must a division
  right after the argument of any function but √ (``cos pi/3`` could mean
  either); the message says so.

>>> parse_answer("sqrt(2)/2").value
0.7071067811865476
>>> parse_answer("53.13°").unit
'deg'
>>> a = parse_answer("45°+45°"); round(a.value, 12), a.unit, a.dimension
(90.0, 'deg', 'angle')
>>> a = parse_answer("20 cm"); a.si, a.dimension, a.unit
(0.2, 'length', None)
>>> parse_quantity("2.1263 m/s", "m/s")
2.1263
>>> parse_quantity("2 s", "m")
Traceback (most recent call last):
...
workbook.expr.InvalidAnswer: This answer is a length in metres; 2 s is a time.
>>> parse_answer("2,5")
Traceback (most recent call last):
...
workbook.expr.InvalidAnswer: Use a dot for decimals: write 2.5, not 2,5.
"""

from __future__ import annotations

import functools
import math
import re
from dataclasses import dataclass, field

from .. import units as U
from .degrees import degree_arguments
from .evaluate import bare, evaluate
from .grammar import MAX_LENGTH, InvalidAnswer
from .parsing import parse_tree
from .precision import typed_precision


@dataclass(frozen=True)
class Answer:
    """A parsed answer.

    ``value`` is in the unit written for angles (degrees for ``53.13°``) and in
    SI for everything else; ``unit`` is ``"deg"``, ``"rad"`` or None (no angle
    unit); ``dimension`` is None when no unit was written, else ``"angle"``,
    ``"length"``, ``"time"``, ``"speed"`` (or another name), or ``""`` when the
    units cancel; ``si`` is the value in rad, m, s, m/s.
    """

    value: float
    unit: str | None
    text: str
    dimension: str | None = None
    si: float | None = field(default=None)

    def __post_init__(self) -> None:
        if self.si is None:
            object.__setattr__(self, "si", self.value)


_PLAIN = re.compile(r"\s*[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?\s*")
Parsed = tuple[Answer, "U.Dim | None", "tuple | None"]  # the answer, its dimension, its tree (None: a plain number)


def _parse(text: object) -> Parsed:
    if isinstance(text, str) and len(text) <= MAX_LENGTH:
        if _PLAIN.fullmatch(text):  # the common case, a plain number: no parser needed
            value = float(text)
            if math.isfinite(value):
                return Answer(value=value, unit=None, text=text), None, None
        return _parse_cached(text)
    return _parse_text(text)


@functools.lru_cache(maxsize=512)
def _parse_cached(text: str) -> Parsed:
    return _parse_text(text)  # errors are raised, not cached


def _quantity(tree: tuple, text: str) -> tuple[Answer, U.Dim | None]:
    try:
        si, dim, angle = evaluate(tree)
    except (OverflowError, RecursionError):
        raise InvalidAnswer("That number is too large.") from None
    if math.isnan(si) or math.isinf(si):
        raise InvalidAnswer("That is not a finite number.")
    unit = None
    value = si
    if dim == U.ANGLE:
        unit = angle or "rad"
        value = si / U.UNITS["°"][0] if unit == "deg" else si
    return Answer(value=value, unit=unit, text=text, dimension=U.dimension_name(dim), si=si), dim


def _parse_text(text: object) -> Parsed:
    tree = parse_tree(text)  # type: ignore[arg-type]
    return (*_quantity(tree, text), tree)  # type: ignore[arg-type]


def parse_answer(text: object) -> Answer:
    """Read ``text`` as one real number (with a unit, if one is written), or raise :class:`InvalidAnswer`.

    >>> a = parse_answer("θ2 = 90°"); round(a.value, 9), a.unit
    (90.0, 'deg')
    >>> parse_answer("-0.2 m").si, parse_answer("10 m / 5 s").dimension
    (-0.2, 'speed')
    >>> round(parse_answer("cos 45°").value, 4), parse_answer("cos 45°").dimension
    (0.7071, '')
    """
    return _parse(text)[0]


def _in_unit(answer: Answer, dim: U.Dim | None, expect: str | None, text: object) -> float:
    """The value of a parsed answer in the unit asked for, or InvalidAnswer naming the unit expected."""
    if bare(dim):
        return answer.value if dim is None else answer.si  # type: ignore[return-value]
    shown = str(text).strip()
    shown = shown if len(shown) <= 24 else "what you typed"
    if expect is None:
        raise InvalidAnswer(f"This answer is a plain number, without a unit; {shown} is {U.describe(dim)}.")
    factor, want, words = U.EXPECT[expect]
    if dim != want:
        raise InvalidAnswer(f"This answer is {words}; {shown} is {U.describe(dim)}.")
    return answer.si / factor  # type: ignore[operator]


def parse_quantity(text: object, expect: str | None) -> float:
    """The answer's value in the unit the exercise asks for.

    ``expect`` is one of ``"deg"``, ``"rad"``, ``"m"``, ``"m/s"``, ``"s"``, or None
    for a plain number. A plain number (no unit, or units that cancel) is
    returned as typed; a unit of the right kind is converted; a unit of the
    wrong kind is :class:`InvalidAnswer` naming the unit expected.

    >>> parse_quantity("20 cm", "m"), parse_quantity("0.5", "m")
    (0.2, 0.5)
    >>> round(parse_quantity("pi/2 rad", "deg"), 9), round(parse_quantity("90°", "rad"), 9)
    (90.0, 1.570796327)
    >>> parse_quantity("3 m", None)
    Traceback (most recent call last):
    ...
    workbook.expr.InvalidAnswer: This answer is a plain number, without a unit; 3 m is a length.
    """
    return read_quantity(text, expect).value


@dataclass(frozen=True)
class Reading:
    """A learner's number in the unit asked for, and how precisely it was typed.

    ``figures`` and ``half_unit`` are set when the answer is one decimal number
    (with a unit, or after ``θ2 =``): its significant figures, and half a unit
    of its last digit in the unit asked for. ``bare``: no unit was written.
    """

    value: float
    bare: bool
    figures: int | None = None
    half_unit: float | None = None
    tree: tuple | None = field(default=None, repr=False, compare=False)
    expect: str | None = field(default=None, repr=False, compare=False)

    def with_degree_arguments(self) -> float | None:
        """The value with ``cos(90)``'s 90 read as degrees, or None when no such argument was typed."""
        tree = degree_arguments(self.tree) if self.tree is not None else None
        if tree is None:
            return None
        try:
            answer, dim = _quantity(tree, "")
            return _in_unit(answer, dim, self.expect, "")
        except InvalidAnswer:
            return None


def read_quantity(text: object, expect: str | None) -> Reading:
    """Read ``text`` in the unit ``expect`` (see :func:`parse_quantity`), with its precision.

    >>> r = read_quantity("0.143", None); r.value, r.figures, r.half_unit
    (0.143, 3, 0.0005)
    >>> r = read_quantity("14.3 cm", "m"); round(r.value, 9), r.figures, round(r.half_unit, 12)
    (0.143, 3, 0.0005)
    >>> read_quantity("sqrt(2)/2", None).figures is None, read_quantity("2 m", "m").bare
    (True, False)
    """
    if expect is not None and expect not in U.EXPECT:
        raise ValueError(f"expect must be one of {sorted(U.EXPECT)} or None, not {expect!r}")
    if isinstance(text, str) and len(text) <= MAX_LENGTH:
        return _read_cached(text, expect)
    return _read(text, expect)


@functools.lru_cache(maxsize=4096)  # a Reading is frozen; errors are raised, not cached
def _read_cached(text: str, expect: str | None) -> Reading:
    return _read(text, expect)


def _read(text: object, expect: str | None) -> Reading:
    answer, dim, tree = _parse(text)
    value = _in_unit(answer, dim, expect, text)
    figures, half = typed_precision(tree if tree is not None else ("num", answer.value), str(text))
    if half is not None and tree is not None and tree[0] != "num":  # typed with a unit: scale to the unit asked
        literal = _literal(tree)
        half = abs(half * value / literal) if literal else None
    return Reading(value=value, bare=bare(dim), figures=figures, half_unit=half, tree=tree, expect=expect)


def _literal(tree: tuple) -> float:
    while tree[0] in ("unit", "neg"):
        tree = tree[1]
    return float(tree[1]) if tree[0] == "num" else 0.0
