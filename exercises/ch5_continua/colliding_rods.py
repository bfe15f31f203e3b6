"""Two equal rods colliding end on: contact stress, contact time and the struck rod's
velocity (Section 5.3.1)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.apart import answers_apart
from dynagrade.exercise.checks import Balance, Recompute
from dynagrade.exercise.figure import arrow, block, describe, dimension, new_drawing
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import rods


def _c(p):
    return rods.longitudinal_wave_speed(p.E, p.rho)


@per_draw
def solve(p):
    c = _c(p)
    Z = rods.mechanical_impedance(p.rho, c, 1.0)  # per unit area: the sections are equal
    v_i = rods.interface_velocity(Z, Z, p.v)
    return {"sigma": rods.impact_stress(p.rho, c, v_i), "t_c": rods.contact_duration(p.L1, c),
            "v2": p.v * p.L1 / p.L2, "c": c, "v_i": v_i}


def _energy_of_the_pulse(p, s):
    """Energy per unit area of the pulse the struck rod carries away, length c t_c, stress
    sigma: strain energy sigma^2/(2E) plus as much kinetic energy per volume (Section 5.3.1)."""
    return np.sqrt(p.E / p.rho) * s["t_c"] * s["sigma"] ** 2 / p.E


def figure(p):
    """The striker (left) moving at v towards the longer rod at rest; schematic."""
    L1, L2 = p.L1, p.L2
    total = L1 + L2
    t = 0.03 * total
    gap = 0.06 * total
    drawing, axes = new_drawing(5.2, 1.5)
    block(axes, (L1 / 2, 0.0), L1, t, color="C0")
    block(axes, (L1 + gap + L2 / 2, 0.0), L2, t, color="0.6")
    arrow(axes, (0.2 * L1, 0.07 * total), (0.8 * L1, 0.07 * total), color="C3")
    axes.text(0.5 * L1, 0.09 * total, f"v = {format_number(p.v)} m/s", color="C3",
              ha="center", va="bottom", fontsize=10)
    axes.text(L1 + gap + L2 / 2, 0.04 * total,
              f"E = {format_number(p.E / 1e9)} GPa, ρ = {format_number(p.rho)} kg/m³",
              ha="center", va="bottom", fontsize=9)
    dimension(axes, (0.0, -0.06 * total), (L1, -0.06 * total), f"L₁ = {format_number(L1)} m",
              tick=0.01 * total, side=-1.0)
    dimension(axes, (L1 + gap, -0.06 * total), (L1 + gap + L2, -0.06 * total),
              f"L₂ = {format_number(L2)} m", tick=0.01 * total, side=-1.0)
    describe(axes, "The shorter rod slides to the right, along its axis, towards the longer rod, which lies at rest in line with it.")
    axes.set_xlim(-0.03 * total, 1.09 * total)
    axes.set_ylim(-0.15 * total, 0.19 * total)
    return drawing


EXERCISE = Exercise(
    id="colliding-rods",
    title="Two rods colliding end on: contact stress and contact time",
    source="Section 5.3.1",
    topics=("longitudinal waves", "impact stress", "wave reflection", "momentum"),
    params=(
        Uniform("E", 70, 210, step=5, unit="GPa", symbol="E"),
        Uniform("rho", 2700, 8900, step=100, unit="kg/m^3", symbol=r"\rho"),
        Uniform("L1", 0.1, 0.6, step=0.02, unit="m", symbol="L_1"),
        Uniform("L2", 0.2, 1.5, step=0.05, unit="m", symbol="L_2"),
        Uniform("v", 0.5, 8.0, step=0.1, unit="m/s", symbol="v"),
    ),
    constraints=(
        Constraint("a real metal (aluminium, steel, copper alloys, titanium): "
                   "sqrt(E/rho) between 3 and 5.5 km/s",
                   lambda p: 3e3 <= np.sqrt(p.E / p.rho) <= 5.5e3),
        Constraint("the struck rod is at least 30 % longer than the striker", lambda p: p.L2 >= 1.3 * p.L1),
        Constraint("the stress, the contact time and the velocity are over 10 % apart in SI and in MPa, ms, m/s",
                   lambda p: answers_apart(solve(p), {"sigma": 1e6, "t_c": 1e-3, "v2": 1.0})),
    ),
    statement="""
