"""Two pendulums coupled by a spring: the linearized mass and stiffness matrices from the
Lagrange equations and the accelerations just after one of them is released (Section 4.4.1)."""

from functools import cache

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric, Uniform,
                                per_draw)
from dynagrade.exercise.apart import numbers_apart
from dynagrade.exercise.checks import Recompute
from dynagrade.exercise.figure import angle_arc, ceiling, describe, dimension, new_drawing, spring


@cache
def _linearized():
    """(K, M) as functions of (m1, m2, L, k, a, g), linearized by the core about the hanging
    position on first use. The spring joins the rods at a below the pivots and stays nearly
    horizontal: it stretches by a (sin(theta2) - sin(theta1)) for pivots on one level."""
    import sympy as sp

    from dynagrade.mechanics import equilibrium

    t = sp.Symbol("t")
    th1, th2 = sp.Function("theta1")(t), sp.Function("theta2")(t)
    m1, m2, L, k, a, g = sp.symbols("m1 m2 L k a g", positive=True)
    T = (m1 * (L * th1.diff(t)) ** 2 + m2 * (L * th2.diff(t)) ** 2) / 2
    V = (-m1 * g * L * sp.cos(th1) - m2 * g * L * sp.cos(th2)
         + k * (a * sp.sin(th2) - a * sp.sin(th1)) ** 2 / 2)
    rest = {th1: 0, th2: 0}
    symbols = [m1, m2, L, k, a, g]
    return (sp.lambdify(symbols, equilibrium.stiffness_matrix(V, [th1, th2], rest)),
            sp.lambdify(symbols, equilibrium.linearized_mass_matrix(T, [th1, th2], t, rest)))


@per_draw
def matrices(p):
    stiffness, mass = _linearized()
    args = (p.m1, p.m2, p.L, p.k, p.a, p.g)
    return np.array(stiffness(*args), dtype=float), np.array(mass(*args), dtype=float)


@per_draw
def solve(p):
    K, M = matrices(p)
    q_ddot = -np.linalg.solve(M, K @ np.array([p.theta0, 0.0]))
    return {"K11": K[0, 0], "K12": K[0, 1], "theta1_ddot": q_ddot[0], "theta2_ddot": q_ddot[1],
            "M11": M[0, 0], "M22": M[1, 1]}


def _nonlinear_start(p, eps=1e-6):
    """(theta1'', theta2'') at the release from the full equations of motion
    m_i L^2 theta_i'' = -m_i g L sin(theta_i) -+ k a^2 cos(theta_i) (sin(theta1) - sin(theta2)),
    taken at the tiny angle eps and scaled up to theta0: the linearized values, to 1e-12."""
    stretch = p.a * np.sin(eps)
    scale = p.theta0 / eps
    return (-scale * (p.m1 * p.g * p.L * np.sin(eps) + p.k * p.a * np.cos(eps) * stretch)
            / (p.m1 * p.L**2),
            scale * p.k * p.a * stretch / (p.m2 * p.L**2))


def _potential(th1, th2, p):
    return (-p.m1 * p.g * p.L * np.cos(th1) - p.m2 * p.g * p.L * np.cos(th2)
            + p.k * (p.a * np.sin(th2) - p.a * np.sin(th1)) ** 2 / 2)


def _hessian_entry(p, i, j, d=1e-4):
    """d^2 V / dtheta_i dtheta_j at rest by central differences of the full potential."""
    def V(e1, e2):
        return _potential(e1, e2, p)
    if i == j == 0:
        return (V(d, 0) - 2 * V(0, 0) + V(-d, 0)) / d**2
    return (V(d, d) - V(d, -d) - V(-d, d) + V(-d, -d)) / (4 * d * d)


def _fair(p):
    """The magnitudes of the answers differ by 5 % or more."""
    s = solve(p)
    return numbers_apart(abs(s[k]) for k in ("K11", "K12", "theta1_ddot", "theta2_ddot"))


