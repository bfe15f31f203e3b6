"""Euler's equations for a heavy unsymmetric top at one instant: the weight's moment, the
angular acceleration and the power of gravity (Section 3.5.1)."""

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric, Uniform,
                                Vector, per_draw)
from dynagrade.exercise.checks import Balance, Recompute
from dynagrade.exercise.figure import angle_arc, arrow, describe, ground, new_drawing
from dynagrade.mechanics import euler_equations, gyro


def _moments(p):
    return np.array([p.I1, p.I2, p.I3])


@per_draw
def solve(p):
    omega = gyro.body_angular_velocity_from_euler_rates(p.theta, p.phi, p.psi_dot,
                                                        p.theta_dot, p.phi_dot)
    moment = gyro.top_gravity_moment(p.m, p.g, p.l, p.theta, p.phi)
    return {
        "M_O": float(np.linalg.norm(moment)),
        "alpha": euler_equations.angular_acceleration_euler(_moments(p), omega, moment),
        "P": float(gyro.top_kinetic_energy_rate(p.m, p.g, p.l, p.theta, p.theta_dot)),
        "omega": omega, "moment": moment,
    }


def _without_gyroscopic_terms(p):
    """The wrong route: I_i omega_i' = M_i, the terms (I_j - I_k) omega_j omega_k left out."""
    return solve(p)["moment"] / _moments(p)


def _far_from(wrong, key, share):
    return lambda p: (np.linalg.norm(np.subtract(wrong(p), solve(p)[key]))
                      > share * np.linalg.norm(solve(p)[key]))


def _inertia_possible(p):
    """Moments about O of a body with its centre of mass on e3^B at l: I1, I2 at least
    m l^2 above zero, and the principal moments about C (I1 - m l^2, I2 - m l^2, I3; the
    parallel-axis theorem) each at most the sum of the other two. About O alone the
    triangle rule lets I3 exceed I1 + I2 - 2 m l^2, which no body can."""
    i = sorted((p.I1 - p.m * p.l**2, p.I2 - p.m * p.l**2, p.I3))
    return min(p.I1, p.I2) >= 1.2 * p.m * p.l**2 and i[2] <= i[0] + i[1]


def draw(p):
    """Schematic: the top on its tip O tilted by theta, its centre of mass C at l on the
    body axis, the weight at C, and the rotation rates."""
    from dynagrade.exercise.figure import Circle, Polygon

    figure, axes = new_drawing(3.6, 3.4)
    ground(axes, -1.2, 1.4, hatch=0.1)
    axis = np.array([np.sin(p.theta), np.cos(p.theta)])
    across = np.array([axis[1], -axis[0]])
    axes.plot([0.0, 0.0], [0.0, 2.5], color="0.4", lw=0.8, ls="--")
    axes.text(-0.08, 2.5, "e₃", ha="right", va="top", fontsize=10)
    cone = [(0.0, 0.0), tuple(axis * 1.4 + across * 0.5), tuple(axis * 1.6 + across * 0.3),
            tuple(axis * 1.6 - across * 0.3), tuple(axis * 1.4 - across * 0.5)]
    axes.add_patch(Polygon(cone, closed=True, facecolor="C0", edgecolor="0.1"))
    arrow(axes, tuple(axis * 1.6), tuple(axis * 2.3), "", color="0.1")
    axes.text(*(axis * 2.3 + [0.1, 0.0]), "e₃ᴮ", ha="left", va="center", fontsize=10)
    centre = axis * 1.1
    axes.add_patch(Circle(tuple(centre), 0.06, facecolor="white", edgecolor="0.1", zorder=4))
    axes.text(*(centre - across * 0.2), "C", ha="right", va="center", fontsize=10)
    # the weight reaches down out of the body, labelled below it (on the body, red on blue,
    # the label was hard to read and crossed the body's edge)
    arrow(axes, tuple(centre), (centre[0], 0.1), color="C3")
    axes.text(centre[0] + 0.08, 0.3, "mg", ha="left", va="center", fontsize=10, color="C3")
    axes.text(*(axis * 0.8 - across * 0.5), "l", ha="center", va="center", fontsize=10)
    angle_arc(axes, (0.0, 0.0), 0.5, np.pi / 2 - p.theta, np.pi / 2, "θ", label_radius=0.7)
    axes.text(0.0, -0.05, "O", ha="center", va="top", fontsize=10)
    describe(axes, "The top stands on its fixed tip O, its body axis e₃ᴮ tilted by θ from "
             "the vertical e₃; its centre of mass C lies on that axis at the distance l "
             "from O, and its weight m g acts at C.")
    axes.set_xlim(-1.3, 2.4)
    axes.set_ylim(-0.4, 2.7)
    return figure


