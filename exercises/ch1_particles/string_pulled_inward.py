"""A particle circling on a frictionless table while its string is pulled in through a
hole: conservation of angular momentum (Example 1.18, eqs. 1.151-1.155)."""

import numpy as np

from dynagrade.exercise import (Constraint, Exercise, Misconception, Numeric, Symbolic,
                                Uniform, apart)
from dynagrade.exercise.checks import Balance, Recompute
from dynagrade.mechanics import angular_momentum as am, energy, kinematics


def solve(p):
    omega1 = am.pulled_string_angular_velocity(p.omega0, p.l0, p.l1)
    v0 = kinematics.circular_speed(p.l0, p.omega0)
    v1 = am.conserved_tangential_speed(v0, p.l0, p.l1)
    return {
        "omega1": omega1,
        "v_ratio": v1 / v0,
        "v0": v0, "v1": v1,
        "W": float(energy.particle_kinetic_energy(p.m, v1) - energy.particle_kinetic_energy(p.m, v0)),
    }


EXERCISE = Exercise(
    id="string-pulled-inward",
    title="Circling mass on a string pulled inward",
    source="Example 1.18",
    topics=("angular momentum balance", "conservation of angular momentum"),
    params=(
        Uniform("m", 0.1, 2.0, step=0.05, unit="kg", symbol="m"),
        Uniform("l0", 0.5, 1.5, step=0.05, unit="m", symbol="l(0)"),
        Uniform("l1", 0.15, 0.9, step=0.05, unit="m", symbol="l_1"),
        Uniform("omega0", 1.0, 6.0, step=0.25, unit="rad/s", symbol=r"\omega(0)"),
    ),
    constraints=(
        # two answers that agree as numbers can be swapped and score (verify's variety rule)
        Constraint("the new angular velocity and the work differ as numbers",
                   lambda p: apart(solve(p)["omega1"], solve(p)["W"])),
        Constraint("the string is pulled in by at least 20 %", lambda p: p.l1 < 0.8 * p.l0),
    ),
    statement="""
A particle of mass $m$ = {{ m }} slides on a frictionless horizontal table, tied to a
string that passes through a hole B in the table. It circles the hole at radius
$l(0)$ = {{ l0 }} with angular velocity $\\omega(0)$ = {{ omega0 }}. The string is then
slowly pulled down until the radius is $l_1$ = {{ l1 }}, and held there.

1. What is the angular velocity at radius $l_1$?
2. By what factor has the circumferential speed $v_t$ changed ($v_t(l_1)/v_t(0)$)?
3. How much work did the pulling force do on the particle?
4. Write the final angular velocity as a formula in $\\omega(0)$ (`omega0`), $l(0)$ (`l0`) and $l_1$ (`l1`).
""",
    solution=r"""
The string force points at the hole B at all times, gravity and the table's normal force
cancel, and the table is frictionless: no force has a moment about B. The angular momentum
balance about the fixed point B, $\dot H_B = M_B = 0$, keeps
$H_B = r_{BP} \times m v_P$ constant (eqs. (1.151), (1.152), Example 1.18). Only the
circumferential velocity $v_t = l\omega$ contributes: $H_B = m\,l\,v_t$ (eq. (1.153)).

1. **Angular velocity.** $m\,l(0)^2\omega(0) = m\,l_1^2\omega_1$, so (eq. (1.155))
   $\omega_1 = \left(\frac{l(0)}{l_1}\right)^2 \omega(0)$.
   With $l(0)$ = {{ l0 }}, $l_1$ = {{ l1 }} and $\omega(0)$ = {{ omega0 }}:
   $\omega_1$ = {{ answers.omega1 }}.
2. **Speed ratio.** $l\,v_t$ is constant (eq. (1.154)), so
   $v_t(l_1)/v_t(0) = l(0)/l_1$ = {{ answers.v_ratio }}: from
   $v_t(0) = l(0)\,\omega(0)$ = {{ si.v0 }} m/s to {{ si.v1 }} m/s.
3. **Work of the pulling force.** Angular momentum is conserved, kinetic energy is not: the
   string force has a component along the (inward) path and does work. By the work–energy
   balance it equals the change of kinetic energy,
   $W = \tfrac{1}{2} m\,(v_t(l_1)^2 - v_t(0)^2)$; with $m$ = {{ m }}: $W$ = {{ answers.W }}.
4. **Formula.** $\omega_1$ = `{{ answers.omega_formula }}`.
""",
    solve=solve,
    checks=(
        # angular momentum about the hole is conserved, eq. (1.154): l v_t = const.
        Balance("angular momentum per unit mass", lambda p, s: p.l0 * p.l0 * p.omega0,
                lambda p, s: p.l1 * p.l1 * s["omega1"], name="angular_momentum"),
        Balance("work", lambda p, s: s["W"], lambda p, s: p.m * (s["v1"]**2 - s["v0"]**2) / 2,
                name="work_energy"),
        # the tangential speed keeps l v_t, eq. (1.154)
        Balance("angular momentum per unit mass, from the speeds", lambda p, s: p.l0 * p.l0 * p.omega0,
                lambda p, s: p.l1 * s["v1"], name="tangential_speed"),
        Recompute("v_ratio", lambda p, s: p.l0 / p.l1, name="speed_ratio"),
    ),
    parts=(
        Numeric("omega1", "final angular velocity", question=1, unit="rad/s", points=2,
                misconceptions=(
                    Misconception("speed kept constant", lambda p: p.omega0 * p.l0 / p.l1,
                                  "It is l v_t that is conserved, and v_t = l ω: ω scales "
                                  "with (l0/l)², eq. (1.155)."),
                    Misconception("angular velocity kept", lambda p: p.omega0,
                                  "No torque about B acts: the angular momentum m l² ω is "
                                  "conserved, not ω."),
                )),
        Numeric("v_ratio", "speed ratio", question=2, points=1,
                misconceptions=(
                    Misconception("squared ratio", lambda p: (p.l0 / p.l1) ** 2,
                                  "v_t ∝ 1/l, eq. (1.154); ω ∝ 1/l²."),
                )),
        Numeric("W", "work of the pulling force", question=3, unit="J", points=1,
                misconceptions=(
                    Misconception("no work", lambda p: 0.0,
                                  "The kinetic energy grows: the pulling force does work, "
                                  "W = T1 − T0."),
                )),
        Symbolic("omega_formula", "final angular velocity as a formula", question=4, points=1,
                 expected="(l0/l1)^2*omega0",
                 variables=("l0", "l1", "omega0"),
                 equals="omega1",
                 misconceptions=(
                     Misconception("speed kept constant", "(l0/l1)*omega0",
                                   "ω scales with the square of the radius ratio."),
                 )),
    ),
)
