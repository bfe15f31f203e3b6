"""Throwing a ball from level ground: range, peak height and flight time (Example 1.9)."""

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric,
                                Symbolic, Uniform)
from dynagrade.exercise.checks import Integrated, Limit, Symmetry
from dynagrade.exercise.checks.motions import height, launched, rising, thrown
from dynagrade.exercise.figure import angle_arc, arrow, ground, new_drawing
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics.examples import projectile


def solve(p):
    v1, v2 = projectile.velocity(0.0, p.v0, p.alpha, p.g)
    return {
        "x_max": projectile.horizontal_range(p.v0, p.alpha, p.g),
        "h_max": projectile.peak_height(p.v0, p.alpha, p.g),
        "t_flight": projectile.flight_time(p.v0, p.alpha, p.g),
        # intermediate quantities of the worked solution
        "v1": float(v1),
        "v2": float(v2),
        "t_peak": projectile.peak_time(p.v0, p.alpha, p.g),
    }


def figure(p):
    """The throw to scale: the path of eq. (1.78) over the flight time of eq. (1.79), the
    launch angle and the launch velocity (its arrow a quarter of the path's width)."""
    t = np.linspace(0.0, projectile.flight_time(p.v0, p.alpha, p.g), 81)
    x1, x2 = projectile.position(t, p.v0, p.alpha, p.g)
    width = float(x1[-1])
    drawing, axes = new_drawing(5.0, 2.2 + 2.0 * np.tan(p.alpha) / 4)
    ground(axes, -0.08 * width, 1.08 * width, hatch=width / 60)
    axes.plot(x1, x2, ls="--", color="0.45", lw=1.0)
    axes.plot([0], [0], "o", color="C3", ms=6)
    tip = (0.25 * width * np.cos(p.alpha), 0.25 * width * np.sin(p.alpha))
    arrow(axes, (0.0, 0.0), tip, f"v₀ = {format_number(p.v0)} m/s",
          offset=(-0.1 * width, 0.05 * width))
    angle_arc(axes, (0.0, 0.0), 0.1 * width, 0.0, p.alpha,
              f"α = {format_number(np.degrees(p.alpha))}°", label_radius=0.2 * width)
    axes.set_xlim(-0.12 * width, 1.12 * width)
    axes.set_ylim(-0.06 * width, max(float(x2.max()), tip[1]) + 0.08 * width)
    return drawing


_LAUNCH = ("v0", "alpha", "g")

def double_angle_matters(p):
    """Whether sin α and sin 2α differ by more than 2 % (twice the tolerance): at 60° they
    agree, and the double-angle slip gives the right range, so it is not tried there."""
    return abs(np.sin(p.alpha) - np.sin(2 * p.alpha)) > 0.02 * np.sin(2 * p.alpha)


def _launch(p):
    """The launch state of eq. (1.75)."""
    return launched(p.v0, p.alpha)


def _flight_horizon(p, solved):
    """Longer than any flight: v0 sin(alpha)/g is half of it."""
    return 4 * p.v0 / p.g


