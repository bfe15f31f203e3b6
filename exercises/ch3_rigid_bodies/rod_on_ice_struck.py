"""A free rod lying on smooth ice struck off-centre by a puck: eccentric impact on an
unconstrained rigid body (Section 3.3)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.apart import numbers_apart
from dynagrade.exercise.checks import Balance, Limit
from dynagrade.exercise.figure import Circle, arrow, block, describe, dimension, new_drawing
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import collisions, inertia, rigid_impact


def _moment_centre(p):
    return inertia.inertia_tensor_rod(p.M, p.L)[0, 0]


@per_draw
def solve(p):
    i_c = _moment_centre(p)
    w_rod = rigid_impact.inverse_effective_mass_free_body(p.M, i_c, p.d)
    impulse = rigid_impact.eccentric_impact_impulse(1.0 / p.m, w_rod, p.v, p.e)
    return {
        "v_C": collisions.velocity_after_impulse(p.M, 0.0, impulse),
        "omega": rigid_impact.angular_velocity_change(impulse, p.d, i_c),
        "v_after": collisions.velocity_after_impulse(p.m, p.v, -impulse),
        "dT": collisions.kinetic_energy_lost_in_impact(p.m, 1.0 / w_rod, p.v, p.e),
        "I_C": i_c,
        "w_rod": w_rod,
        "impulse": impulse,
    }


def _keys(p):
    return [solve(p)[k] for k in ("v_C", "omega", "v_after", "dT")]


@per_draw
def _as_particle_impulse(p):
    """The wrong route: the rod hit as a free particle of mass M (its turning left out)."""
    return rigid_impact.eccentric_impact_impulse(1.0 / p.m, 1.0 / p.M, p.v, p.e)


def figure(p):
    """Top view to scale: the rod along the ice, the puck arriving square to it at the
    distance d from the rod's centre C (Section 3.3)."""
    L = p.L
    drawing, axes = new_drawing(4.2, 3.6)
    block(axes, (0.0, 0.0), 0.035 * L, L, color="#a0724a")
    axes.plot([0.0], [0.0], "o", color="0.1", ms=4)
    axes.text(0.04 * L, -0.03 * L, "C", ha="left", va="top", fontsize=10)
    axes.text(0.0, -0.56 * L, f"M = {format_number(p.M)} kg", ha="center", va="top",
              fontsize=10)
    radius = 0.04 * L
    puck = (-0.55 * L, p.d)
    axes.add_patch(Circle(puck, radius, facecolor="C0", edgecolor="0.1", lw=1.0))
    axes.text(puck[0], puck[1] + 1.6 * radius, f"m = {format_number(p.m)} kg", ha="center",
              va="bottom", fontsize=10)
    arrow(axes, (puck[0] + 1.5 * radius, p.d), (-0.05 * L, p.d), color="C3")
    axes.text(-0.3 * L, p.d - 0.04 * L, f"v = {format_number(p.v)} m/s", color="C3",
              ha="center", va="top", fontsize=10)
    dimension(axes, (0.0, 0.0), (0.0, p.d), f"d = {format_number(p.d)} m", offset=-0.15 * L,
              tick=0.03 * L, side=-1.0)
    dimension(axes, (0.0, -L / 2), (0.0, L / 2), f"L = {format_number(L)} m",
              offset=-0.5 * L, tick=0.03 * L, side=-1.0)
    axes.text(-0.85 * L, -0.5 * L, f"e = {format_number(p.e)}", ha="left", va="bottom",
              fontsize=10)
    describe(axes, "Seen from above: the rod lies at rest on the ice; the puck slides "
                   "towards it perpendicular to the rod and hits it off-centre.")
    axes.set_xlim(-0.9 * L, 0.9 * L)
    axes.set_ylim(-0.62 * L, 0.58 * L)
    return drawing


