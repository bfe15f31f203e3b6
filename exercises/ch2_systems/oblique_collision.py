"""Oblique impact of two smooth billiard balls (Section 2.3.1)."""

import numpy as np

from dynagrade.exercise import (Constraint, Exercise, Misconception, Numeric, Uniform, Vector,
                                per_draw)
from dynagrade.mechanics import collisions


def _line_of_impact(p):
    return np.array([np.cos(p.beta), np.sin(p.beta)])


@per_draw
def _after(p):
    return collisions.velocities_after_oblique_impact(
        p.m1, p.m2, np.array([p.v, 0.0]), np.zeros(2), _line_of_impact(p), p.e)


def _central(p):
    """The wrong route: the whole velocity treated as normal to the contact."""
    return collisions.velocities_after_central_impact(p.m1, p.m2, p.v, 0.0, p.e)


def solve(p):
    after = _after(p)
    return {"v1_after": after.v1, "v2_after": after.v2,
            "speed2": float(np.linalg.norm(after.v2))}


EXERCISE = Exercise(
    id="oblique-billiard-collision",
    title="Oblique collision of two billiard balls",
    source="Section 2.3.1",
    topics=("oblique impact", "coefficient of restitution", "momentum conservation"),
    params=(
        Uniform("m1", 0.15, 0.25, step=0.01, unit="kg", symbol="m_1"),
        Uniform("m2", 0.15, 0.25, step=0.01, unit="kg", symbol="m_2"),
        Uniform("v", 1.0, 5.0, step=0.1, unit="m/s", symbol="v"),
        Uniform("beta", 15, 65, step=1, unit="deg", symbol=r"\beta"),
        Uniform("e", 0.6, 0.95, step=0.05, symbol="e"),
    ),
    constraints=(
        Constraint("ball 1 keeps a clear velocity component along e1 after the impact",
                   lambda p: abs(_after(p).v1[0]) > 0.05 * p.v),
    ),
    statement=r"""
Ball 1 ($m_1$ = {{ m1 }}) rolls with velocity $v$ = {{ v }} along $e_1$ and hits ball 2
($m_2$ = {{ m2 }}) at rest. At the instant of contact the line through both centres
(the line of impact, pointing from ball 1 to ball 2) makes the angle $\beta$ = {{ beta }}
with $e_1$, turned toward $e_2$. The balls are smooth (no friction between them) and
the coefficient of restitution is $e$ = {{ e }}. Treat the balls as particles sliding
on the table.

1. What is the velocity vector of ball 1 after the impact (components along $e_1$, $e_2$)?
2. What is the velocity vector of ball 2 after the impact?
3. What is the speed of ball 2?
""",
    solve=solve,
    parts=(
        Vector("v1_after", "velocity of ball 1 after the impact", unit="m/s", size=2, points=2,
               misconceptions=(
                   Misconception("treated as a central impact",
                                 lambda p: (_central(p).v1, 0.0),
                                 "Only the component along the line of impact changes; the "
                                 "tangential component is kept."),
               )),
        Vector("v2_after", "velocity of ball 2 after the impact", unit="m/s", size=2, points=2,
               misconceptions=(
                   Misconception("treated as a central impact",
                                 lambda p: (_central(p).v2, 0.0),
                                 "Ball 2 is pushed along the line of impact only."),
               )),
        Numeric("speed2", "speed of ball 2", unit="m/s", points=1,
                misconceptions=(
                    Misconception("treated as a central impact", lambda p: _central(p).v2,
                                  "Only the normal component v cos(β) takes part in the "
                                  "impact."),
                )),
    ),
)
