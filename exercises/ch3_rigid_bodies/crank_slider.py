"""Crank-slider mechanism: slider velocity and angular velocity of the connecting rod
(Section 3.1.1)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform
from dynagrade.mechanics import rigid_kinematics as rk


def _crank_rate(p):
    """Angular velocity of the crank from its speed in revolutions per time."""
    return 2 * np.pi * p.n


def solve(p):
    w = _crank_rate(p)
    return {
        "v_B": rk.slider_velocity(p.r, p.l, p.theta, w),
        "omega_rod": abs(rk.connecting_rod_angular_velocity(p.r, p.l, p.theta, w)),
    }


def _pin_only(p):
    """The wrong route: the slider moves with the horizontal velocity of the crank pin."""
    return -p.r * _crank_rate(p) * np.sin(p.theta)


def _distinct(a, b):
    return abs(a - b) > 0.04 * max(abs(a), abs(b))


EXERCISE = Exercise(
    id="crank-slider-velocity",
    title="Crank-slider mechanism",
    source="Section 3.1.1",
    topics=("rigid-body kinematics in 2D", "velocity transfer", "mechanisms"),
    params=(
        Uniform("r", 0.03, 0.15, step=0.005, unit="m", symbol="r"),
        Uniform("l", 0.12, 0.6, step=0.01, unit="m", symbol="l"),
        Uniform("theta", 10, 170, step=5, unit="deg", symbol=r"\theta"),
        Uniform("n", 300, 3000, step=100, unit="1/min", symbol="n"),
    ),
    constraints=(
        Constraint("the rod is at least 2.5 times the crank", lambda p: p.l >= 2.5 * p.r),
        Constraint("the slider is clearly moving (theta away from the dead centres)",
                   lambda p: np.sin(p.theta) > 0.2),
        Constraint("the rod's own motion matters (theta away from 90 deg)",
                   lambda p: p.l >= 2.5 * p.r
                   and _distinct(solve(p)["v_B"], _pin_only(p))
                   and _distinct(solve(p)["omega_rod"], p.r * _crank_rate(p) / p.l)),
    ),
    statement=r"""
In a crank-slider mechanism the crank OA (length $r$ = {{ r }}) turns counter-clockwise about
the fixed pivot O at $n$ = {{ n }}. The connecting rod AB (length $l$ = {{ l }}) drives the
slider B along the horizontal line through O. At the instant considered the crank makes
the angle $\theta$ = {{ theta }} with the line OB (measured from OB, toward the side of A).

1. What is the velocity of the slider (positive away from O)?
2. What is the angular speed of the connecting rod?
""",
    solve=solve,
    parts=(
        Numeric("v_B", "slider velocity", unit="m/s", points=2,
                misconceptions=(
                    Misconception("horizontal velocity of the crank pin", _pin_only,
                                  "The rod turns as well: transfer the velocity from A to B "
                                  "with v_B = v_A + ω_AB × r_AB."),
                )),
        Numeric("omega_rod", "angular speed of the rod", unit="rad/s", points=2,
                misconceptions=(
                    Misconception("rod turning with r omega / l",
                                  lambda p: p.r * _crank_rate(p) / p.l,
                                  "Only the component of v_A normal to the rod turns it, and "
                                  "B's velocity is along the slider line."),
                )),
    ),
)
