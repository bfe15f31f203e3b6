"""A spinning top released without precession dips and nutates: its largest tilt from the
conserved quantities (Section 3.5.2)."""

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric, Uniform,
                                per_draw)
from dynagrade.exercise.checks import Integrated
from dynagrade.exercise.figure import angle_arc, arrow, describe, ground, new_drawing
from dynagrade.mechanics import energy, gyro


@per_draw
def solve(p):
    theta_max = float(gyro.largest_tilt_of_released_top(p.m, p.g, p.l, p.I1, p.I3, p.w3,
                                                        p.theta0))
    height = p.m * p.g * p.l                      # the potential is m g l cos(theta)
    return {
        "theta_max": theta_max,
        "psi_dot": float(gyro.precession_rate_at_largest_tilt(p.m, p.g, p.l, p.I3, p.w3)),
        "dT": float(energy.work_from_potential(height * np.cos(p.theta0),
                                               height * np.cos(theta_max))),
        "psi_fast": float(gyro.fast_top_precession_rate(p.m, p.g, p.l, p.I3, p.w3)),
        "H_v": p.I3 * p.w3 * np.cos(p.theta0),
    }


def _top(t, y, p):
    """Lagrange equation of the symmetric top in theta (y = theta, theta'), with the
    precession rate from the conserved vertical angular momentum,
    psi' = I3 w3 (cos(theta0) - cos(theta)) / (I1 sin^2(theta)):
    I1 theta'' = I1 psi'^2 sin(theta) cos(theta) - I3 w3 psi' sin(theta) + m g l sin(theta)
    (Section 3.5.2)."""
    theta = y[0]
    psi_dot = p.I3 * p.w3 * (np.cos(p.theta0) - np.cos(theta)) / (p.I1 * np.sin(theta) ** 2)
    return (y[1], (p.I1 * psi_dot**2 * np.sin(theta) * np.cos(theta)
                   - p.I3 * p.w3 * psi_dot * np.sin(theta)
                   + p.m * p.g * p.l * np.sin(theta)) / p.I1)


def _precession_at(p, theta):
    return p.I3 * p.w3 * (np.cos(p.theta0) - np.cos(theta)) / (p.I1 * np.sin(theta) ** 2)


_TURN = dict(start=lambda p: (p.theta0, 0.0),
             horizon=lambda p, s: 20 * np.pi * p.I1 / (p.I3 * p.w3) + 2.0,
             event=lambda t, y, p: y[1], direction=-1)


def draw(p):
    """Schematic: the top on its tip O, released at the tilt theta0 spinning about its axis
    with omega3; no precession at the start."""
    from dynagrade.exercise.figure import Polygon

    figure, axes = new_drawing(3.4, 3.2)
    ground(axes, -1.2, 1.6, hatch=0.1)
    axis = np.array([np.sin(p.theta0), np.cos(p.theta0)])
    across = np.array([axis[1], -axis[0]])
    axes.plot([0.0, 0.0], [0.0, 2.4], color="0.4", lw=0.8, ls="--")
    body = [(0.0, 0.0), tuple(axis * 1.2 + across * 0.55), tuple(axis * 1.45 + across * 0.4),
            tuple(axis * 1.45 - across * 0.4), tuple(axis * 1.2 - across * 0.55)]
    axes.add_patch(Polygon(body, closed=True, facecolor="C1", edgecolor="0.1"))
    # the symmetry axis through the body, so that θ₀'s arc visibly ends on it
    axes.plot([0.0, axis[0] * 1.45], [0.0, axis[1] * 1.45], color="0.1", lw=0.8, ls="-.")
    arrow(axes, tuple(axis * 1.45), tuple(axis * 2.2), "", color="0.1")
    axes.annotate("", xy=tuple(axis * 1.9 - across * 0.3), xytext=tuple(axis * 1.9 + across * 0.3),
                  arrowprops={"arrowstyle": "-|>", "connectionstyle": "arc3,rad=-0.5",
                              "color": "C3"})
    axes.text(*(axis * 2.0 + across * 0.45), "ω₃", color="C3", ha="left", va="center",
              fontsize=10)
    # the arc runs over the body; its label stands left of the dashed vertical, where the
    # body is not (inside the angle it lay on the body's edge)
    angle_arc(axes, (0.0, 0.0), 0.55, np.pi / 2 - p.theta0, np.pi / 2)
    axes.text(-0.06, 0.6, "θ₀", ha="right", va="center", fontsize=10)
    axes.text(0.0, -0.05, "O", ha="center", va="top", fontsize=10)
    describe(axes, "The top stands on its fixed tip O with its symmetry axis tilted by θ₀ "
             "from the vertical (dashed) and spins about that axis with ω₃; it is released "
             "without precession or nutation rate.")
    axes.set_xlim(-1.3, 2.3)
    axes.set_ylim(-0.4, 2.6)
    return figure


