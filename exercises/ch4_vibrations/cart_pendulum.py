"""A pendulum hanging from a cart on a spring: mass and stiffness matrices from the
Lagrange equations and the coupled natural frequencies (Section 4.4.1)."""

from functools import cache

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric, Uniform,
                                per_draw)
from dynagrade.mechanics import multi_dof


@cache
def _linearized():
    """(K, M) as functions of (M, m, L, k, g): the core linearizes T and V about the rest
    position. Derived on first use, not when the exercise is loaded."""
    import sympy as sp

    from dynagrade.mechanics import equilibrium

    t = sp.Symbol("t")
    x, phi = sp.Function("x")(t), sp.Function("phi")(t)
    M, m, L, k, g = sp.symbols("M m L k g", positive=True)
    xb, yb = x + L * sp.sin(phi), -L * sp.cos(phi)          # the bob
    T = M * x.diff(t) ** 2 / 2 + m * (xb.diff(t) ** 2 + yb.diff(t) ** 2) / 2
    V = k * x**2 / 2 + m * g * yb
    rest = {x: 0, phi: 0}
    return (sp.lambdify([M, m, L, k, g], equilibrium.stiffness_matrix(V, [x, phi], rest)),
            sp.lambdify([M, m, L, k, g], equilibrium.linearized_mass_matrix(T, [x, phi], t, rest)))


@per_draw
def matrices(p):
    stiffness, mass = _linearized()
    args = (p.M, p.m, p.L, p.k, p.g)
    return np.array(stiffness(*args), dtype=float), np.array(mass(*args), dtype=float)


def solve(p):
    K, M = matrices(p)
    w = multi_dof.natural_frequencies(K, M)
    return {"M11": M[0, 0], "M12": M[0, 1], "K22": K[1, 1], "omega1": w[0], "omega2": w[1]}


def _apart(p):
    w = multi_dof.natural_frequencies(*matrices(p))
    return all(abs(guess / wi - 1) >= 0.05
               for guess in (np.sqrt(p.k / p.M), np.sqrt(p.g / p.L)) for wi in w)


EXERCISE = Exercise(
    id="cart-pendulum-matrices",
    title="Pendulum on a sprung cart: mass and stiffness matrices",
    source="Section 4.4.1",
    topics=("Lagrange equations", "mass matrix", "stiffness matrix", "coupled vibrations"),
    params=(
        Uniform("M", 1.0, 10.0, step=0.5, unit="kg", symbol="M"),
        Uniform("m", 0.5, 5.0, step=0.1, unit="kg", symbol="m"),
        Uniform("L", 0.2, 1.5, step=0.05, unit="m", symbol="L"),
        Uniform("k", 20, 500, step=5, unit="N/m", symbol="k"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("the pendulum is heavy enough to couple (m >= 0.25 M)", lambda p: p.m >= 0.25 * p.M),
        Constraint("L is not 1 m (else m g and m g L agree)", lambda p: abs(p.L - 1.0) >= 0.05),
        Constraint("the uncoupled guesses are at least 5 % off both frequencies", _apart),
    ),
    statement="""
A cart of mass $M$ = {{ M }} rolls without friction on a horizontal track and is tied to
a wall by a spring of stiffness $k$ = {{ k }}. From the cart hangs a pendulum: a point
mass $m$ = {{ m }} on a massless rod of length $L$ = {{ L }}; $g$ = {{ g }}. Use the
cart's displacement $x$ and the pendulum's angle $\\varphi$ from the vertical as
generalized coordinates.

1. Linearize the Lagrange equations about $x = 0$, $\\varphi = 0$ into
   $\\mathbf M\\ddot{\\mathbf q} + \\mathbf K\\mathbf q = \\mathbf 0$ with $\\mathbf q = (x, \\varphi)$.
   Give the entries $M_{11}$, $M_{12}$ and $K_{22}$.
2. What are the two natural angular frequencies $\\omega_1 < \\omega_2$?
""",
    solve=solve,
    parts=(
        Numeric("M11", "mass matrix entry M11", unit="kg", points=1,
                misconceptions=(Misconception("cart only", lambda p: p.M, "The bob moves with the cart: M11 = M + m."),)),
        Numeric("M12", "mass matrix entry M12", unit="kg*m", points=1,
                misconceptions=(Misconception("uncoupled", lambda p: 0.0,
                                              "The bob's velocity contains x' + L phi' cos(phi): T has the term m L x' phi'."),)),
        Numeric("K22", "stiffness matrix entry K22", unit="N*m", points=1,
                misconceptions=(Misconception("m g", lambda p: p.m * p.g, "V = -m g L cos(phi): K22 = m g L."),)),
        Numeric("omega1", "lower natural frequency", unit="rad/s", points=2,
                misconceptions=(
                    Misconception("uncoupled cart", lambda p: np.sqrt(p.k / p.M), "The two motions are coupled through M12."),
                    Misconception("uncoupled pendulum", lambda p: np.sqrt(p.g / p.L), "The two motions are coupled through M12."),
                )),
        Numeric("omega2", "higher natural frequency", unit="rad/s", points=2,
                misconceptions=(
                    Misconception("uncoupled cart", lambda p: np.sqrt(p.k / p.M), "Solve det(K - omega^2 M) = 0."),
                    Misconception("uncoupled pendulum", lambda p: np.sqrt(p.g / p.L), "Solve det(K - omega^2 M) = 0."),
                )),
    ),
)
