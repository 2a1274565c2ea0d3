"""Chapter 12 · Bayes and particle filters: four particles weighted by a range likelihood (12.3, in
checked steps: the likelihoods, then their sum), their effective sample size (12.4, which carries
12.3's weights, in checked steps: the squares, then Σ w²), and systematic resampling by hand (12.5, in
checked steps: the cumulative weights, then how many pointers land in each particle's interval).

>>> from workbook import bank
>>> bank.get("12.3").worked_text()
'[0.5705; 0.3460; 0.07720; 0.006337]'
>>> bank.get("12.4").values["w1"], bank.get("12.4").worked_text()
('0.5705', '2.2164')
>>> bank.get("12.5").worked_text()
'[2; 2; 4; 4; 5]'
"""

from __future__ import annotations

import math

from .. import chains
from ..answer_kinds.matrix import matrix
from ..answer_kinds.number import number
from ..chains import Uses
from ..kinds.derive import Derive
from ..number_format import bmatrix, fmt, shown
from ..reference.domain import Undefined
from ..reference.particles import cumulative, normalise, pointers, systematic_resample
from ..steps import Step
from ..variants import Choice, Param, Vary
from . import column, entries
from .checks import kept_slips

N = 4
_W = tuple(f"w{i}" for i in range(1, N + 1))


def _col(values) -> str:
    return bmatrix(column(values))


# ---- 12.3 Weights from a range likelihood ---------------------------------------------------------

_X = (6.0, 5.5, 7.0, 4.5)


def _errors(p) -> tuple[list[float], list[float]]:
    """The ranges L − xᵢ the particles predict, and the errors z − rᵢ."""
    r = [float(p["wall"]) - float(p[f"x{i}"]) for i in range(1, N + 1)]
    return r, [float(p["z"]) - ri for ri in r]


def _weights(p, given=None):
    """12.3: wᵢ = lᵢ / Σ l with lᵢ = exp(−(z − rᵢ)² / (2σ²)), with the learner's l and Σ l when given."""
    s = float(p["sigma"])
    r, e = _errors(p)
    like_key = [math.exp(-ei * ei / (2 * s * s)) for ei in e]
    like = entries(chains.given(given, "like", column(like_key)))
    total_key = sum(like)
    total = float(chains.given(given, "total", total_key))
    key = [v / total for v in like] if total else [0.0] * N
    dens = [v / (s * math.sqrt(2 * math.pi)) for v in like_key]
    return {
        "key": column(key),
        "slips": kept_slips(column(key), (
            (column(like), f"Those are the likelihoods before normalising: divide each by their sum, "
                           f"{fmt(total_key)}, so the weights add up to 1.", "not-normalised"),
            (column(dens), "Those are the Gaussian's densities, with its factor 1/(σ√(2π)), not normalised: the "
                           "factor cancels once each is divided by the sum, and the weights must add up to 1.",
             "densities-not-normalised"),
            (column(normalise([math.exp(-ei * ei / (s * s)) for ei in e])),
             "That leaves the 2 out of the exponent: exp(−(z − r)² / (2σ²)).", "exponent-without-2"),
            (column(normalise([abs(ei) for ei in e]) if any(e) else [0.0] * N),
             "Those weights grow with the error: a particle whose predicted range is far from z must weigh "
             "less, not more.", "weights-grow-with-error"),
        )),
        "steps": {
            "like": {"key": column(like_key), "slips": kept_slips(column(like_key), (
                (column([math.exp(-ei * ei / (s * s)) for ei in e]),
                 "That leaves the 2 out: l = exp(−(z − r)² / (2σ²)).", "like-without-2"),
                (column([math.exp(-ei * ei / (2 * s)) for ei in e]),
                 f"That divides by 2σ, not 2σ²: with σ = {fmt(s)} m, 2σ² = {fmt(2 * s * s)}.", "sigma-not-squared"),
                (column(dens), "Those carry the Gaussian's factor 1/(σ√(2π)); this exercise's l leaves it out "
                               "(it cancels when the weights are normalised).", "like-with-factor"),
            ))},
            "total": {"key": total_key, "slips": ()},
        },
        "values": {
            "r": _col(r), "e": _col(e), "twos": fmt(2 * s * s),
        },
    }


