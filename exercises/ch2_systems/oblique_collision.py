"""Oblique impact of two smooth billiard balls (Section 2.3.1)."""

import numpy as np

from dynagrade.exercise import (Constraint, Exercise, Misconception, Numeric, Uniform, Vector,
                                per_draw)
from dynagrade.exercise.checks import Balance
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
    n = _line_of_impact(p)
    return {"v1_after": after.v1, "v2_after": after.v2,
            "speed2": float(np.linalg.norm(after.v2)),
            # normal components along the line of impact, before and after
            "v_n": float(np.dot([p.v, 0.0], n)),
            "v1n": float(np.dot(after.v1, n)), "v2n": float(np.dot(after.v2, n))}


def _tangent(p):
    """The unit vector across the line of impact."""
    return np.array([-np.sin(p.beta), np.cos(p.beta)])


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
    solution=r"""
The balls are smooth, so the contact force acts only along the line of impact
$n = (\cos\beta, \sin\beta)$ (Section 2.3.1). Split each velocity into its component along
$n$ and its component perpendicular to it:

- perpendicular to $n$ no force acts, so each ball keeps that component (ball 2 has none);
- along $n$ the impact is a central impact: the normal momentum $m_1 v_{1,n} + m_2 v_{2,n}$ is
  conserved and the relative normal speed is reversed and scaled by $e$.

Before the impact ball 1 has $v_n = v\cos\beta$ = {{ si.v_n }} m/s along $n$ (with $v$ = {{ v }},
$\beta$ = {{ beta }}) and ball 2 is at rest. The two conditions
$m_1 v_{1,n}' + m_2 v_{2,n}' = m_1 v_n$ and $v_{2,n}' - v_{1,n}' = e\,v_n$ give
$v_{1,n}' = \frac{m_1 - e\,m_2}{m_1 + m_2}\,v_n, \qquad v_{2,n}' = \frac{(1 + e)\,m_1}{m_1 + m_2}\,v_n$;
with $m_1$ = {{ m1 }}, $m_2$ = {{ m2 }}, $e$ = {{ e }}: $v_{1,n}'$ = {{ si.v1n }} m/s and
$v_{2,n}'$ = {{ si.v2n }} m/s.

1. **Ball 1.** Its part perpendicular to $n$, $v\,e_1 - v_n n$, stays, its normal part becomes
   $v_{1,n}'$: $v_1' = v\,e_1 + (v_{1,n}' - v_n)\,n$ = {{ answers.v1_after }}.
2. **Ball 2.** It only receives the normal impulse, so it moves along the line of impact:
   $v_2' = v_{2,n}'\,n$ = {{ answers.v2_after }}.
3. **Speed of ball 2.** $|v_2'| = v_{2,n}'$ = {{ answers.speed2 }}.
""",
    solve=solve,
    checks=(
        # momentum balance of the pair, a vector
        Balance("momentum", lambda p, s: (p.m1 * p.v, 0.0),
                lambda p, s: tuple(p.m1 * np.asarray(s["v1_after"]) + p.m2 * np.asarray(s["v2_after"])),
                name="momentum_balance", atol=1e-12),
        # Newton's law of restitution along the line of impact
        Balance("normal relative speed", lambda p, s: p.e * p.v * np.cos(p.beta),
                lambda p, s: s["v2n"] - s["v1n"], name="restitution"),
        # smooth pucks: the impulse is along the line of impact, tangential speeds are kept
        Balance("tangential speed of puck 1", lambda p, s: -p.v * np.sin(p.beta),
                lambda p, s: float(np.dot(s["v1_after"], _tangent(p))), name="smooth_contact",
                atol=1e-12),
    ),
    parts=(
        Vector("v1_after", "velocity of ball 1 after the impact", question=1,
               unit="m/s", size=2, points=2,
               misconceptions=(
                   Misconception("treated as a central impact",
                                 lambda p: (_central(p).v1, 0.0),
                                 "Only the component along the line of impact changes; the "
                                 "tangential component is kept."),
               )),
        Vector("v2_after", "velocity of ball 2 after the impact", question=2,
               unit="m/s", size=2, points=2,
               misconceptions=(
                   Misconception("treated as a central impact",
                                 lambda p: (_central(p).v2, 0.0),
                                 "Ball 2 is pushed along the line of impact only."),
               )),
        Numeric("speed2", "speed of ball 2", question=3, unit="m/s", points=1,
                misconceptions=(
                    Misconception("treated as a central impact", lambda p: _central(p).v2,
                                  "Only the normal component v cos(β) takes part in the "
                                  "impact."),
                )),
    ),
)
