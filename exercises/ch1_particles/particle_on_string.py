"""A particle swung on a string at constant angular velocity: the string force
(Example 1.10, eq. 1.84)."""

import numpy as np

from dynagrade.exercise import (Constraint, Exercise, Misconception, Numeric, Symbolic, Uniform,
                                Variable)
from dynagrade.exercise.checks import Recompute
from dynagrade.exercise.figure import describe, dimension, new_drawing
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import kinematics, particle


def figure(p):
    """Top view of the table to scale: the fixed point O, the string of length l and the
    particle on its circle, turning counter-clockwise at n (Example 1.10)."""
    from dynagrade.exercise.figure import Circle

    l = p.l
    rpm = p.n * 60 / (2 * np.pi)
    drawing, axes = new_drawing(4.0, 4.0)
    axes.add_patch(Circle((0.0, 0.0), l, fill=False, edgecolor="0.5", lw=0.8, ls="--"))
    where = np.radians(35)
    mass = l * np.array([np.cos(where), np.sin(where)])
    axes.plot([0.0, mass[0]], [0.0, mass[1]], color="0.1", lw=1.2)
    axes.plot([0.0], [0.0], "o", color="0.1", ms=5)
    axes.text(-0.06 * l, -0.06 * l, "O", ha="right", va="top", fontsize=10)
    axes.plot(*mass, "o", color="C0", ms=11)
    axes.text(*(1.16 * mass), f"m = {format_number(p.m)} kg", ha="left", va="bottom",
              fontsize=10)
    dimension(axes, (0.0, 0.0), tuple(mass), f"l = {format_number(l)} m", offset=-0.12 * l,
              tick=0.04 * l, side=-1.0)
    start, end = np.radians(100), np.radians(150)
    axes.annotate("", xy=(l * np.cos(end), l * np.sin(end)),
                  xytext=(l * np.cos(start), l * np.sin(start)),
                  arrowprops={"arrowstyle": "-|>", "color": "C3", "lw": 1.5,
                              "connectionstyle": "arc3,rad=0.15", "shrinkA": 0,
                              "shrinkB": 0})
    axes.text(-0.5 * l, 1.0 * l, f"n = {format_number(rpm)} rpm", color="C3",
              ha="right", va="bottom", fontsize=10)
    axes.set_xlim(-1.2 * l, 1.2 * l)
    axes.set_ylim(-1.1 * l, 1.2 * l)
    describe(axes, "Seen from above: the particle moves counter-clockwise on a circle "
             "about the fixed point O, held by the string; a curved arrow beside the circle shows "
             "this sense of rotation")
    return drawing


def solve(p):
    omega = p.n          # the rate n arrives in SI, i.e. as an angular velocity in rad/s
    return {"S": particle.string_tension(p.m, p.l, omega),
            "v": kinematics.circular_speed(p.l, omega),
            "S_double": particle.string_tension(p.m, p.l, 2 * omega), "omega": omega}


EXERCISE = Exercise(
    id="particle-on-a-string",
    title="Particle on a string: the string force",
    source="Example 1.10",
    topics=("linear momentum balance", "circular motion", "centripetal force"),
    params=(
        Uniform("m", 0.1, 2.0, step=0.05, unit="kg", symbol="m"),
        Uniform("l", 0.3, 2.0, step=0.05, unit="m", symbol="l"),
        Uniform("n", 30, 240, step=10, unit="rpm", symbol="n"),
    ),
    constraints=(
        Constraint("omega is not near 1 rad/s, where omega and omega^2 agree",
                   lambda p: abs(p.n - 1.0) > 0.2),
        Constraint("the length is not near 1 m, where l and 1/l agree",
                   lambda p: abs(p.l - 1.0) > 0.1),
    ),
    statement="""
A particle of mass $m$ = {{ m }} on a taut string of length $l$ = {{ l }} is swung around
a fixed point on a smooth horizontal table at the constant rate $n$ = {{ n }} (revolutions
per minute). Gravity acts perpendicular to the table.

1. What is the force in the string?
2. What is the particle's speed?
3. What would the string force be at twice the rate of revolution?
4. Write the string force as a formula in $m$, $l$ and the angular velocity $\\omega$.
""",
    solution=r"""
The particle moves on a circle of radius $l$ at constant angular velocity, so its
acceleration is purely centripetal, $a = -l\omega^2 e_r$ (eq. (1.83)). On the table,
gravity and the normal force cancel; the string force $S$ is the only force in the plane.
First the rate in SI: one revolution is $2\pi$, so $n$ = {{ n }} is
$\omega = 2\pi n$ = {{ si.omega }} rad/s (with $n$ in revolutions per second).

1. **String force.** Linear momentum balance along $e_r$, eq. (1.84): $-S = -m l \omega^2$,
   so $S = m l\omega^2$. With $m$ = {{ m }} and $l$ = {{ l }}: $S$ = {{ answers.S }}.
2. **Speed.** $v = l\omega$ = {{ answers.v }}.
3. **Twice the rate.** $S$ grows with $\omega^2$: doubling the rate multiplies it by four,
   $S$ = {{ answers.S_double }}.
4. **Formula.** $S$ = `{{ answers.S_formula }}`.
""",
    solve=solve,
    checks=(
        # eq. (1.84): S = m l omega^2, omega the rate n in rad/s
        Recompute("S", lambda p, s: p.m * p.l * p.n**2, name="radial_balance"),
        Recompute("S_double", lambda p, s: 4 * s["S"], name="twice_the_rate"),
        Recompute("v", lambda p, s: p.l * p.n, name="speed_eq_1_19"),
    ),
    figure=figure,
    parts=(
        Numeric("S", "string force", question=1, unit="N", points=2,
                misconceptions=(
                    Misconception("rpm used as rad/s", lambda p: p.m * p.l * (p.n * 60 / (2 * np.pi)) ** 2,
                                  "Convert: ω = 2π n / 60 in rad/s."),
                    Misconception("revolutions not converted to radians",
                                  lambda p: p.m * p.l * (p.n / (2 * np.pi)) ** 2,
                                  "One revolution is 2π rad: ω = 2π n / 60."),
                    Misconception("omega not squared",
                                  lambda p: p.m * p.l * p.n,
                                  "|S| = m l ω², eq. (1.84)."),
                )),
        Numeric("v", "speed", question=2, unit="m/s", points=1),
        Numeric("S_double", "string force at twice the rate", question=3, unit="N", points=1,
                misconceptions=(
                    Misconception("linear in omega",
                                  lambda p: 2 * particle.string_tension(p.m, p.l, p.n),
                                  "The force grows with ω²: twice the rate, four times the force."),
                )),
        Symbolic("S_formula", "string force as a formula", question=4,
                 points=1, expected="m*l*omega^2",
                 variables={"m": None, "l": None,
                            "omega": Variable(0.5, 30, "rad/s")},
                 misconceptions=(
                     Misconception("divided by l", "m*omega^2/l",
                                   "a = l ω², so the force is m l ω²."),
                 )),
    ),
)

