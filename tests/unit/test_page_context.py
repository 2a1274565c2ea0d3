"""The page's exercise context is declared once (exerciseContext in docs/assets/js/exercise.js).

The object is sealed, so a module that sets a field the declaration lacks throws in the page;
this finds such a line before a page does: every ``ctx.NAME = ...`` (and ``this.ctx.NAME``) in the
page's modules sets a declared field, every field a module reads is declared, and the variant
on screen is always a number (no ``ctx.variant ?? 0``).
"""

import re
from pathlib import Path

JS = Path(__file__).resolve().parents[2] / "docs" / "assets" / "js"
SOURCES = {path: path.read_text(encoding="utf-8") for path in JS.rglob("*.js")}
DECLARATION = re.search(r"function exerciseContext\(el, shared\) \{.*?Object\.seal\(\{(.*?)\n  \}\);",
                        SOURCES[JS / "exercise.js"], re.S)


def declared() -> set[str]:
    assert DECLARATION, "exercise.js declares no exerciseContext"
    return set(re.findall(r"^\s{4}(\w+)(?=[,:])", DECLARATION.group(1), re.M))


def test_the_declaration_names_every_field():
    assert {"el", "id", "runtime", "progress", "variant", "submit", "field", "given", "steps", "step"} <= declared()


def test_every_field_a_module_sets_or_reads_is_declared():
    fields = declared()
    for path, text in SOURCES.items():
        set_ = set(re.findall(r"\bctx\.(\w+)\s*=(?!=)", text))
        read = set(re.findall(r"\bctx\.(\w+)\b", text))
        assert set_ <= fields, f"{path.name} sets ctx fields exerciseContext does not declare: {sorted(set_ - fields)}"
        assert read <= fields, f"{path.name} reads ctx fields exerciseContext does not declare: {sorted(read - fields)}"


def test_the_variant_on_screen_is_always_a_number():
    for path, text in SOURCES.items():
        assert "ctx.variant ??" not in text, f"{path.name}: ctx.variant is declared as a number"
