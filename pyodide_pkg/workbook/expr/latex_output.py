"""From a tree to LaTeX: how the page shows a formula as the grader read it.

>>> from workbook.expr.grammar import Grammar
>>> from workbook.expr.parsing import parse_tree
>>> latex(parse_tree("-v*sin(theta)*dt", Grammar(variables=frozenset({"v", "theta", "dt"}))))
'-v\\\\sin\\\\theta \\\\cdot dt'
>>> latex(parse_tree("L1 cos(theta1)/2", Grammar(variables=frozenset({"L1", "theta1"}))))
'\\\\frac{L_{1}\\\\cos\\\\theta_{1}}{2}'
"""

from __future__ import annotations

import re

from .grammar import GREEK

_FUNC_LATEX = {
    "sin": r"\sin", "cos": r"\cos", "tan": r"\tan", "asin": r"\arcsin", "acos": r"\arccos",
    "atan": r"\arctan", "exp": r"\exp", "ln": r"\ln", "log": r"\ln", "log10": r"\log_{10}",
    "sind": r"\operatorname{sind}", "cosd": r"\operatorname{cosd}", "tand": r"\operatorname{tand}",
}
_GREEK_ASCII = set(GREEK.values()) - {"pi"}


def latex(tree: tuple) -> str:
    """The LaTeX of a parsed tree."""
    return _latex(tree, 0)


def _join(left: str, right: str) -> str:
    """Two LaTeX pieces side by side; a command followed by a letter needs a space."""
    if re.search(r"\\[A-Za-z]+$", left) and right[:1].isalpha():
        return left + " " + right
    return left + right


def variable_latex(name: str) -> str:
    r"""How a variable shows, as the chapters write it: ``theta1`` → ``\theta_{1}``, ``dt`` → ``dt``
    (a small step, as in ``v\,dt``; ``Δt`` typed is read as ``dt`` too), ``L_2`` → ``L_{2}``.

    >>> variable_latex("theta1"), variable_latex("dt"), variable_latex("dtheta"), variable_latex("Kp")
    ('\\theta_{1}', 'dt', 'd\\theta', 'K_{p}')
    """
    m = re.fullmatch(r"([A-Za-z]+?)_?([0-9]*)", name)
    if not m:
        return rf"\mathit{{{name}}}"
    base, sub = m.group(1), m.group(2)
    if base in _GREEK_ASCII:
        out = "\\" + base
    elif len(base) > 1 and base[0] == "d" and (base[1:] in _GREEK_ASCII or len(base) == 2):
        out = "d" + ("\\" + base[1:] if base[1:] in _GREEK_ASCII else base[1:])
    elif len(base) == 2 and base[0].isupper() and not sub:
        out, sub = base[0], base[1]
    elif len(base) > 1:
        out = rf"\mathit{{{base}}}"
    else:
        out = base
    return out + (f"_{{{sub}}}" if sub else "")


def _number(v: float) -> str:
    if v == int(v) and abs(v) < 1e15:
        return str(int(v))
    s = format(v, ".12g")
    if "e" in s:
        mant, exp = s.split("e")
        return rf"{mant} \times 10^{{{int(exp)}}}"
    return s


_PREC = {"+": 1, "-": 1, "*": 2, "/": 2, "neg": 3, "^": 4}


def _prec(node: tuple) -> int:
    if node[0] == "bin":
        return _PREC[node[1]]
    if node[0] == "neg":
        return 3
    if node[0] == "num" and node[1] < 0:
        return 3
    return 5


def _paren(s: str) -> str:
    return rf"\left({s}\right)"


def _latex(node: tuple, parent: int) -> str:
    out = _latex_raw(node)
    return _paren(out) if _prec(node) < parent else out


def _latex_raw(node: tuple) -> str:
    kind = node[0]
    if kind == "num":
        return _number(node[1])
    if kind == "const":
        return {"pi": r"\pi", "tau": r"\tau", "e": "e"}[node[1]]
    if kind == "var":
        return variable_latex(node[1])
    if kind == "neg":
        return "-" + _latex(node[1], 4)
    if kind == "unit":
        inner = _latex(node[1], 5)
        return inner + (r"\,\mathrm{rad}" if node[2][3] == "rad" else r"^{\circ}")
    if kind == "call":
        name, args = node[1], node[2]
        if name == "sqrt":
            return rf"\sqrt{{{_latex(args[0], 0)}}}"
        if name == "abs":
            return rf"\left|{_latex(args[0], 0)}\right|"
        if name == "atan2":
            return rf"\operatorname{{atan2}}\left({_latex(args[0], 0)}, {_latex(args[1], 0)}\right)"
        return _join(_FUNC_LATEX[name], _func_arg(args[0]))
    op, a, b = node[1], node[2], node[3]
    if op == "/":
        return rf"\frac{{{_latex(a, 0)}}}{{{_latex(b, 0)}}}"
    if op == "^":
        if a[0] == "call" and a[1] in ("sin", "cos", "tan"):
            return _join(rf"{_FUNC_LATEX[a[1]]}^{{{_latex(b, 0)}}}", _func_arg(a[2][0]))
        return f"{_latex(a, 5)}^{{{_latex(b, 0)}}}"
    if op == "*":
        left, right = _latex(a, 2), _latex(b, 3)
        if _ends_with_bare_call(a):  # \sin\theta \cdot dt: read back, "\sin\theta dt" would be ambiguous
            return rf"{left} \cdot {right}"
        if _prec(b) == 3:
            return rf"{left} \cdot {_paren(right)}"
        if right[:1].isdigit() or right[:1] == ".":  # 2, 2^{2}, 3 m: two numbers side by side read as one
            return rf"{left} \cdot {right}"
        if right.startswith("\\") and not right.startswith(r"\left"):
            return _join(left, right)
        return f"{left} {right}"
    left = _latex(a, 1)
    right = _latex(b, 2 if op == "-" else 1)
    if _prec(b) == 3:
        right = _paren(right)
    return f"{left} {op} {right}"


def _ends_with_bare_call(node: tuple) -> bool:
    """The node, printed, ends with a function whose argument has no parentheses (``\\cos\\theta``)."""
    while True:
        if node[0] == "bin" and node[1] in "*^" and not (node[1] == "^" and node[2][0] == "call"):
            node = node[3]
        elif node[0] == "bin" and node[1] == "^":
            node = node[2]
        elif node[0] == "neg":
            node = node[1]
        else:
            break
    return (node[0] == "call" and node[1] in _FUNC_LATEX
            and _func_arg(node[2][0]) == _latex(node[2][0], 0))


def _func_arg(arg: tuple) -> str:
    if arg[0] in ("var", "const", "num") and not (arg[0] == "num" and arg[1] < 0):
        return _latex(arg, 0)
    if arg[0] == "unit" and arg[1][0] in ("num", "var"):
        return _latex(arg, 0)
    return _paren(_latex(arg, 0))


