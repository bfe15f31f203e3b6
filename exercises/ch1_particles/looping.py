"""A car coasting through a circular looping (Example 1.13)."""

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric,
                                Symbolic, Uniform, apart)
from dynagrade.exercise.checks import Balance, Recompute
from dynagrade.exercise.figure import angle_arc, arrow, describe, ground, new_drawing
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics.examples import looping


def figure(p):
    """The looping to scale in metres: the circle of radius R clamped at A, the car at the
    angle phi travelled from the bottom, and the entry velocity (Example 1.13)."""
    from dynagrade.exercise.figure import Circle

    R = p.R
    drawing, axes = new_drawing(4.6, 4.0)
    axes.add_patch(Circle((0.0, R), R, fill=False, edgecolor="0.1", lw=1.4))
    ground(axes, -1.9 * R, 1.2 * R, hatch=R / 12)
    car = np.array([R * np.sin(p.phi), R * (1.0 - np.cos(p.phi))])
    axes.plot([0.0, car[0]], [R, car[1]], color="0.4", lw=0.8, ls=":")
    axes.plot([0.0, 0.0], [R, 0.0], color="0.4", lw=0.8, ls=":")
    axes.plot(*car, "s", color="C0", ms=9)
    axes.text(*(car + 0.18 * R * (car - (0.0, R)) / R), "car", ha="center", va="center",
              fontsize=9)
    angle_arc(axes, (0.0, R), 0.22 * R, -np.pi / 2, p.phi - np.pi / 2,
              f"φ = {format_number(np.degrees(p.phi))}°", label_radius=0.45 * R)
    radius_end = (0.0, R) + R * np.array([np.cos(0.75 * np.pi), np.sin(0.75 * np.pi)])
    axes.plot([0.0, radius_end[0]], [R, radius_end[1]], color="0.1", lw=0.8)
    axes.text(0.5 * radius_end[0] - 0.08 * R, 0.5 * (R + radius_end[1]) + 0.08 * R,
              f"R = {format_number(R)} m", ha="right", va="bottom", fontsize=10)
    axes.plot([0.0], [0.0], "^", color="0.1", ms=8)
    axes.text(0.06 * R, -0.15 * R, "A", ha="left", va="top", fontsize=10)
    arrow(axes, (-1.7 * R, 0.12 * R), (-0.9 * R, 0.12 * R),
          f"v₀ = {format_number(p.v0)} m/s", offset=(0.0, 0.2 * R), color="C3")
    axes.set_xlim(-1.95 * R, 1.25 * R)
    axes.set_ylim(-0.3 * R, 2.1 * R)
    describe(axes, "A circular looping stands on the ground, clamped at its lowest point A. "
             "The car comes in from the left along the ground and travels round the "
             "looping counter-clockwise; φ is the angle at the centre from the line down "
             "to A to the line out to the car")
    return drawing


def solve(p):
    reactions = looping.support_reactions(p.phi, p.m, p.v0, p.R, p.g)
    return {
        "v_min_entry": looping.minimum_entry_speed(p.R, p.g),
        "N_max": looping.maximum_normal_force(p.m, p.v0, p.R, p.g),
        "v_phi": looping.speed(p.phi, p.v0, p.R, p.g),
        "N_phi": looping.looping_normal_force(p.phi, p.m, p.v0, p.R, p.g),
        "M_A": reactions.MA,
    }


def _normal_force(p, solved):
    """Radial momentum balance at angle phi, eq. (1.115): N = m v(phi)^2 / R
    + m g cos(phi), with v(phi) from the energy balance eq. (1.110)."""
    v_squared = p.v0**2 - 2 * p.g * p.R * (1 - np.cos(p.phi))
    return p.m * v_squared / p.R + p.m * p.g * np.cos(p.phi)


