"""Chapter 12 · Bayes and particle filters: the discrete Bayes filter on a ring of five cells, its
predict (12.1, a convolution with the motion's kernel, in checked steps: the belief moved exactly
one cell, then two) and its update by a door sensor's likelihood (12.2, which carries 12.1's predicted belief,
in checked steps: the products, then their sum 1/η).

>>> from workbook import bank
>>> bank.get("12.1").worked_text()
'[0.04; 0.13; 0.3; 0.35; 0.18]'
>>> bank.get("12.2").worked_text()
'[0.02151; 0.2097; 0.4839; 0.1882; 0.09677]'
"""

from __future__ import annotations

from .. import chains
from ..answer_kinds.matrix import matrix
from ..answer_kinds.number import number
from ..chains import Uses
from ..kinds.derive import Derive
from ..number_format import bmatrix, fmt
from ..reference.particles import normalise, predict
from ..steps import Step
from ..variants import Choice, Param, Vary
from . import column, entries
from .checks import kept_slips

CELLS = 5
_NAMES = tuple(f"c{i}" for i in range(1, CELLS + 1))


def _column_or_none(values):
    return None if values is None else column(values)


def _col(values) -> str:
    return bmatrix(column(values))


def _shift(belief, k: int) -> list[float]:
    """bel(i − k) for every cell i, round the ring."""
    return predict(belief, {k: 1.0})


def _drawn_belief(p, prefix: str) -> list[float] | None:
    """Four drawn cells and the fifth that makes them add up to 1 (None when it would be negative)."""
    first = [float(p[f"{prefix}{i}"]) for i in range(1, CELLS)]
    last = round(1.0 - sum(first), 10)
    return None if last < 0 else [*first, last]


# ---- 12.1 Predict: a convolution ------------------------------------------------------------------

_PRIOR = (0.1, 0.3, 0.4, 0.2)  # and 0 in cell 5


def _kernel(p) -> dict[int, float]:
    under, over = float(p["under"]), float(p["over"])
    return {0: under, 1: round(1.0 - under - over, 10), 2: over}


def _predict(p, given=None):
    """12.1: bel′(i) = p₀ bel(i) + p₁ bel(i − 1) + p₂ bel(i − 2), with the learner's own bel(i − 1) (which,
    moved one cell more, is bel(i − 2)) and bel(i − 2) when given."""
    bel = _drawn_belief(p, "b") or [0.2] * CELLS
    k = _kernel(p)
    one_key = _shift(bel, 1)
    one = entries(chains.given(given, "one", column(one_key)))
    two_key = _shift(one, 1)
    two = entries(chains.given(given, "two", column(two_key)))
    key = [k[0] * b + k[1] * o + k[2] * t for b, o, t in zip(bel, one, two)]
    back = predict(bel, {0: k[0], -1: k[1], -2: k[2]})
    no_wrap = [k[0] * bel[i] + k[1] * (bel[i - 1] if i >= 1 else 0.0) + k[2] * (bel[i - 2] if i >= 2 else 0.0)
               for i in range(CELLS)]
    return {
        "key": column(key),
        "slips": kept_slips(column(key), (
            (column(back), "That moves the belief the wrong way round the ring: bel′(i) takes bel(i − k), the "
                           "cell k behind, for a move of k cells forward.", "kernel-backwards"),
            (column(one_key), "That is the belief moved exactly one cell: the chances of staying put and of "
                              "moving two cells must be added too.", "exact-move-only"),
            (column(no_wrap), "That lets the belief fall off the end of the corridor: on the ring, a move past "
                              "cell 5 comes back at cell 1, so the cells still add up to 1.", "no-wrap"),
            (column([k[1] * o for o in one_key]),
             f"That is only p₁ bel(i − 1), the exact move weighted by {fmt(k[1])}: add p₀ bel(i) and "
             "p₂ bel(i − 2).", "one-term-only"),
        )),
        "steps": {
            "one": {"key": column(one_key), "slips": kept_slips(column(one_key), (
                (column(_shift(bel, -1)), "That moves the belief one cell back: bel(i − 1) is the cell behind "
                                          "cell i, so cell 1's value moves to cell 2.", "shift-backwards"),
                (column(bel), "That is the belief before the move.", "not-shifted"),
            ))},
            "two": {"key": column(two_key), "slips": kept_slips(column(two_key), (
                (column(_shift(one, -1)), "That moves bel(i − 1) back again, which gives bel(i) itself: bel(i − 2) "
                                          "is bel(i − 1) moved one cell further forward.", "two-shift-backwards"),
                (column(one), "That is bel(i − 1): move it one cell further forward.", "two-not-shifted"),
            ))},
        },
        "values": {
            "bel": _col(bel), "b5": fmt(bel[-1]), "p0": fmt(k[0]), "p1": fmt(k[1]), "p2": fmt(k[2]),
        },
    }


def _predict_ok(p):
    """A belief that adds up to 1, with mass in at least two cells, and three of the slips told apart."""
    bel = _drawn_belief(p, "b")
    if bel is None or sum(1 for b in bel if b > 0) < 2:
        return False
    made = _predict(p)
    return (len(made["slips"]) >= 3 and len(made["steps"]["one"]["slips"]) == 2
            and len(made["steps"]["two"]["slips"]) == 2)


# ---- 12.2 Update: multiply by the likelihood, normalise ------------------------------------------

