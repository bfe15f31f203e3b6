"""Steady precession of a heavy symmetric top: slow and fast precession, the fast-top
approximation and the smallest spin (Section 3.5.2)."""

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric,
                                Uniform, apart)
from dynagrade.exercise.checks import Balance, Recompute
from dynagrade.mechanics import gyro


def _rates(p):
    return gyro.steady_precession_rates(p.m, p.g, p.l, p.I1, p.I3, p.w3, p.theta)


def _rates_apart(p):
    """The smallest spin and the fast precession rate differ as numbers; below the
    smallest spin there is no steady precession (another constraint refuses it)."""
    w_min = gyro.minimum_spin_for_steady_precession(p.m, p.g, p.l, p.I1, p.I3, p.theta)
    return p.w3 <= w_min or apart(w_min, _rates(p).fast)


def _fast_top(p):
    return gyro.fast_top_precession_rate(p.m, p.g, p.l, p.I3, p.w3)


def solve(p):
    return {
        "w_min": gyro.minimum_spin_for_steady_precession(p.m, p.g, p.l, p.I1, p.I3, p.theta),
        "psi_slow": _rates(p).slow,
        "psi_fast": _rates(p).fast,
        "psi_approx": _fast_top(p),
    }


def _gravity_torque(p, solved):
    return p.m * p.g * p.l


def _gyroscopic(rate):
    """The torque steady precession at ``rate`` needs about the nodal axis, per
    sin(theta) (Section 3.5.2): psi' (I3 omega3 - I1 psi' cos(theta))."""
    return lambda p, s: s[rate] * (p.I3 * p.w3 - p.I1 * s[rate] * np.cos(p.theta))


def _roots(p):
    """The steady precession rates solve I1 cos(theta) psi'^2 - I3 w3 psi' + m g l = 0."""
    a, b, c = p.I1 * np.cos(p.theta), -p.I3 * p.w3, p.m * p.g * p.l
    root = np.sqrt(b * b - 4 * a * c)
    return sorted(((-b - root) / (2 * a), (-b + root) / (2 * a)))


