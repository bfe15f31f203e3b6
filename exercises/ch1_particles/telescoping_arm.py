"""A robot's telescoping arm that extends while it turns: velocity and acceleration of its
gripper in the co-rotating polar basis, with the centripetal and Coriolis terms
(Section 1.1.3, eqs. (1.31), (1.33) and (1.35))."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, Vector, per_draw
from dynagrade.exercise.apart import numbers_apart
from dynagrade.exercise.checks import Recompute
from dynagrade.exercise.figure import Circle, angle_arc, arrow, describe, new_drawing
from dynagrade.mechanics import kinematics

POLAR = ("e_r", "e_phi")


@per_draw
def solve(p):
    r = p.r0 + kinematics.distance_at_constant_acceleration(p.t, 0.0, p.b)
    rdot = kinematics.speed_at_constant_acceleration(p.t, 0.0, p.b)
    phidot = kinematics.speed_at_constant_acceleration(p.t, 0.0, p.eps)
    v = kinematics.polar_velocity(r, rdot, phidot)
    a = kinematics.polar_acceleration(r, rdot, p.b, phidot, p.eps)
    return {
        "v": tuple(float(c) for c in v),
        "a": tuple(float(c) for c in a),
        "a_abs": float(kinematics.acceleration_magnitude(*a)),
        # for the worked solution
        "r": float(r), "rdot": float(rdot), "phidot": float(phidot),
        "centripetal": float(r * phidot**2), "coriolis": float(2 * rdot * phidot),
    }


def _gripper(p, t):
    """The gripper's Cartesian position at time t: r(t) (cos phi(t), sin phi(t)) with
    r = r0 + b t^2/2 and phi = eps t^2/2 (eq. (1.22))."""
    r, phi = p.r0 + p.b * t**2 / 2, p.eps * t**2 / 2
    return np.array([r * np.cos(phi), r * np.sin(phi)])


def _differenced(order):
    """The Cartesian velocity (order 1) or acceleration (order 2) of the gripper at t, by a
    central difference of its positions, projected on e_r and e_phi at t (eq. (1.29))."""
    def route(p, s):
        dt = 1e-4 * p.t
        before, now, after = (_gripper(p, p.t + k * dt) for k in (-1, 0, 1))
        vector = (after - before) / (2 * dt) if order == 1 else (after - 2 * now + before) / dt**2
        phi = p.eps * p.t**2 / 2
        return (vector @ (np.cos(phi), np.sin(phi)), vector @ (-np.sin(phi), np.cos(phi)))
    return route


def _rates_of_components(p):
    """The wrong route of eq. (1.35): the rates of v_r = r' and v_phi = r phi'."""
    s = solve(p)
    return (p.b, s["rdot"] * s["phidot"] + s["r"] * p.eps)


def _both_components_matter(p) -> bool:
    """Each component of a is at least 35 % of |a| (so |a| differs from each by over 5 %)."""
    s = solve(p)
    return min(abs(c) for c in s["a"]) >= 0.35 * s["a_abs"]


def _numbers_apart(p) -> bool:
    """The components of v and a and |a| (in SI, magnitudes) differ pairwise by over 5 %:
    no answer can be given for another."""
    s = solve(p)
    values = [abs(c) for c in (*s["v"], *s["a"], s["a_abs"])]
    return numbers_apart(values)


def figure(p):
    """Top view (schematic): the arm turning about its vertical axis at O, the gripper at
    the distance r and the angle phi from the fixed e1 direction, and the co-rotating basis
    vectors at the gripper."""
    phi = 0.6
    drawing, axes = new_drawing(4.4, 3.4)
    axes.add_patch(Circle((0.0, 0.0), 0.09, facecolor="white", edgecolor="0.1", lw=1.2, zorder=3))
    axes.text(-0.05, -0.14, "O", ha="right", va="top", fontsize=10)
    axes.plot([0.0, 1.0], [0.0, 0.0], color="0.5", lw=0.8, ls="-.")
    axes.text(1.05, 0.0, "e₁", ha="left", va="center", fontsize=10, color="0.3")
    tip = 2.0 * np.array([np.cos(phi), np.sin(phi)])
    axes.plot([0.0, 0.55 * tip[0]], [0.0, 0.55 * tip[1]], color="0.2", lw=5)      # outer tube
    axes.plot([0.0, tip[0]], [0.0, tip[1]], color="0.45", lw=2.5)                 # inner tube
    axes.plot([tip[0]], [tip[1]], "s", color="C0", ms=8)
    axes.text(*(0.5 * tip + (-0.12, 0.14)), "r", ha="center", va="center", fontsize=11)
    angle_arc(axes, (0.0, 0.0), 0.6, 0.0, phi, "φ", label_radius=0.78)
    e_r = np.array([np.cos(phi), np.sin(phi)])
    e_phi = np.array([-np.sin(phi), np.cos(phi)])
    arrow(axes, tuple(tip), tuple(tip + 0.55 * e_r), color="C3")
    arrow(axes, tuple(tip), tuple(tip + 0.55 * e_phi), color="C3")
    axes.text(*(tip + 0.72 * e_r), "$e_r$", ha="center", va="center", fontsize=10, color="C3")
    axes.text(*(tip + 0.72 * e_phi), "$e_\\varphi$", ha="center", va="center", fontsize=10, color="C3")
    describe(axes, "Seen from above: the arm turns counter-clockwise about O and its inner "
             "tube slides out; the red arrows at the gripper are the radial and the "
             "circumferential unit vectors.")
    axes.set_xlim(-0.5, 2.8)
    axes.set_ylim(-0.4, 2.3)
    return drawing


EXERCISE = Exercise(
    id="telescoping-arm",
    title="A telescoping arm extending while it turns",
    source="Section 1.1.3",
    topics=("polar coordinates", "Coriolis term", "centripetal acceleration"),
    params=(
        Uniform("r0", 0.3, 1.0, step=0.05, unit="m", symbol="r_0"),
        Uniform("b", 0.05, 0.5, step=0.01, unit="m/s^2", symbol=r"\ddot r"),
        Uniform("eps", 0.2, 2.0, step=0.05, unit="rad/s^2", symbol=r"\ddot\varphi"),
        Uniform("t", 0.5, 3.0, step=0.1, unit="s", symbol="t"),
    ),
    constraints=(
        Constraint("both components of the acceleration are at least 35 % of its magnitude",
                   _both_components_matter),
        Constraint("the components of v and a and |a| differ pairwise by over 5 %",
                   _numbers_apart),
        Constraint("the arm turns less than one turn", lambda p: p.eps * p.t**2 / 2 < 2 * np.pi),
    ),
    statement=r"""
