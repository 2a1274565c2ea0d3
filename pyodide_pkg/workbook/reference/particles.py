"""Bayes filters: the discrete filter on a 1-D grid (predict by convolution, update by a likelihood,
normalise) and the particle filter (Gaussian range weights, the effective sample size, systematic
resampling; Thrun, Burgard & Fox, Probabilistic Robotics, ch. 2 and 4).

The grid is a ring of cells (a circular corridor): a move past the last cell comes back at the first.

>>> predict([0.0, 1.0, 0.0, 0.0], {0: 0.2, 1: 0.8})
[0.0, 0.2, 0.8, 0.0]
>>> update([0.25, 0.25, 0.25, 0.25], [0.75, 0.25, 0.25, 0.75])
[0.375, 0.125, 0.125, 0.375]
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

from .domain import Undefined

Point = Sequence[float]


def normalise(values: Sequence[float]) -> list[float]:
    """The values divided by their sum, so that they add up to 1.

    >>> normalise([1, 3])
    [0.25, 0.75]
    """
    total = float(sum(values))
    if not total > 0:
        raise Undefined("the values add up to 0: there is nothing to normalise")
    return [v / total for v in values]


def predict(belief: Sequence[float], kernel: Mapping[int, float]) -> list[float]:
    """The belief after a move: bel′(i) = Σ_k kernel[k] · bel(i − k), cells counted round the ring.

    ``kernel[k]`` is the chance that the robot moved ``k`` cells.

    >>> predict([0.5, 0.5, 0.0], {1: 1.0})
    [0.0, 0.5, 0.5]
    """
    n = len(belief)
    return [sum(p * belief[(i - k) % n] for k, p in kernel.items()) for i in range(n)]


def update(belief: Sequence[float], likelihood: Sequence[float]) -> list[float]:
    """The belief after a measurement: bel(i) · p(z | i), normalised.

    >>> update([0.5, 0.5], [0.9, 0.1])
    [0.9, 0.1]
    """
    return normalise([b * p for b, p in zip(belief, likelihood)])


def gaussian(x: float, mean: float, sigma: float) -> float:
    """The normal density N(x; mean, σ²).

    >>> round(gaussian(0.0, 0.0, 1.0), 6)
    0.398942
    """
    return math.exp(-0.5 * ((x - mean) / sigma) ** 2) / (sigma * math.sqrt(2 * math.pi))


def range_likelihood(point: Point, z: Sequence[float], landmarks: Sequence[Point], sigma: float) -> float:
    """p(z | x): the product over the landmarks of exp(−(z_k − r_k)² / (2σ²)), r_k the range from
    ``point`` to landmark k (the Gaussian's constant factor left out: it cancels when normalised).

    >>> range_likelihood((0.0, 0.0), [5.0], [(3.0, 4.0)], 0.5)
    1.0
    """
    e = sum((zk - math.dist(point, m)) ** 2 for zk, m in zip(z, landmarks))
    return math.exp(-e / (2 * sigma * sigma))


def range_weights(points: Sequence[Point], z: Sequence[float], landmarks: Sequence[Point],
                  sigma: float) -> list[float]:
    """The particles' normalised weights from their range likelihoods.

    >>> [round(w, 6) for w in range_weights([(0.0, 0.0), (1.0, 0.0)], [1.0], [(2.0, 0.0)], 1.0)]
    [0.377541, 0.622459]
    """
    return normalise([range_likelihood(p, z, landmarks, sigma) for p in points])


def n_eff(weights: Sequence[float]) -> float:
    """The effective sample size 1 / Σ w² of normalised weights: N when all are equal, 1 when one holds all.

    >>> n_eff([0.25] * 4), n_eff([1.0, 0.0, 0.0])
    (4.0, 1.0)
    """
    s = sum(w * w for w in weights)
    if not s > 0:
        raise Undefined("the weights are all 0")
    return 1.0 / s


def cumulative(weights: Sequence[float]) -> list[float]:
    """c_j = w_0 + … + w_j.

    >>> cumulative([0.25, 0.5, 0.25])
    [0.25, 0.75, 1.0]
    """
    out, c = [], 0.0
    for w in weights:
        c += w
        out.append(c)
    return out


def pointers(u: float, n: int) -> list[float]:
    """The systematic resampler's n pointers (u + k) / n, k = 0 … n − 1, for one draw u in [0, 1).

    >>> pointers(0.5, 4)
    [0.125, 0.375, 0.625, 0.875]
    """
    return [(u + k) / n for k in range(n)]


def systematic_resample(weights: Sequence[float], u: float) -> list[int]:
    """Low-variance resampling: for each pointer (u + k) / n, the first index j whose cumulative
    weight c_j is greater than the pointer (strictly: a pointer on a boundary goes to the next
    particle); if rounding leaves none, the last. ``weights`` must add up to 1 and u lie in [0, 1).

    >>> systematic_resample([0.1, 0.6, 0.3], 0.5)
    [1, 1, 2]
    >>> systematic_resample([0.25] * 4, 0.0)
    [0, 1, 2, 3]
    """
    if not 0 <= u < 1:
        raise Undefined(f"the draw u = {u} is not in [0, 1)")
    c = cumulative(weights)
    n, j, out = len(weights), 0, []
    for p in pointers(u, n):
        while j < n - 1 and not p < c[j]:
            j += 1
        out.append(j)
    return out


def particle_step(particles: Sequence[Point], u: Point, z: Sequence[float], landmarks: Sequence[Point],
                  rng_uniform: float, sigma: float = 0.5) -> tuple[list[tuple[float, float]], list[float]]:
    """One step of a particle filter: move every particle (x, y) by u = (dx, dy) (no motion noise),
    weight it by the range likelihood of z (σ = ``sigma``), normalise, and resample systematically
    with the one draw ``rng_uniform``. Returns (the resampled particles, the normalised weights).

    >>> new, w = particle_step([(0.0, 0.0), (2.0, 0.0)], (1.0, 0.0), [1.0], [(2.0, 0.0)], 0.5)
    >>> new, [round(v, 4) for v in w]
    ([(1.0, 0.0), (3.0, 0.0)], [0.5, 0.5])
    """
    moved = [(float(x) + u[0], float(y) + u[1]) for x, y in particles]
    w = range_weights(moved, z, landmarks, sigma)
    return [moved[j] for j in systematic_resample(w, rng_uniform)], w
