"""A car braking with locked wheels: deceleration and the load on each axle, from the
balances of linear and angular momentum of a translating rigid body (Section 3.2.1)."""

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric,
                                Uniform)
from dynagrade.exercise.checks import Balance, Limit, Recompute
from dynagrade.exercise.figure import (Circle, arrow, block, describe, dimension, ground,
                                       new_drawing)
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import particle, rigid_kinetics


def _front(p, mu, l_f, l_r):
    return rigid_kinetics.front_axle_load_when_braking(p.m, p.g, mu, l_f, l_r, p.h)


def solve(p):
    weight = p.m * p.g
    # Coulomb friction on the wheels sliding forward (+e1), summed over both axles,
    # whose normal forces add up to the weight: N_f + N_r = m g
    friction = particle.kinetic_friction(weight, [1.0, 0.0], p.mu)[0]
    return {
        "a": -friction / p.m,
        "N_f": _front(p, p.mu, p.l_f, p.l_r),
        "N_r": rigid_kinetics.rear_axle_load_when_braking(p.m, p.g, p.mu, p.l_f, p.l_r, p.h),
    }


def figure(p):
    """The car to scale, moving to the right: axles, the centre of mass C at l_f behind
    the front axle and h above the road."""
    wheel = 0.32
    drawing, axes = new_drawing(5.0, 2.6)
    front, rear = p.l_f, -p.l_r
    ground(axes, rear - 1.1, front + 1.1, 0.0, hatch=0.08)
    block(axes, ((front + rear) / 2, 0.85), p.l_f + p.l_r + 1.5, 1.0, color="#9ab7d3")
    for x in (front, rear):
        axes.add_patch(Circle((x, wheel), wheel, facecolor="0.25", edgecolor="0.1", lw=1.0))
    axes.plot([0.0], [p.h], "o", color="0.1", ms=5)
    axes.text(0.06, p.h + 0.05, "C", ha="left", va="bottom", fontsize=10)
    dimension(axes, (rear, 0.0), (0.0, 0.0), f"l_r = {format_number(p.l_r)} m",
              offset=-0.3, tick=0.05, side=-1.0)
    dimension(axes, (0.0, 0.0), (front, 0.0), f"l_f = {format_number(p.l_f)} m",
              offset=-0.3, tick=0.05, side=-1.0)
    # h ahead of the car, C's height carried over by a dashed line: beside C the label
    # lay on the body's edge and the wheel
    axes.plot([0.0, front + 0.95], [p.h, p.h], color="0.4", lw=0.6, ls="--")
    dimension(axes, (front + 0.9, 0.0), (front + 0.9, p.h), f"h = {format_number(p.h)} m",
              offset=0.0, tick=0.05, side=-1.0)
    arrow(axes, (front + 0.9, 1.6), (front + 1.5, 1.6), "v", offset=(0.0, 0.13), color="C3")
    axes.text(rear - 0.7, 1.55, f"m = {format_number(p.m)} kg,  μ = {format_number(p.mu)}",
              ha="left", va="bottom", fontsize=10)
    describe(axes, "The car moves to the right; its front axle is on the right. C lies "
                   "between the axles; a dashed line carries its height h to the dimension "
                   "line ahead of the car.")
    axes.set_xlim(rear - 1.2, front + 1.9)
    axes.set_ylim(-0.75, 1.9)
    return drawing


def _front_by_rear_contact(p, s):
    """Moments about the rear contact point (moving with the car, which translates):
    N_f (l_f + l_r) = m g l_r + m a h, the inertial term m a h from r x m a_C."""
    return p.m * (p.g * p.l_r + s["a"] * p.h) / (p.l_f + p.l_r)


def _rear_by_front_contact(p, s):
    """Moments about the front contact point: N_r (l_f + l_r) = m g l_f - m a h."""
    return p.m * (p.g * p.l_f - s["a"] * p.h) / (p.l_f + p.l_r)


def _swap_matters(p):
    """Swapping l_f and l_r changes N_f by more than twice the 1 % tolerance."""
    return abs(p.l_r - p.l_f) > 0.02 * (p.l_r + p.mu * p.h)


