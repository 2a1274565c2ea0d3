"""Chapter 2's bug hunt: a quaternion integrated from a gyroscope and never renormalised."""

from __future__ import annotations

from ..figures.symptoms import gyro_facts
from ..kinds.debug import Debug
from ..number_format import fmt
from ..reference.rotation3d import quat_integrate

_GYRO = """\
import math
def integrate_gyro(q, wx, wy, wz, dt, steps):
    w, x, y, z = q
    for _ in range(steps):
        dw = -0.5 * (x * wx + y * wy + z * wz)
        dx = 0.5 * (w * wx + y * wz - z * wy)
        dy = 0.5 * (w * wy - x * wz + z * wx)
        dz = 0.5 * (w * wz + x * wy - y * wx)
        q = (w + dw * dt, x + dx * dt, y + dy * dt, z + dz * dt)
        n = math.sqrt(sum(c * c for c in q))
        w, x, y, z = q
    return (w, x, y, z)
"""


def _integrate(q, wx, wy, wz, dt, steps):
    return quat_integrate(q, (wx, wy, wz), dt, steps)


def _bug() -> str:
    f = gyro_facts()
    return (f"The norm n is computed and never used, so q is never renormalised. Each Euler step lengthens q a "
            f"little (by √(1 + (‖ω‖·dt/2)²)), and nothing brings it back: spinning at {fmt(f['rate'])} rad/s with "
            f"dt = {fmt(f['dt'])} s, ‖q‖ passes 1.01 after {f['first_over']} steps and is {fmt(f['final'])} after "
            f"{f['steps']}. A quaternion that is not a unit one is not a rotation: turning a vector with it "
            f"stretches it by ‖q‖², here {fmt(f['stretch'])} times, so the robot's attitude, and every sensor "
            f"reading rotated with it, drifts in size as well as in angle. Fix: w, x, y, z = (c / n for c in q).")


EXERCISES = (
    Debug(
        id="2.9",
        title="Find the bug in the gyro integration",
        code=_GYRO,
        bug_line=11,
        fixed_line="        w, x, y, z = (c / n for c in q)",
        bug=_bug(),
        notes={
            1: "imports math for sqrt",
            2: "takes the attitude q = (w, x, y, z), the body rates in rad/s, the step and how many steps",
            3: "unpacks the starting attitude",
            4: "one Euler step per gyroscope sample",
            5: "correct: the scalar part of q̇ = ½ q ⊗ (0, ω)",
            6: "correct: the x part of ½ q ⊗ (0, ω)",
            7: "correct: the y part of ½ q ⊗ (0, ω)",
            8: "correct: the z part of ½ q ⊗ (0, ω)",
            9: "correct: the Euler step q + q̇·dt",
            10: "correct: the norm of the new q",
            12: "returns the final attitude",
        },
        function="integrate_gyro",
        reference=_integrate,
        cases=(((1.0, 0.0, 0.0, 0.0), 0.0, 0.0, 5.0, 0.01, 100),
               ((0.7071, 0.7071, 0.0, 0.0), 0.3, -0.2, 1.0, 0.02, 50),
               ((0.5, 0.5, 0.5, 0.5), 1.0, 2.0, -1.5, 0.01, 30)),
        symptom="quaternion-norm",
    ),
)
