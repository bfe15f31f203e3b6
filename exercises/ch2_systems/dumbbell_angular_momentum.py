"""Angular momentum of a spinning, flying dumbbell about its centre of mass and about a
fixed point (Section 2.2.3)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.checks import Balance, Recompute
from dynagrade.exercise.figure import angle_arc, arrow, describe, dimension, new_drawing
from dynagrade.mechanics import systems


def _state(p):
    """Masses, positions and velocities of the two particles (planar, components e1, e2)."""
    masses = [p.m1, p.m2]
    total = systems.total_mass(masses)
    direction = np.array([np.cos(p.phi), np.sin(p.phi)])
    centre = np.array([0.0, p.d])
    r = np.array([centre - p.m2 / total * p.L * direction,
                  centre + p.m1 / total * p.L * direction])
    rot = p.omega * np.array([[0.0, -1.0], [1.0, 0.0]])
    v = np.array([[p.v, 0.0] + rot @ (ri - centre) for ri in r])
    return masses, r, v


def figure(p):
    """The dumbbell to scale at the instant considered: the balls where :func:`_state`
    puts them about the centre of mass C (their distances from C in the ratio m2 : m1,
    Section 2.2.1), C at the height d above O with its velocity v along e1, the spin
    omega and the angle phi of the rod; the unit vectors e1, e2 at O."""
    from dynagrade.exercise.figure import Circle

    _, r, _ = _state(p)
    size = max(p.L, p.d)
    drawing, axes = new_drawing(5.0, 3.2)
    unit = 0.22 * size
    arrow(axes, (0.0, 0.0), (unit, 0.0), "e₁", offset=(0.0, -0.06 * size), color="0.3")
    arrow(axes, (0.0, 0.0), (0.0, unit), "e₂", offset=(-0.07 * size, 0.0), color="0.3")
    axes.add_patch(Circle((0.0, 0.0), 0.02 * size, facecolor="0.1", zorder=3))
    axes.text(-0.04 * size, -0.05 * size, "O", ha="right", va="top", fontsize=10)
    centre = np.array([0.0, p.d])
    axes.plot(*zip(*r), color="0.3", lw=2.5, solid_capstyle="round")
    heavier = max(p.m1, p.m2)
    for point, mass, name in zip(r, (p.m1, p.m2), ("m₁", "m₂")):
        radius = 0.07 * size * (mass / heavier) ** (1 / 3)
        axes.add_patch(Circle(tuple(point), radius, facecolor="C0", edgecolor="0.1",
                              lw=1.0, zorder=3))
        outward = (point - centre) / np.linalg.norm(point - centre)
        axes.text(*(point + outward * (radius + 0.07 * size)), name, ha="center",
                  va="center", fontsize=10)
    axes.add_patch(Circle(tuple(centre), 0.025 * size, facecolor="white", edgecolor="0.1",
                          lw=1.0, zorder=4))
    axes.plot([0.0, 0.0], [unit, p.d], color="0.5", lw=0.6, ls=":")
    arrow(axes, tuple(centre), tuple(centre + [0.35 * size, 0.0]), "v",
          offset=(0.0, 0.05 * size), color="C3")
    axes.plot([0.0, 0.2 * size], [p.d, p.d], color="0.5", lw=0.6, ls="-.")
    angle_arc(axes, tuple(centre), 0.12 * size, 0.0, p.phi, "φ", label_radius=0.2 * size)
    spin = 0.3 * size
    start, end = p.phi + np.pi / 2 - 0.5, p.phi + np.pi / 2 + 0.5   # beside the rod
    axes.annotate("", xy=tuple(centre + spin * np.array([np.cos(end), np.sin(end)])),
                  xytext=tuple(centre + spin * np.array([np.cos(start), np.sin(start)])),
                  arrowprops={"arrowstyle": "-|>", "color": "#23802a", "lw": 1.3,
                              "connectionstyle": "arc3,rad=0.3", "shrinkA": 0,
                              "shrinkB": 0})
    middle = (start + end) / 2
    axes.text(*(centre + (spin + 0.08 * size) * np.array([np.cos(middle), np.sin(middle)])),
              "ω", color="#23802a", ha="center", va="center", fontsize=10)
    below = p.phi - np.pi / 2 - 0.4             # the side of the rod away from omega
    axes.text(*(centre + 0.08 * size * np.array([np.cos(below), np.sin(below)])), "C",
              ha="center", va="center", fontsize=10)
    dimension(axes, (0.0, 0.0), tuple(centre), "d", offset=0.45 * size, tick=0.03 * size,
              side=-1.0)
    describe(axes, "The centre of mass C is straight above O and moves to the right; the "
             "dumbbell spins counter-clockwise. The angle φ is measured counter-clockwise "
             "from the horizontal to the rod, which points from m₁ to m₂.")
    reach = max(0.55 * size, p.L)
    axes.set_xlim(-reach - 0.15 * size, reach + 0.15 * size)
    axes.set_ylim(min(-0.15 * size, float(r[:, 1].min()) - 0.15 * size),
                  p.d + max(0.45 * size, float(r[:, 1].max() - p.d) + 0.15 * size))
    return drawing


@per_draw
def solve(p):
    masses, r, v = _state(p)
    return {
        "H_C": systems.angular_momentum_about_centre_of_mass(masses, r, v)[2],
        "H_O": systems.system_angular_momentum_about_point(masses, r, v, [0.0, 0.0])[2],
        "M": systems.total_mass(masses),
        "H_orbit": systems.angular_momentum_transfer(
            0.0, systems.total_mass(masses), [0.0, p.d], [p.v, 0.0])[2],
    }


def _geometric_centre_h(p):
    """The wrong route: both masses at L/2 from the centre of rotation."""
    return (p.m1 + p.m2) * (p.L / 2) ** 2 * p.omega


EXERCISE = Exercise(
    id="dumbbell-angular-momentum",
    title="Angular momentum of a flying dumbbell",
    source="Section 2.2.3",
    topics=("angular momentum of a system", "centre of mass"),
    params=(
        Uniform("m1", 0.5, 3.0, step=0.1, unit="kg", symbol="m_1"),
        Uniform("m2", 0.5, 3.0, step=0.1, unit="kg", symbol="m_2"),
        Uniform("L", 0.3, 1.5, step=0.05, unit="m", symbol="L"),
        Uniform("omega", 2.0, 20.0, step=0.5, unit="rad/s", symbol=r"\omega"),
        Uniform("v", 1.0, 10.0, step=0.5, unit="m/s", symbol="v"),
        Uniform("d", 0.5, 3.0, step=0.1, unit="m", symbol="d"),
        Uniform("phi", 0, 180, step=5, unit="deg", symbol=r"\varphi"),
    ),
    constraints=(
        Constraint("the masses differ enough that the centre of mass is off the middle",
                   lambda p: abs(p.m1 - p.m2) > 0.3 * max(p.m1, p.m2)),
        Constraint("the two contributions to H_O do not nearly cancel",
                   lambda p: abs(solve(p)["H_O"]) > 0.2 * p.d * (p.m1 + p.m2) * p.v),
    ),
    statement=r"""
