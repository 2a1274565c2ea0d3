"""From a tree to a fast function of the formula's variables: closures, never ``eval``.

A formula is evaluated at many points to compare it with the key, so its tree
is turned into nested closures once.

>>> from workbook.expr.grammar import Grammar
>>> from workbook.expr.parsing import parse_tree
>>> used = set()
>>> f = compile_tree(parse_tree("2*x + 1", Grammar(variables=frozenset({"x"}))), used)
>>> f({"x": 3.0}), used
(7.0, {'x'})
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping

from .grammar import CONSTANTS, FUNCTIONS, MAX_EXPONENT, InvalidAnswer

Env = Mapping[str, float]


def compile_tree(node: tuple, used: set[str]) -> Callable[[Env], float]:
    """A function of the variables (a mapping) computing ``node``; the names it reads are added to ``used``."""
    kind = node[0]
    if kind in ("num", "const"):
        value = node[1] if kind == "num" else CONSTANTS[node[1]]
        return lambda env: value
    if kind == "var":
        name = node[1]
        used.add(name)
        return lambda env: env[name]
    if kind == "neg":
        f = compile_tree(node[1], used)
        return lambda env: -f(env)
    if kind == "unit":
        f, factor = compile_tree(node[1], used), node[2][0]
        return lambda env: f(env) * factor
    if kind == "bin":
        op, f, g = node[1], compile_tree(node[2], used), compile_tree(node[3], used)
        if op == "+":
            return lambda env: f(env) + g(env)
        if op == "-":
            return lambda env: f(env) - g(env)
        if op == "*":
            return lambda env: f(env) * g(env)
        if op == "/":
            return lambda env: f(env) / g(env)

        def power(env: Env) -> float:
            exponent = g(env)
            if abs(exponent) > MAX_EXPONENT:
                raise ValueError("exponent too large")
            return math.pow(f(env), exponent)  # ValueError for a negative base and a fractional power
        return power
    if kind == "call":
        fn = FUNCTIONS[node[1]][1]
        args = [compile_tree(a, used) for a in node[2]]
        if len(args) == 1:
            a = args[0]
            return lambda env: fn(a(env))
        a, b = args
        return lambda env: fn(a(env), b(env))
    raise InvalidAnswer("That is not a formula.")  # pragma: no cover