def figure(p):
    """Schematic: the two pendulums hanging from one ceiling, the spring between the rods a
    below the pivots, the left one drawn displaced by theta1 (counter-clockwise positive)."""
    from dynagrade.exercise.figure import Circle

    drawing, axes = new_drawing(3.6, 3.0)
    L, a, gap, shown = 1.0, 0.45, 1.0, np.radians(18)
    ceiling(axes, -0.4, gap + 0.4, 0.0, hatch=0.06)
    for x0, angle, name in ((0.0, shown, "m₁"), (gap, 0.0, "m₂")):
        tip = (x0 + L * np.sin(angle), -L * np.cos(angle))
        axes.plot([x0, tip[0]], [0.0, tip[1]], color="0.2", lw=1.5)
        axes.add_patch(Circle(tip, 0.07, facecolor="C0", edgecolor="0.1"))
        axes.text(tip[0] + 0.1, tip[1] - 0.05, name, ha="left", va="top", fontsize=10)
        axes.plot([x0, x0], [0.0, -L - 0.1], color="0.5", lw=0.6, ls="-.")
    left = (a * np.sin(shown), -a * np.cos(shown))
    spring(axes, left, (gap, -a), coils=5, width=0.08)
    axes.text(gap / 2 + 0.05, -a + 0.08, "k", ha="center", va="bottom", fontsize=10)
    dimension(axes, (0.0, 0.0), (0.0, -a), "a", offset=-0.2, tick=0.04, side=-1.0)
    dimension(axes, (gap, 0.0), (gap, -L), "L", offset=0.25, tick=0.04)
    # the angle's label beside the rod, clear of the spring's end below it
    angle_arc(axes, (0.0, 0.0), 0.25, -np.pi / 2, -np.pi / 2 + shown)
    label_at = shown + 0.3
    axes.text(0.3 * np.sin(label_at), -0.3 * np.cos(label_at), "θ₁", ha="left", va="center",
              fontsize=10)
    describe(axes, "The left pendulum is drawn swung counter-clockwise, the positive sense of "
             "both angles; the right one hangs straight down. The spring is relaxed when both hang "
             "vertically.")
    axes.set_xlim(-0.55, gap + 0.6)
    axes.set_ylim(-L - 0.3, 0.2)
    return drawing


