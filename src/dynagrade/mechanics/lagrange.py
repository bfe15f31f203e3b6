"""Lagrange equations of the second kind, Section 4.1 of the notes.

A system with generalized coordinates q = (q_1, ..., q_n) is described by its kinetic
energy T(q, q', t) and potential V(q).  The coordinates are sympy functions of the
time symbol t, e.g. ``theta = sympy.Function("theta")(t)``; T and V are sympy
expressions in them, their time derivatives and the system's parameters.  The
functions below derive the equations of motion

    d/dt (dL/dq_i') - dL/dq_i = Q_i,     L = T - V,

symbolically; Q_i are the generalized forces not derived from V (e.g. dampers).
"""
from __future__ import annotations

from typing import Sequence

import sympy as sp

Coordinates = Sequence[sp.Expr]
"""The generalized coordinates q_i: sympy functions of the time symbol (or plain symbols)."""


def generalized_velocities(q: Coordinates, t: sp.Symbol) -> list[sp.Expr]:
    """Generalized velocities q_i' = d q_i / d t of the coordinates q, Section 4.1."""
    return [sp.diff(qi, t) for qi in q]


def lagrangian(T: sp.Expr, V: sp.Expr) -> sp.Expr:
    """Lagrangian L = T - V, Section 4.1."""
    return T - V


def equations_of_motion(T: sp.Expr, V: sp.Expr, q: Coordinates, t: sp.Symbol,
                        Q: Sequence[sp.Expr] | None = None) -> list[sp.Expr]:
    """Lagrange equations d/dt(dL/dq_i') - dL/dq_i - Q_i = 0, Section 4.1.

    Returns a list of sympy expressions, one per coordinate, each of which vanishes
    on the motion.  ``Q`` optionally lists the non-potential generalized forces.
    """
    L = lagrangian(T, V)
    equations = []
    for i, (qi, qdi) in enumerate(zip(q, generalized_velocities(q, t))):
        e = sp.diff(sp.diff(L, qdi), t) - sp.diff(L, qi)
        if Q is not None:
            e = e - Q[i]
        equations.append(sp.expand(e))
    return equations


def mass_matrix(T: sp.Expr, q: Coordinates, t: sp.Symbol) -> sp.Matrix:
    """Generalized mass matrix M_ij = d^2 T / (dq_i' dq_j'), Section 4.1 (T = q'^T M q' / 2)."""
    qd = generalized_velocities(q, t)
    return sp.Matrix(len(q), len(q), lambda i, j: sp.diff(T, qd[i], qd[j]))


def generalized_forces(V: sp.Expr, q: Coordinates, Q: Sequence[sp.Expr] | None = None) -> sp.Matrix:
    """Generalized forces Q_i = -dV/dq_i (+ non-potential Q_i), Section 4.1."""
    forces = [-sp.diff(V, qi) for qi in q]
    if Q is not None:
        forces = [f + Qi for f, Qi in zip(forces, Q)]
    return sp.Matrix(forces)


def dissipative_forces(D: sp.Expr, q: Coordinates, t: sp.Symbol) -> list[sp.Expr]:
    """Generalized damping forces Q_i = -dD/dq_i' of a dissipation function D, Section 4.1.

    For dampers of coefficient c_j whose elongation rate is u_j', D = sum c_j u_j'^2 / 2.
    """
    return [-sp.diff(D, qd) for qd in generalized_velocities(q, t)]


def accelerations(T: sp.Expr, V: sp.Expr, q: Coordinates, t: sp.Symbol,
                  Q: Sequence[sp.Expr] | None = None) -> list[sp.Expr]:
    """Generalized accelerations q'' solved from the Lagrange equations, Section 4.1.

    Returns a list of sympy expressions for q_i'' in terms of q, q' and the parameters.
    """
    eqs = sp.Matrix(equations_of_motion(T, V, q, t, Q))
    qdd = [sp.diff(qi, t, 2) for qi in q]
    A = eqs.jacobian(qdd)
    rest = eqs.subs({a: 0 for a in qdd})
    solution = A.LUsolve(-rest)
    return [sp.simplify(s) for s in solution]


def effective_potential(T: sp.Expr, V: sp.Expr, q: Coordinates, t: sp.Symbol) -> sp.Expr:
    """Effective potential V* = V - T_0, Section 4.1 (used for equilibria in Section 4.2).

    T_0 is the part of T that does not depend on the generalized velocities (e.g. the
    kinetic energy of a prescribed rotation of the frame); for T = T_2 + T_0 the
    equations of motion are those of kinetic energy T_2 and potential V - T_0.
    """
    T0 = T.subs({qd: 0 for qd in generalized_velocities(q, t)})
    return sp.simplify(V - T0)


def state_symbols(q: Coordinates) -> tuple[list[sp.Symbol], list[sp.Symbol], list[sp.Symbol]]:
    """Plain sympy symbols (q_i, q_i', q_i'') standing for the coordinates, their rates and
    accelerations, named e.g. theta, theta_dot, theta_ddot (for lambdify), Section 4.1."""
    # A plain Symbol has a ``func`` too (the class Symbol): name it by itself, and a
    # coordinate q(t) by its function's name.
    names = [qi.name if isinstance(qi, sp.Symbol) else qi.func.__name__ for qi in q]
    pos = [sp.Symbol(n, real=True) for n in names]
    vel = [sp.Symbol(n + "_dot", real=True) for n in names]
    acc = [sp.Symbol(n + "_ddot", real=True) for n in names]
    return pos, vel, acc


def in_state_symbols(expr: sp.Expr, q: Coordinates, t: sp.Symbol) -> sp.Expr:
    """The expression ``expr`` with q_i'', q_i' and q_i(t) replaced by plain symbols of
    :func:`state_symbols` (highest derivatives first), Section 4.1."""
    pos, vel, acc = state_symbols(q)
    rules = {}
    for qi, p, v, a in zip(q, pos, vel, acc):
        rules[sp.diff(qi, t, 2)] = a
    out = expr.subs(rules)
    out = out.subs({sp.diff(qi, t): v for qi, v in zip(q, vel)})
    return out.subs({qi: p for qi, p in zip(q, pos)})
