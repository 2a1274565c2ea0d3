"""Feedback typesets its mathematics: a Trace reason or a quoted Design step shows KaTeX,
never the `$…$` source (the grader sends the formulas as data.math; the native side is
tests/unit/test_message_math.py)."""

from __future__ import annotations

from helpers import answer_trace, arrange_design, check, exercise, open_chapter, role
from workbook import bank
from workbook.kinds.design import Design
from workbook.kinds.trace import Trace


def typeset(ex) -> dict:
    """What the feedback shows: its visible text, and how many KaTeX formulas it holds."""
    box = ex.locator(role("feedback"))
    box.locator(".katex").first.wait_for()
    return {"text": box.inner_text(), "formulas": box.locator(".katex").count(),
            "source": box.locator(".arithmatex:not([data-rendered])").count()}


def test_the_first_trace_reason_a_learner_meets_is_typeset(page, site_url):
    open_chapter(page, site_url, 0)
    ex = exercise(page, "0.3")
    assert answer_trace(ex, "b") == "correct"
    shown = typeset(ex)
    assert shown["formulas"] == 1 and shown["source"] == 0
    assert "$" not in shown["text"] and "\\top" not in shown["text"]
    assert shown["text"].startswith("Right. A rotation matrix is orthogonal")
    # a wrong answer without formulas is plain text, as before
    assert answer_trace(ex, "c") == "incorrect"
    box = ex.locator(role("feedback"))
    assert box.locator(".katex").count() == 0 and box.inner_text().startswith("That turns the point")


def test_a_wrong_trace_answer_and_a_design_message_are_typeset(page, site_url):
    open_chapter(page, site_url, 1)
    ex = exercise(page, "1.4")
    assert answer_trace(ex, "a") == "incorrect"
    shown = typeset(ex)
    assert shown["formulas"] >= 1 and "$" not in shown["text"] and "\\top" not in shown["text"]
    design = exercise(page, "1.5")
    order = list(reversed(bank.get("1.5").solution))
    arrange_design(design, order)
    assert check(design) == "incorrect"
    shown = typeset(design)
    assert shown["formulas"] >= 1 and "$" not in shown["text"] and "\\text" not in shown["text"]


def test_every_formula_in_a_trace_or_design_message_is_valid_katex(page, site_url):
    """Natively we know the pieces pair up; here KaTeX must read each one without an error."""
    texs = sorted({p["tex"] for ex in bank.all_exercises() if isinstance(ex, (Trace, Design))
                   for verdict in _replies(ex) for p in verdict.data.get("math", []) if isinstance(p, dict)})
    assert len(texs) >= 17
    open_chapter(page, site_url, 0, wait_ready=False)
    page.wait_for_function("() => Boolean(window.katex)")
    failed = page.evaluate(
        "(texs) => texs.flatMap((t) => { try { katex.renderToString(t, { throwOnError: true }); return []; }"
        " catch (e) { return [t + ': ' + e.message]; } })", texs)
    assert failed == []


def _replies(ex):
    if isinstance(ex, Trace):
        return [ex.check(o.key) for o in ex.options]
    keys = list(ex.solution)
    return [ex.check(keys[i:] + keys[:i]) for i in range(1, len(keys))]
