"""A cart runs into a cart at rest that carries a spring bumper: the largest compression
from the energy of the relative motion (Section 2.2.2)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.checks import Integrated
from dynagrade.exercise.figure import arrow, block, describe, ground, new_drawing, spring
from dynagrade.mechanics import systems


@per_draw
def solve(p):
    v_c = float(systems.centre_of_mass_velocity([p.m1, p.m2], [[p.v0], [0.0]])[0])
    return {
        "v_C": v_c,
        "x_max": float(systems.maximum_spring_compression_between_particles(
            p.m1, p.m2, p.k, p.v0)),
        "V_max": float(systems.relative_kinetic_energy(p.m1, p.m2, p.v0)),
        "T0": float(systems.system_kinetic_energy([p.m1, p.m2], [[p.v0], [0.0]])),
        "mu": float(systems.reduced_mass(p.m1, p.m2)),
    }


def _well_apart(p):
    """The three answers (m/s, m or cm, J) differ by at least 10 %, the compression taken
    in metres and in the centimetres it is asked in."""
    v_c, x_max, v_max = (solve(p)[k] for k in ("v_C", "x_max", "V_max"))
    pairs = [(v_c, v_max)] + [(x, other) for x in (x_max, 100 * x_max) for other in (v_c, v_max)]
    return all(abs(a - b) >= 0.1 * max(a, b) for a, b in pairs)


def draw(p):
    """Schematic: cart 1 moving right with v0 towards cart 2 at rest, whose spring bumper
    faces it."""
    from dynagrade.exercise.figure import Circle

    figure, axes = new_drawing(5.0, 1.9)
    ground(axes, -0.2, 5.2, hatch=0.1)
    for centre, width, label, colour in (((0.8, 0.45), 1.2, "m₁", "C0"),
                                         ((4.0, 0.45), 1.2, "m₂", "C1")):
        block(axes, centre, width, 0.5, label, color=colour)
        for dx in (-0.35, 0.35):
            axes.add_patch(Circle((centre[0] + dx, 0.1), 0.1, facecolor="0.3"))
    spring(axes, (3.4, 0.45), (2.5, 0.45), coils=5, width=0.25)
    axes.plot([2.5, 2.5], [0.3, 0.6], color="0.1", lw=2.0)
    axes.text(2.95, 0.85, "k", ha="center", va="bottom", fontsize=10)
    arrow(axes, (0.4, 1.0), (1.4, 1.0), "v₀", offset=(0.0, 0.18), color="C3")
    describe(axes, "Cart m₁ on the left moves to the right with speed v₀ towards cart m₂, "
             "which is at rest and carries a spring bumper on its left side.")
    axes.set_xlim(-0.3, 5.3)
    axes.set_ylim(-0.3, 1.5)
    return figure


def _carts(t, y, p):
    """Both carts with the bumper force between them while it is compressed
    (y = x1, x2, v1, v2; compression x1 - x2, starting at contact)."""
    force = p.k * max(y[0] - y[1], 0.0)
    return (y[2], y[3], -force / p.m1, force / p.m2)


_CONTACT = dict(start=lambda p: (0.0, 0.0, p.v0, 0.0), horizon=lambda p, s: 10.0,
                event=lambda t, y, p: y[2] - y[3], direction=-1)


EXERCISE = Exercise(
    id="cart-hits-spring-bumper",
    title="A cart runs into a spring bumper: largest compression",
    source="Section 2.2.2",
    topics=("work-energy balance of a system", "relative kinetic energy", "centre of mass"),
    params=(
        Uniform("m1", 0.5, 5.0, step=0.1, unit="kg", symbol="m_1"),
        Uniform("m2", 0.5, 5.0, step=0.1, unit="kg", symbol="m_2"),
        Uniform("v0", 0.5, 4.0, step=0.1, unit="m/s", symbol="v_0"),
        Uniform("k", 200, 5000, step=50, unit="N/m", symbol="k"),
    ),
    constraints=(
        Constraint("the masses differ by at least 15 %, so that the centre-of-mass speed is "
                   "not v0/2", lambda p: abs(p.m1 - p.m2) >= 0.15 * max(p.m1, p.m2)),
        Constraint("the three answers differ by at least 10 %", _well_apart),
    ),
    statement=r"""
