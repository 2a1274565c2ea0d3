"""Chapter 7 · The Jacobian and velocity."""

import math

from .. import chains
from ..answer_kinds.base import Slip
from ..answer_kinds.expression import formula
from ..answer_kinds.matrix import matrix
from ..answer_kinds.number import number
from ..chains import Uses
from ..kinds.debug import Debug
from ..kinds.derive import Derive
from ..number_format import approx, bmatrix, fmt, paren, prose, relation, shown, signed
from ..reference.arm import (
    end_effector_velocity,
    forward_kinematics_2link,
    jacobian_2link,
    jacobian_det,
    most_manipulable_theta2,
    velocity_ratio,
)
from ..reference.linalg import add
from ..steps import Step
from ..tolerance import agrees, clean
from ..variants import Choice, Param, Vary
from . import column, grid
from .ch6_arm_kinematics import LINK2_DIRECTION, link2_direction_slips  # as chapter 6 asks them
from .ch7_bugs import JACOBIAN_SIGN_BUG
from .checks import apart, kept_slips
from .jacobian_formulas import FORMULAS, entry_of


def _angle(deg: float, tex: bool = False) -> str:
    """An angle as the chapter writes it: ``0`` bare, any other with its degree sign; in a
    message, with a true minus; in TeX as the argument of sin or cos (``tex=True``), a
    negative one in parentheses: ``(-30°)``.

    >>> _angle(0), _angle(-35), _angle(-30, tex=True)
    ('0', '−35°', '(-30°)')
    """
    s = "0" if deg == 0 else f"{(fmt if tex else prose)(deg)}°"
    return f"({s})" if tex and deg < 0 else s


def _jacobian_entry(p, given=None):
    """7.1: J(1,1) for equal links L at θ1, with the elbow at θ2 = 90° − θ1 (link 2 points straight up).
    Steps: θ1 + θ2, then link 2's term −L2 sin(θ1 + θ2), each from the learner's own previous one
    (``given``); link 1's term −L1 sin θ1 is added last."""
    L, t1 = p["L"], p["t1"]
    t2 = 90 - t1
    J = jacobian_2link(L, L, math.radians(t1), math.radians(t2))
    s1, c1 = math.sin(math.radians(t1)), math.cos(math.radians(t1))
    det = jacobian_det(L, L, math.radians(t1), math.radians(t2))
    t12 = chains.given(given, "t12", t1 + t2)
    link2 = chains.given(given, "link2", jacobian_2link(0, L, 0, math.radians(t12))[0][1])  # −L2 sin(θ1 + θ2)
    link1 = jacobian_2link(L, 0, math.radians(t1), 0)[0][0]  # −L1 sin θ1
    slips = [Slip(-J[0][0], "Check the sign, and the entry: J(1,1) = ∂x/∂θ1 = −L1 sin θ1 − L2 sin(θ1+θ2), "
                  f"negative here (the derivative of cos is −sin). +{fmt(J[1][0])} is J(2,1), the derivative of y.",
                      name="check-sign-entry-j")]
    if t1 != 0:  # −J(1,1) and J(2,1) part ways: each slip gets its own message
        slips = [
            Slip(-J[0][0], "Check the sign: J(1,1) = ∂x/∂θ1 = −L1 sin θ1 − L2 sin(θ1+θ2), negative here "
                 "(the derivative of cos is −sin).", name="check-sign-j-1"),
            Slip(J[1][0], "That is J(2,1) = ∂y/∂θ1, the derivative of y. J(1,1) differentiates x.", name="j-2-1-y"),
            Slip(J[0][1], "That is J(1,2) = ∂x/∂θ2: only link 2 depends on θ2. J(1,1) differentiates by θ1, "
                 "which moves both links.", name="j-1-2-theta2"),
        ]
    link2_slips = kept_slips(J[0][1], (
        (-J[0][1], "Check the sign: the derivative of L2 cos(θ1 + θ2) is −L2 sin(θ1 + θ2).",
            "check-sign-derivative-l2"),
        (J[1][1], "That is L2 cos(θ1 + θ2), link 2's own x. Its derivative by θ1 is −L2 sin(θ1 + θ2).",
            "l2-cos-theta1-theta2"),
        (jacobian_2link(0, L, 0, math.radians(t2))[0][1],
         f"That is −L2 sin θ2, link 2 at θ2 = {_angle(t2)}. It points at θ1 + θ2 = 90°.", "l2-sin-theta2-link"),
    ))
    return {
        "key": link1 + link2,
        "slips": tuple(slips),
        "steps": {
            "t12": {"key": t12, "slips": link2_direction_slips(t1, t2)},
            "link2": {"key": link2, "slips": link2_slips},
        },
        "values": {
            "deg1": "" if t1 == 0 else "°", "t2": fmt(t2), "a1": _angle(t1, tex=True), "s1": fmt(s1),
            "m1": fmt(-L * s1), "l1c": fmt(L * c1),
            "j11": fmt(J[0][0]), "j12": fmt(J[0][1]), "j21": fmt(J[1][0]),
            "r11": relation(J[0][0], shown(-L * s1) - L), "r21": relation(J[1][0], shown(L * c1)),
            "det": fmt(det), "rdet": relation(det, -shown(J[0][1]) * shown(J[1][0])),
            "next71": ("Exercise 7.2 puts this Jacobian to work." if (L, t1) == (1, 0)
                       else "Exercise 7.2 puts the Jacobian of this exercise's first numbers to work."),
        },
    }


