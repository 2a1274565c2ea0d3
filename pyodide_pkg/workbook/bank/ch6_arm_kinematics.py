"""Chapter 6 · Two-link arm: forward and inverse kinematics.

6.2 and 6.3 can be worked in checked steps (θ1 + θ2, then link 2's share of x; cos θ2, then θ2).
The arm's first step, the direction of link 2 (LINK2_DIRECTION with its slips), is also chapter 7's.
"""

import math

from .. import chains
from ..answer_kinds.base import Slip
from ..answer_kinds.expression import formula
from ..answer_kinds.number import number
from ..kinds.build import Build
from ..kinds.derive import Derive
from ..kinds.trace import Option, Trace
from ..number_format import approx, fmt, paren, prose, relation, shown, signed
from ..reference.arm import (
    cos_elbow,
    forward_kinematics_2link,
    inverse_kinematics_2link,
    is_reachable,
)
from ..reference.domain import Undefined
from ..steps import Step
from ..variants import Choice, Param, Vary
from .checks import apart, kept_slips, slips_apart

_T1, _T2 = math.radians(30), math.radians(45)


def _straight_reach(p):
    """6.1: equal links L stretched along x (θ1 = θ2 = 0); asked: the tip's x."""
    L = p["L"]
    tip = forward_kinematics_2link(L, L, 0, 0)[0]
    elbow = forward_kinematics_2link(L, 0, 0, 0)[0]  # link 1 alone
    return {
        "key": tip,
        "slips": (Slip(elbow, "That is the elbow, the end of link 1. Add link 2, which also points along x.",
            name="elbow-end-link-1"),),
        "values": {"tip": fmt(tip)},
    }


# The first step of 6.2, 7.1 and 7.6: the direction of link 2 (any whole turn more or less is the same).
LINK2_DIRECTION = Step("t12", "θ1 + θ2", number(label="θ1 + θ2, the direction of link 2", unit="°", angle="deg",
                                                periodic=True))


def link2_direction_slips(t1: float, t2: float) -> tuple[Slip, ...]:
    """The slips in θ1 + θ2, the direction of link 2 (in degrees; 6.2, 7.1, 7.6)."""
    return kept_slips(t1 + t2, (
        (t2, f"That is θ2 alone. θ2 is measured from link 1, which points at {prose(t1)}°: "
             "link 2 points at θ1 + θ2.", "theta2-alone-theta2-measured"),
        (t1 - t2, "That is θ1 − θ2. θ2 turns link 2 further, the same way θ1 turns link 1, "
                  "so the two angles add.", "theta1-theta2-theta2-turns"),
    ), turn=360)


def _bent_reach(p, given=None):
    """6.2: unit links at θ1, θ2 (degrees); asked: the tip's x to four decimals. Steps: the direction
    of link 2, θ1 + θ2, then link 2's share of x, each from the learner's own previous one (``given``)."""
    t1, t2 = p["t1"], p["t2"]
    r1, r2 = math.radians(t1), math.radians(t2)
    x, y = forward_kinematics_2link(1, 1, r1, r2)
    c1, s1 = forward_kinematics_2link(1, 0, r1, 0)  # link 1 alone
    c12, s12 = forward_kinematics_2link(0, 1, r1, r2)  # link 2 alone
    t12 = chains.given(given, "t12", t1 + t2)
    x2 = chains.given(given, "x2", forward_kinematics_2link(0, 1, math.radians(t12), 0)[0])
    x2_slips = kept_slips(c12, (
        (s12, "That is link 2's share of y, L2·sin(θ1 + θ2). Its share of x uses the cosine.", "link-2-share-of-y"),
        (forward_kinematics_2link(0, 1, r2, 0)[0],  # link 2 drawn at θ2 itself
         f"That is cos {prose(t2)}°, link 2 at θ2. It points at θ1 + θ2: take the cosine of {prose(t1 + t2)}°.",
             "cos-link-2-theta2"),
    ))
    return {
        "key": c1 + x2,
        "slips": (
            Slip(forward_kinematics_2link(1, 1, r1, r2 - r1)[0],  # link 2 drawn at θ2 itself
                 f"You used cos {fmt(t2)}° for link 2. Its direction is θ1 + θ2 = {fmt(t1 + t2)}°: joint angles "
                 "add up along the chain.", name="used-cos-link-2"),
            Slip(y, "That is the y-coordinate. For x use the cosines.", name="y-coordinate-use-cosines"),
            Slip(c12, f"That is link 2's share alone. Add link 1's L1·cos θ1 = {fmt(c1)}.", name="link-2-alone"),
        ),
        "steps": {
            "t12": {"key": t12, "slips": link2_direction_slips(t1, t2)},
            "x2": {"key": x2, "slips": x2_slips},
        },
        "values": {
            "t12": fmt(t1 + t2), "c1": fmt(c1), "s1": fmt(s1), "c12": fmt(c12), "s12": fmt(s12),
            "c12s": signed(c12), "s12s": signed(s12), "x": fmt(x), "y": fmt(y), "xp": paren(x), "yp": paren(y),
            "r": fmt(math.hypot(x, y)), "r_rel": relation(math.hypot(x, y), math.hypot(shown(x), shown(y))),
        },
    }


