"""A block slides up a rough slope until it stops (Example 1.15)."""

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric,
                                Symbolic, Uniform, apart)
from dynagrade.exercise.checks import Balance, Limit
from dynagrade.exercise.figure import arrow, block, inclined_plane
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics.examples import incline


def figure(p):
    """The slope to scale at its angle, the block near its foot and the launch velocity
    up the slope (Example 1.15)."""
    drawing, axes, along, normal = inclined_plane(p.alpha)
    size = 0.09
    foot = 0.18 * along
    block(axes, tuple(foot + 0.5 * size * (along + normal)), size, size, "m", angle=p.alpha)
    start = foot + size * (along + 0.5 * normal)
    arrow(axes, tuple(start), tuple(start + 0.3 * along),
          f"v₀ = {format_number(p.v0)} m/s", offset=tuple(0.09 * normal), color="C3")
    axes.text(*(0.62 * along - 0.07 * normal), f"μ = {format_number(p.mu)}",
              ha="center", va="center", fontsize=10, rotation=np.degrees(p.alpha),
              rotation_mode="anchor")
    axes.set_ylim(-0.05, along[1] + 0.12)
    return drawing


def solve(p):
    return {
        "delta_x": incline.distance_up_slope(p.v0, p.alpha, p.mu, p.g),
        "a_up": incline.deceleration_up_slope(p.alpha, p.mu, p.g),
        "t_stop": incline.time_up_slope(p.v0, p.alpha, p.mu, p.g),
    }


