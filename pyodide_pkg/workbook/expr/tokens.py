"""From text to tokens: unify how symbols are typed, then split and classify names.

:func:`normalise` turns the many spellings of one symbol (unicode minus signs,
º for °, ×, ÷, superscripts, ½) into one; :func:`canonical_name` spells a
Greek name in ASCII; :func:`tokenize` cuts the text into numbers, names,
operators and strings, and asks the :class:`~.grammar.Grammar` what each name
is. A run of letters that is no known name is split into known names when
exactly one split exists (``L1cos`` is L1, cos).

>>> [tok[:2] for tok in tokenize("2 cos 45°", Grammar()) if tok[0] != "end"]
[('num', 2.0), ('func', 'cos'), ('num', 45.0), ('unit', '°')]
"""

from __future__ import annotations

import re
import unicodedata

from .grammar import ALIASES, GREEK, Grammar, InvalidAnswer, not_an_expression
from .latex_input import from_latex

_DEGREE_LIKE = str.maketrans({"\u00ba": "°", "\u02da": "°", "\u2218": "°", "\u00b0": "°"})
_FRACTIONS = {"\u00bd": "(1/2)", "\u00bc": "(1/4)", "\u00be": "(3/4)", "\u2153": "(1/3)", "\u2154": "(2/3)"}
_SUPER = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹⁻⁺", "0123456789-+")
_SUPER_RUN = re.compile("[⁰¹²³⁴⁵⁶⁷⁸⁹⁻⁺]+")
_AFTER_NFKC = str.maketrans({
    "\u2010": "-", "\u2011": "-", "\u2012": "-", "\u2013": "-", "\u2014": "-", "\u2212": "-",
    "\ufe63": "-", "\uff0d": "-", "\u00d7": "*", "\u22c5": "*", "\u00b7": "*", "\u2217": "*",
    "\u00f7": "/", "\u2044": "/", "\u2215": "/", "\u2248": "=", "\u2219": "*", "\u2027": "*",
    "\u2206": "Δ", "\u2032": "'", "\u02b9": "'", "\u2019": "'", "\u2033": "''", "\u201d": "''",
})
_TOKEN = re.compile(r"""\s*(?:
    (?P<num>(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?)
  | (?P<name>[^\W\d]\w*)
  | (?P<op>\*\*|[-+*/^(),°√\[\]{}=])
  | (?P<str>'[^']*'?|"[^"]*"?)
)""", re.X)
# ISO 80000-1 groups an integer's digits in threes with a space (7 500, 12 345 678): a first group of 1 to 3
# digits, then groups of exactly 3; a decimal part may follow the last group. Any other spacing stays two numbers.
_ISO_GROUPS = re.compile(r"(?<![\w.])([1-9][0-9]{0,2})((?: [0-9]{3})+)(?![0-9])")
_COMMA_NUMBER = re.compile(r"([+-]?\d+),(\d+)((?:,\d+)*)\s*(?:[^\d\s,.(][^,]*)?")


def canonical_name(name: str) -> str:
    """ASCII spelling of a name a learner typed: Greek spelled out, a leading Δ as d.

    >>> canonical_name("θ1"), canonical_name("Δt"), canonical_name("ω")
    ('theta1', 'dt', 'omega')
    """
    if name.isascii():
        return name
    out = []
    for i, ch in enumerate(name):
        if ch == "Δ" and i == 0 and len(name) > 1:
            out.append("d")
        else:
            out.append(GREEK.get(ch, ch))
    return "".join(out)


def normalise(text: str) -> str:
    """Unify the many ways of typing the same symbols (minus signs, °, ×, superscripts, LaTeX).

    >>> normalise("θ₂ = −45º × 2²"), normalise("∆t′"), normalise(r"\\frac{1}{2}")
    ('θ2 = -45° * 2^(2)', "Δt'", '((1)/(2))')
    """
    if "\\" in text or "_{" in text or "^{" in text:  # LaTeX: commands, or braced sub- and superscripts
        text = from_latex(text)
    if text.replace("°", "").isascii():  # nothing below changes ASCII text but degrees-minutes-seconds
        return _dms(text.strip())
    s = text.translate(_DEGREE_LIKE)
    if any(ch in s for ch in _FRACTIONS):  # 2½ is 2 + 1/2, ½ alone is 1/2
        s = re.sub(r"(\d)\s*([½¼¾⅓⅔])", lambda m: f"({m.group(1)}+{_FRACTIONS[m.group(2)]})", s)
        for old, new in _FRACTIONS.items():
            s = s.replace(old, new)
    s = _SUPER_RUN.sub(lambda m: "^(" + m.group(0).translate(_SUPER) + ")", s)
    s = unicodedata.normalize("NFKC", s)
    return _dms(s.translate(_AFTER_NFKC).strip())


_DMS = re.compile(r"""([0-9]+(?:\.[0-9]*)?)\s*°\s*"""  # degrees
                  r"""([0-9]+(?:\.[0-9]*)?)\s*'(?!')"""  # minutes
                  r"""(?:\s*([0-9]+(?:\.[0-9]*)?)\s*(?:''|"))?""")  # seconds, if any


