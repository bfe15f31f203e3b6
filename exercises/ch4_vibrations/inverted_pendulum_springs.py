"""An inverted pendulum held upright by two springs: stability of the upright position
and the frequency of small oscillations (Section 4.2)."""

from functools import cache

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric,
                                Symbolic, Uniform, Variable)
from dynagrade.exercise.checks import Recompute


@cache
def _upright():
    """(k_min of (m, L, a, g), omega^2 of (m, L, a, k, g)) about the upright position,
    derived by the core on first use (not at load)."""
    import sympy as sp

    from dynagrade.mechanics import equilibrium, inertia

    t = sp.Symbol("t")
    theta = sp.Function("theta")(t)
    m, L, a, k, g = sp.symbols("m L a k g", positive=True)
    # uniform rod pivoted at its lower end (J = m L^2 / 3 by Steiner), two horizontal
    # springs at height a
    J = inertia.parallel_axis_moment(inertia.inertia_tensor_rod(m, L)[0, 0], m, L / 2)
    T = J * theta.diff(t) ** 2 / 2
    V = m * g * L / 2 * sp.cos(theta) + 2 * k * (a * sp.sin(theta)) ** 2 / 2
    k_upright = equilibrium.stiffness_matrix(V, [theta], {theta: 0})[0, 0]
    return (sp.lambdify([m, L, a, g], sp.solve(sp.Eq(k_upright, 0), k)[0]),
            sp.lambdify([m, L, a, k, g],
                        equilibrium.linearized_frequency_squared(T, V, [theta], t, {theta: 0})))


def omega(p):
    omega_squared = _upright()[1]
    return float(np.sqrt(omega_squared(p.m, p.L, p.a_frac * p.L, p.k, p.g)))


def solve(p):
    k_min = _upright()[0]
    return {"k_min": k_min(p.m, p.L, p.a_frac * p.L, p.g), "omega": omega(p),
            "a": p.a_frac * p.L}


def _curvature(p):
    """V = m g (L/2) cos(theta) + 2 k (a sin(theta))^2 / 2, so V''(0) = 2 k a^2 - m g L / 2
    (Section 4.2)."""
    a = p.a_frac * p.L
    return 2 * p.k * a**2 - p.m * p.g * p.L / 2


