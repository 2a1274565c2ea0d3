"""Chapter 13 · Aligning point sets: one ICP iteration's pairing, each point of a scan with its
nearest point of the map (13.6).

>>> from workbook import bank
>>> bank.get("13.6").worked_text()
'[1; 3; 4]'
"""

from __future__ import annotations

from ..answer_kinds.matrix import matrix
from ..kinds.derive import Derive
from ..number_format import bmatrix, fmt
from ..reference.alignment import nearest
from ..variants import Param, Vary
from . import column
from .checks import kept_slips

_MAP = ((0, 0), (4, 0), (4, 3), (0, 3))
_SCAN = ((1, 0), (4, 2), (1, 4))


def _sets(p):
    S = [(int(p[f"s{i}x"]), int(p[f"s{i}y"])) for i in (1, 2, 3)]
    M = [(int(p[f"m{i}x"]), int(p[f"m{i}y"])) for i in (1, 2, 3, 4)]
    return S, M


def _sq(a, b):
    return (a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2


def _pairs(p):
    """13.6: for each scan point, the number of its nearest map point."""
    S, M = _sets(p)
    D = tuple(tuple(float(_sq(s, m)) for m in M) for s in S)
    key = [float(k) for k in nearest(S, M)]
    far = [float(1 + row.index(max(row))) for row in D]
    plain = [float(1 + row.index(min(row))) for row in
             ([abs(s[0] - m[0]) + abs(s[1] - m[1]) for m in M] for s in S)]
    return {
        "key": column(key),
        "slips": kept_slips(column(key), (
            (column([1.0, 2.0, 3.0]), "That pairs the points by their order in the lists. ICP does not know "
                                      "which point is which: each scan point is paired with the map point "
                                      "nearest to it.", "pairs-points-their-order"),
            (column(far), "Those are the farthest map points. Pair each scan point with the nearest one, the "
                          "smallest squared distance in its row.", "farthest-map-points-pair"),
            (column(plain), "Those are the nearest by |Δx| + |Δy|, the distance along the grid. ICP's nearest "
                            "neighbour is by straight-line distance, √(Δx² + Δy²).", "nearest-x-y-distance"),
        )),
        "values": {"D": bmatrix(D), "mins": ",\\ ".join(fmt(min(row)) for row in D)},
    }


def _pairs_ok(p):
    """Four different map points, each row's smallest squared distance the only one (no tie), no pairing
    by order, and the steps' slips told apart."""
    S, M = _sets(p)
    if len(set(M)) < 4:
        return False
    for s in S:
        d = sorted(_sq(s, m) for m in M)
        if d[0] == d[1]:
            return False
    made = _pairs(p)
    return len(made["slips"]) >= 2


EXERCISES = (
    Derive(
        id="13.6",
        title="One ICP pairing: nearest neighbours",
        spec=matrix(label="the map point paired with each scan point (j₁, j₂, j₃)ᵀ", names=("j1", "j2", "j3")),
        vary=Vary(_pairs, *(Param(f"s{i}{a}", _SCAN[i - 1][k], 0, 5, 1) for i in (1, 2, 3) for k, a in enumerate("xy")),
                  *(Param(f"m{i}{a}", _MAP[i - 1][k], 0, 5, 1) for i in (1, 2, 3, 4) for k, a in enumerate("xy")),
                  valid=_pairs_ok),
    ),
)
