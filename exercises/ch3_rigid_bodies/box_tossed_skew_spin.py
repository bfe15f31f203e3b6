"""A box tossed spinning about a skew axis: Euler's equations without a moment give the
angular velocity's first change, and its magnitude is not kept though T is (Section 3.4.4)."""

import numpy as np

from dynagrade.exercise import (Constraint, Exercise, Misconception, Numeric, Uniform, Vector,
                                per_draw)
from dynagrade.exercise.apart import numbers_apart
from dynagrade.exercise.checks import Balance, Integrated, Recompute
from dynagrade.exercise.figure import arrow, describe, new_drawing
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import euler_equations, inertia, rigid_kinetics


@per_draw
def _omega(p):
    return np.array([p.w1, p.w2, p.w3])


@per_draw
def _moments(p):
    return np.diag(inertia.inertia_tensor_box(p.m, p.a, p.b, p.c))


@per_draw
def solve(p):
    moments = _moments(p)
    omega_dot = euler_equations.angular_acceleration_euler(moments, _omega(p), np.zeros(3))
    return {
        "omega_dot": omega_dot,
        "T": rigid_kinetics.rotational_kinetic_energy(np.diag(moments), _omega(p)),
        "speed_rate": euler_equations.angular_speed_rate(_omega(p), omega_dot),
        "I1": moments[0], "I2": moments[1], "I3": moments[2],
        "speed": float(np.linalg.norm(_omega(p))),
    }


def _skew(p):
    return min(abs(p.w1), abs(p.w2), abs(p.w3)) >= 1


def _box_moments_by_hand(p):
    """Principal moments of a box about its centre, m (b^2 + c^2)/12 and cyclic."""
    return (p.m * (p.b**2 + p.c**2) / 12, p.m * (p.a**2 + p.c**2) / 12,
            p.m * (p.a**2 + p.b**2) / 12)


def _free_spin(t, y, p):
    """Euler's equations without a moment, written out (Section 3.4.4)."""
    i1, i2, i3 = _box_moments_by_hand(p)
    return ((i2 - i3) * y[1] * y[2] / i1, (i3 - i1) * y[2] * y[0] / i2,
            (i1 - i2) * y[0] * y[1] / i3)


def _kinetic_energy(t, y, p):
    i1, i2, i3 = _box_moments_by_hand(p)
    return 0.5 * (i1 * y[0]**2 + i2 * y[1]**2 + i3 * y[2]**2)


def _reversed_cross_product(p):
    return -solve(p)["omega_dot"]


def _edges_mixed_up_T(p):
    """The wrong moments: each axis given its own edge, m a^2/12 about b1 and so on."""
    return 0.5 * p.m / 12 * (p.a**2 * p.w1**2 + p.b**2 * p.w2**2 + p.c**2 * p.w3**2)


def figure(p):
    """Schematic: the box in an oblique view with its body axes and edges (Section 3.4.4)."""
    drawing, axes = new_drawing(4.0, 3.2)
    x, y, z = np.array([1.6, 0.0]), np.array([0.6, 0.45]), np.array([0.0, 1.0])
    corner = np.array([-0.8, -0.7])
    faces = ((0, x, y), (0, x, z), (0, y, z), (x + y + z, -x, -y), (x + y + z, -x, -z),
             (x + y + z, -y, -z))
    for start, u, w in faces:
        base = corner + start
        points = [base, base + u, base + u + w, base + w, base]
        axes.plot([q[0] for q in points], [q[1] for q in points], color="0.2", lw=1.0)
    centre = corner + (x + y + z) / 2
    # the axes' labels past their tips (b₃ reaches out of the box's top): beside the arrows
    # they lay on the box's edges
    for direction, length, name in ((x, 0.55, "b₁"), (y, 1.0, "b₂"), (z, 0.95, "b₃")):
        tip = centre + length * direction
        arrow(axes, tuple(centre), tuple(tip), color="C0")
        axes.text(*(tip + 0.14 * direction / np.hypot(*direction)), name, ha="center",
                  va="center", fontsize=10, color="C0")
    axes.text(*(corner + x / 2 - np.array([0.0, 0.1])), f"a = {format_number(p.a)} m",
              ha="center", va="top", fontsize=10)
    axes.text(*(corner + x + y / 2 + np.array([0.1, -0.05])), f"b = {format_number(p.b)} m",
              ha="left", va="center", fontsize=10)
    axes.text(*(corner + z / 2 - np.array([0.1, 0.0])), f"c = {format_number(p.c)} m",
              ha="right", va="center", fontsize=10)
    describe(axes, "The box with its body axes through its centre: b1 along the edge a, b2 "
                   "along b and b3 along c.")
    axes.set_xlim(-1.6, 1.9)
    axes.set_ylim(-1.0, 1.2)
    return drawing