EXERCISE = Exercise(
    id="inverted-pendulum-springs",
    title="Inverted pendulum on springs: stability and small oscillations",
    source="Section 4.2",
    topics=("equilibrium", "stability", "potential energy", "linearization"),
    params=(
        Uniform("m", 0.5, 10.0, step=0.5, unit="kg", symbol="m"),
        Uniform("L", 0.5, 2.0, step=0.1, unit="m", symbol="L"),
        Uniform("a_frac", 0.3, 1.0, step=0.05, symbol="a/L"),
        Uniform("k", 50, 2000, step=10, unit="N/m", symbol="k"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("the springs hold the rod upright with a margin of 30 %",
                   lambda p: p.k >= 1.3 * p.m * p.g * p.L / (4 * (p.a_frac * p.L) ** 2)),
        Constraint("gravity lowers omega^2 by at least 6 %",
                   lambda p: p.m * p.g * p.L / 2 >= 0.06 * 2 * p.k * (p.a_frac * p.L) ** 2),
    ),
    statement="""
A uniform rod of mass $m$ = {{ m }} and length $L$ = {{ L }} stands upright on a
frictionless pin at its lower end. Two identical horizontal springs of stiffness
$k$ = {{ k }}, one on each side, are attached to the rod at the height
$a = {{ a_frac.value }}\\,L$ above the pin; they are relaxed when the rod is upright and
stay horizontal. Let $\\theta$ be the rod's angle from the vertical; $g$ = {{ g }}.

1. Write the potential energy $V(\\theta)$ as an expression in `theta`, `m`, `g`, `L`, `k`, `a`,
   with the zero level of gravity's potential at the pin (an additive constant does not
   matter and is not graded).
2. Which spring stiffness $k_{\\min}$ is at least needed for the upright position to be stable?
3. With the given springs, what is the angular frequency of small oscillations about the upright position?
""",
    solution=r"""
One degree of freedom, $\theta$: the upright position is an equilibrium, stable when the
potential energy has a minimum there, and the small oscillations follow from
$J\ddot\theta + V''(0)\,\theta = 0$ (equilibrium and stability, Section 4.2).

1. **Potential energy.** The centre of mass is at height $\tfrac{L}{2}\cos\theta$; each
   spring is stretched (or compressed) by $a\sin\theta$:
   $$V(\theta) = \frac{m g L}{2}\cos\theta + 2\cdot\tfrac{1}{2} k\,(a\sin\theta)^2,$$
   written as `{{ answers.V }}`.
2. **Smallest stiffness.** $V'(0) = 0$, and
   $$V''(0) = 2 k a^2 - \frac{m g L}{2}$$
   must be positive: gravity destabilises, the springs stabilise. So
   $$k_{\min} = \frac{m g L}{4 a^2};$$
   with $m$ = {{ m }}, $L$ = {{ L }}, $a$ = {{ si.a }} m and $g$ = {{ g }}:
   $k_{\min}$ = {{ answers.k_min }}.
3. **Small oscillations.** The rod turns about its end, $J = \tfrac{1}{3} m L^2$, and with
   $k$ = {{ k }}
   $$\omega = \sqrt{\frac{V''(0)}{J} } = \sqrt{\frac{2 k a^2 - m g L/2}{m L^2/3} },$$
   that is $\omega$ = {{ answers.omega }}.
""",
    solve=solve,
    checks=(
        Recompute("k_min", lambda p, s: p.m * p.g * p.L / (4 * (p.a_frac * p.L) ** 2),
                  name="zero_curvature"),
        # about the pin the rod's moment of inertia is m L^2 / 3
        Recompute("omega", lambda p, s: np.sqrt(_curvature(p) / (p.m * p.L**2 / 3)),
                  name="curvature_over_inertia"),
    ),
    parts=(
        Symbolic("V", "potential energy", question=1, points=1, up_to_constant=("theta",),
                 expected="m*g*L/2*cos(theta) + k*a^2*sin(theta)^2",
                 variables={"theta": Variable(-1.5, 1.5, "rad"), "m": None, "g": None, "L": None,
                            "k": None, "a": Variable(0.1, 3, "m")},
                 misconceptions=(Misconception("one spring only", "m*g*L/2*cos(theta) + k*a^2*sin(theta)^2/2",
                                               "Both springs are stretched (one compressed) by a sin(theta)."),)),
        Numeric("k_min", "minimum spring stiffness", question=2, unit="N/m", points=2,
                misconceptions=(
                    Misconception("one spring only", lambda p: p.m * p.g * p.L / (2 * (p.a_frac * p.L) ** 2),
                                  "Each of the two springs adds k a^2 to V''(0)."),
                )),
        Numeric("omega", "angular frequency of small oscillations", question=3,
                unit="rad/s", points=2,
                misconceptions=(
                    Misconception("gravity forgotten", lambda p: np.sqrt(2 * p.k * (p.a_frac * p.L) ** 2 / (p.m * p.L**2 / 3)),
                                  "Gravity destabilizes: V''(0) = 2 k a^2 - m g L/2."),
                    Misconception("point-mass inertia m L^2",
                                  lambda p: np.sqrt((2 * p.k * (p.a_frac * p.L) ** 2 - p.m * p.g * p.L / 2) / (p.m * p.L**2)),
                                  "The rod's moment of inertia about its end is m L^2 / 3."),
                    Misconception("f for omega", lambda p: omega(p) / (2 * np.pi), "omega is in rad/s; f = omega/(2 pi)."),
                )),
    ),
)
