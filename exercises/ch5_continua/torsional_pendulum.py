"""A disk on a wire or shaft: torsional stiffness and the torsional pendulum (Section 5.1)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.checks import Recompute
from dynagrade.mechanics import inertia, stiffness, vibrations


def k_t(p, polar=True):
    section = stiffness.circle_polar_moment(p.d) if polar else stiffness.circle_second_moment(p.d)
    return stiffness.torsional_stiffness(stiffness.shear_modulus(p.E, p.nu), section, p.L)


def _J(p):
    return inertia.inertia_tensor_disk(p.m, p.R)[2, 2]


@per_draw
def _period(p):
    return vibrations.period(vibrations.natural_frequency(k_t(p), _J(p)))


def solve(p):
    return {"kt": k_t(p), "T": _period(p), "G": stiffness.shear_modulus(p.E, p.nu),
            "I_p": stiffness.circle_polar_moment(p.d), "J": _J(p)}


EXERCISE = Exercise(
    id="torsional-pendulum-shaft",
    title="Torsional pendulum: a disk on a shaft",
    source="Section 5.1",
    topics=("torsional stiffness", "shear modulus", "torsional vibration"),
    params=(
        Uniform("E", 70, 210, step=10, unit="GPa", symbol="E"),
        Uniform("nu", 0.25, 0.35, step=0.01, symbol=r"\nu"),
        Uniform("d", 2, 20, step=0.5, unit="mm", symbol="d"),
        Uniform("L", 0.3, 2.0, step=0.05, unit="m", symbol="L"),
        Uniform("m", 1, 30, step=0.5, unit="kg", symbol="m"),
        Uniform("R", 0.05, 0.4, step=0.01, unit="m", symbol="R"),
    ),
    constraints=(
        Constraint("a period between 0.05 s and 20 s",
                   lambda p: 0.05 <= _period(p) <= 20),
    ),
    statement="""
A homogeneous disk (mass $m$ = {{ m }}, radius $R$ = {{ R }}) hangs at the lower end of a
vertical circular rod of diameter $d$ = {{ d }} and length $L$ = {{ L }}, clamped at its
top. The rod's material has $E$ = {{ E }} and Poisson's ratio $\\nu$ = {{ nu }}. Neglect
the rod's mass.

1. What is the torsional stiffness $k_t$ of the rod?
2. What is the period of the disk's torsional oscillations?
""",
    solution=r"""
The massless rod is a torsional spring; the disk a rigid body turning about the rod's
axis: $J\ddot\varphi + k_t\varphi = 0$ (torsional stiffness, Section 5.1).

1. **Torsional stiffness.** A rod of length $L$ twisted by $\varphi$ carries the torque
   $G I_p\,\varphi/L$, so
   $$k_t = \frac{G I_p}{L},\qquad G = \frac{E}{2(1 + \nu)},\qquad I_p = \frac{\pi}{2}\Bigl(\frac d2\Bigr)^4 .$$
   With $E$ = {{ E }} and $\nu$ = {{ nu }}: $G$ = {{ si.G }} Pa; with $d$ = {{ d }}:
   $I_p$ = {{ si.I_p }} m⁴; with $L$ = {{ L }}: $k_t$ = {{ answers.kt }}. (The polar
   moment, not the bending moment of area $I_p/2$.)
2. **Period.** The disk has $J = \tfrac{1}{2} m R^2$ = {{ si.J }} kg·m² ($m$ = {{ m }},
   $R$ = {{ R }}), so $\omega = \sqrt{k_t/J}$ and
   $$T = 2\pi\sqrt{\frac{J}{k_t} },$$
   that is $T$ = {{ answers.T }}.
""",
    solve=solve,
    checks=(
        # k_t = G (pi d^4 / 32) / L with G = E / (2 (1 + nu)), J = m R^2 / 2 (Section 5.1)
        Recompute("T", lambda p, s: 2 * np.pi * np.sqrt(
            p.m * p.R**2 / 2 / (p.E / (2 * (1 + p.nu)) * np.pi * p.d**4 / 32 / p.L)),
                  name="period_by_hand"),
    ),
    parts=(
        Numeric("kt", "torsional stiffness", question=1, unit="N*m", points=2,
                misconceptions=(
                    Misconception("E for G", lambda p: stiffness.torsional_stiffness(p.E, stiffness.circle_polar_moment(p.d), p.L),
                                  "Torsion is resisted by the shear modulus G = E/(2(1 + nu))."),
                    Misconception("I for I_p", lambda p: k_t(p, polar=False), "Use the polar moment I_p = pi d^4/32."),
                )),
        Numeric("T", "period", question=2, unit="s", points=2,
                misconceptions=(
                    Misconception("J = m R^2", lambda p: vibrations.period(vibrations.natural_frequency(k_t(p), p.m * p.R**2)),
                                  "A solid disk has J = m R^2/2."),
                    Misconception("1/omega", lambda p: 1 / vibrations.natural_frequency(k_t(p), p.m * p.R**2 / 2),
                                  "T = 2 pi / omega."),
                )),
    ),
)
