"""Chapter 11 · Arm kinematics in 3-D: reading a modified-DH table (Trace), screws in the body frame
(Trace), and the steps of the space Jacobian (Design)."""

from __future__ import annotations

from ..kinds.design import Design, Step
from ..kinds.trace import Option, Trace

EXERCISES = (
    Trace(
        id="11.5",
        title="A DH table with α and a from the link before",
        answer="c",
        options=(
            Option("a", "$A_i = \\mathrm{Rot}_z(\\theta_i)\\,\\mathrm{Trans}_z(d_i)\\,\\mathrm{Trans}_x(a_{i-1})\\,"
                        "\\mathrm{Rot}_x(\\alpha_{i-1})$, the standard product with this table's numbers",
                   "That is the standard DH product, which turns about z first and twists about x last. There a and "
                   "α belong to link i itself; this table's a and α belong to link i − 1, the link before, and in "
                   "Craig's convention they come first in the product."),
            Option("b", "Either product gives the same arm: the two conventions differ only in their names",
                   "They place the link frames differently: standard DH puts frame i at the far end of link i, on "
                   "joint i + 1's axis, and the modified convention puts it on joint i's own axis. Their "
                   "matrices differ, and so does their product, unless the frames are adjusted to match."),
            Option("c", "$A_i = \\mathrm{Rot}_x(\\alpha_{i-1})\\,\\mathrm{Trans}_x(a_{i-1})\\,"
                        "\\mathrm{Rot}_z(\\theta_i)\\,\\mathrm{Trans}_z(d_i)$",
                   "Right. Craig's modified convention: a row holds the twist α and the length a of link i − 1, "
                   "the link before, then joint i's own θ and d. The transform first moves along the link before "
                   "(about and along x) and then turns and slides along joint i's axis (z)."),
            Option("d", "$A_i = \\mathrm{Rot}_z(\\theta_i)\\,\\mathrm{Rot}_x(\\alpha_{i-1})\\,"
                        "\\mathrm{Trans}_x(a_{i-1})\\,\\mathrm{Trans}_z(d_i)$",
                   "That mixes the two orders. In either convention the two z moves sit side by side and so do "
                   "the two x moves; only which pair comes first differs. Modified DH does x first."),
        ),
    ),
    Trace(
        id="11.7",
        title="Screw axes taken in the tool's frame",
        answer="b",
        options=(
            Option("a", "e^[B₁]θ₁ e^[B₂]θ₂ e^[B₃]θ₃ M, as with the space-frame axes: they are the same lines",
                   "The lines are the same, but their six numbers are not: a screw axis's ω and v depend on the "
                   "frame they are written in. The product of exponentials of the B's, with M on the right, is "
                   "not T except at special angles."),
            Option("b", "Use T = M e^[B₁]θ₁ e^[B₂]θ₂ e^[B₃]θ₃: with body-frame screws, M comes first",
                   "Right. In the body form each exponential moves the tool in its own frame, so they multiply "
                   "M on the right, in the same joint order: T = M e^[B₁]θ₁ ⋯ e^[Bₙ]θₙ. The two sets of axes "
                   "are related by B_i = Ad(M⁻¹) S_i, and the two products give the same T."),
            Option("c", "Reverse the order: e^[B₃]θ₃ e^[B₂]θ₂ e^[B₁]θ₁ M",
                   "Reversing the order does not convert one form into the other. The joints stay in the order "
                   "of the chain, base first; what changes is the side M sits on."),
            Option("d", "Use the body Jacobian in place of the exponentials",
                   "The Jacobian maps joint rates to the tool's twist; it does not give the pose. The pose of "
                   "body-frame screws is M e^[B₁]θ₁ e^[B₂]θ₂ e^[B₃]θ₃."),
        ),
    ),
    Design(
        id="11.10",
        title="The space Jacobian of an n-joint arm, in order",
        steps=(
            Step("first", "The first column is the first screw axis: $J_{s1} = S_1$"),
            Step("start", "Start the running product at $T = e^{[S_1]\\theta_1}$"),
            Step("next", "The next column is $J_{si} = \\mathrm{Ad}_T\\, S_i$, the next screw carried by $T$"),
            Step("grow", "Multiply the product on the right by that joint's exponential, $T \\leftarrow T\\, "
                         "e^{[S_i]\\theta_i}$"),
            Step("repeat", "Repeat the last two steps until the last joint's column"),
        ),
        shown=("next", "grow", "first", "repeat", "start"),
    ),
)
