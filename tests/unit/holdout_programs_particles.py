"""Hold-out programs of exercise 12.8 (particle_step), kept apart from ``holdout_programs.py`` so that
neither file grows past 400 lines; that module merges them in."""

from __future__ import annotations

_NUMPY = '''import numpy as np


def particle_step(particles, u, z, landmarks, rng_uniform):
    moved = np.asarray(particles, dtype=float) + np.asarray(u, dtype=float)
    L = np.asarray(landmarks, dtype=float)
    r = np.linalg.norm(moved[:, None, :] - L[None, :, :], axis=2)
    e = ((np.asarray(z, dtype=float)[None, :] - r) ** 2).sum(axis=1)
    w = np.exp(-e / (2 * 0.5 ** 2))
    w = w / w.sum()
    n = len(w)
    pointers = (rng_uniform + np.arange(n)) / n
    idx = np.minimum(np.searchsorted(np.cumsum(w), pointers, side="{side}"), n - 1)
    return moved[idx].tolist(), w.tolist()
'''

WRONG: dict[str, object] = {
    "weights not normalised": [("    w = [v / total for v in w]\n", "")],
    "σ in place of σ²": [("math.exp(-e / (2 * 0.5 ** 2))", "math.exp(-e / (2 * 0.5))")],
    "a tie sent to the particle before": [("while pointer >= c and j < n - 1", "while pointer > c and j < n - 1")],
    "the pointers without the draw": [("pointer = (rng_uniform + k) / n", "pointer = k / n")],
    "the draw taken as r in [0, 1/N)": [("pointer = (rng_uniform + k) / n", "pointer = rng_uniform + k / n")],
    "the weights of the particles before the move": [("for p in moved:", "for p in particles:")],
    "only the first landmark": [("for zk, m in zip(z, landmarks))", "for zk, m in zip(z[:1], landmarks[:1]))")],
    "the particles not moved": [("out.append(moved[j])", "out.append(tuple(particles[j]))")],
    "numpy searchsorted on the left (ties back)": _NUMPY.replace("{side}", "left"),
}

RIGHT: dict[str, object] = {
    "numpy searchsorted on the right": _NUMPY.replace("{side}", "right"),
    "bisect": '''import bisect
import math


def particle_step(particles, u, z, landmarks, rng_uniform):
    moved = [(p[0] + u[0], p[1] + u[1]) for p in particles]
    like = [math.exp(-sum((zk - math.hypot(p[0] - m[0], p[1] - m[1])) ** 2 for zk, m in zip(z, landmarks)) / 0.5)
            for p in moved]
    total = sum(like)
    w = [v / total for v in like]
    c, run = [], 0.0
    for v in w:
        run += v
        c.append(run)
    n = len(w)
    picked = [moved[min(bisect.bisect_right(c, (rng_uniform + k) / n), n - 1)] for k in range(n)]
    return picked, w
''',
}
