"""A puck hitting a smooth rigid wall at an angle: rebound angle and speed, energy lost
(Section 1.2.4)."""

import numpy as np

from dynagrade.exercise import (Constraint, Exercise, Misconception, Numeric, Symbolic, Uniform)
from dynagrade.exercise.checks import Balance, Limit, Recompute
from dynagrade.exercise.figure import angle_arc, arrow, new_drawing, wall
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import impact


def figure(p):
    """Top view: the smooth wall, its normal at the point of impact and the puck coming in
    at the angle theta to the normal with speed v (Section 1.2.4). The rebound is left for
    the student to find."""
    from dynagrade.exercise.figure import Circle

    drawing, axes = new_drawing(4.2, 3.6)
    wall(axes, 0.0, -1.15, 0.25, side=1.0, hatch=0.06)
    axes.plot([-1.3, 0.0], [0.0, 0.0], color="0.4", lw=0.8, ls="-.")
    axes.text(-1.3, 0.06, "normal", ha="left", va="bottom", fontsize=9, color="0.3")
    incoming = np.array([np.cos(p.theta), np.sin(p.theta)])   # direction of travel
    start = -1.2 * incoming
    axes.plot([start[0], 0.0], [start[1], 0.0], color="0.5", lw=0.8, ls="--")
    axes.add_patch(Circle(tuple(start), 0.07, facecolor="C0", edgecolor="0.1", lw=1.0))
    tail = start + 0.12 * incoming
    arrow(axes, tuple(tail), tuple(tail + 0.45 * incoming), color="C3")
    normal_left = np.array([-np.sin(p.theta), np.cos(p.theta)])
    axes.text(*(tail + 0.25 * incoming - 0.14 * normal_left), f"v = {format_number(p.v)} m/s",
              color="C3", ha="center", va="center", fontsize=10,
              rotation=np.degrees(p.theta), rotation_mode="anchor")
    axes.text(start[0] - 0.11, start[1], f"m = {format_number(p.m)} kg", ha="right",
              va="center", fontsize=10)
    angle_arc(axes, (0.0, 0.0), 0.35, np.pi, np.pi + p.theta,
              f"θ = {format_number(np.degrees(p.theta))}°", label_radius=0.62)
    axes.text(0.12, -0.95, f"e = {format_number(p.e)}", ha="left", va="bottom", fontsize=10)
    axes.set_xlim(-1.45, 0.55)
    axes.set_ylim(-1.25, 0.3)
    return drawing


def solve(p):
    return {
        "theta_out": float(impact.rebound_angle(p.theta, p.e)),
        "v_out": float(impact.rebound_speed(p.v, p.theta, p.e)),
        "dT": float(impact.impact_energy_loss(p.m, p.v, p.theta, p.e)),
        "J": float(impact.wall_impulse(p.m, p.v * np.cos(p.theta), p.e)),
        "v_n": float(p.v * np.cos(p.theta)),
        "v_t": float(p.v * np.sin(p.theta)),
        "v_n_out": float(abs(impact.rebound_normal_velocity(p.v * np.cos(p.theta), p.e))),
    }


