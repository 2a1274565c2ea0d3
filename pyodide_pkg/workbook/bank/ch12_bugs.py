"""Chapter 12's bug hunt: a systematic resampler that builds its cumulative weights from likelihoods
that were never normalised, so its pointers, spread over [0, 1), cover only part of the cloud."""

from __future__ import annotations

from ..kinds.debug import Debug
from ..number_format import fmt
from ..reference.particles import normalise, systematic_resample

_RESAMPLER = """\
def resample(particles, weights, u):
    # weights: one likelihood per particle, not yet normalised; u: one draw in [0, 1)
    n = len(particles)
    total = sum(weights)
    c = [0.0] * n
    running = 0.0
    for j in range(n):
        running += weights[j]
        c[j] = running
    out, j = [], 0
    for k in range(n):
        pointer = (u + k) / n
        while j < n - 1 and pointer >= c[j]:
            j += 1
        out.append(particles[j])
    return out
"""


def _resample(particles, weights, u):
    """The particles the systematic resampler keeps, from the normalised weights."""
    return [particles[j] for j in systematic_resample(normalise(weights), u)]


_CASES = (
    ((1.0, 2.0, 3.0, 4.0, 5.0), (0.9, 0.8, 0.6, 0.5, 0.2), 0.5),  # likelihoods adding up to 3
    ((0.0, 0.5, 1.0, 1.5), (0.1, 0.05, 0.05, 0.2), 0.2),  # adding up to 0.4
    ((2.0, 4.0, 6.0), (1.0, 1.0, 1.0), 0.1),
)


def resample_facts() -> dict:
    """The first case: what the bug keeps and what it should."""
    particles, weights, u = _CASES[0]
    program: dict = {}
    exec(_RESAMPLER, program)  # the bug's own code says what it keeps: nothing here copies it
    return {"total": sum(weights), "particles": particles, "u": u, "wrong": program["resample"](particles, weights, u),
            "right": _resample(particles, weights, u)}


def _listed(xs) -> str:
    return ", ".join(fmt(x) for x in xs)


def _bug() -> str:
    f = resample_facts()
    return ("Line 8 adds the raw likelihoods, so the last cumulative weight is their sum, not 1, while the "
            f"pointers (u + k)/n on line 12 stay in [0, 1). With the {len(f['right'])} particles at "
            f"{_listed(f['particles'])} m, likelihoods adding up to {fmt(f['total'])} and u = {fmt(f['u'])}, the "
            f"pointers reach only the first {len(set(f['wrong']))} particles: it keeps those at "
            f"{_listed(f['wrong'])} m where the normalised weights keep {_listed(f['right'])} m. Likelihoods adding "
            "up to less than 1 do the opposite and pile every late pointer on the last particle. Line 4 "
            "computes the sum and nothing uses it. Fix: running += weights[j] / total.")


EXERCISES = (
    Debug(
        id="12.9",
        title="Find the bug in the resampler",
        code=_RESAMPLER,
        bug_line=8,
        fixed_line="        running += weights[j] / total",
        bug=_bug(),
        notes={
            1: "takes the particles, their likelihoods and the one draw",
            2: "correct: a comment that says the weights are not normalised yet",
            3: "correct: the number of particles",
            4: "correct: the sum that normalises the weights",
            5: "correct: room for the cumulative weights",
            6: "correct: the running sum starts at 0",
            7: "correct: each particle in turn",
            9: "correct: c_j = w_0 + … + w_j",
            10: "correct: the kept particles, and the first particle to test",
            11: "correct: one pointer per particle",
            12: "correct: the pointers (u + k)/n, evenly spaced by 1/n from u/n",
            13: "correct: while the pointer is at or past c_j, particle j is not the one",
            14: "correct: on to the next particle, until its cumulative weight is greater than the pointer",
            15: "correct: keeps that particle",
            16: "correct: the resampled set",
        },
        function="resample",
        reference=_resample,
        cases=_CASES,
    ),
)
