"""A rod falling with its foot sliding on a frictionless floor: its centre falls straight
down, and the work-energy balance gives its spin and speeds (Section 3.2.5)."""


import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric,
                                Uniform, per_draw)
from dynagrade.exercise.apart import numbers_apart
from dynagrade.exercise.checks import Balance, Integrated
from dynagrade.exercise.figure import angle_arc, describe, dimension, ground, new_drawing
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import rigid_kinematics, rigid_kinetics


@per_draw
def solve(p):
    rate = rigid_kinetics.sliding_rod_angular_speed(p.theta0, p.theta1, p.g, p.L)
    half = p.L / 2 * np.array([np.sin(p.theta1), np.cos(p.theta1)])   # from the foot to C
    v_c = np.array([0.0, -half[0] * rate])                          # C falls straight down
    v_foot = rigid_kinematics.velocity_of_point(v_c, -rate, -half)  # omega e3 = -rate e3
    rate_down = rigid_kinetics.sliding_rod_angular_speed(p.theta0, np.pi / 2, p.g, p.L)
    return {
        "omega": rate,
        "v_C": float(np.linalg.norm(v_c)),
        "v_A": float(np.linalg.norm(v_foot)),
        "v_land": p.L / 2 * rate_down,
    }


def _apart(p):
    s = solve(p)
    return numbers_apart((s["omega"], s["v_C"], s["v_A"], s["v_land"]))


def _pivoted_rate(p):
    """The wrong model: the foot held fixed, 1/2 (m L^2/3) w^2 = m g (L/2)(cos t0 - cos t)."""
    return np.sqrt(3 * p.g * (np.cos(p.theta0) - np.cos(p.theta1)) / p.L)


def figure(p):
    """To scale: the rod at release (solid) and at theta1 (dashed), the foot on the floor."""
    drawing, axes = new_drawing(4.4, 3.0)
    L = p.L
    ground(axes, -0.9 * L, 0.9 * L, 0.0, hatch=0.04 * L)
    x_c = L / 2 * np.sin(p.theta0)            # C keeps its horizontal position
    for theta, style in ((p.theta0, "-"), (p.theta1, "--")):
        foot = x_c - L / 2 * np.sin(theta)
        axes.plot([foot, foot + L * np.sin(theta)], [0.0, L * np.cos(theta)], style,
                  color="#a0724a", lw=3 if style == "-" else 1.5)
    foot0, foot1 = x_c - L / 2 * np.sin(p.theta0), x_c - L / 2 * np.sin(p.theta1)
    axes.plot([foot0, foot0], [0.0, 0.35 * L], color="0.4", lw=0.6, ls=":")
    axes.plot([foot1, foot1], [0.0, 0.35 * L], color="0.4", lw=0.6, ls=":")
    # θ₀ is narrow: its label stands right of the solid rod, level with the arc's top
    angle_arc(axes, (foot0, 0.0), 0.3 * L, np.pi / 2 - p.theta0, np.pi / 2)
    axes.text(foot0 + 0.36 * L * np.sin(p.theta0) + 0.03 * L, 0.36 * L * np.cos(p.theta0),
              "θ₀", ha="left", va="center", fontsize=10)
    angle_arc(axes, (foot1, 0.0), 0.22 * L, np.pi / 2 - p.theta1, np.pi / 2, "θ₁")
    dimension(axes, (foot0, 0.0), (foot0 + L * np.sin(p.theta0), L * np.cos(p.theta0)),
              f"L = {format_number(L)} m", offset=0.08 * L, tick=0.02 * L, side=1.0)
    describe(axes, "The solid rod is the release position, leaning right from its foot on "
                   "the floor; the dashed rod is the later position at θ₁, its foot slid to "
                   "the left. Both angles are measured from the vertical.")
    axes.set_xlim(-0.9 * L, 0.95 * L)
    axes.set_ylim(-0.08 * L, 1.08 * L)
    return drawing


def _fall(t, y, p):
    """Lagrange's equation of the rod (T = 1/2 m L^2 (sin^2/4 + 1/12) t'^2,
    V = m g L/2 cos t), solved for t''."""
    theta, rate = y
    s, c = np.sin(theta), np.cos(theta)
    return (rate, (p.g / p.L * s / 2 - s * c / 4 * rate**2) / (s**2 / 4 + 1 / 12))


