"""Harmonic force on the outer mass of an undamped two-mass chain: the steady-state
amplitudes (in phase or in antiphase) and the forcing frequency at which the driven mass
stands still (Section 4.4.3)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.apart import numbers_apart
from dynagrade.exercise.checks import Recompute
from dynagrade.exercise.figure import arrow, block, describe, ground, new_drawing, spring, wall
from dynagrade.mechanics import multi_dof, vibrations


@per_draw
def matrices(p):
    return multi_dof.chain_stiffness_matrix([p.k1, p.k2]), multi_dof.lumped_mass_matrix([p.m1, p.m2])


@per_draw
def solve(p):
    K, M = matrices(p)
    Omega = 2 * np.pi * p.f
    X = multi_dof.steady_state_amplitudes(K, M, np.zeros((2, 2)), [0.0, p.F0], Omega).real
    # m2 stands still where the first row's dynamic stiffness K11 - Omega^2 M11 vanishes:
    # m1 on both springs then acts as an absorber (Section 4.4.3)
    w_a = vibrations.natural_frequency(K[0, 0], M[0, 0])
    w = multi_dof.natural_frequencies(K, M)
    return {"X1": X[0], "X2": X[1], "f_a": vibrations.frequency_in_hertz(w_a),
            "Omega": Omega, "omega1": w[0], "omega2": w[1]}


def _cramer(p):
    """(X1, X2) by Cramer's rule for (K - Omega^2 M) X = (0, F0) with
    K = [[k1 + k2, -k2], [-k2, k2]], M = diag(m1, m2)."""
    W2 = (2 * np.pi * p.f) ** 2
    a, b, d = p.k1 + p.k2 - W2 * p.m1, -p.k2, p.k2 - W2 * p.m2
    det = a * d - b * b
    return -b * p.F0 / det, a * p.F0 / det


def _m2_alone(p):
    return p.F0 / (p.k2 - (2 * np.pi * p.f) ** 2 * p.m2)


def _m1_matters(p):
    """Far above both resonances m2 moves nearly as if m1 were fixed: the slip is then no slip."""
    return abs(_m2_alone(p) / solve(p)["X2"] - 1) > 0.03


def _fair(p):
    """The forcing is 10 % or more from both resonances and the anti-resonance, and the
    answers (mm and Hz) differ by 5 % or more."""
    s = solve(p)
    if any(abs(s["Omega"] / w - 1) < 0.1 for w in (s["omega1"], s["omega2"], 2 * np.pi * s["f_a"])):
        return False
    return numbers_apart((abs(1e3 * s["X1"]), abs(1e3 * s["X2"]), s["f_a"]))


def figure(p):
    """Schematic: wall, spring k1, mass m1, spring k2, mass m2 on a smooth floor, the force
    on m2 and the displacements x1, x2 to the right."""
    drawing, axes = new_drawing(4.8, 1.9)
    wall(axes, 0.0, 0.0, 1.0, side=-1.0, hatch=0.06)
    ground(axes, 0.0, 4.3, hatch=0.06)
    spring(axes, (0.0, 0.4), (0.8, 0.4), coils=5, width=0.15)
    block(axes, (1.2, 0.4), 0.8, 0.8, "m₁")
    spring(axes, (1.6, 0.4), (2.4, 0.4), coils=5, width=0.15)
    block(axes, (2.8, 0.4), 0.8, 0.8, "m₂")
    axes.text(0.4, 0.62, "k₁", ha="center", va="bottom", fontsize=10)
    axes.text(2.0, 0.62, "k₂", ha="center", va="bottom", fontsize=10)
    arrow(axes, (3.2, 0.4), (4.1, 0.4), "F₀ cos Ωt", offset=(0.0, 0.22), color="C3")
    arrow(axes, (1.0, 1.0), (1.5, 1.0), "x₁", offset=(0.0, 0.12), color="0.3")
    arrow(axes, (2.6, 1.0), (3.1, 1.0), "x₂", offset=(0.0, 0.12), color="0.3")
    describe(axes, "Both masses slide without friction; the force acts on m₂ to the right.")
    axes.set_xlim(-0.3, 4.4)
    axes.set_ylim(-0.25, 1.35)
    return drawing


EXERCISE = Exercise(
    id="two-mass-forced-chain",
    title="Two masses in a chain, the outer one shaken: amplitudes and anti-resonance",
    source="Section 4.4.3",
    topics=("forced vibration", "multi-DOF vibrations", "anti-resonance", "steady state"),
    params=(
        Uniform("m1", 20, 300, step=5, unit="kg", symbol="m_1"),
        Uniform("m2", 10, 200, step=5, unit="kg", symbol="m_2"),
        Uniform("k1", 1e4, 2e5, step=1e3, unit="N/m", symbol="k_1"),
        Uniform("k2", 1e4, 2e5, step=1e3, unit="N/m", symbol="k_2"),
        Uniform("F0", 50, 1000, step=10, unit="N", symbol="F_0"),
        Uniform("f", 0.5, 8.0, step=0.1, unit="Hz", symbol="f"),
    ),
    constraints=(
        Constraint("the forcing is 10 % off the resonances and the anti-resonance; the "
                   "answers differ by 5 %", _fair),
    ),
    statement="""