def _bent_reach_well_posed(p):
    """6.2: the tip's x is not near 0; the key and the slips are told apart; and the four-decimal
    values the statement gives add up to the x and y the derivation prints (the worked answer)."""
    made = _bent_reach(p)
    v = {name: shown(float(text)) for name, text in made["values"].items() if name in ("c1", "s1", "c12", "s12")}
    x, y = forward_kinematics_2link(1, 1, math.radians(p["t1"]), math.radians(p["t2"]))
    adds_up = relation(x, v["c1"] + v["c12"]) == relation(y, v["s1"] + v["s12"]) == "="
    return adds_up and abs(made["key"]) >= 0.1 and slips_apart(made)


_ALONG = {(1, 0): "x", (0, 1): "y", (-1, 0): "-x", (0, -1): "-y"}  # link 1's direction, as the text names it
_HEADS = {(1, 0): "runs straight right", (0, 1): "rises straight up", (-1, 0): "runs straight left",
          (0, -1): "drops straight down"}


def _unit(angle):
    """The unit vector at a multiple of 90° (radians), as integers."""
    return round(math.cos(angle)), round(math.sin(angle))


def _elbow_side(target, elbow):
    """Where the elbow sits, seen from the base looking at the target: left or right of that line,
    and above or below it (the target is never straight above the base here)."""
    (x, y), (ex, ey) = target, elbow
    side = "left" if x * ey - y * ex > 0 else "right"
    return side, "above" if ey > y / x * ex else "below"


def _elbow_share(theta2):
    """The angle (radians) the elbow adds to the shoulder's, atan2(L2 sin θ2, L1 + L2 cos θ2) for unit
    links: the direction of the tip when link 1 lies along x."""
    x, y = forward_kinematics_2link(1, 1, 0, theta2)
    if math.hypot(x, y) < 1e-9:  # a learner's θ2 = ±180°: link 2 folded back onto link 1
        raise Undefined("with θ2 = ±180° link 2 folds back onto link 1 and the tip sits on the base, "
                        "so no θ1 reaches the target")
    return math.atan2(y, x)


def _diagonal_steps(x, y, c2, t2, phi, branch, other, rel, target):
    """6.3's steps: cos θ2 from the law of cosines, then θ2 of the branch (the learner's own c2 and t2 when given)."""
    r = math.hypot(x, y)
    return {
        "c2": {"key": c2, "slips": (
            Slip((r * r) / 2, "You left out L1² + L2²: the law of cosines takes them away from x² + y² "
                              "before dividing by 2·L1·L2.", name="left-out-l12-l22"),
            Slip((r * r - 4) / 2, "You took away (L1 + L2)², not L1² + L2²: square each link on its own.",
                name="took-away-l1-l2"),
            Slip((r - 2) / 2, "You used the distance r = √(x² + y²) itself. The law of cosines takes its "
                              "square, x² + y².", name="used-distance-r-x2"),
        )},
        "t2": {"key": t2, "label": f"θ2 ({branch}, θ2 {rel} 0)", "slips": (
            Slip(-t2, f"That is θ2 of the {other} solution. This exercise asks for the {branch} one, "
                      f"θ2 {rel} 0.", name="theta2-solution-exercise-asks"),
            Slip(phi, f"{fmt(phi)}° is the direction of the target, {target}; it goes into θ1, not θ2.",
                name="direction-target-goes-into"),
        )},
    }


