"""Degrees typed where radians are read: the other reading of sin, cos and tan of a bare number.

``cos(90)`` reads 90 as radians, as a calculator in radian mode does. A learner
who wrote it almost always meant 90°. :func:`degree_arguments` gives the tree in
which every bare constant term inside a sin, cos or tan argument is read as
degrees; marking tries it only when the plain reading is wrong, and names the
slip when it is right.

A term is bare when it has no unit and names no variable and no constant: in
``sin(θ1 + 90)`` only the 90 changes, ``cos(pi/2)`` and ``cos(90°)`` stay as
they are.

>>> from workbook.expr.parsing import parse_tree
>>> from workbook.expr.evaluate import evaluate
>>> round(evaluate(degree_arguments(parse_tree("2*cos(90)")))[0], 12)
0.0
>>> degree_arguments(parse_tree("cos(pi/2) + sin(30°)")) is None
True
"""

from __future__ import annotations

from .. import units as U

TRIG = frozenset({"sin", "cos", "tan"})
_DEG = (*U.UNITS["°"], "°", "deg")


def _bare(node: tuple) -> bool:
    """No unit, no variable, no named constant anywhere inside."""
    if node[0] == "num":
        return True
    if node[0] in ("var", "const", "unit"):
        return False
    if node[0] == "call":
        return all(_bare(a) for a in node[2])
    return all(_bare(part) for part in node[1:] if isinstance(part, tuple))


def _terms(node: tuple) -> tuple | None:
    """The argument with each bare additive term read as degrees; None when nothing changes."""
    if node[0] == "bin" and node[1] in "+-":
        left, right = _terms(node[2]), _terms(node[3])
        if left is None and right is None:
            return None
        return ("bin", node[1], left or node[2], right or node[3])
    if node[0] == "neg":
        inner = _terms(node[1])
        return None if inner is None else ("neg", inner)
    return ("unit", node, _DEG) if _bare(node) else None


def degree_arguments(tree: tuple) -> tuple | None:
    """``tree`` with the bare terms of every trigonometric argument read as degrees, or None if it has none."""
    kind = tree[0]
    if kind == "call":
        args = [degree_arguments(a) or a for a in tree[2]]
        changed = any(new is not old for new, old in zip(args, tree[2]))
        if tree[1] in TRIG:
            converted = _terms(args[0])
            if converted is not None:
                args[0], changed = converted, True
        return ("call", tree[1], args) if changed else None
    if kind in ("neg", "unit"):
        inner = degree_arguments(tree[1])
        return None if inner is None else (kind, inner, *tree[2:])
    if kind == "bin":
        a, b = degree_arguments(tree[2]), degree_arguments(tree[3])
        return None if a is None and b is None else ("bin", tree[1], a or tree[2], b or tree[3])
    return None
