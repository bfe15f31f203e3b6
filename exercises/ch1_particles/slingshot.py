"""An elastic slingshot: release speed from the conservation of energy (Example 1.14,
eqs. 1.124-1.125)."""

import numpy as np

from dynagrade.exercise import (Constraint, Exercise, Misconception, Numeric, Symbolic,
                                Uniform, apart)
from dynagrade.exercise.checks import Integrated
from dynagrade.exercise.figure import describe, dimension, ground, new_drawing, spring
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import energy


def figure(p):
    """The slingshot to scale in centimetres: the fixed point at height l0 above the
    particle's centre, the particle in the slot pulled sideways by dx on the spring, and
    its position below the fixed point (dashed) that it passes after the release
    (Example 1.14). The spring runs from the fixed point to the particle's centre, so at
    the dashed position its drawn length is l0, and l0 is dimensioned to that centre, on
    the slot's centre line y = 0 (it once ran to the slot's floor, which drew the spring
    short by the particle's radius). The slot's upper lip is drawn light, behind the
    spring."""
    from dynagrade.exercise.figure import Circle

    l0, dx = 100 * p.l0, 100 * p.dx
    size = max(l0, dx)
    radius = 0.04 * size
    drawing, axes = new_drawing(5.0, 1.4 + 2.6 * l0 / max(size, dx + 0.3 * size))
    ground(axes, -0.35 * size, dx + 0.2 * size, y=-radius, hatch=size / 40)
    top = (0.0, l0)
    axes.add_patch(Circle(top, 0.025 * size, facecolor="white", edgecolor="0.1", lw=1.0,
                          zorder=3))
    axes.plot([-0.06 * size, 0.06 * size], [l0 + 0.025 * size] * 2, color="0.1", lw=1.6)
    lip = 1.4 * radius
    axes.plot([-0.35 * size, dx + 0.2 * size], [lip, lip], color="0.55", lw=1.0, zorder=0)
    describe(axes, "The particle slides in a smooth horizontal slot, between its floor and "
             "its upper lip drawn in light grey.")
    spring(axes, top, (dx, 0.0), coils=7, width=0.06 * size)
    axes.add_patch(Circle((dx, 0.0), radius, facecolor="C0", edgecolor="0.1", lw=1.0,
                          zorder=3))
    axes.add_patch(Circle((0.0, 0.0), radius, fill=False, edgecolor="0.5", lw=0.8,
                          ls="--"))
    axes.text(dx + 1.6 * radius, 1.2 * radius, f"m = {format_number(p.m)} kg",
              ha="left", va="bottom", fontsize=10)
    axes.text(0.55 * dx + 0.08 * size, 0.5 * l0 + 0.06 * size, f"k = {format_number(p.k)} N/m",
              ha="left", va="bottom", fontsize=10)
    dimension(axes, (0.0, 0.0), top, f"l₀ = {format_number(l0)} cm", offset=0.12 * size,
              tick=0.02 * size)
    dimension(axes, (0.0, -radius), (dx, -radius), f"Δx = {format_number(dx)} cm",
              offset=-0.1 * size, tick=0.02 * size, side=-1.0)
    axes.set_xlim(-0.4 * size, dx + 0.25 * size)
    axes.set_ylim(-0.29 * size, l0 + 0.08 * size)
    return drawing


def solve(p):
    return {"stretch": float(energy.slingshot_stretch(p.dx, p.l0)),
            "V1": float(energy.spring_potential_of_stretch(p.k, energy.slingshot_stretch(p.dx, p.l0))),
            "v": float(energy.slingshot_speed(p.k, p.m, p.dx, p.l0))}


def _in_the_slot(t, y, p):
    """The particle in the slot, pulled by the spring from the point l0 above the slot:
    m x'' = -k (L - l0) x / L with L = sqrt(x^2 + l0^2) (Example 1.14)."""
    length = np.hypot(y[0], p.l0)
    return (y[1], -p.k / p.m * (length - p.l0) * y[0] / length)


