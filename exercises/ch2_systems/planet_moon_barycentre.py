"""A planet and its moon: where their centre of mass lies, inside the planet or not, and how
the relative motion splits between the two bodies (relative coordinates of two particles,
kinematics of systems of particles, Section 2.1)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Options, Uniform, per_draw
from dynagrade.exercise.checks import Balance, Limit, Recompute
from dynagrade.exercise.figure import Circle, arrow, describe, dimension, new_drawing
from dynagrade.mechanics import systems


@per_draw
def solve(p):
    masses = (1.0, p.q)                      # in units of the planet's mass: only q matters
    relative = systems.positions_relative_to_centre_of_mass(masses, ((0.0, 0.0), (p.d, 0.0)))
    x_C = float(-relative[0][0])             # C lies on the line, x_C from the planet's centre
    speeds = systems.speeds_relative_to_centre_of_mass(masses[0], masses[1], p.w)
    return {
        "x_C": x_C,
        "inside": "inside" if x_C < p.R else "outside",
        "v_planet": float(speeds.v1),
        "v_moon": float(speeds.v2),
        "M": systems.total_mass(masses),     # for the worked solution, in planet masses
    }


def figure(p):
    """Schematic: the planet (radius R) and the moon on a line, their distance d and the
    moon's velocity w relative to the planet, perpendicular to that line. C is not drawn."""
    drawing, axes = new_drawing(5.0, 2.4)
    axes.add_patch(Circle((0.0, 0.0), 0.55, facecolor="C0", edgecolor="0.1", lw=1.0))
    axes.add_patch(Circle((3.6, 0.0), 0.2, facecolor="0.7", edgecolor="0.1", lw=1.0))
    axes.plot([0.0, 3.6], [0.0, 0.0], color="0.4", lw=0.8, ls="--")
    axes.plot([0.0, 0.55 * np.cos(2.2)], [0.0, 0.55 * np.sin(2.2)], color="0.1", lw=0.9)
    axes.text(-0.42, 0.18, "R", ha="center", va="center", fontsize=10, color="white")
    dimension(axes, (0.0, -0.8), (3.6, -0.8), "d", side=-1.0)
    arrow(axes, (3.6, 0.22), (3.6, 1.0), "w", offset=(0.15, 0.0), color="C3")
    axes.text(0.0, 0.7, "planet", ha="center", va="bottom", fontsize=10)
    axes.text(3.6, -0.32, "moon", ha="center", va="top", fontsize=10)
    describe(axes, "Schematic: the planet on the left, the moon on the right on a dashed "
             "line through both centres; the moon's velocity relative to the planet, w, "
             "points perpendicular to that line.")
    axes.set_xlim(-0.9, 4.4)
    axes.set_ylim(-1.2, 1.3)
    return drawing


