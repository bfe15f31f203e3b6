"""A flywheel spun up by a falling weight against bearing friction, then coasting to rest:
the work-energy balance in two stages (Section 3.2.5)."""


import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric,
                                Uniform, per_draw)
from dynagrade.exercise.apart import numbers_apart
from dynagrade.exercise.checks import Balance, Integrated
from dynagrade.exercise.figure import (Circle, block, describe, dimension, new_drawing, pivot)
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import kinematics, rigid_kinetics


def _spin(p, friction_moment):
    return rigid_kinetics.drum_angular_speed_after_drop(p.m, p.g, p.h, p.r, p.J,
                                                        friction_moment)


def _weight_energy_forgotten(p):
    """The wrong balance m g h - M_f h/r = J omega^2 / 2, without the weight's 1/2 m v^2."""
    return np.sqrt(2 * (p.m * p.g * p.h - p.M_f * p.h / p.r) / p.J)


@per_draw
def solve(p):
    omega1 = _spin(p, p.M_f)
    deceleration = rigid_kinetics.angular_acceleration_about_fixed_axis(p.M_f, p.J)
    return {
        "omega1": omega1,
        # a constant moment works through the angle the drum turns, h / r
        "W_f": p.M_f * kinematics.angle_from_arc_length(p.h, p.r),
        "n2": rigid_kinetics.spin_down_angle(omega1, deceleration) / (2 * np.pi),
    }


def _apart(p):
    if p.m * p.g * p.r <= p.M_f:   # never starts: the other constraints reject the draw
        return False
    s = solve(p)
    return numbers_apart((s["omega1"], s["W_f"], s["n2"]))


def figure(p):
    """Schematic: the flywheel with its drum on a fixed axle, the weight on the string."""
    drawing, axes = new_drawing(3.6, 3.4)
    pivot(axes, (0.0, 0.0), 0.12)
    axes.add_patch(Circle((0.0, 0.0), 1.0, facecolor="#d9c39a", edgecolor="0.1", lw=1.2))
    axes.add_patch(Circle((0.0, 0.0), 0.35, facecolor="#a0724a", edgecolor="0.1", lw=1.0))
    axes.plot([0.35, 0.35], [0.0, -1.6], color="0.1", lw=1.0)
    block(axes, (0.35, -1.85), 0.5, 0.5, "m", color="#9ab7d3")
    dimension(axes, (0.9, -2.1), (0.9, -3.1), f"h = {format_number(p.h)} m", offset=0.0,
              tick=0.05, side=-1.0)
    axes.plot([0.1, 1.0], [-2.1, -2.1], color="0.3", lw=0.6, ls=":")
    axes.plot([0.1, 1.0], [-3.1, -3.1], color="0.3", lw=0.6, ls=":")
    axes.text(-1.05, 1.05, f"J = {format_number(p.J)} kg·m²", ha="left", va="bottom",
              fontsize=9)
    # one label a line (a label's "\n" is not a line break in the SVG)
    for row, text in enumerate((f"r = {format_number(p.r)} m", f"m = {format_number(p.m)} kg",
                                f"M_f = {format_number(p.M_f)} N·m")):
        axes.text(-1.55, -1.1 - 0.28 * row, text, ha="left", va="top", fontsize=9)
    describe(axes, "The string hangs from the right side of the drum (the small inner disk) "
                   "and carries the weight m, which drops h before the string comes off.")
    axes.set_xlim(-1.6, 1.6)
    axes.set_ylim(-3.3, 1.4)
    return drawing


def _spin_up(t, y, p):
    """Angular momentum balances: (m r^2 + J) phi'' = m g r - M_f while the string pulls."""
    return (y[1], (p.m * p.g * p.r - p.M_f) / (p.m * p.r**2 + p.J))