EXERCISE = Exercise(
    id="projectile-range",
    title="Throwing a ball: range, peak height and flight time",
    source="Example 1.9",
    topics=("projectile motion", "linear momentum balance", "kinematics"),
    params=(
        Uniform("v0", 5.0, 30.0, step=0.5, unit="m/s", symbol="v_0"),
        Uniform("alpha", 15, 75, step=1, unit="deg", symbol=r"\alpha"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        # At 45 degrees sin(2a) = 1 and the range equals v0^2/g: the sin(a) slip is
        # then the only misconception to catch, and near 45 it is caught weakly.
        Constraint("the angle is at least 5 degrees away from 45 degrees",
                   lambda p: abs(p.alpha - np.pi / 4) >= np.radians(5) - 1e-9),
    ),
    statement="""
A ball is thrown from level ground with speed $v_0$ = {{ v0 }} at an angle
$\\alpha$ = {{ alpha }} above the horizontal. Gravity is $g$ = {{ g }}; neglect air drag.

1. How far from the launch point does the ball land?
2. How high above the ground does it rise?
3. How long is it in the air?
4. Write the landing distance as a formula in $v_0$, $\\alpha$ and $g$.
""",
    solution=r"""
Linear momentum balance for the ball, eq. (1.63), in the two directions (Example 1.9):
the only force is the weight $-mg\,\mathbf{e}_2$, so $\ddot x_1 = 0$ and $\ddot x_2 = -g$.
With the launch velocity of eq. (1.75), $v_0\cos\alpha$ = {{ si.v1 }} m/s along
$\mathbf{e}_1$ and $v_0\sin\alpha$ = {{ si.v2 }} m/s along $\mathbf{e}_2$, integrating
twice gives the path of eq. (1.78): $x_1(t) = v_0 t\cos\alpha$ and
$x_2(t) = v_0 t\sin\alpha - g t^2/2$.

1. The ball lands when $x_2 = 0$ again, at $t_{1,\max} = 2 v_0\sin\alpha/g$, eq. (1.79).
   Then $x_{1,\max} = v_0\cos\alpha\, t_{1,\max}$, eq. (1.80):
   $x_{1,\max} = 2 v_0^2\sin\alpha\cos\alpha/g = v_0^2\sin 2\alpha/g$ = {{ answers.x_max }}.
2. At the peak the vertical velocity vanishes: $\dot x_2 = v_0\sin\alpha - g t = 0$ at
   $t_{2,\max} = v_0\sin\alpha/g$ = {{ si.t_peak }} s, eq. (1.81). Putting it into $x_2(t)$,
   eq. (1.82): $x_{2,\max} = v_0^2\sin^2\alpha/(2g)$ = {{ answers.h_max }}.
3. The flight time is $t_{1,\max} = 2 v_0\sin\alpha/g$ = {{ answers.t_flight }}: twice the
   time to the peak, because the parabola is symmetric about its peak.
4. Step 1 as a formula: `{{ answers.x_max_formula }}`.
5. **Check.** At $\alpha = \pi/4$ the same speed would reach $v_0^2/g$ = {{ checks.at_45_degrees }}
   m, the longest range of all (Example 1.9), and no less than {{ answers.x_max }}.
""",
    solve=solve,
    checks=(
        Integrated("x_max", thrown, _launch, _flight_horizon, lambda t, y, p: y[0],
                   name="integrated_range", event=height, direction=-1),
        Integrated("t_flight", thrown, _launch, _flight_horizon, lambda t, y, p: t,
                   name="integrated_flight_time", event=height, direction=-1),
        Integrated("h_max", thrown, _launch, _flight_horizon, lambda t, y, p: y[1],
                   name="integrated_peak", event=rising, direction=-1),
        # Example 1.9: the range is largest, v0^2/g, at alpha = pi/4
        Limit("x_max", {"alpha": np.pi / 4}, lambda p: p.v0**2 / p.g, name="at_45_degrees"),
        # eq. (1.80): sin(2 alpha) is the same at the complementary angle
        Symmetry("x_max", lambda p: {"alpha": np.pi / 2 - p.alpha},
                 name="complementary_angle"),
    ),
    figure=figure, figure_to_scale=True,
    parts=(
        Numeric("x_max", "landing distance", question=1, unit="m", points=2,
                misconceptions=(
                    Misconception("sin(alpha) for sin(2 alpha)",
                                  lambda p: p.v0**2 * np.sin(p.alpha) / p.g,
                                  "The range is 2 v0² sin α cos α / g = v0² sin 2α / g, "
                                  "eq. (1.80): check the double angle.",
                                  applies=double_angle_matters),
                    Misconception("half the range",
                                  lambda p: projectile.horizontal_range(p.v0, p.alpha, p.g) / 2,
                                  "That is where the ball is highest: it lands after twice "
                                  "the time to the peak."),
                )),
        Numeric("h_max", "peak height", question=2, unit="m", points=1,
                misconceptions=(
                    Misconception("sin instead of sin squared",
                                  lambda p: p.v0**2 * np.sin(p.alpha) / (2 * p.g),
                                  "Only the vertical component v0 sin α is lost to gravity: "
                                  "h = (v0 sin α)² / (2g), eq. (1.82)."),
                )),
        Numeric("t_flight", "flight time", question=3, unit="s", points=1,
                misconceptions=(
                    Misconception("time to the peak",
                                  lambda p: projectile.peak_time(p.v0, p.alpha, p.g),
                                  "That is the time to the peak; the ball needs as long "
                                  "again to come down, eq. (1.79)."),
                )),
        Symbolic("x_max_formula", "landing distance as a formula", question=4, points=1,
                 expected="v0^2*sin(2*alpha)/g", variables=_LAUNCH, equals="x_max",
                 misconceptions=(
                     Misconception("sin(alpha) for sin(2 alpha)", "v0^2*sin(alpha)/g",
                                   "Check the double angle: 2 sin α cos α = sin 2α."),
                 )),
    ),
)