def _dms(s: str) -> str:
    """Degrees, minutes and seconds (``53°7'48"``, ``53°7.8'``) as one number of degrees: ``(53+7/60+48/3600)°``.

    >>> _dms("53°7'48''"), _dms("-12° 30'")
    ('(53+7/60+48/3600)°', '-(12+30/60)°')
    """
    if "'" not in s or "°" not in s:
        return s

    def degrees(m: re.Match) -> str:
        d, minutes, seconds = m.group(1), m.group(2), m.group(3)
        if float(minutes) >= 60 or (seconds is not None and float(seconds) >= 60):
            raise InvalidAnswer(f"Minutes and seconds are below 60: {m.group(0).strip()} is not an angle in "
                                "degrees, minutes and seconds.")
        return f"({d}+{minutes}/60{f'+{seconds}/3600' if seconds is not None else ''})°"

    return _DMS.sub(degrees, s)


def check_commas(s: str) -> None:
    """Refuse a comma inside a number, saying whether it looks like a decimal or a thousands separator.

    >>> check_commas("2,5")
    Traceback (most recent call last):
    ...
    workbook.expr.InvalidAnswer: Use a dot for decimals: write 2.5, not 2,5.
    """
    m = _COMMA_NUMBER.fullmatch(s)
    if not m:
        return
    a, b, more = m.group(1), m.group(2), m.group(3)
    if len(b) == 3 and (not more or all(len(g) == 3 for g in more.split(",")[1:])) and len(a.lstrip("+-")) <= 3:
        whole = a + b + more.replace(",", "")
        decimal = f"{a}.{b.rstrip('0') or '0'}"
        if more:
            raise InvalidAnswer(f"Write {whole} without thousands separators.")
        raise InvalidAnswer(
            f"“{a},{b}” is ambiguous: write {whole} (no thousands separator) or {decimal} (a dot for decimals).")
    if not more:
        raise InvalidAnswer(f"Use a dot for decimals: write {a}.{b}, not {a},{b}.")


def ungroup(text: str) -> str:
    """``text`` (normalised: a thin space is a space by now) with ISO digit groups joined: ``7 500`` -> ``7500``.

    >>> ungroup("7 500"), ungroup("12 345 678.5 m"), ungroup("7 50"), ungroup("1234 567"), ungroup("2e3 000")
    ('7500', '12345678.5 m', '7 50', '1234 567', '2e3 000')
    """
    if " " not in text:
        return text
    return _ISO_GROUPS.sub(lambda m: m.group(1) + m.group(2).replace(" ", ""), text)


def tokenize(text: str, grammar: Grammar) -> list[tuple]:
    """Tokens ``(kind, value, space_before)``; names are classified by ``grammar``.

    Kinds: num, var, const, func, unit, op, str, end. A name that is not known is
    split into known names when that can be done in exactly one way
    (``L1cos`` -> L1, cos); otherwise it is an error naming what is allowed.
    """
    text = ungroup(text)
    raw: list[tuple] = []
    pos, n = 0, len(text)
    while pos < n:
        m = _TOKEN.match(text, pos)
        if not m or m.end() == pos or m.lastgroup is None:
            if text[pos:].strip() == "":
                break
            raise not_an_expression(grammar)
        space = m.start(m.lastgroup) > pos
        kind, value = m.lastgroup, m.group(m.lastgroup)
        pos = m.end()
        raw.append((kind, value, space))
    tokens: list[tuple] = []
    for k, (kind, value, space) in enumerate(raw):
        if kind == "num":
            tokens.append(("num", float(value), space))
        elif kind == "name":
            call = k + 1 < len(raw) and raw[k + 1][1] == "("
            tokens.extend(_classify(value, space, grammar, call))
        elif value == "°":
            tokens.append(("unit", "°", space))
        else:
            tokens.append((kind, value, space))
    tokens.extend([("end", None, False)] * 4)
    return tokens


def _classify(raw: str, space: bool, grammar: Grammar, call: bool) -> list[tuple]:
    name = canonical_name(raw)
    for candidate in (name, name.replace("_", "")):
        kind = grammar.kind(candidate)
        if kind:
            return [(kind, ALIASES.get(candidate, candidate), space)]
    count, pieces = _segment(name.replace("_", ""), grammar)
    if count > 1:
        raise grammar.ambiguous(raw)
    if count == 0:
        lowered = [v for v in grammar.variables if v.lower() == name.replace("_", "").lower()]
        if len(lowered) == 1:
            return [("var", lowered[0], space)]
        raise grammar.unknown(raw, call)
    out = []
    for i, (kind, value) in enumerate(pieces):
        out.append((kind, float(value) if kind == "num" else ALIASES.get(value, value), space and i == 0))
    return out


def _segment(name: str, grammar: Grammar) -> tuple[int, list[tuple[str, str]]]:
    """How many ways (0, 1, or 2 for "several") ``name`` reads as known names in a row, and one of them."""
    n = len(name)
    if n > 40:
        return 0, []
    memo: dict[tuple[int, bool], tuple[int, list]] = {}

    def ways(i: int, after_func: bool) -> tuple[int, list]:
        if i == n:
            return 1, []
        if (i, after_func) in memo:
            return memo[(i, after_func)]
        count, best = 0, []
        for j in range(i + 1, n + 1):
            piece = name[i:j]
            if piece.isdigit():
                if not after_func or (j < n and name[j].isdigit()):
                    continue
                kind: str | None = "num"
            else:
                kind = grammar.kind(piece)
                if kind is None or kind == "unit" or piece == "e":
                    continue
            c, rest = ways(j, kind == "func")
            if c:
                count += c
                best = [(kind, piece)] + rest
            if count > 1:
                break
        memo[(i, after_func)] = (min(count, 2), best)
        return memo[(i, after_func)]

    return ways(0, False)