EXERCISE = Exercise(
    id="sliding-up-a-slope",
    title="Frictional sliding up a slope",
    source="Example 1.15",
    topics=("work-energy balance", "Coulomb friction", "inclined plane"),
    params=(
        Uniform("m", 0.5, 5.0, step=0.1, unit="kg", symbol="m"),
        Uniform("v0", 2.0, 12.0, step=0.5, unit="m/s", symbol="v_0"),
        Uniform("alpha", 10, 50, step=1, unit="deg", symbol=r"\alpha"),
        Uniform("mu", 0.1, 0.6, step=0.05, symbol=r"\mu"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        # Taking N = m g instead of m g cos(alpha) changes the distance by the factor
        # (sin a + mu cos a)/(sin a + mu); on shallow slopes that is within tolerance.
        Constraint("the slope is steep enough that cos(alpha) matters by at least 5 %",
                   lambda p: p.mu * (1 - np.cos(p.alpha))
                   >= 0.05 * (np.sin(p.alpha) + p.mu * np.cos(p.alpha))),
        # decelerating uniformly to rest, delta_x = v0 t_stop / 2: at v0 = 2 m/s the
        # distance in m and the time in s are one number, and swapping the formulas
        # scores both
        Constraint("the distance and the time differ as numbers (v0 not 2 m/s)",
                   lambda p: apart(p.v0 / 2, 1.0)),
    ),
    statement="""
A block of mass $m$ = {{ m }} is pushed up a slope inclined at $\\alpha$ = {{ alpha }}
and leaves your hand with speed $v_0$ = {{ v0 }}. The coefficient of kinetic friction
between block and slope is $\\mu$ = {{ mu }}; $g$ = {{ g }}.

1. How far up the slope does the block slide before it comes to rest?
2. What is the magnitude of its deceleration while it slides up?
3. How long does it slide up?
4. Write the distance as a formula in $v_0$, $\\alpha$, $\\mu$ and $g$.
""",
    solution=r"""
Only the start (speed $v_0$) and the end (at rest) matter, so use the work–energy balance
$T_2 - T_1 = W_{12}$ (Example 1.15). Gravity is conservative; friction is not and its work is
integrated along the path. The normal force is $N = mg\cos\alpha$ (no motion across the
slope), so friction is $R = \mu m g\cos\alpha$, pointing down the slope while the block
slides up.

1. **Distance.** Over the distance $\Delta x$ the block rises $h = \Delta x\sin\alpha$.
   Eqs. (1.126)–(1.127): $0 - \tfrac{1}{2} m v_0^2 = -\mu m g\cos\alpha\,\Delta x - mg\,\Delta x\sin\alpha$,
   so (eq. (1.128))
   $\Delta x = \frac{v_0^2}{2g(\sin\alpha + \mu\cos\alpha)}$.
   With $v_0$ = {{ v0 }}, $\alpha$ = {{ alpha }}, $\mu$ = {{ mu }}, $g$ = {{ g }}:
   $\Delta x$ = {{ answers.delta_x }}. The mass drops out.
2. **Deceleration.** Linear momentum balance along the slope: gravity and friction both
   point down the slope, $m a = mg\sin\alpha + \mu mg\cos\alpha$, so
   $a = g(\sin\alpha + \mu\cos\alpha)$ = {{ answers.a_up }}. (Check: $v_0^2 = 2a\,\Delta x$.)
3. **Time.** The deceleration is constant, so the speed $v_0 - at$ vanishes at
   $t = v_0/a$ = {{ answers.t_stop }}.
4. **Formula.** $\Delta x$ = `{{ answers.delta_x_formula }}`.
5. **Check.** Without friction ($\mu \to 0$) the block would slide up
   $v_0^2/(2g\sin\alpha)$ = {{ checks.frictionless }} m, farther than with it, as it must.
""",
    solve=solve,
    checks=(
        # work-energy balance of Example 1.15, eq. (1.127): m v0^2/2 = m g dx sin(alpha)
        # + mu m g cos(alpha) dx
        Balance("energy per unit mass", lambda p, s: p.v0**2 / 2,
                lambda p, s: p.g * s["delta_x"] * (np.sin(p.alpha) + p.mu * np.cos(p.alpha)),
                name="work_energy"),
        Balance("speed", lambda p, s: p.v0, lambda p, s: abs(s["a_up"]) * s["t_stop"],
                name="uniform_deceleration"),
        # mu -> 0: the frictionless climb v0^2 / (2 g sin(alpha))
        Limit("delta_x", {"mu": 0.0}, lambda p: p.v0**2 / (2 * p.g * np.sin(p.alpha)),
              name="frictionless"),
    ),
    figure=figure, figure_to_scale=True,
    parts=(
        Numeric("delta_x", "distance up the slope", question=1, unit="m", points=2,
                misconceptions=(
                    Misconception("friction ignored",
                                  lambda p: p.v0**2 / (2 * p.g * np.sin(p.alpha)),
                                  "Friction also takes energy: W = -µ m g cos α Δx, "
                                  "eq. (1.127)."),
                    Misconception("friction helps",
                                  lambda p: p.v0**2 / (2 * p.g * (np.sin(p.alpha)
                                                                   - p.mu * np.cos(p.alpha))),
                                  "Friction opposes the motion up the slope: both gravity and "
                                  "friction slow the block, eq. (1.128)."),
                    Misconception("normal force taken as m g",
                                  lambda p: p.v0**2 / (2 * p.g * (np.sin(p.alpha) + p.mu)),
                                  "On a slope the normal force is m g cos α, not m g."),
                )),
        Numeric("a_up", "deceleration", question=2, unit="m/s^2", points=1,
                misconceptions=(
                    Misconception("friction ignored", lambda p: p.g * np.sin(p.alpha),
                                  "Friction µ m g cos α adds to the pull of gravity down the "
                                  "slope."),
                )),
        Numeric("t_stop", "time to stop", question=3, unit="s", points=1),
        Symbolic("delta_x_formula", "distance as a formula", question=4, points=1,
                 expected="v0^2/(2*g*(sin(alpha) + mu*cos(alpha)))",
                 variables=("v0", "alpha", "mu", "g"),
                 equals="delta_x",
                 misconceptions=(
                     Misconception("friction ignored", "v0^2/(2*g*sin(alpha))",
                                   "Friction also does work on the way up."),
                 )),
    ),
)
