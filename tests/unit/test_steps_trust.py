"""Checked steps whose verdicts a teacher would not sign (issue 46, "Steps and chains"), over 200 draws each.

- 6.3: cos θ2 = −1 (the bank's own slip "took away (L1 + L2)²") makes θ2 = ±180°. When θ2 is asked, that
  θ2 is defined: step 2 and the final follow from step 1 (carried), never "undefined". When θ1 is asked, θ1
  is rightly undefined there, and the verdict names step 1, where the slip is: step 2 follows from it.
- 5.7: an entry's floor for cancelling takes its scale from its own row and column, not from Ω₃₃ = 1000, so a
  wrong determinant does not credit an x–y block of zeros as carried, as a final or as step 2.
"""

from __future__ import annotations

import pytest

import many_draws
from through_api import grade
from workbook import bank
from workbook.number_format import fmt

SEEDS = range(many_draws.count(200))


def _asks_theta2(v) -> bool:
    return v.answer.label.startswith("θ2")


@pytest.mark.parametrize("seed", SEEDS)
def test_6_3_a_theta2_of_180_follows_from_cos_minus_one(seed):
    v = bank.get("6.3").variant(seed)
    half_turn = "180" if "elbow-down" in v.answer.label else "-180"
    assert fmt(min((s.value for s in v.step_answers["c2"].slips), key=lambda c: abs(c + 1))) == "-1"
    step2 = grade(v, half_turn, step="t2", sent={"c2": "-1"})
    assert step2["tag"] == "carried" and step2["data"]["carried"]["step"] == "c2", step2
    assert "step 1" in step2["message"]
    if _asks_theta2(v):
        final = grade(v, half_turn, sent={"c2": "-1", "t2": half_turn})
        assert final["tag"] == "carried" and final["data"]["carried"]["step"] == "c2", final
    else:
        final = grade(v, "17", sent={"c2": "-1", "t2": half_turn})
        assert final["tag"] == "undefined" and final["data"]["carried"]["step"] == "c2", final
        assert "The slip is in step 1" in final["message"] and "no θ1 reaches the target" in final["message"]


def test_6_3_draws_ask_both_angles():
    asked = {_asks_theta2(bank.get("6.3").variant(seed)) for seed in SEEDS}
    assert asked == {True, False}


@pytest.mark.parametrize("seed", SEEDS)
def test_5_7_a_wrong_determinant_does_not_credit_a_block_of_zeros(seed):
    v = bank.get("5.7").variant(seed)
    det, w33 = v.step_answers["det"].key, v.answer.key[2][2]
    s, b = v.params["s"], v.params["b"]
    for factor in (10, 100, 1000):
        wrong = float(fmt(det * factor))
        block = [[s / wrong, -b / wrong], [-b / wrong, s / wrong]]
        if max(abs(e) for row in block for e in row) < 5e-4:
            continue  # zeros are the learner's block to the figures typed: they do follow
        zeros = f"0, 0, 0; 0, 0, 0; 0, 0, {fmt(w33)}"
        final = grade(v, zeros, sent={"det": fmt(wrong)})
        assert final["tag"] != "carried", (factor, final)
        step = grade(v, "0, 0; 0, 0", step="block", sent={"det": fmt(wrong)})
        assert step["tag"] != "carried", (factor, step)
        # and the block the learner's determinant does give is still carried, as a step and in the final
        typed = "; ".join(", ".join(fmt(e, significant=6) for e in row) for row in block)
        assert grade(v, typed, step="block", sent={"det": fmt(wrong)})["tag"] == "carried"
        whole = f"{typed.split('; ')[0]}, 0; {typed.split('; ')[1]}, 0; 0, 0, {fmt(w33)}"
        assert grade(v, whole, sent={"det": fmt(wrong), "block": typed})["tag"] == "carried"


@pytest.mark.parametrize("seed", SEEDS)
def test_6_2_a_final_inside_the_typed_step_s_own_rounding_follows_from_it(seed):
    """6.2: a wrong x₂ typed to 4 decimals, the final worked from its unrounded value. Where x = cos θ1 + x₂
    cancels, the final lies outside the tolerance of the key worked from the typed x₂, though inside what that
    x₂'s rounding allows (half a unit of its last digit either way): it is carried all the same."""
    v = bank.get("6.2").variant(seed)
    c1 = v.answer.key - v.step_answers["x2"].key
    t12 = fmt(v.step_answers["t12"].key)
    checked = 0
    for k in range(1, 40):
        unrounded = -c1 + k * 0.00137  # finals from 0.00137 up: they cancel against cos θ1
        typed = f"{unrounded:.4f}"
        final = f"{c1 + unrounded:.4g}"
        if v.step_answers["x2"].check(typed).status == "correct":
            continue
        lo, hi = sorted((c1 + float(typed) - 5e-5, c1 + float(typed) + 5e-5))
        if not lo <= float(final) <= hi:
            continue
        said = grade(v, final, sent={"t12": t12, "x2": typed})
        assert said["tag"] == "carried" and said["data"]["carried"]["step"] == "x2", (typed, final, said)
        checked += 1
    assert checked >= 20
    # outside that rounding it is still refused
    far = f"{c1 + float(f'{-c1 + 0.01:.4f}') + 0.0003:.4g}"
    assert grade(v, far, sent={"t12": t12, "x2": f"{-c1 + 0.01:.4f}"})["tag"] != "carried"
