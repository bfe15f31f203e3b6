"""Ballistic pendulum: a bullet embeds itself in a block hanging on strings (Section 2.3.1).

The strings' length L is given and the rise h = V^2/(2 g) stays below it, so the block
swings on taut strings no higher than their attachment, as h = V^2/(2 g) assumes (issue
31: without L the statement asked for rises of 13.9 m and 32 m). Question 3 asks for the
energy lost, in J: the fraction lost, M/(m + M), is within 1 % of 0.99 for nearly every
bullet and block, so it was one answer for the whole class."""

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric,
                                Symbolic, Uniform, per_draw)
from dynagrade.exercise.checks import Balance, Recompute
from dynagrade.exercise.figure import arrow, block, ceiling, new_drawing
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import collisions, energy
from dynagrade.mechanics.examples import projectile


def _energy_conserving_speed(p):
    """The wrong route: kinetic energy of the bullet shared by bullet and block."""
    return p.v * np.sqrt(p.m / (p.m + p.M))


def figure(p):
    """The block hanging at rest on its two strings of length L and the bullet flying at
    it horizontally (Section 2.3.1); a schematic in fixed proportions."""
    from dynagrade.exercise.figure import Ellipse

    drawing, axes = new_drawing(5.0, 2.6)
    width, height, hang = 0.5, 0.25, 1.0
    ceiling(axes, -0.45, 0.45, hang, hatch=0.04)
    for x in (-0.18, 0.18):
        axes.plot([x, x], [hang, height / 2], color="0.2", lw=0.9)
    axes.text(0.24, (hang + height / 2) / 2, f"L = {format_number(p.L)} m", ha="left",
              va="center", fontsize=10)
    block(axes, (0.0, 0.0), width, height, "M", color="#a0724a")
    axes.text(width / 2 + 0.06, -0.02, f"M = {format_number(p.M)} kg", ha="left",
              va="center", fontsize=10)
    bullet = (-1.3, 0.0)
    axes.add_patch(Ellipse(bullet, 0.09, 0.035, facecolor="0.25", edgecolor="0.1"))
    axes.text(bullet[0], 0.06, f"m = {format_number(1000 * p.m)} g", ha="center",
              va="bottom", fontsize=10)
    arrow(axes, (bullet[0] + 0.1, 0.0), (bullet[0] + 0.55, 0.0), color="C3")
    axes.text(bullet[0] + 0.33, -0.06, f"v = {format_number(p.v)} m/s", color="C3",
              ha="center", va="top", fontsize=10)
    axes.set_xlim(-1.5, 1.1)
    axes.set_ylim(-0.3, hang + 0.08)
    return drawing


@per_draw
def solve(p):
    common = collisions.common_velocity_after_plastic_impact(p.m, p.M, p.v, 0.0)
    lost = collisions.kinetic_energy_lost_in_impact(p.m, p.M, p.v, 0.0)
    before = energy.particle_kinetic_energy(p.m, p.v)
    return {
        "V": common,
        # the block swings up like a vertical throw with the speed V: h = V^2 / (2 g)
        "h": projectile.peak_height(common, np.pi / 2, p.g),
        "T_lost": lost,
        # intermediate quantities of the worked solution
        "fraction_lost": lost / before,
        "momentum": p.m * p.v,
        "T_before": before,
        "T_after": energy.particle_kinetic_energy(p.m + p.M, common),
    }


