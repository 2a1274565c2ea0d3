"""Formula answers: ``L1 cos θ1 + L2 cos(θ1 + θ2)`` read over named variables.

:func:`parse_formula` uses the one answer parser (:mod:`.parsing`) with the
exercise's variables (ASCII names such as ``theta1``, ``L1``, ``dt``) and the
forms a learner types for them: ``θ1``, ``θ₁``, ``theta_1``, ``L₁``, ``Δt`` for
``dt``, ``ω`` for ``omega``; also ``Θ1`` or ``l1`` when only one variable
matches regardless of case. The tree is compiled once into closures, so a
formula is evaluated many times quickly and never through ``eval``.

Implicit products, and what is refused (so that no reading is a guess):

- a number before a name or a parenthesis: ``2L1``, ``2(θ1 + θ2)``, ``2π``;
- names side by side, with or without a space: ``L1 L2``, ``L1cos(θ1)``,
  ``v dt``; a run of letters is split into names only when exactly one split
  exists (``vdt`` is v·dt when the variables are v and dt; if ``d`` and ``t``
  were variables too, the run is refused as ambiguous);
- a parenthesis after a name or a parenthesis: ``L1(cos θ1)``, ``(a)(b)``;
- a function without parentheses takes one name, number or number-with-unit
  (another function may follow: ``cos θ1 cos θ2``):
  ``L1 cos θ1 + L2 cos(θ1 + θ2)`` reads as it looks; ``cos 2θ``, ``sin θ L1``
  and ``sin x^2`` are refused with "put the argument in parentheses";
- a name followed by a number (``θ1 2``) is refused: write the ``*``.
- ``sin²θ`` and ``sin^2(θ)`` are (sin θ)².
- ``°`` after a number converts it to radians (``θ1 + 90°``); other units are
  not part of a formula.

>>> f = parse_formula("L₁ cos θ₁ + L2 cos(θ1 + θ2)", ("theta1", "theta2", "L1", "L2"))
>>> f.latex
'L_{1}\\\\cos\\\\theta_{1} + L_{2}\\\\cos\\\\left(\\\\theta_{1} + \\\\theta_{2}\\\\right)'
>>> sorted(f.names)
['L1', 'L2', 'theta1', 'theta2']
>>> f.evaluate({"theta1": 0.0, "theta2": 0.0, "L1": 1.0, "L2": 1.0})
2.0
>>> parse_formula("v*Δt*cos(ω)", ("v", "omega", "dt")).latex
'v dt\\\\cos\\\\omega'
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable
from dataclasses import dataclass

from .compile import Env, compile_tree
from .degrees import degree_arguments
from .grammar import Grammar
from .latex_output import latex
from .parsing import parse_tree


@dataclass(frozen=True)
class Formula:
    """A parsed formula: ``evaluate(env)``, its ``latex`` and the variable ``names`` it uses."""

    text: str
    latex: str
    names: frozenset[str]
    _fn: Callable[[Env], float]
    tree: tuple = ()

    def with_degree_arguments(self) -> Formula | None:
        """The formula with the bare numbers inside sin, cos and tan read as degrees (``sin(θ1 + 90)``),
        or None when it has none."""
        tree = degree_arguments(self.tree) if self.tree else None
        if tree is None:
            return None
        used: set[str] = set()
        return Formula(self.text, latex(tree), self.names, compile_tree(tree, used), tree)

    def evaluate(self, env: Env) -> float:
        """The formula's value for the variables in ``env``.

        Raises ``ValueError`` when a variable is missing or the formula is not
        defined there (sqrt of a negative, a huge exponent), and
        ``ZeroDivisionError``/``OverflowError`` from the arithmetic.
        """
        try:
            return float(self._fn(env))
        except KeyError as err:
            raise ValueError(f"no value given for {err.args[0]}") from None


def parse_formula(text: object, variables: Iterable[str]) -> Formula:
    """Read ``text`` as a formula over ``variables`` (ASCII names), or raise InvalidAnswer.

    >>> parse_formula("2L1 + x", ["L1"])  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    workbook.expr.InvalidAnswer: Unknown name “x”. The formula may use L1, numbers, pi and the functions sqrt, ..., abs.
    >>> parse_formula("1 - 2sin²θ", ["theta"]).latex
    '1 - 2\\\\sin^{2}\\\\theta'
    """
    names = tuple(variables)
    for name in names:
        if not re.fullmatch(r"[A-Za-z][A-Za-z0-9_]*", name):
            raise ValueError(f"variable names must be ASCII identifiers, not {name!r}")
    vars_ = frozenset(names)
    grammar = Grammar(variables=vars_, units=False,
                      examples=f"2*{names[0]}, sin({names[0]}), sqrt({names[0]})/2" if names else "2*pi")
    tree = parse_tree(text, grammar)  # type: ignore[arg-type]
    used: set[str] = set()
    fn = compile_tree(tree, used)
    return Formula(text=str(text), latex=latex(tree), names=frozenset(used), _fn=fn, tree=tree)