_PREDICTED = (0.04, 0.13, 0.3, 0.35)  # 12.1's answer for its own numbers (and 0.18 in cell 5)
_DOORS = {"2, 3": (2, 3), "1, 3": (1, 3), "2, 4": (2, 4), "3, 5": (3, 5), "1, 4": (1, 4), "4, 5": (4, 5)}


def _likelihood(p) -> list[float]:
    doors = _DOORS[p["doors"]]
    return [float(p["hit"]) if i + 1 in doors else float(p["false"]) for i in range(CELLS)]


def _carries_121(p):
    """12.1's variant whose answer this draw carries: the workbook's own numbers carry variant 0's."""
    return 0 if tuple(p[f"a{i}"] for i in range(1, CELLS)) == _PREDICTED else None


def _spread(values) -> list[float] | None:
    """The values normalised, or None when they add up to 0 (a slip that cannot be formed)."""
    return normalise(values) if sum(values) > 0 else None


def _update(p, given=None):
    """12.2: bel(i) ∝ p(door | i) bel′(i), with the learner's 12.1 answer, products and η when given."""
    prior_key = _drawn_belief(p, "a") or [0.2] * CELLS
    prior = entries(chains.given(given, "prior", column(prior_key)))
    like = _likelihood(p)
    prod_key = [a * b for a, b in zip(like, prior)]
    prod = entries(chains.given(given, "prod", column(prod_key)))
    eta_key = sum(prod)
    eta = float(chains.given(given, "eta", eta_key))
    key = [v / eta for v in prod] if eta else [0.0] * CELLS
    plain = normalise(prior_key) if sum(prior_key) > 0 else prior_key
    return {
        "key": column(key),
        "slips": kept_slips(column(key), (
            (column(prod), "Those are the products p(z | i) bel′(i) before normalising: divide each by their sum, "
                           f"{fmt(eta_key)}, so that the cells add up to 1.", "not-normalised"),
            (_column_or_none(_spread([b * (1 - q) for b, q in zip(prior, like)])),
             "That weights each cell by the chance of seeing no door there: the sensor saw a door, so a door "
             "cell's weight is p(door | door).", "likelihood-of-the-other-reading"),
            (_column_or_none(_spread([a + b for a, b in zip(like, prior)])), "That adds the likelihood to the belief: "
                                                                       "Bayes' rule multiplies them.", "added"),
            (column(plain), "That is the predicted belief itself: the measurement has not been used.",
             "update-skipped"),
        )),
        "steps": {
            "prod": {"key": column(prod_key), "slips": kept_slips(column(prod_key), (
                (column([b * (1 - q) for b, q in zip(prior, like)]),
                 "Those use 1 − p(door | i), the chance of seeing no door; the sensor saw one.", "other-reading"),
                (column(like), "That is the likelihood alone: multiply it by the predicted belief.", "likelihood-only"),
            ))},
            "eta": {"key": eta_key, "slips": kept_slips(eta_key, (
                (sum(like), "That adds up the likelihoods alone: add up the products p(z | i) bel′(i).",
                 "sum-of-likelihoods"),
                (1.0 / eta_key, "That is η, the inverse of the sum: this step asks for the sum of the products "
                                "itself, 1/η.", "eta-inverted"),
            ))},
        },
        "values": {
            "a5": fmt(prior_key[-1]), "like": _col(like),
            "hit": fmt(p["hit"]), "false": fmt(p["false"]),
            "from121": ("exercise 12.1's predicted belief" if _carries_121(p) == 0
                        else "the predicted belief after a move"),
        },
    }


def _update_ok(p):
    """A prior that adds up to 1 with every cell above 0, a sensor better than chance, and the slips told apart."""
    prior = _drawn_belief(p, "a")
    if prior is None or min(prior) <= 0 or p["hit"] <= p["false"]:
        return False
    made = _update(p)
    return (len(made["slips"]) >= 3 and len(made["steps"]["prod"]["slips"]) == 2
            and len(made["steps"]["eta"]["slips"]) == 2)


EXERCISES = (
    Derive(
        id="12.1",
        title="Predict on a grid: a convolution",
        spec=matrix(label="bel′, cells 1 to 5", names=_NAMES),
        vary=Vary(_predict, *(Param(f"b{i}", _PRIOR[i - 1], 0, 0.6, 0.1) for i in range(1, CELLS)),
                  Choice("under", 0.2, (0.1, 0.2, 0.3)), Choice("over", 0.1, (0.1, 0.2)), valid=_predict_ok),
        steps=(Step("one", "bel(i − 1)", matrix(label="bel(i − 1), the belief moved exactly one cell",
                                                  names=_NAMES)),
               Step("two", "bel(i − 2)", matrix(label="bel(i − 2), the belief moved exactly two cells",
                                                  names=_NAMES))),
    ),
    Derive(
        id="12.2",
        title="Update on a grid: multiply and normalise",
        spec=matrix(label="bel, cells 1 to 5", names=_NAMES),
        vary=Vary(_update, *(Param(f"a{i}", _PREDICTED[i - 1], 0.01, 0.4, 0.01) for i in range(1, CELLS)),
                  Choice("doors", "2, 3", tuple(_DOORS)), Choice("hit", 0.6, (0.6, 0.7, 0.8, 0.9)),
                  Choice("false", 0.2, (0.1, 0.2, 0.3)), valid=_update_ok),
        uses=(Uses("12.1", "prior", "the predicted belief bel′", variant=_carries_121),),
        steps=(Step("prod", "p(z | i) bel′(i)", matrix(label="p(z | i) bel′(i), before normalising", names=_NAMES)),
               Step("eta", "1/η", number(label="1/η, the sum of the products"))),
    ),
)