EXERCISE = Exercise(
    id="oblique-wall-impact",
    title="Oblique impact on a smooth wall",
    source="Section 1.2.4",
    topics=("particle impact", "coefficient of restitution", "oblique impact"),
    params=(
        Uniform("m", 0.1, 1.0, step=0.05, unit="kg", symbol="m"),
        Uniform("v", 2.0, 15.0, step=0.5, unit="m/s", symbol="v"),
        Uniform("theta", 15, 65, step=1, unit="deg", symbol=r"\theta"),
        Uniform("e", 0.3, 0.85, step=0.05, symbol="e"),
    ),
    constraints=(
        Constraint("the incidence angle is clear of 45 degrees",
                   lambda p: abs(p.theta - np.pi / 4) > np.radians(3)),
    ),
    statement="""
A puck of mass $m$ = {{ m }} slides on smooth ice and hits a straight, rigid, smooth
boards wall with speed $v$ = {{ v }}, its path making the angle $\\theta$ = {{ theta }}
with the wall's normal. The coefficient of restitution is $e$ = {{ e }}.

1. At what angle to the normal does it leave the wall (in degrees)?
2. With what speed does it leave?
3. How much kinetic energy is lost in the impact?
4. What impulse does the wall give the puck (magnitude)?
5. Write the rebound angle, in radians, as a formula in $\\theta$ (`theta`, in radians)
   and $e$.
""",
    solution=r"""
Split the velocity into the component along the wall's normal and the component along the
wall. The wall is smooth, so it exerts only a normal impulse: the tangential component is
unchanged, and the normal component is reversed and scaled by the coefficient of restitution.
Before the impact $v_n = v\cos\theta$ = {{ si.v_n }} m/s and $v_t = v\sin\theta$
= {{ si.v_t }} m/s (with $v$ = {{ v }}, $\theta$ = {{ theta }}); after it
$v_n' = e\,v_n$ = {{ si.v_n_out }} m/s (with $e$ = {{ e }}) and $v_t' = v_t$.

1. **Rebound angle.** $\tan\theta' = v_t'/v_n' = \tan\theta / e$, so
   $\theta' = \arctan(\tan\theta/e)$ = {{ answers.theta_out }}: since $e < 1$ the puck
   leaves at a larger angle from the normal, closer along the wall, than it came in.
2. **Rebound speed.** $v' = \sqrt{v_t^2 + e^2 v_n^2}$ = {{ answers.v_out }}.
3. **Energy lost.** Only the normal part loses energy:
   $\Delta T = \tfrac{1}{2} m (v^2 - v'^2) = \tfrac{1}{2} m (1 - e^2) v_n^2$ = {{ answers.dT }}
   (with $m$ = {{ m }}).
4. **Impulse.** Linear momentum balance across the impact: the impulse equals the change of
   momentum, which is purely normal, $J = m(v_n' + v_n) = (1 + e)\, m v_n$ = {{ answers.J }}.
5. **Formula.** $\theta'$ = `{{ answers.theta_formula }}`.
6. **Check.** With $e = 1$ the ball would leave as fast as it came,
   $v'$ = {{ checks.elastic }} m/s, mirrored about the normal.
""",
    solve=solve,
    checks=(
        # the wall acts along its normal only: the tangential speed is kept, the normal one
        # reversed and scaled by e
        Recompute("v_out", lambda p, s: np.hypot(p.e * p.v * np.cos(p.theta), p.v * np.sin(p.theta)),
                  name="components"),
        Balance("kinetic energy", lambda p, s: p.m * p.v**2 / 2,
                lambda p, s: p.m * s["v_out"]**2 / 2 + s["dT"], name="energy_balance"),
        Recompute("J", lambda p, s: p.m * (1 + p.e) * p.v * np.cos(p.theta),
                  name="normal_momentum_change"),
        Limit("v_out", {"e": 1.0}, lambda p: p.v, name="elastic"),
    ),
    figure=figure, figure_to_scale=True,
    parts=(
        Numeric("theta_out", "rebound angle", question=1, unit="deg", points=2,
                misconceptions=(
                    Misconception("mirror reflection", lambda p: p.theta,
                                  "Only the normal component is reduced, by e: the puck leaves "
                                  "flatter, tan θ' = tan θ / e."),
                    Misconception("tangent multiplied by e",
                                  lambda p: np.arctan(p.e * np.tan(p.theta)),
                                  "The smooth wall keeps the tangential part; the normal part "
                                  "shrinks: tan θ' = tan θ / e."),
                )),
        Numeric("v_out", "rebound speed", question=2, unit="m/s", points=1,
                misconceptions=(
                    Misconception("whole velocity scaled by e", lambda p: p.e * p.v,
                                  "Only the normal component is scaled by e on a smooth wall."),
                )),
        Numeric("dT", "kinetic energy lost", question=3, unit="J", points=1,
                misconceptions=(
                    Misconception("whole kinetic energy scaled",
                                  lambda p: (1 - p.e**2) * 0.5 * p.m * p.v**2,
                                  "Only the normal part's energy m (v cos θ)²/2 is reduced."),
                )),
        Numeric("J", "impulse of the wall", question=4, unit="N*s", points=1,
                misconceptions=(
                    Misconception("factor (1 + e) missing",
                                  lambda p: p.m * p.v * np.cos(p.theta),
                                  "The normal velocity is reversed: Δv_n = (1 + e) v cos θ."),
                )),
        Symbolic("theta_formula", "rebound angle as a formula", question=5, points=1,
                 expected="atan(tan(theta)/e)",
                 variables=("theta", "e"),
                 equals="theta_out",
                 misconceptions=(
                     Misconception("tangent multiplied by e", "atan(e*tan(theta))",
                                   "The normal component shrinks, so the tangent grows: tan θ' = tan θ / e."),
                 )),
    ),
)