EXERCISE = Exercise(
    id="rod-on-ice-struck-by-puck",
    title="Rod on smooth ice struck off-centre by a puck",
    source="Section 3.3",
    topics=("eccentric impact", "coefficient of restitution", "free rigid body"),
    params=(
        Uniform("M", 1.0, 6.0, step=0.5, unit="kg", symbol="M"),
        Uniform("L", 0.6, 2.0, step=0.1, unit="m", symbol="L"),
        Uniform("m", 0.2, 1.5, step=0.05, unit="kg", symbol="m"),
        Uniform("v", 2.0, 12.0, step=0.5, unit="m/s", symbol="v"),
        Uniform("d", 0.05, 0.9, step=0.05, unit="m", symbol="d"),
        Uniform("e", 0.2, 0.9, step=0.05, symbol="e"),
    ),
    constraints=(
        Constraint("the puck hits the rod off-centre and clear of its ends",
                   lambda p: 0.1 * p.L <= p.d <= 0.45 * p.L),
        Constraint("the rod's turning changes the answers: d^2/I_C adds over 12 % to "
                   "1/m + 1/M",
                   lambda p: p.d**2 / _moment_centre(p) > 0.12 * (1 / p.m + 1 / p.M)),
        Constraint("the four answers differ from each other by over 5 %",
                   lambda p: numbers_apart(_keys(p))),
        Constraint("the puck's velocity after the impact is not close to zero",
                   lambda p: abs(solve(p)["v_after"]) > 0.05 * p.v),
    ),
    statement=r"""
A slender rod (mass $M$ = {{ M }}, length $L$ = {{ L }}) lies at rest on smooth, horizontal
ice. A puck of mass $m$ = {{ m }} slides with $v$ = {{ v }} perpendicular to the rod and
hits it at the distance $d$ = {{ d }} from the rod's centre C; the coefficient of
restitution is $e$ = {{ e }}. The contact is smooth and the puck may be treated as a
particle. Nothing holds the rod.

1. What is the speed of the rod's centre C just after the impact?
2. What is the rod's angular speed just after the impact?
3. What is the puck's velocity just after the impact (positive in its original direction)?
4. How much kinetic energy is lost in the impact?
""",
    solution=r"""
Only the contact impulse $\hat F$ acts in the plane of the ice during the short impact, so
we use the impulse balances of an eccentric impact together with the coefficient of
restitution (impact of rigid bodies, Section 3.3).

**Effective inverse mass of the rod.** The impulse moves C and turns the rod about C,
with $I_C = \tfrac{1}{12} M L^2$ = {{ si.I_C }} kg·m². The hit point then moves at
$v_C + \omega d = \hat F\,(1/M + d^2/I_C)$, so the rod answers like a particle of inverse
mass $w = 1/M + d^2/I_C$ = {{ si.w_rod }} 1/kg.

**Impulse.** The puck: $m v' = m v - \hat F$. Restitution at the hit point:
$v_C + \omega d - v' = e\,v$. Together
$$\hat F = \frac{(1+e)\,v}{1/m + 1/M + d^2/I_C}$$
= {{ si.impulse }} N·s.

1. **Centre.** Linear impulse balance of the rod: $M v_C = \hat F$, so
   $v_C$ = {{ answers.v_C }}.
2. **Angular speed.** Angular impulse balance about C: $I_C\,\omega = \hat F d$, so
   $\omega$ = {{ answers.omega }}.
3. **Puck.** $v' = v - \hat F/m$ = {{ answers.v_after }}{% if si.v_after.value < 0 %} (negative: it bounces back){% else %} (positive: it
   keeps going forward, more slowly){% endif %}.
4. **Energy lost.** With the effective mass $1/w$ of the rod in place of a particle's mass,
   the loss of a two-particle impact holds:
   $$\Delta T = \frac{1}{2}\,\frac{1 - e^2}{1/m + w}\,v^2$$
   = {{ answers.dT }}.

**Check.** A blow through the centre ($d = 0$) would not turn the rod; it would then move
off with $(1+e)\,m v/(m+M)$ = {{ checks.central_blow }} m/s, faster than
{{ answers.v_C }}: part of the impulse's effect now goes into turning.
""",
    solve=solve,
    checks=(
        # linear momentum of puck and rod through the impact (Section 3.3)
        Balance("linear momentum", lambda p, s: p.m * p.v,
                lambda p, s: p.m * s["v_after"] + p.M * s["v_C"], name="linear_momentum"),
        # angular momentum about the rod's centre, I_C = M L^2 / 12 written out
        Balance("angular momentum about C", lambda p, s: p.m * p.v * p.d,
                lambda p, s: p.m * s["v_after"] * p.d + p.M * p.L**2 / 12 * s["omega"],
                name="angular_momentum"),
        # Newton's restitution at the hit point
        Balance("separation speed", lambda p, s: p.e * p.v,
                lambda p, s: s["v_C"] + s["omega"] * p.d - s["v_after"], name="restitution"),
        # kinetic energy before minus after, translation and rotation of the rod
        Balance("energy lost", lambda p, s: 0.5 * p.m * p.v**2 - s["dT"],
                lambda p, s: 0.5 * p.m * s["v_after"]**2 + 0.5 * p.M * s["v_C"]**2
                + 0.5 * p.M * p.L**2 / 12 * s["omega"]**2, name="energy"),
        # d = 0: a central impact of two particles (Section 2.3.1)
        Limit("v_C", {"d": 0.0}, lambda p: (1 + p.e) * p.m * p.v / (p.m + p.M),
              name="central_blow"),
    ),
    figure=figure, figure_to_scale=True,
    parts=(
        Numeric("v_C", "speed of the rod's centre", question=1, unit="m/s", points=2,
                misconceptions=(
                    Misconception("rod treated as a particle",
                                  lambda p: _as_particle_impulse(p) / p.M,
                                  "The blow is off-centre: the rod also turns, so at the hit "
                                  "point it gives way like a mass 1/(1/M + d²/I_C) < M."),
                )),
        Numeric("omega", "angular speed of the rod", question=2, unit="rad/s", points=2,
                misconceptions=(
                    Misconception("all of the puck's angular momentum to the rod",
                                  lambda p: p.m * p.v * p.d / _moment_centre(p),
                                  "The puck keeps angular momentum m v' d about C: use the "
                                  "impulse, I_C ω = F̂ d."),
                    Misconception("moment of inertia about the end",
                                  lambda p: solve(p)["impulse"] * p.d / (p.M * p.L**2 / 3),
                                  "A free rod turns about its centre of mass: I_C = M L²/12."),
                )),
        Numeric("v_after", "velocity of the puck after the impact", question=3, unit="m/s",
                points=1,
                misconceptions=(
                    Misconception("rod treated as a particle",
                                  lambda p: p.v - _as_particle_impulse(p) / p.m,
                                  "The rod gives way more than a particle of mass M would: "
                                  "its effective inverse mass is 1/M + d²/I_C."),
                )),
        Numeric("dT", "kinetic energy lost", question=4, unit="J", points=1,
                misconceptions=(
                    Misconception("the puck's energy times 1 − e²",
                                  lambda p: 0.5 * p.m * p.v**2 * (1 - p.e**2),
                                  "Only the energy of the relative motion is lost: "
                                  "ΔT = ½ (1 − e²) v² / (1/m + w), with the rod's effective "
                                  "inverse mass w."),
                )),
    ),
)
