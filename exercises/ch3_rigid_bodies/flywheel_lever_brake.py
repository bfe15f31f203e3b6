"""A flywheel stopped by a lever brake: shoe force, angular deceleration from the balance
of angular momentum about the fixed axle, stopping time and turns (Section 3.2.2)."""


import numpy as np

from dynagrade.exercise import (Constraint, Exercise, Misconception, Numeric, Uniform,
                                per_draw)
from dynagrade.exercise.apart import numbers_apart
from dynagrade.exercise.checks import Integrated, Recompute
from dynagrade.exercise.figure import (Circle, arrow, describe, dimension,
                                       new_drawing, pivot)
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import inertia, rigid_kinetics


def _deceleration(p, normal, moment_of_inertia):
    return rigid_kinetics.angular_acceleration_about_fixed_axis(p.mu * normal * p.R,
                                                                moment_of_inertia)


@per_draw
def solve(p):
    normal = rigid_kinetics.brake_lever_shoe_force(p.P, p.b, p.c)
    alpha = _deceleration(p, normal, inertia.inertia_tensor_disk(p.m, p.R)[2, 2])
    phi = rigid_kinetics.spin_down_angle(p.omega0, alpha)
    return {
        "N": normal,
        "alpha": alpha,
        "t": rigid_kinetics.spin_down_time(p.omega0, alpha),
        "n": phi / (2 * np.pi),
        "phi": phi,
    }


def _apart(p):
    """No two answers (of different units) share their number: 5 % apart."""
    s = solve(p)
    return numbers_apart((s["N"], s["alpha"], s["t"], s["n"]))


def figure(p):
    """The flywheel and the lever to scale: pivot O on the tangent at the top of the
    wheel, the shoe c from O, the force P at b from O."""
    drawing, axes = new_drawing(4.6, 3.0)
    R = p.R
    axes.add_patch(Circle((0.0, 0.0), R, facecolor="#d9c39a", edgecolor="0.1", lw=1.2))
    axes.plot([0.0], [0.0], "o", color="0.1", ms=4)
    # the sense of turning: a counter-clockwise arrow right of the centre
    axes.annotate("", xy=(0.28 * R, 0.48 * R), xytext=(0.28 * R, -0.48 * R),
                  arrowprops={"arrowstyle": "-|>", "connectionstyle": "arc3,rad=0.5",
                              "color": "0.2", "lw": 1.0, "shrinkA": 0, "shrinkB": 0})
    axes.text(0.12 * R, 0.0, "ω₀", ha="left", va="center", fontsize=10)
    top = R + 0.02
    pivot(axes, (-p.c, top), 0.06)
    axes.plot([-p.c, p.b - p.c], [top + 0.02, top + 0.02], color="#a0724a", lw=4)
    axes.text(-p.c - 0.05, top + 0.05, "O", ha="right", va="bottom", fontsize=10)
    arrow(axes, (p.b - p.c, top + 0.4), (p.b - p.c, top + 0.06), color="C3")
    axes.text(p.b - p.c + 0.04, top + 0.25, f"P = {format_number(p.P)} N", color="C3",
              ha="left", va="center", fontsize=10)
    dimension(axes, (-p.c, top), (0.0, top), f"c = {format_number(p.c)} m", offset=0.5,
              tick=0.03, side=1.0)
    dimension(axes, (-p.c, top), (p.b - p.c, top), f"b = {format_number(p.b)} m", offset=0.7,
              tick=0.03, side=1.0)
    # the radius down to the lower left, labelled outside the wheel
    corner = (-R * np.sqrt(0.5), -R * np.sqrt(0.5))
    axes.annotate("", xy=corner, xytext=(0.0, 0.0),
                  arrowprops={"arrowstyle": "-|>", "color": "0.2", "lw": 0.8,
                              "shrinkA": 0, "shrinkB": 0, "mutation_scale": 8})
    axes.text(corner[0] - 0.03, corner[1] - 0.02, f"R = {format_number(R)} m", ha="right",
              va="top", fontsize=10)
    describe(axes, "The wheel turns counter-clockwise; the brake shoe presses down on the top "
                   "of the wheel, directly above its centre.")
    axes.set_xlim(min(-p.c - 0.3, -0.71 * R - 0.4), p.b - p.c + 0.5)
    axes.set_ylim(-R - 0.1, top + 0.85)
    return drawing


def _spin_down(t, y, p):
    """I phi'' = -mu N R with I = m R^2 / 2 and N = P b / c (lever about O)."""
    return (y[1], -p.mu * (p.P * p.b / p.c) * p.R / (p.m * p.R**2 / 2))


