"""Kinetic energy and angular momentum of an unsymmetric top from its Euler angles and
rates (Section 3.5.1)."""

import itertools

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.checks import Recompute
from dynagrade.exercise.figure import angle_arc, arrow, describe, ground, new_drawing
from dynagrade.mechanics import gyro, rigid_kinetics


def _inertia(p):
    """Inertia tensor about the tip O in the principal body frame."""
    return np.diag([p.I1, p.I2, p.I3])


@per_draw
def solve(p):
    omega = gyro.body_angular_velocity_from_euler_rates(p.theta, p.phi, p.psi_dot,
                                                        p.theta_dot, p.phi_dot)
    h = rigid_kinetics.rigid_body_angular_momentum(_inertia(p), omega)
    return {
        "T": rigid_kinetics.rotational_kinetic_energy(_inertia(p), omega),
        "H_v": float(h @ gyro.body_components_of_vertical(p.theta, p.phi)),
        "H_abs": float(np.linalg.norm(h)),
        "w1": float(omega[0]), "w2": float(omega[1]), "w3": float(omega[2]),
        "h1": float(h[0]), "h2": float(h[1]), "h3": float(h[2]),
    }


def _space_route(p):
    """The same top in the space frame, with numpy alone: R = R1(theta) R3(phi) (psi = 0
    costs nothing, nothing here depends on psi); omega = psi' e3 + theta' e1 (the line of
    nodes) + phi' R e3; the inertia tensor about O in space axes R I R^T (Sections 3.2.3,
    3.5.1). Returns (T, vertical H, |H|)."""
    c, s = np.cos(p.theta), np.sin(p.theta)
    r1 = np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])
    c, s = np.cos(p.phi), np.sin(p.phi)
    r3 = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    rotation = r1 @ r3
    omega = (p.psi_dot * np.array([0.0, 0.0, 1.0]) + p.theta_dot * np.array([1.0, 0.0, 0.0])
             + p.phi_dot * rotation[:, 2])
    h = rotation @ np.diag([p.I1, p.I2, p.I3]) @ rotation.T @ omega
    return 0.5 * omega @ h, h[2], np.linalg.norm(h)


def _apart(p):
    """The three answers differ by at least 8 % in SI."""
    values = [abs(solve(p)[k]) for k in ("T", "H_v", "H_abs")]
    return all(abs(a - b) > 0.08 * max(a, b) for a, b in itertools.combinations(values, 2))


def _rates_as_components(p):
    """The wrong route: the Euler rates taken as the body components of omega."""
    return 0.5 * (p.I1 * p.theta_dot**2 + p.I2 * p.psi_dot**2 + p.I3 * p.phi_dot**2)


def _spin_part_vertical(p):
    """The wrong route: only the axial angular momentum, projected on the vertical."""
    return p.I3 * solve(p)["w3"] * np.cos(p.theta)


def _differs(wrong, key):
    return lambda p: abs(wrong(p) - solve(p)[key]) > 0.03 * abs(solve(p)[key])


def draw(p):
    """Schematic: the top on its tip O, the vertical e3 and the body axis e3^B tilted by
    theta, the precession about the vertical and the spin about the body axis."""
    from dynagrade.exercise.figure import Ellipse

    figure, axes = new_drawing(3.6, 3.4)
    ground(axes, -1.2, 1.2, hatch=0.1)
    axis = np.array([np.sin(p.theta), np.cos(p.theta)])
    axes.plot([0.0, 0.0], [0.0, 2.6], color="0.4", lw=0.8, ls="--")
    axes.text(0.08, 2.6, "e₃", ha="left", va="top", fontsize=10)
    body = axis * 1.3
    axes.plot([0.0, body[0]], [0.0, body[1]], color="0.1", lw=1.2)
    axes.add_patch(Ellipse(tuple(body), 1.3, 0.45, angle=-np.degrees(p.theta),
                           facecolor="C0", edgecolor="0.1"))
    tip = axis * 2.3
    arrow(axes, tuple(axis * 1.8), tuple(tip), "", color="0.1")
    axes.text(tip[0] + 0.1, tip[1], "e₃ᴮ", ha="left", va="center", fontsize=10)
    angle_arc(axes, (0.0, 0.0), 0.6, np.pi / 2 - p.theta, np.pi / 2, "θ", label_radius=0.8)
    axes.annotate("", xy=(0.35, 2.25), xytext=(-0.35, 2.25),
                  arrowprops={"arrowstyle": "-|>", "connectionstyle": "arc3,rad=0.5",
                              "color": "#23802a"})
    axes.text(-0.45, 2.3, "ψ̇", color="#23802a", ha="right", va="center", fontsize=10)
    axes.text(0.0, -0.05, "O", ha="center", va="top", fontsize=10)
    spin_at = axis * 1.95 + np.array([axis[1], -axis[0]]) * 0.3
    axes.text(*spin_at, "φ̇", color="C3", ha="left", va="center", fontsize=10)
    describe(axes, "The top stands on its fixed tip O; its body axis e₃ᴮ is tilted by θ "
             "from the vertical e₃; it precesses about e₃ (ψ̇) and spins about e₃ᴮ (φ̇).")
    axes.set_xlim(-1.3, 2.3)
    axes.set_ylim(-0.4, 2.8)
    return figure


