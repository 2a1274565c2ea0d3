"""Chapter 6 · Two-link arm: forward and inverse kinematics."""

import math

from ..kinds.build import Build
from ..answer_kinds.base import Slip
from ..answer_kinds.number import number
from ..answer_kinds.expression import formula
from ..kinds.derive import Derive
from ..kinds.trace import Option, Trace
from ..number_format import fmt, paren
from ..reference.arm import (
    cos_elbow,
    forward_kinematics_2link,
    inverse_kinematics_2link,
    is_reachable,
)
from ..tolerance import agrees
from ..variants import Choice, Param, Vary

_T1, _T2 = math.radians(30), math.radians(45)


def _four(x):
    """A value to four decimals as the text prints it: 0.8660, but an exact 0.5 stays 0.5."""
    return fmt(x) if math.isclose(x, round(x, 4), abs_tol=1e-12) else f"{x:.4f}"


def _signed4(x):
    """A following term to four decimals: ``+ 0.2588`` or ``- 0.3420``."""
    s = _four(x)
    return f"- {s[1:]}" if s.startswith("-") else f"+ {s}"


def _words(x):
    """A number in a message, with a true minus sign: −90."""
    return fmt(x).replace("-", "−")


def _apart(key, values, *, periodic=False):
    """True when no two of key, *values are the same answer (angles in degrees: give or take whole turns)."""
    seen = [key]
    for v in values:
        if any(agrees(v + 360 * k, s) for s in seen for k in ((-1, 0, 1) if periodic else (0,))):
            return False
        seen.append(v)
    return True


def _straight_reach(p):
    """6.1: equal links L stretched along x (θ1 = θ2 = 0); asked: the tip's x."""
    L = p["L"]
    tip = forward_kinematics_2link(L, L, 0, 0)[0]
    elbow = forward_kinematics_2link(L, 0, 0, 0)[0]  # link 1 alone
    return {
        "key": tip,
        "slips": (Slip(elbow, "That is the elbow, the end of link 1. Add link 2, which also points along x."),),
        "values": {"tip": fmt(tip)},
    }


def _bent_reach(p):
    """6.2: unit links at θ1, θ2 (degrees); asked: the tip's x to four decimals."""
    t1, t2 = p["t1"], p["t2"]
    r1, r2 = math.radians(t1), math.radians(t2)
    x, y = forward_kinematics_2link(1, 1, r1, r2)
    c1, s1 = forward_kinematics_2link(1, 0, r1, 0)  # link 1 alone
    c12, s12 = forward_kinematics_2link(0, 1, r1, r2)  # link 2 alone
    return {
        "key": x,
        "slips": (
            Slip(forward_kinematics_2link(1, 1, r1, r2 - r1)[0],  # link 2 drawn at θ2 itself
                 f"You used cos {fmt(t2)}° for link 2. Its direction is θ1 + θ2 = {fmt(t1 + t2)}°: joint angles "
                 "add up along the chain."),
            Slip(y, "That is the y-coordinate. For x use the cosines."),
            Slip(c12, f"That is link 2's share alone. Add link 1's L1·cos θ1 = {_four(c1)}."),
        ),
        "values": {
            "t12": fmt(t1 + t2), "c1": _four(c1), "s1": _four(s1), "c12": _four(c12), "s12": _four(s12),
            "c12s": _signed4(c12), "s12s": _signed4(s12), "x": _four(x), "y": _four(y),
            "r": fmt(round(math.hypot(x, y), 2)),
        },
    }


def _bent_reach_well_posed(p):
    """6.2: the tip's x is not near 0; every slip lies well away from the key and from each other; and the
    four-decimal values the statement gives add up to the four-decimal x and y the derivation prints."""
    made = _bent_reach(p)
    v, answers = made["values"], [made["key"], *(s.value for s in made["slips"])]
    adds_up = all(_four(float(v[a]) + float(v[b])) == v[total] for a, b, total in (("c1", "c12", "x"),
                                                                                    ("s1", "s12", "y")))
    return adds_up and abs(made["key"]) >= 0.1 and all(
        abs(a - b) > 0.01 for i, a in enumerate(answers) for b in answers[i + 1:])


_ALONG = {(1, 0): "x", (0, 1): "y", (-1, 0): "-x", (0, -1): "-y"}  # link 1's direction, as the text names it
_HEADS = {(1, 0): "runs straight right", (0, 1): "rises straight up", (-1, 0): "runs straight left",
          (0, -1): "drops straight down"}


def _unit(angle):
    """The unit vector at a multiple of 90° (radians), as integers."""
    return round(math.cos(angle)), round(math.sin(angle))


