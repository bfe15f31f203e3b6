"""A particle on a circle with a prescribed angle phi(t) = phi0 + c t^2: velocity and
acceleration vectors (Example 1.3)."""

import numpy as np

from dynagrade.exercise import (Constraint, Exercise, Misconception, Numeric, Uniform, Vector,
                                per_draw)
from dynagrade.exercise.checks import Recompute
from dynagrade.mechanics import kinematics


def _angles(p):
    return p.c * p.t**2, 2 * p.c * p.t, 2 * p.c


@per_draw
def solve(p):
    phi, phidot, phiddot = _angles(p)
    a = kinematics.circular_acceleration(p.r, phi, phidot, phiddot)
    return {
        "v": tuple(kinematics.circular_velocity(p.r, phi, phidot)),
        "speed": kinematics.circular_speed(p.r, phidot),
        "a": tuple(a),
        "a_abs": float(np.linalg.norm(a)),
        "phi": phi, "phidot": phidot, "phiddot": phiddot,
    }


def _centripetal_only(p):
    phi, phidot, _ = _angles(p)
    return tuple(kinematics.circular_acceleration(p.r, phi, phidot, 0.0))


def _cartesian(p, radial, tangential):
    """e1, e2 components of radial e_r + tangential e_phi at phi = c t^2, eq. (1.27)."""
    phi = p.c * p.t**2
    return (radial * np.cos(phi) - tangential * np.sin(phi),
            radial * np.sin(phi) + tangential * np.cos(phi))


def _acceleration_magnitude(p, solved):
    """eq. (1.20) with phi = c t^2: normal r phi'^2 and tangential r phi'' components."""
    return p.r * np.hypot((2 * p.c * p.t) ** 2, 2 * p.c)


EXERCISE = Exercise(
    id="circular-trajectory",
    title="Particle on a circular trajectory",
    source="Example 1.3",
    topics=("kinematics", "circular motion", "centripetal acceleration"),
    params=(
        Uniform("r", 0.5, 3.0, step=0.1, unit="m", symbol="r"),
        Uniform("c", 0.2, 2.0, step=0.05, unit="rad/s^2", symbol="c"),
        Uniform("t", 0.5, 2.0, step=0.05, unit="s", symbol="t"),
    ),
    constraints=(
        Constraint("the angular velocity is not close to 1 rad/s (where forgetting it is harmless)",
                   lambda p: abs(2 * p.c * p.t - 1.0) > 0.1),
        Constraint("both acceleration parts matter: 0.2 < phi'^2/phi'' < 5",
                   lambda p: 0.2 < (2 * p.c * p.t) ** 2 / (2 * p.c) < 5),
        Constraint("no velocity or acceleration component is close to zero",
                   lambda p: min(abs(x) for x in solve(p)["v"] + solve(p)["a"])
                   > 0.08 * solve(p)["a_abs"]),
    ),
    statement="""
A particle on a string of fixed length $r$ = {{ r }} moves on a circle about the origin in
the $x_1$-$x_2$ plane. Its angle from the $x_1$-axis is $\\varphi(t) = c\\,t^2$ with
$c$ = {{ c }}.

At $t$ = {{ t }}:

1. give its velocity $(v_1, v_2)$ in Cartesian components;
2. its speed;
3. its acceleration $(a_1, a_2)$ in Cartesian components;
4. the magnitude of its acceleration.
""",
    solution=r"""
On a circle of fixed radius $r$ the position is $r(\cos\varphi, \sin\varphi)$ (eq. (1.18));
differentiating once and twice in time gives velocity and acceleration (eqs. (1.19), (1.20)).
First the angle and its rates at $t$ = {{ t }}, with $c$ = {{ c }}:
$\varphi = c t^2$ = {{ si.phi }} rad, $\dot\varphi = 2ct$ = {{ si.phidot }} rad/s,
$\ddot\varphi = 2c$ = {{ si.phiddot }} rad/s².

1. **Velocity.** Eq. (1.19): $v = r\dot\varphi\,(-\sin\varphi, \cos\varphi)$; with
   $r$ = {{ r }}: $v$ = {{ answers.v }}.
2. **Speed.** $|v| = r\dot\varphi$ = {{ answers.speed }}.
3. **Acceleration.** Eq. (1.20):
   $a = -r\dot\varphi^2(\cos\varphi, \sin\varphi) + r\ddot\varphi\,(-\sin\varphi, \cos\varphi)$
   — a centripetal part and, because $\ddot\varphi \neq 0$, a tangential part:
   $a$ = {{ answers.a }}.
4. **Magnitude.** The two parts are perpendicular, so
   $|a| = r\sqrt{\dot\varphi^4 + \ddot\varphi^2}$ = {{ answers.a_abs }}.
""",
    solve=solve,
    checks=(
        Recompute("a_abs", _acceleration_magnitude, name="polar_components"),
        Recompute("speed", lambda p, s: p.r * 2 * p.c * p.t, name="speed_eq_1_19"),
        # eqs. (1.19) and (1.20) in Cartesian components with phi = c t^2
        Recompute("v", lambda p, s: _cartesian(p, 0.0, 2 * p.c * p.t * p.r), name="velocity_eq_1_19",
                  atol=1e-12),
        Recompute("a", lambda p, s: _cartesian(p, -p.r * (2 * p.c * p.t) ** 2, 2 * p.c * p.r),
                  name="acceleration_eq_1_20", atol=1e-12),
    ),
    parts=(
        Vector("v", "velocity", question=1, unit="m/s", size=2, points=2,
               misconceptions=(
                   Misconception("angle and rate mixed up",
                                 lambda p: (-p.r * np.sin(p.c * p.t**2), p.r * np.cos(p.c * p.t**2)),
                                 "v = r φ̇ (−sin φ, cos φ): do not forget the factor φ̇, eq. (1.19)."),
               )),
        Numeric("speed", "speed", question=2, unit="m/s", points=1),
        Vector("a", "acceleration", question=3, unit="m/s^2", size=2, points=2,
               misconceptions=(
                   Misconception("tangential part forgotten", _centripetal_only,
                                 "φ̈ ≠ 0: the acceleration also has r φ̈ along e_φ, eq. (1.20)."),
               )),
        Numeric("a_abs", "magnitude of the acceleration", question=4, unit="m/s^2", points=1,
                misconceptions=(
                    Misconception("centripetal part only",
                                  lambda p: p.r * (2 * p.c * p.t) ** 2,
                                  "Add the tangential part r φ̈ (at right angles)."),
                )),
    ),
)
