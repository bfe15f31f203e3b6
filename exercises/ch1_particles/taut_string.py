"""A particle whirled on a taut, inextensible string with a known angular velocity and
angular acceleration: speed and acceleration in polar components (Example 1.5)."""

import numpy as np

from dynagrade.exercise import (Constraint, Exercise, Misconception, Numeric, Symbolic,
                                Uniform, apart, per_draw)
from dynagrade.exercise.checks import Recompute
from dynagrade.mechanics import kinematics


@per_draw
def solve(p):
    v_r, v_phi = kinematics.polar_velocity(p.l, 0.0, p.omega)
    a_r, a_phi = kinematics.polar_acceleration(p.l, 0.0, 0.0, p.omega, p.alpha)
    return {"v": float(np.hypot(v_r, v_phi)), "a_r": a_r, "a_phi": a_phi,
            "a_abs": float(np.hypot(a_r, a_phi))}


EXERCISE = Exercise(
    id="taut-string-whirl",
    title="Particle on a taut string: speed and acceleration",
    source="Example 1.5",
    topics=("polar coordinates", "circular motion", "centripetal acceleration"),
    params=(
        Uniform("l", 0.3, 2.0, step=0.05, unit="m", symbol="l"),
        Uniform("omega", 1.5, 8.0, step=0.1, unit="rad/s", symbol=r"\omega"),
        Uniform("alpha", 0.5, 20.0, step=0.5, unit="rad/s^2", symbol=r"\dot\omega"),
    ),
    constraints=(
        # two answers that agree as numbers can be swapped and score (verify's variety rule)
        Constraint("the speed and the tangential acceleration differ as numbers",
                   lambda p: apart(solve(p)["v"], solve(p)["a_phi"])),
        Constraint("the angular velocity is not near 1 rad/s, where omega and omega^2 agree",
                   lambda p: abs(p.omega - 1.0) > 0.2),
        Constraint("the tangential part changes |a| by at least 5 %",
                   lambda p: solve(p)["a_abs"] > 1.05 * p.l * p.omega**2),
    ),
    statement="""
A particle on a taut, inextensible string of length $l$ = {{ l }} circles about a fixed
point O in a plane. At the instant considered the string turns at $\\omega = \\dot\\varphi$
= {{ omega }} and speeds up at $\\dot\\omega = \\ddot\\varphi$ = {{ alpha }}.

1. What is the particle's speed?
2. What is the radial component $a_r$ of its acceleration ($\\boldsymbol e_r$ points outward)?
3. What is the circumferential component $a_\\varphi$?
4. What is the magnitude of the acceleration?
5. Write $a_r$ as a formula in $l$ and $\\omega$.
""",
    solution=r"""
The string is inextensible, so in polar coordinates about O the radius is fixed, $r = l$,
$\dot r = \ddot r = 0$. The polar components of velocity and acceleration (eqs. (1.31) and
(1.33)) reduce to (eq. (1.36), Example 1.5)
$v = l\dot\varphi\,e_\varphi, \qquad a = -l\dot\varphi^2\,e_r + l\ddot\varphi\,e_\varphi$.
Here $l$ = {{ l }}, $\dot\varphi = \omega$ = {{ omega }} and $\ddot\varphi = \dot\omega$ = {{ alpha }}.

1. **Speed.** $|v| = l\omega$ = {{ answers.v }}.
2. **Radial acceleration.** $a_r = \ddot r - r\dot\varphi^2 = -l\omega^2$ = {{ answers.a_r }};
   negative: the centripetal acceleration points towards O.
3. **Circumferential acceleration.** $a_\varphi = 2\dot r\dot\varphi + r\ddot\varphi = l\dot\omega$
   = {{ answers.a_phi }}.
4. **Magnitude.** The components are perpendicular:
   $|a| = \sqrt{a_r^2 + a_\varphi^2} = l\sqrt{\omega^4 + \dot\omega^2}$ = {{ answers.a_abs }}.
5. **Formula.** $a_r$ = `{{ answers.a_r_formula }}`.
""",
    solve=solve,
    checks=(
        # eq. (1.36): v = l phi', a = -l phi'^2 e_r + l phi'' e_phi
        Recompute("a_r", lambda p, s: -p.l * p.omega**2, name="centripetal_eq_1_36"),
        Recompute("a_phi", lambda p, s: p.l * p.alpha, name="tangential_eq_1_36"),
        Recompute("v", lambda p, s: p.l * p.omega, name="speed_eq_1_36"),
    ),
    parts=(
        Numeric("v", "speed", question=1, unit="m/s", points=1),
        Numeric("a_r", "radial acceleration", question=2, unit="m/s^2", points=2,
                misconceptions=(
                    Misconception("sign: outward", lambda p: p.l * p.omega**2,
                                  "The centripetal acceleration points inward: a_r = −l φ̇², "
                                  "eq. (1.36)."),
                    Misconception("omega not squared", lambda p: -p.l * p.omega,
                                  "a_r = r̈ − r φ̇² with r̈ = 0, eq. (1.33)."),
                )),
        Numeric("a_phi", "circumferential acceleration", question=3, unit="m/s^2", points=1,
                misconceptions=(
                    Misconception("Coriolis-like term added", lambda p: 2 * p.l * p.alpha,
                                  "With r = l constant, ṙ = 0: a_φ = l φ̈ only."),
                )),
        Numeric("a_abs", "magnitude of the acceleration", question=4, unit="m/s^2", points=1,
                misconceptions=(
                    Misconception("centripetal part only", lambda p: p.l * p.omega**2,
                                  "Combine both components: |a| = l √(φ̇⁴ + φ̈²)."),
                )),
        Symbolic("a_r_formula", "a_r as a formula", question=5, points=1, expected="-l*omega^2",
                 variables=("l", "omega"),
                 equals="a_r",
                 misconceptions=(
                     Misconception("sign: outward", "l*omega^2",
                                   "e_r points outward; the acceleration points inward."),
                 )),
    ),
)