def _weights_ok(p):
    """Particles inside the corridor, four different errors, no likelihood below 0.005 (no weight too small to
    type), the best weight under 0.9, and the slips told apart."""
    r, e = _errors(p)
    if min(r) <= 0 or len({abs(v) for v in e}) < N:
        return False
    made = _weights(p)
    w = entries(made["key"])
    return (min(entries(made["steps"]["like"]["key"])) >= 0.005 and max(w) < 0.9 and len(made["slips"]) >= 3
            and len(made["steps"]["like"]["slips"]) >= 2)


# ---- 12.4 The effective sample size ---------------------------------------------------------------

def _printed_123() -> list[float]:
    """12.3's weights for its own numbers, as its page prints them."""
    return [shown(v) for v in entries(_weights(_DEFAULTS_123)["key"])]


_DEFAULTS_123 = {"wall": 10, "z": 4.0, "sigma": 0.5, **{f"x{i}": _X[i - 1] for i in range(1, N + 1)}}


def _carries_123(p):
    """12.3's variant whose weights this draw carries: the workbook's own numbers carry variant 0's."""
    return 0 if [p[n] for n in _W[:-1]] == _printed_123()[:-1] else None


def _w_of(p) -> list[float]:
    """The four weights: 12.3's as printed (variant 0), or three drawn and the fourth that makes them add up to 1."""
    if _carries_123(p) == 0:
        return _printed_123()
    first = [float(p[n]) for n in _W[:-1]]
    return [*first, round(1.0 - sum(first), 10)]


def _neff(p, given=None):
    """12.4: N_eff = 1 / Σ wᵢ², with the learner's 12.3 weights and Σ w² when given."""
    w = entries(chains.given(given, "w", column(_w_of(p))))
    squares_key = [v * v for v in w]
    squares = entries(chains.given(given, "squares", column(squares_key)))
    sq_key = sum(squares)
    sq = float(chains.given(given, "sq", sq_key))
    key = 1.0 / sq if sq else 0.0
    return {
        "key": key,
        "slips": kept_slips(key, (
            (sq, "That is Σ w² itself: the effective sample size is its inverse, 1 / Σ w².", "not-inverted"),
            (1.0 / sum(w) if sum(w) else None, "That is 1 / Σ w, which is 1 for any normalised weights: square "
                                                "each weight first.", "weights-not-squared"),
            (N * sq, f"That is N Σ w²: N_eff = 1 / Σ w², between 1 and N = {N}.", "times-n"),
            (1.0 / max(w) if max(w) else None, "That is 1 / max w, another rough measure; this exercise's N_eff "
                                               "is 1 / Σ w².", "one-over-max"),
        )),
        "steps": {
            "squares": {"key": column(squares_key), "slips": kept_slips(column(squares_key), (
                (column([2 * v for v in w]), "Those are the weights doubled: square each one, wᵢ · wᵢ.", "doubled"),
                (column([math.sqrt(v) for v in w]) if min(w) >= 0 else None,
                 "Those are the square roots: square each weight, wᵢ · wᵢ.",
                 "square-roots"),
            ))},
            "sq": {"key": sq_key, "slips": kept_slips(sq_key, (
                (sum(w), "That adds up the weights, which gives 1: add up their squares.", "sum-not-squares"),
                (sum(squares) / N, f"That is the mean of the squares: add them up, without dividing by N = {N}.",
                 "mean-of-squares"),
            ))},
        },
        "values": {
            **{n: fmt(v) for n, v in zip(_W, w)},
            "verdict": ("below N/2 = 2: resample now" if key < N / 2 else
                        "at least N/2 = 2: the weights are still spread enough, so keep them and wait"),
            "from123": "the weights of exercise 12.3" if _carries_123(p) == 0 else "four normalised weights",
        },
    }


