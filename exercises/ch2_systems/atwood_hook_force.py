"""An Atwood machine hanging from a hook: the hook force from the motion of the centre of
mass (Section 2.2.1)."""

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric, Uniform,
                                per_draw)
from dynagrade.exercise.checks import Balance, Recompute
from dynagrade.exercise.figure import arrow, block, ceiling, describe, new_drawing
from dynagrade.mechanics import systems


@per_draw
def solve(p):
    a = systems.atwood_acceleration(p.m1, p.m2, p.g)
    masses = [p.m1, p.m2]
    total = systems.total_mass(masses)
    # r_C is the mass-weighted mean of the positions, so a_C is that of the accelerations
    # (vertical, up positive): m1 goes down with a, m2 up with a
    a_c_up = float(systems.centre_of_mass(masses, [[-a], [a]])[0])
    hook = float(systems.total_external_force(total, a_c_up)) + total * p.g
    return {"a": a, "a_C": -a_c_up, "F": hook, "M_total": total, "W": total * p.g}


def draw(p):
    """Schematic: the hook under the ceiling, the pulley, m1 lower on the left (it will
    descend), m2 on the right, gravity downward."""
    from dynagrade.exercise.figure import Circle

    figure, axes = new_drawing(3.6, 3.6)
    ceiling(axes, -1.2, 1.2, 3.0, hatch=0.12)
    axes.plot([0.0, 0.0], [3.0, 2.3], color="0.1", lw=1.5)              # the hook
    axes.text(0.1, 2.7, "hook", ha="left", va="center", fontsize=9)
    axes.add_patch(Circle((0.0, 2.0), 0.3, facecolor="0.85", edgecolor="0.1", lw=1.2))
    axes.plot([-0.3, -0.3], [2.0, 0.6], color="0.1", lw=1.0)
    axes.plot([0.3, 0.3], [2.0, 1.2], color="0.1", lw=1.0)
    block(axes, (-0.3, 0.35), 0.5, 0.5, "m₁")
    block(axes, (0.3, 0.95), 0.4, 0.4, "m₂", color="C1")
    arrow(axes, (1.0, 1.6), (1.0, 0.9), "g", offset=(0.15, 0.0), color="0.3")
    describe(axes, "A light pulley hangs from a hook under the ceiling; block m₁ hangs on "
             "the left side of the string, block m₂ on the right; gravity points down.")
    axes.set_xlim(-1.3, 1.4)
    axes.set_ylim(-0.1, 3.3)
    return figure


def _string_tension(p):
    """Free body of each block (Section 1.2.1): m1 a = m1 g - T and m2 a = T - m2 g give
    T = 2 m1 m2 g / (m1 + m2)."""
    return 2 * p.m1 * p.m2 * p.g / (p.m1 + p.m2)


EXERCISE = Exercise(
    id="atwood-hook-force",
    title="Atwood machine on a hook: the force that carries it",
    source="Section 2.2.1",
    topics=("balance of linear momentum of a system", "centre of mass", "internal forces"),
    params=(
        Uniform("m1", 2.0, 10.0, step=0.1, unit="kg", symbol="m_1"),
        Uniform("m2", 0.5, 6.0, step=0.1, unit="kg", symbol="m_2"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("m1 is clearly the heavier block (m2 <= 2/3 m1), so that the blocks "
                   "accelerate noticeably", lambda p: p.m2 <= 2 / 3 * p.m1),
    ),
    statement=r"""
Two blocks, $m_1$ = {{ m1 }} and $m_2$ = {{ m2 }}, hang on the two ends of an inextensible,
light string over a light pulley that turns without friction. The pulley's axle hangs from
a hook in the ceiling. The blocks are released from rest ($g$ = {{ g }}).

1. With which acceleration does $m_1$ descend?
2. With which acceleration does the centre of mass of the two blocks move downward?
3. What force does the hook carry while the blocks move?
""",
    solution=r"""
Take the two blocks, the string and the light pulley as one system. The string forces are
internal; the external forces are the weights and the hook force $F$. So the centre of
mass moves as a particle of the total mass $M = m_1 + m_2$ = {{ si.M_total }} kg under
$F - M g$ (balance of linear momentum of a system, Section 2.2.1; $m_1$ = {{ m1 }},
$m_2$ = {{ m2 }}, $g$ = {{ g }}).

1. **The blocks.** Along the string the tension is internal and only the weights drive:
   $(m_1 + m_2)\,a = (m_1 - m_2)\,g$, so $a = \frac{m_1 - m_2}{m_1 + m_2}\,g$ = {{ answers.a }}.
2. **The centre of mass.** $m_1$ goes down with $a$ while $m_2$ goes up with $a$:
   $a_C = \frac{m_1 a - m_2 a}{m_1 + m_2} = \left(\frac{m_1 - m_2}{m_1 + m_2}\right)^2 g$
   = {{ answers.a_C }} downward, smaller than $a$.
3. **The hook.** $M a_C = M g - F$ (down positive), so
   $F = M (g - a_C) = \frac{4 m_1 m_2}{m_1 + m_2}\,g$ = {{ answers.F }}, less than the weight
   $M g$ = {{ si.W }} N of the blocks at rest.
4. **Check.** Each block alone gives the string force $T = 2 m_1 m_2 g/(m_1 + m_2)$; the
   pulley hangs on two strands: $2T$ = {{ checks.two_strands }} N, the hook force again.
""",
    solve=solve,
    checks=(
        # free bodies of the two blocks: the light pulley is held by two strands of tension T
        Recompute("F", lambda p, s: 2 * _string_tension(p), name="two_strands"),
        # a_C from the two accelerations, read from the free body of m1: a = g - T/m1
        Recompute("a_C", lambda p, s: (p.m1 - p.m2) * (p.g - _string_tension(p) / p.m1)
                  / (p.m1 + p.m2), name="weighted_accelerations"),
        Balance("momentum balance of m1 + m2", lambda p, s: (p.m1 + p.m2) * (p.g - s["a_C"]),
                lambda p, s: s["F"], name="hook_balance"),
    ),
    figure=draw,
    parts=(
        Numeric("a", "acceleration of m1", question=1, unit="m/s^2", points=1,
                misconceptions=(
                    Misconception("only m1 accelerated", lambda p: (p.m1 - p.m2) * p.g / p.m1,
                                  "The net weight (m1 − m2) g accelerates both blocks: divide "
                                  "by m1 + m2."),
                )),
        Numeric("a_C", "acceleration of the centre of mass", question=2, unit="m/s^2",
                points=1, misconceptions=(
                    Misconception("the centre of mass moves like the blocks",
                                  lambda p: systems.atwood_acceleration(p.m1, p.m2, p.g),
                                  "One block rises while the other falls: a_C is the "
                                  "mass-weighted mean, (m1 a − m2 a)/(m1 + m2)."),
                )),
        Numeric("F", "hook force", question=3, unit="N", points=2,
                misconceptions=(
                    Misconception("the weight of the blocks at rest",
                                  lambda p: (p.m1 + p.m2) * p.g,
                                  "The centre of mass accelerates downward: F = M (g − a_C) "
                                  "is less than M g (Section 2.2.1)."),
                    Misconception("one strand only", lambda p: _string_tension(p),
                                  "The pulley hangs on both strands: F = 2T."),
                )),
    ),
)