EXERCISE = Exercise(
    id="elastic-slingshot",
    title="Elastic slingshot",
    source="Example 1.14",
    topics=("conservation of energy", "spring potential"),
    params=(
        Uniform("m", 0.01, 0.2, step=0.005, unit="kg", symbol="m"),
        Uniform("k", 50, 800, step=10, unit="N/m", symbol="k"),
        Uniform("l0", 5, 30, step=1, unit="cm", symbol="l_0"),
        Uniform("dx", 5, 40, step=1, unit="cm", symbol=r"\Delta x"),
    ),
    constraints=(
        # two answers that agree as numbers can be swapped and score (verify's variety rule)
        Constraint("the stretch in cm and the speed in m/s differ as numbers",
                   lambda p: apart(100 * solve(p)["stretch"], solve(p)["v"])),
        Constraint("taking dx as the stretch is off by more than 5 %",
                   lambda p: energy.slingshot_stretch(p.dx, p.l0) < 0.95 * p.dx),
    ),
    statement="""
A linear spring of stiffness $k$ = {{ k }} and natural length $l_0$ = {{ l0 }} is fixed at
one end to a point at height $l_0$ above a straight horizontal slot; its other end holds a
particle of mass $m$ = {{ m }} that slides without friction in the slot, which holds it
down against the spring's upward pull. The particle starts directly below the fixed
point, is pulled sideways along the slot by $\\Delta x$ = {{ dx }} and released from rest.

1. By how much is the spring stretched before release?
2. How much energy does the spring store then?
3. What is the particle's speed when it passes below the fixed point?
4. Write that speed as a formula in $k$, $m$, $\\Delta x$ (write `dx`) and $l_0$.
""",
    solution=r"""
The slot is smooth and, like gravity, pushes perpendicular to the motion, so the spring
force is the only force doing work, and it is conservative: the energy $T + V$ is conserved
(eq. (1.102), Example 1.14).

1. **Stretch.** Pulled aside by $\Delta x$, the spring reaches from the fixed point at height
   $l_0$ to the particle, so its length is $\sqrt{\Delta x^2 + l_0^2}$ and its stretch
   $\delta = \sqrt{\Delta x^2 + l_0^2} - l_0$.
   With $\Delta x$ = {{ dx }} and $l_0$ = {{ l0 }}: $\delta$ = {{ answers.stretch }}.
2. **Stored energy.** $V_1 = \tfrac{1}{2} k\delta^2$ (eq. (1.124)); with $k$ = {{ k }} and
   $\delta$ = {{ si.stretch }} m: $V_1$ = {{ answers.V1 }}.
3. **Speed below the fixed point.** There the spring has its natural length, $V_2 = 0$.
   $T_1 + V_1 = T_2 + V_2$ with $T_1 = 0$ and $T_2 = \tfrac{1}{2} m v^2$ gives (eq. (1.125))
   $v = \sqrt{\frac{k}{m} }\left(\sqrt{\Delta x^2 + l_0^2} - l_0\right)$;
   with $m$ = {{ m }}: $v$ = {{ answers.v }}. Linear momentum balance would need the
   integration of a force that changes direction and size along the way; the energy
   balance skips it.
4. **Formula.** $v$ = `{{ answers.v_formula }}`.
""",
    solve=solve,
    checks=(
        Integrated("v", _in_the_slot, lambda p: (p.dx, 0.0), lambda p, s: 100 * np.sqrt(p.m / p.k) * (1 + p.dx / p.l0),
                   lambda t, y, p: abs(y[1]), name="integrated_release",
                   event=lambda t, y, p: y[0], direction=-1),
    ),
    figure=figure, figure_to_scale=True,
    parts=(
        Numeric("stretch", "stretch of the spring", question=1, unit="cm", points=1,
                misconceptions=(
                    Misconception("sideways pull taken as the stretch", lambda p: p.dx,
                                  "The spring's new length is √(Δx² + l0²); subtract l0."),
                )),
        Numeric("V1", "stored energy", question=2, unit="J", points=1),
        Numeric("v", "speed below the fixed point", question=3, unit="m/s", points=2,
                misconceptions=(
                    Misconception("sideways pull taken as the stretch",
                                  lambda p: np.sqrt(p.k / p.m) * p.dx,
                                  "The stretch is √(Δx² + l0²) − l0, eq. (1.124)."),
                    Misconception("factor 1/2 on one side only",
                                  lambda p: np.sqrt(2 * p.k / p.m) * energy.slingshot_stretch(p.dx, p.l0),
                                  "Both energies carry a factor 1/2: k s²/2 = m v²/2."),
                )),
        Symbolic("v_formula", "speed as a formula", question=4, points=1,
                 expected="sqrt(k/m)*(sqrt(dx^2 + l0^2) - l0)",
                 variables=("k", "m", "dx", "l0"),
                 equals="v",
                 misconceptions=(
                     Misconception("sideways pull taken as the stretch", "sqrt(k/m)*dx",
                                   "The stretch is √(Δx² + l0²) − l0."),
                 )),
    ),
)