def _diagonal_ik(p):
    """6.3: unit links reaching a diagonal target (±1, ±1); asked: θ2 or θ1 of one elbow branch, in degrees."""
    x, y, asked, branch = p["x"], p["y"], p["asked"], p["branch"]
    sol = inverse_kinematics_2link(1, 1, x, y)
    down = branch == "elbow-down"
    mine, twin = (sol.elbow_down, sol.elbow_up) if down else (sol.elbow_up, sol.elbow_down)
    other, rel = ("elbow-up", "≥") if down else ("elbow-down", "≤")
    t1d, t1u = math.degrees(sol.elbow_down[0]), math.degrees(sol.elbow_up[0])
    phi = math.degrees(math.atan2(y, x))
    elbow, elbow_up = _unit(sol.elbow_down[0]), _unit(sol.elbow_up[0])
    target = f"atan2({_words(y)}, {_words(x)})"
    if asked == "θ2":
        key = math.degrees(mine[1])
        slips = [
            Slip(cos_elbow(1, 1, x, y), "That is cos θ2. The angle whose cosine is 0 is what is asked."),
            Slip(math.degrees(twin[1]), f"{_words(math.degrees(twin[1]))}° is a valid pose too: the {other} solution. "
                                        f"This exercise asks for the {branch} one, θ2 {rel} 0."),
            Slip(phi, f"{_words(phi)}° is the direction of the target, {target}; it goes into θ1, not θ2."),
        ]
    else:
        key, share = math.degrees(mine[0]), phi - math.degrees(mine[0])
        slips = [
            Slip(math.degrees(twin[0]), f"{_words(math.degrees(twin[0]))}° is θ1 of the {other} pose. "
                                        f"This exercise asks for the {branch} one, θ2 {rel} 0."),
            Slip(phi, f"{_words(phi)}° is the direction of the target, {target}. θ1 also takes away the angle the "
                      f"elbow adds: atan2(L2 sin θ2, L1 + L2 cos θ2) = {_words(share)}°."),
        ]
        theta2 = math.degrees(mine[1])
        if _apart(key, [s.value for s in slips] + [theta2], periodic=True):
            slips.append(Slip(theta2, "That is θ2, the elbow angle. This asks for θ1, the shoulder angle."))
    return {
        "key": key,
        "label": f"{asked} ({branch}, θ2 {rel} 0)",
        "periodic": asked == "θ1",  # a shoulder angle give or take a whole turn is the same pose
        "slips": tuple(slips),
        "values": {
            "px": paren(x), "py": paren(y), "phi": fmt(phi), "t1d": fmt(t1d), "t1u": fmt(t1u),
            "along": _ALONG[elbow], "ex": fmt(elbow[0]), "ey": fmt(elbow[1]),
            "rise": _HEADS[(x - elbow[0], y - elbow[1])],
            "eux": fmt(elbow_up[0]), "euy": fmt(elbow_up[1]),
            "asked_tex": "\\theta_2" if asked == "θ2" else "\\theta_1", "rel_tex": "\\ge" if down else "\\le",
            "ans": fmt(key),
        },
    }


def _fk_formula(p):
    """6.6: the tip's x or y as a formula in θ1, θ2, L1, L2."""
    coord = p["coord"]
    i = "xy".index(coord)
    fn, other = ("cos", "sin") if coord == "x" else ("sin", "cos")
    words = {"cos": "cosines", "sin": "sines"}
    identity = {
        "x": "\\cos(\\theta_1+\\theta_2) = \\cos\\theta_1\\cos\\theta_2 - \\sin\\theta_1\\sin\\theta_2",
        "y": "\\sin(\\theta_1+\\theta_2) = \\sin\\theta_1\\cos\\theta_2 + \\cos\\theta_1\\sin\\theta_2",
    }[coord]
    return {
        "key": lambda theta1, theta2, L1, L2: forward_kinematics_2link(L1, L2, theta1, theta2)[i],
        "answer_text": f"L1*{fn}(theta1) + L2*{fn}(theta1 + theta2)",
        "label": f"{coord}(θ1, θ2)",
        "slips": (
            Slip(lambda theta1, theta2, L1, L2: forward_kinematics_2link(L1, L2, theta1, theta2 - theta1)[i],
                 "Link 2 points at θ1 + θ2, not θ2: θ2 is measured from link 1, so the angles add up along "
                 "the chain."),
            Slip(lambda theta1, theta2, L1, L2: forward_kinematics_2link(L1, L2, theta1, theta2)[1 - i],
                 f"That is {'yx'[i]}(θ1, θ2), with {words[other]}. The {coord}-coordinate uses {words[fn]}."),
            Slip(lambda theta1, theta2, L1, L2: forward_kinematics_2link(L1, L2, theta1 + theta2, 0)[i],
                 "That puts both links at θ1 + θ2. Link 1 points at θ1 alone."),
        ),
        "values": {"fn": "\\" + fn, "identity": identity,
                   "at62": _four(forward_kinematics_2link(1, 1, _T1, _T2)[i])},
    }