A robot arm turns in a horizontal plane about a fixed vertical axis through O, and its
telescoping inner tube slides out. At $t = 0$ the arm is at rest with its gripper at the
distance $r_0$ = {{ r0 }} from O. From then on the gripper's distance grows at the constant
rate $\ddot r$ = {{ b }}, and the arm's angle $\varphi$ at the constant angular acceleration
$\ddot\varphi$ = {{ eps }}.

Answer in the co-rotating polar basis $(e_r, e_\varphi)$ at the gripper, as
`[radial, circumferential]` or as `… e_r + … e_phi`. At $t$ = {{ t }}:

1. what is the gripper's velocity?
2. what is its acceleration?
3. what is the magnitude of its acceleration?
""",
    solution=r"""
Polar coordinates about O, eqs. (1.31) and (1.33): $v = \dot r\,e_r + r\dot\varphi\,e_\varphi$ and
$a = (\ddot r - r\dot\varphi^2)\,e_r + (2\dot r\dot\varphi + r\ddot\varphi)\,e_\varphi$. With
constant $\ddot r$ and $\ddot\varphi$ from rest, at $t$ = {{ t }}:
$\dot r = \ddot r\,t$ = {{ si.rdot }} m/s, $r = r_0 + \ddot r t^2/2$ = {{ si.r }} m and
$\dot\varphi = \ddot\varphi\,t$ = {{ si.phidot }} rad/s.

1. **Velocity.** $v$ = {{ answers.v }}.
2. **Acceleration.** The centripetal term is $r\dot\varphi^2$ = {{ si.centripetal }} m/s²
   and the Coriolis term $2\dot r\dot\varphi$ = {{ si.coriolis }} m/s², so
   $a$ = {{ answers.a }}. The components are not the rates of $\dot r$ and $r\dot\varphi$
   (eq. (1.35)): the basis turns with the arm.
3. **Magnitude.** $e_r$ and $e_\varphi$ are orthonormal: $|a| = \sqrt{a_r^2 + a_\varphi^2}$ =
   {{ answers.a_abs }}.
4. **Check.** Differencing the gripper's Cartesian positions $r(\cos\varphi, \sin\varphi)$
   twice in time and projecting on $e_r$, $e_\varphi$ gives the same acceleration,
   {{ checks.differenced_acceleration }} m/s².
""",
    solve=solve,
    checks=(
        # the Cartesian path r(t)(cos phi(t), sin phi(t)), differenced in time and projected
        Recompute("v", _differenced(1), name="differenced_velocity", rtol=1e-6),
        Recompute("a", _differenced(2), name="differenced_acceleration", rtol=1e-5),
        Recompute("a_abs", lambda p, s: float(np.linalg.norm(_differenced(2)(p, s))),
                  name="differenced_magnitude", rtol=1e-5),
    ),
    figure=figure,
    parts=(
        Vector("v", "velocity", question=1, unit="m/s", size=2, basis=POLAR, points=1,
               misconceptions=(
                   Misconception("angular rate for the circumferential speed",
                                 lambda p: (p.b * p.t, p.eps * p.t),
                                 "The circumferential component is r φ̇, eq. (1.31).",
                                 applies=lambda p: abs(solve(p)["r"] - 1.0) > 0.03),
               )),
        Vector("a", "acceleration", question=2, unit="m/s^2", size=2, basis=POLAR, points=3,
               misconceptions=(
                   Misconception("rates of the velocity's components", _rates_of_components,
                                 "a_r ≠ v̇_r and a_φ ≠ v̇_φ in the turning basis, eq. (1.35): "
                                 "use eq. (1.33)."),
                   Misconception("centripetal term missing",
                                 lambda p: (p.b, solve(p)["a"][1]),
                                 "a_r = r̈ − r φ̇², eq. (1.33): the arm's turning pulls the "
                                 "gripper toward O."),
                   Misconception("Coriolis term missing",
                                 lambda p: (solve(p)["a"][0], solve(p)["r"] * p.eps),
                                 "a_φ = 2 ṙ φ̇ + r φ̈, eq. (1.33): the sliding tube turning "
                                 "adds 2 ṙ φ̇."),
               )),
        Numeric("a_abs", "magnitude of the acceleration", question=3, unit="m/s^2", points=1,
                misconceptions=(
                    Misconception("components added",
                                  lambda p: sum(abs(c) for c in solve(p)["a"]),
                                  "e_r and e_φ are perpendicular: |a| = √(a_r² + a_φ²)."),
                )),
    ),
)
