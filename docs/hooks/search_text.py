"""MkDocs hook: search results that show formulas as text, not as LaTeX source.

The search plugin indexes each page's HTML as text, so a formula appears in a
result's snippet as its source, ``\\(\\theta = \\pi/6\\)``. After the plugin has
written ``search/search_index.json`` (hooks run after the plugins), every
``\\(…\\)`` and ``\\[…\\]`` in the index's titles and texts is replaced by a
Unicode reading of it (``θ = π/6``), made by pylatexenc. The pages themselves
keep their TeX for KaTeX.
"""

from __future__ import annotations

import html
import json
import re
from pathlib import Path

from pylatexenc.latex2text import LatexNodes2Text, MacroTextSpec, get_default_latex_context_db

INDEX = "search/search_index.json"
MATH = re.compile(r"\\\((.+?)\\\)|\\\[(.+?)\\\]", re.S)
# Relations and binary operators stand between spaces ("θ = π/6", "3 × 3"), however the TeX spaced them.
SPACED = "=≠≈≤≥<>→×·"
# Operator names, read with a space either side ("v cos θ", not "vcos θ"); pylatexenc's defaults
# lack some of them (it would drop "det" from "\det R").
OPERATORS = ("det", "tr", "rank", "diag", "arg", "sgn", "sin", "cos", "tan", "exp", "log", "ln", "min", "max")


def _converter() -> LatexNodes2Text:
    context = get_default_latex_context_db().filter_context()
    context.add_context_category(
        "workbook-operators", prepend=True,
        macros=[MacroTextSpec(name, simplify_repl=f" {name} ") for name in OPERATORS])
    return LatexNodes2Text(latex_context=context, math_mode="text", strict_latex_spaces=False)


def spaced(plain: str) -> str:
    """A formula's Unicode reading with one space around each relation and operator name, none inside brackets."""
    plain = re.sub(f"\\s*([{SPACED}])\\s*", r" \1 ", plain)
    plain = " ".join(plain.split())
    plain = re.sub(r"([(\[{]) ", r"\1", plain)  # "(cos x)", not "( cos x)"
    plain = re.sub(r" ([,;)\]}])", r"\1", plain)
    plain = re.sub(rf"\b({'|'.join(OPERATORS)}) \(", r"\1(", plain)  # "sin(θ)" as written
    return re.sub(r"(^|[(\[{]|[=<>≤≥≠≈→] )- (?=\S)", r"\1-", plain)  # a leading minus: "-sin θ", "= -1"


def math_as_text(text: str, convert=None) -> str:
    """``text`` (HTML-escaped, as the index holds it) with each inline or display formula read as Unicode."""
    convert = convert or _converter().latex_to_text

    def one(match: re.Match) -> str:
        tex = html.unescape(match.group(1) if match.group(1) is not None else match.group(2))
        try:
            plain = convert(tex)
        except Exception:  # a formula pylatexenc cannot read: keep its source rather than fail the build
            return match.group(0)
        return html.escape(spaced(plain), quote=False)

    return MATH.sub(one, text)


def on_post_build(config, **kwargs):
    path = Path(config.site_dir) / INDEX
    if not path.exists():
        return
    index = json.loads(path.read_text(encoding="utf-8"))
    convert = _converter().latex_to_text
    for doc in index.get("docs", []):
        for key in ("title", "text"):
            if isinstance(doc.get(key), str):
                doc[key] = math_as_text(doc[key], convert)
    path.write_text(json.dumps(index, ensure_ascii=False, separators=(",", ":")), encoding="utf-8")
