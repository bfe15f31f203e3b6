"""A body shot straight up against height-dependent gravity g R^2/(R+x)^2 (Example 1.2,
acceleration known as a function of position, eq. 1.17).

The body is a planet or moon of drawn radius and surface gravity, not always the Earth,
so that its escape speed sqrt(2 g R) differs between students (issue 31: it used to be
11.1803 km/s for everybody)."""

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric, Symbolic,
                                Uniform, per_draw)
from dynagrade.exercise.checks import Integrated, Limit, Recompute
from dynagrade.mechanics import energy, kinematics


@per_draw
def solve(p):
    return {
        "v_x": float(kinematics.rocket_speed_at_height(p.x, p.v0, p.g, p.R)),
        "h_max": float(kinematics.rocket_peak_height(p.v0, p.g, p.R)),
        "v_esc": kinematics.escape_speed(p.g, p.R),
    }


def _climb(t, y, p):
    """Vertical flight under gravity falling off with distance: x'' = -g R^2 / (R + x)^2
    (Newton's law of gravitation with g at the surface)."""
    return (y[1], -p.g * p.R**2 / (p.R + y[0]) ** 2)


def _speed_at_height(p, solved):
    """Energy conservation with the potential -m g R^2 / (R + x), eq. (1.102)."""
    return np.sqrt(p.v0**2 - 2 * p.g * p.R * p.x / (p.R + p.x))


EXERCISE = Exercise(
    id="rocket-variable-gravity",
    title="Vertical launch against height-dependent gravity",
    source="Example 1.2",
    topics=("kinematics", "acceleration as a function of position", "gravity"),
    params=(
        Uniform("v0", 3.0, 9.0, step=0.25, unit="km/s", symbol="v_0"),
        Uniform("x", 200, 3000, step=50, unit="km", symbol="x"),
        Uniform("R", 3000, 7000, step=100, unit="km", symbol="R"),
        Uniform("g", 5.0, 12.0, step=0.1, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("the probe comes back: v0 below 90 % of the escape speed",
                   lambda p: p.v0 < 0.9 * kinematics.escape_speed(p.g, p.R)),
        Constraint("the probe passes the height x well below its peak",
                   lambda p: p.x < 0.9 * solve(p)["h_max"]),
        Constraint("constant gravity would give a speed at x at least 4 % off",
                   lambda p: abs(max(p.v0**2 - 2 * p.g * p.x, 0.0) ** 0.5 - solve(p)["v_x"])
                   > 0.04 * solve(p)["v_x"]),
    ),
    statement="""
A probe leaves the surface of a planet of radius $R$ = {{ R }} vertically with speed
$v_0$ = {{ v0 }} (engine off, no air). Gravity decreases with the height $x$ as $g(x) = g R^2/(R+x)^2$ with
the surface gravity $g$ = {{ g }}.

1. What is its speed at the height $x$ = {{ x }}?
2. How high does it rise?
3. Above what launch speed would it never come back?
4. Write the greatest height as a formula in $v_0$, $g$ and $R$.
""",
    solution=r"""
The acceleration is known as a function of the position, $\ddot x = -gR^2/(R + x)^2$.
Write $\ddot x = v\,\mathrm dv/\mathrm dx$ and integrate over $x$ (Example 1.2, eq. (1.17)):
$\tfrac{1}{2} v^2 - \tfrac{1}{2} v_0^2 = -\int_0^x \frac{gR^2}{(R + \xi)^2}\,\mathrm d\xi
  = -\frac{gRx}{R + x}$.
(This is the energy conservation of the probe in the field of the planet.)

1. **Speed at $x$.** $v(x) = \sqrt{v_0^2 - 2gRx/(R + x)}$; with $v_0$ = {{ v0 }},
   $g$ = {{ g }}, $R$ = {{ R }} and $x$ = {{ x }}: $v$ = {{ answers.v_x }}. (With
   constant $g$ it would be slower: gravity weakens with height.)
2. **Greatest height.** $v = 0$: $v_0^2 = 2gRh/(R + h)$, solved for $h$:
   $h_{\max} = \frac{R v_0^2}{2gR - v_0^2}$
   = {{ answers.h_max }}.
3. **Escape speed.** $h_{\max}$ grows without bound as $v_0^2 \to 2gR$: above
   $v_{\text{esc} } = \sqrt{2gR}$ = {{ answers.v_esc }} the probe never comes back.
4. **Formula.** $h_{\max}$ = `{{ answers.h_formula }}`.
5. **Check.** Were gravity uniform ($R \to \infty$) the probe would rise only
   $v_0^2/(2g)$ = {{ checks.uniform_gravity }} m: gravity falling off with height lets it climb higher.
""",
    solve=solve,
    checks=(
        # R -> infinity: uniform gravity, the vertical throw's v0^2 / (2 g), eq. (1.106);
        # at R = 1e12 m the remaining v0^2 / (2 g R) is below 5e-6
        Limit("h_max", {"R": 1e12}, lambda p: p.v0**2 / (2 * p.g), name="uniform_gravity",
              rtol=1e-5),
        # below 90 % of the escape speed the probe turns round well within 100 v0/g
        Integrated("h_max", _climb, lambda p: (0.0, p.v0), lambda p, s: 100 * p.v0 / p.g,
                   lambda t, y, p: y[0], name="integrated_climb",
                   event=lambda t, y, p: y[1], direction=-1),
        Recompute("v_x", _speed_at_height, name="energy_balance"),
        Recompute("v_esc", lambda p, s: np.sqrt(2 * p.g * p.R), name="zero_total_energy"),
    ),
    parts=(
        Numeric("v_x", "speed at height x", question=1, unit="km/s", points=1,
                misconceptions=(
                    Misconception("constant gravity",
                                  lambda p: max(p.v0**2 - 2 * p.g * p.x, 0.0) ** 0.5,
                                  "g decreases with height: integrate v dv = a(x) dx, eq. (1.17)."),
                )),
        Numeric("h_max", "greatest height", question=2, unit="km", points=2,
                misconceptions=(
                    Misconception("constant gravity",
                                  lambda p: energy.height_gain(p.v0, 0.0, p.g),
                                  "v0²/(2g) holds only while g is constant; here g(x) falls off "
                                  "with height, eq. (1.17)."),
                )),
        Numeric("v_esc", "escape speed", question=3, unit="km/s", points=1,
                misconceptions=(
                    Misconception("no factor 2", lambda p: (p.g * p.R) ** 0.5,
                                  "v0² = 2 g R x/(R+x) tends to 2 g R as x grows."),
                )),
        Symbolic("h_formula", "greatest height as a formula", question=4, points=1,
                 expected="R*v0^2/(2*g*R - v0^2)",
                 variables=("v0", "g", "R"),
                 equals="h_max",
                 misconceptions=(
                     Misconception("constant gravity", "v0^2/(2*g)",
                                   "That is the constant-gravity height."),
                 )),
    ),
)
