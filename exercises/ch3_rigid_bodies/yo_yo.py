"""A yo-yo unwinding from its string: work-energy balance with rotation (Section 3.2.5)."""

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric, Symbolic,
                                Uniform)
from dynagrade.mechanics import inertia, rigid_kinetics
from dynagrade.mechanics import rigid_kinematics as rk


def _moment(p):
    return inertia.inertia_tensor_disk(p.m, p.R)[2, 2]


def solve(p):
    v = rigid_kinetics.rolling_speed_after_drop(p.h, p.g, p.m, p.r, _moment(p))
    return {
        "v": v,
        "omega": rk.rolling_angular_velocity(v, p.r),
        # the string pulls like the friction on a body rolling down a vertical "incline"
        "S": rigid_kinetics.friction_for_rolling_on_incline(np.pi / 2, p.g, p.m, p.r,
                                                            _moment(p)),
    }


EXERCISE = Exercise(
    id="yo-yo-unwinding",
    title="Yo-yo unwinding from its string",
    source="Section 3.2.5",
    topics=("work-energy balance", "kinetic energy of a rigid body", "rolling constraint"),
    params=(
        Uniform("m", 0.05, 0.5, step=0.01, unit="kg", symbol="m"),
        Uniform("R", 3.0, 6.0, step=0.1, unit="cm", symbol="R"),
        Uniform("r", 0.8, 2.0, step=0.05, unit="cm", symbol="r"),
        Uniform("h", 0.2, 1.5, step=0.05, unit="m", symbol="h"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("the axle is thick enough that the string tension differs from the weight",
                   lambda p: p.r >= 0.22 * p.R),
    ),
    statement=r"""
A yo-yo is modelled as a homogeneous disk of mass $m$ = {{ m }} and radius $R$ = {{ R }};
its string is wound on a thin axle of radius $r$ = {{ r }} and the upper end of the string
is held fixed. The yo-yo is released from rest with the string vertical ($g$ = {{ g }}).

1. How fast does its centre move after it has dropped $h$ = {{ h }}?
2. What is then its angular speed?
3. What is the tension in the string while it unwinds?
4. Give the speed of question 1 as a formula in $g$, $h$, $R$ and $r$.
""",
    solve=solve,
    parts=(
        Numeric("v", "speed after dropping h", unit="m/s", points=2,
                misconceptions=(
                    Misconception("rotational kinetic energy forgotten",
                                  lambda p: np.sqrt(2 * p.g * p.h),
                                  "The yo-yo spins: m g h = ½ m v² + ½ I_C (v/r)²."),
                    Misconception("outer radius in the rolling condition",
                                  lambda p: rigid_kinetics.rolling_speed_after_drop(
                                      p.h, p.g, p.m, p.R, _moment(p)),
                                  "The string unwinds from the axle: v = ω r."),
                )),
        Numeric("omega", "angular speed", unit="rad/s", points=1),
        Numeric("S", "string tension", unit="N", points=1,
                misconceptions=(
                    Misconception("tension equal to the weight", lambda p: p.m * p.g,
                                  "The yo-yo accelerates downward: S < m g."),
                )),
        Symbolic("v_formula", "speed as a formula", points=1,
                 expected="sqrt(2*g*h/(1 + R^2/(2*r^2)))",
                 variables=("g", "h", "R", "r"),
                 equals="v",
                 misconceptions=(
                     Misconception("rotational kinetic energy forgotten", "sqrt(2*g*h)",
                                   "The yo-yo spins as well."),
                 )),
    ),
)