A mass $m_1$ = {{ m1 }} is tied to a wall by a spring $k_1$ = {{ k1 }}; a second mass
$m_2$ = {{ m2 }} is tied to $m_1$ by a spring $k_2$ = {{ k2 }}. Both slide without
friction. The force $F_0\\cos\\Omega t$ with $F_0$ = {{ F0 }} and $f = \\Omega/2\\pi$ = {{ f }}
acts on $m_2$. In the steady state $x_j = X_j\\cos\\Omega t$ ($x_j$ to the right, from
the position where the springs are relaxed).

1. What are $X_1$ and $X_2$ (with sign: negative means in antiphase with the force)?
2. At which forcing frequency $f_a$ (in Hz) would $m_2$ stand still, for the same masses
   and springs?
""",
    solution=r"""
The undamped chain under harmonic forcing, $\mathbf M\ddot{\mathbf x} + \mathbf K\mathbf x = \mathbf F\cos\Omega t$
(damped and forced multi-DOF vibrations, Section 4.4.3), with
$\mathbf M = \operatorname{diag}(m_1, m_2)$, $K_{11} = k_1 + k_2$, $K_{12} = K_{2 1} = -k_2$,
$K_{2 2} = k_2$ and $\mathbf F = (0, F_0)$. The ansatz $\mathbf x = \mathbf X\cos\Omega t$
turns it into $(\mathbf K - \Omega^2\mathbf M)\mathbf X = \mathbf F$. Here
$\Omega = 2\pi f$ = {{ si.Omega }} rad/s; the natural frequencies, where
$\det(\mathbf K - \Omega^2\mathbf M)$ vanishes, are {{ si.omega1 }} rad/s and
{{ si.omega2 }} rad/s.

1. **Amplitudes.** With $\Delta = (k_1 + k_2 - \Omega^2 m_1)(k_2 - \Omega^2 m_2) - k_2^2$,
   Cramer's rule gives
   $$X_1 = \frac{k_2 F_0}{\Delta},\qquad X_2 = \frac{(k_1 + k_2 - \Omega^2 m_1)\,F_0}{\Delta}:$$
   $X_1$ = {{ answers.X1 }} and $X_2$ = {{ answers.X2 }}.
2. **Anti-resonance of $m_2$.** $X_2 = 0$ where $k_1 + k_2 = \Omega^2 m_1$:
   $$f_a = \frac{1}{2\pi}\sqrt{\frac{k_1 + k_2}{m_1}}$$
   = {{ answers.f_a }}. Then $m_1$, held by both springs, moves so that spring $k_2$ passes
   exactly $-F_0\cos\Omega t$ to $m_2$: $m_1$ acts as a vibration absorber for $m_2$.
   **Check.** For $\Omega \to 0$ both amplitudes tend to the static deflections
   $F_0/k_1$ and $F_0/k_1 + F_0/k_2$.
""",
    solve=solve,
    checks=(
        Recompute("X1", lambda p, s: _cramer(p)[0], name="cramer_x1"),
        Recompute("X2", lambda p, s: _cramer(p)[1], name="cramer_x2"),
        Recompute("f_a", lambda p, s: np.sqrt((p.k1 + p.k2) / p.m1) / (2 * np.pi),
                  name="first_row_vanishes"),
    ),
    figure=figure,
    parts=(
        Numeric("X1", "amplitude X1", question=1, unit="mm", points=1, misconceptions=(
            Misconception("static deflection", lambda p: p.F0 / p.k1,
                          "The masses' inertia matters at Omega: solve (K - Omega^2 M) X = F."),
        )),
        Numeric("X2", "amplitude X2", question=1, unit="mm", points=2, misconceptions=(
            Misconception("m2 alone on k2", _m2_alone,
                          "m1 is not fixed: solve both rows of (K - Omega^2 M) X = F.",
                          applies=_m1_matters),
            Misconception("static deflection", lambda p: p.F0 / p.k1 + p.F0 / p.k2,
                          "The masses' inertia matters at Omega: solve (K - Omega^2 M) X = F."),
        )),
        Numeric("f_a", "anti-resonance frequency of m2", question=2, unit="Hz", points=2,
                misconceptions=(
                    Misconception("m2's own frequency", lambda p: np.sqrt(p.k2 / p.m2) / (2 * np.pi),
                                  "m2 stands still when the row of m1 has no dynamic stiffness: "
                                  "k1 + k2 = Omega^2 m1.",
                                  applies=lambda p: abs(p.k2 * p.m1 / ((p.k1 + p.k2) * p.m2) - 1) > 0.05),
                    Misconception("m1 on k1 only", lambda p: np.sqrt(p.k1 / p.m1) / (2 * np.pi),
                                  "With m2 at rest both springs hold m1: k1 + k2 = Omega^2 m1."),
                    Misconception("omega for f", lambda p: np.sqrt((p.k1 + p.k2) / p.m1),
                                  "f = omega/(2 pi)."),
                )),
    ),
)
