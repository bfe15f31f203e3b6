"""A ball rolls off a table and bounces on a smooth floor: the impact reverses and scales
only the vertical velocity, so the bounce is flatter and shorter than the fall (particle
impact, Section 1.2.4, with the throw of Example 1.9)."""

import numpy as np

from dynagrade.exercise import Constant, Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.apart import numbers_apart
from dynagrade.exercise.checks import Balance, Integrated, Limit
from dynagrade.exercise.checks.motions import height, thrown
from dynagrade.exercise.figure import arrow, block, describe, dimension, ground, new_drawing
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import impact, kinematics
from dynagrade.mechanics.examples import projectile


@per_draw
def solve(p):
    t_fall = float(kinematics.time_from_rest_over_distance(p.h, p.g))
    v_in = (p.u, -float(impact.impact_speed_after_fall(p.h, p.g)))     # the vertical fall is free
    v_out = impact.rebound_velocity(v_in, (0.0, 1.0), p.e)
    speed_out = float(np.hypot(*v_out))
    beta = float(np.arctan2(v_out[1], v_out[0]))
    return {
        "x1": p.u * t_fall,
        "beta": beta,
        "h1": float(impact.rebound_height(p.h, p.e)),
        "d12": float(projectile.horizontal_range(speed_out, beta, p.g)),
        # for the worked solution
        "t_fall": t_fall, "v_down": -v_in[1], "v_up": float(v_out[1]), "speed_out": speed_out,
    }


def _keys_apart(p) -> bool:
    """The three lengths (first impact, bounce height, bounce length) differ by over 5 %."""
    s = solve(p)
    values = (s["x1"], s["h1"], s["d12"])
    return numbers_apart(values)


def figure(p):
    """Side view to scale: the table of height h, the ball at its edge with the horizontal
    velocity u, the floor. The flight is left for the student."""
    drawing, axes = new_drawing(5.0, 2.6)
    reach = 2.6 * p.h
    ground(axes, -0.9 * p.h, reach, hatch=0.05 * p.h)
    block(axes, (-0.45 * p.h, 0.5 * p.h), 0.9 * p.h, p.h, color="0.85")
    ball = 0.05 * p.h
    axes.plot([ball], [p.h + ball], "o", color="C0", ms=8)
    arrow(axes, (2 * ball, p.h + ball), (0.5 * p.h, p.h + ball), f"u = {format_number(p.u)} m/s",
          offset=(0.0, 0.12 * p.h), color="C3")
    dimension(axes, (-1.0 * p.h, 0.0), (-1.0 * p.h, p.h), "h", side=1.0)
    axes.text(0.6 * reach, 0.08 * p.h, f"e = {format_number(p.e)}", ha="center", va="bottom",
              fontsize=10)
    describe(axes, "Side view: the ball leaves the edge of the table horizontally to the "
             "right with the speed u and falls to the floor, on which it bounces.")
    axes.set_xlim(-1.3 * p.h, reach)
    axes.set_ylim(-0.2 * p.h, 1.45 * p.h)
    return drawing


