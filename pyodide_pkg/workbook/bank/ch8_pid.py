"""Chapter 8 · PID control."""

import math

from ..answer_kinds.base import Slip
from ..answer_kinds.matrix import matrix
from ..answer_kinds.number import number
from ..kinds.build import Build
from ..kinds.derive import Derive
from ..kinds.trace import Option, Trace
from ..number_format import fmt, paren, prose, signed
from ..reference.pid import d_term, i_term, p_term, pid_sequence, pid_step, pid_terms
from ..variants import Choice, Param, Vary
from . import column
from .checks import apart


def _p_step(p):
    """8.1: the output Kp·e of P control, with e = target − actual."""
    e = p["target"] - p["actual"]
    u = p_term(e, p["Kp"])
    return {
        "key": u,
        "slips": (
            Slip(p_term(p["actual"] - p["target"], p["Kp"]),
                 f"Sign: the error is target − actual = {'+' if e > 0 else '−'}{fmt(abs(e))}, so the push is "
                 f"{'positive' if e > 0 else 'negative'}, toward the target.", name="sign-error-target-actual"),
            Slip(e, "That is the error e. The output multiplies it by Kp.", name="error-e-output-multiplies"),
        ),
        "values": {"e": fmt(e), "pe": paren(e), "u": fmt(u)},
    }


# 8.2 and 8.7: three PID steps with a shrinking error e[0] > e[1] > e[2] > 0, from e[−1] = 0.
_THREE_STEPS = (Param("Kp", 1, 0.5, 3, 0.1), Param("Ki", 0.1, 0.05, 0.3, 0.01), Param("Kd", 0.5, 0.2, 1, 0.05),
                Choice("dt", 1, (0.5, 1, 2)),
                Param("e0", 5, 3, 9, 1), Param("e1", 3, 2, 6, 1), Param("e2", 1, 1, 4, 1))
_GAINS = ("Kp", "Ki", "Kd", "dt")


def _three_steps(p):
    """The terms at step 2 and the strings both derivations print."""
    errors = [p["e0"], p["e1"], p["e2"]]
    gains = {g: p[g] for g in _GAINS}
    P, I, D = (
        p_term(errors[2], p["Kp"]),
        i_term(errors, p["Ki"], p["dt"]),
        d_term(errors[2], errors[1], p["Kd"], p["dt"]),
    )
    return {
        "errors": errors, "gains": gains, "P": P, "I": I, "D": D,
        "values": {"P": fmt(P), "I": fmt(I), "D": fmt(D), "S": fmt(sum(errors)), "drop": fmt(errors[1] - errors[2])},
    }


def _i_share(I, P) -> str:
    """How the I term stands to the P term (P > 0), as 8.2 and 8.7 put it in words:
    ``"little"`` (at most a third of P), ``"smaller"``, ``"almost"`` (70 % of P or more),
    ``"equal"`` (within float noise) or ``"more"``.

    >>> [_i_share(I, 1) for I in (0.2, 0.5, 0.9, 1.0000000000001, 1.3)]
    ['little', 'smaller', 'almost', 'equal', 'more']
    >>> _ADDS[_i_share(0.9, 1)]  # 8.2's own numbers: I = 0.9 beside P = 1
    'almost as much again'
    """
    if math.isclose(I, P, rel_tol=1e-9, abs_tol=1e-12):
        return "equal"
    share = I / P
    return "more" if share > 1 else "almost" if share >= 0.7 else "smaller" if share > 1 / 3 else "little"


_ADDS = {"little": "a little", "smaller": "a smaller push", "almost": "almost as much again",  # 8.2: "I adds …"
         "equal": "as much again", "more": "even more"}
_PUSHES = {"little": "still adds a smaller push", "smaller": "still adds a smaller push",  # 8.7: "I … and …"
           "almost": "still pushes\nalmost as hard", "equal": "pushes just as hard",  # the page breaks the line there
           "more": "pushes harder still"}


def _shrinking(p):
    """e[0] > e[1] > e[2] > 0: the error shrinks at every step and is not yet gone."""
    return p["e0"] > p["e1"] > p["e2"] > 0


def _falling_fast(p):
    """8.7's story: the error shrinks, and at least halves in the last step."""
    return _shrinking(p) and 2 * p["e2"] <= p["e1"]


def _converging(p):
    """8.2's story: the error shrinks, and the push is gentle: positive, weaker than the step before, and
    no more than P alone (D eases off at least as much as I adds), yet told apart from P (the
    derivation prints P, which must not pass for the answer)."""
    if not _shrinking(p):
        return False
    u = pid_sequence([p["e0"], p["e1"], p["e2"]], *(p[g] for g in _GAINS))
    P = p_term(p["e2"], p["Kp"])
    return 0 < u[2] < u[1] and u[2] <= P + 1e-9 and (apart(u[2], P) or math.isclose(u[2], P))