# Exercise 6.4: the arm L1 = 2, L2 = 1 reaches the annulus 1 ≤ r ≤ 3.
_ARM = (2, 1)
_TARGETS = {"a": (3, 0), "b": (1, 0), "c": (2, 1), "d": (3, 1)}
_UNREACHABLE = [k for k, (x, y) in _TARGETS.items() if not is_reachable(*_ARM, x, y)]
assert _UNREACHABLE == ["d"], _UNREACHABLE

EXERCISES = (
    Derive(
        id="6.1",
        title="FK of the straight arm",
        answer=number(label="x-coordinate of the end effector", unit="m"),
        vary=Vary(_straight_reach, Param("L", 1, 0.5, 2.5, 0.1, unit=" m")),
    ),
    Derive(
        id="6.2",
        title="FK of a bent arm",
        answer=number(label="x-coordinate of the end effector", unit="m"),
        vary=Vary(_bent_reach, Param("t1", 30, 5, 85, 5, unit="°"), Param("t2", 45, 5, 120, 5, unit="°"),
                  valid=_bent_reach_well_posed),
    ),
    Derive(
        id="6.3",
        title="IK: the elbow angle",
        answer=number(label="θ2 (elbow-down, θ2 ≥ 0)", unit="°", angle="deg"),
        vary=Vary(_diagonal_ik, Param("x", 1, -1, 1, 2), Param("y", 1, -1, 1, 2),
                  Choice("asked", "θ2", ("θ2", "θ1")), Choice("branch", "elbow-down", ("elbow-down", "elbow-up"))),
    ),
    Trace(
        id="6.4",
        title="Workspace boundary",
        answer=_UNREACHABLE[0],
        options=(
            Option("a", "$(3, 0)$",
                   "Reachable, just: it is exactly $L_1 + L_2 = 3$ away, so the arm reaches it fully stretched. "
                   "The boundary belongs to the workspace, with a single IK solution."),
            Option("b", "$(1, 0)$",
                   "Reachable, just: it is exactly $|L_1 - L_2| = 1$ away, the inner edge, reached with the elbow folded back "
                   "($\\theta_2 = 180°$)."),
            Option("c", "$(2, 1)$",
                   "Reachable: $\\sqrt{4 + 1} \\approx 2.24$ lies between 1 and 3, inside the annulus, so there are two "
                   "elbow solutions."),
            Option("d", "$(3, 1)$",
                   "Right. $\\sqrt{9 + 1} = \\sqrt{10} \\approx 3.16 > L_1 + L_2 = 3$: beyond full stretch. "
                   "$\\cos\\theta_2$ would come out above 1, which no angle has."),
        ),
    ),
    Build(
        id="6.5",
        title="Implement forward_kinematics_2link",
        function="forward_kinematics_2link",
        params=("L1", "L2", "theta1", "theta2"),
        starter=(
            "import math\n\n\n"
            "def forward_kinematics_2link(L1, L2, theta1, theta2):\n"
            '    """Tip position (x, y) of a two-link planar arm; angles in radians."""\n'
            "    # Your code here: add up the two links, each at its own angle.\n"
            "    return (L1 + L2, 0.0)\n"
        ),
        solution=(
            "import math\n\n\n"
            "def forward_kinematics_2link(L1, L2, theta1, theta2):\n"
            '    """Tip position (x, y) of a two-link planar arm; angles in radians."""\n'
            "    phi = theta1 + theta2  # direction of link 2\n"
            "    x = L1 * math.cos(theta1) + L2 * math.cos(phi)\n"
            "    y = L1 * math.sin(theta1) + L2 * math.sin(phi)\n"
            "    return (x, y)\n"
        ),
        reference=forward_kinematics_2link,
        examples=((1, 1, 0.0, 0.0), (1, 1, _T1, _T2), (1, 1, 0.0, math.pi / 2), (2, 1, math.pi / 2, math.pi)),
        random_args=lambda rng: (rng.uniform(0.1, 3), rng.uniform(0.1, 3),
                                 rng.uniform(-math.pi, math.pi), rng.uniform(-math.pi, math.pi)),
    ),
    Derive(
        id="6.6",
        title="FK as a formula",
        answer=formula(
            variables=("theta1", "theta2", "L1", "L2"),
            domain={"theta1": (-3.0, 3.0), "theta2": (-3.0, 3.0), "L1": (0.2, 2.0), "L2": (0.2, 2.0)},
        ),
        vary=Vary(_fk_formula, Choice("coord", "x", ("x", "y"))),
    ),
)