def _root2(k: float) -> str:
    """k·√2 in TeX: ``\\sqrt2``, ``1.5\\sqrt2``."""
    return "\\sqrt2" if math.isclose(k, 1) else f"{fmt(k)}\\sqrt2"


def _tip_velocity(p, given=None):
    """7.2: (ẋ, ẏ) = J (θ̇1, 0) at θ = (0, 90°) with equal links L, J printed in the statement; asked: ẋ.

    >>> made = _tip_velocity({"L": 1.5, "w1": -2}); print(made["values"]["J"], made["key"])
    \\begin{bmatrix} -1.5 & -1.5 \\\\ 1.5 & 0 \\end{bmatrix} 3.0
    """
    L, w = p["L"], p["w1"]
    J = jacobian_2link(L, L, 0, math.pi / 2)
    J[0][0] = chains.given(given, "j11", J[0][0])  # the learner's own J(1,1) from exercise 7.1
    v = end_effector_velocity(J, [w, 0])
    return {
        "key": v[0],
        "slips": (
            Slip(v[1], "That is ẏ, from the second row of J. ẋ comes from the first row.", name="second-row-j-comes"),
            Slip(end_effector_velocity(J, [w, w])[0], "θ̇2 is 0, so the second column of J contributes nothing.",
                name="theta-2-0-so"),
        ),
        "values": {"J": bmatrix(J), "pw": paren(w), "xd": fmt(v[0]), "yd": fmt(v[1]),
                   "j11": fmt(J[0][0]), "pj12": paren(J[0][1]), "j21": fmt(J[1][0]), "j22": fmt(J[1][1]),
                   "radius": _root2(L), "speed": f"{_root2(abs(w) * L)} {approx(math.hypot(*v))}"},
    }


def _straight_arm_det(p):
    """7.3: det J of the straight arm (θ2 = 0) with equal links L: always 0, the point of the exercise."""
    L = p["L"]
    return {
        "key": jacobian_det(L, L, 0, 0),
        "slips": (
            Slip(jacobian_det(L, L, 0, math.pi / 2),
                 "That is det J at θ2 = 90°. det J = L1 L2 sin θ2, and sin 0 = 0.", name="det-j-theta2-90"),
            Slip(float(L + L), "det J = L1 L2 sin θ2, a product with sin θ2, not a sum of lengths.",
                name="det-j-l1-l2"),
        ),
    }


def _best_elbow(p):
    """7.4: the θ2 in [0°, 180°] where w = |det J| peaks, for equal links L (always 90°)."""
    L = p["L"]
    J = jacobian_2link(L, L, 0, math.pi / 2)
    wmax = jacobian_det(L, L, 0, math.pi / 2)
    return {
        "key": math.degrees(most_manipulable_theta2(L, L, samples=181)),
        "slips": (
            Slip(0.0, "At θ2 = 0 the arm is straight and w = 0: that is the worst angle, a singularity.",
                name="theta2-0-arm-straight"),
            Slip(180.0, "At θ2 = 180° the arm is folded back and w = 0: another singularity.",
                name="theta2-180-arm-folded"),
            Slip(wmax, "That is the largest value of w. The question asks for the angle where it happens.",
                name="largest-value-w-question"),
        ),
        "values": {"w2": "" if L == 1 else fmt(L * L), "wmax": fmt(wmax),
                   "j11": fmt(J[0][0]), "j12": fmt(J[0][1]), "j21": fmt(J[1][0]), "j22": fmt(J[1][1]),
                   "ratio": fmt(velocity_ratio(J))},
    }


