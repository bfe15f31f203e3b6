"""An Atwood machine whose pulley has mass: the pulley's angular momentum balance makes
the two rope forces differ (Section 3.2.2)."""

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric,
                                Uniform, per_draw)
from dynagrade.exercise.checks import Balance, Recompute
from dynagrade.exercise.figure import (Circle, block, ceiling, describe, new_drawing)
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import inertia, rigid_kinetics


def _moment(p):
    return inertia.inertia_tensor_disk(p.M, p.R)[2, 2]


def _acceleration(p, moment):
    return rigid_kinetics.atwood_acceleration_with_heavy_pulley(p.m1, p.m2, p.g, p.R, moment)


@per_draw
def solve(p):
    a = _acceleration(p, _moment(p))
    return {
        "a": a,
        "S1": rigid_kinetics.hanging_mass_rope_force(p.m1, p.g, -a),
        "S2": rigid_kinetics.hanging_mass_rope_force(p.m2, p.g, a),
    }


def figure(p):
    """Schematic: the pulley hanging from the ceiling, m1 on the left, m2 on the right."""
    drawing, axes = new_drawing(4.2, 3.4)
    ceiling(axes, -1.2, 1.2, 1.6, hatch=0.08)
    axes.plot([0.0, 0.0], [0.0, 1.6], color="0.1", lw=1.2)
    axes.add_patch(Circle((0.0, 0.0), 0.6, facecolor="#d9c39a", edgecolor="0.1", lw=1.2))
    axes.plot([0.0], [0.0], "o", color="0.1", ms=4)
    # the data beside the bodies, where no rope or edge runs through them
    axes.text(0.7, 0.55, f"M = {format_number(p.M)} kg", ha="left", va="center", fontsize=9)
    axes.text(0.7, 0.3, f"R = {format_number(p.R)} m", ha="left", va="center", fontsize=9)
    axes.plot([-0.6, -0.6], [0.0, -1.9], color="0.1", lw=1.0)
    axes.plot([0.6, 0.6], [0.0, -1.3], color="0.1", lw=1.0)
    block(axes, (-0.6, -2.2), 0.7, 0.6, "m₁", color="#9ab7d3")
    block(axes, (0.6, -1.6), 0.7, 0.6, "m₂", color="#9ab7d3")
    axes.text(-1.05, -2.2, f"m₁ = {format_number(p.m1)} kg", ha="right", va="center", fontsize=9)
    axes.text(1.05, -1.6, f"m₂ = {format_number(p.m2)} kg", ha="left", va="center", fontsize=9)
    describe(axes, "The rope runs over the pulley; m₁ hangs on the left and m₂ on the "
                   "right. Not to scale.")
    axes.set_xlim(-2.4, 2.4)
    axes.set_ylim(-2.7, 1.8)
    return drawing


def _drop_energy(p, s):
    """Work-energy route (Section 3.2.5): after m1 drops h, (m1 - m2) g h equals
    (m1 + m2 + M/2) v^2 / 2, and v^2 / (2 h) is the acceleration (here h = 1 m)."""
    h = 1.0
    v_squared = 2 * (p.m1 - p.m2) * p.g * h / (p.m1 + p.m2 + p.M / 2)
    return v_squared / (2 * h)