def _neff_ok(p):
    """Weights that add up to 1 with none negative, N_eff not at N/2 exactly, and the slips told apart."""
    w = _w_of(p)
    if min(w) < 0:
        return False
    made = _neff(p)
    return (abs(made["key"] - N / 2) > 0.05 and len(made["slips"]) >= 3
            and len(made["steps"]["squares"]["slips"]) == 2 and len(made["steps"]["sq"]["slips"]) == 2)


# ---- 12.5 Systematic resampling by hand -----------------------------------------------------------

M = 5
_RW = (0.1, 0.35, 0.05, 0.3)  # and 0.2 for particle 5


def _resample_parts(p):
    first = [float(p[f"q{i}"]) for i in range(1, M)]
    w = [*first, round(1.0 - sum(first), 10)]
    return w, float(p["r"])


def ptr_key_of(r: float) -> list[float]:
    """The pointers r + k/5, k = 0 … 4 (Probabilistic Robotics' form: r drawn in [0, 1/5))."""
    return pointers(r * M, M)


def _picks(c: list[float], ptr: list[float]) -> list[int]:
    """For each pointer, the particle (from 1) whose cumulative weight is the first greater than it (else the last)."""
    return [1 + next((j for j, cj in enumerate(c) if pt < cj), M - 1) for pt in ptr]


def _laid_out(copies: list[float]) -> list[float]:
    """Particle j written copies[j] times, in order: the five picks."""
    n = [round(v) for v in copies]
    if any(abs(v - k) > 1e-9 or k < 0 for v, k in zip(copies, n)) or sum(n) != M:
        raise Undefined(f"copies that are not whole numbers adding up to {M} cannot be laid out as {M} picks")
    return [float(j) for j, k in enumerate(n, 1) for _ in range(k)]


def _resample(p, given=None):
    """12.5: the particle each pointer r + k/5 picks, from the learner's cumulative weights and copies when given."""
    w, r = _resample_parts(p)
    ptr = ptr_key_of(r)
    c_key = cumulative(w)
    c = entries(chains.given(given, "cum", column(c_key)))
    picked = _picks(c, ptr)
    copies_key = [float(picked.count(j)) for j in range(1, M + 1)]
    copies = entries(chains.given(given, "copies", column(copies_key)))
    key = _laid_out(copies)
    before = [0.0, *c_key[:-1]]
    plain = [float(1 + j) for j in systematic_resample(w, 0.0)]
    nearest = [float(round(M * v)) for v in w]
    return {
        "key": column(key),
        "slips": kept_slips(column(key), (
            (column([k - 1 for k in key]), "Those count the particles from 0: number them 1 to 5, as the statement "
                                           "does.", "counted-from-zero"),
            (column([max(1.0, k - 1) for k in key]),
             "Those are one particle too early: a pointer picks the first particle whose cumulative weight is "
             "greater than it, the one whose interval [c_{j−1}, c_j) holds the pointer.", "one-too-early"),
            (column(plain), "Those are the pointers k/5 without r: every pointer starts at r.", "without-r"),
        )),
        "steps": {
            "cum": {"key": column(c_key), "slips": kept_slips(column(c_key), (
                (column(w), "Those are the weights themselves: add each one to the sum of those before it.",
                 "weights-not-summed"),
                (column(before), "Those are the sums before each particle (starting at 0): c_j includes w_j itself.",
                 "sums-before"),
            ))},
            "copies": {"key": column(copies_key), "slips": kept_slips(column(copies_key), (
                (column(w), "Those are the weights: count how many of the five pointers land in each particle's "
                            "interval [c_{j−1}, c_j).", "copies-are-weights"),
                (column(nearest) if sum(nearest) == M else None,
                 "Those are 5 w_j rounded, which the pointers need not follow: count the pointers that land in "
                 "each interval.", "rounded-5w"),
            ))},
        },
        "values": {"wt5": fmt(w[-1]), "ptr": _col(ptr), "M": str(M), "fate": _fate([int(k) for k in key])},
    }