EXERCISE = Exercise(
    id="rod-sliding-on-frictionless-floor",
    title="A rod falling on a frictionless floor",
    source="Section 3.2.5",
    topics=("work-energy balance", "kinetic energy of a rigid body", "plane motion"),
    params=(
        Uniform("L", 0.5, 2.5, step=0.05, unit="m", symbol="L"),
        Uniform("theta0", 5, 30, step=1, unit="deg", symbol=r"\theta_0"),
        Uniform("theta1", 35, 75, step=1, unit="deg", symbol=r"\theta_1"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("the foot and the centre move at clearly different speeds "
                   "(theta1 at least 4 degrees from 45)",
                   lambda p: abs(p.theta1 - np.pi / 4) > np.radians(4)),
        Constraint("the rod has clearly moved by theta1 (at least 20 degrees past theta0), "
                   "so that the two positions and their angles stand apart in the figure",
                   lambda p: p.theta1 - p.theta0 >= np.radians(20)),
        Constraint("no two answers share their number (5 % apart)", _apart),
    ),
    statement=r"""
A homogeneous slender rod of length $L$ = {{ L }} stands on a frictionless horizontal
floor, leaning at $\theta_0$ = {{ theta0 }} from the vertical, and is released from
rest ($g$ = {{ g }}). Its lower end A slides on the floor and stays on it until the rod
lies flat.

1. What is the rod's angular speed when it leans at $\theta_1$ = {{ theta1 }}?
2. How fast does its centre C move then?
3. How fast does the foot A slide then?
4. How fast does C move just before the rod hits the floor?
""",
    solution=r"""
The floor pushes only vertically (no friction) and gravity is vertical, so the balance of
linear momentum (Section 3.2.1) keeps the horizontal velocity of C at zero: C falls
straight down. With C at height $\tfrac{L}{2}\cos\theta$,
$v_C = \tfrac{L}{2}\sin\theta\,\dot\theta$. The normal force does no work (A moves
horizontally), so the work-energy balance (Section 3.2.5) holds with
$T = \tfrac{1}{2} m v_C^2 + \tfrac{1}{2}\,\tfrac{1}{12} m L^2\,\dot\theta^2$:
$$m g\,\tfrac{L}{2}(\cos\theta_0 - \cos\theta)
= \tfrac{1}{2} m \tfrac{L^2}{4}\Bigl(\sin^2\theta + \tfrac{1}{3}\Bigr)\dot\theta^2 .$$

1. **Angular speed.** $\dot\theta^2 = \dfrac{12 g\,(\cos\theta_0 - \cos\theta)}{L\,(1 + 3\sin^2\theta)}$;
   with $L$ = {{ L }}, $\theta_0$ = {{ theta0 }}, $\theta_1$ = {{ theta1 }}:
   $\dot\theta$ = {{ answers.omega }}.
2. **Centre.** $v_C = \tfrac{L}{2}\sin\theta_1\,\dot\theta$ = {{ answers.v_C }}, straight down.
3. **Foot.** A lies $\tfrac{L}{2}\cos\theta$ below C on the rod, and moves horizontally:
   $v_A = \tfrac{L}{2}\cos\theta_1\,\dot\theta$ = {{ answers.v_A }}.
4. **Landing.** When the rod lies flat, $\theta = \pi/2$: $\dot\theta^2 = 3 g\cos\theta_0/L$ and
   $v_C = \tfrac{L}{2}\dot\theta = \sqrt{\tfrac{3}{4} g L\cos\theta_0}$ = {{ answers.v_land }},
   less than the free fall from the height $\tfrac{L}{2}\cos\theta_0$ would give,
   $\sqrt{g L\cos\theta_0}$, because a quarter of the energy goes into the spin.

**Check.** Integrating the rod's equation of motion from rest at $\theta_0$ until it leans
at $\theta_1$ gives $\dot\theta$ = {{ checks.integrated_fall }} rad/s again.
""",
    solve=solve,
    figure=figure,
    figure_to_scale=True,
    checks=(
        # the equation of motion integrated from rest at theta0 until theta reaches theta1
        Integrated("omega", _fall, lambda p: (p.theta0, 0.0),
                   lambda p, s: 20 * np.sqrt(p.L / p.g), lambda t, y, p: y[1],
                   name="integrated_fall", event=lambda t, y, p: y[0] - p.theta1, direction=1,
                   rtol=1e-5),
        # energy: the potential energy lost equals translation plus rotation (per unit mass)
        Balance("energy", lambda p, s: p.g * p.L / 2 * (np.cos(p.theta0) - np.cos(p.theta1)),
                lambda p, s: s["v_C"] ** 2 / 2 + p.L**2 / 24 * s["omega"] ** 2,
                name="energy_at_theta1"),
    ),
    parts=(
        Numeric("omega", "angular speed at theta1", question=1, unit="rad/s", points=2,
                misconceptions=(
                    Misconception("foot taken as a fixed pivot", _pivoted_rate,
                                  "The foot slides: C falls vertically, and T = ½ m v_C² + "
                                  "½ (m L²/12) θ̇²."),
                )),
        Numeric("v_C", "speed of C at theta1", question=2, unit="m/s", points=1,
                misconceptions=(
                    Misconception("C on a circle about the foot",
                                  lambda p: p.L / 2 * solve(p)["omega"],
                                  "C falls straight down: only the vertical part "
                                  "(L/2) sin θ θ̇ remains."),
                )),
        Numeric("v_A", "speed of the foot at theta1", question=3, unit="m/s", points=1,
                misconceptions=(
                    Misconception("sin and cos swapped", lambda p: solve(p)["v_C"],
                                  "A is (L/2) cos θ below C: v_A = (L/2) cos θ θ̇."),
                )),
        Numeric("v_land", "speed of C at landing", question=4, unit="m/s", points=1,
                misconceptions=(
                    Misconception("free fall", lambda p: np.sqrt(p.g * p.L * np.cos(p.theta0)),
                                  "The rod also spins at landing: ½ m v² + ½ (m L²/12)(2v/L)²."),
                )),
    ),
)
