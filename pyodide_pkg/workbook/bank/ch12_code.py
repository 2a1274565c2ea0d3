"""Chapter 12 · Code the robot: particle_step(particles, u, z, landmarks, rng_uniform), one step of a
particle filter (move, weight by the range likelihood, normalise, resample systematically with the one
draw it is given), so that its result is deterministic and can be checked."""

from __future__ import annotations

import math
import random

from ..kinds.build import Build
from ..reference.particles import particle_step

SIGMA = 0.5  # the range sensor's standard deviation, m (the statement's)

_SOLUTION = '''import math


def particle_step(particles, u, z, landmarks, rng_uniform):
    """Move, weight by the ranges (sigma 0.5 m), resample systematically with one draw."""
    moved = [(x + u[0], y + u[1]) for x, y in particles]
    w = []
    for p in moved:
        e = sum((zk - math.dist(p, m)) ** 2 for zk, m in zip(z, landmarks))
        w.append(math.exp(-e / (2 * 0.5 ** 2)))
    total = sum(w)
    w = [v / total for v in w]
    n, out, j, c = len(moved), [], 0, w[0]
    for k in range(n):
        pointer = (rng_uniform + k) / n
        while pointer >= c and j < n - 1:  # the first particle whose cumulative weight passes the pointer
            j += 1
            c += w[j]
        out.append(moved[j])
    return out, w
'''

_STARTER = (
    "import math\n\n\n"
    "def particle_step(particles, u, z, landmarks, rng_uniform):\n"
    "    # Your code here: move, weight, normalise, resample. This moves and keeps every particle.\n"
    "    moved = [(x + u[0], y + u[1]) for x, y in particles]\n"
    "    n = len(moved)\n"
    "    return moved, [1 / n] * n\n"
)

_SQUARE = ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))  # all 1 m from the origin
_LANDMARKS = ((0.0, 0.0), (4.0, 0.0))

_CASES = {
    "equal weights (every particle 1 m from the one landmark)": (_SQUARE, (0.0, 0.0), (1.0,), ((0.0, 0.0),), 0.5),
    "equal weights: every pointer on a boundary (a tie goes to the next particle)":
        (_SQUARE, (0.0, 0.0), (1.0,), ((0.0, 0.0),), 0.0),
    "one dominant particle": (((1.0, 1.0), (3.0, 2.5), (-1.0, 2.0), (2.0, -1.5), (0.5, 3.0)), (0.5, 0.0),
                              (math.dist((1.5, 1.0), _LANDMARKS[0]), math.dist((1.5, 1.0), _LANDMARKS[1])),
                              _LANDMARKS, 0.3),
    "a draw near the top edge, 0.999999": (((0.0, 0.0), (0.5, 0.5), (1.0, 0.0), (1.5, 0.5)), (1.0, 0.5),
                                           (2.2, 2.0), _LANDMARKS, 0.999999),
    "a particle whose weight is exactly 0 (it is never picked)": (((1.0, 0.0), (60.0, 0.0), (1.2, 0.1)),
                                                                   (0.0, 0.0), (1.0,), ((0.0, 0.0),), 0.0),
    "one particle": (((2.0, 1.0),), (0.5, -0.5), (1.0, 2.0), _LANDMARKS, 0.7),
    "three landmarks, the robot moved": (((0.0, 1.0), (0.3, 1.2), (-0.2, 0.8), (0.1, 0.9), (0.4, 1.1), (0.0, 1.4)),
                                         (1.0, 1.0), (2.0, 2.7, 2.4), ((1.0, 0.0), (4.0, 2.0), (0.0, 4.0)), 0.25),
}
_NAMED = {tuple(map(tuple, args[0])) + (args[4],): name for name, args in _CASES.items()}


def _describe(particles, u, z, landmarks, rng_uniform) -> str:
    name = _NAMED.get(tuple(map(tuple, particles)) + (rng_uniform,))
    marks = f"{len(landmarks)} landmark" + ("s" if len(landmarks) != 1 else "")
    some = f"{len(particles)} particle" + ("s" if len(particles) != 1 else "")
    head = f"particle_step: {some}, {marks}, draw {rng_uniform:g}"
    return head + (f": {name}" if name else "")


def _random(rng: random.Random) -> tuple:
    """3 to 10 particles within 1.5 m of where the robot starts, a move of up to 1 m, 1 to 3 landmarks in a
    10 m square, the ranges from the robot's true new position with 0.1 m of noise, and one draw."""
    start = (rng.uniform(-3, 3), rng.uniform(-3, 3))
    u = (rng.uniform(-1, 1), rng.uniform(-1, 1))
    particles = tuple((start[0] + rng.uniform(-1.5, 1.5), start[1] + rng.uniform(-1.5, 1.5))
                      for _ in range(rng.randint(3, 10)))
    landmarks = tuple((rng.uniform(-5, 5), rng.uniform(-5, 5)) for _ in range(rng.randint(1, 3)))
    truth = (start[0] + u[0], start[1] + u[1])
    z = tuple(math.dist(truth, m) + rng.gauss(0, 0.1) for m in landmarks)
    return particles, u, z, landmarks, rng.random()


def _ties_back(weights, rng_uniform) -> list[int]:
    """The resampler with a pointer on a boundary sent to the particle before it (c_j ≥ pointer)."""
    n, out, j, c = len(weights), [], 0, weights[0]
    for k in range(n):
        pointer = (rng_uniform + k) / n
        while pointer > c and j < n - 1:
            j += 1
            c += weights[j]
        out.append(j)
    return out


def _diagnose(args, got, want) -> str:
    """Weights that do not add up to 1, or the particles a tie sent back would give, in words."""
    try:
        weights = [float(v) for v in got[1]]
        picked = [tuple(float(v) for v in p) for p in got[0]]
    except (TypeError, ValueError, IndexError, KeyError):
        return ""
    if len(weights) == len(want[1]) and abs(sum(weights) - 1) > 1e-6:
        return f"your weights add up to {sum(weights):.4g}, not 1: divide each by their sum."
    moved = [(float(x) + args[1][0], float(y) + args[1][1]) for x, y in args[0]]
    back = [moved[j] for j in _ties_back([float(v) for v in want[1]], float(args[4]))]
    right = [tuple(p) for p in want[0]]
    if back != right and len(picked) == len(back) and all(math.dist(a, b) < 1e-9 for a, b in zip(picked, back)):
        return ("a pointer that lands exactly on a cumulative weight went to the particle before it: it belongs "
                "to the next one (the first whose cumulative weight is greater than the pointer).")
    return ""


EXERCISES = (
    Build(
        id="12.8",
        title="Code the robot: particle_step",
        function="particle_step",
        params=("particles", "u", "z", "landmarks", "rng_uniform"),
        starter=_STARTER,
        solution=_SOLUTION,
        reference=particle_step,
        run_figure="particles",
        examples=(
            (((0.0, 0.0), (2.0, 0.0)), (1.0, 0.0), (1.0,), ((2.0, 0.0),), 0.5),
            (((0.0, 0.0), (1.0, 0.5), (2.0, 0.0), (3.0, 0.5)), (0.5, 0.0), (2.0, 2.2), _LANDMARKS, 0.25),
        ),
        edge_cases=tuple(_CASES.values()),
        random_args=_random,
        describe=_describe,
        diagnose=_diagnose,
    ),
)
