"""The golden variant 0: every exercise's statement, hint and derivation as the page prints them.

Every Derive exercise is a generator whose chapter text holds ``{{name}}``
placeholders; variant 0 must print exactly what the workbook printed before the
placeholders came in. ``variant0.json`` beside this file holds those pages'
HTML (title, prompt, hint, derivation and worked answer per exercise);
``tests/unit/test_variants.py`` renders variant 0 from the templates and
compares byte for byte.

    python tests/golden/variant0.py --write

rewrites it, after a deliberate change of a chapter's text.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
for path in (ROOT / "pyodide_pkg", ROOT / "docs" / "hooks"):
    sys.path.insert(0, str(path))

from exercise_text import load_all  # noqa: E402
from workbook import bank  # noqa: E402

FILE = Path(__file__).with_name("variant0.json")


def pages() -> dict[str, dict[str, str]]:
    """Each exercise's variant-0 texts, as the build renders them."""
    out = {}
    for ex_id, text in load_all(ROOT).items():
        ex = bank.get(ex_id)
        filled = text.filled(getattr(ex, "values", {}) or {})
        out[ex_id] = {**filled.as_dict(), "title": filled.title or ex.title, "worked": ex.worked_html()}
    return dict(sorted(out.items(), key=lambda kv: tuple(map(int, kv[0].split(".")))))


if __name__ == "__main__":
    text = json.dumps(pages(), ensure_ascii=False, indent=1) + "\n"
    if "--write" in sys.argv:
        FILE.write_text(text, encoding="utf-8")
        print(f"wrote {FILE.relative_to(ROOT)}")
    else:
        sys.stdout.write(text)