Two slender rods of the same material ($E$ = {{ E }}, $\\rho$ = {{ rho }}) and the same
cross-section lie in line on a smooth table. Rod 1, of length $L_1$ = {{ L1 }}, slides at
$v$ = {{ v }} along its axis into the end of rod 2, of length $L_2$ = {{ L2 }} ($L_2 > L_1$),
which is at rest. The end faces are flat and meet squarely.

1. What compressive stress do the rods carry at the contact face?
2. How long are the rods in contact?
3. With which velocity does the centre of mass of rod 2 move after the contact?
""",
    solution=r"""
At the impact a compressive wave starts into each rod from the contact face, at
$c = \sqrt{E/\rho}$ = {{ si.c }} m/s; a wave of particle velocity $u$ carries the stress
$\rho c u$ (longitudinal waves, Section 5.3.1).

1. **Contact stress.** The face moves at one velocity $v_i$ for both rods. Rod 2 is pushed
   from rest to $v_i$, rod 1 braked from $v$ to $v_i$; the two waves carry one force:
   $\rho c\,v_i = \rho c\,(v - v_i)$, so $v_i = v/2$ = {{ si.v_i }} m/s and
   $$\sigma = \rho c\,\frac{v}{2}$$
   = {{ answers.sigma }} ($\rho$ = {{ rho }}, $v$ = {{ v }}).
2. **Contact time.** The wave in rod 1 reaches its free end after $L_1/c$ and reflects
   there as a release wave that stops rod 1's material; back at the face after
   $$t_c = \frac{2L_1}{c}$$
   = {{ answers.t_c }} ($L_1$ = {{ L1 }}) rod 1 is at rest and unloaded, and the rods part.
   Rod 2, longer, has not yet sent anything back to the face.
3. **Rod 2's velocity.** Rod 1 ends at rest, so its momentum $\rho A L_1 v$ has gone to
   rod 2: $v_2 = v\,L_1/L_2$ = {{ answers.v2 }} ($L_2$ = {{ L2 }}).

**Check.** The contact force's impulse $\sigma A\,t_c$ gives rod 2 the velocity
$\sigma t_c/(\rho L_2)$ = {{ checks.impulse_of_the_contact }} m/s, the same; and the pulse
rod 2 carries away, of length $c\,t_c$, holds all of rod 1's kinetic energy.
""",
    solve=solve,
    checks=(
        # impulse and momentum: sigma A t_c = rho A L2 v2
        Recompute("v2", lambda p, s: s["sigma"] * s["t_c"] / (p.rho * p.L2), name="impulse_of_the_contact"),
        # energy: rod 1's kinetic energy ends in rod 2's pulse (per unit area)
        Balance("energy", lambda p, s: p.rho * p.L1 * p.v**2 / 2, _energy_of_the_pulse,
                name="energy_of_the_pulse"),
    ),
    figure=figure,
    parts=(
        Numeric("sigma", "contact stress", question=1, unit="MPa", points=2,
                misconceptions=(
                    Misconception("full speed rho c v", lambda p: p.rho * _c(p) * p.v,
                                  "Rod 2 gives way: the face moves at v/2 and the stress is rho c v/2."),
                    Misconception("dynamic pressure rho v^2", lambda p: p.rho * p.v**2,
                                  "The stress of a wave is rho c times its particle velocity, here v/2."),
                )),
        Numeric("t_c", "contact time", question=2, unit="ms", points=2,
                misconceptions=(
                    Misconception("one way L1/c", lambda p: p.L1 / _c(p),
                                  "The wave has to go to rod 1's free end and back: t_c = 2 L1/c."),
                    Misconception("the longer rod 2 L2/c", lambda p: 2 * p.L2 / _c(p),
                                  "The shorter rod's release wave ends the contact first: t_c = 2 L1/c."),
                )),
        Numeric("v2", "velocity of rod 2's centre of mass", question=3, unit="m/s", points=1,
                misconceptions=(
                    Misconception("the face velocity v/2", lambda p: p.v / 2,
                                  "v/2 is the particle velocity inside the pulse; the momentum rho A L1 v spreads over rod 2: v2 = v L1/L2.",
                                  applies=lambda p: abs(np.log(2 * p.L1 / p.L2)) > 0.02),
                    Misconception("all of v", lambda p: p.v,
                                  "Rod 2 is heavier than rod 1: momentum gives v2 = v L1/L2."),
                )),
    ),
)
