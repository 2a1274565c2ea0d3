"""LaTeX a learner pastes (often from the page itself), rewritten in the reader's plain notation.

The page typesets its formulas with KaTeX, and learners copy from it or type
the TeX they know: ``\\frac{\\sqrt{3}}{2}``, ``5 \\cdot \\cos(\\theta_1)``,
``90^\\circ``, ``\\text{ m}``. :func:`from_latex` turns these into the plain
notation :mod:`.tokens` reads (``((sqrt(3))/(2))``, ``5 * cos (θ_1)``, ``90°``,
`` m``). Matrices (``\\begin{bmatrix}``) are split into entries by
:mod:`.layout` before their entries come here.

>>> from_latex(r"\\frac{\\sqrt{3}}{2}")
'((sqrt(3))/(2))'
>>> from_latex(r"L_{1}\\cos\\theta_{1} + 90^{\\circ}")
'L_1 cos θ_1 + 90°'
>>> from_latex(r"\\left(1 + \\tfrac12\\right) \\cdot 2\\,\\text{m}")
'(1 + ((1)/(2))) * 2 m'
>>> from_latex(r"\\infty")  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
workbook.expr.InvalidAnswer: The grader does not read the LaTeX command \\infty. Type the value ... or cos.
"""

from __future__ import annotations

import re

from .grammar import GREEK, InvalidAnswer

_LETTERS = {name: letter for letter, name in GREEK.items() if letter not in "ϕ"}
_LETTERS.update({"varphi": "φ", "vartheta": "θ", "varepsilon": "ε", "Delta": "Δ", "Pi": "Π"})
_FUNCTIONS = {"sin", "cos", "tan", "arcsin", "arccos", "arctan", "exp", "ln", "log", "sqrt"}
_TIMES = {"cdot": " * ", "times": " * ", "ast": " * ", "div": " / "}
_SPACES = {",", ";", ":", "!", " ", "quad", "qquad", "enspace", "thinspace", "displaystyle", "textstyle"}
_SIZES = {"left", "right", "big", "Big", "bigg", "Bigg", "bigl", "bigr", "Bigl", "Bigr", "biggl", "biggr"}
_TEXT = {"text", "mathrm", "mathit", "textrm", "mathbf", "boldsymbol", "mathsf", "operatorname", "textit"}
_SYMBOLS = {"circ": "°", "degree": "°", "approx": "≈", "top": "ᵀ", "intercal": "ᵀ", "prime": "′",
            "pm": "±", "lbrace": "(", "rbrace": ")", "{": "(", "}": ")", "%": "%", "minus": "-"}
_COMMAND = re.compile(r"\\([A-Za-z]+|.)")


def _group(s: str, i: int) -> tuple[str, int]:
    """The argument starting at ``s[i]`` (after spaces): a ``{...}`` group or one character; and where it ends."""
    while i < len(s) and s[i] == " ":
        i += 1
    if i >= len(s):
        raise InvalidAnswer("A LaTeX command is missing its argument in braces, for example \\frac{1}{2}.")
    if s[i] != "{":
        m = _COMMAND.match(s, i)
        if m:  # \frac\pi2: a command as the argument
            return m.group(0), m.end()
        return s[i], i + 1
    depth = 0
    for j in range(i, len(s)):
        depth += {"{": 1, "}": -1}.get(s[j], 0)
        if depth == 0:
            return s[i + 1:j], j + 1
    raise InvalidAnswer("The braces do not match: check every “{” has its “}”.")


def from_latex(text: str) -> str:
    """``text`` with its LaTeX commands rewritten; unknown commands are refused with a message."""
    s = text.strip()
    for opening, closing in (("$$", "$$"), ("$", "$"), ("\\(", "\\)"), ("\\[", "\\]")):
        if s.startswith(opening) and s.endswith(closing) and len(s) >= len(opening) + len(closing):
            s = s[len(opening):len(s) - len(closing)]
            break
    return re.sub(r"  +", " ", _convert(s)).strip()


def _convert(s: str) -> str:
    out: list[str] = []
    i = 0
    while i < len(s):
        ch = s[i]
        if ch in "^_" and i + 1 < len(s):
            arg, i = _group(s, i + 1)
            inner = _convert(arg).strip()
            if ch == "_":
                out.append("_" + inner)
            elif inner in ("°", "ᵀ") or (inner and set(inner) == {"′"}):  # 7^{\prime}, 48^{\prime\prime}
                out.append(inner)
            else:
                out.append(f"^({inner})")
            continue
        if ch in "{}":
            out.append("(" if ch == "{" else ")")
            i += 1
            continue
        if ch != "\\":
            out.append(ch)
            i += 1
            continue
        m = _COMMAND.match(s, i)
        if m is None:
            raise InvalidAnswer("A “\\” ends the answer: remove it, or finish the LaTeX command.")
        name, i = m.group(1), m.end()
        if name in ("frac", "dfrac", "tfrac"):
            top, i = _group(s, i)
            bottom, i = _group(s, i)
            out.append(f"(({_convert(top)})/({_convert(bottom)}))")
        elif name == "sqrt":
            root = None
            if i < len(s) and s[i] == "[":
                end = s.find("]", i)
                if end < 0:
                    raise InvalidAnswer("The “[” after \\sqrt is not closed.")
                root, i = s[i + 1:end], end + 1
            arg, i = _group(s, i)
            out.append(f"sqrt({_convert(arg)})" if root is None else f"(({_convert(arg)})^(1/({_convert(root)})))")
        elif name in _TEXT:
            arg, i = _group(s, i)
            out.append(" " + _convert(arg) + " ")
        elif name in _TIMES:
            out.append(_TIMES[name])
        elif name in _SPACES:
            out.append(" ")
        elif name in _SIZES:
            if i < len(s) and s[i] == ".":
                i += 1  # \left. is an invisible delimiter
        elif name == "Delta":  # \Delta t is one name, Δt (read as dt)
            while i < len(s) and s[i] == " ":
                i += 1
            out.append(" Δ")
        elif name in _LETTERS:
            out.append(" " + _LETTERS[name] + " " if name in ("pi", "tau") else " " + _LETTERS[name])
        elif name in _FUNCTIONS:
            out.append(f" {name} ")
        elif name in _SYMBOLS:
            out.append(_SYMBOLS[name])
        else:
            shown = "\\" + name if len(name) < 20 else "\\" + name[:20] + "…"
            raise InvalidAnswer(f"The grader does not read the LaTeX command {shown}. Type the value with "
                                "numbers, + − · /, and functions such as sqrt or cos.")
    return "".join(out)
