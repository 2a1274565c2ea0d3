"""The decision records (docs/decisions/): each dated, with its context, decision and consequences, and indexed.

docs/performance.md keeps the bench's method and latest numbers; every lever tried and every
finding is a record of its own, numbered in the order tried, and listed on docs/decisions/index.md.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
DECISIONS = ROOT / "docs" / "decisions"
RECORDS = sorted(DECISIONS.glob("[0-9][0-9][0-9][0-9]-*.md"))
NAME = re.compile(r"^(\d{4})-[a-z0-9]+(-[a-z0-9]+)*\.md$")


def test_the_records_are_numbered_in_order_from_one():
    assert len(RECORDS) >= 40
    assert all(NAME.match(p.name) for p in RECORDS), [p.name for p in RECORDS if not NAME.match(p.name)]
    assert [int(p.name[:4]) for p in RECORDS] == list(range(1, len(RECORDS) + 1))


@pytest.mark.parametrize("path", RECORDS, ids=lambda p: p.name[:4])
def test_each_record_is_dated_with_context_decision_and_consequences(path):
    text = path.read_text(encoding="utf-8")
    assert text.startswith(f"# {path.name[:4]}. ")
    assert re.search(r"^- \*\*Date:\*\* 20\d\d-[01]\d-[0-3]\d\b", text, re.M), "no date"
    assert re.search(r"^- \*\*Status:\*\* \S", text, re.M), "no status"
    headings = re.findall(r"^## (.+)$", text, re.M)
    assert headings == ["Context", "Decision", "Consequences"]
    for part in re.split(r"^## .+$", text, flags=re.M)[1:]:
        assert part.strip(), f"{path.name}: an empty section"
    # Markdown only, no HTML of its own: every record renders through one template, which the
    # browser tests audit on a sample (tests/browser/test_a11y.py, DECISIONS_AUDITED).
    prose = re.sub(r"`[^`]*`", "", text, flags=re.S)
    assert not re.search(r"<[A-Za-z/!]", prose), f"{path.name}: raw HTML"


def test_the_index_lists_every_record_and_performance_links_it():
    index = (DECISIONS / "index.md").read_text(encoding="utf-8")
    listed = re.findall(r"^\| \[(\d{4})\]\(([^)]+)\)", index, re.M)
    assert [name for _, name in listed] == [p.name for p in RECORDS]
    performance = (ROOT / "docs" / "performance.md").read_text(encoding="utf-8")
    assert "](decisions/index.md)" in performance
    assert "## Findings" in performance and "\n- **" not in performance.split("## Findings")[1]  # no finding left inline
    assert len(performance.splitlines()) < 200  # the method and the latest numbers (it was 750 lines)
