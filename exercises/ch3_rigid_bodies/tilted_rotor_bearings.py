"""A cylindrical rotor mounted slightly askew on its shaft: Euler's equations give the couple
the bearings must supply, and the angular momentum leaves the shaft (Section 3.4.4)."""

import numpy as np

from dynagrade.exercise import (Constraint, Exercise, Misconception, Numeric, Options, Uniform,
                                per_draw)
from dynagrade.exercise.apart import numbers_apart
from dynagrade.exercise.checks import Balance, Recompute
from dynagrade.exercise.figure import (angle_arc, arrow, block, describe, dimension,
                                       new_drawing)
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import euler_equations, inertia, rigid_kinetics, rotations

B3 = np.array([0.0, 0.0, 1.0])


def _principal(p):
    return np.diag(inertia.inertia_tensor_cylinder(p.m, p.R, p.h))


def _shaft(p):
    """The shaft's direction in the rotor's principal axes: tilted by beta from b3 to b2."""
    return np.array([0.0, np.sin(p.beta), np.cos(p.beta)])


@per_draw
def solve(p):
    moments = _principal(p)
    omega = p.omega * _shaft(p)
    h = rigid_kinetics.rigid_body_angular_momentum(np.diag(moments), omega)
    couple = float(np.linalg.norm(euler_equations.gyroscopic_moment(moments, omega,
                                                                    np.zeros(3))))
    return {
        "delta": rotations.angle_between(h, _shaft(p)),
        "side": "same" if rotations.angle_between(h, B3) < p.beta else "opposite",
        "M": couple,
        "F": euler_equations.bearing_force_of_couple(couple, p.l),
        "I1": moments[0],
        "I3": moments[2],
        "H": float(np.linalg.norm(h)),
    }


def _differs(value, wrong):
    """A misconception tells only where it misses the key by over twice the tolerance."""
    return abs(wrong / value - 1) > 0.03


def _couple_from_turning_H(p, solved):
    """dH/dt in the fixed frame by a central difference: H turns with the shaft, H(t) =
    R_shaft(omega t) H(0); the moments written out for a cylinder (Section 3.2.3)."""
    i1 = p.m * (3 * p.R**2 + p.h**2) / 12
    i3 = p.m * p.R**2 / 2
    h0 = p.omega * np.array([0.0, i1 * np.sin(p.beta), i3 * np.cos(p.beta)])
    axis = _shaft(p)
    dt = 1e-4 / p.omega

    def turned(t):
        c, s = np.cos(p.omega * t), np.sin(p.omega * t)
        return c * h0 + s * np.cross(axis, h0) + (1 - c) * axis * (axis @ h0)
    return float(np.linalg.norm((turned(dt) - turned(-dt)) / (2 * dt)))


def figure(p):
    """Side view to scale: the shaft between its two bearings, the rotor at the middle with
    its symmetry axis tilted by beta from the shaft (Section 3.4.4)."""
    span = p.l
    drawing, axes = new_drawing(4.8, 3.0)
    axes.plot([-0.6 * span, 0.6 * span], [0.0, 0.0], color="0.2", lw=2.0)
    for x in (-span / 2, span / 2):
        block(axes, (x, 0.0), 0.05 * span, 0.12 * span, color="0.5")
    block(axes, (0.0, 0.0), p.h, 2 * p.R, angle=p.beta, color="#9fb7d4")
    axis = np.array([np.cos(p.beta), np.sin(p.beta)])
    tip = 0.45 * span * axis
    axes.plot([-tip[0], tip[0]], [-tip[1], tip[1]], ls="--", color="C3", lw=1.0)
    # β's arc just outside the rotor, its label to the right of the arc's end, above the
    # dashed axis and the bearing: at the arc's middle (a few degrees) it lay on the shaft
    reach = float(np.hypot(p.h / 2, p.R)) + 0.04 * span
    angle_arc(axes, (0.0, 0.0), reach, 0.0, p.beta)
    axes.text(reach * axis[0], max(reach * axis[1] + 0.02 * span, 0.08 * span),
              f"β = {format_number(np.degrees(p.beta))}°", ha="left", va="bottom",
              fontsize=10)
    arrow(axes, (0.6 * span, 0.0), (0.75 * span, 0.0))
    axes.text(0.6 * span, -0.04 * span, f"ω = {format_number(p.omega)} rad/s", ha="left",
              va="top", fontsize=10, color="C0")
    dimension(axes, (-span / 2, 0.0), (span / 2, 0.0), f"l = {format_number(span)} m",
              offset=-max(0.12 * span, 1.3 * p.R), tick=0.02 * span, side=-1.0)
    describe(axes, "The rotor, a solid cylinder, sits on the shaft at the middle between "
                   "the bearings; the dashed line is its symmetry axis, tilted from the shaft "
                   "by beta.")
    axes.set_xlim(-0.65 * span, 0.9 * span)
    axes.set_ylim(-max(0.3 * span, 1.6 * p.R), max(0.2 * span, 1.3 * p.R))
    return drawing


