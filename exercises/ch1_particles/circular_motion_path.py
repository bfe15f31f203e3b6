"""A car speeding up on a circular track, described in the space-curve frame
(Example 1.6, eqs. 1.51 and 1.54)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.checks import Recompute
from dynagrade.mechanics import kinematics


@per_draw
def solve(p):
    v = kinematics.speed_at_constant_acceleration(p.t, p.v0, p.at)      # s'' = a_t constant
    s = kinematics.distance_at_constant_acceleration(p.t, p.v0, p.at)
    a_n = kinematics.path_centripetal_acceleration(v, p.R)
    return {
        "v": v,
        "a_n": a_n,
        "a_abs": float(kinematics.acceleration_magnitude(p.at, a_n)),
        "phi": kinematics.angle_from_arc_length(s, p.R),
        "s": s,
    }


def _speed_from_distance(p, solved):
    """Constant path acceleration s'' = a_t: v^2 = v0^2 + 2 a_t s (eq. (1.42) integrated
    in s rather than t)."""
    return np.sqrt(p.v0**2 + 2 * p.at * solved["s"])


def _total_acceleration(p, solved):
    """eq. (1.51): a = s'' e_t + (s'^2 / rho) e_n, its magnitude with v from eq. (1.42)."""
    v = p.v0 + p.at * p.t
    return np.hypot(p.at, v**2 / p.R)


EXERCISE = Exercise(
    id="circular-motion-path-frame",
    title="Speeding up on a circle: tangential and normal acceleration",
    source="Example 1.6",
    topics=("space curves", "tangential and normal acceleration", "circular motion"),
    params=(
        Uniform("R", 20, 200, step=5, unit="m", symbol="R"),
        Uniform("v0", 2.0, 15.0, step=0.5, unit="m/s", symbol="v_0"),
        Uniform("at", 0.5, 3.0, step=0.1, unit="m/s^2", symbol=r"\ddot s"),
        Uniform("t", 2.0, 10.0, step=0.5, unit="s", symbol="t"),
    ),
    constraints=(
        Constraint("the normal part is at least 20 % of the tangential part and vice versa",
                   lambda p: 0.2 < solve(p)["a_n"] / p.at < 5),
        Constraint("the car turns less than one lap", lambda p: solve(p)["phi"] < 2 * np.pi),
    ),
    statement="""
A car drives on a circular track of radius $R$ = {{ R }}. At $t = 0$ its speed is
$v_0$ = {{ v0 }}, and it speeds up at the constant rate $\\ddot s$ = {{ at }}.

At $t$ = {{ t }}:

1. what is its speed?
2. what is the normal (centripetal) component $v^2/\\rho$ of its acceleration?
3. what is the magnitude of its acceleration?
4. through what angle $\\varphi$ has it turned since $t = 0$ (in rad)?
""",
    solution=r"""
Describe the motion along the path: arc length $s(t)$, tangent $e_t$ and normal $e_n$
towards the centre. The acceleration is $a = \ddot s\, e_t + \frac{v^2}{\rho} e_n$
(eq. (1.51)), and on a circle $\rho = R$ and $s = R\varphi$ (Example 1.6).

1. **Speed.** $\ddot s$ is constant, so $v(t) = v_0 + \ddot s\, t$; with $v_0$ = {{ v0 }},
   $\ddot s$ = {{ at }} and $t$ = {{ t }}: $v$ = {{ answers.v }}.
2. **Normal acceleration.** $a_n = v^2/R$ with the speed *at time $t$* and $R$ = {{ R }}:
   $a_n$ = {{ answers.a_n }}.
3. **Magnitude.** $e_t$ and $e_n$ are perpendicular, so
   $|a| = \sqrt{\ddot s^2 + (v^2/R)^2}$ = {{ answers.a_abs }}.
4. **Angle turned.** The distance driven is $s = v_0 t + \tfrac{1}{2} \ddot s\, t^2$
   = {{ si.s }} m, and $\varphi = s/R$ = {{ answers.phi }}.
""",
    solve=solve,
    checks=(
        Recompute("v", _speed_from_distance, name="speed_from_distance"),
        Recompute("a_abs", _total_acceleration, name="path_acceleration"),
        Recompute("phi", lambda p, s: (p.v0 * p.t + p.at * p.t**2 / 2) / p.R,
                  name="arc_length_angle"),
    ),
    parts=(
        Numeric("v", "speed", question=1, unit="m/s", points=1),
        Numeric("a_n", "normal acceleration", question=2, unit="m/s^2", points=2,
                misconceptions=(
                    Misconception("initial speed used", lambda p: p.v0**2 / p.R,
                                  "Use the speed at time t: v = v0 + s̈ t."),
                )),
        Numeric("a_abs", "magnitude of the acceleration", question=3, unit="m/s^2", points=1,
                misconceptions=(
                    Misconception("components added",
                                  lambda p: p.at + (p.v0 + p.at * p.t) ** 2 / p.R,
                                  "e_t and e_n are perpendicular: |a| = √(s̈² + (v²/ρ)²), eq. (1.51)."),
                    Misconception("normal part only",
                                  lambda p: (p.v0 + p.at * p.t) ** 2 / p.R,
                                  "The car also speeds up along e_t."),
                )),
        Numeric("phi", "angle turned", question=4, unit="rad", points=1,
                misconceptions=(
                    Misconception("constant speed", lambda p: p.v0 * p.t / p.R,
                                  "s(t) = v0 t + s̈ t²/2, and φ = s/R, eq. (1.53)."),
                )),
    ),
)
