"""A puck circling on a table, tied through a hole to a hanging weight: angular momentum
and energy of the pair fix how far in and out it swings (Section 2.2.3)."""

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric, Uniform,
                                per_draw)
from dynagrade.exercise.checks import Balance, Integrated
from dynagrade.exercise.figure import arrow, describe, dimension, new_drawing
from dynagrade.mechanics import angular_momentum, systems


@per_draw
def solve(p):
    H = float(angular_momentum.planar_angular_momentum(p.m1, p.r0, p.v0 / p.r0))
    r_other = float(systems.turning_radius_through_hole(p.m1, p.m2, p.g, H, p.r0))
    return {
        "r_s": float(systems.steady_radius_through_hole(p.m1, p.m2, p.g, H)),
        "r_1": r_other,
        "v_1": float(angular_momentum.conserved_tangential_speed(p.v0, p.r0, r_other)),
        "H": H,
    }


def _distinct(p):
    """The three answers (m, m, m/s) differ by at least 10 % in SI."""
    a, b, c = (solve(p)[k] for k in ("r_s", "r_1", "v_1"))
    return min(abs(a - b) / max(a, b), abs(a - c) / max(a, c), abs(b - c) / max(b, c)) >= 0.1


def draw(p):
    """Schematic side view: the table with the hole, the puck at r0 moving into the page
    (shown by its velocity's symbol), the string through the hole to the hanging weight."""
    from dynagrade.exercise.figure import Circle, Rectangle

    figure, axes = new_drawing(4.6, 3.0)
    axes.add_patch(Rectangle((-3.0, 1.8), 2.85, 0.2, facecolor="0.85", edgecolor="0.1"))
    axes.add_patch(Rectangle((0.15, 1.8), 1.2, 0.2, facecolor="0.85", edgecolor="0.1"))
    axes.add_patch(Circle((-2.0, 2.15), 0.15, facecolor="C0", edgecolor="0.1"))
    axes.text(-2.0, 2.45, "m₁", ha="center", va="bottom", fontsize=11)
    axes.plot([-1.85, 0.0], [2.1, 2.1], color="0.1", lw=1.0)
    axes.plot([0.0, 0.0], [2.1, 0.8], color="0.1", lw=1.0)
    axes.add_patch(Rectangle((-0.25, 0.3), 0.5, 0.5, facecolor="C1", edgecolor="0.1"))
    axes.text(0.4, 0.55, "m₂", ha="left", va="center", fontsize=11)
    dimension(axes, (-2.0, 2.8), (0.0, 2.8), "r₀", tick=0.08, side=1.0)
    axes.text(-2.35, 1.55, "v₀ ⊥ page", ha="center", va="top", fontsize=9)
    arrow(axes, (1.0, 1.3), (1.0, 0.6), "g", offset=(0.15, 0.0), color="0.3")
    describe(axes, "Side view: the puck m₁ slides on the smooth table at the distance r₀ "
             "from the hole; the string runs through the hole down to the hanging block m₂. "
             "The puck's initial velocity v₀ is horizontal and perpendicular to the string "
             "(into the page).")
    axes.set_xlim(-3.1, 1.6)
    axes.set_ylim(0.1, 3.3)
    return figure


def _radial(t, y, p):
    """Equation of motion of the string's length coordinate r (y = r, r'): the puck and
    the weight move together along the string, (m1 + m2) r'' = m1 r phidot^2 - m2 g, with
    phidot = r0 v0 / r^2 from the puck's angular momentum (Section 2.2.3)."""
    phidot = p.r0 * p.v0 / y[0] ** 2
    return (y[1], (p.m1 * y[0] * phidot**2 - p.m2 * p.g) / (p.m1 + p.m2))


def _outward_first(p):
    """+1 if the puck first swings outward (the weight is too light to hold it at r0)."""
    return 1.0 if p.m1 * p.v0**2 / p.r0 > p.m2 * p.g else -1.0