def _link2_direction(deg: float) -> str:
    """Where link 2 points, in words (the text says it outside math): an angle counter-clockwise
    from the x-axis, from 0° to 360°, so that no minus sign stands in prose.

    >>> _link2_direction(-150), _link2_direction(450), _link2_direction(55)
    ('at 210° from the x-axis, counter-clockwise', 'straight up', 'at 55° from the x-axis, counter-clockwise')
    """
    d = deg % 360
    words: dict[float, str] = {90: "straight up", 270: "straight down", 0: "straight along the positive x-axis",
             180: "straight along the negative x-axis"}
    return words.get(d, f"at {fmt(d)}° from the x-axis, counter-clockwise")


def _unit_jacobian(p, given=None):
    """7.6: the whole J of the unit-link arm at (θ1, θ2). Steps: θ1 + θ2, then J's second column
    (link 2 alone), each from the learner's own previous one (``given``); the first column adds
    link 1's share to the second.

    >>> made = _unit_jacobian({"t1": 50, "t2": -100}, given={"col2": ((0.766,), (0.6428,))})
    >>> made["key"][0][0], made["steps"]["col2"]["key"][0][0] == made["key"][0][1]
    (0.0, True)
    """
    t1, t2 = p["t1"], p["t2"]
    r1, r2 = math.radians(t1), math.radians(t2)
    J = jacobian_2link(1, 1, r1, r2)
    s1, c1, s12, c12 = math.sin(r1), math.cos(r1), math.sin(r1 + r2), math.cos(r1 + r2)
    x, y = forward_kinematics_2link(1, 1, r1, r2)
    t12 = chains.given(given, "t12", t1 + t2)
    link2 = jacobian_2link(0, 1, 0, math.radians(t12))  # link 2 alone: both columns are its column 2
    exact2 = column((link2[0][1], link2[1][1]))
    col2 = chains.given(given, "col2", exact2)
    if not apart(col2, exact2, rel=1e-3):  # the learner's column is this one to its printed digits: keep
        col2 = exact2                      # its exact entries, so rounding cannot spoil a small J(1,1)
    link1 = jacobian_2link(1, 0, r1, 0)  # link 1's share: column 1 only
    at_t2 = jacobian_2link(0, 1, 0, r2)
    col2_slips = kept_slips(col2, (
        (column((s12, c12)), "Check the sign of the first entry: the derivative of L2 cos(θ1 + θ2) is "
                             "−L2 sin(θ1 + θ2).", "check-sign-first-entry"),
        (column((c12, s12)), "That is link 2 itself, (L2 cos(θ1 + θ2), L2 sin(θ1 + θ2)): where it reaches, "
                             "not how fast the tip moves. Differentiate each by θ2.", "link-2-itself-l2"),
        (column((at_t2[0][1], at_t2[1][1])), f"That puts link 2 at θ2 = {_angle(t2)}. It points at θ1 + θ2 = "
                                             f"{_angle(t1 + t2)}.", "puts-link-2-theta2"),
    ))
    return {
        "key": grid(add(link1, [[col2[0][0]] * 2, [col2[1][0]] * 2])),
        "slips": (
            Slip(grid([J[0], [J[1][0], 1 * s12]]),
                 "J(2,2) uses sin(θ1 + θ2): that is the bug of exercise 7.5. ∂/∂θ2 of L2 sin(θ1 + θ2) is "
                 f"L2 cos(θ1 + θ2) = cos {prose(t1 + t2)}° = {prose(c12)}.", name="j-2-2-uses"),
            Slip(grid(jacobian_2link(1, 1, r2, r1)),
                 f"That is J at θ = ({_angle(t2)}, {_angle(t1)}): the two joint angles are swapped. "
                 f"Here θ1 = {_angle(t1)} and θ2 = {_angle(t2)}.", name="j-theta-two-joint"),
            Slip(grid(jacobian_2link(1, 1, r1, 0)),
                 f"That is J of the straight arm, θ2 = 0. Put θ2 = {_angle(t2)} into sin(θ1 + θ2) and cos(θ1 + θ2).",
                     name="j-straight-arm-theta2"),
        ),
        "steps": {
            "t12": {"key": t12, "slips": link2_direction_slips(t1, t2)},
            "col2": {"key": col2, "slips": col2_slips},
        },
        "values": {
            "deg1": "" if t1 == 0 else "°", "t12": fmt(t1 + t2), "a12": _angle(t1 + t2, tex=True),
            "sum12": f"{fmt(t1)}{'' if t1 == 0 else '°'} {signed(t2)}°",
            **_trig_terms(s1, c1, s12, c12, J),
            "j11": fmt(J[0][0]), "j12": fmt(J[0][1]), "j21": fmt(J[1][0]), "j22": fmt(J[1][1]),
            "x": fmt(x), "y": fmt(y), "link2": _link2_direction(t1 + t2),
            "det": fmt(jacobian_det(1, 1, r1, r2)),
            "as71": " as in exercise 7.1" if (t1, t2) == (0, 90) else " a new pose",
        },
    }


