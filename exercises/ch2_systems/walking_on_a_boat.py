"""A person walks along a boat floating at rest: the centre of mass stays put
(Section 2.2.1)."""

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform
from dynagrade.exercise.checks import Balance, Recompute
from dynagrade.exercise.figure import arrow, describe, dimension, new_drawing
from dynagrade.mechanics import systems


def solve(p):
    x_boat = systems.recoil_displacement(p.m, p.M, p.d)
    return {
        "x_B": x_boat,
        "x_P": p.d - x_boat,
        # the speeds split as the displacements do: m v_P = M v_B at every instant
        "v_B": systems.speeds_relative_to_centre_of_mass(p.m, p.M, p.u).v2,
        "M_total": systems.total_mass([p.m, p.M]),
    }


def draw(p):
    """Schematic: the boat on the water, the person at its stern, the walk d relative to
    the boat towards the bow and the pier on the left (the shore's fixed point)."""
    from dynagrade.exercise.figure import Circle, Polygon, Rectangle

    figure, axes = new_drawing(5.0, 2.6)
    axes.plot([-1.0, 6.0], [0.0, 0.0], color="C0", lw=1.0, zorder=0)  # water line
    axes.add_patch(Polygon([(0.0, 0.5), (5.0, 0.5), (4.6, -0.3), (0.4, -0.3)], closed=True,
                           facecolor="0.85", edgecolor="0.1", lw=1.2))
    axes.add_patch(Rectangle((-1.0, -0.6), 0.5, 1.4, facecolor="0.6", edgecolor="0.1"))
    axes.text(-0.75, 1.0, "pier", ha="center", va="bottom", fontsize=9)
    axes.text(2.5, 0.05, "M", ha="center", va="center", fontsize=11)
    axes.plot([0.7, 0.7], [0.5, 1.3], color="0.1", lw=2.0)             # the person
    axes.add_patch(Circle((0.7, 1.45), 0.15, facecolor="C1", edgecolor="0.1"))
    axes.text(0.35, 1.45, "m", ha="right", va="center", fontsize=11)
    axes.plot([0.7 + 3.6, 0.7 + 3.6], [0.5, 1.3], color="0.45", lw=1.0, ls="--")
    dimension(axes, (0.7, 0.5), (4.3, 0.5), "d", offset=-1.1, tick=0.1, side=-1.0)
    arrow(axes, (1.0, 1.3), (2.6, 1.3), "u", offset=(0.0, 0.2), color="C3")
    describe(axes, "The person stands at the stern (left) of the boat and walks the "
             "distance d towards the bow (right), with speed u relative to the boat; "
             "the dashed line marks where the walk ends on the boat.")
    axes.set_xlim(-1.2, 5.4)
    axes.set_ylim(-0.8, 2.0)
    return figure


EXERCISE = Exercise(
    id="walking-on-a-boat",
    title="Walking along a floating boat",
    source="Section 2.2.1",
    topics=("balance of linear momentum of a system", "centre of mass", "internal forces"),
    params=(
        Uniform("m", 50, 100, step=1, unit="kg", symbol="m"),
        Uniform("M", 100, 400, step=5, unit="kg", symbol="M"),
        Uniform("d", 2.0, 5.0, step=0.1, unit="m", symbol="d"),
        Uniform("u", 0.5, 1.5, step=0.05, unit="m/s", symbol="u"),
    ),
    constraints=(
        Constraint("the boat is clearly heavier than the person (M >= 1.5 m), so that the "
                   "two displacements differ", lambda p: p.M >= 1.5 * p.m),
    ),
    statement=r"""
A boat of mass $M$ = {{ M }} floats at rest beside a pier; a person of mass $m$ = {{ m }}
stands at rest at its stern. The person walks the distance $d$ = {{ d }} along the boat
towards the bow, with constant speed $u$ = {{ u }} relative to the boat, and stops. The
water exerts no horizontal force on the boat.

1. How far does the boat move relative to the pier?
2. How far does the person move relative to the pier?
3. With which speed does the boat move relative to the pier while the person walks?
""",
    solution=r"""
Take the person and the boat as one system. The forces between the person's feet and the
boat are internal; no external horizontal force acts, so the horizontal momentum stays
zero and the centre of mass stays where it was (balance of linear momentum of a system,
Section 2.2.1). The total mass is $m + M$ = {{ si.M_total }} kg ($m$ = {{ m }},
$M$ = {{ M }}).

1. **The boat.** Let the boat move back by $x_B$; the person then moves forward by
   $x_P = d - x_B$ relative to the pier. The centre of mass stays: $m x_P = M x_B$, so
   $m (d - x_B) = M x_B$ and
   $x_B = \frac{m}{m + M}\,d$ = {{ answers.x_B }} (with $d$ = {{ d }}), opposite to the walk.
2. **The person.** $x_P = d - x_B = \frac{M}{m + M}\,d$ = {{ answers.x_P }}: the lighter
   body moves farther.
3. **Speed of the boat.** At every instant the momenta cancel, $m v_P = M v_B$, with
   $v_P + v_B = u$ = {{ u }}. Hence $v_B = \frac{m}{m + M}\,u$ = {{ answers.v_B }}; it stops
   when the person stops.
4. **Check.** The walk takes $d/u$, and the boat drifts at $v_B$ all that time:
   $v_B\,d/u$ = {{ checks.boat_drift_over_the_walk }} m, the $x_B$ of question 1.
""",
    solve=solve,
    checks=(
        # the centre of mass stays: the person's and the boat's mass-weighted shifts cancel
        Balance("mass-weighted displacements", lambda p, s: p.m * s["x_P"],
                lambda p, s: p.M * s["x_B"], name="centre_of_mass_stays"),
        # the two displacements relative to the pier make up the walk relative to the boat
        Balance("walk relative to the boat", lambda p, s: p.d,
                lambda p, s: s["x_P"] + s["x_B"], name="walk_on_the_boat"),
        # the boat's speed of question 3 kept for the walking time d/u gives question 1's x_B
        Recompute("x_B", lambda p, s: s["v_B"] * p.d / p.u, name="boat_drift_over_the_walk"),
        # walking at constant u takes d/u; the boat covers x_B in that time
        Balance("boat speed", lambda p, s: s["v_B"], lambda p, s: s["x_B"] * p.u / p.d,
                name="constant_speed_walk"),
    ),
    figure=draw,
    parts=(
        Numeric("x_B", "displacement of the boat", question=1, unit="m", points=2,
                misconceptions=(
                    Misconception("the person's walk taken relative to the pier",
                                  lambda p: p.m * p.d / p.M,
                                  "d is measured on the boat, which moves back: m (d − x_B) "
                                  "= M x_B (the centre of mass stays, Section 2.2.1)."),
                )),
        Numeric("x_P", "displacement of the person", question=2, unit="m", points=1,
                misconceptions=(
                    Misconception("the boat's motion forgotten", lambda p: p.d,
                                  "The boat moves back while the person walks: x_P = d − x_B."),
                )),
        Numeric("v_B", "speed of the boat", question=3, unit="m/s", points=1,
                misconceptions=(
                    Misconception("u taken relative to the pier", lambda p: p.m * p.u / p.M,
                                  "u is the speed relative to the boat: v_P + v_B = u and "
                                  "m v_P = M v_B."),
                )),
    ),
)
