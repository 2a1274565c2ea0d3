"""Chapter 13 · Aligning point sets: what point-to-plane ICP gains on a wall (Trace), and why ICP
needs a good first guess (Trace)."""

from __future__ import annotations

from ..kinds.trace import Option, Trace

EXERCISES = (
    Trace(
        id="13.7",
        title="Point-to-point or point-to-plane along a corridor",
        answer="b",
        options=(
            Option("a", "Both converge in the same number of iterations: they minimise the same error",
                   "They minimise different errors. Point-to-point adds up the full distance to the paired "
                   "point; point-to-plane only the part along the surface's normal, the distance to the wall "
                   "itself."),
            Option("b", "Point-to-plane gets there in a few iterations; point-to-point creeps, because its pairs "
                        "drag the scan along the wall",
                   "Right. The scan's points on the wall are paired with map points that are not their true "
                   "partners, a little along the wall. Point-to-point pulls each point towards its pair, "
                   "sideways too, so every step is held back by pairs that are wrong along the wall. "
                   "Point-to-plane measures only the distance across the wall (along its normal), which the "
                   "wrong pairing does not change, so the slide along the wall costs nothing and the step across "
                   "it is taken in full."),
            Option("c", "Point-to-plane pins down the robot's position along the corridor better",
                   "Neither can: a straight, featureless wall looks the same wherever the robot stands along "
                   "it. Point-to-plane leaves that direction free, and only the ends of the corridor or a "
                   "door pin it down."),
            Option("d", "Point-to-point is the better choice here, because a wall has no corners to pair",
                   "Pairs do not need corners: every scan point gets its nearest map point. What the flat "
                   "wall does is make those pairs wrong along the wall, which hurts point-to-point, not "
                   "point-to-plane."),
        ),
    ),
    Trace(
        id="13.8",
        title="ICP from a poor first guess",
        answer="c",
        options=(
            Option("a", "It still finds the true pose, only more slowly: ICP converges from any start",
                   "ICP only ever goes downhill from where it starts. Each iteration lowers the error for the "
                   "pairs it has, so it reaches a nearby minimum, which need not be the true one."),
            Option("b", "It stops at once with an error, because the nearest-neighbour pairs are wrong",
                   "Nothing tells ICP the pairs are wrong: each point always has some nearest neighbour, the "
                   "fit runs, the error falls, and it ends with a confident answer."),
            Option("c", "It can settle on the wrong pose, with the square turned by about 90°, and report a small "
                        "error",
                   "Right. From a start 60° off, most corners are nearest the wrong corner, so the first fit "
                   "turns the scan towards those. ICP then pairs again from there and only ever improves on "
                   "the pairs it has: a square looks the same turned by 90°, so the scan can settle there, a "
                   "local minimum with a small error. A good start (odometry, or a coarse global search) puts "
                   "ICP in the true minimum's basin."),
            Option("d", "It gives a reflection of the scan, the mirror image of the map",
                   "Not if each fit keeps det R = +1: the reflection fix rules mirrors out at every "
                   "iteration. A poor start gives a wrong turn, not a mirror."),
        ),
    ),
)