def _trig_terms(s1, c1, s12, c12, J):
    """7.6's printed sines and cosines, to the fewest figures (at least 4) with which the sums the
    hint and the derivation print, −s1 − s12 and c1 + c12, land on J's entries within the
    tolerance: where the two terms nearly cancel (0.8192 − 0.8660 for −0.04687), more figures.

    >>> _trig_terms(-0.57358, 0.81915, -0.5, -0.86603, ((1.07358, 0.5), (-0.04688, -0.86603)))["c1"]
    '0.81915'
    """
    for figures in range(4, 12):
        s1_, c1_, s12_, c12_ = (fmt(v, significant=figures) for v in (s1, c1, s12, c12))
        sums = (-float(s1_) - float(s12_), float(c1_) + float(c12_))
        if all(agrees(got, clean(want)) for got, want in zip(sums, (J[0][0], J[1][0]))):
            break
    b11, b21 = fmt(-s12, significant=figures), c12_
    return {"s1": s1_, "c1": c1_, "s12": s12_, "c12": c12_, "a11": fmt(-s1, significant=figures),
            "b11": f"- {b11[1:]}" if b11.startswith("-") else f"+ {b11}",
            "b21": f"- {b21[1:]}" if b21.startswith("-") else f"+ {b21}"}


def _well_posed_jacobian(p):
    """7.6: no singular pose, and no slip that equals the key (θ1 = θ2 makes the swap
    harmless; sin = cos at θ1 + θ2 = 45° or −135° hides the exercise-7.5 bug)."""
    t1, t2 = p["t1"], p["t2"]
    return t2 % 180 != 0 and t1 != t2 and (t1 + t2) % 180 != 45


_X_OF = "L_1\\cos\\theta_1 + L_2\\cos(\\theta_1 + \\theta_2)"
_Y_OF = "L_1\\sin\\theta_1 + L_2\\sin(\\theta_1 + \\theta_2)"


def _jacobian_formula(p):
    """7.7: one entry of J as a formula in θ1, θ2, L1, L2 (which one is drawn)."""
    entry = p["entry"]
    r, c = (int(k) for k in entry.strip("()").split(","))
    answer, tex, equals, slips = FORMULAS[r, c]
    coord, joint = "xy"[r - 1], c
    at71 = jacobian_2link(1, 1, 0, math.pi / 2)[r - 1][c - 1]  # exercise 7.1's own numbers: unit links at (0, 90°)
    return {
        "key": entry_of(r - 1, c - 1),
        "answer_text": answer,
        "label": f"J{entry} = ∂{coord}/∂θ{joint}",
        "slips": tuple(Slip(f, m, name=name) for f, m, name in slips),
        "values": {
            "ij": f"{r}{c}", "coord": coord, "j": str(joint),
            "fk": _X_OF if r == 1 else _Y_OF, "fk2": (_X_OF if r == 1 else _Y_OF).replace(" + \\theta", "+\\theta"),
            "terms": "Both terms contain" if joint == 1 else "Only the second term contains",
            "carries": "the whole arm, so both links appear" if joint == 1 else "link 2 alone, so only link 2 appears",
            "equals": equals,
            "turning": "the base" if joint == 1 else "the elbow",
            "ref71": "the entry exercise 7.1 asks for" if (r, c) == (1, 1) else "as exercise 7.1's derivation finds",
            "at71": fmt(at71),
            "formula2": tex.format(s=""),
        },
    }