EXERCISE = Exercise(
    id="box-tossed-with-skew-spin",
    title="A box tossed spinning about a skew axis: Euler's equations",
    source="Section 3.4.4",
    topics=("Euler equations", "torque-free rotation", "kinetic energy"),
    params=(
        Uniform("m", 0.5, 3.0, step=0.1, unit="kg", symbol="m"),
        Uniform("a", 0.1, 0.5, step=0.02, unit="m", symbol="a"),
        Uniform("b", 0.1, 0.5, step=0.02, unit="m", symbol="b"),
        Uniform("c", 0.1, 0.5, step=0.02, unit="m", symbol="c"),
        Uniform("w1", -6, 6, step=1, unit="rad/s", symbol=r"\omega_1"),
        Uniform("w2", -6, 6, step=1, unit="rad/s", symbol=r"\omega_2"),
        Uniform("w3", -6, 6, step=1, unit="rad/s", symbol=r"\omega_3"),
    ),
    constraints=(
        Constraint("three distinct edges, each two by over 15 %",
                   lambda p: min(abs(p.a - p.b), abs(p.b - p.c), abs(p.a - p.c))
                   > 0.15 * max(p.a, p.b, p.c)),
        Constraint("the box spins about a skew axis: every component at least 1 rad/s", _skew),
        Constraint("the angular speed changes noticeably: |d|omega|/dt| > 0.01 |omega|^2",
                   lambda p: _skew(p)
                   and abs(solve(p)["speed_rate"]) > 0.01 * solve(p)["speed"]**2),
        Constraint("the angular acceleration is at least 2 rad/s^2",
                   lambda p: _skew(p) and np.linalg.norm(solve(p)["omega_dot"]) >= 2),
        Constraint("T and d|omega|/dt differ by over 5 %",
                   lambda p: _skew(p) and numbers_apart([solve(p)["speed_rate"],
                                                         solve(p)["T"]])),
    ),
    statement=r"""
A homogeneous box (mass $m$ = {{ m }}, edges $a$ = {{ a }}, $b$ = {{ b }}, $c$ = {{ c }}
along its body axes $b_1, b_2, b_3$ through its centre) is tossed into the air. Just after
the throw its angular velocity has the body components
$(\omega_1, \omega_2, \omega_3)$ = ({{ w1 }}, {{ w2 }}, {{ w3 }}). Air drag is negligible,
so gravity, acting at the centre, exerts no moment about it.

1. What is the box's angular acceleration $\dot\omega$ at that instant (components along
   $b_1, b_2, b_3$)?
2. What is the kinetic energy of its rotation?
3. At which rate does its angular speed $|\omega|$ change at that instant?
""",
    solution=r"""
The body axes are principal axes of the box at its centre (Section 3.2.3):
$I_1 = m(b^2 + c^2)/12$ = {{ si.I1 }} kg·m², $I_2 = m(a^2 + c^2)/12$ = {{ si.I2 }} kg·m²,
$I_3 = m(a^2 + b^2)/12$ = {{ si.I3 }} kg·m². With no moment about the centre, the balance
of angular momentum in the body frame gives Euler's equations (Section 3.4.4),
$$I_1\dot\omega_1 = (I_2 - I_3)\,\omega_2\omega_3,\quad
I_2\dot\omega_2 = (I_3 - I_1)\,\omega_3\omega_1,\quad
I_3\dot\omega_3 = (I_1 - I_2)\,\omega_1\omega_2 .$$

1. With $(\omega_1, \omega_2, \omega_3)$ = ({{ w1 }}, {{ w2 }}, {{ w3 }}):
   $\dot\omega$ = {{ answers.omega_dot }}. No moment does not mean a constant $\omega$:
   $H = I\omega$ is constant in space, but $\omega$ is not along a principal axis.
2. $T = \tfrac12(I_1\omega_1^2 + I_2\omega_2^2 + I_3\omega_3^2)$ = {{ answers.T }}; it
   stays constant: $\dot T = \sum I_i\omega_i\dot\omega_i = 0$ by the equations above.
3. $\frac{d}{dt}|\omega| = \omega\cdot\dot\omega/|\omega|$ with
   $|\omega|$ = {{ si.speed }} rad/s: {{ answers.speed_rate }}. Unlike $T$ and $|H|$,
   the angular speed is not kept.

**Check.** Euler's equations integrated for a short time keep
$T$ = {{ checks.integrated_energy }} J, as question 2 says.
""",
    solve=solve,
    checks=(
        # Euler's equations integrated over a tenth of a turn: T is kept
        Integrated("T", _free_spin, lambda p: (p.w1, p.w2, p.w3),
                   lambda p, s: 0.6 / s["speed"], _kinetic_energy, name="integrated_energy",
                   rtol=1e-6),
        # |H|^2 is kept too: sum I_i^2 w_i w_i' = 0
        Balance("rate of |H|^2", lambda p, s: 0.0,
                lambda p, s: sum(i**2 * w * wd for i, w, wd in zip(
                    _box_moments_by_hand(p), (p.w1, p.w2, p.w3), s["omega_dot"])),
                name="angular_momentum_kept", atol=1e-9),
        # d|omega|/dt from the equations written out
        Recompute("speed_rate", lambda p, s: np.dot((p.w1, p.w2, p.w3), _free_spin(0, (
            p.w1, p.w2, p.w3), p)) / np.sqrt(p.w1**2 + p.w2**2 + p.w3**2),
            name="speed_rate_by_hand"),
    ),
    figure=figure,
    parts=(
        Vector("omega_dot", "angular acceleration", question=1, size=3, unit="rad/s^2",
               points=2, atol=0.02,
               misconceptions=(
                   Misconception("no moment, so no angular acceleration",
                                 lambda p: np.zeros(3),
                                 "Without a moment H is constant, not ω: Euler's equations "
                                 "I1 ω1' = (I2 − I3) ω2 ω3 and cyclic."),
                   Misconception("cross product in the wrong order", _reversed_cross_product,
                                 "I ω' + ω × (I ω) = M: the terms are (I2 − I3) ω2 ω3, "
                                 "not (I3 − I2) ω2 ω3."),
               )),
        Numeric("T", "kinetic energy", question=2, unit="J", points=1,
                misconceptions=(
                    Misconception("each axis with its own edge", _edges_mixed_up_T,
                                  "About b1 the box extends along b and c: I1 = m(b² + c²)/12.",
                                  applies=lambda p: abs(_edges_mixed_up_T(p) / solve(p)["T"]
                                                        - 1) > 0.03),
                )),
        Numeric("speed_rate", "rate of change of the angular speed", question=3,
                unit="rad/s^2", points=1,
                misconceptions=(
                    Misconception("|ω| kept like T", lambda p: 0.0,
                                  "T = ½ ω·Iω and |H| = |Iω| are kept, but |ω| is not: "
                                  "d|ω|/dt = ω·ω'/|ω| with ω' from Euler's equations."),
                )),
    ),
)