def _numbers(ids) -> str:
    words = [str(i) for i in ids]
    return words[0] if len(words) == 1 else ", ".join(words[:-1]) + " and " + words[-1]


def _fate(picked: list[int]) -> str:
    """Which particles the pointers copy and which they drop, in words."""
    twice = sorted({j for j in picked if picked.count(j) > 1})
    dropped = [j for j in range(1, M + 1) if j not in picked]
    if not twice or not dropped:
        return "every particle is kept once"
    many, gone = len(twice) > 1, len(dropped) > 1
    copied = f"particle{'s' if many else ''} {_numbers(twice)} {'are' if many else 'is'} kept more than once"
    lost = f"particle{'s' if gone else ''} {_numbers(dropped)} {'are' if gone else 'is'} dropped"
    return f"{copied} and {lost}"


def _resample_ok(p):
    """Weights that add up to 1 with none 0, r in [0, 1/5), no pointer on a cumulative boundary, some particle
    picked twice (so another is dropped), and the slips told apart."""
    w, r = _resample_parts(p)
    if min(w) <= 0 or not 0 <= r < 1 / M:
        return False
    c = cumulative(w)
    if any(abs(pt - cj) < 0.005 for pt in ptr_key_of(r) for cj in c):
        return False
    made = _resample(p)
    return (len(set(entries(made["key"]))) < M and len(made["slips"]) == 3 and len(made["steps"]["cum"]["slips"]) == 2
            and len(made["steps"]["copies"]["slips"]) >= 1)


EXERCISES = (
    Derive(
        id="12.3",
        title="Particle weights from a range",
        spec=matrix(label="w = (w₁, w₂, w₃, w₄)ᵀ", names=_W),
        vary=Vary(_weights, Param("wall", 10, 8, 12, 1), Param("z", 4.0, 2, 6, 0.5), Choice("sigma", 0.5, (0.5, 1.0)),
                  *(Param(f"x{i}", _X[i - 1], 2, 8, 0.5) for i in range(1, N + 1)), valid=_weights_ok),
        steps=(Step("like", "lᵢ", matrix(label="l = (l₁, l₂, l₃, l₄)ᵀ, the likelihoods", names=tuple(f"l{i}" for i in
                                                                                                 range(1, N + 1)))),
               Step("total", "Σ l", number(label="Σ l, the sum of the likelihoods"))),
    ),
    Derive(
        id="12.4",
        title="The effective sample size",
        spec=number(label="N_eff"),
        vary=Vary(_neff, *(Param(n, v, 0.02, 0.85, 0.01) for n, v in zip(_W[:-1], _printed_123())), valid=_neff_ok),
        uses=(Uses("12.3", "w", "the weights w", variant=_carries_123),),
        steps=(Step("squares", "wᵢ²", matrix(label="(w₁², w₂², w₃², w₄²)ᵀ, the squared weights",
                                              names=tuple(f"s{i}" for i in range(1, N + 1)))),
               Step("sq", "Σ w²", number(label="Σ w², the sum of the squared weights"))),
    ),
    Derive(
        id="12.5",
        title="Systematic resampling by hand",
        same_answer=("Which of five particles each of five pointers picks, in order: at most 126 answers "
                     "(five indices that never go down), so some students share one."),
        spec=matrix(label="the particle each pointer picks (j₁, …, j₅)ᵀ",
                    names=tuple(f"j{i}" for i in range(1, M + 1))),
        vary=Vary(_resample, *(Param(f"q{i}", _RW[i - 1], 0.05, 0.5, 0.05) for i in range(1, M)),
                  Param("r", 0.12, 0.01, 0.19, 0.01), valid=_resample_ok),
        steps=(Step("cum", "c_j", matrix(label="the cumulative weights c₁, …, c₅", names=tuple(f"c{i}" for i in
                                                                                            range(1, M + 1)))),
               Step("copies", "n_j", matrix(label="how many pointers land in each particle's interval n₁, …, n₅",
                                            names=tuple(f"n{i}" for i in range(1, M + 1))))),
    ),
)