EXERCISE = Exercise(
    id="tilted-rotor-bearing-forces",
    title="A rotor mounted askew on its shaft: bearing forces",
    source="Section 3.4.4",
    topics=("Euler equations", "dynamic imbalance", "angular momentum"),
    params=(
        Uniform("m", 2.0, 20.0, step=0.5, unit="kg", symbol="m"),
        Uniform("R", 0.05, 0.3, step=0.01, unit="m", symbol="R"),
        Uniform("h", 0.02, 0.6, step=0.01, unit="m", symbol="h"),
        Uniform("beta", 2, 12, step=1, unit="deg", symbol=r"\beta"),
        Uniform("omega", 50, 300, step=5, unit="rad/s", symbol=r"\omega"),
        Uniform("l", 0.3, 1.2, step=0.05, unit="m", symbol="l"),
    ),
    constraints=(
        Constraint("the rotor is clearly disk-like or rod-like: |3 R^2 - h^2| > 0.5 R^2",
                   lambda p: abs(3 * p.R**2 - p.h**2) > 0.5 * p.R**2),
        Constraint("the rotor fits well between the bearings: sqrt((h/2)^2 + R^2) < 0.35 l",
                   lambda p: np.hypot(p.h / 2, p.R) < 0.35 * p.l),
        Constraint("a solid cylinder of a real material: m / (pi R^2 h) is 1000 to 8000 "
                   "kg/m^3 (plastic to steel)",
                   lambda p: 1000 <= p.m / (np.pi * p.R**2 * p.h) <= 8000),
        Constraint("angle, couple and bearing force differ by over 5 %",
                   lambda p: numbers_apart([np.degrees(solve(p)["delta"]), solve(p)["M"],
                                            solve(p)["F"]])),
    ),
    statement=r"""
A rotor, a homogeneous solid cylinder (mass $m$ = {{ m }}, radius $R$ = {{ R }}, length
$h$ = {{ h }}), sits with its centre on a shaft, midway between two bearings
$l$ = {{ l }} apart. Through a mounting error its symmetry axis is tilted from the shaft by
$\beta$ = {{ beta }}. The shaft turns at the constant rate $\omega$ = {{ omega }}; gravity
is carried separately and plays no part here.

1. By which angle does the rotor's angular momentum about its centre deviate from the
   shaft?
2. Does the angular momentum lie on the same side of the shaft as the rotor's symmetry
   axis, or on the opposite side? (`same` or `opposite`)
3. How large is the couple the bearings must exert on the rotor?
4. How large is the force each bearing exerts?
""",
    solution=r"""
Use the rotor's principal axes at its centre: $b_3$ its symmetry axis, $b_2$ in the plane
of the tilt. For a solid cylinder $I_1 = I_2 = m(3R^2 + h^2)/12$ = {{ si.I1 }} kg·m² and
$I_3 = mR^2/2$ = {{ si.I3 }} kg·m². In these axes the angular velocity is
$\omega = \omega\,(0,\; \sin\beta,\; \cos\beta)$, constant: it is the shaft's.

1. **Angular momentum.** $H = (0,\; I_1\omega\sin\beta,\; I_3\omega\cos\beta)$,
   $|H|$ = {{ si.H }} kg·m²/s. It is tilted from $b_3$ by $\arctan(I_1\tan\beta/I_3)$,
   not by $\beta$: $H$ is parallel to $\omega$ only for a principal axis. The angle
   between $H$ and the shaft is $\delta$ = {{ answers.delta }}.
2. With $I_1 < I_3$ (a disk-like rotor) $H$ tilts less than $\beta$ from $b_3$, so it lies
   between $b_3$ and the shaft; with $I_1 > I_3$ (a long rotor) it lies beyond the shaft.
   Here: **{{ answers.side }}**.
3. **Couple.** Euler's equations with $\dot\omega = 0$ (balance of angular momentum in the
   body frame, Section 3.4.4): $M = \omega \times (I\omega)$, of magnitude
   $$|M| = \omega^2\,|I_3 - I_1|\,\sin\beta\cos\beta$$
   = {{ answers.M }}. It turns with the shaft: a rotating load on the bearings.
4. **Bearing forces.** The centre stays on the axis, so the bearings exert no net force:
   two opposite forces $l$ apart make the couple, $F = |M|/l$ = {{ answers.F }}.

**Check.** In the fixed frame $H$ turns round the shaft at $\omega$, and its rate of
change, by a central difference over a short time, is {{ checks.turning_H }} N·m: the
couple of question 3.
""",
    solve=solve,
    checks=(
        Recompute("M", _couple_from_turning_H, name="turning_H", rtol=1e-6),
        # H about its own axis by hand: tan(angle from b3) = I1 tan(beta) / I3
        Recompute("delta", lambda p, s: abs(p.beta - np.arctan(
            (3 * p.R**2 + p.h**2) / 6 / p.R**2 * np.tan(p.beta))), name="delta_by_hand"),
        # the bearings' two forces make the couple
        Balance("couple of the bearing forces", lambda p, s: s["F"] * p.l, lambda p, s: s["M"],
                name="bearing_couple"),
    ),
    figure=figure, figure_to_scale=True,
    parts=(
        Numeric("delta", "angle between H and the shaft", question=1, unit="deg", points=1,
                misconceptions=(
                    Misconception("H along the symmetry axis", lambda p: p.beta,
                                  "H = I ω: its components are I1 ω sin β and I3 ω cos β, so "
                                  "it lies along neither ω nor b3.",
                                  applies=lambda p: _differs(solve(p)["delta"], p.beta)),
                )),
        Options("side", "side of H", question=2, options=("same", "opposite")),
        Numeric("M", "couple of the bearings", question=3, unit="N*m", points=2,
                misconceptions=(
                    Misconception("thin-disk moments of inertia",
                                  lambda p: p.omega**2 * p.m * p.R**2 / 4
                                  * np.sin(p.beta) * np.cos(p.beta),
                                  "The rotor has length h: I1 = m(3R² + h²)/12, so "
                                  "I3 − I1 = m(3R² − h²)/12.",
                                  applies=lambda p: _differs(abs(3 * p.R**2 - p.h**2) / 12,
                                                             p.R**2 / 4)),
                    Misconception("I3 alone", lambda p: p.omega**2 * p.m * p.R**2 / 2
                                  * np.sin(p.beta) * np.cos(p.beta),
                                  "M = ω × (I ω) takes the difference of the principal "
                                  "moments, I3 − I1.",
                                  applies=lambda p: _differs(abs(3 * p.R**2 - p.h**2) / 12,
                                                             p.R**2 / 2)),
                )),
        Numeric("F", "force of each bearing", question=4, unit="N", points=1,
                misconceptions=(
                    Misconception("lever arm l/2", lambda p: 2 * solve(p)["M"] / p.l,
                                  "The two forces are l apart; their couple is F l."),
                )),
    ),
)
