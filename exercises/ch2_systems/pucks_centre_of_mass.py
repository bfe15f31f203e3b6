"""Three pucks on an air table: the centre of mass, its velocity and the pucks' positions
and velocities relative to it (kinematics of systems of particles, Section 2.1)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Uniform, Vector, per_draw
from dynagrade.exercise.checks import Recompute
from dynagrade.exercise.figure import arrow, describe, new_drawing
from dynagrade.mechanics import systems


def _masses(p):
    return [p.m1, p.m2, p.m3]


def _positions(p):
    return np.array([[p.x1, p.y1], [p.x2, p.y2], [p.x3, p.y3]])


def _velocities(p):
    return np.array([[p.u1, p.w1], [p.u2, p.w2], [p.u3, p.w3]])


@per_draw
def solve(p):
    masses, r, v = _masses(p), _positions(p), _velocities(p)
    moments = np.asarray(masses)[:, None] * r
    momenta = np.asarray(masses)[:, None] * v
    return {
        "r_C": tuple(systems.centre_of_mass(masses, r)),
        "v_C": tuple(systems.centre_of_mass_velocity(masses, v)),
        "rho_1": tuple(systems.positions_relative_to_centre_of_mass(masses, r)[0]),
        "u_2": tuple(systems.positions_relative_to_centre_of_mass(masses, v)[1]),
        # for the worked solution: the total mass and the sums the means are made of
        "M": systems.total_mass(masses),
        "Sx": float(moments[:, 0].sum()), "Sy": float(moments[:, 1].sum()),
        "Px": float(momenta[:, 0].sum()), "Py": float(momenta[:, 1].sum()),
    }


def _centroid(p):
    """The wrong route: the plain mean of the positions, as if the masses were equal."""
    return tuple(_positions(p).mean(axis=0))


def _mean_velocity(p):
    """The wrong route: the plain mean of the velocities."""
    return tuple(_velocities(p).mean(axis=0))


def _reversed(name):
    """The wrong route: the relative vector of part ``name`` taken the other way round."""
    return lambda p: tuple(-np.asarray(solve(p)[name]))


def _differ(a, b) -> bool:
    """Whether ``a`` and ``b`` differ in a component by clearly more than a part's
    tolerance (5 % of the component, or of a tenth of the vector, and 2 cm or cm/s)."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    scale = np.maximum(np.abs(b), 0.1 * np.linalg.norm(b))
    return bool(np.any(np.abs(a - b) > np.maximum(0.05 * scale, 0.02)))


def _apart(p) -> bool:
    """The pucks are 0.4 m apart and 0.5 m from O (clear of each other and of the axes
    drawn at O)."""
    r = _positions(p)
    return (all(np.linalg.norm(r[i] - r[j]) >= 0.4 for i, j in ((0, 1), (0, 2), (1, 2)))
            and bool(np.all(np.linalg.norm(r, axis=1) >= 0.5)))


def _discriminating(p) -> bool:
    """Every misconception below gives a clearly different answer from the key."""
    s = solve(p)
    r, v = _positions(p), _velocities(p)
    return (_differ(_centroid(p), s["r_C"]) and _differ(_mean_velocity(p), s["v_C"])
            and _differ(_reversed("rho_1")(p), s["rho_1"])
            and _differ(r[0] - _centroid(p), s["rho_1"])
            and _differ(_reversed("u_2")(p), s["u_2"])
            and _differ(v[1] - v[0], s["u_2"]))


