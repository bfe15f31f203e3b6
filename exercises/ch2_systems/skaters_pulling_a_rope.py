"""Two skaters spinning on a rope pull themselves together: the angular momentum about the
centre of mass stays, the kinetic energy grows (Section 2.2.3)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.checks import Balance, Recompute
from dynagrade.exercise.figure import describe, dimension, new_drawing
from dynagrade.mechanics import angular_momentum, systems


def _pair(p, L, omega):
    """Masses, positions and velocities of the skaters L apart on e1, spinning
    counter-clockwise with omega about their centre of mass (which is at rest)."""
    masses = [p.m1, p.m2]
    r = np.array([[0.0, 0.0], [L, 0.0]])
    rho = systems.positions_relative_to_centre_of_mass(masses, r)
    v = omega * np.column_stack((-rho[:, 1], rho[:, 0]))
    return masses, r, v


def _moment(p, L):
    """Moment of inertia of the pair about C: its angular momentum per unit spin."""
    return float(systems.angular_momentum_about_centre_of_mass(*_pair(p, L, 1.0))[2])


@per_draw
def solve(p):
    omega2 = float(angular_momentum.conserved_angular_velocity(p.omega1, _moment(p, p.L1),
                                                               _moment(p, p.L2)))
    masses, _, v_before = _pair(p, p.L1, p.omega1)
    before = systems.system_kinetic_energy(masses, v_before)
    _, _, v = _pair(p, p.L2, omega2)
    after = systems.system_kinetic_energy(masses, v)
    return {
        "omega2": omega2,
        "v1": float(np.linalg.norm(v[0])),
        "W": after - before,
        "H_C": float(systems.angular_momentum_about_centre_of_mass(
            *_pair(p, p.L1, p.omega1))[2]),
        "T1": before, "T2": after,
    }


def _distinct(p):
    """The three answers (rad/s, m/s, J) differ by at least 10 % in SI."""
    a, b, c = (solve(p)[k] for k in ("omega2", "v1", "W"))
    return min(abs(a - b) / max(a, b), abs(a - c) / max(a, c), abs(b - c) / max(b, c)) >= 0.1


def draw(p):
    """Schematic top view: the two skaters on the rope, their centre of mass C nearer the
    heavier one, the counter-clockwise spin omega1 and the rope length L1."""
    from dynagrade.exercise.figure import Circle

    figure, axes = new_drawing(4.8, 2.6)
    x_c = p.m2 / (p.m1 + p.m2) * 4.0
    axes.plot([0.0, 4.0], [0.0, 0.0], color="0.3", lw=1.2)
    for x, label in ((0.0, "m₁"), (4.0, "m₂")):
        axes.add_patch(Circle((x, 0.0), 0.25, facecolor="C0", edgecolor="0.1"))
        axes.text(x, 0.45, label, ha="center", va="bottom", fontsize=11)
    axes.add_patch(Circle((x_c, 0.0), 0.07, facecolor="white", edgecolor="0.1", zorder=4))
    axes.text(x_c, -0.25, "C", ha="center", va="top", fontsize=10)
    axes.annotate("", xy=(x_c - 0.35, 0.55), xytext=(x_c + 0.35, 0.55),
                  arrowprops={"arrowstyle": "-|>", "connectionstyle": "arc3,rad=0.5",
                              "color": "#23802a"})
    axes.text(x_c, 0.95, "ω₁", color="#23802a", ha="center", va="bottom", fontsize=11)
    dimension(axes, (0.0, -0.7), (4.0, -0.7), "L₁", tick=0.08, side=-1.0)
    describe(axes, "Top view: the skaters m₁ (left) and m₂ (right) hold the ends of the rope "
             "and spin counter-clockwise about their centre of mass C.")
    axes.set_xlim(-0.6, 4.6)
    axes.set_ylim(-1.3, 1.3)
    return figure


def _tension_work(p, solved):
    """Work the skaters do on the rope, from its tension: the relative motion is that of
    one particle of mass mu = m1 m2/(m1 + m2) on a string of length L, pulled with
    T = mu L omega^2 while omega = omega1 L1^2/L^2 (Section 2.2.3): W = int_L2^L1 T dL."""
    from scipy.integrate import quad

    mu = p.m1 * p.m2 / (p.m1 + p.m2)
    return quad(lambda L: mu * L * (p.omega1 * p.L1**2 / L**2) ** 2, p.L2, p.L1,
                epsabs=0.0, epsrel=1e-11)[0]


EXERCISE = Exercise(
    id="skaters-pulling-a-rope",
    title="Two skaters on a rope pull themselves together",
    source="Section 2.2.3",
    topics=("balance of angular momentum of a system", "centre of mass",
            "work of internal forces"),
    params=(
        Uniform("m1", 50, 100, step=1, unit="kg", symbol="m_1"),
        Uniform("m2", 40, 90, step=1, unit="kg", symbol="m_2"),
        Uniform("L1", 4.0, 10.0, step=0.1, unit="m", symbol="L_1"),
        Uniform("L2", 1.5, 3.5, step=0.1, unit="m", symbol="L_2"),
        Uniform("omega1", 0.2, 0.8, step=0.05, unit="rad/s", symbol=r"\omega_1"),
    ),
    constraints=(
        Constraint("the masses differ by at least 15 %, so that C is off the rope's middle",
                   lambda p: abs(p.m1 - p.m2) >= 0.15 * max(p.m1, p.m2)),
        Constraint("the skaters pull in a good part of the rope (L2 <= 0.6 L1)",
                   lambda p: p.L2 <= 0.6 * p.L1),
        Constraint("people can do it: at most one turn a second at the end (omega2 <= 6.3 "
                   "rad/s) and neither skater faster than 7 m/s",
                   lambda p: solve(p)["omega2"] <= 6.3
                   and max(p.m1, p.m2) / (p.m1 + p.m2) * p.L2 * solve(p)["omega2"] <= 7.0),
        Constraint("the three answers differ by at least 10 % in SI", _distinct),
    ),
    statement=r"""
