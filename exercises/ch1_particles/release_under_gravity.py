"""A stone released with a known velocity under gravity: position and velocity at a
later time (Example 1.1)."""

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric, Symbolic,
                                Uniform, Variable, Vector, per_draw)
from dynagrade.exercise.checks import Integrated
from dynagrade.exercise.checks.motions import thrown
from dynagrade.mechanics import kinematics


def _state(p):
    g = (0.0, -p.g)
    r = kinematics.release_position(p.t, (0.0, p.h0), (p.v01, p.v02), g)
    v = kinematics.release_velocity(p.t, (p.v01, p.v02), g)
    return r, v


@per_draw
def solve(p):
    r, v = _state(p)
    return {"r_t": tuple(r), "v_t": tuple(v), "x2_t": float(r[1])}


@per_draw
def _no_half(p):
    return p.h0 + p.v02 * p.t - p.g * p.t**2


def _released(p):
    """The state at release: at height h0 with the velocity (v01, v02)."""
    return (0.0, p.h0, p.v01, p.v02)


def _until_t(p, solved):
    return p.t


EXERCISE = Exercise(
    id="release-under-gravity",
    title="Release under gravity: position and velocity at time t",
    source="Example 1.1",
    topics=("kinematics", "trajectory from acceleration", "gravity"),
    params=(
        Uniform("h0", 5.0, 40.0, step=1.0, unit="m", symbol="h_0"),
        Uniform("v01", 1.0, 12.0, step=0.5, unit="m/s", symbol="v_{1}(0)"),
        Uniform("v02", 2.0, 15.0, step=0.5, unit="m/s", symbol="v_{2}(0)"),
        Uniform("t", 0.4, 2.5, step=0.1, unit="s", symbol="t"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("the stone is still in the air at time t",
                   lambda p: solve(p)["x2_t"] > 0.5),
        # the factor 1/2 in g t^2/2 must matter beyond tolerance
        Constraint("dropping the 1/2 in g t^2/2 changes the height by more than 5 %",
                   lambda p: abs(_no_half(p) - solve(p)["x2_t"]) > 0.05 * abs(solve(p)["x2_t"])),
        Constraint("the vertical velocity at t is clearly nonzero",
                   lambda p: abs(p.v02 - p.g * p.t) > 0.5),
    ),
    statement="""
A stone is released at time $t = 0$ from the point $\\boldsymbol r(0) = h_0\\,\\boldsymbol e_2$
with $h_0$ = {{ h0 }} above the ground ($x_2 = 0$), with velocity components
$v_1(0)$ = {{ v01 }} (horizontal, $\\boldsymbol e_1$) and $v_2(0)$ = {{ v02 }} (upward,
$\\boldsymbol e_2$). Gravity $g$ = {{ g }} acts in $-\\boldsymbol e_2$; neglect air drag.

1. Give the position $(x_1, x_2)$ at $t$ = {{ t }}.
2. Give the velocity $(v_1, v_2)$ at that time.
3. What is the height $x_2$ at that time?
4. Write the height $x_2(t)$ as a formula in $h_0$, $v_2(0)$ (the initial upward velocity), $g$ and $t$.
""",
    solution=r"""
The only force is gravity, so linear momentum balance gives the constant acceleration
$a = -g\,e_2$. Integrating twice in time with the initial values (Example 1.1, eqs. (1.11)
and (1.12)):
$v(t) = v(0) - gt\,e_2, \qquad r(t) = r(0) + v(0)\,t - \tfrac{1}{2} g t^2\,e_2$.
Here $r(0) = (0, h_0)$ with $h_0$ = {{ h0 }} and $v(0) = (v_1(0), v_2(0))$ with
$v_1(0)$ = {{ v01 }}, $v_2(0)$ = {{ v02 }}; $t$ = {{ t }}, $g$ = {{ g }}.

1. **Position.** $x_1 = v_1(0)\,t$ and $x_2 = h_0 + v_2(0)\,t - \tfrac{1}{2} g t^2$:
   $r$ = {{ answers.r_t }}.
2. **Velocity.** The horizontal component does not change, the vertical one decreases
   linearly: $v = (v_1(0),\ v_2(0) - gt)$ = {{ answers.v_t }}.
3. **Height.** The second component of the position: $x_2$ = {{ answers.x2_t }}.
4. **Formula.** $x_2(t)$ = `{{ answers.x2_formula }}`.
""",
    solve=solve,
    checks=(
        Integrated("r_t", thrown, _released, _until_t,
                   lambda t, y, p: (y[0], y[1]), name="integrated_position", atol=1e-9),
        Integrated("v_t", thrown, _released, _until_t,
                   lambda t, y, p: (y[2], y[3]), name="integrated_velocity", atol=1e-9),
    ),
    parts=(
        Vector("r_t", "position at t", question=1, unit="m", size=2, points=2,
               misconceptions=(
                   Misconception("no factor 1/2", lambda p: (p.v01 * p.t, _no_half(p)),
                                 "Integrating a = -g twice gives -g t²/2, eq. (1.12)."),
               )),
        Vector("v_t", "velocity at t", question=2, unit="m/s", size=2, points=2,
               misconceptions=(
                   Misconception("horizontal velocity lost",
                                 lambda p: (0.0, p.v02 - p.g * p.t),
                                 "No force acts along e1: v1 stays v1(0) (Example 1.1)."),
                   Misconception("gravity adds upward", lambda p: (p.v01, p.v02 + p.g * p.t),
                                 "Gravity points in -e2: v2 = v2(0) - g t, eq. (1.11)."),
               )),
        Numeric("x2_t", "height at t", question=3, unit="m", points=1,
                misconceptions=(
                    Misconception("no factor 1/2", _no_half,
                                  "Integrating a = -g twice gives -g t²/2, eq. (1.12)."),
                    Misconception("initial height forgotten",
                                  lambda p: p.v02 * p.t - p.g * p.t**2 / 2,
                                  "Add the initial position r(0), eq. (1.12)."),
                )),
        Symbolic("x2_formula", "height as a formula", question=4, points=1,
                 expected="h0 + v02*t - g*t^2/2",
                 variables={"h0": None, "v02": Variable(aliases=("v_{02}",)), "g": None,
                            "t": None},
                 equals="x2_t",
                 misconceptions=(
                     Misconception("no factor 1/2", "h0 + v02*t - g*t^2",
                                   "Integrating a = -g twice gives -g t²/2."),
                 )),
    ),
)