EXERCISE = Exercise(
    id="heavy-top-steady-precession",
    title="Steady precession of a heavy top",
    source="Section 3.5.2",
    topics=("spinning tops", "Euler angles", "steady precession", "fast-top approximation"),
    params=(
        Uniform("m", 0.1, 1.0, step=0.05, unit="kg", symbol="m"),
        Uniform("l", 2, 8, step=0.5, unit="cm", symbol="l"),
        Uniform("I1", 2e-4, 2e-3, step=1e-4, unit="kg*m^2", symbol="I_1"),
        Uniform("I3", 1e-4, 1e-3, step=5e-5, unit="kg*m^2", symbol="I_3"),
        Uniform("w3", 20, 300, step=5, unit="rad/s", symbol=r"\omega_3"),
        Uniform("theta", 10, 70, step=5, unit="deg", symbol=r"\theta"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        # two answers that agree as numbers can be swapped and score (verify's variety rule)
        Constraint("the smallest spin and the fast precession rate differ", _rates_apart),
        Constraint("the spin is between 1.2 and 3 times the smallest for steady precession",
                   lambda p: 1.2 < p.w3 / gyro.minimum_spin_for_steady_precession(
                       p.m, p.g, p.l, p.I1, p.I3, p.theta) < 3.0),
        Constraint("the transverse moment about the tip exceeds the axial one", lambda p: p.I1 > p.I3),
    ),
    statement=r"""
A symmetric top of mass $m$ = {{ m }} spins on a fixed tip O; its centre of mass lies on the
symmetry axis at $l$ = {{ l }} from O. About O its transverse moment of inertia is
$I_1$ = {{ I1 }} and its axial one $I_3$ = {{ I3 }}. The axis is tilted by
$\theta$ = {{ theta }} from the vertical and the axial component of the angular velocity is
$\omega_3$ = {{ w3 }} ($g$ = {{ g }}).

1. What is the smallest $\omega_3$ for which steady precession at this tilt is possible?
2. What is the rate of the slow steady precession?
3. What is the rate of the fast steady precession?
4. What precession rate does the fast-top approximation give?
""",
    solution=r"""
In steady precession the tilt $\theta$, the precession rate $\dot\psi$ and the axial rate
$\omega_3$ stay constant, and the balance of angular momentum about the fixed tip O reduces
to one equation (heavy symmetric top, Section 3.5.2):
$$m g l = \dot\psi\,\bigl(I_3\,\omega_3 - I_1\,\dot\psi\cos\theta\bigr),
\qquad\text{i.e.}\qquad I_1\cos\theta\;\dot\psi^2 - I_3\,\omega_3\,\dot\psi + m g l = 0 .$$
Here $m$ = {{ m }}, $l$ = {{ l }}, $I_1$ = {{ I1 }}, $I_3$ = {{ I3 }},
$\theta$ = {{ theta }}, $\omega_3$ = {{ w3 }} and $g$ = {{ g }}.

1. **Smallest spin.** The quadratic in $\dot\psi$ has real roots only if its discriminant
   is not negative, $I_3^2\,\omega_3^2 \ge 4 I_1 m g l\cos\theta$:
   $$\omega_{3,\min} = \frac{\sqrt{4 I_1 m g l\cos\theta} }{I_3},$$
   that is $\omega_{3,\min}$ = {{ answers.w_min }}.
2. **Slow precession.** The smaller root,
   $$\dot\psi_{\mathrm{slow} } = \frac{I_3\,\omega_3 - \sqrt{I_3^2\,\omega_3^2 - 4 I_1 m g l\cos\theta} }{2 I_1\cos\theta},$$
   gives $\dot\psi_{\mathrm{slow} }$ = {{ answers.psi_slow }}.
3. **Fast precession.** The larger root (plus sign in front of the square root) gives
   $\dot\psi_{\mathrm{fast} }$ = {{ answers.psi_fast }}.
4. **Fast-top approximation.** For a fast top the term $I_1\dot\psi^2\cos\theta$ is small
   beside $I_3\,\omega_3\,\dot\psi$; dropping it leaves $m g l = \dot\psi\, I_3\,\omega_3$:
   $$\dot\psi \approx \frac{m g l}{I_3\,\omega_3},$$
   which gives {{ answers.psi_approx }}, close to the slow root of step 2 and independent
   of the tilt.
""",
    solve=solve,
    checks=(
        Balance("torque of the slow precession", _gravity_torque, _gyroscopic("psi_slow"),
                name="slow_precession_balance"),
        Balance("torque of the fast precession", _gravity_torque, _gyroscopic("psi_fast"),
                name="fast_precession_balance"),
        # the two rates meet where the quadratic's discriminant vanishes
        Recompute("w_min", lambda p, s: np.sqrt(4 * p.I1 * p.m * p.g * p.l * np.cos(p.theta)) / p.I3,
                  name="double_root"),
        Recompute("psi_approx", lambda p, s: p.m * p.g * p.l / (p.I3 * p.w3), name="fast_top"),
        # which root is which: the slow one is the smaller, by the quadratic formula
        Recompute("psi_slow", lambda p, s: _roots(p)[0], name="smaller_root"),
        Recompute("psi_fast", lambda p, s: _roots(p)[1], name="larger_root"),
    ),
    parts=(
        Numeric("w_min", "smallest axial spin", question=1, unit="rad/s", points=1),
        Numeric("psi_slow", "slow precession rate", question=2, unit="rad/s", points=2,
                misconceptions=(
                    Misconception("fast-top approximation", _fast_top,
                                  "Near the smallest spin the approximation m g l/(I3 ω3) is "
                                  "poor: solve the quadratic I1 cos θ ψ'² − I3 ω3 ψ' + m g l = 0."),
                )),
        Numeric("psi_fast", "fast precession rate", question=3, unit="rad/s", points=2,
                misconceptions=(
                    Misconception("fast-top approximation", _fast_top,
                                  "The fast root is near I3 ω3/(I1 cos θ)."),
                )),
        Numeric("psi_approx", "fast-top approximation", question=4, unit="rad/s", points=1),
    ),
)
