"""Chapter 10 · 3-D poses: what blending across the double cover does (Trace), and the order of a
camera-to-world pipeline that starts from a scalar-last message (Design)."""

from __future__ import annotations

from ..kinds.design import Design, Step
from ..kinds.trace import Option, Trace

EXERCISES = (
    Trace(
        id="10.6",
        title="Blending across the double cover",
        answer="c",
        options=(
            Option("a", "It turns smoothly through the $10°$ between them",
                   "Only if $q_1$ is first replaced by $-q_1$. As logged, $q_0 \\cdot q_1 \\approx -1$: the two "
                   "quaternions sit on opposite sides of the sphere, and the straight line between them is the "
                   "long way round."),
            Option("b", "Nothing happens: the blend raises an error because it is not a unit quaternion",
                   "Dividing by the norm hides that. The average of $q_0$ and $q_1$ is short, nearly zero in "
                   "the middle, but not zero, and after the division it is a unit quaternion again. No error "
                   "is raised; the robot simply moves."),
            Option("c", "It swings the long way, through about $350°$, fastest in the middle",
                   "Right. $q_1$ as logged is the $10°$ turn written past $360°$, so the line from $q_0$ to "
                   "$q_1$ crosses the sphere the long way: $360° - 10° = 350°$ of turn. Near $t = \\tfrac12$ the "
                   "unnormalised average almost vanishes, so the normalised one whips round there. Check "
                   "$q_0 \\cdot q_1$ and flip $q_1$ when it is negative."),
            Option("d", "It holds $q_0$ until $t = \\tfrac12$, then jumps to $q_1$",
                   "The blend changes with every step of $t$; there is no jump, only a very fast swing through "
                   "the middle, the long way round."),
        ),
    ),
    Design(
        id="10.7",
        title="A detection into the world, from a ROS pose",
        steps=(
            Step("msg", "Read the base's pose message: its position and its orientation as $(x, y, z, w)$"),
            Step("order", "Reorder the orientation to $(w, x, y, z)$, the order the code uses"),
            Step("matrix", "Build ${}^{\\text{world}}T_{\\text{base}}$ from $R(q)$ and the position"),
            Step("chain", "Compose ${}^{\\text{world}}T_{\\text{cam}} = {}^{\\text{world}}T_{\\text{base}}\\,"
                          "{}^{\\text{base}}T_{\\text{cam}}$ with the calibrated camera mount"),
            Step("apply", "Apply ${}^{\\text{world}}T_{\\text{cam}}$ to the detection ${}^{\\text{cam}}p$"),
        ),
        shown=("chain", "apply", "order", "msg", "matrix"),
    ),
)