Two skaters, $m_1$ = {{ m1 }} and $m_2$ = {{ m2 }}, hold the ends of a light rope of length
$L_1$ = {{ L1 }} on frictionless ice and spin about their common centre of mass, which is
at rest, with $\omega_1$ = {{ omega1 }}. Pulling hand over hand they shorten the rope
between them to $L_2$ = {{ L2 }}. Treat the skaters as particles.

1. With which angular velocity do they spin then?
2. What is then the speed of skater 1?
3. How much work have the skaters done in pulling?
""",
    solution=r"""
The rope's forces on the skaters are internal and act along the line between them; the
ice exerts no horizontal force. So the total momentum stays zero (C stays at rest) and
the angular momentum about C stays constant (balance of angular momentum of a system,
Section 2.2.3). The kinetic energy is not conserved: the skaters' arms do work.

Skater $i$ circles C at $r_1 = \frac{m_2}{m_1 + m_2} L$, $r_2 = \frac{m_1}{m_1 + m_2} L$,
so $H_C = (m_1 r_1^2 + m_2 r_2^2)\,\omega = \mu L^2\omega$ with
$\mu = m_1 m_2/(m_1 + m_2)$; at the start $H_C$ = {{ si.H_C }} kg·m²/s ($m_1$ = {{ m1 }},
$m_2$ = {{ m2 }}, $L_1$ = {{ L1 }}, $\omega_1$ = {{ omega1 }}).

1. **Angular velocity.** $\mu L_1^2\omega_1 = \mu L_2^2\omega_2$, so
   $\omega_2 = \omega_1 (L_1/L_2)^2$ = {{ answers.omega2 }} ($L_2$ = {{ L2 }}).
2. **Skater 1.** $v_1 = r_1\omega_2 = \frac{m_2}{m_1 + m_2} L_2\,\omega_2$ = {{ answers.v1 }}.
3. **Work.** The kinetic energy $T = \tfrac{1}{2}\mu L^2\omega^2 = H_C^2/(2\mu L^2)$ grows
   from {{ si.T1 }} J to {{ si.T2 }} J; by the work-energy balance (Section 2.2.2) the
   skaters did $W = T_2 - T_1$ = {{ answers.W }}.
4. **Check.** The rope tension $\mu L\omega^2$ integrated over the shortening,
   $\int_{L_2}^{L_1}\mu L\,\omega^2\,dL$, gives {{ checks.tension_work }} J again.
""",
    solve=solve,
    checks=(
        Balance("angular momentum about C", lambda p, s: p.m1 * p.m2 / (p.m1 + p.m2)
                * p.L1**2 * p.omega1,
                lambda p, s: p.m1 * p.m2 / (p.m1 + p.m2) * p.L2**2 * s["omega2"],
                name="momentum_about_c"),
        Recompute("W", _tension_work, name="tension_work", rtol=1e-8),
    ),
    figure=draw,
    parts=(
        Numeric("omega2", "angular velocity after pulling", question=1, unit="rad/s",
                points=2, misconceptions=(
                    Misconception("kinetic energy conserved (omega linear in L1/L2)",
                                  lambda p: p.omega1 * p.L1 / p.L2,
                                  "The skaters do work, so T is not conserved; the angular "
                                  "momentum μ L² ω about C is: ω grows with (L1/L2)²."),
                )),
        Numeric("v1", "speed of skater 1", question=2, unit="m/s", points=1,
                misconceptions=(
                    Misconception("rotation about the middle of the rope",
                                  lambda p: p.L2 / 2 * p.omega1 * (p.L1 / p.L2) ** 2,
                                  "The skaters spin about their centre of mass: "
                                  "r1 = m2 L2/(m1 + m2)."),
                )),
        Numeric("W", "work done in pulling", question=3, unit="J", points=1,
                misconceptions=(
                    Misconception("no work: angular momentum is conserved",
                                  lambda p: 0.0 * p.L1,
                                  "Angular momentum is conserved, kinetic energy is not: "
                                  "T = H_C²/(2 μ L²) grows as L shrinks."),
                )),
    ),
)