EXERCISE = Exercise(
    id="car-in-a-looping",
    title="Car in a looping",
    source="Example 1.13",
    topics=("work-energy balance", "normal force", "circular motion", "support reactions"),
    params=(
        Uniform("m", 600, 1500, step=50, unit="kg", symbol="m"),
        Uniform("R", 3.0, 10.0, step=0.5, unit="m", symbol="R"),
        Uniform("v0", 12.0, 30.0, step=0.5, unit="m/s", symbol="v_0"),
        Uniform("phi", 20, 160, step=5, unit="deg", symbol=r"\varphi"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        # two answers that agree as numbers can be swapped and score (verify's variety rule)
        Constraint("the speed at phi and the smallest entry speed differ",
                   lambda p: apart(solve(p)["v_min_entry"], solve(p)["v_phi"])),
        Constraint("the car stays on the track (v0 > sqrt(5 g R))",
                   lambda p: p.v0 > 1.05 * looping.minimum_entry_speed(p.R, p.g)),
        Constraint("the angle is clear of 90 degrees, where cos(phi) vanishes",
                   lambda p: abs(p.phi - np.pi / 2) > np.radians(10)),
        # Forgetting the speed lost on the way up changes N(phi) by 2 m g (1 - cos phi);
        # it must stand out from the 1 % tolerance.
        Constraint("the height gained by phi changes the normal force by at least 5 %",
                   lambda p: 2 * p.m * p.g * (1 - np.cos(p.phi))
                   >= 0.05 * looping.looping_normal_force(p.phi, p.m, p.v0, p.R, p.g)),
    ),
    statement="""
A car of mass $m$ = {{ m }} coasts with its engine off into a circular looping of radius
$R$ = {{ R }}, entering at the bottom with speed $v_0$ = {{ v0 }}. Neglect friction and
treat the car as a particle; $g$ = {{ g }}. The looping is clamped to the ground at its
lowest point A.

1. What is the smallest entry speed for which the car does not lose contact anywhere?
2. What is the largest normal force on the car during the looping?
3. What is the car's speed after it has travelled the angle $\\varphi$ = {{ phi }} around the looping?
4. What is the normal force there?
5. What is the magnitude of the clamping moment at A at that instant?
6. Write the smallest entry speed as a formula in $g$ and $R$.
""",
    solution=r"""
Without friction only gravity does work on the car (the normal force is perpendicular to
the track), so energy is conserved, eq. (1.102). At the angle $\varphi$ the car is
$R(1 - \cos\varphi)$ above the entry (Example 1.13).

1. **Smallest entry speed.** Energy conservation gives the speed,
   $v^2(\varphi) = v_0^2 - 2gR(1 - \cos\varphi)$ (eq. (1.110)). Linear momentum balance
   towards the centre, $m v^2/R = N - mg\cos\varphi$ (the centripetal acceleration $v^2/R$),
   gives the normal force (eq. (1.116))
   $N(\varphi) = \frac{m v_0^2}{R} + mg(3\cos\varphi - 2)$.
   It is smallest at the top, $\varphi = \pi$: $N(\pi) = m v_0^2/R - 5mg \ge 0$ requires
   $v_0 \ge \sqrt{5gR}$ (eq. (1.118)); with $R$ = {{ R }} and $g$ = {{ g }}:
   $v_{0,\min}$ = {{ answers.v_min_entry }}. (Merely reaching the top, $v_0 > 2\sqrt{gR}$, is
   not enough: the car would fall off the track first.)
2. **Largest normal force.** $N$ is largest where $\cos\varphi = 1$, at the bottom:
   $N_{\max} = m v_0^2/R + mg$; with $m$ = {{ m }} and $v_0$ = {{ v0 }}:
   $N_{\max}$ = {{ answers.N_max }}.
3. **Speed at $\varphi$** = {{ phi }}: $v = \sqrt{v_0^2 - 2gR(1 - \cos\varphi)}$
   = {{ answers.v_phi }}.
4. **Normal force there.** $N(\varphi)$ from above: {{ answers.N_phi }}.
5. **Clamping moment.** The car pushes on the track with $N$ along the radius; that force
   has the lever arm $R\sin\varphi$ about A (eq. (1.122)), so
   $|M_A| = N R\sin\varphi$ = {{ answers.M_A }}.
6. **Formula.** $v_{0,\min}$ = `{{ answers.v_min_formula }}`.
""",
    solve=solve,
    checks=(
        # energy balance from the bottom to phi, eq. (1.109)
        Balance("energy per unit mass", lambda p, s: p.v0**2 / 2,
                lambda p, s: s["v_phi"]**2 / 2 + p.g * p.R * (1 - np.cos(p.phi)),
                name="energy_balance"),
        Recompute("N_phi", _normal_force, name="radial_balance"),
        # eq. (1.118): the top is reached with N >= 0 from v0 = sqrt(5 g R)
        Recompute("v_min_entry", lambda p, s: np.sqrt(5 * p.g * p.R), name="eq_1_118"),
        Recompute("N_max", lambda p, s: p.m * p.v0**2 / p.R + p.m * p.g, name="at_the_bottom"),
        # eq. (1.122): the foundation's moment from the normal force at phi
        Recompute("M_A", lambda p, s: _normal_force(p, s) * p.R * np.sin(p.phi),
                  name="support_moment"),
    ),
    figure=figure, figure_to_scale=True,
    parts=(
        Numeric("v_min_entry", "smallest entry speed", question=1, unit="m/s", points=2,
                misconceptions=(
                    Misconception("only reaching the top",
                                  lambda p: looping.speed_to_reach_top(p.R, p.g),
                                  "v0 > 2√(gR) only gets the car to the top, eq. (1.112); "
                                  "it must also keep N ≥ 0 there, which needs √(5gR), "
                                  "eq. (1.118)."),
                )),
        Numeric("N_max", "largest normal force", question=2, unit="N", points=1,
                misconceptions=(
                    Misconception("weight forgotten", lambda p: p.m * p.v0**2 / p.R,
                                  "At the bottom the track carries the weight as well as "
                                  "providing the centripetal force."),
                )),
        Numeric("v_phi", "speed at phi", question=3, unit="m/s", points=1),
        Numeric("N_phi", "normal force at phi", question=4, unit="N", points=1,
                misconceptions=(
                    Misconception("energy loss of the height ignored",
                                  lambda p: p.m * p.v0**2 / p.R + p.m * p.g * np.cos(p.phi),
                                  "The car is slower at height R(1 − cos φ): use v(φ) from "
                                  "the energy balance, eq. (1.116)."),
                )),
        Numeric("M_A", "clamping moment at A", question=5, unit="N*m", points=1,
                misconceptions=(
                    Misconception("static moment",
                                  lambda p: looping.static_support_reactions(
                                      p.phi, p.m, p.R, p.g).MA,
                                  "That is the moment of the car at rest; in motion the track "
                                  "pushes with N(φ), eq. (1.122)."),
                )),
        Symbolic("v_min_formula", "smallest entry speed as a formula", question=6, points=1,
                 expected="sqrt(5*g*R)",
                 variables=("g", "R"),
                 equals="v_min_entry",
                 misconceptions=(
                     Misconception("only reaching the top", "2*sqrt(g*R)",
                                   "That only gets the car to the top; it must also keep "
                                   "contact there."),
                 )),
    ),
)