Two small balls, $m_1$ = {{ m1 }} and $m_2$ = {{ m2 }}, are joined by a light rod of length
$L$ = {{ L }} and fly in a vertical plane, in which $e_1$ points horizontally to the right
and $e_2$ vertically up; $e_3 = e_1 \times e_2$ points out of the plane, toward the viewer.
At the instant considered the centre of mass C is at the height $d$ = {{ d }} straight
above a fixed point O (so $r_{OC} = d\,e_2$), it moves horizontally along $+e_1$ with
speed $v$ = {{ v }}, and the dumbbell spins counter-clockwise (seen from $+e_3$) with
$\omega$ = {{ omega }}; the rod, pointing from $m_1$ to $m_2$, makes the angle
$\varphi$ = {{ phi }} with $e_1$ (counter-clockwise).

1. What is the angular momentum of the dumbbell about its centre of mass ($e_3$ component)?
2. What is its angular momentum about the fixed point O ($e_3$ component)?
""",
    solution=r"""
Split the motion into the translation of the centre of mass C and the rotation about it
(Section 2.2.3): $H_O = H_C + r_{OC} \times M v_C$ with the total mass
$M = m_1 + m_2$ = {{ si.M }} kg (with $m_1$ = {{ m1 }} and $m_2$ = {{ m2 }}).

1. **About the centre of mass.** C divides the rod so that $m_1 r_1 = m_2 r_2$:
   $r_1 = m_2 L/M$ and $r_2 = m_1 L/M$. Relative to C each ball moves on a circle with
   speed $r_i\omega$, perpendicular to the rod, so
   $H_C = (m_1 r_1^2 + m_2 r_2^2)\,\omega = \frac{m_1 m_2}{m_1 + m_2} L^2\,\omega$,
   counter-clockwise, i.e. along $+e_3$. The angle $\varphi$ = {{ phi }} does not matter. With
   $L$ = {{ L }} and $\omega$ = {{ omega }}: $H_C$ = {{ answers.H_C }}.
2. **About O.** C is at $r_{OC} = d\,e_2$ and moves with $v_C = v\,e_1$, so
   $r_{OC} \times M v_C = -M d v\,e_3$ = {{ si.H_orbit }} kg·m²/s along $e_3$ (with
   $d$ = {{ d }}, $v$ = {{ v }}): the translation to the right, above O, turns clockwise about O.
   Hence $H_O = H_C - M d v$ = {{ answers.H_O }}.
""",
    solve=solve,
    checks=(
        # about C the dumbbell spins with the reduced mass: H_C = m1 m2 / (m1 + m2) L^2 omega
        Recompute("H_C", lambda p, s: p.m1 * p.m2 / (p.m1 + p.m2) * p.L**2 * p.omega,
                  name="spin_about_c"),
        # H_O = H_C + r_C x M v_C with r_C = d e2, v_C = v e1: the orbit adds -M v d
        Balance("angular momentum about O", lambda p, s: s["H_O"],
                lambda p, s: s["H_C"] - (p.m1 + p.m2) * p.v * p.d, name="transfer"),
    ),
    figure=figure,
    figure_to_scale=True,
    parts=(
        Numeric("H_C", "angular momentum about C", question=1, unit="kg*m^2/s", points=2,
                misconceptions=(
                    Misconception("rotation about the middle of the rod", _geometric_centre_h,
                                  "The dumbbell spins about its centre of mass, which is not "
                                  "the middle of the rod when m1 ≠ m2."),
                )),
        Numeric("H_O", "angular momentum about O", question=2, unit="kg*m^2/s", points=2,
                misconceptions=(
                    Misconception("transfer term forgotten", lambda p: solve(p)["H_C"],
                                  "About O add r_OC × M v_C, the angular momentum of the "
                                  "centre-of-mass motion."),
                    Misconception("transfer term with the wrong sign",
                                  lambda p: 2 * solve(p)["H_C"] - solve(p)["H_O"],
                                  "r_OC × M v_C for C above O moving along +e1 points along "
                                  "−e3."),
                )),
    ),
)