EXERCISE = Exercise(
    id="braking-car-axle-loads",
    title="Braking car: deceleration and axle loads",
    source="Section 3.2.1",
    topics=("balance of linear momentum", "rigid body in translation", "load transfer"),
    params=(
        Uniform("m", 900, 2200, step=50, unit="kg", symbol="m"),
        Uniform("l_f", 0.9, 1.3, step=0.05, unit="m", symbol="l_f"),
        Uniform("l_r", 1.3, 1.9, step=0.05, unit="m", symbol="l_r"),
        Uniform("h", 0.45, 0.7, step=0.01, unit="m", symbol="h"),
        Uniform("mu", 0.4, 0.95, step=0.05, symbol=r"\mu"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("the rear wheels stay on the road (mu h < l_f) with a margin",
                   lambda p: p.mu * p.h < 0.8 * p.l_f),
        Constraint("the two axle loads differ clearly",
                   lambda p: (p.l_r - p.l_f + 2 * p.mu * p.h) > 0.1 * (p.l_f + p.l_r)),
    ),
    statement=r"""
A car of mass $m$ = {{ m }} brakes on a level road with all four wheels locked, so that
they slide with the friction coefficient $\mu$ = {{ mu }}. Its centre of mass C lies
$l_f$ = {{ l_f }} behind the front axle, $l_r$ = {{ l_r }} ahead of the rear axle and
$h$ = {{ h }} above the road ($g$ = {{ g }}). The car does not pitch: it translates, and
its rear wheels stay on the road. Treat it as one rigid body; the wheels' rotation is
over (they are locked).

1. What is the car's deceleration?
2. What is the normal force of the road on the two front wheels together?
3. What is the normal force on the two rear wheels together?
""",
    solution=r"""
The car is a rigid body in translation: every point has the acceleration $a_C$ of the
centre of mass. The balance of linear momentum (Section 3.2.1) holds for the whole body,
$m\,a_C = F$, and, since the body does not rotate, its angular momentum about C stays
zero, so the moments of all forces about C cancel (Section 3.2.2). The forces are the
weight $m g$ at C, the normal forces $N_f$, $N_r$ and the sliding friction
$\mu N_f$, $\mu N_r$ backward at the two contacts.

1. **Deceleration.** Vertically $N_f + N_r = m g$; horizontally
   $m a = \mu (N_f + N_r) = \mu m g$, so $a = \mu g$ = {{ answers.a }}, whatever the
   split between the axles.
2. **Front axle.** Moments about C (the contacts lie $h$ below C, the friction points
   backward, so it pitches the nose down):
   $$N_f\,l_f - N_r\,l_r - \mu (N_f + N_r)\,h = 0
   \quad\Rightarrow\quad N_f = \frac{m g\,(l_r + \mu h)}{l_f + l_r},$$
   with $m$ = {{ m }}, $l_f$ = {{ l_f }}, $l_r$ = {{ l_r }}, $h$ = {{ h }} and
   $\mu$ = {{ mu }}: $N_f$ = {{ answers.N_f }}.
3. **Rear axle.** $N_r = m g - N_f = \dfrac{m g\,(l_f - \mu h)}{l_f + l_r}$
   = {{ answers.N_r }}. It stays positive because $\mu h < l_f$.

**Check.** Without friction ($\mu \to 0$) the front axle would carry its static share
$m g\,l_r/(l_f + l_r)$ = {{ checks.static_front_load }} N; braking moves
$\mu m g\,h/(l_f + l_r)$ from the rear to the front axle.
""",
    solve=solve,
    figure=figure,
    figure_to_scale=True,
    checks=(
        # moments about each contact point instead of about C (Section 3.2.2, with r x m a_C)
        Recompute("N_f", _front_by_rear_contact, name="moments_about_rear_contact"),
        Recompute("N_r", _rear_by_front_contact, name="moments_about_front_contact"),
        # vertical balance of linear momentum: the road carries the weight
        Balance("vertical", lambda p, s: s["N_f"] + s["N_r"], lambda p, s: p.m * p.g,
                name="axles_carry_the_weight"),
        Limit("N_f", {"mu": 0.0}, lambda p: p.m * p.g * p.l_r / (p.l_f + p.l_r),
              name="static_front_load"),
    ),
    parts=(
        Numeric("a", "deceleration", question=1, unit="m/s^2", points=1,
                misconceptions=(
                    Misconception("friction on the front wheels only",
                                  lambda p: p.mu * _front(p, p.mu, p.l_f, p.l_r) / p.m,
                                  "All four wheels are locked: the friction μ(N_f + N_r) = μ m g "
                                  "acts at both axles."),
                )),
        Numeric("N_f", "normal force on the front axle", question=2, unit="N", points=2,
                misconceptions=(
                    Misconception("load transfer forgotten",
                                  lambda p: _front(p, 0.0, p.l_f, p.l_r),
                                  "The friction acts at the road, h below C: its moment about "
                                  "C, μ m g h, loads the front axle."),
                    Misconception("friction's moment with the wrong sense",
                                  lambda p: _front(p, -p.mu, p.l_f, p.l_r),
                                  "Backward friction below C pitches the nose down: it adds "
                                  "to the front load."),
                    Misconception("lever arms swapped",
                                  lambda p: _front(p, p.mu, p.l_r, p.l_f),
                                  "The front axle's share of the weight is m g l_r/(l_f + l_r): "
                                  "the axle nearer C carries more.", applies=_swap_matters),
                )),
        Numeric("N_r", "normal force on the rear axle", question=3, unit="N", points=2,
                misconceptions=(
                    Misconception("load transfer forgotten",
                                  lambda p: p.m * p.g * p.l_f / (p.l_f + p.l_r),
                                  "Braking unloads the rear axle by μ m g h/(l_f + l_r)."),
                )),
    ),
)