EXERCISE = Exercise(
    id="string-through-a-table-hole",
    title="A puck on a table tied through a hole to a hanging weight",
    source="Section 2.2.3",
    topics=("balance of angular momentum of a system", "work-energy balance of a system",
            "central force"),
    params=(
        Uniform("m1", 0.2, 2.0, step=0.05, unit="kg", symbol="m_1"),
        Uniform("m2", 0.2, 2.0, step=0.05, unit="kg", symbol="m_2"),
        Uniform("r0", 0.2, 0.8, step=0.02, unit="m", symbol="r_0"),
        Uniform("v0", 0.5, 4.0, step=0.1, unit="m/s", symbol="v_0"),
        Constant("l", 2.0, unit="m", symbol="l"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("the start is clearly off the steady circle (r0/r_s outside 0.8 ... 1.25)",
                   lambda p: not 0.8 < p.r0 / solve(p)["r_s"] < 1.25),
        Constraint("the puck stays on the table and the weight below it: the other turning "
                   "radius lies between 5 cm and 0.9 l",
                   lambda p: 0.05 < solve(p)["r_1"] < 0.9 * p.l),
        Constraint("the three answers differ by at least 10 % in SI", _distinct),
    ),
    statement=r"""
A puck of mass $m_1$ = {{ m1 }} slides on a smooth horizontal table. A light string of
length $l$ = {{ l }} runs from it through a small smooth hole in the table to a block of
mass $m_2$ = {{ m2 }} that hangs freely below. The puck is launched at the distance
$r_0$ = {{ r0 }} from the hole with the speed $v_0$ = {{ v0 }} perpendicular to the string;
the block is at rest at that instant. The string stays taut throughout, the puck never
reaches the hole and the block never reaches the table ($g$ = {{ g }}).

1. At which radius could the puck circle steadily with the same angular momentum about
   the hole?
2. Between $r_0$ and which other radius does the puck swing in and out?
3. What is the puck's speed at that other radius?
""",
    solution=r"""
Take puck, string and block as the system. The weights, the normal force of the table and
the hole's force on the string have no moment about the vertical through the hole, so
the angular momentum about that axis stays: $H = m_1 r^2\dot\varphi = m_1 r_0 v_0$
= {{ si.H }} kg·m²/s (balance of angular momentum of a system, Section 2.2.3; the block
moves vertically and adds nothing). The string does no work in total (it is inextensible),
so the energy of the system is conserved (Section 2.2.2):
$$\tfrac{1}{2}(m_1 + m_2)\,\dot r^2 + \frac{H^2}{2 m_1 r^2} + m_2 g r = \text{const},$$
with $m_1$ = {{ m1 }}, $m_2$ = {{ m2 }}, $r_0$ = {{ r0 }}, $v_0$ = {{ v0 }}, $g$ = {{ g }}.

1. **Steady circle.** The string force $m_2 g$ then supplies the centripetal force:
   $m_2 g = m_1 r\dot\varphi^2 = H^2/(m_1 r^3)$, so $r_s = \left(\frac{H^2}{m_1 m_2 g}\right)^{1/3}$
   = {{ answers.r_s }}.
2. **Other turning radius.** There $\dot r = 0$ again: the energy equation with $\dot r = 0$ at
   $r_0$ and at $r_1$ gives, after dividing by $r_1 - r_0$,
   $2 m_1 m_2 g\,r_0^2 r_1^2 - H^2 r_1 - H^2 r_0 = 0$, whose positive root is
   $r_1$ = {{ answers.r_1 }}, on the other side of $r_s$ from $r_0$.
3. **Speed.** At a turning radius the velocity is perpendicular to the string, so
   $v_1 = H/(m_1 r_1) = v_0 r_0/r_1$ = {{ answers.v_1 }}.
4. **Check.** Integrating $(m_1 + m_2)\,\ddot r = H^2/(m_1 r^3) - m_2 g$ from $r_0$ until $\dot r$
   vanishes again gives $r_1$ = {{ checks.integrated_turning_radius }} m.
""",
    solve=solve,
    checks=(
        Integrated("r_1", _radial, lambda p: (p.r0, 0.0), lambda p, s: 20.0,
                   lambda t, y, p: y[0], name="integrated_turning_radius",
                   event=lambda t, y, p: _outward_first(p) * y[1], direction=-1, rtol=1e-6),
        Balance("energy at the two turning radii",
                lambda p, s: p.m1 * p.v0**2 / 2 + p.m2 * p.g * p.r0,
                lambda p, s: p.m1 * s["v_1"] ** 2 / 2 + p.m2 * p.g * s["r_1"],
                name="energy_balance"),
    ),
    figure=draw,
    parts=(
        Numeric("r_s", "radius of steady circling", question=1, unit="m", points=1,
                misconceptions=(
                    Misconception("both masses in the centripetal force",
                                  lambda p: np.cbrt((p.m1 * p.r0 * p.v0) ** 2
                                                    / ((p.m1 + p.m2) * p.m1 * p.g)),
                                  "Only the puck circles; the string force m2 g pulls it in: "
                                  "m2 g = H²/(m1 r³)."),
                )),
        Numeric("r_1", "other turning radius", question=2, unit="m", points=2,
                misconceptions=(
                    Misconception("mirror of r0 about the steady radius",
                                  lambda p: 2 * solve(p)["r_s"] - p.r0,
                                  "The effective potential H²/(2 m1 r²) + m2 g r is not "
                                  "symmetric about r_s: solve the energy equation.",
                                  applies=lambda p: abs(2 * solve(p)["r_s"] - p.r0
                                                        - solve(p)["r_1"]) > 0.03 * solve(p)["r_1"]),
                )),
        Numeric("v_1", "speed at the other turning radius", question=3, unit="m/s", points=1,
                misconceptions=(
                    Misconception("speed unchanged", lambda p: p.v0,
                                  "The angular momentum m1 r v stays, so v = v0 r0/r1."),
                )),
    ),
)