def _diagonal_ik(p, given=None):
    """6.3: unit links reaching a diagonal target (±1, ±1); asked: θ2 or θ1 of one elbow branch, in degrees.
    Steps: cos θ2 from the law of cosines, then θ2 of the branch, each from the learner's own
    previous one (``given``); θ1 follows from that θ2."""
    x, y, asked, branch = p["x"], p["y"], p["asked"], p["branch"]
    sol = inverse_kinematics_2link(1, 1, x, y)
    down = branch == "elbow-down"
    sign = 1 if down else -1
    mine, twin = (sol.elbow_down, sol.elbow_up) if down else (sol.elbow_up, sol.elbow_down)
    other, rel = ("elbow-up", "≥") if down else ("elbow-down", "≤")
    c2 = chains.given(given, "c2", cos_elbow(1, 1, x, y))
    t2 = chains.given(given, "t2", sign * math.degrees(math.acos(c2)))  # ValueError when |cos θ2| > 1
    phi = math.degrees(math.atan2(y, x))
    share = math.degrees(_elbow_share(mine[1]))  # the angle the elbow adds, for the printed θ2
    elbow, elbow_twin = _unit(mine[0]), _unit(twin[0])
    side, above = _elbow_side((x, y), elbow)
    target = f"atan2({fmt(y)}, {fmt(x)})"
    steps = _diagonal_steps(x, y, c2, t2, phi, branch, other, rel, target)
    if asked == "θ2":
        key = t2  # θ1 is not asked, so a θ2 of ±180° (no θ1 reaches the target) is a fair θ2 all the same
        slips = [
            Slip(cos_elbow(1, 1, x, y), "That is cos θ2. The angle whose cosine is 0 is what is asked.",
                name="cos-theta2-angle-whose"),
            Slip(math.degrees(twin[1]), f"{fmt(math.degrees(twin[1]))}° is a valid pose too: the {other} solution. "
                                        f"This exercise asks for the {branch} one, θ2 {rel} 0.",
                                            name="valid-pose-too-solution"),
            Slip(phi, f"{fmt(phi)}° is the direction of the target, {target}; it goes into θ1, not θ2.",
                name="direction-target-goes-into"),
        ]
    else:
        try:  # θ1 follows from the learner's θ2; at θ2 = ±180° none does, though their steps stand
            key = math.degrees(math.atan2(y, x) - _elbow_share(math.radians(t2)))
        except Undefined as err:
            return {"undefined": str(err), "steps": steps}
        slips = [
            Slip(math.degrees(twin[0]), f"{fmt(math.degrees(twin[0]))}° is θ1 of the {other} pose. "
                                        f"This exercise asks for the {branch} one, θ2 {rel} 0.",
                                            name="theta1-pose-exercise-asks"),
            Slip(phi, f"{fmt(phi)}° is the direction of the target, {target}. θ1 also takes away the angle the "
                      f"elbow adds: atan2(L2 sin θ2, L1 + L2 cos θ2) = {fmt(share)}°.",
                          name="direction-target-theta1-also"),
        ]
        if apart(key, *(slip.value for slip in slips), t2, turn=360):
            slips.append(Slip(t2, "That is θ2, the elbow angle. This asks for θ1, the shoulder angle.",
                name="theta2-elbow-angle-asks"))
    return {
        "key": key,
        "label": f"{asked} ({branch}, θ2 {rel} 0)",
        "periodic": asked == "θ1",  # a shoulder angle give or take a whole turn is the same pose
        "slips": tuple(slips),
        "steps": steps,
        "values": {
            "px": paren(x), "py": paren(y), "phi": fmt(phi), "pm": "" if down else "-",
            "t1": fmt(math.degrees(mine[0])), "s2": fmt(math.sin(mine[1])), "minus_share": signed(-share),
            "along": _ALONG[elbow], "ex": fmt(elbow[0]), "ey": fmt(elbow[1]),
            "rise": _HEADS[(x - elbow[0], y - elbow[1])], "side": side, "above": above,
            "other": other, "t1o": fmt(math.degrees(twin[0])), "t2o": fmt(math.degrees(twin[1])),
            "eox": fmt(elbow_twin[0]), "eoy": fmt(elbow_twin[1]),
            "asked_tex": "\\theta_2" if asked == "θ2" else "\\theta_1", "rel_tex": "\\ge" if down else "\\le",
        },
    }