EXERCISE = Exercise(
    id="released-top-nutation",
    title="A spinning top released without precession: how far does it dip?",
    source="Section 3.5.2",
    topics=("spinning tops", "nutation", "conserved quantities", "heavy symmetric top"),
    params=(
        Uniform("m", 0.1, 1.0, step=0.05, unit="kg", symbol="m"),
        Uniform("l", 2, 8, step=0.5, unit="cm", symbol="l"),
        Uniform("I1", 4e-4, 3e-3, step=1e-4, unit="kg*m^2", symbol="I_1"),
        Uniform("I3", 1e-4, 1e-3, step=5e-5, unit="kg*m^2", symbol="I_3"),
        Uniform("w3", 10, 150, step=5, unit="rad/s", symbol=r"\omega_3"),
        Uniform("theta0", 10, 60, step=5, unit="deg", symbol=r"\theta_0"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("the moments about O belong to a top with C at l: I1 >= 1.2 m l^2, "
                   "I1 > I3, and I3 <= 2 (I1 - m l^2), the axial moment at most the sum of "
                   "the two transverse ones about C",
                   lambda p: p.I1 >= 1.2 * p.m * p.l**2 and p.I1 > p.I3
                   and p.I3 <= 2 * (p.I1 - p.m * p.l**2)),
        Constraint("the top dips noticeably but stays clear of the ground: "
                   "3 deg <= theta_max - theta0, theta_max <= 80 deg",
                   lambda p: np.radians(3) <= solve(p)["theta_max"] - p.theta0
                   and solve(p)["theta_max"] <= np.radians(80)),
    ),
    statement=r"""
A symmetric top of mass $m$ = {{ m }} stands on a fixed, smooth tip O; its centre of mass
lies on the symmetry axis at $l$ = {{ l }} from O. About O its transverse moment of inertia
is $I_1$ = {{ I1 }} and its axial one $I_3$ = {{ I3 }}. It is released with its axis at
$\theta_0$ = {{ theta0 }} from the vertical, spinning about the axis with
$\omega_3$ = {{ w3 }}, without any precession or nutation rate
($\dot\psi = \dot\theta = 0$; $g$ = {{ g }}). The axis then dips and rises periodically.

1. What is the largest tilt of the axis from the vertical?
2. What is the precession rate $\dot\psi$ when the axis is tilted most?
3. How much kinetic energy has the top gained then?
""",
    solution=r"""
Three quantities stay constant (heavy symmetric top, Section 3.5.2): the axial
angular momentum $H_3 = I_3\omega_3$ (the body is axisymmetric and the weight's moment about
O is normal to the axis), the vertical angular momentum
$H_v = I_1\dot\psi\sin^2\theta + I_3\omega_3\cos\theta$ (that moment is horizontal) and the
energy
$\tfrac{1}{2} I_1(\dot\theta^2 + \dot\psi^2\sin^2\theta) + \tfrac{1}{2} I_3\omega_3^2 + m g l\cos\theta$
(the smooth tip does no work). At release $\dot\psi = 0$, so
$H_v = I_3\omega_3\cos\theta_0$ = {{ si.H_v }} kg·m²/s ($m$ = {{ m }}, $l$ = {{ l }},
$I_1$ = {{ I1 }}, $I_3$ = {{ I3 }}, $\omega_3$ = {{ w3 }}, $\theta_0$ = {{ theta0 }},
$g$ = {{ g }}).

1. **Largest tilt.** There $\dot\theta = 0$ again. With $u = \cos\theta$: the vertical
   momentum gives $\dot\psi = \frac{I_3\omega_3(u_0 - u)}{I_1(1 - u^2)}$, and the energy
   $\tfrac{1}{2} I_1\dot\psi^2(1 - u^2) = m g l\,(u_0 - u)$. Dividing by $u_0 - u$:
   $u_0 - u = \beta(1 - u^2)$ with $\beta = \frac{2 I_1 m g l}{I_3^2\omega_3^2}$, a quadratic in
   $u$ whose root below $u_0$ gives $\theta_{\max}$ = {{ answers.theta_max }}.
2. **Precession rate there.** Put $u_0 - u = \beta(1 - u^2)$ into $\dot\psi$:
   $\dot\psi = \frac{I_3\omega_3\beta}{I_1} = \frac{2 m g l}{I_3\omega_3}$ = {{ answers.psi_dot }}:
   twice the fast-top rate $m g l/(I_3\omega_3)$ = {{ si.psi_fast }} rad/s. The axis
   precesses in steps, from rest at the top of each dip to this rate at its bottom.
3. **Kinetic energy gained.** All of it from the weight: $\Delta T =
   m g l(\cos\theta_0 - \cos\theta_{\max})$ = {{ answers.dT }}, now in the precession $\tfrac{1}{2} I_1\dot\psi^2\sin^2\theta$.
4. **Check.** Integrating the top's equation of motion in $\theta$ from the release to the
   next turning point gives $\theta_{\max}$ = {{ checks.integrated_turning_tilt }} rad.
""",
    solve=solve,
    checks=(
        Integrated("theta_max", _top, read=lambda t, y, p: y[0],
                   name="integrated_turning_tilt", rtol=1e-6, **_TURN),
        Integrated("psi_dot", _top, read=lambda t, y, p: _precession_at(p, y[0]),
                   name="integrated_precession_rate", rtol=1e-5, **_TURN),
    ),
    figure=draw,
    parts=(
        Numeric("theta_max", "largest tilt", question=1, unit="deg", points=2,
                misconceptions=(
                    Misconception("no nutation: the tilt stays", lambda p: p.theta0,
                                  "Released without precession the top is not in steady "
                                  "precession: its axis dips until energy and the vertical "
                                  "angular momentum allow θ' = 0 again."),
                )),
        Numeric("psi_dot", "precession rate at the largest tilt", question=2, unit="rad/s",
                points=2, misconceptions=(
                    Misconception("fast-top rate", lambda p: p.m * p.g * p.l / (p.I3 * p.w3),
                                  "m g l/(I3 ω3) is the mean rate of a fast top; at the "
                                  "bottom of the dip the rate is twice that."),
                )),
        Numeric("dT", "kinetic energy gained", question=3, unit="J", points=1,
                misconceptions=(
                    Misconception("sin^2 theta left out of the precession energy",
                                  lambda p: 0.5 * p.I1 * solve(p)["psi_dot"] ** 2,
                                  "Only the horizontal part ψ' sin θ of the precession "
                                  "rotates the axis: T gains ½ I1 ψ'² sin²θ."),
                )),
    ),
)
