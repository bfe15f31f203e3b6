"""A car body on its front and rear suspension: stiffness matrix of bounce and pitch, the
coupling between them and where the centre of mass would have to sit to remove it
(Section 4.4.1)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.apart import numbers_apart
from dynagrade.exercise.checks import Recompute
from dynagrade.exercise.figure import angle_arc, arrow, block, describe, dimension, ground, \
    new_drawing, spring
from dynagrade.mechanics import multi_dof


@per_draw
def matrices(p):
    return multi_dof.bounce_pitch_matrices(p.m, p.J, p.k1, p.k2, p.l1, p.l2)


@per_draw
def solve(p):
    K, M = matrices(p)
    # x0 up, theta = 0, at rest: M q'' = -K q gives the pitch acceleration
    q_ddot = -np.linalg.solve(M, K @ np.array([p.x0, 0.0]))
    # the centre's place (distance l1 behind the front spring) that makes K12 vanish
    l1_star = float(np.roots([p.k1 + p.k2, -p.k2 * (p.l1 + p.l2)])[0])
    return {"K12": K[0, 1], "K22": K[1, 1], "l1_star": l1_star, "theta_ddot0": q_ddot[1],
            "K11": K[0, 0]}


def _apart(p):
    """The magnitudes of the numeric answers differ by 5 % or more."""
    s = solve(p)
    return numbers_apart(abs(s[k]) for k in ("K12", "K22", "l1_star", "theta_ddot0"))


def _potential(x, theta, p):
    """V = k1 (x + l1 theta)^2 / 2 + k2 (x - l2 theta)^2 / 2 (the springs' stretch)."""
    return p.k1 * (x + p.l1 * theta) ** 2 / 2 + p.k2 * (x - p.l2 * theta) ** 2 / 2


def _mixed_derivative(p, d=1e-3):
    """d^2 V / dx dtheta by a central difference (exact for a quadratic V)."""
    return (_potential(d, d, p) - _potential(d, -d, p) - _potential(-d, d, p)
            + _potential(-d, -d, p)) / (4 * d * d)


def _unequal_springs(p):
    return abs(p.k1 / p.k2 - 1) > 0.05


def figure(p):
    """The body as a beam over its two springs, schematic: front (k1) on the right at l1
    ahead of the centre of mass G, rear (k2) on the left at l2 behind it, with x up and
    theta counter-clockwise (front up)."""
    drawing, axes = new_drawing(4.8, 2.6)
    l1, l2 = 1.3, 1.7
    height = 0.9
    block(axes, (0.0, height + 0.15), 1.3 * (l1 + l2), 0.3, color="0.75")
    axes.text(-0.6 * l2, height + 0.15, "$m$, $J_G$", ha="center", va="center", fontsize=10)
    for x, name in ((l1, "k₁"), (-l2, "k₂")):
        spring(axes, (x, 0.0), (x, height), coils=5, width=0.18)
        axes.text(x + 0.15, height / 2, name, ha="left", va="center", fontsize=10)
    ground(axes, -l2 - 0.5, l1 + 0.5, hatch=0.08)
    axes.plot([0.0], [height + 0.15], "o", color="0.1", ms=4)
    # inside the body, beside the dot (below it the label ran across the body's edge)
    axes.text(0.1, height + 0.15, "G", ha="left", va="center", fontsize=10)
    arrow(axes, (0.0, height + 0.35), (0.0, height + 0.85), "x", offset=(0.12, 0.0), color="C3")
    angle_arc(axes, (0.0, height + 0.15), 0.55, 0.35, 1.2, "θ", label_radius=0.75)
    # an arrowhead at the arc's end: theta turns counter-clockwise
    tip, before = 1.2, 1.05
    axes.annotate("", xy=(0.55 * np.cos(tip), height + 0.15 + 0.55 * np.sin(tip)),
                  xytext=(0.55 * np.cos(before), height + 0.15 + 0.55 * np.sin(before)),
                  arrowprops={"arrowstyle": "-|>", "color": "0.2", "lw": 0.8,
                              "mutation_scale": 8})
    dimension(axes, (0.0, 0.0), (l1, 0.0), "l₁", offset=-0.3, tick=0.05, side=-1.0)
    dimension(axes, (-l2, 0.0), (0.0, 0.0), "l₂", offset=-0.3, tick=0.05, side=-1.0)
    describe(axes, "The car drives to the right: the front spring k₁ is on the right, the rear "
             "spring k₂ on the left. x points up at the centre of mass G; θ turns "
             "counter-clockwise, lifting the front.")
    axes.set_xlim(-l2 - 0.7, l1 + 0.7)
    axes.set_ylim(-0.7, height + 1.0)
    return drawing


EXERCISE = Exercise(
    id="bounce-pitch-matrices",
    title="Car body on two springs: coupled bounce and pitch",
    source="Section 4.4.1",
    topics=("multi-DOF vibrations", "stiffness matrix", "coupled vibrations", "static coupling"),
    params=(
        Uniform("m", 800, 2000, step=50, unit="kg", symbol="m"),
        Uniform("J", 800, 3500, step=50, unit="kg*m^2", symbol="J_G"),
        Uniform("k1", 15e3, 45e3, step=1e3, unit="N/m", symbol="k_1"),
        Uniform("k2", 15e3, 45e3, step=1e3, unit="N/m", symbol="k_2"),
        Uniform("l1", 0.9, 1.6, step=0.05, unit="m", symbol="l_1"),
        Uniform("l2", 1.1, 1.9, step=0.05, unit="m", symbol="l_2"),
        Uniform("x0", 10, 50, step=1, unit="mm", symbol="x_0"),
    ),
    constraints=(
        Constraint("bounce and pitch are clearly coupled: |k1 l1 - k2 l2| >= 10 % of k1 l1",
                   lambda p: abs(p.k1 * p.l1 - p.k2 * p.l2) >= 0.1 * p.k1 * p.l1),
        Constraint("the numeric answers differ by at least 5 %", _apart),
    ),
    statement="""
A car body (mass $m$ = {{ m }}, moment of inertia $J_G$ = {{ J }} about its centre of mass
$G$ for pitching) rests on a front spring $k_1$ = {{ k1 }} at the distance
$l_1$ = {{ l1 }} ahead of $G$ and a rear spring $k_2$ = {{ k2 }} at $l_2$ = {{ l2 }}
behind it. Use as generalized coordinates the upward displacement $x$ of $G$ from the
rest position and the pitch angle $\\theta$ (positive when the front rises), small; the
springs stay vertical. Write the linearized equations of motion as
$\\mathbf M\\ddot{\\mathbf q} + \\mathbf K\\mathbf q = \\mathbf 0$ with $\\mathbf q = (x, \\theta)$.

1. What are the stiffness matrix entries $K_{12}$ and $K_{2 2}$?
2. How far behind the front spring would $G$ have to lie (same springs, same wheelbase
   $l_1 + l_2$) for bounce and pitch to be uncoupled?
3. The body is lifted by $x_0$ = {{ x0 }} without pitching and released from rest. What is its angular acceleration $\\ddot\\theta$ just
   after the release?
""",
    solution=r"""
Two degrees of freedom, $\mathbf q = (x, \theta)$. For small angles the spring ends move
$x + l_1\theta$ (front) and $x - l_2\theta$ (rear), so the energies are quadratic forms
and the Lagrange equations are linear (equations of motion for multi-DOF vibrations,
Section 4.4.1):
$$T = \tfrac12 m\dot x^2 + \tfrac12 J_G\dot\theta^2,\qquad
V = \tfrac12 k_1 (x + l_1\theta)^2 + \tfrac12 k_2 (x - l_2\theta)^2 .$$

1. **Stiffness matrix.** $K_{ij} = \partial^2 V/\partial q_i\partial q_j$:
   $$K_{11} = k_1 + k_2,\quad K_{12} = K_{2 1} = k_1 l_1 - k_2 l_2,\quad K_{2 2} = k_1 l_1^2 + k_2 l_2^2,
   \qquad \mathbf M = \operatorname{diag}(m, J_G).$$
   With the given springs and distances, $K_{11}$ = {{ si.K11 }} N/m,
   $K_{12}$ = {{ answers.K12 }} and $K_{2 2}$ = {{ answers.K22 }}.
2. **Uncoupling.** $K_{12} = 0$ needs $k_1 l_1 = k_2 l_2$ with $l_1 + l_2$ fixed:
   $$l_1^* = \frac{k_2\,(l_1 + l_2)}{k_1 + k_2}$$
   = {{ answers.l1_star }}; then a vertical push only bounces and a torque only pitches the body.
3. **Coupling at work.** At release $\theta = 0$, $\dot{\mathbf q} = \mathbf 0$ and the
   second equation reads $J_G\ddot\theta + K_{12}\,x_0 = 0$:
   $\ddot\theta = -K_{12}x_0/J_G$ = {{ answers.theta_ddot0 }} ($x_0$ = {{ x0 }},
   $J_G$ = {{ J }}). **Check.** A mixed difference of $V$ gives back
   $K_{12}$ = {{ checks.mixed_difference }} N; it vanishes, and with it the pitching,
   exactly at $l_1 = l_1^*$.
""",
    solve=solve,
    checks=(
        Recompute("K12", lambda p, s: _mixed_derivative(p), name="mixed_difference", rtol=1e-6),
        Recompute("theta_ddot0", lambda p, s: -_mixed_derivative(p) * p.x0 / p.J,
                  name="second_equation", rtol=1e-6),
        Recompute("K22", lambda p, s: p.k1 * p.l1**2 + p.k2 * p.l2**2, name="lever_arms_squared"),
    ),
    figure=figure,
    parts=(
        Numeric("K12", "stiffness entry K12", question=1, unit="N", points=2, misconceptions=(
            Misconception("lever arms squared", lambda p: p.k1 * p.l1**2 - p.k2 * p.l2**2,
                          "K12 = d^2V/(dx dtheta): each spring contributes k l once, signed."),
            Misconception("rear sign lost", lambda p: p.k1 * p.l1 + p.k2 * p.l2,
                          "The rear spring end moves x - l2 theta: its term is -k2 l2."),
        )),
        Numeric("K22", "stiffness entry K22", question=1, unit="N*m", points=1, misconceptions=(
            Misconception("lever arms not squared", lambda p: p.k1 * p.l1 + p.k2 * p.l2,
                          "A spring at distance l resists pitch with k l^2."),
        )),
        Numeric("l1_star", "distance of G behind the front spring", question=2, unit="m",
                points=1, misconceptions=(
                    Misconception("springs swapped", lambda p: p.k1 * (p.l1 + p.l2) / (p.k1 + p.k2),
                                  "k1 l1 = k2 l2: the stiffer spring must be the nearer one.",
                                  applies=_unequal_springs),
                    Misconception("half the wheelbase", lambda p: (p.l1 + p.l2) / 2,
                                  "Only equal springs need G midway; in general k1 l1 = k2 l2.",
                                  applies=_unequal_springs),
                )),
        Numeric("theta_ddot0", "angular acceleration at release", question=3, unit="rad/s^2",
                points=1, misconceptions=(
                    Misconception("divided by m", lambda p: -solve(p)["K12"] * p.x0 / p.m,
                                  "The pitch equation has J_G theta'' on its left.",
                                  applies=lambda p: abs(p.m / p.J - 1) > 0.03),
                    Misconception("no coupling", lambda p: 0.0,
                                  "K12 is not zero: a pure lift makes the springs' moments unequal."),
                )),
    ),
)