EXERCISES = (
    Derive(
        id="7.1",
        title="Jacobian at θ = (0, 90°)",
        spec=number(label="J(1,1)"),
        vary=Vary(_jacobian_entry, Param("L", 1, 0.5, 2, 0.1, unit=" m"), Param("t1", 0, -45, 45, 5, unit="°")),
        steps=(LINK2_DIRECTION, Step("link2", "link 2's term", number(label="−L2·sin(θ1 + θ2), link 2's term"))),
    ),
    Derive(
        id="7.2",
        title="End-effector velocity",
        spec=number(label="ẋ", unit="m/s"),
        vary=Vary(
            _tip_velocity, Param("L", 1, 0.5, 2, 0.01, unit=" m"), Param("w1", 1, -2, 2, 0.5, unit=" rad/s", avoid=(0,))
        ),
        uses=(Uses("7.1", "j11", "J(1,1)", variant=lambda p: 0 if p["L"] == 1 else None),),
    ),
    Derive(
        id="7.3",
        title="Spot the singularity",
        same_answer="det J of the straight arm is 0 for every link length: that is the point of the exercise.",
        spec=number(label="det J at θ2 = 0"),
        vary=Vary(_straight_arm_det, Param("L", 1, 0.5, 2.5, 0.1, unit=" m", avoid=(2,))),
    ),
    Derive(
        id="7.4",
        title="Best elbow angle",
        same_answer="The best elbow angle is 90° for every link length: that is the point of the exercise.",
        spec=number(label="θ2 that maximises w = |det J|", unit="°", angle="deg"),
        vary=Vary(_best_elbow, Param("L", 1, 0.5, 2, 0.1, unit=" m")),
    ),
    Debug(
        id="7.5",
        title="Find the bug in the Jacobian",
        code=JACOBIAN_SIGN_BUG,
        bug_line=8,
        fixed_line="    J22 = L2 * c12",
        bug=(
            "J(2,2) = ∂y/∂θ2. Only the second link depends on θ2, through y ∋ L2·sin(θ1 + θ2), whose "
            "derivative is L2·cos(θ1 + θ2) = L2·c12. The line uses s12, so ẏ is wrong whenever joint 2 moves."
        ),
        notes={
            1: "imports math for sin and cos",
            2: "takes both link lengths and both joint angles",
            3: "link 1 points at θ1, so its sine and cosine use t1",
            4: "link 2 points at θ1 + θ2, so its terms use the sum",
            5: "correct: ∂x/∂θ1 = −L1 sin θ1 − L2 sin(θ1+θ2)",
            6: "correct: ∂x/∂θ2 = −L2 sin(θ1+θ2), only link 2 depends on θ2",
            7: "correct: ∂y/∂θ1 = L1 cos θ1 + L2 cos(θ1+θ2)",
            9: "returns the rows [∂x/∂θ, ∂y/∂θ] in the right places",
        },
        function="jacobian_2link",
        reference=jacobian_2link,
        cases=((1, 1, 0.0, math.pi / 2), (2, 1, 0.3, 0.4), (1, 1, 0.5, -1.2)),
    ),
    Derive(
        id="7.6",
        title="The whole Jacobian at θ = (0, 90°)",
        spec=matrix(label="J"),
        vary=Vary(
            _unit_jacobian,
            Param("t1", 0, -60, 60, 5, unit="°"),
            Param("t2", 90, -150, 150, 5, unit="°", avoid=(0,)),
            valid=_well_posed_jacobian,
        ),
        steps=(LINK2_DIRECTION, Step("col2", "J's second column", matrix(label="J's second column (∂x/∂θ2, ∂y/∂θ2)"))),
    ),
    Derive(
        id="7.7",
        title="J(1,1) as a formula",
        same_answer="A formula in θ1, θ2, L1 and L2: students differ only in which of four entries they are asked.",
        spec=formula(
            variables=("theta1", "theta2", "L1", "L2"),
            domain={"theta1": (-3.0, 3.0), "theta2": (-3.0, 3.0), "L1": (0.2, 2.0), "L2": (0.2, 2.0)},
        ),
        vary=Vary(_jacobian_formula, Choice("entry", "(1,1)", ("(1,1)", "(1,2)", "(2,1)", "(2,2)"))),
    ),
)