EXERCISE = Exercise(
    id="top-angular-acceleration",
    title="Heavy unsymmetric top: Euler's equations at one instant",
    source="Section 3.5.1",
    topics=("spinning tops", "Euler's equations", "Euler angles", "power of a moment"),
    params=(
        Uniform("m", 0.05, 0.3, step=0.01, unit="kg", symbol="m"),
        Uniform("l", 2.0, 5.0, step=0.5, unit="cm", symbol="l"),
        Uniform("I1", 3e-4, 1.2e-3, step=5e-5, unit="kg*m^2", symbol="I_1"),
        Uniform("I2", 3e-4, 1.2e-3, step=5e-5, unit="kg*m^2", symbol="I_2"),
        Uniform("I3", 1e-4, 8e-4, step=5e-5, unit="kg*m^2", symbol="I_3"),
        Uniform("theta", 20, 70, step=5, unit="deg", symbol=r"\theta"),
        Uniform("phi", 0, 345, step=15, unit="deg", symbol=r"\varphi"),
        Uniform("psi_dot", 1.0, 8.0, step=0.25, unit="rad/s", symbol=r"\dot\psi"),
        Uniform("theta_dot", -3.0, 3.0, step=0.25, unit="rad/s", symbol=r"\dot\theta"),
        Uniform("phi_dot", 10, 60, step=2, unit="rad/s", symbol=r"\dot\varphi"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("the moments of inertia about O belong to a real body with C at l",
                   _inertia_possible),
        Constraint("the body is clearly unsymmetric: I1 and I2 differ by at least 25 %",
                   lambda p: abs(p.I1 - p.I2) >= 0.25 * max(p.I1, p.I2)),
        Constraint("the top clearly nutates, and not at 1 rad/s (where the power and the "
                   "moment would coincide): |theta'| >= 0.5 rad/s, ||theta'| - 1| >= 0.2",
                   lambda p: abs(p.theta_dot) >= 0.5 and abs(abs(p.theta_dot) - 1) >= 0.2),
    ),
    statement=r"""
A rigid body of mass $m$ = {{ m }} spins on a fixed tip O; its centre of mass C lies on the
body axis $e_3^B$ at $l$ = {{ l }} from O. The body axes $e_1^B, e_2^B, e_3^B$ are principal
axes about O, with the moments $I_1$ = {{ I1 }}, $I_2$ = {{ I2 }}, $I_3$ = {{ I3 }}. Its
orientation is given by the Euler angles of the lecture ($R = R_3(\psi) R_1(\theta)
R_3(\varphi)$; precession $\psi$ about the vertical $e_3$). At the instant considered
$\theta$ = {{ theta }}, $\varphi$ = {{ phi }}, $\dot\psi$ = {{ psi_dot }},
$\dot\theta$ = {{ theta_dot }}, $\dot\varphi$ = {{ phi_dot }} ($g$ = {{ g }}). The tip
is smooth but stays in place.

1. What is the magnitude of the weight's moment about O?
2. What is the angular acceleration $\dot\omega$ of the body (components in the body
   frame)?
3. At which rate does the body's kinetic energy change?
""",
    solution=r"""
O is fixed, so the balance of angular momentum about O holds in the body frame as Euler's
equations with the moments of inertia about O (Section 3.4.4), the weight being the only
force with a moment about O (top, general description, Section 3.5.1):
$I_1\dot\omega_1 = M_1 + (I_2 - I_3)\,\omega_2\omega_3$ and cyclic.
The angular velocity from the Euler rates ($\theta$ = {{ theta }}, $\varphi$ = {{ phi }},
$\dot\psi$ = {{ psi_dot }}, $\dot\theta$ = {{ theta_dot }}, $\dot\varphi$ = {{ phi_dot }})
has the body components $\omega$ = ({{ si.omega[0] }}, {{ si.omega[1] }},
{{ si.omega[2] }}) rad/s.

1. **Moment of the weight.** $M_O = l e_3^B\times(-m g\,e_3)$; with the body components
   $(\sin\theta\sin\varphi, \sin\theta\cos\varphi, \cos\theta)$ of $e_3$ this is
   $M_O = m g l\,(\sin\theta\cos\varphi, -\sin\theta\sin\varphi, 0)$ = ({{ si.moment[0] }},
   {{ si.moment[1] }}, {{ si.moment[2] }}) N·m, horizontal, of magnitude
   $m g l\sin\theta$ = {{ answers.M_O }} ($m$ = {{ m }}, $l$ = {{ l }}, $g$ = {{ g }}).
2. **Angular acceleration.** Euler's equations with $I_1$ = {{ I1 }}, $I_2$ = {{ I2 }},
   $I_3$ = {{ I3 }}:
   $\dot\omega_1 = (M_1 + (I_2 - I_3)\omega_2\omega_3)/I_1$,
   $\dot\omega_2 = (M_2 + (I_3 - I_1)\omega_3\omega_1)/I_2$,
   $\dot\omega_3 = (M_3 + (I_1 - I_2)\omega_1\omega_2)/I_3$, so
   $\dot\omega$ = {{ answers.alpha }}.
3. **Power.** The tip force does no work (O does not move); the weight's work is the loss
   of the potential $m g l\cos\theta$, so
   $\dot T = m g l\sin\theta\,\dot\theta$ = {{ answers.P }} (work-energy balance,
   Section 3.2.5).
4. **Check.** The power of the moment, $M_O\cdot\omega$, gives {{ checks.power_of_the_moment }} W,
   the same.
""",
    solve=solve,
    checks=(
        # the power of the weight's moment, P = M_O . omega (Section 3.2.5)
        Recompute("P", lambda p, s: float(np.dot(s["moment"], s["omega"])),
                  name="power_of_the_moment"),
        # dT/dt = omega . I omega' as well: the gyroscopic terms do no work
        Balance("rate of kinetic energy", lambda p, s: s["P"],
                lambda p, s: float(np.dot(s["omega"], _moments(p) * s["alpha"])),
                name="energy_rate_from_euler"),
        Recompute("M_O", lambda p, s: p.m * p.g * p.l * np.sin(p.theta),
                  name="lever_arm_of_the_weight"),
    ),
    figure=draw,
    parts=(
        Numeric("M_O", "moment of the weight about O", question=1, unit="N*m", points=1,
                misconceptions=(
                    Misconception("lever arm l instead of l sin(theta)",
                                  lambda p: p.m * p.g * p.l,
                                  "The lever arm of the vertical weight about O is the "
                                  "horizontal distance l sin θ."),
                    Misconception("cos instead of sin", lambda p: p.m * p.g * p.l * np.cos(p.theta),
                                  "θ is measured from the vertical: the lever arm is l sin θ.",
                                  applies=lambda p: abs(np.tan(p.theta) - 1) > 0.03),
                )),
        Vector("alpha", "angular acceleration (body frame)", question=2, unit="rad/s^2",
               size=3, points=3, atol=0.1, misconceptions=(
                   Misconception("gyroscopic terms left out", _without_gyroscopic_terms,
                                 "In the rotating body frame dH/dt = I ω' + ω × I ω: keep the "
                                 "terms (I2 − I3) ω2 ω3 and cyclic (Euler's equations).",
                                 applies=_far_from(_without_gyroscopic_terms, "alpha", 0.05)),
               )),
        Numeric("P", "rate of change of the kinetic energy", question=3, unit="W", points=1,
                misconceptions=(
                    Misconception("|M| |omega|",
                                  lambda p: solve(p)["M_O"] * np.linalg.norm(solve(p)["omega"]),
                                  "Only the component of ω along M_O does work: P = M_O · ω."),
                )),
    ),
)