EXERCISE = Exercise(
    id="planet-moon-barycentre",
    title="A planet and its moon: the common centre of mass",
    source="Section 2.1",
    topics=("centre of mass", "relative coordinates", "kinematics of systems of particles"),
    params=(
        Uniform("q", 0.02, 0.1, step=0.002, symbol="q"),
        Uniform("R", 2000, 7000, step=100, unit="km", symbol="R"),
        Uniform("d", 30000, 150000, step=1000, unit="km", symbol="d"),
        Uniform("w", 0.3, 1.5, step=0.01, unit="km/s", symbol="w"),
    ),
    constraints=(
        Constraint("C is clearly inside or clearly outside the planet (5 % of R)",
                   lambda p: abs(solve(p)["x_C"] - p.R) > 0.05 * p.R),
        Constraint("the moon is well clear of the planet, d >= 4 R", lambda p: p.d >= 4 * p.R),
    ),
    statement=r"""
A moon orbits a planet of radius $R$ = {{ R }}; the moon's mass is $q$ = {{ q }} times the
planet's. For the centre of mass, take both bodies as particles at their centres. At the
instant considered the moon's centre is at the distance $d$ = {{ d }} from the planet's
centre, and it moves relative to the planet at the speed $w$ = {{ w }} perpendicular to the
line joining the centres.

1. How far from the planet's centre is the centre of mass C of planet and moon (in km)?
2. Does C lie inside or outside the planet? (`inside` or `outside`)
3. How fast does the planet's centre move relative to C (in m/s)?
4. How fast does the moon move relative to C (in m/s)?
""",
    solution=r"""
For two particles the centre of mass $r_C = (m_1 r_1 + m_2 r_2)/M$ and the relative position
$r = r_2 - r_1$ give each particle's position relative to C (Section 2.1):
$r_1 - r_C = -\frac{m_2}{M} r$ and $r_2 - r_C = \frac{m_1}{M} r$. Differentiating, the
velocities relative to C are $-\frac{m_2}{M}\dot r$ and $\frac{m_1}{M}\dot r$. In units of the
planet's mass, $m_1 = 1$, $m_2 = q$ = {{ q }} and $M = 1 + q$ = {{ si.M }}.

1. **Where C is.** $|r_1 - r_C| = \frac{q}{1+q}\,d$ = {{ answers.x_C }} from the planet's
   centre, on the line toward the moon ($d$ = {{ d }}).
2. **Inside or outside.** Compared with $R$ = {{ R }}: C lies **{{ answers.inside }}** the
   planet.
3. **Planet relative to C.** $\frac{q}{1+q}\,w$ = {{ answers.v_planet }} ($w$ = {{ w }}).
4. **Moon relative to C.** $\frac{1}{1+q}\,w$ = {{ answers.v_moon }}: a little less than $w$:
   seen from the planet, C itself moves the same way as the moon.
5. **Check.** For a moon of negligible mass ($q \to 0$) C would sit at the planet's centre
   and the moon would move relative to C at the full $w$ = {{ checks.light_moon }} m/s.
""",
    solve=solve,
    checks=(
        # C balances the first moments: m1 |r1 - rC| = m2 |r2 - rC|
        Balance("first moments about C", lambda p, s: 1.0 * s["x_C"],
                lambda p, s: p.q * (p.d - s["x_C"]), name="moments_about_C"),
        # no momentum relative to C: m1 v1 = m2 v2; and the speeds add up to w
        Balance("momentum relative to C", lambda p, s: 1.0 * s["v_planet"],
                lambda p, s: p.q * s["v_moon"], name="momentum_about_C"),
        Recompute("v_moon", lambda p, s: p.w - s["v_planet"], name="speeds_add_up"),
        Limit("v_moon", {"q": 0.0}, lambda p: p.w, name="light_moon"),
    ),
    figure=figure,
    parts=(
        Numeric("x_C", "distance of C from the planet's centre", question=1, unit="km", points=2,
                misconceptions=(
                    Misconception("the midpoint", lambda p: p.d / 2,
                                  "C is the mass-weighted mean of the positions: it lies near "
                                  "the heavier planet, at q d/(1 + q)."),
                    Misconception("m2/m1 for m2/M", lambda p: p.q * p.d,
                                  "Divide by the total mass M = m1 + m2: q d/(1 + q).",
                                  applies=lambda p: p.q > 0.025),
                )),
        Options("inside", "C inside or outside the planet", question=2,
                options=("inside", "outside"), points=1),
        Numeric("v_planet", "speed of the planet relative to C", question=3, unit="m/s", points=1,
                misconceptions=(
                    Misconception("masses swapped", lambda p: p.w / (1 + p.q),
                                  "The heavier body moves less: the planet's share of w is "
                                  "m2/M = q/(1 + q)."),
                )),
        Numeric("v_moon", "speed of the moon relative to C", question=4, unit="m/s", points=1,
                misconceptions=(
                    Misconception("relative speed for the speed relative to C", lambda p: p.w,
                                  "w is relative to the planet, which itself moves relative to "
                                  "C: the moon's share is m1/M = 1/(1 + q).",
                                  applies=lambda p: p.q > 0.025),
                )),
    ),
)
