"""A particle coasting against linear (Stokes) drag a = -k v (Example 1.2)."""

import numpy as np

from dynagrade.exercise import (Constraint, Exercise, Misconception, Numeric, Symbolic,
                                Uniform)
from dynagrade.exercise.checks import Integrated
from dynagrade.mechanics import kinematics


def solve(p):
    v1 = p.fraction * p.v0
    return {
        "v_t": kinematics.linear_drag_velocity(p.t, p.v0, p.k),
        "t_1": kinematics.linear_drag_time_to_speed(p.v0, v1, p.k),
        "x_1": kinematics.linear_drag_distance_to_speed(p.v0, v1, p.k),
        "x_total": kinematics.linear_drag_coasting_distance(p.v0, p.k),
    }


def _drag(t, y, p):
    """Linear drag alone, eq. (1.104) with eq. (1.13): x'' = -k x'."""
    return (y[1], -p.k * y[1])


def _start(p):
    return (0.0, p.v0)


def _slowed(t, y, p):
    """Zero when the speed has fallen to v1 = fraction v0."""
    return y[1] - p.fraction * p.v0


def _ten_decay_times(p, solved):
    """Longer than the slowing to v1 >= 0.2 v0 takes (ln 5 decay times)."""
    return 10 / p.k


EXERCISE = Exercise(
    id="linear-drag-coasting",
    title="Coasting against linear drag",
    source="Example 1.2",
    topics=("kinematics", "separation of variables", "viscous drag"),
    params=(
        Uniform("v0", 2.0, 20.0, step=0.5, unit="m/s", symbol="v_0"),
        Uniform("k", 0.1, 2.0, step=0.05, unit="1/s", symbol="k"),
        Uniform("t", 0.2, 4.0, step=0.1, unit="s", symbol="t"),
        Uniform("fraction", 0.2, 0.8, step=0.05, symbol="v_1/v_0"),
    ),
    constraints=(
        # v0 (1 - k t), the first-order slip, must be clearly off (and not negative)
        Constraint("k t lies between 0.15 and 2.5, where exp(-k t) and 1 - k t differ",
                   lambda p: 0.15 <= p.k * p.t <= 2.5),
    ),
    statement="""
A particle moves along a straight line through a viscous medium that decelerates it by
$a = -k v$ with $k$ = {{ k }}. At $t = 0$ its speed is $v_0$ = {{ v0 }}; no other force acts.

1. What is its speed at $t$ = {{ t }}?
2. When has its speed dropped to $v_1 = {{ fraction.value }}\\,v_0$?
3. How far has it travelled by then?
4. How far does it travel in total before it (asymptotically) comes to rest?
5. Write $v(t)$ as a formula in $v_0$, $k$ and $t$.
""",
    solution=r"""
The acceleration depends on the velocity, $\dot v = -kv$: separate the variables and
integrate (Example 1.2).

1. **Speed.** $\int_{v_0}^{v} \mathrm dv/v = -\int_0^t k\,\mathrm dt$ gives
   $\ln(v/v_0) = -kt$, i.e. $v(t) = v_0 e^{-kt}$ (eq. (1.14)). With $v_0$ = {{ v0 }},
   $k$ = {{ k }} and $t$ = {{ t }}: $v$ = {{ answers.v_t }}.
2. **Time to $v_1$.** Solve $v_1 = v_0 e^{-kt_1}$ for the time:
   $t_1 = \ln(v_0/v_1)/k$ with $v_1/v_0$ = {{ fraction.value }}: $t_1$ = {{ answers.t_1 }}.
3. **Distance to $v_1$.** Write the acceleration as a function of position,
   $\dot v = v\,\mathrm dv/\mathrm dx = -kv$, so $\mathrm dv/\mathrm dx = -k$: the speed falls
   linearly with distance, $x = (v_0 - v_1)/k$ = {{ answers.x_1 }}.
4. **Total distance.** Let $v_1 \to 0$: $x_\infty = v_0/k$ = {{ answers.x_total }} — finite,
   although the particle never quite stops.
5. **Formula.** $v(t)$ = `{{ answers.v_formula }}`.
""",
    solve=solve,
    checks=(
        Integrated("v_t", _drag, _start, lambda p, s: p.t, lambda t, y, p: y[1],
                   name="integrated_speed"),
        Integrated("t_1", _drag, _start, _ten_decay_times, lambda t, y, p: t,
                   name="integrated_time_to_v1", event=_slowed, direction=-1),
        Integrated("x_1", _drag, _start, _ten_decay_times, lambda t, y, p: y[0],
                   name="integrated_distance_to_v1", event=_slowed, direction=-1),
        # after many decay times the distance is within e^-40 of the total
        Integrated("x_total", _drag, _start, lambda p, s: 40 / p.k, lambda t, y, p: y[0],
                   name="integrated_coasting"),
    ),
    parts=(
        Numeric("v_t", "speed at t", question=1, unit="m/s", points=1,
                misconceptions=(
                    Misconception("constant deceleration k v0",
                                  lambda p: p.v0 * (1 - p.k * p.t),
                                  "The deceleration shrinks with the speed: separate variables, "
                                  "dv/v = -k dt, eq. (1.14)."),
                )),
        Numeric("t_1", "time to reach v1", question=2, unit="s", points=1,
                misconceptions=(
                    Misconception("constant deceleration k v0",
                                  lambda p: (1 - p.fraction) / p.k,
                                  "Use v(t) = v0 exp(-k t), so t = ln(v0/v1)/k."),
                )),
        Numeric("x_1", "distance to reach v1", question=3, unit="m", points=2,
                misconceptions=(
                    Misconception("distance at the initial speed",
                                  lambda p: p.v0 * np.log(1 / p.fraction) / p.k,
                                  "The speed drops on the way: with a = v dv/dx = -k v, "
                                  "dx = -dv/k, eq. (1.17)."),
                )),
        Numeric("x_total", "total distance", question=4, unit="m", points=1),
        Symbolic("v_formula", "v(t) as a formula", question=5, points=1, expected="v0*exp(-k*t)",
                 variables=("v0", "k", "t"),
                 equals="v_t",
                 misconceptions=(
                     Misconception("constant deceleration", "v0*(1 - k*t)",
                                   "The deceleration is proportional to v: the speed decays "
                                   "exponentially."),
                 )),
    ),
)