def _pid_output(p):
    """8.2: u[2] = P + I + D after three steps."""
    t = _three_steps(p)
    (e0, e1, e2), P, I, D, Ki, dt = t["errors"], t["P"], t["I"], t["D"], p["Ki"], p["dt"]
    u = pid_sequence(t["errors"], **t["gains"])[2]
    times = f", {fmt(Ki)} × {fmt(e0 + e1 + e2)}." if dt == 1 else \
        f", times dt: {fmt(Ki)} × {fmt(e0 + e1 + e2)} × {fmt(dt)}."
    return {
        "key": u,
        "slips": (
            Slip(P + I, f"You left out the D term. The error fell from {fmt(e1)} to {fmt(e2)}, so "
                        f"Kd·(e[2] − e[1])/dt = {prose(D)}.", name="left-out-d-term"),
            Slip(P + D, "You left out the I term: Ki times the sum of all errors so far" + times,
                name="left-out-i-term"),
            Slip(P + I - D, "D sign: it is Kd·(e[2] − e[1]), new minus old, and the error is shrinking.",
                name="d-sign-kd-e"),
            Slip(P + Ki * e2 * dt + D,
                 f"The I term integrates every error so far ({fmt(e0)} + {fmt(e1)} + {fmt(e2)}), not only the current "
                 "one.", name="i-term-integrates-every"),
        ),
        "values": {**t["values"], "Ds": signed(D), "u": fmt(u), "pile": fmt((e0 + e1 + e2) * dt),
                   "more": _ADDS[_i_share(I, P)]},
    }


def _falling_error_d_term(p):
    """8.6: the D term Kd·(e[k] − e[k−1])/dt of a falling error."""
    ek, ep, Kd, dt = p["ek"], p["ep"], p["Kd"], p["dt"]
    D = d_term(ek, ep, Kd, dt)
    return {
        "key": D,
        "slips": (
            Slip(
                -D,
                f"Sign flipped: the D term uses e[k] − e[k−1] = {fmt(ek)} − {fmt(ep)} = {prose(ek - ep)}. "
                "A falling error gives a negative D.", name="sign-flipped-d-term"
            ),
            Slip(Kd * (ek - ep), f"You forgot to divide by dt = {fmt(dt)}.", name="forgot-divide-dt"),
            Slip(Kd * (ek - ep) * dt, "Divide by dt, don't multiply: the derivative is a change per second.",
                name="divide-dt-don-t"),
        ),
        "values": {
            "de": fmt(ek - ep),
            "kde": fmt(Kd * (ek - ep)),
            "D": fmt(D),
            "drop": fmt(ep - ek),
            "rate": fmt((ek - ep) / dt),
            "span": _SPANS[dt],
        },
    }


_SPANS = {0.05: "a twentieth of a second", 0.1: "a tenth of a second", 0.2: "a fifth of a second",
          0.25: "a quarter of a second", 0.5: "half a second"}


def _d_is_a_brake(p):
    """The error falls, and fast enough for D to dwarf it: at least twice e[k−1] in size."""
    return p["ek"] < p["ep"] and abs(d_term(p["ek"], p["ep"], p["Kd"], p["dt"])) >= 2 * p["ep"]


def _pid_terms(p):
    """8.7: the column (P, I, D) at step 2."""
    t = _three_steps(p)
    (e0, e1, e2), P, I, D = t["errors"], t["P"], t["I"], t["D"]
    at_default = p == {q.name: q.default for q in _THREE_STEPS}
    return {
        "key": column(pid_terms(t["errors"], **t["gains"])),
        "slips": (
            Slip(column((P, p["Ki"] * e2 * p["dt"], D)),
                 f"The I term integrates every error so far, {fmt(e0)} + {fmt(e1)} + {fmt(e2)}, not only the current "
                 "one.", name="i-term-integrates-every"),
            Slip(column((P, I, -D)),
                 "The D term has the wrong sign: it is Kd·(e[2] − e[1])/dt, new minus old, and the error is "
                 "shrinking.", name="d-term-has-wrong"),
            Slip(column((P, i_term(t["errors"][:2], p["Ki"], p["dt"]), D)),
                 f"The I term stops one step short: the integral includes the current error e[2] = {fmt(e2)}.",
                     name="i-term-stops-step"),
        ),
        "values": {**t["values"], "u": fmt(pid_sequence(t["errors"], **t["gains"])[2]), "push": _PUSHES[_i_share(I, P)],
                   "lead": "Take exercise 8.2 again" if at_default else "Take three PID steps",
                   "total": "exercise 8.2's" if at_default else "the output"},
    }


