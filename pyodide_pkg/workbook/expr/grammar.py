"""What an answer may contain: the limits, functions, constants and names, and the error raised.

:class:`Grammar` says what a name means in one kind of answer (a number, or a
formula over some variables) and words the message when a name is unknown.
:class:`InvalidAnswer` is the one error of the expression reader; its public
home is :mod:`workbook.answers`, so tracebacks name it
``workbook.expr.InvalidAnswer``.

>>> SCALAR.kind("cos"), SCALAR.kind("pi"), SCALAR.kind("km"), SCALAR.kind("x")
('func', 'const', 'unit', None)
>>> Grammar(variables=frozenset({"theta1"})).typed_forms()
' (θ1, θ₁ and theta_1 work too)'
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from dataclasses import dataclass

from .. import units as U

# Limits, checked while reading, so that no input runs for long or uses much memory.
MAX_LENGTH = 200
MAX_DEPTH = 12
MAX_NODES = 100
MAX_EXPONENT = 1000.0


class InvalidAnswer(ValueError):
    """The input could not be read as one number; the message says why."""


# Its public home: tracebacks and doctests name it workbook.expr.InvalidAnswer.
InvalidAnswer.__module__ = "workbook.expr"


FUNCTIONS: dict[str, tuple[int, Callable[..., float]]] = {
    "sqrt": (1, math.sqrt), "sin": (1, math.sin), "cos": (1, math.cos), "tan": (1, math.tan),
    "asin": (1, math.asin), "acos": (1, math.acos), "atan": (1, math.atan), "atan2": (2, math.atan2),
    "exp": (1, math.exp), "ln": (1, math.log), "log": (1, math.log), "log10": (1, math.log10),
    "abs": (1, abs), "sind": (1, lambda d: math.sin(math.radians(d))),
    "cosd": (1, lambda d: math.cos(math.radians(d))), "tand": (1, lambda d: math.tan(math.radians(d))),
}
ALIASES = {"arcsin": "asin", "arccos": "acos", "arctan": "atan", "arctan2": "atan2", "sqr": "sqrt"}
CONSTANTS = {"pi": math.pi, "e": math.e, "tau": math.tau}
TRIG = {"sin", "cos", "tan"}
_KNOWN_FUNCS = "sqrt, sin, cos, tan, asin, acos, atan, atan2, exp, ln, log, abs"

GREEK = {
    "α": "alpha", "β": "beta", "γ": "gamma", "δ": "delta", "ε": "epsilon", "ζ": "zeta", "η": "eta",
    "θ": "theta", "ι": "iota", "κ": "kappa", "λ": "lambda", "μ": "mu", "ν": "nu", "ξ": "xi",
    "π": "pi", "ρ": "rho", "σ": "sigma", "τ": "tau", "υ": "upsilon", "φ": "phi", "ϕ": "phi",
    "χ": "chi", "ψ": "psi", "ω": "omega", "Θ": "Theta", "Φ": "Phi", "Ψ": "Psi", "Ω": "Omega",
    "Λ": "Lambda", "Σ": "Sigma", "Γ": "Gamma",
}


@dataclass
class Grammar:
    """What names mean in one kind of answer: numbers (no variables) or a formula."""

    variables: frozenset[str] = frozenset()
    units: bool = True  # every unit of workbook.units; False: angle units only
    examples: str = "0.5, -1/2, sqrt(2)/2, pi/4, 53.13°"

    def kind(self, name: str) -> str | None:
        if name in self.variables:
            return "var"
        if name in FUNCTIONS or name in ALIASES:
            return "func"
        if name in CONSTANTS:
            return "const"
        unit = U.lookup(name)
        if unit is not None and (self.units or unit[1] == U.ANGLE):
            return "unit"
        return None

    def unknown(self, name: str, call: bool) -> InvalidAnswer:
        if name in ("True", "False", "None"):
            return InvalidAnswer("Only numbers can be used in an answer.")
        if call and not self.variables:
            return InvalidAnswer(f"Unknown function “{name}”. Known: {_KNOWN_FUNCS}.")
        if self.variables:
            names = ", ".join(sorted(self.variables, key=lambda v: (v.lower(), v)))
            return InvalidAnswer(
                f"Unknown name “{name}”. The formula may use {names}{self.typed_forms()}, "
                f"numbers, pi and the functions {_KNOWN_FUNCS}.")
        return InvalidAnswer(f"Unknown name “{name}”. Use numbers, pi, e and functions such as sqrt, sin, cos, atan2.")


    def typed_forms(self) -> str:
        """An example of the Greek and subscript spellings, for messages: " (θ1, θ₁ and theta_1 work too)"."""
        greek = {v: k for k, v in GREEK.items() if k not in "ϕπ"}
        for var in sorted(self.variables):
            m = re.fullmatch(r"([A-Za-z]+?)_?([0-9]*)", var)
            if m and m.group(1) in greek:
                g, d = greek[m.group(1)], m.group(2)
                if d:
                    sub = d.translate(str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉"))
                    return f" ({g}{d}, {g}{sub} and {m.group(1)}_{d} work too)"
                return f" ({g} works too)"
        return ""

    def ambiguous(self, name: str) -> InvalidAnswer:
        return InvalidAnswer(f"“{name}” can be read as names in more than one way: put * or spaces between them.")


SCALAR = Grammar()


def not_an_expression(grammar: Grammar) -> InvalidAnswer:
    """The message for text that reads as nothing at all, with the grammar's examples."""
    return InvalidAnswer(f"That is not a number or an arithmetic expression. Examples that work: {grammar.examples}.")
