"""Mechanical equilibrium, stability and linearization, Section 4.2 of the notes.

Equilibria of a conservative system are the stationary points of its potential V(q)
(grad V = 0); an equilibrium is stable when the Hessian of V there (the stiffness
matrix of the linearized system) is positive definite (Lagrange-Dirichlet).
Linearizing about an equilibrium q* gives M(q*) dq'' + K dq = 0 with the mass
matrix of Section 4.1 and K = Hessian of V at q*.

Coordinates are sympy functions of t or plain symbols (as in :mod:`lagrange`).
"""
from __future__ import annotations

import numpy as np
import sympy as sp

from dynagrade.mechanics import lagrange
from dynagrade.mechanics._common import Function, Quantity
from dynagrade.mechanics.lagrange import Coordinates


def _plain(q):
    """Dummy symbols standing for the coordinates q, and the substitution to them."""
    dummies = [sp.Dummy(f"q{i}", real=True) for i in range(len(q))]
    return dummies, dict(zip(q, dummies))


def equilibrium_conditions(V: sp.Expr, q: Coordinates) -> list[sp.Expr]:
    """Equilibrium conditions dV/dq_i = 0 as the list of the derivatives dV/dq_i, Section 4.2."""
    return [sp.diff(V, qi) for qi in q]


def equilibrium_positions(V: sp.Expr, q: Coordinates) -> list[dict[sp.Expr, sp.Expr]]:
    """Equilibrium positions from dV/dq = 0 (as sympy solves it), as dicts {q_i: value}, Section 4.2.

    Angles are returned within one period as sympy reports them (e.g. 0 and pi).
    """
    dummies, to_dummy = _plain(q)
    conditions = [c.subs(to_dummy) for c in equilibrium_conditions(V, q)]
    back = dict(zip(dummies, q))
    if len(q) == 1:
        # one coordinate: solve factor by factor (sympy.solve on the product can miss
        # roots of trigonometric factors such as sin(theta) = 0 at theta = pi)
        _, factors = sp.factor_list(sp.factor(sp.expand_trig(conditions[0])))
        values = []
        for f, _ in factors:
            if f.has(dummies[0]):
                values += [v for v in sp.solve(f, dummies[0]) if v not in values]
        return [{q[0]: v} for v in values]
    solutions = sp.solve(conditions, dummies, dict=True)
    return [{back[d]: value for d, value in sol.items()} for sol in solutions]


def equilibrium_positions_in_interval(dV_dq: Function, a: float, b: float,
                                      samples: int = 2001) -> list[float]:
    """Roots of a 1-DOF equilibrium condition dV/dq (a callable) on [a, b], Section 4.2.

    Bracketed by sign changes on ``samples`` grid points and refined with brentq.
    """
    from scipy.optimize import brentq
    grid = np.linspace(a, b, samples)
    values = np.array([dV_dq(x) for x in grid])
    roots = [float(x) for x, v in zip(grid, values) if v == 0.0]
    for x0, x1, v0, v1 in zip(grid[:-1], grid[1:], values[:-1], values[1:]):
        if v0 * v1 < 0.0:
            roots.append(brentq(dV_dq, x0, x1, xtol=1e-14))
    return sorted(roots)


def stiffness_matrix(V: sp.Expr, q: Coordinates, q_eq: dict[sp.Expr, sp.Expr]) -> sp.Matrix:
    """Stiffness matrix K_ij = d^2 V / (dq_i dq_j) at the equilibrium q_eq (dict), Section 4.2."""
    dummies, to_dummy = _plain(q)
    Vd = V.subs(to_dummy)
    H = sp.hessian(Vd, dummies)
    return sp.simplify(H.subs({to_dummy[k]: v for k, v in q_eq.items()}))


def linearized_mass_matrix(T: sp.Expr, q: Coordinates, t: sp.Symbol,
                           q_eq: dict[sp.Expr, sp.Expr]) -> sp.Matrix:
    """Mass matrix M(q_eq) of the equations linearized about the equilibrium q_eq, Section 4.2."""
    M = lagrange.mass_matrix(T, q, t)
    return sp.simplify(M.subs(q_eq))


def stability(K: Quantity, tol: float = 1e-12) -> str:
    """Stability of an equilibrium from its (numeric) stiffness matrix K, Section 4.2.

    "stable" if K is positive definite, "unstable" if it has a negative eigenvalue,
    "undecided" if its smallest eigenvalue vanishes (higher derivatives decide).
    """
    K = np.atleast_2d(np.asarray(K, dtype=float))
    eig = np.linalg.eigvalsh(0.5 * (K + K.T))
    scale = max(1.0, float(np.max(np.abs(eig))))
    if np.min(eig) > tol * scale:
        return "stable"
    if np.min(eig) < -tol * scale:
        return "unstable"
    return "undecided"


def linearized_frequency_squared(T: sp.Expr, V: sp.Expr, q: Coordinates, t: sp.Symbol,
                                 q_eq: dict[sp.Expr, sp.Expr]) -> sp.Expr:
    """Square omega^2 = K/M of the small-oscillation frequency of a 1-DOF system about q_eq, Section 4.2."""
    K = stiffness_matrix(V, q, q_eq)[0, 0]
    M = linearized_mass_matrix(T, q, t, q_eq)[0, 0]
    return sp.simplify(K / M)

