"""A block on a rough table pulled by a hanging block: the work-energy balance of the pair
(Section 2.2.2)."""

import itertools

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric, Uniform,
                                per_draw)
from dynagrade.exercise.checks import Balance, Integrated
from dynagrade.exercise.figure import arrow, block, describe, dimension, new_drawing
from dynagrade.mechanics import energy


@per_draw
def solve(p):
    friction = float(energy.friction_work_on_floor(p.mu, p.m1, p.g, p.s))     # negative
    gravity = float(energy.work_from_potential(p.m2 * p.g * p.s, 0.0))
    v = float(energy.speed_after_work(p.m1 + p.m2, 0.0, gravity + friction))
    return {
        "v": v,
        "D": -friction,
        # block 1 alone: the string's work is its kinetic energy plus what friction took
        "W_T": float(energy.particle_kinetic_energy(p.m1, v)) - friction,
        "W_g": gravity,
    }


def _answers_differ(p):
    """No two answers (a speed and two works, all in SI) within 8 % of each other."""
    values = [solve(p)[k] for k in ("v", "D", "W_T")]
    return all(abs(a - b) > 0.08 * max(a, b) for a, b in itertools.combinations(values, 2))


def draw(p):
    """Schematic: block 1 on the table, the string over the pulley at the edge, block 2
    hanging, the drop s of block 2."""
    from dynagrade.exercise.figure import Circle, Rectangle

    figure, axes = new_drawing(4.6, 3.0)
    axes.add_patch(Rectangle((-2.5, 0.0), 3.0, 2.0, facecolor="0.9", edgecolor="0.1"))
    axes.text(-1.0, 1.0, "table", ha="center", va="center", fontsize=9, color="0.4")
    block(axes, (-1.4, 2.3), 0.8, 0.6, "m₁")
    axes.text(-1.4, 1.85, "μ", ha="center", va="center", fontsize=10)
    axes.add_patch(Circle((0.7, 2.2), 0.2, facecolor="0.85", edgecolor="0.1", lw=1.2))
    axes.plot([-1.0, 0.7], [2.4, 2.4], color="0.1", lw=1.0)
    axes.plot([0.9, 0.9], [2.2, 1.1], color="0.1", lw=1.0)
    block(axes, (0.9, 0.8), 0.5, 0.6, "m₂", color="C1")
    dimension(axes, (1.5, 1.1), (1.5, 0.1), "s", tick=0.08, side=-1.0)
    arrow(axes, (-2.2, 3.1), (-2.2, 2.5), "g", offset=(-0.15, 0.0), color="0.3")
    describe(axes, "Block m₁ rests on the rough top of the table; the string runs "
             "horizontally from it over a pulley at the right edge down to block m₂, "
             "which descends the distance s.")
    axes.set_xlim(-2.6, 2.0)
    axes.set_ylim(-0.1, 3.3)
    return figure


def _falling_pair(t, y, p):
    """Equations of motion of the two blocks, each with its own free body: m1 x'' = T -
    mu m1 g and m2 x'' = m2 g - T, with T eliminated (Section 1.2.1)."""
    return (y[1], (p.m2 - p.mu * p.m1) * p.g / (p.m1 + p.m2))