EXERCISES = (
    Derive(
        id="8.1",
        title="One step of P control",
        spec=number(label="control output u"),
        vary=Vary(_p_step, Param("target", 10, 0, 20, 1), Param("actual", 7, 0, 20, 1),
                  Param("Kp", 2, 0.5, 5, 0.1, avoid=(1,)),
                  valid=lambda p: p["target"] != p["actual"]),
    ),
    Derive(
        id="8.2",
        title="PID over three steps",
        spec=number(label="u[2]"),
        vary=Vary(_pid_output, *_THREE_STEPS, valid=_converging),
    ),
    Trace(
        id="8.3",
        title="Diagnose the oscillation",
        answer="b",
        options=(
            Option("a", "$K_i$ too high",
                   "Too much integral gives overshoot and a slow swing back as the accumulated sum unwinds, "
                   "not a fast oscillation about the target."),
            Option("b", "$K_p$ too high",
                   "Right. A large proportional gain overcorrects: it shoots past the target, the error flips sign, "
                   "and it shoots back just as hard. Lower $K_p$, or add $K_d$ to damp it."),
            Option("c", "$K_d$ too high",
                   "Too much derivative makes the output jittery, because it amplifies sensor noise; it damps motion "
                   "rather than sustaining an oscillation."),
            Option("d", "$K_p$ too low",
                   "A weak proportional gain makes the arm sluggish, creeping toward the target; it does not "
                   "overshoot."),
        ),
    ),
    Build(
        id="8.4",
        title="Implement pid_step",
        function="pid_step",
        params=("e", "e_prev", "integral", "Kp", "Ki", "Kd", "dt"),
        starter=(
            "def pid_step(e, e_prev, integral, Kp, Ki, Kd, dt):\n"
            '    """One PID step; return (u, new_integral)."""\n'
            "    # Your code here: update the integral, then add the P, I and D terms.\n"
            "    return (Kp * e, integral)\n"
        ),
        solution=(
            "def pid_step(e, e_prev, integral, Kp, Ki, Kd, dt):\n"
            '    """One PID step; return (u, new_integral)."""\n'
            "    new_integral = integral + e * dt\n"
            "    p = Kp * e\n"
            "    i = Ki * new_integral\n"
            "    d = Kd * (e - e_prev) / dt\n"
            "    return (p + i + d, new_integral)\n"
        ),
        reference=pid_step,
        run_figure="pid",
        examples=(
            (3, 3, 0, 2, 0, 0, 1),
            (5, 0, 0, 1, 0.1, 0.5, 1),
            (3, 5, 5, 1, 0.1, 0.5, 1),
            (1, 3, 8, 1, 0.1, 0.5, 1),
            (2, 5, 0, 0, 0, 1, 0.1),
        ),
        random_args=lambda rng: (rng.uniform(-10, 10), rng.uniform(-10, 10), rng.uniform(-20, 20),
                                 rng.uniform(0, 5), rng.uniform(0, 2), rng.uniform(0, 2),
                                 rng.uniform(0.01, 1.0)),
    ),
    Trace(
        id="8.5",
        title="Remove the steady-state error",
        answer="d",
        options=(
            Option("a", "Raise $K_p$",
                   "A larger $K_p$ shrinks the leftover error, since a smaller $e$ now makes the same holding force, "
                   "but it never reaches zero, and too large a gain starts to oscillate."),
            Option("b", "Add a D term",
                   "At rest the error is constant, so its derivative is zero and the D term contributes nothing "
                   "there."),
            Option("c", "Sample faster (smaller $dt$)",
                   "The sampling rate does not change the balance $K_p e = \\text{gravity}$; the offset stays."),
            Option("d", "Add an I term",
                   "Right. While any error remains, the integral keeps growing and pushes harder, until the error is "
                   "zero; "
                   "then the integral stops changing and holds the load by itself."),
        ),
    ),
    Derive(
        id="8.6",
        title="The sign of the D term",
        spec=number(label="D term"),
        vary=Vary(_falling_error_d_term, Param("ek", 2, 0, 8, 0.5), Param("ep", 5, 1, 10, 0.5),
                  Param("Kd", 1, 0.5, 3, 0.05),
                  Choice("dt", 0.1, tuple(_SPANS)), valid=_d_is_a_brake),
    ),
    Derive(
        id="8.7",
        title="The three terms, one by one",
        spec=matrix(label="the terms at step 2", names=("P", "I", "D")),
        vary=Vary(_pid_terms, *_THREE_STEPS, valid=_falling_fast),
    ),
)