def figure(p):
    """The table seen from above at the instant considered, to scale: each puck at its
    position (its area grows with its mass), its velocity as an arrow (0.25 m per m/s),
    and the frame's origin O with its x and y directions. The centre of mass is not drawn:
    it is asked for."""
    from dynagrade.exercise.figure import Circle

    r, v = _positions(p), _velocities(p)
    drawing, axes = new_drawing(5.0, 4.0)
    scale = 0.25                                   # arrow length (m) per m/s
    arrow(axes, (0.0, 0.0), (0.3, 0.0), color="0.3")
    arrow(axes, (0.0, 0.0), (0.0, 0.3), color="0.3")
    axes.text(0.36, 0.0, "x", ha="left", va="center", fontsize=10, color="0.3")
    axes.text(0.0, 0.36, "y", ha="center", va="bottom", fontsize=10, color="0.3")
    axes.text(-0.05, -0.05, "O", ha="right", va="top", fontsize=10)
    heaviest = max(_masses(p))
    for sub, point, velocity, mass in zip("₁₂₃", r, v, _masses(p)):
        radius = 0.12 * np.sqrt(mass / heaviest)
        axes.add_patch(Circle(tuple(point), radius, facecolor="C0", edgecolor="0.1", lw=1.0,
                              zorder=3))
        speed = np.linalg.norm(velocity)
        away = velocity / speed if speed > 1e-9 else np.array([0.6, -0.8])
        # the puck's mass symbol on the side away from its velocity arrow (a subscript
        # digit, which no reader takes for a number of the variant)
        axes.text(*(point - (radius + 0.09) * away), f"m{sub}", ha="center",
                  va="center", fontsize=10)
        if speed > 1e-9:
            tip = point + scale * velocity
            arrow(axes, tuple(point), tuple(tip), color="C3")
            label_at = point + (max(scale * speed, radius) + 0.1) * away   # clear of the puck
            axes.text(*label_at, f"v{sub}", color="C3", ha="center",
                      va="center", fontsize=10)
    describe(axes, "Seen from above: the pucks glide on the table in the directions of "
             "their velocity arrows; x points to the right, y up the page, from the origin O.")
    reach = np.vstack([r, r + scale * v, [[0.0, 0.0], [0.4, 0.45]]])
    low, high = reach.min(axis=0) - 0.25, reach.max(axis=0) + 0.25
    axes.set_xlim(low[0], high[0])
    axes.set_ylim(low[1], high[1])
    return drawing


