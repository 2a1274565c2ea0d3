"""Messages with mathematics: every Trace reason and quoted Design step carries its
formulas as pieces the page typesets (data.math), and no `$` is left unpaired.

The browser side (the pieces typeset with KaTeX, no `$` on screen) is
tests/browser/test_feedback_math.py.
"""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "pyodide_pkg"))

from workbook import bank
from workbook.kinds.design import Design, Step
from workbook.kinds.trace import Option, Trace
from workbook.math_text import pieces


def joined(parts) -> str:
    """The pieces written back as the chapter writes them."""
    return "".join(p if isinstance(p, str) else f"${p['tex']}$" for p in parts)


def trace_replies():
    """(exercise id, option key, verdict) for every option of every Trace exercise."""
    return [(ex.id, o.key, ex.check(o.key)) for ex in bank.all_exercises() if isinstance(ex, Trace) for o in ex.options]


def test_every_trace_message_with_tex_comes_with_its_pieces():
    with_tex = []
    for ex_id, key, verdict in trace_replies():
        math = verdict.data.get("math")
        if "$" in verdict.message:
            with_tex.append((ex_id, key))
            assert math, (ex_id, key)
            assert joined(math) == verdict.message, (ex_id, key)
            assert all(isinstance(p, str) or (set(p) == {"tex"} and p["tex"].strip()) for p in math)
            assert not any("$" in (p if isinstance(p, str) else p["tex"]) for p in math), (ex_id, key)
        else:
            assert math is None, (ex_id, key)
    # the issue counted them: 0.3's right answer is the first a learner meets
    assert ("0.3", "b") in with_tex
    assert len(with_tex) >= 17 and len({ex_id for ex_id, _ in with_tex}) >= 8, with_tex


def test_no_trace_or_design_text_leaves_a_dollar_unpaired():
    for ex in bank.all_exercises():
        if isinstance(ex, Trace):
            for o in ex.options:
                assert joined(pieces(o.text)) == o.text and joined(pieces(o.why)) == o.why, (ex.id, o.key)
        if isinstance(ex, Design):
            for step in ex.steps:
                assert joined(pieces(step.text)) == step.text, (ex.id, step.key)


def test_a_design_message_quoting_a_formula_carries_it():
    ex = bank.get("1.5")
    order = list(reversed(ex.solution))
    verdict = ex.check(order)
    assert verdict.status == "incorrect" and "$" in verdict.message
    assert joined(verdict.data["math"]) == verdict.message
    assert verdict.data["first_wrong"] == 1  # the data it had stays
    assert "math" not in ex.check(list(ex.solution)).data


@pytest.mark.parametrize("text", ["costs $5", "$a$ and $b", "$$"])
def test_an_unpaired_dollar_is_refused_when_the_bank_loads(text):
    with pytest.raises(ValueError, match=r"exercise 99\.1"):
        Trace(id="99.1", title="t", answer="a", options=(Option("a", "fine", text), Option("b", "fine", "fine")))
    with pytest.raises(ValueError, match=r"exercise 99\.1"):
        Design(id="99.1", title="t", steps=(Step("a", text), Step("b", "two")), shown=("b", "a"))
