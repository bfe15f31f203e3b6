"""A door closer: critical damping, and the closing motion when critically damped and when
overdamped (Section 4.3.2)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.mechanics import vibrations


@per_draw
def omega_n(p):
    return vibrations.natural_frequency(p.kt, p.J)


def solve(p):
    w = omega_n(p)
    return {
        "c_cr": vibrations.critical_damping(p.kt, p.J),
        "theta_crit": vibrations.free_response(p.t1, p.theta0, 0.0, w, 1.0),
        "theta_over": vibrations.free_response(p.t1, p.theta0, 0.0, w, p.ratio),
    }


EXERCISE = Exercise(
    id="door-closer-damping",
    title="Door closer: critically damped and overdamped return",
    source="Section 4.3.2",
    topics=("critical damping", "overdamped response", "free vibration", "torsional oscillator"),
    params=(
        Uniform("J", 2.0, 15.0, step=0.5, unit="kg*m^2", symbol="J"),
        Uniform("kt", 5.0, 60.0, step=1.0, unit="N*m", symbol="k_t"),
        Uniform("theta0", 30, 90, step=5, unit="deg", symbol=r"\theta_0"),
        Uniform("ratio", 1.5, 4.0, step=0.1, symbol="c/c_{cr}"),
        Uniform("t1", 0.5, 4.0, step=0.1, unit="s", symbol="t_1"),
    ),
    constraints=(
        Constraint("the door is still visibly open at t1 (both cases above 3 degrees) and has moved",
                   lambda p: np.radians(3) <= vibrations.free_response(p.t1, p.theta0, 0.0, omega_n(p), 1.0) <= 0.8 * p.theta0),
        Constraint("the door is not nearly closed in the overdamped case either",
                   lambda p: vibrations.free_response(p.t1, p.theta0, 0.0, omega_n(p), p.ratio) <= 0.97 * p.theta0),
    ),
    statement="""
A door (moment of inertia $J$ = {{ J }} about its hinges) is pulled shut by a closer that
acts as a torsional spring of stiffness $k_t$ = {{ kt }} (per radian) with a rotary viscous
damper. The door is opened to $\\theta_0$ = {{ theta0 }} and released from rest.

1. Which damping coefficient $c_{cr}$ (in N·m·s) makes the closer critically damped?
2. With critical damping, what is the door's angle at $t_1$ = {{ t1 }} after release?
3. The damper is set to $c = {{ ratio.value }}\\,c_{cr}$ instead. What is the angle at $t_1$ now?
""",
    solve=solve,
    parts=(
        Numeric("c_cr", "critical damping coefficient", unit="N*m*s", points=1,
                misconceptions=(Misconception("sqrt(k J)", lambda p: np.sqrt(p.kt * p.J),
                                              "Critical damping is c_cr = 2 sqrt(k_t J) (zeta = 1)."),)),
        Numeric("theta_crit", "angle at t1, critically damped", unit="deg", points=2,
                misconceptions=(
                    Misconception("pure exponential decay", lambda p: p.theta0 * np.exp(-omega_n(p) * p.t1),
                                  "For zeta = 1, theta = (theta0 + (v0 + omega_n theta0) t) e^{-omega_n t}."),
                    Misconception("undamped", lambda p: p.theta0 * np.cos(omega_n(p) * p.t1),
                                  "The damper is there: use the critically damped response."),
                )),
        Numeric("theta_over", "angle at t1, overdamped", unit="deg", points=2,
                misconceptions=(Misconception("critically damped again",
                                              lambda p: vibrations.free_response(p.t1, p.theta0, 0.0, omega_n(p), 1.0),
                                              "zeta > 1: the response is the sum of two decaying exponentials."),)),
    ),
)
