"""What exercise 5.10's test rows say about a step that disagrees with the reference.

Each sentence states a fact about the learner's poses that the grader checks on the numbers
themselves: pose 0 came back moved; an angle lies outside (−π, π]; the poses came back as given;
every pose moved exactly against the reference's step; or the poses are exactly those of the
step with one named slip (an edge's angle error left unwrapped, every Ω taken as the identity),
recomputed here from the reference's own parts. A sentence is said only when it is true of
the numbers, so a correct step never gets one, and a slip the list does not know gets none.

Two edges in a row, the second turning pose 2 past π, and the step of a program that forgot to wrap
the result's angles; then one that moved the anchor and took no step:

>>> from workbook.reference.pose_graph_step import gauss_newton_se2
>>> W = [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
>>> args = ([[1, 0, 0], [2, 0, 0], [3, 0, 3.0]], [[0, 1, [1, 0, 0], W], [1, 2, [1, 0, 3.2], W]])
>>> want = gauss_newton_se2(*args)
>>> diagnose(args, [[1.0, 0.0, 0.0], [2.0, 0.0, 0.0], [3.0, 0.0, 3.2]], want)
'The angle of pose 2, 3.2, lies outside (−π, π]; wrapped, it agrees with the reference.'
>>> print(diagnose(args, [[1.5, 0.0, 0.0], [2.0, 0.0, 0.0], [3.0, 0.0, 3.0]], want))
Pose 0 moved: it is the anchor, so it comes back exactly as given.
Poses 1 and 2 came back just as given: no step was applied.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

from ..build_judge import first_difference
from ..number_format import compact
from ..reference.pose_graph import edge_error_relative
from ..reference.pose_graph_step import anchored_step, linear_system, moved

ANGLES = ("[*][2]",)
TOL = 1e-6  # how near the learner's numbers must be to a slip's to be called that slip's (relative and absolute)

ANCHOR = "Pose 0 moved: it is the anchor, so it comes back exactly as given."
UNMOVED = "{poses} came back just as given: no step was applied."
OPPOSITE = ("Every pose moved by exactly minus the reference's step: a sign is flipped somewhere "
            "(the error is e = z − h, the step solves H Δx = −b).")
UNWRAPPED = ("These are the poses of a step whose edge angle errors were not wrapped: "
             "e_θ = z_θ − (θ_j − θ_i) must be brought into (−π, π] ({edge}).")
UNWEIGHTED = "These are the poses of a step with every Ω taken as the identity: weight each edge by its own Ω."


def _same(a: Any, b: Any) -> bool:
    return first_difference(a, b, TOL, TOL, angles=ANGLES) is None


def unwrapped_error(xi, xj, z) -> list[float]:
    """The edge error with its angle left as the plain difference z_θ − (θj − θi)."""
    e = edge_error_relative(xi, xj, z)
    return [e[0], e[1], z[2] - (xj[2] - xi[2])]


def step_with(poses, edges, error: Callable = edge_error_relative) -> list[list[float]]:
    return moved(poses, anchored_step(*linear_system(poses, edges, error)))


def _unwrapped_edge(poses, edges) -> str:
    """The first edge whose plain angle error is outside (−π, π], named with that error."""
    for i, j, z, _ in edges:
        raw = z[2] - (poses[j][2] - poses[i][2])
        if abs(raw) > math.pi:
            return f"edge {i}→{j}: z_θ − (θ_j − θ_i) = {compact(raw)} rad"
    return ""


def _wrapped(poses: Any) -> list[list[float]]:
    """The poses with every angle brought into [−π, π] (the sentences on angles are said apart)."""
    return [[p[0], p[1], math.remainder(p[2], 2 * math.pi) if math.isfinite(p[2]) else p[2]] for p in poses]


def _others(n: int) -> str:
    """Poses 1 to n − 1 named: "Pose 1", "Poses 1 and 2", "Poses 1, 2 and 3"."""
    names = [str(k) for k in range(1, n)]
    return f"Pose {names[0]}" if len(names) == 1 else f"Poses {', '.join(names[:-1])} and {names[-1]}"


def diagnose(args: tuple, got: Any, want: Any) -> str:
    """The sentences that are true of ``got`` (the learner's poses, shaped as ``want``), "" when none is."""
    poses, edges = args
    poses = [[float(v) for v in p] for p in poses]
    said = []
    for k, p in enumerate(got):
        if math.isfinite(p[2]) and abs(p[2]) > math.pi + 1e-9:
            agrees = _same(math.remainder(p[2], 2 * math.pi), want[k][2])
            said.append(f"The angle of pose {k}, {compact(p[2])}, lies outside (−π, π]"
                        + ("; wrapped, it agrees with the reference." if agrees else "."))
    got = _wrapped(got)
    if not _same(got[0], poses[0]):
        said.insert(0, ANCHOR)
    rest, free = got[1:], poses[1:]
    slips = []
    if not _same(want[1:], free):  # the reference steps: taking none, or its opposite, can show
        if _same(rest, free):
            said.append(UNMOVED.format(poses=_others(len(poses))))
            return " ".join(said)
        slips.append((OPPOSITE, [[2 * p[0] - w[0], 2 * p[1] - w[1], 2 * p[2] - w[2]] for p, w in zip(free, want[1:])]))
    edge = _unwrapped_edge(poses, edges)
    if edge:
        slips.append((UNWRAPPED.format(edge=edge), step_with(poses, edges, unwrapped_error)[1:]))
    unit = [(i, j, z, [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]) for i, j, z, _ in edges]
    slips.append((UNWEIGHTED, step_with(poses, unit)[1:]))
    said += [sentence for sentence, theirs in slips if not _same(theirs, want[1:]) and _same(rest, _wrapped(theirs))]
    return " ".join(said)
