"""Chapter 8 · PID control."""

from ..answer_kinds.matrix import MatrixDerive
from ..kinds.build import Build
from ..kinds.derive import Derive, Slip
from ..kinds.trace import Option, Trace
from ..reference.pid import d_term, i_term, p_term, pid_sequence, pid_step, pid_terms
from . import column

_GAINS = dict(Kp=1, Ki=0.1, Kd=0.5, dt=1)
_ERRORS = [5, 3, 1]
_U2 = pid_sequence(_ERRORS, **_GAINS)[2]
_P2 = p_term(_ERRORS[2], _GAINS["Kp"])
_I2 = i_term(_ERRORS, _GAINS["Ki"], _GAINS["dt"])
_D2 = d_term(_ERRORS[2], _ERRORS[1], _GAINS["Kd"], _GAINS["dt"])

EXERCISES = (
    Derive(
        id="8.1",
        title="One step of P control",
        key=p_term(10 - 7, 2),
        label="control output u",
        slips=(
            Slip(p_term(7 - 10, 2), "Sign: the error is target − actual = +3, so the push is positive, toward the target."),
            Slip(10 - 7, "That is the error e. The output multiplies it by Kp."),
        ),
    ),
    Derive(
        id="8.2",
        title="PID over three steps",
        key=_U2,
        label="u[2]",
        slips=(
            Slip(_P2 + _I2, "You left out the D term. The error fell from 3 to 1, so Kd·(e[2] − e[1])/dt = −1."),
            Slip(_P2 + _D2, "You left out the I term: Ki times the sum of all errors so far, 0.1 × 9."),
            Slip(_P2 + _I2 - _D2, "D sign: it is Kd·(e[2] − e[1]), new minus old, and the error is shrinking."),
            Slip(_P2 + _GAINS["Ki"] * _ERRORS[2] + _D2,
                 "The I term integrates every error so far (5 + 3 + 1), not only the current one."),
        ),
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
                   "A weak proportional gain makes the arm sluggish, creeping toward the target; it does not overshoot."),
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
                   "At rest the error is constant, so its derivative is zero and the D term contributes nothing there."),
            Option("c", "Sample faster (smaller $dt$)",
                   "The sampling rate does not change the balance $K_p e = \\text{gravity}$; the offset stays."),
            Option("d", "Add an I term",
                   "Right. While any error remains, the integral keeps growing and pushes harder, until the error is zero; "
                   "then the integral stops changing and holds the load by itself."),
        ),
    ),
    Derive(
        id="8.6",
        title="The sign of the D term",
        key=d_term(2, 5, 1, 0.1),
        label="D term",
        slips=(
            Slip(-d_term(2, 5, 1, 0.1), "Sign flipped: the D term uses e[k] − e[k−1] = 2 − 5 = −3. A falling error gives a negative D."),
            Slip(1 * (2 - 5), "You forgot to divide by dt = 0.1."),
            Slip(1 * (2 - 5) * 0.1, "Divide by dt, don't multiply: the derivative is a change per second."),
        ),
    ),
    MatrixDerive(
        id="8.7",
        title="The three terms, one by one",
        key=column(pid_terms(_ERRORS, **_GAINS)),
        label="(P, I, D)ᵀ at step 2",
        slips=(
            Slip(column((_P2, _GAINS["Ki"] * _ERRORS[2] * _GAINS["dt"], _D2)),
                 "The I term integrates every error so far, 5 + 3 + 1, not only the current one."),
            Slip(column((_P2, _I2, -_D2)),
                 "The D term has the wrong sign: it is Kd·(e[2] − e[1])/dt, new minus old, and the error is "
                 "shrinking."),
            Slip(column((_P2, i_term(_ERRORS[:2], _GAINS["Ki"], _GAINS["dt"]), _D2)),
                 "The I term stops one step short: the integral includes the current error e[2] = 1."),
        ),
    ),
)
