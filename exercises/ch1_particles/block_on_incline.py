"""A block sliding down an inclined plane with kinetic friction: acceleration, normal
force, and whether it comes to rest (Example 1.8, eqs. 1.72-1.74)."""

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric, Options,
                                Symbolic, Uniform)
from dynagrade.exercise.checks import Limit, Recompute
from dynagrade.exercise.figure import block, inclined_plane
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics.examples import incline


def figure(p):
    """The rough plane to scale at its angle with the block on it (Example 1.8); the slope
    is one unit long, the block a tenth of that."""
    drawing, axes, along, normal = inclined_plane(p.alpha)
    size = 0.11
    block(axes, tuple(0.72 * along + 0.5 * size * normal), 1.4 * size, size, "m",
          angle=p.alpha)
    axes.text(*(0.72 * along + 1.5 * size * normal), f"m = {format_number(p.m)} kg",
              ha="center", va="center", fontsize=10, rotation=np.degrees(p.alpha),
              rotation_mode="anchor")
    axes.text(*(0.42 * along + 0.045 * normal), f"μ = {format_number(p.mu)}",
              ha="center", va="center", fontsize=10, rotation=np.degrees(p.alpha),
              rotation_mode="anchor")
    axes.set_ylim(-0.05, along[1] + 0.2)
    return drawing


def solve(p):
    return {
        "a": incline.sliding_acceleration(p.alpha, p.mu, p.g),
        "N": incline.incline_normal_force(p.m, p.alpha, p.g),
        "stops": "yes" if incline.decelerates_down_slope(p.alpha, p.mu) else "no",
    }


def swapped(p):
    """The acceleration with sin and cos swapped."""
    return p.g * (np.cos(p.alpha) - p.mu * np.sin(p.alpha))


def swap_matters(p):
    """Whether swapping sin and cos changes the acceleration by more than 2 % (twice the
    tolerance); near 45° it does not, and the swap is not tried there."""
    key = incline.sliding_acceleration(p.alpha, p.mu, p.g)
    return abs(swapped(p) - key) > 0.02 * abs(key)


def _sliding_down(p, solved):
    """Linear momentum balance along the slope with Coulomb friction, eq. (1.73):
    x1'' = g (sin(alpha) - mu cos(alpha))."""
    return p.g * (np.sin(p.alpha) - p.mu * np.cos(p.alpha))


EXERCISE = Exercise(
    id="block-sliding-down-incline",
    title="Block sliding down a rough incline",
    source="Example 1.8",
    topics=("linear momentum balance", "Coulomb friction", "inclined plane"),
    params=(
        Uniform("m", 0.5, 10.0, step=0.5, unit="kg", symbol="m"),
        Uniform("alpha", 10, 50, step=1, unit="deg", symbol=r"\alpha"),
        Uniform("mu", 0.1, 0.9, step=0.05, symbol=r"\mu"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("the block clearly accelerates or decelerates: |a| > 0.3 m/s^2",
                   lambda p: abs(incline.sliding_acceleration(p.alpha, p.mu, p.g)) > 0.3),
    ),
    statement="""
A block of mass $m$ = {{ m }} slides down a plane inclined at $\\alpha$ = {{ alpha }}.
The kinetic friction coefficient is $\\mu$ = {{ mu }}; $g$ = {{ g }}.

1. What is its acceleration along the slope, counted positive down the slope (negative if it slows down)?
2. What is the normal force of the plane on the block?
3. Does the block eventually come to rest on the slope?
4. Write the acceleration as a formula in $g$, $\\alpha$ and $\\mu$.
""",
    solution=r"""
Take $x_1$ down the slope and $x_2$ normal to it. On the block act gravity $mg$, the normal
force $N$ and kinetic friction $R = \mu N$, which points up the slope as long as the block
slides down (eq. (1.74)).

1. **Acceleration.** Linear momentum balance in the inclined frame, eq. (1.72):
   $m\ddot x_1 = mg\sin\alpha - R$ and $0 = N - mg\cos\alpha$. With $R = \mu N$ the mass drops
   out, eq. (1.73):
   $\ddot x_1 = g(\sin\alpha - \mu\cos\alpha)$.
   With $g$ = {{ g }}, $\alpha$ = {{ alpha }} and $\mu$ = {{ mu }}: $\ddot x_1$ = {{ answers.a }}.
2. **Normal force.** From the balance normal to the slope, $N = mg\cos\alpha$ — only the
   component of the weight across the slope presses on it. With $m$ = {{ m }}:
   $N$ = {{ answers.N }}.
3. **Does it stop?** The sign of $\sin\alpha - \mu\cos\alpha$ decides, i.e. whether
   $\mu$ is larger than $\tan\alpha$.
{%- if answers.stops == "yes" %}
   Here $\mu$ = {{ mu }} is larger than $\tan\alpha$: the acceleration is negative, the block
   slows down and comes to rest — **{{ answers.stops }}**.
{%- else %}
   Here $\mu$ = {{ mu }} is smaller than $\tan\alpha$: the acceleration is positive, the block
   keeps speeding up and never comes to rest — **{{ answers.stops }}**.
{%- endif %}
4. **Formula.** $\ddot x_1$ = `{{ answers.a_formula }}`.
5. **Check.** Without friction ($\mu \to 0$, Example 1.8) the block would speed up at
   $g\sin\alpha$ = {{ checks.frictionless }} m/s²: friction only ever lowers $\ddot x_1$.
""",
    solve=solve,
    checks=(
        Recompute("a", _sliding_down, name="momentum_balance_along_slope"),
        # eq. (1.68) tilted: the normal force carries the weight's component m g cos(alpha)
        Recompute("N", lambda p, s: p.m * p.g * np.cos(p.alpha), name="normal_balance"),
        # Example 1.8 without friction: x1'' = g sin(alpha)
        Limit("a", {"mu": 0.0}, lambda p: p.g * np.sin(p.alpha), name="frictionless"),
    ),
    figure=figure, figure_to_scale=True,
    parts=(
        Numeric("a", "acceleration down the slope", question=1, unit="m/s^2", points=2,
                misconceptions=(
                    Misconception("sin and cos swapped", swapped,
                                  "Gravity's component along the slope is m g sin α, the normal "
                                  "force m g cos α, eq. (1.72).", applies=swap_matters),
                    Misconception("friction forgotten", lambda p: p.g * np.sin(p.alpha),
                                  "Friction R = µ N acts up the slope while the block slides "
                                  "down, eq. (1.73)."),
                    Misconception("normal force taken as m g",
                                  lambda p: p.g * (np.sin(p.alpha) - p.mu),
                                  "On a slope N = m g cos α."),
                )),
        Numeric("N", "normal force", question=2, unit="N", points=1,
                misconceptions=(
                    Misconception("normal force equals the weight", lambda p: p.m * p.g,
                                  "Only the component m g cos α presses on the slope."),
                )),
        Options("stops", "comes to rest", question=3, options=("yes", "no"), points=1),
        Symbolic("a_formula", "acceleration as a formula", question=4, points=1,
                 expected="g*(sin(alpha) - mu*cos(alpha))",
                 variables=("g", "alpha", "mu"),
                 equals="a",
                 misconceptions=(
                     Misconception("sin and cos swapped", "g*(cos(alpha) - mu*sin(alpha))",
                                   "Gravity along the slope is g sin α."),
                 )),
    ),
)
