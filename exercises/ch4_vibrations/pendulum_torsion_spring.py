"""A pendulum with a torsional spring at its pivot: equation of motion by Lagrange and the
linearized natural frequency (Section 4.1)."""

from functools import cache

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric,
                                Symbolic, Uniform, Variable)
from dynagrade.exercise.checks import Integrated, Recompute
from dynagrade.mechanics import vibrations


@cache
def _system():
    """(t, theta, T, V): the system as the statement gives it, in the angle theta."""
    import sympy as sp

    t = sp.Symbol("t")
    theta = sp.Function("theta")(t)
    m, L, g, kt = sp.symbols("m L g kt", positive=True)
    return t, theta, m * L**2 * theta.diff(t) ** 2 / 2, -m * g * L * sp.cos(theta) + kt * theta**2 / 2


def acceleration():
    """theta'' as the core derives it with the Lagrange equations (tests hold the
    statement's formula against it)."""
    from dynagrade.mechanics import lagrange

    t, theta, T, V = _system()
    return lagrange.in_state_symbols(lagrange.accelerations(T, V, [theta], t)[0], [theta], t)


@cache
def _omega_squared():
    """omega^2 of (m, L, g, kt), linearized by the core about theta = 0 on first use."""
    import sympy as sp

    from dynagrade.mechanics import equilibrium

    t, theta, T, V = _system()
    m, L, g, kt = sp.symbols("m L g kt", positive=True)
    return sp.lambdify([m, L, g, kt],
                       equilibrium.linearized_frequency_squared(T, V, [theta], t, {theta: 0}))


def omega(p):
    return float(np.sqrt(_omega_squared()(p.m, p.L, p.g, p.kt)))


def solve(p):
    w = omega(p)
    return {"omega": w, "f": vibrations.frequency_in_hertz(w), "T_period": vibrations.period(w)}


# theta is no parameter; the parameters take their own units and (widened) ranges
_VARS = {"theta": Variable(-3, 3, "rad"), "m": None, "L": None, "g": None, "kt": None}

def _swing(t, y, p):
    """m L^2 theta'' = -k_t theta - m g L sin(theta) (Section 4.1)."""
    return (y[1], -(p.kt * y[0] + p.m * p.g * p.L * np.sin(y[0])) / (p.m * p.L**2))


