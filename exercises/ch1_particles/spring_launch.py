"""A particle shot upward by a compressed spring: launch height (Example 1.12, variation,
eq. 1.108)."""

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric, Symbolic,
                                Uniform, per_draw)
from dynagrade.exercise.checks import Balance, Integrated
from dynagrade.mechanics import energy


@per_draw
def solve(p):
    h = energy.spring_launch_height(p.k, p.dx, p.m, p.g)
    return {"h": h, "V_spring": float(energy.spring_potential_of_stretch(p.k, p.dx)),
            "v_release": float(energy.speed_after_work(p.m, 0.0, energy.spring_potential_of_stretch(p.k, p.dx)
                                                       - p.m * p.g * p.dx))}


def _launch(t, y, p):
    """The particle on the spring while compressed, under gravity after: x measured up from
    the compressed start, the spring pushes k (dx - x) while x < dx (eqs. (1.96), (1.97))."""
    push = p.k * (p.dx - y[0]) if y[0] < p.dx else 0.0
    return (y[1], push / p.m - p.g)


def _compressed(p):
    """At rest with the spring compressed (x = 0)."""
    return (0.0, 0.0)


def _launch_horizon(p, solved):
    """Longer than the push (half a period of the spring) and the climb after it."""
    return np.pi * np.sqrt(p.m / p.k) + 2 * p.dx * np.sqrt(p.k / p.m) / p.g


def _relaxed(t, y, p):
    """Zero when the spring reaches its natural length."""
    return y[0] - p.dx


EXERCISE = Exercise(
    id="spring-launch-height",
    title="Spring launch: how high does the particle fly?",
    source="Example 1.12",
    topics=("conservation of energy", "spring potential", "gravity potential"),
    params=(
        Uniform("m", 0.02, 0.5, step=0.01, unit="kg", symbol="m"),
        Uniform("k", 100, 2000, step=50, unit="N/m", symbol="k"),
        Uniform("dx", 2, 15, step=0.5, unit="cm", symbol=r"\Delta x"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("the spring launches the particle well clear of itself",
                   lambda p: solve(p)["h"] > 3 * p.dx),
        # m g dx must be at least a tenth of the spring energy, else ignoring it is harmless
        Constraint("the rise over the compression costs at least 10 % of the spring energy",
                   lambda p: p.m * p.g * p.dx > 0.1 * energy.spring_potential_of_stretch(p.k, p.dx)),
        Constraint("the height stays below 100 m", lambda p: solve(p)["h"] < 100),
    ),
    statement="""
A particle of mass $m$ = {{ m }} sits on a vertical spring (stiffness $k$ = {{ k }}),
and both are held with the spring compressed by $\\Delta x$ = {{ dx }}. They are released
from rest, and the spring launches the particle straight up; $g$ = {{ g }}, no air drag,
the spring is massless.

1. How high above its starting point does the particle rise?
2. How much energy was stored in the spring?
3. How fast is the particle when the spring reaches its natural length?
4. Write the height as a formula in $k$, $\\Delta x$ (write `dx`), $m$ and $g$.
""",
    solution=r"""
Spring force and gravity are conservative and there is no drag, so $T + V$ is conserved
(eq. (1.102)); compare the start (at rest, spring compressed) with the state asked for.
Measure heights from the starting point.

1. **Height.** At the start $T_1 = 0$ and the spring stores $\tfrac{1}{2} k\Delta x^2$; at the
   highest point $T_2 = 0$, the particle has left the relaxed spring and gravity stores $mgh$:
   $\tfrac{1}{2} k\,\Delta x^2 = mgh \quad\Rightarrow\quad h = \frac{k\,\Delta x^2}{2mg}$.
   With $k$ = {{ k }}, $\Delta x$ = {{ dx }}, $m$ = {{ m }}, $g$ = {{ g }}:
   $h$ = {{ answers.h }}.
2. **Stored energy.** $V_{\text{spring} } = \tfrac{1}{2} k\,\Delta x^2$ = {{ answers.V_spring }}.
3. **Speed at the natural length.** The particle has then risen by $\Delta x$ and the spring
   is relaxed: $\tfrac{1}{2} k\,\Delta x^2 = \tfrac{1}{2} m v^2 + mg\,\Delta x$, so
   $v = \sqrt{k\Delta x^2/m - 2g\,\Delta x}$ = {{ answers.v_release }}.
4. **Formula.** $h$ = `{{ answers.h_formula }}`.
""",
    solve=solve,
    checks=(
        Integrated("h", _launch, _compressed,
                   _launch_horizon,
                   lambda t, y, p: y[0], name="integrated_launch",
                   event=lambda t, y, p: y[1], direction=-1, rtol=1e-5),
        # energy conservation, eq. (1.107): the spring's energy ends as m g h
        Balance("energy", lambda p, s: s["V_spring"], lambda p, s: p.m * p.g * s["h"],
                name="energy_balance"),
        # at the spring's natural length (x = dx) the speed of the same integration
        Integrated("v_release", _launch, _compressed, _launch_horizon, lambda t, y, p: y[1],
                   name="integrated_release", event=_relaxed, direction=1),
    ),
    parts=(
        Numeric("h", "height above the start", question=1, unit="m", points=2,
                misconceptions=(
                    Misconception("factor 1/2 in the spring energy forgotten",
                                  lambda p: p.k * p.dx**2 / (p.m * p.g),
                                  "The spring energy is k Δx²/2, eq. (1.97)."),
                    Misconception("spring energy linear in the compression",
                                  lambda p: p.k * p.dx / (2 * p.m * p.g),
                                  "V = k Δx²/2: the compression enters squared."),
                )),
        Numeric("V_spring", "stored spring energy", question=2, unit="J", points=1),
        Numeric("v_release", "speed at the spring's natural length", question=3,
                unit="m/s", points=1,
                misconceptions=(
                    Misconception("gravity over the compression ignored",
                                  lambda p: (p.k / p.m) ** 0.5 * p.dx,
                                  "The particle also rises by Δx while the spring expands: "
                                  "subtract m g Δx."),
                )),
        Symbolic("h_formula", "height as a formula", question=4,
                 points=1, expected="k*dx^2/(2*m*g)",
                 variables=("k", "dx", "m", "g"),
                 equals="h",
                 misconceptions=(
                     Misconception("factor 1/2 forgotten", "k*dx^2/(m*g)",
                                   "The spring energy is k Δx²/2."),
                 )),
    ),
)
