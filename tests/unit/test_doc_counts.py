"""The guides count what the bank holds: "N chapters" and "N exercises" in README.md and the
site's own pages (not the chapters) say the numbers the bank has, in digits or in words, so a
new chapter cannot leave a guide saying "eleven"."""

from __future__ import annotations

import re
from pathlib import Path

from workbook import bank

ROOT = Path(__file__).resolve().parents[2]
WORDS = ["zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "eleven", "twelve",
         "thirteen", "fourteen", "fifteen", "sixteen"]
COUNT = re.compile(r"\b(\d[\d,]*|" + "|".join(WORDS) + r")\s+(core\s+)?(chapters|exercises)\b", re.IGNORECASE)
CORE = 10  # chapters 0 to 9, the home page's core path


def _documents() -> list[Path]:
    docs = [p for p in (ROOT / "docs").rglob("*.md") if "chapters" not in p.parts]
    return [ROOT / "README.md", ROOT / "AUTHORING.md", ROOT / "DEVELOPING.md", *docs]


def _number(word: str) -> int:
    return int(word.replace(",", "")) if word[0].isdigit() else WORDS.index(word.lower())


def test_every_count_of_chapters_and_exercises_is_the_bank_s():
    chapters = len(bank.chapters())
    expected = {("chapters", False): chapters, ("chapters", True): CORE, ("exercises", False): len(bank.all_exercises())}
    wrong, seen = [], 0
    for doc in _documents():
        for m in COUNT.finditer(doc.read_text(encoding="utf-8")):
            seen += 1
            said, core, what = _number(m.group(1)), bool(m.group(2)), m.group(3).lower()
            if said != expected[(what, core)]:
                wrong.append(f"{doc.relative_to(ROOT)}: {m.group(0)!r} (the bank has {expected[(what, core)]})")
    assert seen >= 3, "the guides stopped counting: this test reads nothing"
    assert not wrong, "\n".join(wrong)