EXERCISE = Exercise(
    id="block-pulled-over-a-table-edge",
    title="A hanging block pulls a block across a rough table",
    source="Section 2.2.2",
    topics=("work-energy balance of a system", "friction", "internal forces"),
    params=(
        Uniform("m1", 1.0, 8.0, step=0.1, unit="kg", symbol="m_1"),
        Uniform("m2", 0.5, 5.0, step=0.1, unit="kg", symbol="m_2"),
        Uniform("mu", 0.1, 0.6, step=0.02, symbol=r"\mu"),
        Uniform("s", 0.2, 2.0, step=0.05, unit="m", symbol="s"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("the hanging weight clearly overcomes friction (m2 >= 1.3 mu m1), so the "
                   "blocks start to move", lambda p: p.m2 >= 1.3 * p.mu * p.m1),
        Constraint("friction matters (mu m1 >= 0.2 m2) and the blocks accelerate with at "
                   "least 0.05 g", lambda p: p.mu * p.m1 >= 0.2 * p.m2
                   and p.m2 - p.mu * p.m1 >= 0.05 * (p.m1 + p.m2)),
        Constraint("the three answers differ by more than 8 %", _answers_differ),
    ),
    statement=r"""
Block 1 ($m_1$ = {{ m1 }}) lies on a rough horizontal table (coefficient of friction
$\mu$ = {{ mu }} for sliding and sticking alike). A light, inextensible string runs from it
horizontally over a light pulley at the table's edge to block 2 ($m_2$ = {{ m2 }}), which
hangs freely. Since $m_2 > \mu m_1$ the blocks start to move when released from rest.
Block 2 descends the distance $s$ = {{ s }} ($g$ = {{ g }}).

1. What is the speed of the blocks then?
2. How much energy has friction dissipated?
3. How much work has the string done on block 1?
""",
    solution=r"""
Take both blocks and the string as the system. The string is inextensible: it pulls
block 1 forward and block 2 back with the same force, and both move the same distance, so
the string's internal forces do no work in total. The work-energy balance of the system
(Section 2.2.2) then only has the external forces' work: gravity on block 2,
$m_2 g s$ = {{ si.W_g }} J, and friction on block 1 ($m_1$ = {{ m1 }}, $m_2$ = {{ m2 }},
$\mu$ = {{ mu }}, $s$ = {{ s }}, $g$ = {{ g }}).

1. **Speed.** Both blocks move with one speed $v$:
   $\tfrac{1}{2}(m_1 + m_2)\,v^2 = m_2 g s - \mu m_1 g s$, so
   $v = \sqrt{2 g s\,(m_2 - \mu m_1)/(m_1 + m_2)}$ = {{ answers.v }}.
2. **Friction.** The normal force on block 1 is $m_1 g$, so friction dissipates
   $\mu m_1 g s$ = {{ answers.D }}.
3. **String on block 1.** For block 1 alone the string force is external; its
   work-energy balance reads $W_T - \mu m_1 g s = \tfrac{1}{2} m_1 v^2$, so
   $W_T$ = {{ answers.W_T }}. The string does the same work negatively on block 2: the two
   cancel, as step 1 assumed.
4. **Check.** Integrating $(m_1 + m_2)\,\ddot x = (m_2 - \mu m_1)\,g$ until $x = s$ gives
   $v$ = {{ checks.integrated_speed }} m/s again.
""",
    solve=solve,
    checks=(
        Integrated("v", _falling_pair, lambda p: (0.0, 0.0), lambda p, s: 10.0,
                   lambda t, y, p: y[1], name="integrated_speed",
                   event=lambda t, y, p: y[0] - p.s, direction=1),
        # the string force from block 2's free body, T = m2 (g - a), times the distance
        Balance("work of the string on block 1", lambda p, s: s["W_T"],
                lambda p, s: p.m2 * (p.g - s["v"] ** 2 / (2 * p.s)) * p.s,
                name="tension_times_distance"),
    ),
    figure=draw,
    parts=(
        Numeric("v", "speed of the blocks", question=1, unit="m/s", points=2,
                misconceptions=(
                    Misconception("only block 2 set in motion",
                                  lambda p: np.sqrt(2 * p.g * p.s * (p.m2 - p.mu * p.m1) / p.m2),
                                  "Both blocks move with the same speed: the kinetic energy "
                                  "is ½ (m1 + m2) v²."),
                    Misconception("friction forgotten",
                                  lambda p: np.sqrt(2 * p.g * p.s * p.m2 / (p.m1 + p.m2)),
                                  "Friction on block 1 does the work −μ m1 g s (eq. (1.89))."),
                )),
        Numeric("D", "energy dissipated by friction", question=2, unit="J", points=1,
                misconceptions=(
                    Misconception("normal force of both blocks",
                                  lambda p: p.mu * (p.m1 + p.m2) * p.g * p.s,
                                  "Only block 1 presses on the table: N = m1 g."),
                )),
        Numeric("W_T", "work of the string on block 1", question=3, unit="J", points=1,
                misconceptions=(
                    Misconception("string force taken as the weight of block 2",
                                  lambda p: p.m2 * p.g * p.s,
                                  "Block 2 accelerates, so the string force is less than "
                                  "m2 g: T = m2 (g − a)."),
                )),
    ),
)