Cart 1 ($m_1$ = {{ m1 }}) rolls with speed $v_0$ = {{ v0 }} along a level, frictionless
track towards cart 2 ($m_2$ = {{ m2 }}), which stands at rest and carries a light spring
bumper of stiffness $k$ = {{ k }} on the side facing cart 1.

1. With which speed do the carts move at the instant the spring is compressed most?
2. What is the largest compression of the spring?
3. What is the largest energy stored in the spring?
""",
    solution=r"""
Take both carts and the spring as the system. No external horizontal force acts, so the
momentum $m_1 v_0$ and with it the centre-of-mass velocity stay constant (Section 2.2.1).
The kinetic energy splits as $T = \tfrac{1}{2} M v_C^2 + T'$, and the spring force, being
internal, can only change the part $T' = \tfrac{1}{2}\mu v_{\text{rel} }^2$ of the relative
motion, with the reduced mass $\mu = m_1 m_2/(m_1 + m_2)$ = {{ si.mu }} kg (work-energy
balance, Section 2.2.2; $m_1$ = {{ m1 }}, $m_2$ = {{ m2 }}).

1. **Speed at the largest compression.** The spring stops shortening when the carts no
   longer approach: both move with $v_C = \frac{m_1 v_0}{m_1 + m_2}$ = {{ answers.v_C }}
   ($v_0$ = {{ v0 }}).
2. **Largest compression.** All of $T'$ is then stored:
   $\tfrac{1}{2} k x_{\max}^2 = \tfrac{1}{2}\mu v_0^2$, so $x_{\max} = v_0\sqrt{\mu/k}$
   = {{ answers.x_max }} ($k$ = {{ k }}).
3. **Stored energy.** $V_{\max} = \tfrac{1}{2}\mu v_0^2$ = {{ answers.V_max }}, less than the
   kinetic energy $\tfrac{1}{2} m_1 v_0^2$ = {{ si.T0 }} J of cart 1: the part
   $\tfrac{1}{2}(m_1 + m_2) v_C^2$ stays with the centre of mass.
4. **Check.** Integrating both carts with the bumper force until they stop approaching
   gives the compression {{ checks.integrated_compression }} m.
""",
    solve=solve,
    checks=(
        Integrated("x_max", _carts, read=lambda t, y, p: y[0] - y[1],
                   name="integrated_compression", **_CONTACT),
        Integrated("v_C", _carts, read=lambda t, y, p: y[3], name="integrated_common_speed",
                   **_CONTACT),
    ),
    figure=draw,
    parts=(
        Numeric("v_C", "common speed at the largest compression", question=1, unit="m/s",
                points=1, misconceptions=(
                    Misconception("cart 1 stops", lambda p: 0.0 * p.v0,
                                  "Momentum m1 v0 stays: at the largest compression both carts "
                                  "move with v_C = m1 v0/(m1 + m2)."),
                    Misconception("half the speed", lambda p: p.v0 / 2,
                                  "Only for equal masses is v_C = v0/2."),
                )),
        Numeric("x_max", "largest compression", question=2, unit="cm", points=2,
                misconceptions=(
                    Misconception("all the kinetic energy stored",
                                  lambda p: p.v0 * np.sqrt(p.m1 / p.k),
                                  "Cart 2 is pushed along: only the relative kinetic energy "
                                  "½ μ v0² goes into the spring (Section 2.2.2)."),
                )),
        Numeric("V_max", "largest spring energy", question=3, unit="J", points=1,
                misconceptions=(
                    Misconception("all the kinetic energy stored",
                                  lambda p: p.m1 * p.v0**2 / 2,
                                  "The centre of mass keeps ½ (m1 + m2) v_C²; the spring takes "
                                  "only ½ μ v0²."),
                )),
    ),
)