EXERCISE = Exercise(
    id="pucks-centre-of-mass",
    title="Three pucks on an air table: centre of mass and relative coordinates",
    source="Section 2.1",
    topics=("centre of mass", "relative coordinates", "kinematics of systems of particles"),
    params=(
        Uniform("m1", 0.2, 3.0, step=0.1, unit="kg", symbol="m_1"),
        Uniform("m2", 0.2, 3.0, step=0.1, unit="kg", symbol="m_2"),
        Uniform("m3", 0.2, 3.0, step=0.1, unit="kg", symbol="m_3"),
        Uniform("x1", -1.5, 1.5, step=0.1, unit="m", symbol="x_1"),
        Uniform("y1", -1.5, 1.5, step=0.1, unit="m", symbol="y_1"),
        Uniform("x2", -1.5, 1.5, step=0.1, unit="m", symbol="x_2"),
        Uniform("y2", -1.5, 1.5, step=0.1, unit="m", symbol="y_2"),
        Uniform("x3", -1.5, 1.5, step=0.1, unit="m", symbol="x_3"),
        Uniform("y3", -1.5, 1.5, step=0.1, unit="m", symbol="y_3"),
        Uniform("u1", -2.0, 2.0, step=0.1, unit="m/s", symbol=r"\dot x_1"),
        Uniform("w1", -2.0, 2.0, step=0.1, unit="m/s", symbol=r"\dot y_1"),
        Uniform("u2", -2.0, 2.0, step=0.1, unit="m/s", symbol=r"\dot x_2"),
        Uniform("w2", -2.0, 2.0, step=0.1, unit="m/s", symbol=r"\dot y_2"),
        Uniform("u3", -2.0, 2.0, step=0.1, unit="m/s", symbol=r"\dot x_3"),
        Uniform("w3", -2.0, 2.0, step=0.1, unit="m/s", symbol=r"\dot y_3"),
    ),
    constraints=(
        Constraint("the pucks are at least 0.4 m apart and 0.5 m from O", _apart),
        Constraint("the heaviest puck is at least twice the lightest",
                   lambda p: max(_masses(p)) >= 2 * min(_masses(p))),
        Constraint("C is at least 0.2 m from O and moves at least 0.2 m/s",
                   lambda p: np.linalg.norm(solve(p)["r_C"]) >= 0.2
                   and np.linalg.norm(solve(p)["v_C"]) >= 0.2),
        Constraint("puck 1 is at least 0.2 m from C and puck 2 moves at least 0.2 m/s "
                   "relative to C",
                   lambda p: np.linalg.norm(solve(p)["rho_1"]) >= 0.2
                   and np.linalg.norm(solve(p)["u_2"]) >= 0.2),
        Constraint("every misconception gives a clearly different answer", _discriminating),
    ),
    statement=r"""
Three small pucks glide on a horizontal air table. In the table's fixed frame (origin O,
unit vector $e_x$ to the right and $e_y$ up the page, as drawn) they are, at the instant
considered, at the positions $r_i = x_i\,e_x + y_i\,e_y$ with the velocities
$v_i = \dot x_i\,e_x + \dot y_i\,e_y$:

- puck 1: $m_1$ = {{ m1 }} at $x_1$ = {{ x1 }}, $y_1$ = {{ y1 }}, moving with
  $\dot x_1$ = {{ u1 }}, $\dot y_1$ = {{ w1 }};
- puck 2: $m_2$ = {{ m2 }} at $x_2$ = {{ x2 }}, $y_2$ = {{ y2 }}, moving with
  $\dot x_2$ = {{ u2 }}, $\dot y_2$ = {{ w2 }};
- puck 3: $m_3$ = {{ m3 }} at $x_3$ = {{ x3 }}, $y_3$ = {{ y3 }}, moving with
  $\dot x_3$ = {{ u3 }}, $\dot y_3$ = {{ w3 }}.

Give each vector as its two components along $e_x$ and $e_y$, e.g. `[0.5, -1.2]`.

1. Where is the centre of mass C of the three pucks, $r_C$?
2. What is the velocity $v_C$ of the centre of mass?
3. What is the position of puck 1 relative to the centre of mass, $\rho_1 = r_1 - r_C$?
4. What is the velocity of puck 2 relative to the centre of mass, $\dot\rho_2 = v_2 - v_C$?
""",
    solution=r"""
The centre of mass of a system of particles is the mass-weighted mean of their positions,
$r_C = \frac{1}{M}\sum_i m_i r_i$ with the total mass $M = \sum_i m_i$; differentiating
it in time gives its velocity $v_C = \frac{1}{M}\sum_i m_i v_i$. Each particle's position
splits as $r_i = r_C + \rho_i$ into the centre of mass and its coordinates $\rho_i$
relative to it, and $\sum_i m_i \rho_i = 0$ (kinematics of systems of particles,
Section 2.1).

Here $M = m_1 + m_2 + m_3$ = {{ si.M }} kg ($m_1$ = {{ m1 }}, $m_2$ = {{ m2 }},
$m_3$ = {{ m3 }}).

1. **Centre of mass.** The first moments are $\sum_i m_i x_i$ = {{ si.Sx }} kg·m and
   $\sum_i m_i y_i$ = {{ si.Sy }} kg·m; dividing by $M$,
   $r_C$ = {{ answers.r_C }}. The heavier pucks pull C toward themselves: the plain mean
   of the three positions would be right only for equal masses.
2. **Velocity of the centre of mass.** In the same way $\sum_i m_i \dot x_i$ =
   {{ si.Px }} kg·m/s and $\sum_i m_i \dot y_i$ = {{ si.Py }} kg·m/s, so
   $v_C$ = {{ answers.v_C }}.
3. **Puck 1 relative to C.** $\rho_1 = r_1 - r_C$ with $x_1$ = {{ x1 }} and
   $y_1$ = {{ y1 }}: $\rho_1$ = {{ answers.rho_1 }}.
4. **Puck 2 relative to C.** $\dot\rho_2 = v_2 - v_C$ with $\dot x_2$ = {{ u2 }} and
   $\dot y_2$ = {{ w2 }}: $\dot\rho_2$ = {{ answers.u_2 }}.
""",
    solve=solve,
    checks=(
        # the mass-weighted mean of the positions and of the velocities
        Recompute("r_C", lambda p, s: ((p.m1 * p.x1 + p.m2 * p.x2 + p.m3 * p.x3) / (p.m1 + p.m2 + p.m3),
                                       (p.m1 * p.y1 + p.m2 * p.y2 + p.m3 * p.y3) / (p.m1 + p.m2 + p.m3)),
                  name="weighted_mean_position", atol=1e-12),
        Recompute("v_C", lambda p, s: ((p.m1 * p.u1 + p.m2 * p.u2 + p.m3 * p.u3) / (p.m1 + p.m2 + p.m3),
                                       (p.m1 * p.w1 + p.m2 * p.w2 + p.m3 * p.w3) / (p.m1 + p.m2 + p.m3)),
                  name="weighted_mean_velocity", atol=1e-12),
        # relative to the centre of mass: puck 1's position, puck 2's velocity
        Recompute("rho_1", lambda p, s: (p.x1 - (p.m1 * p.x1 + p.m2 * p.x2 + p.m3 * p.x3) / (p.m1 + p.m2 + p.m3),
                                         p.y1 - (p.m1 * p.y1 + p.m2 * p.y2 + p.m3 * p.y3) / (p.m1 + p.m2 + p.m3)),
                  name="relative_position", atol=1e-12),
        Recompute("u_2", lambda p, s: (p.u2 - (p.m1 * p.u1 + p.m2 * p.u2 + p.m3 * p.u3) / (p.m1 + p.m2 + p.m3),
                                       p.w2 - (p.m1 * p.w1 + p.m2 * p.w2 + p.m3 * p.w3) / (p.m1 + p.m2 + p.m3)),
                  name="relative_velocity", atol=1e-12),
    ),
    figure=figure,
    figure_to_scale=True,
    parts=(
        Vector("r_C", "position of the centre of mass", question=1, unit="m", size=2, points=2,
               atol=0.005,
               misconceptions=(
                   Misconception("plain mean of the positions", _centroid,
                                 "Weight each position with its mass: "
                                 "r_C = (m1 r1 + m2 r2 + m3 r3)/M (Section 2.1)."),
               )),
        Vector("v_C", "velocity of the centre of mass", question=2, unit="m/s", size=2, points=2,
               atol=0.005,
               misconceptions=(
                   Misconception("plain mean of the velocities", _mean_velocity,
                                 "v_C is the time derivative of r_C: weight each velocity "
                                 "with its mass, v_C = (m1 v1 + m2 v2 + m3 v3)/M."),
               )),
        Vector("rho_1", "position of puck 1 relative to C", question=3, unit="m", size=2, points=1,
               atol=0.005,
               misconceptions=(
                   Misconception("r_C − r_1 instead of r_1 − r_C", _reversed("rho_1"),
                                 "The relative position points from C to the puck: "
                                 "rho_1 = r_1 − r_C."),
                   Misconception("relative to the plain mean of the positions",
                                 lambda p: tuple(_positions(p)[0] - _centroid(p)),
                                 "C is the mass-weighted mean of the positions, not the "
                                 "plain mean."),
               )),
        Vector("u_2", "velocity of puck 2 relative to C", question=4, unit="m/s", size=2, points=1,
               atol=0.005,
               misconceptions=(
                   Misconception("v_C − v_2 instead of v_2 − v_C", _reversed("u_2"),
                                 "The relative velocity is the rate of rho_2 = r_2 − r_C: "
                                 "v_2 − v_C."),
                   Misconception("relative to puck 1 instead of C",
                                 lambda p: tuple(_velocities(p)[1] - _velocities(p)[0]),
                                 "Relative to the centre of mass means v_2 − v_C, not "
                                 "v_2 − v_1."),
               )),
    ),
)