EXERCISE = Exercise(
    id="pendulum-torsion-spring-lagrange",
    title="Pendulum with a torsional spring: Lagrange equation and linearized frequency",
    source="Section 4.1",
    topics=("Lagrange equations", "linearization", "natural frequency"),
    params=(
        Uniform("m", 0.2, 5.0, step=0.1, unit="kg", symbol="m"),
        Uniform("L", 0.3, 2.0, step=0.05, unit="m", symbol="L"),
        Uniform("kt", 0.5, 40.0, step=0.5, unit="N*m", symbol="k_t"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        # the spring must matter: forgetting it (omega^2 = g/L) is then more than 3 % off
        Constraint("the spring adds at least 6 % to omega^2",
                   lambda p: p.kt / (p.m * p.L**2) >= 0.06 * p.g / p.L),
        Constraint("gravity adds at least 6 % to omega^2",
                   lambda p: p.g / p.L >= 0.06 * p.kt / (p.m * p.L**2)),
    ),
    statement="""
A point mass $m$ = {{ m }} sits at the end of a massless rod of length $L$ = {{ L }} that
swings in a vertical plane about a frictionless pivot. A torsional spring of stiffness
$k_t$ = {{ kt }} (per radian) at the pivot is relaxed when the rod hangs straight down.
Let $\\theta$ be the angle of the rod from the downward vertical; $g$ = {{ g }}.

1. Write the kinetic and potential energy, derive the equation of motion with the
   Lagrange equations and give the angular acceleration $\\ddot\\theta$ as an expression
   in `theta`, `m`, `L`, `g` and `kt` (valid for large angles).
2. Linearize about $\\theta = 0$: what is the natural angular frequency $\\omega$?
3. What is the natural frequency $f$ in Hz, and the period of small oscillations?
4. Give $\\omega$ of question 2 as a formula in `m`, `L`, `g` and `kt`.
""",
    solution=r"""
One generalized coordinate, $\theta$: Lagrange's equation
$\frac{d}{dt}\frac{\partial T}{\partial\dot\theta} - \frac{\partial T}{\partial\theta}
+ \frac{\partial V}{\partial\theta} = 0$ (Section 4.1), then the linearisation about the
hanging position.

1. **Equation of motion.** The mass moves on a circle of radius $L$; gravity and the
   torsional spring both store energy:
   $$T = \tfrac{1}{2} m L^2\dot\theta^2,\qquad V = -m g L\cos\theta + \tfrac{1}{2} k_t\theta^2 .$$
   Lagrange's equation gives $m L^2\ddot\theta + m g L\sin\theta + k_t\theta = 0$, so
   $$\ddot\theta = -\frac{g}{L}\sin\theta - \frac{k_t\,\theta}{m L^2},$$
   written as `{{ answers.theta_ddot }}`.
2. **Natural angular frequency.** For small angles $\sin\theta \approx \theta$:
   $\ddot\theta + \bigl(\frac gL + \frac{k_t}{m L^2}\bigr)\theta = 0$, so
   $$\omega = \sqrt{\frac{g}{L} + \frac{k_t}{m L^2} }$$
   (`{{ answers.omega_formula }}`). With $m$ = {{ m }}, $L$ = {{ L }}, $k_t$ = {{ kt }} and
   $g$ = {{ g }}: $\omega$ = {{ answers.omega }}.
3. **Frequency and period.** $f = \omega/(2\pi)$ = {{ answers.f }} and
   $T = 2\pi/\omega$ = {{ answers.T_period }}.
4. **Formula.** $\omega = \sqrt{g/L + k_t/(mL^2)}$, written as `{{ answers.omega_formula }}`.
""",
    solve=solve,
    checks=(
        # released from rest at 0.01 rad: back at rest one period later (the amplitude
        # changes the period by less than 1e-5)
        Integrated("T_period", _swing, lambda p: (0.01, 0.0),
                   lambda p, s: 3 * s["T_period"], lambda t, y, p: t,
                   name="integrated_small_swing", event=lambda t, y, p: y[1], direction=-1,
                   rtol=1e-4),
        Recompute("omega", lambda p, s: np.sqrt((p.kt + p.m * p.g * p.L) / (p.m * p.L**2)),
                  name="linearized_by_hand"),
    ),
    parts=(
        Symbolic("theta_ddot", "angular acceleration", question=1, points=2,
                 expected="-g/L*sin(theta) - kt*theta/(m*L^2)", variables=_VARS,
                 misconceptions=(
                     Misconception("linearized too early", "-g/L*theta - kt*theta/(m*L^2)",
                                   "The equation of motion holds for large angles: keep sin(theta)."),
                     Misconception("spring torque not divided by the inertia", "-g/L*sin(theta) - kt*theta",
                                   "d/dt(dT/dtheta') = m L^2 theta'': divide every torque by m L^2."),
                 )),
        Numeric("omega", "natural angular frequency", question=2, unit="rad/s", points=2,
                misconceptions=(
                    Misconception("spring forgotten", lambda p: np.sqrt(p.g / p.L),
                                  "The torsional spring adds k_t/(m L^2) to omega^2."),
                    Misconception("gravity forgotten", lambda p: np.sqrt(p.kt / (p.m * p.L**2)),
                                  "Gravity also restores: -m g L sin(theta) linearizes to -m g L theta."),
                    Misconception("f for omega", lambda p: omega(p) / (2 * np.pi),
                                  "omega is in rad/s; f = omega/(2 pi) is in Hz."),
                )),
        Numeric("f", "natural frequency", question=3, unit="Hz", points=1,
                misconceptions=(Misconception("omega for f", omega,
                                              "f = omega/(2 pi): a frequency in Hz counts cycles per second."),)),
        Numeric("T_period", "period", question=3, unit="s", points=1,
                misconceptions=(Misconception("1/omega for the period", lambda p: 1 / omega(p),
                                              "The period is 2 pi / omega."),)),
        Symbolic("omega_formula", "omega as a formula", question=4, points=1,
                 expected="sqrt(g/L + kt/(m*L^2))", variables=("m", "L", "g", "kt"),
                 equals="omega"),
    ),
)