EXERCISE = Exercise(
    id="spring-coupled-pendulums",
    title="Two pendulums coupled by a spring: linearized equations of motion",
    source="Section 4.4.1",
    topics=("Lagrange equations", "stiffness matrix", "coupled vibrations", "linearization"),
    params=(
        Uniform("m1", 0.2, 3.0, step=0.1, unit="kg", symbol="m_1"),
        Uniform("m2", 0.2, 3.0, step=0.1, unit="kg", symbol="m_2"),
        Uniform("L", 0.4, 1.5, step=0.05, unit="m", symbol="L"),
        Uniform("a", 0.1, 1.35, step=0.05, unit="m", symbol="a"),
        Uniform("k", 5, 200, step=1, unit="N/m", symbol="k"),
        Uniform("theta0", 2, 8, step=0.5, unit="deg", symbol=r"\theta_0"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("the spring is attached on the rods, at most 90 % down", lambda p: p.a <= 0.9 * p.L),
        Constraint("the coupling matters: k a^2 is at least 10 % of m1 g L and of m2 g L",
                   lambda p: p.k * p.a**2 >= 0.1 * max(p.m1, p.m2) * p.g * p.L),
        Constraint("the answers differ by at least 5 %", _fair),
    ),
    statement="""
Two pendulums hang side by side from one ceiling, pendulum 1 on the left: point masses
$m_1$ = {{ m1 }} and $m_2$ = {{ m2 }} on massless rods of the same length $L$ = {{ L }}. A spring of stiffness
$k$ = {{ k }} joins the rods at the distance $a$ = {{ a }} below the pivots; it is relaxed
when both hang vertically and stays nearly horizontal; $g$ = {{ g }}. The angles
$\\theta_1$, $\\theta_2$ from the downward vertical are both positive counter-clockwise.

1. Linearize the Lagrange equations about $\\theta_1 = \\theta_2 = 0$ into
   $\\mathbf M\\ddot{\\boldsymbol\\theta} + \\mathbf K\\boldsymbol\\theta = \\mathbf 0$. Give
   the stiffness entries $K_{11}$ and $K_{12}$.
2. Pendulum 1 is held at $\\theta_1 = \\theta_0$ = {{ theta0 }} with pendulum 2 hanging at
   rest, and released. Using the linearized equations, what are $\\ddot\\theta_1$ and
   $\\ddot\\theta_2$ just after the release?
""",
    solution=r"""
Two degrees of freedom, $\boldsymbol\theta = (\theta_1, \theta_2)$; the energies
$$T = \tfrac12 m_1 L^2\dot\theta_1^2 + \tfrac12 m_2 L^2\dot\theta_2^2,\qquad
V = -m_1 g L\cos\theta_1 - m_2 g L\cos\theta_2 + \tfrac12 k a^2(\sin\theta_2 - \sin\theta_1)^2$$
linearized about the hanging position give $\mathbf M = \operatorname{diag}(m_1 L^2, m_2 L^2)$
and $K_{ij} = \partial^2 V/\partial\theta_i\partial\theta_j$ at rest (equations of motion
for multi-DOF vibrations, Section 4.4.1).

1. **Stiffness matrix.**
   $$K_{11} = m_1 g L + k a^2,\qquad K_{12} = K_{2 1} = -k a^2,\qquad K_{2 2} = m_2 g L + k a^2:$$
   $K_{11}$ = {{ answers.K11 }} and $K_{12}$ = {{ answers.K12 }}; the mass matrix has
   $M_{11}$ = {{ si.M11 }} kg·m² and $M_{2 2}$ = {{ si.M22 }} kg·m².
2. **At the release.** With $\boldsymbol\theta = (\theta_0, 0)$ and $\mathbf M$ diagonal,
   $\ddot\theta_1 = -K_{11}\theta_0/M_{11} = -\bigl(\frac gL + \frac{k a^2}{m_1 L^2}\bigr)\theta_0$
   = {{ answers.theta1_ddot }} and
   $\ddot\theta_2 = -K_{2 1}\theta_0/M_{2 2} = \frac{k a^2}{m_2 L^2}\theta_0$
   = {{ answers.theta2_ddot }}: the compressed spring starts pushing pendulum 2 along at once.
   **Check.** The full nonlinear equations, taken at a tiny angle and scaled up to
   $\theta_0$, give back $\ddot\theta_2$ = {{ checks.nonlinear_second }} rad/s²; at
   $\theta_0$ itself they differ by the factor $\sin\theta_0/\theta_0$, below 1 % here.
""",
    solve=solve,
    checks=(
        Recompute("K11", lambda p, s: _hessian_entry(p, 0, 0), name="curvature_by_difference", rtol=1e-5),
        Recompute("K12", lambda p, s: _hessian_entry(p, 0, 1), name="mixed_difference", rtol=1e-5),
        Recompute("theta1_ddot", lambda p, s: _nonlinear_start(p)[0], name="nonlinear_first"),
        Recompute("theta2_ddot", lambda p, s: _nonlinear_start(p)[1], name="nonlinear_second"),
    ),
    figure=figure,
    parts=(
        Numeric("K11", "stiffness entry K11", question=1, unit="N*m", points=1, misconceptions=(
            Misconception("spring forgotten", lambda p: p.m1 * p.g * p.L,
                          "The spring resists theta1 too: K11 = m1 g L + k a^2."),
            Misconception("a not squared", lambda p: p.m1 * p.g * p.L + p.k * p.a,
                          "The spring stretches a theta1 and acts with the lever a: k a^2.",
                          applies=lambda p: abs(p.k * p.a - p.k * p.a**2) > 0.03 * solve(p)["K11"]),
        )),
        Numeric("K12", "stiffness entry K12", question=1, unit="N*m", points=1, misconceptions=(
            Misconception("rod length for a", lambda p: -p.k * p.L**2,
                          "The spring sits at a below the pivots: K12 = -k a^2."),
        )),
        Numeric("theta1_ddot", "angular acceleration of pendulum 1", question=2, unit="rad/s^2",
                points=1, misconceptions=(
                    Misconception("spring forgotten", lambda p: -p.g * p.theta0 / p.L,
                                  "The compressed spring also pushes pendulum 1 back: K11 = m1 g L + k a^2."),
                )),
        Numeric("theta2_ddot", "angular acceleration of pendulum 2", question=2, unit="rad/s^2",
                points=2, misconceptions=(
                    Misconception("not coupled at first", lambda p: 0.0,
                                  "K21 theta0 acts at once: the spring is already compressed by a theta0."),
                    Misconception("m1 for m2", lambda p: p.k * p.a**2 * p.theta0 / (p.m1 * p.L**2),
                                  "Pendulum 2's equation has M22 = m2 L^2.",
                                  applies=lambda p: abs(p.m1 / p.m2 - 1) > 0.03),
                )),
    ),
)
