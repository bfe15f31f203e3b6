"""A door closer: critical damping, and the closing motion when critically damped and when
overdamped (Section 4.3.2)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.checks import Integrated, Recompute
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
        "omega_n": w,
    }


def _door(ratio):
    """J theta'' + c theta' + k_t theta = 0 with c = ratio * 2 sqrt(k_t J) (Section 4.3.2)."""
    def rhs(t, y, p):
        c = ratio(p) * 2 * np.sqrt(p.kt * p.J)
        return (y[1], -(c * y[1] + p.kt * y[0]) / p.J)
    return rhs


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
    solution=r"""
The door is a torsional oscillator, $J\ddot\theta + c\,\dot\theta + k_t\theta = 0$; its free
response depends on the damping ratio $\zeta = c/c_{cr}$ (free damped vibration,
Section 4.3.2). The natural frequency is $\omega_n = \sqrt{k_t/J}$ = {{ si.omega_n }} rad/s
with $J$ = {{ J }} and $k_t$ = {{ kt }}.

1. **Critical damping.** The characteristic equation $J\lambda^2 + c\lambda + k_t = 0$ has a
   double root when its discriminant vanishes, $c^2 = 4 k_t J$:
   $$c_{cr} = 2\sqrt{k_t J},$$
   that is $c_{cr}$ = {{ answers.c_cr }}.
2. **Critically damped.** The double root $\lambda = -\omega_n$ gives
   $\theta = (A + B t)\,e^{-\omega_n t}$; with $\theta(0) = \theta_0$ and $\dot\theta(0) = 0$,
   $B = \omega_n\theta_0$:
   $$\theta(t) = \theta_0\,(1 + \omega_n t)\,e^{-\omega_n t}.$$
   With $\theta_0$ = {{ theta0 }} and $t_1$ = {{ t1 }}: $\theta(t_1)$ = {{ answers.theta_crit }}.
3. **Overdamped.** With $\zeta$ = {{ ratio.value }} the roots are real,
   $\lambda_{1,2} = -\omega_n\bigl(\zeta \mp \sqrt{\zeta^2 - 1}\bigr)$, and the same initial
   conditions give
   $$\theta(t) = \theta_0\,\frac{\lambda_2 e^{\lambda_1 t} - \lambda_1 e^{\lambda_2 t} }{\lambda_2 - \lambda_1},$$
   so $\theta(t_1)$ = {{ answers.theta_over }}: more damping closes the door more slowly,
   because the slow root $\lambda_1$ moves toward zero.
""",
    solve=solve,
    checks=(
        Integrated("theta_crit", _door(lambda p: 1.0), lambda p: (p.theta0, 0.0),
                   lambda p, s: p.t1, lambda t, y, p: y[0], name="integrated_critical"),
        Integrated("theta_over", _door(lambda p: p.ratio), lambda p: (p.theta0, 0.0),
                   lambda p, s: p.t1, lambda t, y, p: y[0], name="integrated_overdamped"),
        Recompute("c_cr", lambda p, s: 2 * np.sqrt(p.kt * p.J), name="critical_damping"),
    ),
    parts=(
        Numeric("c_cr", "critical damping coefficient", question=1, unit="N*m*s", points=1,
                misconceptions=(Misconception("sqrt(k J)", lambda p: np.sqrt(p.kt * p.J),
                                              "Critical damping is c_cr = 2 sqrt(k_t J) (zeta = 1)."),)),
        Numeric("theta_crit", "angle at t1, critically damped", question=2, unit="deg", points=2,
                misconceptions=(
                    Misconception("pure exponential decay", lambda p: p.theta0 * np.exp(-omega_n(p) * p.t1),
                                  "For zeta = 1, theta = (theta0 + (v0 + omega_n theta0) t) e^{-omega_n t}."),
                    Misconception("undamped", lambda p: p.theta0 * np.cos(omega_n(p) * p.t1),
                                  "The damper is there: use the critically damped response."),
                )),
        Numeric("theta_over", "angle at t1, overdamped", question=3, unit="deg", points=2,
                misconceptions=(Misconception("critically damped again",
                                              lambda p: vibrations.free_response(p.t1, p.theta0, 0.0, omega_n(p), 1.0),
                                              "zeta > 1: the response is the sum of two decaying exponentials."),)),
    ),
)
