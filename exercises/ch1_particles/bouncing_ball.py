"""A ball dropped on a hard floor: rebound speed and height, energy lost, and the
coefficient of restitution from measured heights (Section 1.2.4)."""

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric, Symbolic,
                                Uniform)
from dynagrade.exercise.checks import Balance, Integrated, Limit, Recompute
from dynagrade.exercise.checks.motions import falling, height
from dynagrade.mechanics import energy, impact


def solve(p):
    v_in = float(impact.impact_speed_after_fall(p.h0, p.g))
    v_out = abs(impact.rebound_normal_velocity(v_in, p.e))
    return {
        "v_out": v_out,
        "v_in": v_in,
        "h1": impact.rebound_height(p.h0, p.e),
        "dT": float(energy.particle_kinetic_energy(p.m, v_in) - energy.particle_kinetic_energy(p.m, v_out)),
        "h3": impact.rebound_height(p.h0, p.e, 3),
    }


EXERCISE = Exercise(
    id="bouncing-ball",
    title="Bouncing ball: restitution, rebound height and energy lost",
    source="Section 1.2.4",
    topics=("particle impact", "coefficient of restitution", "conservation of energy"),
    params=(
        Uniform("m", 0.05, 0.6, step=0.01, unit="kg", symbol="m"),
        Uniform("h0", 0.5, 3.0, step=0.1, unit="m", symbol="h_0"),
        Uniform("e", 0.4, 0.9, step=0.02, symbol="e"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("e and e^2 differ by more than 5 %", lambda p: p.e < 0.95),
    ),
    statement="""
A ball of mass $m$ = {{ m }} is dropped from rest at the height $h_0$ = {{ h0 }} onto a
rigid floor. The coefficient of restitution is $e$ = {{ e }}; $g$ = {{ g }}, no air drag.

1. With what speed does it leave the floor after the first impact?
2. How high does it rise after the first impact?
3. How much kinetic energy is lost in the first impact?
4. How high does it rise after the third impact?
5. Write the height after the first impact as a formula in $h_0$ and $e$.
""",
    solution=r"""
Between impacts only gravity acts, so energy is conserved (eq. (1.102)); in an impact the
floor reverses the normal velocity and scales it by the coefficient of restitution $e$.

1. **Rebound speed.** Energy conservation on the way down, $\tfrac{1}{2} m v^2 = mgh_0$, gives the
   impact speed $v = \sqrt{2gh_0}$ = {{ si.v_in }} m/s. The impact reverses it and multiplies
   it by $e$ = {{ e }}: $v' = e\sqrt{2gh_0}$ = {{ answers.v_out }}.
2. **First rebound height.** Energy conservation on the way up,
   $h_1 = v'^2/(2g) = e^2 h_0$ = {{ answers.h1 }}: the height goes with the speed squared.
3. **Energy lost.** The kinetic energy before the impact is $\tfrac{1}{2} m v^2 = mgh_0$ and
   keeps the fraction $e^2$, so
   $\Delta T = \tfrac{1}{2} m (v^2 - v'^2) = (1 - e^2)\, m g h_0$ = {{ answers.dT }}
   (with $m$ = {{ m }}).
4. **Third rebound.** Every impact multiplies the height by $e^2$, so after three impacts
   $h_3 = e^6 h_0$ = {{ answers.h3 }}.
5. **Formula.** $h_1$ = `{{ answers.h1_formula }}`.
6. **Check.** With $e = 1$ (a perfectly elastic floor) the ball would come back to
   $h_1 = h_0$ = {{ checks.elastic }} m and lose no energy.
""",
    solve=solve,
    checks=(
        Integrated("v_in", falling, lambda p: (p.h0, 0.0), lambda p, s: 2 * np.sqrt(2 * p.h0 / p.g),
                   lambda t, y, p: abs(y[1]), name="integrated_fall", event=height, direction=-1),
        # energy after the bounce, eq. (1.102): m g h1 = m v_out^2 / 2
        Balance("energy after the bounce", lambda p, s: p.g * s["h1"], lambda p, s: s["v_out"]**2 / 2,
                name="rebound_energy"),
        # each bounce keeps e^2 of the height: h3 = e^6 h0
        Recompute("h3", lambda p, s: p.e**6 * p.h0, name="three_bounces"),
        Recompute("dT", lambda p, s: p.m * p.g * p.h0 * (1 - p.e**2), name="energy_lost"),
        # e = 1: a perfectly elastic bounce returns to the starting height
        Limit("h1", {"e": 1.0}, lambda p: p.h0, name="elastic"),
    ),
    parts=(
        Numeric("v_out", "rebound speed", question=1, unit="m/s", points=1),
        Numeric("h1", "height after the first bounce", question=2, unit="m", points=2,
                misconceptions=(
                    Misconception("e applied to the height", lambda p: p.e * p.h0,
                                  "e scales the speed; the height goes with the speed squared: "
                                  "h1 = e² h0."),
                )),
        Numeric("dT", "kinetic energy lost", question=3, unit="J", points=1,
                misconceptions=(
                    Misconception("loss fraction 1 - e", lambda p: (1 - p.e) * p.m * p.g * p.h0,
                                  "The kinetic energy keeps the fraction e², so (1 − e²) is lost."),
                )),
        Numeric("h3", "height after the third bounce", question=4, unit="m", points=1,
                misconceptions=(
                    Misconception("e^3 instead of e^6", lambda p: p.e**3 * p.h0,
                                  "Each bounce multiplies the height by e²."),
                )),
        Symbolic("h1_formula", "height after the first bounce as a formula", question=5, points=1,
                 expected="e^2*h0",
                 variables=("e", "h0"),
                 equals="h1",
                 misconceptions=(
                     Misconception("e applied to the height", "e*h0",
                                   "The height goes with the speed squared."),
                 )),
    ),
)