EXERCISE = Exercise(
    id="flywheel-lever-brake",
    title="Stopping a flywheel with a lever brake",
    source="Section 3.2.2",
    topics=("balance of angular momentum", "fixed-axis rotation", "friction brake"),
    params=(
        Uniform("m", 20, 120, step=5, unit="kg", symbol="m"),
        Uniform("R", 0.2, 0.5, step=0.01, unit="m", symbol="R"),
        Uniform("omega0", 300, 1500, step=10, unit="rpm", symbol=r"\omega_0"),
        Uniform("P", 40, 250, step=5, unit="N", symbol="P"),
        Uniform("b", 0.6, 1.2, step=0.05, unit="m", symbol="b"),
        Uniform("c", 0.15, 0.4, step=0.01, unit="m", symbol="c"),
        Uniform("mu", 0.3, 0.6, step=0.05, symbol=r"\mu"),
    ),
    constraints=(
        Constraint("the shoe sits on the lever between O and P (c < 0.7 b)",
                   lambda p: p.c < 0.7 * p.b),
        Constraint("the wheel takes 3 s to 3 min to stop",
                   lambda p: 3.0 < solve(p)["t"] < 180.0),
        Constraint("no two answers share their number", _apart),
    ),
    statement=r"""
A flywheel, a homogeneous disk of mass $m$ = {{ m }} and radius $R$ = {{ R }}, turns on
a frictionless fixed axle at $\omega_0$ = {{ omega0 }}. It is stopped by a brake: a
lever, pivoted at O on the tangent to the top of the wheel, presses a shoe on the top of
the wheel at $c$ = {{ c }} from O when a constant force $P$ = {{ P }} pushes its end
down at $b$ = {{ b }} from O. The friction coefficient between shoe and wheel is
$\mu$ = {{ mu }}; the friction force lies on the line through O, so it has no moment
about O. Neglect the lever's mass.

1. What is the normal force of the shoe on the wheel?
2. What is the wheel's angular deceleration?
3. How long does the wheel take to stop?
4. How many revolutions does it make while it stops?
""",
    solution=r"""
The wheel turns about its fixed axle; the balance of angular momentum about the axle
(Section 3.2.2) reads $I\,\dot\omega = M$, with $I = \tfrac{1}{2} m R^2$ and the moment
$M$ of the shoe's friction. The lever is massless, so the moments on it about O cancel.

1. **Shoe force.** About O: $N c = P b$, so $N = P b/c$; with $P$ = {{ P }},
   $b$ = {{ b }}, $c$ = {{ c }}: $N$ = {{ answers.N }}.
2. **Angular deceleration.** The friction $\mu N$ acts on the rim, lever arm $R$:
   $$\tfrac{1}{2} m R^2\,\dot\omega = -\mu N R
   \quad\Rightarrow\quad \alpha = -\dot\omega = \frac{2 \mu N}{m R},$$
   with $\mu$ = {{ mu }}, $m$ = {{ m }}, $R$ = {{ R }}: $\alpha$ = {{ answers.alpha }}.
3. **Stopping time.** The deceleration is constant, so $\omega = \omega_0 - \alpha t$
   vanishes at $t = \omega_0/\alpha$, with $\omega_0$ = {{ omega0 }} = {{ si.omega0 }}
   rad/s: $t$ = {{ answers.t }}.
4. **Revolutions.** The angle turned is $\varphi = \omega_0^2/(2\alpha)$ = {{ si.phi }}
   rad, that is $n = \varphi/(2\pi)$ = {{ answers.n }} revolutions.

**Check.** The mean speed times the time gives the same angle: $\tfrac{1}{2}\omega_0 t/(2\pi)$
= {{ checks.mean_speed_turns }} revolutions.
""",
    solve=solve,
    figure=figure,
    figure_to_scale=True,
    checks=(
        # the spin-down integrated until the wheel stops: the time, and the turns
        Integrated("t", _spin_down, lambda p: (0.0, p.omega0), lambda p, s: 2 * s["t"],
                   lambda t, y, p: t, name="integrated_stop_time",
                   event=lambda t, y, p: y[1], direction=-1),
        # uniform deceleration: the angle is the mean speed omega0/2 times the stopping time
        Recompute("n", lambda p, s: p.omega0 * s["t"] / 2 / (2 * np.pi), name="mean_speed_turns"),
        Integrated("n", _spin_down, lambda p: (0.0, p.omega0), lambda p, s: 2 * s["t"],
                   lambda t, y, p: y[0] / (2 * np.pi), name="integrated_turns",
                   event=lambda t, y, p: y[1], direction=-1),
    ),
    parts=(
        Numeric("N", "normal force of the shoe", question=1, unit="N", points=1,
                misconceptions=(
                    Misconception("lever arms inverted", lambda p: p.P * p.c / p.b,
                                  "Moments about O: N c = P b, the shoe is nearer O."),
                    Misconception("the push taken as the shoe force", lambda p: p.P,
                                  "The lever multiplies the push by b/c."),
                )),
        Numeric("alpha", "angular deceleration", question=2, unit="rad/s^2", points=2,
                misconceptions=(
                    Misconception("disk taken as a ring",
                                  lambda p: _deceleration(p, solve(p)["N"], p.m * p.R**2),
                                  "A homogeneous disk has I = ½ m R²."),
                    Misconception("friction coefficient forgotten",
                                  lambda p: _deceleration(p, solve(p)["N"] / p.mu,
                                                          p.m * p.R**2 / 2),
                                  "The braking force on the rim is the friction μ N."),
                )),
        Numeric("t", "stopping time", question=3, unit="s", points=1,
                misconceptions=(
                    Misconception("rpm used as rad/s",
                                  lambda p: p.omega0 * 30 / np.pi / solve(p)["alpha"],
                                  "Convert: 1 rpm = 2π/60 rad/s."),
                )),
        Numeric("n", "revolutions until it stops", question=4, points=1,
                misconceptions=(
                    Misconception("angle in radians given as revolutions",
                                  lambda p: 2 * np.pi * solve(p)["n"],
                                  "φ = ω0²/(2α) is in radians: divide by 2π."),
                    Misconception("full speed for the whole time",
                                  lambda p: 2 * solve(p)["n"],
                                  "The mean speed while decelerating uniformly is ω0/2."),
                )),
    ),
)