EXERCISE = Exercise(
    id="top-energy-and-momentum",
    title="Kinetic energy and angular momentum of an unsymmetric top",
    source="Section 3.5.1",
    topics=("spinning tops", "Euler angles", "inertia tensor", "angular momentum"),
    params=(
        Uniform("I1", 3e-4, 1.2e-3, step=5e-5, unit="kg*m^2", symbol="I_1"),
        Uniform("I2", 3e-4, 1.2e-3, step=5e-5, unit="kg*m^2", symbol="I_2"),
        Uniform("I3", 1e-4, 8e-4, step=5e-5, unit="kg*m^2", symbol="I_3"),
        Uniform("theta", 20, 70, step=5, unit="deg", symbol=r"\theta"),
        Uniform("phi", 0, 345, step=15, unit="deg", symbol=r"\varphi"),
        Uniform("psi_dot", 1.0, 8.0, step=0.25, unit="rad/s", symbol=r"\dot\psi"),
        Uniform("theta_dot", -3.0, 3.0, step=0.25, unit="rad/s", symbol=r"\dot\theta"),
        Uniform("phi_dot", 10, 60, step=2, unit="rad/s", symbol=r"\dot\varphi"),
    ),
    constraints=(
        Constraint("the body is clearly unsymmetric: I1 and I2 differ by at least 25 %",
                   lambda p: abs(p.I1 - p.I2) >= 0.25 * max(p.I1, p.I2)),
        Constraint("the moments belong to a real body: each principal moment about O is at "
                   "most the sum of the other two",
                   lambda p: 2 * max(p.I1, p.I2, p.I3) <= p.I1 + p.I2 + p.I3),
        Constraint("the nutation rate is not zero", lambda p: abs(p.theta_dot) >= 0.5),
        Constraint("the three answers differ by at least 8 % in SI", _apart),
    ),
    statement=r"""
A rigid body spins on a fixed tip O. Its principal axes of inertia about O are the body
axes $e_1^B, e_2^B, e_3^B$, with the moments $I_1$ = {{ I1 }}, $I_2$ = {{ I2 }},
$I_3$ = {{ I3 }}. Its orientation is given by the Euler angles of the lecture
($R = R_3(\psi) R_1(\theta) R_3(\varphi)$: precession $\psi$ about the vertical $e_3$,
nutation $\theta$, spin $\varphi$ about $e_3^B$). At the instant considered
$\theta$ = {{ theta }}, $\varphi$ = {{ phi }}, $\dot\psi$ = {{ psi_dot }},
$\dot\theta$ = {{ theta_dot }} and $\dot\varphi$ = {{ phi_dot }}.

1. What is the kinetic energy of the body?
2. What is the vertical component $H_O\cdot e_3$ of its angular momentum about O?
3. What is the magnitude of its angular momentum about O?
""",
    solution=r"""
With O fixed, the angular momentum about O and the kinetic energy follow from the
angular velocity and the inertia tensor about O: $H_O = I_O\,\omega$,
$T = \tfrac{1}{2}\,\omega\cdot I_O\,\omega$ (Section 3.2.2; Section 3.2.5). Both are simplest in
the principal body frame, where $I_O = \mathrm{diag}(I_1, I_2, I_3)$ with $I_1$ = {{ I1 }},
$I_2$ = {{ I2 }}, $I_3$ = {{ I3 }} (top, general description, Section 3.5.1).

The angular velocity from the Euler rates ($\theta$ = {{ theta }}, $\varphi$ = {{ phi }},
$\dot\psi$ = {{ psi_dot }}, $\dot\theta$ = {{ theta_dot }}, $\dot\varphi$ = {{ phi_dot }}):
$\omega_1 = \dot\psi\sin\theta\sin\varphi + \dot\theta\cos\varphi$ = {{ si.w1 }} rad/s,
$\omega_2 = \dot\psi\sin\theta\cos\varphi - \dot\theta\sin\varphi$ = {{ si.w2 }} rad/s,
$\omega_3 = \dot\psi\cos\theta + \dot\varphi$ = {{ si.w3 }} rad/s.

1. **Kinetic energy.** $T = \tfrac{1}{2}(I_1\omega_1^2 + I_2\omega_2^2 + I_3\omega_3^2)$
   = {{ answers.T }}.
2. **Vertical component.** In the body frame $H_O = (I_1\omega_1, I_2\omega_2, I_3\omega_3)$
   = ({{ si.h1 }}, {{ si.h2 }}, {{ si.h3 }}) kg·m²/s, and the vertical $e_3$ has the body
   components $(\sin\theta\sin\varphi, \sin\theta\cos\varphi, \cos\theta)$. Their dot
   product is $H_O\cdot e_3$ = {{ answers.H_v }}. (Gravity's moment about O is
   horizontal, so this component stays constant while the top moves.)
3. **Magnitude.** $|H_O| = \sqrt{(I_1\omega_1)^2 + (I_2\omega_2)^2 + (I_3\omega_3)^2}$
   = {{ answers.H_abs }}; $H_O$ is not parallel to $\omega$ since $I_1 \ne I_2 \ne I_3$.
4. **Check.** In the space frame, $\omega = \dot\psi e_3 + \dot\theta e_1' + \dot\varphi e_3^B$
   and $I_O = R\,\mathrm{diag}(I_1, I_2, I_3)\,R^T$ give $T$ = {{ checks.space_frame_energy }} J
   again.
""",
    solve=solve,
    checks=(
        Recompute("T", lambda p, s: _space_route(p)[0], name="space_frame_energy"),
        Recompute("H_v", lambda p, s: _space_route(p)[1], name="space_frame_vertical"),
        Recompute("H_abs", lambda p, s: _space_route(p)[2], name="space_frame_magnitude"),
    ),
    figure=draw,
    parts=(
        Numeric("T", "kinetic energy", question=1, unit="J", points=2,
                misconceptions=(
                    Misconception("Euler rates used as body components", _rates_as_components,
                                  "ψ', θ' and φ' are rates about three different, non-"
                                  "orthogonal axes: build ω's body components first "
                                  "(Section 3.5.1).",
                                  applies=_differs(_rates_as_components, "T")),
                )),
        Numeric("H_v", "vertical angular momentum", question=2, unit="kg*m^2/s", points=2,
                misconceptions=(
                    Misconception("only the axial part projected", _spin_part_vertical,
                                  "The transverse components I1 ω1 and I2 ω2 have vertical "
                                  "parts too: take the full dot product with e3.",
                                  applies=_differs(_spin_part_vertical, "H_v")),
                )),
        Numeric("H_abs", "magnitude of the angular momentum", question=3, unit="kg*m^2/s",
                points=1, misconceptions=(
                    Misconception("H = I3 |omega|",
                                  lambda p: p.I3 * np.sqrt(solve(p)["w1"] ** 2
                                                           + solve(p)["w2"] ** 2
                                                           + solve(p)["w3"] ** 2),
                                  "Each component of ω has its own moment of inertia: "
                                  "H = (I1 ω1, I2 ω2, I3 ω3).",
                                  applies=_differs(lambda p: p.I3 * np.sqrt(
                                      solve(p)["w1"] ** 2 + solve(p)["w2"] ** 2
                                      + solve(p)["w3"] ** 2), "H_abs")),
                )),
    ),
)
