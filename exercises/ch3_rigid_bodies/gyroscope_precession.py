"""A gyroscope supported at one end of its horizontal axle: precession rate
(Section 3.5.2)."""

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric, Uniform,
                                per_draw)
from dynagrade.exercise.checks import Recompute
from dynagrade.mechanics import gyro, inertia, rigid_kinetics, vibrations


@per_draw
def _spin(p):
    """Spin rate in rad/s from revolutions per time."""
    return 2 * np.pi * p.n


@per_draw
def solve(p):
    disk = inertia.inertia_tensor_disk(p.m, p.R)
    rate = gyro.fast_top_precession_rate(p.m, p.g, p.l, disk[2, 2], _spin(p))
    spin_momentum = rigid_kinetics.rigid_body_angular_momentum(disk, [0.0, 0.0, _spin(p)])[2]
    # one precession revolution takes the period of the rotation at the rate psi_dot
    return {"H": float(spin_momentum), "psi_dot": rate, "T": vibrations.period(rate),
            "omega_spin": _spin(p), "I3": disk[2, 2]}


def _precession(p, solved):
    """The gravity torque m g l turns the spin momentum H = (m R^2 / 2) omega_s around:
    m g l = H psi' for a fast top (Section 3.5.2)."""
    return p.m * p.g * p.l / (p.m * p.R**2 / 2 * 2 * np.pi * p.n)


EXERCISE = Exercise(
    id="gyroscope-precession",
    title="Precession of a gyroscope",
    source="Section 3.5.2",
    topics=("gyroscope", "steady precession", "fast-top approximation"),
    params=(
        Uniform("m", 0.2, 2.0, step=0.05, unit="kg", symbol="m"),
        Uniform("R", 3, 12, step=0.5, unit="cm", symbol="R"),
        Uniform("l", 5, 20, step=0.5, unit="cm", symbol="l"),
        Uniform("n", 1000, 6000, step=100, unit="1/min", symbol="n"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("the gyroscope is fast: spin at least 30 times the precession rate",
                   lambda p: _spin(p) > 30 * solve(p)["psi_dot"]),
    ),
    statement=r"""
A gyroscope consists of a homogeneous disk (mass $m$ = {{ m }}, radius $R$ = {{ R }}) on a
light axle. The axle is horizontal and rests with one end on a pivot; the disk's centre
is at $l$ = {{ l }} from the pivot. The disk spins about the axle at $n$ = {{ n }}
($g$ = {{ g }}). Use the fast-top approximation.

1. What is the spin angular momentum of the disk?
2. With which angular velocity does the axle precess about the vertical?
3. How long does one full precession take?
""",
    solution=r"""
The weight's moment about the pivot turns the spin angular momentum of the disk; in the
fast-top approximation the angular momentum is that of the spin alone, and its rate of
change $\dot\psi\,e_3\times H$ equals the moment (gyroscope, Section 3.5.2).

1. **Spin angular momentum.** The disk spins about its axis of symmetry with
   $\omega_s = 2\pi n$ = {{ si.omega_spin }} rad/s ($n$ = {{ n }}), and its axial moment of
   inertia is $I_3 = \tfrac{1}{2} m R^2$ = {{ si.I3 }} kg·m² ($m$ = {{ m }}, $R$ = {{ R }}). So
   $$H = I_3\,\omega_s = \tfrac{1}{2} m R^2\,\omega_s,$$
   which gives $H$ = {{ answers.H }}.
2. **Precession rate.** The weight acts at $l$ = {{ l }} from the pivot, so its moment is
   $M = m g l$, horizontal and normal to the axle. With the axle horizontal,
   $|\dot H| = \dot\psi H = m g l$:
   $$\dot\psi = \frac{m g l}{I_3\,\omega_s},$$
   and the axle precesses at $\dot\psi$ = {{ answers.psi_dot }}.
3. **Period of precession.** One full turn about the vertical takes
   $$T = \frac{2\pi}{\dot\psi},$$
   that is $T$ = {{ answers.T }}.
""",
    solve=solve,
    checks=(
        Recompute("psi_dot", _precession, name="torque_turns_momentum"),
        Recompute("T", lambda p, s: 2 * np.pi / _precession(p, s), name="one_revolution"),
    ),
    parts=(
        Numeric("H", "spin angular momentum", question=1, unit="kg*m^2/s", points=1,
                misconceptions=(
                    Misconception("spin in revolutions, not radians",
                                  lambda p: inertia.inertia_tensor_disk(p.m, p.R)[2, 2] * p.n,
                                  "Convert the spin to rad/s: ω = 2π n."),
                )),
        Numeric("psi_dot", "precession rate", question=2, unit="rad/s", points=2,
                misconceptions=(
                    Misconception("transverse moment of inertia used",
                                  lambda p: p.m * p.g * p.l
                                  / (inertia.inertia_tensor_disk(p.m, p.R)[0, 0] * _spin(p)),
                                  "The spin angular momentum uses the axial moment ½ m R²."),
                    Misconception("moment of inertia m R^2",
                                  lambda p: p.g * p.l / (p.R**2 * _spin(p)),
                                  "A solid disk has I3 = ½ m R²."),
                )),
        Numeric("T", "precession period", question=3, unit="s", points=1),
    ),
)
