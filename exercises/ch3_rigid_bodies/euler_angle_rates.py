"""Angular velocity of a top from its Euler-angle rates (Section 3.5.1)."""

import numpy as np

from dynagrade.exercise import (Constraint, Exercise, Misconception, Numeric, Uniform, Vector,
                                per_draw)
from dynagrade.exercise.checks import Recompute
from dynagrade.mechanics import gyro


def _omega(p):
    return gyro.body_angular_velocity_from_euler_rates(p.theta, p.phi, p.psi_dot,
                                                       p.theta_dot, p.phi_dot)


@per_draw
def solve(p):
    w = _omega(p)
    return {"omega_body": w, "omega_abs": float(np.linalg.norm(w))}


@per_draw
def _rates_added(p):
    """The wrong route: precession and spin added as if about one axis."""
    return np.array([p.theta_dot, 0.0, p.psi_dot + p.phi_dot])


def _magnitude(p, solved):
    """omega = psi' (space axis) + theta' (line of nodes) + phi' (body axis), Section 3.5.1:
    the line of nodes is perpendicular to both axes, which enclose theta, so
    |omega|^2 = theta'^2 + psi'^2 + phi'^2 + 2 psi' phi' cos(theta) in any convention."""
    return np.sqrt(p.theta_dot**2 + p.psi_dot**2 + p.phi_dot**2
                   + 2 * p.psi_dot * p.phi_dot * np.cos(p.theta))


EXERCISE = Exercise(
    id="euler-angle-rates",
    title="Angular velocity of a top from its Euler angles",
    source="Section 3.5.1",
    topics=("Euler angles", "spinning tops", "angular velocity"),
    params=(
        Uniform("theta", 10, 80, step=5, unit="deg", symbol=r"\theta"),
        Uniform("phi", 0, 345, step=15, unit="deg", symbol=r"\varphi"),
        Uniform("psi_dot", 0.5, 5.0, step=0.25, unit="rad/s", symbol=r"\dot\psi"),
        Uniform("theta_dot", -2.0, 2.0, step=0.25, unit="rad/s", symbol=r"\dot\theta"),
        Uniform("phi_dot", 10, 100, step=5, unit="rad/s", symbol=r"\dot\varphi"),
    ),
    constraints=(
        Constraint("the nutation rate is not zero", lambda p: abs(p.theta_dot) > 0.1),
        Constraint("the tilt changes the magnitude noticeably",
                   lambda p: abs(solve(p)["omega_abs"] - np.linalg.norm(_rates_added(p)))
                   > 0.02 * solve(p)["omega_abs"]),
    ),
    statement=r"""
The orientation of a top is described by the Euler angles of the lecture: precession
$\psi$ about the vertical $e_3$, nutation $\theta$ about the line of nodes and spin
$\varphi$ about the symmetry axis $e_3^B$ ($R = R_3(\psi) R_1(\theta) R_3(\varphi)$). At the
instant considered $\theta$ = {{ theta }}, $\varphi$ = {{ phi }}, and the rates are
$\dot\psi$ = {{ psi_dot }}, $\dot\theta$ = {{ theta_dot }}, $\dot\varphi$ = {{ phi_dot }}.

1. What are the components of the top's angular velocity in its body frame
   ($e_1^B, e_2^B, e_3^B$)?
2. What is the magnitude of the angular velocity?
""",
    solution=r"""
The angular velocity of the top is the sum of the three rotation rates about their own
axes (Euler angles, Section 3.5.1):
$$\omega = \dot\psi\,e_3 + \dot\theta\,e_1' + \dot\varphi\,e_3^B,$$
where $e_1'$ is the line of nodes. To add them we need all three in the body frame.

1. **Body-frame components.** The spin axis is $e_3^B$ itself; the line of nodes has the
   components $(\cos\varphi, -\sin\varphi, 0)$; the vertical $e_3$ has
   $(\sin\theta\sin\varphi, \sin\theta\cos\varphi, \cos\theta)$. Hence
   $$\omega_1^B = \dot\psi\sin\theta\sin\varphi + \dot\theta\cos\varphi,\qquad
   \omega_2^B = \dot\psi\sin\theta\cos\varphi - \dot\theta\sin\varphi,\qquad
   \omega_3^B = \dot\psi\cos\theta + \dot\varphi .$$
   With $\theta$ = {{ theta }}, $\varphi$ = {{ phi }}, $\dot\psi$ = {{ psi_dot }},
   $\dot\theta$ = {{ theta_dot }} and $\dot\varphi$ = {{ phi_dot }}:
   $\omega^B$ = {{ answers.omega_body }}.
2. **Magnitude.** The length of a vector is the same in every frame:
   $$|\omega| = \sqrt{(\omega_1^B)^2 + (\omega_2^B)^2 + (\omega_3^B)^2},$$
   which gives $|\omega|$ = {{ answers.omega_abs }}.
   Adding $\dot\psi$ and $\dot\varphi$ as if about one axis is wrong: the vertical and the
   symmetry axis make the angle $\theta$.
""",
    solve=solve,
    checks=(
        Recompute("omega_abs", _magnitude, name="magnitude_without_components"),
    ),
    parts=(
        Vector("omega_body", "body-frame angular velocity", question=1,
               unit="rad/s", size=3, points=3,
               atol=0.01,
               misconceptions=(
                   Misconception("rates added about one axis", _rates_added,
                                 "The precession rate is about the vertical, not about the "
                                 "symmetry axis: ψ' e3 has components ψ' (sin θ sin φ, "
                                 "sin θ cos φ, cos θ) in the body frame."),
               )),
        Numeric("omega_abs", "magnitude of the angular velocity", question=2,
                unit="rad/s", points=1,
                misconceptions=(
                    Misconception("rates added about one axis",
                                  lambda p: float(np.linalg.norm(_rates_added(p))),
                                  "ψ' e3 and φ' e3^B are not parallel when θ ≠ 0."),
                )),
    ),
)
