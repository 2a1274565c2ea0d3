"""Printed = accepted, and printed arithmetic adds up: 1,000 variants of every Derive exercise.

For every distinct draw among variants 0–999 of every Derive exercise, read
from the page's rendered text (the templates filled as the page and the
worker's ``draw`` fill them):

- the derivation's ``**Answer:**`` line ends with the worked answer itself
  (the ``{{worked}}`` placeholder, which the answer kind fills), and the grader
  accepts what it prints, with the words after it (``300 variables``, ``0.5 m``);
- "Type it as" (the worked answer) is accepted;
- every relation ``A = B`` or ``A ≈ B`` between two numeric sides, in the
  statement, the hint and the derivation, holds to the printed precision
  (``printed_math.check_formula``);
- arithmetic the hint or the derivation prints on its own printed numbers
  (``0.8192 - 0.8660``) that stands for the answer, done as printed and typed
  with every digit it gives (``-0.0468``), is accepted: the page never prints
  values too rounded to reach the key.

``python tests/unit/test_printed.py`` prints the counts (draws, relations
checked) and every failure, for a closing note.
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

import pytest

import many_draws
from exercise_text import load_all  # docs/hooks/exercise_text.py
from printed_math import check_formula, computed, math_of, read_side, relations
from workbook import bank

ROOT = Path(__file__).resolve().parents[2]
SEEDS = range(many_draws.count(1000))
DERIVE = [ex for ex in bank.all_exercises() if ex.kind == "derive"]
TEXTS = load_all(ROOT)
ANSWER_LINE = re.compile(r"<p>\s*<strong>Answer:</strong>(.*?)</p>", re.S)


def draws(ex):
    """The distinct variants among the seeds (many seeds share a draw on a small grid)."""
    seen = set()
    for seed in SEEDS:
        v = ex.variant(seed)
        key = tuple(sorted(v.values.items()))
        if key not in seen:
            seen.add(key)
            yield seed, v


def answer_line_problems(v, solution_html: str) -> list[str]:
    found = ANSWER_LINE.findall(solution_html)
    if len(found) != 1:
        return [f"the derivation has {len(found)} Answer lines"]
    formulas = math_of(found[0])
    if not formulas:
        return ["the Answer line has no formula"]
    chains = relations(formulas[-1])
    printed = chains[-1][-1][0] if chains else formulas[-1].strip()
    out = []
    if printed.rstrip(". ") != v.answer.worked_tex():
        out.append(f"the Answer line ends with {printed!r}, not the worked answer {v.answer.worked_tex()!r}")
    verdict = v.check(printed)
    if verdict.status != "correct":
        out.append(f"the Answer line's {printed!r} is graded {verdict.status}: {verdict.message}")
    words = re.sub(r"<[^>]*>", "", found[0].rsplit("</span>", 1)[-1]).strip().rstrip(".").strip()
    if words and v.answer_kind == "number":  # "$300$ variables", "$x = 0.5$ m": the line as a learner copies it
        verdict = v.check(f"{printed.rstrip('. ')} {words}")
        if verdict.status != "correct":
            out.append(f"the Answer line's {printed!r} with its words {words!r} is graded {verdict.status}: "
                       f"{verdict.message}")
    return out


def computed_problems(v, filled) -> list[str]:
    """The answer computed from the printed numbers of the hint and the derivation, where they print the sum."""
    key = v.answer.key
    if v.answer_kind == "number":
        flat = [key]
    elif v.answer_kind == "matrix":
        flat = [x for row in key for x in row]
    else:
        return []
    out = []
    for tex in math_of(filled.hint) + math_of(filled.solution):
        for chain in relations(tex):
            for side, _ in chain:
                got = computed(side)
                if got is None or len(got.values) != len(flat) or not all(
                        abs(a - k) <= s + 2e-3 * abs(k) for a, s, k in zip(got.values, got.slack, flat)):
                    continue  # not arithmetic on printed numbers, or not the answer
                typed = [f"{x:.12g}" for x in got.values]
                if v.answer_kind == "matrix":
                    c = v.answer.shape[1]
                    typed = [typed[i:i + c] for i in range(0, len(typed), c)]
                verdict = v.check(typed if v.answer_kind == "matrix" else typed[0])
                if verdict.status != "correct":
                    out.append(f"{side.strip()[:70]!r} computed as printed, {typed}, is graded {verdict.status}: "
                               f"{verdict.message}")
    return out


def problems_of(ex) -> tuple[list[str], int, int]:
    """Every failure over the draws, the number of draws, and the number of relations checked."""
    problems, n_draws, n_checked = [], 0, 0
    for seed, v in draws(ex):
        n_draws += 1
        filled = TEXTS[ex.id].filled(v.values)
        here = [f"Answer line: {p}" for p in answer_line_problems(v, filled.solution)]
        here += computed_problems(v, filled)
        worked = v.check(v.worked_text() if v.answer_kind != "matrix" else v.answer.typed(v.answer.key))
        if worked.status != "correct":
            here.append(f"type it as {v.worked_text()!r}: {worked.status}")
        if v.answer_kind == "matrix" and v.check(v.worked_text()).status != "correct":
            here.append(f"the worked grid {v.worked_text()!r} is not accepted")
        for part in (filled.title, filled.prompt, filled.hint, filled.solution):
            for tex in math_of(part):
                n_checked += sum(1 for chain in relations(tex) for (a, _), (b, rel) in zip(chain, chain[1:])
                                 if rel in ("=", "\\approx") and read_side(a) and read_side(b))
                here += check_formula(tex)
        problems += [f"{ex.id} variant {seed}: {p}" for p in here]
    return problems, n_draws, n_checked


@pytest.mark.parametrize("ex", DERIVE, ids=lambda ex: ex.id)
def test_printed_is_accepted_and_adds_up(ex):
    problems, _, _ = problems_of(ex)
    assert not problems, f"{len(problems)} problems, e.g.\n" + "\n".join(problems[:12])


if __name__ == "__main__":
    sys.path[:0] = [str(ROOT / "pyodide_pkg"), str(ROOT / "docs" / "hooks")]
    total = [0, 0, 0]
    for ex in DERIVE:
        problems, n, checked = problems_of(ex)
        total[0] += n
        total[1] += checked
        total[2] += len(problems)
        print(f"{ex.id}: {n} draws, {checked} relations checked, {len(problems)} problems")
        for p in problems[:3]:
            print("   ", p)
    print(f"all: {total[0]} draws, {total[1]} relations checked, {total[2]} problems")