EXERCISE = Exercise(
    id="flywheel-spun-by-falling-weight",
    title="A flywheel spun up by a falling weight, then coasting to rest",
    source="Section 3.2.5",
    topics=("work-energy balance", "fixed-axis rotation", "friction moment"),
    params=(
        Uniform("J", 0.05, 1.0, step=0.01, unit="kg*m^2", symbol="J"),
        Uniform("r", 0.03, 0.1, step=0.005, unit="m", symbol="r"),
        Uniform("m", 1.0, 10.0, step=0.1, unit="kg", symbol="m"),
        Uniform("h", 0.5, 2.0, step=0.05, unit="m", symbol="h"),
        Uniform("M_f", 0.05, 1.5, step=0.01, unit="N*m", symbol="M_f"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("the weight clearly overcomes the bearing friction (m g r > 2 M_f)",
                   lambda p: p.m * p.g * p.r > 2 * p.M_f),
        Constraint("the friction takes a noticeable share of the work (M_f > 0.06 m g r)",
                   lambda p: p.M_f > 0.06 * p.m * p.g * p.r),
        Constraint("the weight's own kinetic energy counts (m r^2 > 3 % of J)",
                   lambda p: p.m * p.r**2 > 0.03 * p.J),
        Constraint("no two answers share their number (5 % apart)", _apart),
    ),
    statement=r"""
A flywheel (moment of inertia $J$ = {{ J }} about its fixed horizontal axle) carries a
drum of radius $r$ = {{ r }}. A string wound on the drum holds a weight of mass
$m$ = {{ m }}. The system is released from rest; the bearing exerts a constant friction
moment $M_f$ = {{ M_f }} against the rotation. After the weight has dropped
$h$ = {{ h }} the string comes off the drum, and the flywheel coasts until it stops
($g$ = {{ g }}).

1. What is the flywheel's angular speed when the string comes off?
2. How much work has the bearing friction done on the flywheel by then (give its
   magnitude)?
3. How many revolutions does the flywheel make while it coasts to rest?
""",
    solution=r"""
Work-energy balance (Section 3.2.5) for each stage: the change of kinetic energy equals the
work of the forces and moments acting. The string does no net work on weight and
flywheel together; the bearing friction moment $M_f$ does the work $-M_f\,\Delta\varphi$.

1. **Spin-up.** While the weight drops $h$ the flywheel turns $\Delta\varphi = h/r$,
   and the weight moves with $v = \omega r$:
   $$m g h - M_f\,\frac{h}{r} = \tfrac{1}{2}\bigl(m r^2 + J\bigr)\,\omega_1^2 ,$$
   with $m$ = {{ m }}, $h$ = {{ h }}, $r$ = {{ r }}, $J$ = {{ J }}, $M_f$ = {{ M_f }}:
   $\omega_1$ = {{ answers.omega1 }}.
2. **Friction's work.** $|W_f| = M_f\,h/r$ = {{ answers.W_f }}.
3. **Coasting.** Without the string only the flywheel moves:
   $\tfrac{1}{2} J \omega_1^2 = M_f\,\varphi_2$, so $\varphi_2 = J\omega_1^2/(2 M_f)$ and
   $n_2 = \varphi_2/(2\pi)$ = {{ answers.n2 }} revolutions. The weight's kinetic energy
   left with the weight.

**Check.** Integrating $(m r^2 + J)\,\ddot\varphi = m g r - M_f$ from rest until the drum
has paid out $h$ gives $\omega_1$ = {{ checks.integrated_spin_up }} rad/s again.
""",
    solve=solve,
    figure=figure,
    checks=(
        # the spin-up integrated until the drum has paid out the string length h
        Integrated("omega1", _spin_up, lambda p: (0.0, 0.0),
                   lambda p, s: 100.0, lambda t, y, p: y[1], name="integrated_spin_up",
                   event=lambda t, y, p: y[0] * p.r - p.h, direction=1, rtol=1e-6),
        # coasting: the flywheel's kinetic energy is worn away by M_f over 2 pi n2
        Balance("coasting energy", lambda p, s: p.J * s["omega1"] ** 2 / 2,
                lambda p, s: p.M_f * 2 * np.pi * s["n2"], name="coasting_energy"),
    ),
    parts=(
        Numeric("omega1", "angular speed when the string comes off", question=1,
                unit="rad/s", points=2,
                misconceptions=(
                    Misconception("friction forgotten", lambda p: _spin(p, 0.0),
                                  "The bearing friction takes M_f h/r of the energy."),
                    Misconception("weight's kinetic energy forgotten",
                                  _weight_energy_forgotten,
                                  "The weight moves with v = ω r: its ½ m v² counts too."),
                )),
        Numeric("W_f", "work of the bearing friction", question=2, unit="J", points=1,
                misconceptions=(
                    Misconception("moment times the drop", lambda p: p.M_f * p.h,
                                  "A moment works through an angle: Δφ = h/r."),
                )),
        Numeric("n2", "revolutions while coasting", question=3, points=2,
                misconceptions=(
                    Misconception("angle in radians given as revolutions",
                                  lambda p: 2 * np.pi * solve(p)["n2"],
                                  "φ₂ = J ω₁²/(2 M_f) is in radians: divide by 2π."),
                    Misconception("weight's energy kept in the wheel",
                                  lambda p: (p.m * p.r**2 + p.J) * solve(p)["omega1"] ** 2
                                  / (4 * np.pi * p.M_f),
                                  "Once the string is off, only ½ J ω₁² is left to wear away."),
                )),
    ),
)