def _elbow_as_defined(p):
    """6.3: the chapter's definition holds: elbow-down (θ2 ≥ 0) keeps the elbow right of the base-target
    line, elbow-up (θ2 ≤ 0) left of it; the derivation says so in words."""
    made = _diagonal_ik(p)
    return made["values"]["side"] == ("right" if p["branch"] == "elbow-down" else "left")


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
                 "the chain.", name="link-2-points-theta1"),
            Slip(lambda theta1, theta2, L1, L2: forward_kinematics_2link(L1, L2, theta1, theta2)[1 - i],
                 f"That is {'yx'[i]}(θ1, θ2), with {words[other]}. The {coord}-coordinate uses {words[fn]}.",
                     name="theta1-theta2-coordinate-uses"),
            Slip(lambda theta1, theta2, L1, L2: forward_kinematics_2link(L1, L2, theta1 + theta2, 0)[i],
                 "That puts both links at θ1 + θ2. Link 1 points at θ1 alone.", name="puts-both-links-theta1"),
        ),
        "values": {"fn": "\\" + fn, "identity": identity,
                   "at62": fmt(forward_kinematics_2link(1, 1, _T1, _T2)[i]),
                   "at62_rel": relation(forward_kinematics_2link(1, 1, _T1, _T2)[i])},
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
        spec=number(label="x-coordinate of the end effector", unit="m"),
        vary=Vary(_straight_reach, Param("L", 1, 0.25, 2.5, 0.01, unit=" m")),
    ),
    Derive(
        id="6.2",
        title="FK of a bent arm",
        spec=number(label="x-coordinate of the end effector", unit="m"),
        vary=Vary(_bent_reach, Param("t1", 30, 5, 85, 5, unit="°"), Param("t2", 45, 5, 120, 5, unit="°"),
                  valid=_bent_reach_well_posed),
        steps=(LINK2_DIRECTION,
               Step("x2", "link 2's share of x", number(label="L2·cos(θ1 + θ2), link 2's share of x", unit="m"))),
    ),
    Derive(
        id="6.3",
        title="IK: the elbow angle",
        same_answer=("The target is one of the four diagonal points (±1, ±1) with unit links, so the angles come from "
                     "a short list."),
        spec=number(label="θ2 (elbow-down, θ2 ≥ 0)", unit="°", angle="deg"),
        vary=Vary(_diagonal_ik, Param("x", 1, -1, 1, 2), Param("y", 1, -1, 1, 2),
                  Choice("asked", "θ2", ("θ2", "θ1")), Choice("branch", "elbow-down", ("elbow-down", "elbow-up")),
                  valid=_elbow_as_defined),
        steps=(Step("c2", "cos θ2", number(label="cos θ2, from the law of cosines")),
               Step("t2", "θ2", number(unit="°", angle="deg"))),
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
                   "Reachable, just: it is exactly $|L_1 - L_2| = 1$ away, the inner edge, reached with the elbow "
                   "folded back "
                   "($\\theta_2 = 180°$)."),
            Option("c", "$(2, 1)$",
                   f"Reachable: $\\sqrt{{4 + 1}} {approx(math.sqrt(5))}$ lies between 1 and 3, inside the annulus, so "
                   "there are two "
                   "elbow solutions."),
            Option("d", "$(3, 1)$",
                   f"Right. $\\sqrt{{9 + 1}} = \\sqrt{{10}} {approx(math.sqrt(10))} > L_1 + L_2 = 3$: beyond full "
                   "stretch. "
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
        run_figure="arm",
        examples=((1, 1, 0.0, 0.0), (1, 1, _T1, _T2), (1, 1, 0.0, math.pi / 2), (2, 1, math.pi / 2, math.pi)),
        random_args=lambda rng: (rng.uniform(0.1, 3), rng.uniform(0.1, 3),
                                 rng.uniform(-math.pi, math.pi), rng.uniform(-math.pi, math.pi)),
    ),
    Derive(
        id="6.6",
        title="FK as a formula",
        same_answer="A formula in θ1, θ2, L1 and L2: students differ only in whether x or y is asked.",
        spec=formula(
            variables=("theta1", "theta2", "L1", "L2"),
            domain={"theta1": (-3.0, 3.0), "theta2": (-3.0, 3.0), "L1": (0.2, 2.0), "L2": (0.2, 2.0)},
        ),
        vary=Vary(_fk_formula, Choice("coord", "x", ("x", "y"))),
    ),
)