EXERCISE = Exercise(
    id="atwood-massive-pulley",
    title="Atwood machine with a heavy pulley",
    source="Section 3.2.2",
    topics=("balance of angular momentum", "fixed-axis rotation", "rope forces"),
    params=(
        Uniform("m1", 2.0, 8.0, step=0.1, unit="kg", symbol="m_1"),
        Uniform("m2", 1.0, 6.0, step=0.1, unit="kg", symbol="m_2"),
        Uniform("M", 0.5, 6.0, step=0.1, unit="kg", symbol="M"),
        Uniform("R", 0.05, 0.2, step=0.01, unit="m", symbol="R"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("m1 is clearly the heavier mass (m1 > 1.2 m2)", lambda p: p.m1 > 1.2 * p.m2),
        Constraint("the two rope forces differ by more than 5 %",
                   lambda p: solve(p)["S1"] > 1.05 * solve(p)["S2"]),
    ),
    statement=r"""
Two blocks hang on a rope over a pulley: $m_1$ = {{ m1 }} on one side,
$m_2$ = {{ m2 }} on the other. The pulley is a homogeneous disk (mass $M$ = {{ M }},
radius $R$ = {{ R }}) turning on a frictionless fixed axle, and the rope does not slip
on it. The system is released from rest ($g$ = {{ g }}).

1. What is the acceleration of the blocks?
2. What is the rope force on $m_1$?
3. What is the rope force on $m_2$?
""",
    solution=r"""
Balance of linear momentum for each block (Section 3.2.1) and balance of angular
momentum of the pulley about its fixed axle (Section 3.2.2). With $m_1$ descending
with $a$, the rope forces $S_1$, $S_2$ and $I = \tfrac{1}{2} M R^2$, rolling of the rope
on the pulley giving $\dot\omega = a/R$:
$$m_1 a = m_1 g - S_1, \qquad m_2 a = S_2 - m_2 g, \qquad
I\,\frac{a}{R} = (S_1 - S_2)\,R .$$

1. **Acceleration.** Adding the three (the last divided by $R$),
   $$a = \frac{(m_1 - m_2)\,g}{m_1 + m_2 + M/2},$$
   with $m_1$ = {{ m1 }}, $m_2$ = {{ m2 }}, $M$ = {{ M }}: $a$ = {{ answers.a }}.
2. **Rope force on $m_1$.** $S_1 = m_1 (g - a)$ = {{ answers.S1 }}.
3. **Rope force on $m_2$.** $S_2 = m_2 (g + a)$ = {{ answers.S2 }}. The two differ by
   $I a/R^2 = \tfrac{1}{2} M a$: the difference is what spins up the pulley.

**Check.** The work-energy balance (Section 3.2.5) gives the same acceleration: after
$m_1$ has dropped a height $h$, $(m_1 - m_2)\,g h = \tfrac{1}{2}(m_1 + m_2 + M/2)\,v^2$,
and $v^2/(2h)$ = {{ checks.work_energy_route }} m/s².
""",
    solve=solve,
    figure=figure,
    checks=(
        # the pulley's balance with the solver's own rope forces: (S1 - S2) R = I a / R
        Balance("pulley", lambda p, s: (s["S1"] - s["S2"]) * p.R,
                lambda p, s: p.M * p.R**2 / 2 * s["a"] / p.R, name="pulley_spin_up"),
        Recompute("a", _drop_energy, name="work_energy_route"),
    ),
    parts=(
        Numeric("a", "acceleration of the blocks", question=1, unit="m/s^2", points=2,
                misconceptions=(
                    Misconception("pulley's inertia forgotten",
                                  lambda p: _acceleration(p, 0.0),
                                  "The pulley spins up too: add I/R² = M/2 to the masses."),
                    Misconception("pulley taken as a ring",
                                  lambda p: _acceleration(p, p.M * p.R**2),
                                  "A homogeneous disk has I = ½ M R², not M R²."),
                )),
        Numeric("S1", "rope force on m1", question=2, unit="N", points=1,
                misconceptions=(
                    Misconception("weight of m1", lambda p: p.m1 * p.g,
                                  "m1 accelerates downward: S1 = m1 (g − a) < m1 g."),
                    Misconception("massless-pulley rope force",
                                  lambda p: 2 * p.m1 * p.m2 * p.g / (p.m1 + p.m2),
                                  "With a heavy pulley the two rope forces differ: use "
                                  "S1 = m1 (g − a) with a of question 1."),
                )),
        Numeric("S2", "rope force on m2", question=3, unit="N", points=1,
                misconceptions=(
                    Misconception("equal rope forces", lambda p: solve(p)["S1"],
                                  "The pulley's angular momentum balance needs S1 > S2."),
                )),
    ),
)