EXERCISE = Exercise(
    id="ballistic-pendulum",
    title="Ballistic pendulum",
    source="Section 2.3.1",
    topics=("plastic impact", "momentum conservation", "work-energy balance"),
    params=(
        Uniform("m", 5, 50, step=1, unit="g", symbol="m"),
        Uniform("M", 0.5, 5.0, step=0.1, unit="kg", symbol="M"),
        Uniform("v", 100, 600, step=10, unit="m/s", symbol="v"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
        Uniform("L", 1.0, 3.0, step=0.1, unit="m", symbol="L"),
    ),
    constraints=(
        # h = V^2/(2 g) holds while the strings stay taut: up to their attachment, h <= L
        Constraint("the block rises less than the strings' length (h < L)",
                   lambda p: solve(p)["h"] < p.L),
    ),
    statement=r"""
A bullet of mass $m$ = {{ m }} flying horizontally with speed $v$ = {{ v }} hits a wooden
block of mass $M$ = {{ M }} that hangs at rest on strings of length $L$ = {{ L }}, and stays
stuck in it.
Treat bullet and block as particles; $g$ = {{ g }}.

1. With which speed $V$ does the block (with the bullet) start to swing?
2. How high does the block rise?
3. How much kinetic energy is lost in the impact?
4. Give $V$ as a formula in $m$, $M$ and $v$.
""",
    solution=r"""
Two stages, each with its own balance (Section 2.3.1): the impact is so short that the
strings, still vertical, and gravity give no horizontal impulse, so the horizontal linear
momentum of bullet and block is conserved; but the bullet sticks (a plastic impact), so
kinetic energy is not. During the swing that follows, only gravity does work (the strings
are perpendicular to the motion), so mechanical energy is conserved.

1. Momentum before and after the impact, with $m$ = {{ si.m }} kg:
   $m v = (m + M) V$, where $m v$ = {{ si.momentum }} kg·m/s. Hence
   $V = m v/(m + M)$ = {{ answers.V }}.
2. Work-energy balance from the lowest to the highest point of the swing:
   $\frac{1}{2}(m + M) V^2 = (m + M) g h$, so $h = V^2/(2g)$ = {{ answers.h }}.
   The masses cancel: the block rises as high as a body thrown straight up with $V$.
   The rise is less than the strings' length $L$ = {{ L }}, so the strings stay taut and
   the block swings no higher than their attachment.
3. Kinetic energy of the bullet $T_1 = \frac{1}{2} m v^2$ = {{ si.T_before }} J; of bullet and
   block just after the impact $T_2 = \frac{1}{2}(m + M) V^2$ = {{ si.T_after }} J. The impact
   dissipates $T_1 - T_2$ = {{ answers.T_lost }}, the fraction
   $(T_1 - T_2)/T_1 = M/(m + M)$ = {{ si.fraction_lost }}: nearly all of it, since the
   block is much heavier than the bullet.
4. From step 1: `{{ answers.V_formula }}`.
""",
    solve=solve,
    checks=(
        # momentum balance of the plastic impact: m v = (m + M) V
        Balance("momentum", lambda p, s: p.m * p.v, lambda p, s: (p.m + p.M) * s["V"],
                name="momentum_balance"),
        # energy balance of the swing, eq. (1.102): (m + M) V^2 / 2 = (m + M) g h
        Balance("energy per unit mass", lambda p, s: s["V"]**2 / 2, lambda p, s: p.g * s["h"],
                name="swing_energy"),
        Recompute("fraction_lost", lambda p, s: p.M / (p.m + p.M), name="plastic_loss"),
        # the loss of a plastic impact on a block at rest: T1 M/(m + M) = m M v^2/(2 (m + M))
        Recompute("T_lost", lambda p, s: p.m * p.M * p.v**2 / (2 * (p.m + p.M)),
                  name="energy_lost"),
    ),
    figure=figure,
    parts=(
        Numeric("V", "speed just after the impact", question=1, unit="m/s", points=2,
                misconceptions=(
                    Misconception("kinetic energy conserved in the impact", _energy_conserving_speed,
                                  "A plastic impact dissipates energy: only momentum is "
                                  "conserved during the impact."),
                )),
        Numeric("h", "rise of the block", question=2, unit="cm", points=1,
                misconceptions=(
                    Misconception("kinetic energy conserved in the impact",
                                  lambda p: p.m * p.v**2 / (2 * (p.m + p.M) * p.g),
                                  "Energy is conserved during the swing, not during the "
                                  "impact."),
                )),
        Numeric("T_lost", "kinetic energy lost", question=3, unit="J", points=1,
                misconceptions=(
                    Misconception("the energy left for the energy lost",
                                  lambda p: p.m**2 * p.v**2 / (2 * (p.m + p.M)),
                                  "That is T2, what bullet and block keep; the loss is "
                                  "T1 - T2 = T1 M/(m + M), nearly all of T1."),
                )),
        Symbolic("V_formula", "V as a formula", question=4, points=1, expected="m*v/(m+M)",
                 variables=("m", "M", "v"),
                 equals="V",
                 misconceptions=(
                     Misconception("kinetic energy conserved", "v*sqrt(m/(m+M))",
                                   "Only momentum is conserved in a plastic impact."),
                 )),
    ),
)