EXERCISE = Exercise(
    id="ball-rolling-off-table",
    title="A ball rolling off a table bounces on the floor",
    source="Section 1.2.4",
    topics=("particle impact", "coefficient of restitution", "projectile motion"),
    params=(
        Uniform("h", 0.6, 1.5, step=0.05, unit="m", symbol="h"),
        Uniform("u", 1.0, 5.0, step=0.1, unit="m/s", symbol="u"),
        Uniform("e", 0.3, 0.9, step=0.02, symbol="e"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("the three lengths asked for differ by over 5 % (e is clear of 1/2, where "
                   "the bounce is as long as the fall)", _keys_apart),
    ),
    statement=r"""
A small ball rolls off the edge of a table of height $h$ = {{ h }} with the horizontal speed
$u$ = {{ u }} and falls to the hard, smooth floor. The coefficient of restitution between ball
and floor is $e$ = {{ e }}; $g$ = {{ g }}, no air drag, the ball is taken as a particle.

1. How far from the foot of the table does it first hit the floor?
2. At what angle above the floor does it leave the floor after that impact (in degrees)?
3. How high does it rise after that impact?
4. How far from the first impact point does it hit the floor again?
""",
    solution=r"""
In flight only gravity acts: the horizontal velocity stays $u$ and the vertical motion is a
free fall (Example 1.9). The smooth floor exerts only a vertical impulse: the horizontal
velocity is kept through the impact, the vertical one is reversed and scaled by $e$
(Section 1.2.4).

1. **First impact.** The fall from $h$ = {{ h }} takes $t = \sqrt{2h/g}$ = {{ si.t_fall }} s,
   so $x_1 = u\sqrt{2h/g}$ = {{ answers.x1 }}.
2. **Rebound angle.** The ball arrives with the vertical speed $\sqrt{2gh}$ = {{ si.v_down }}
   m/s and leaves with $e\sqrt{2gh}$ = {{ si.v_up }} m/s (with $e$ = {{ e }}) and still $u$
   = {{ u }} horizontally: $\tan\beta = e\sqrt{2gh}/u$, $\beta$ = {{ answers.beta }}, flatter
   than it came in.
3. **Rebound height.** Only the vertical speed lifts the ball: $h_1 = (e\sqrt{2gh})^2/(2g)
   = e^2h$ = {{ answers.h1 }}.
4. **Second impact.** The bounce is a throw from the floor at the speed
   $\sqrt{u^2 + 2e^2gh}$ = {{ si.speed_out }} m/s and the angle $\beta$: by eq. (1.80) it
   lands $v'^2\sin 2\beta/g = 2eu\sqrt{2h/g}$ = {{ answers.d12 }} further on.
5. **Check.** With $e = 1$ the ball would rise back to the table's height,
   {{ checks.elastic }} m.
""",
    solve=solve,
    checks=(
        # the fall from the table edge integrated until the ball reaches the floor
        Integrated("x1", thrown, lambda p: (0.0, p.h, p.u, 0.0), lambda p, s: 3 * s["t_fall"],
                   lambda t, y, p: y[0], name="integrated_fall", event=height, direction=-1),
        # the bounce integrated from the impact point, starting with the velocity the
        # impact law gives: (u, e sqrt(2 g h))
        Integrated("d12", thrown, lambda p: (0.0, 0.0, p.u, p.e * np.sqrt(2 * p.g * p.h)),
                   lambda p, s: 6 * s["t_fall"], lambda t, y, p: y[0], name="integrated_bounce",
                   event=height, direction=-1),
        # energy on the way up after the impact: the kinetic energy of the vertical motion
        # becomes potential energy, eq. (1.102)
        Balance("energy of the vertical motion after the impact",
                lambda p, s: s["v_up"]**2 / 2, lambda p, s: p.g * s["h1"], name="rise_energy"),
        Limit("h1", {"e": 1.0}, lambda p: p.h, name="elastic"),
    ),
    figure=figure,
    figure_to_scale=True,
    parts=(
        Numeric("x1", "distance to the first impact", question=1, unit="m", points=1,
                misconceptions=(
                    Misconception("h = g t² without the 1/2", lambda p: p.u * np.sqrt(p.h / p.g),
                                  "From rest, h = g t²/2: the fall takes √(2h/g)."),
                )),
        Numeric("beta", "rebound angle above the floor", question=2, unit="deg", points=2,
                misconceptions=(
                    Misconception("mirror reflection", lambda p: np.arctan2(np.sqrt(2 * p.g * p.h), p.u),
                                  "Only the vertical velocity is scaled by e; the horizontal u "
                                  "is kept: tan β = e√(2gh)/u."),
                )),
        Numeric("h1", "rebound height", question=3, unit="m", points=1,
                misconceptions=(
                    Misconception("e applied to the height", lambda p: p.e * p.h,
                                  "e scales the vertical speed; the height goes with its square: "
                                  "h₁ = e²h."),
                )),
        Numeric("d12", "distance between the impacts", question=4, unit="m", points=2,
                misconceptions=(
                    Misconception("the whole velocity scaled by e",
                                  lambda p: 2 * p.e**2 * p.u * np.sqrt(2 * p.h / p.g),
                                  "The smooth floor gives only a vertical impulse: the ball keeps "
                                  "u horizontally."),
                    Misconception("half the bounce", lambda p: p.e * p.u * np.sqrt(2 * p.h / p.g),
                                  "The bounce rises for e√(2h/g) and falls as long again: "
                                  "it lasts 2e√(2h/g)."),
                )),
    ),
)
