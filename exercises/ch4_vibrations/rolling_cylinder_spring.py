"""A cylinder rolling on a spring: equivalent mass and stiffness of a one-degree-of-freedom
system and its natural frequency (Section 4.3.1)."""

import numpy as np

from dynagrade.exercise import (Constraint, Exercise, Misconception, Numeric, Symbolic, Uniform,
                                per_draw)
from dynagrade.exercise.checks import Recompute
from dynagrade.mechanics import inertia, vibrations


@per_draw
def m_eq(p):
    # x' for the translation, phi' = x'/r for the rotation (J = m r^2 / 2)
    return vibrations.equivalent_mass([p.m, inertia.inertia_tensor_disk(p.m, p.r)[2, 2]],
                                      [1.0, 1.0 / p.r])


@per_draw
def k_eq(p):
    # a spring attached at height a above the centre stretches by (r + a)/r per unit x
    return vibrations.equivalent_stiffness([p.k], [(p.r + p.a) / p.r])


def solve(p):
    w = vibrations.natural_frequency(k_eq(p), m_eq(p))
    return {"m_eq": m_eq(p), "k_eq": k_eq(p), "omega": w, "f": vibrations.frequency_in_hertz(w)}


EXERCISE = Exercise(
    id="rolling-cylinder-spring",
    title="Rolling cylinder on a spring: equivalent mass and stiffness",
    source="Section 4.3.1",
    topics=("equivalent mass", "equivalent stiffness", "natural frequency", "rolling"),
    params=(
        Uniform("m", 1.0, 20.0, step=0.5, unit="kg", symbol="m"),
        Uniform("r", 0.05, 0.3, step=0.01, unit="m", symbol="r"),
        Uniform("a", 0.0, 0.3, step=0.01, unit="m", symbol="a"),
        Uniform("k", 100, 5000, step=50, unit="N/m", symbol="k"),
    ),
    constraints=(
        Constraint("the attachment point lies on the cylinder, at least 0.2 r above the centre",
                   lambda p: 0.2 * p.r - 1e-12 <= p.a <= p.r + 1e-12),
        # at a = 0.22 r the lever (k_eq = 3k/2) cancels the rolling inertia (m_eq = 3m/2)
        Constraint("omega differs from sqrt(k/m) by at least 3 %",
                   lambda p: abs(k_eq(p) / m_eq(p) / (p.k / p.m) - 1) >= 0.06),
    ),
    statement="""
A solid homogeneous cylinder (mass $m$ = {{ m }}, radius $r$ = {{ r }}) rolls without
slipping on a horizontal floor. A horizontal spring of stiffness $k$ = {{ k }}, fixed to a
wall, is pinned to the cylinder's end face at the height $a$ = {{ a }} above the axis,
vertically above the centre when the spring is relaxed. Let $x$ be the displacement of the
centre; consider small motions.

1. What is the equivalent mass $m_{eq}$ (with $T = m_{eq}\\dot x^2/2$)?
2. What is the equivalent stiffness $k_{eq}$ (with $V = k_{eq} x^2/2$)?
3. What are the natural angular frequency and the natural frequency in Hz?
4. Give $\\omega$ as a formula in `k`, `m`, `r`, `a`.
""",
    solution=r"""
A one-degree-of-freedom system in the coordinate $x$: write the kinetic and potential
energies as $T = \tfrac{1}{2} m_{eq}\dot x^2$ and $V = \tfrac{1}{2} k_{eq} x^2$; then
$\omega = \sqrt{k_{eq}/m_{eq} }$ (equivalent mass and stiffness, Section 4.3.1).

1. **Equivalent mass.** Rolling without slipping ties the rotation to the translation,
   $\dot\varphi = \dot x/r$, and the solid cylinder has $J = \tfrac{1}{2} m r^2$:
   $$T = \tfrac{1}{2} m\dot x^2 + \tfrac{1}{2}\cdot\tfrac{1}{2} m r^2\Bigl(\frac{\dot x}{r}\Bigr)^2
   = \tfrac{1}{2}\cdot\tfrac{3}{2} m\,\dot x^2,$$
   so $m_{eq} = \tfrac{3}{2} m$ = {{ answers.m_eq }} ($m$ = {{ m }}).
2. **Equivalent stiffness.** The contact point is the instantaneous centre, so a point at
   height $r + a$ above it moves $x\,(r + a)/r$ horizontally for small motions. The spring
   is stretched that much:
   $$V = \tfrac{1}{2} k\Bigl(\frac{r + a}{r}\Bigr)^2 x^2,\qquad k_{eq} = k\Bigl(\frac{r + a}{r}\Bigr)^2,$$
   so with $k$ = {{ k }}, $r$ = {{ r }} and $a$ = {{ a }}: $k_{eq}$ = {{ answers.k_eq }}.
3. **Natural frequency.** $\omega = \sqrt{k_{eq}/m_{eq} }$ = {{ answers.omega }} and
   $f = \omega/(2\pi)$ = {{ answers.f }}.
4. **As a formula.** $$\omega = \frac{r + a}{r}\sqrt{\frac{2k}{3m} },$$ written as
   `{{ answers.omega_formula }}`.
""",
    solve=solve,
    checks=(
        # T = (m + (m r^2 / 2) / r^2) x'^2 / 2, V = k ((r + a) x / r)^2 / 2 (Section 4.3.1)
        Recompute("omega", lambda p, s: np.sqrt(p.k * ((p.r + p.a) / p.r) ** 2 / (1.5 * p.m)),
                  name="energy_route"),
        Recompute("m_eq", lambda p, s: 1.5 * p.m, name="rolling_mass"),
    ),
    parts=(
        Numeric("m_eq", "equivalent mass", question=1, unit="kg", points=1,
                misconceptions=(
                    Misconception("rotation forgotten", lambda p: p.m,
                                  "The rolling cylinder also stores J phi'^2/2 = m x'^2/4."),
                    Misconception("J = m r^2 (thin ring)", lambda p: 2 * p.m,
                                  "A solid cylinder has J = m r^2/2 about its axis."),
                )),
        Numeric("k_eq", "equivalent stiffness", question=2, unit="N/m", points=1,
                misconceptions=(
                    Misconception("spring at the centre", lambda p: p.k,
                                  "The attachment point moves (r + a)/r times as far as the centre."),
                    Misconception("ratio not squared", lambda p: p.k * (p.r + p.a) / p.r,
                                  "V = k (u)^2/2 with u = (r + a) x / r: the ratio enters squared."),
                )),
        Numeric("omega", "natural angular frequency", question=3, unit="rad/s", points=1,
                misconceptions=(
                    Misconception("sqrt(k/m)", lambda p: np.sqrt(p.k / p.m),
                                  "Use the equivalent mass and stiffness of the whole system."),
                    Misconception("f for omega", lambda p: vibrations.natural_frequency(k_eq(p), m_eq(p)) / (2 * np.pi),
                                  "omega is in rad/s; f = omega/(2 pi)."),
                )),
        Numeric("f", "natural frequency", question=3, unit="Hz", points=1,
                misconceptions=(Misconception("omega for f", lambda p: vibrations.natural_frequency(k_eq(p), m_eq(p)),
                                              "f = omega/(2 pi)."),)),
        Symbolic("omega_formula", "omega as a formula", question=4, points=1,
                 expected="(r + a)/r*sqrt(2*k/(3*m))",
                 variables=("k", "m", "r", "a"),
                 equals="omega"),
    ),
)
