"""The elastic (spring) pendulum: Lagrange equations in polar coordinates, the static
equilibrium and the two linearized natural frequencies (Sections 4.1 and 4.2)."""

import numpy as np
import sympy as sp

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric,
                                Symbolic, Uniform, Variable)
from dynagrade.mechanics import equilibrium, lagrange, multi_dof

_t = sp.Symbol("t")
_r, _phi = sp.Function("r")(_t), sp.Function("phi")(_t)
_m, _k, _L0, _g = sp.symbols("m k L0 g", positive=True)
_T = _m * (_r.diff(_t) ** 2 + _r**2 * _phi.diff(_t) ** 2) / 2
_V = _k * (_r - _L0) ** 2 / 2 - _m * _g * _r * sp.cos(_phi)
# the radial equation of motion as the core derives it (tests hold the statement's formula against it)
ACCELERATIONS = [lagrange.in_state_symbols(a, [_r, _phi], _t)
                 for a in lagrange.accelerations(_T, _V, [_r, _phi], _t)]
# the hanging equilibrium: phi = 0 and the r that makes dV/dr vanish
_EQ = [e for e in equilibrium.equilibrium_positions(_V.subs(_phi, 0), [_r])][0][_r]
_R_STATIC = sp.lambdify([_m, _k, _L0, _g], _EQ)
_Q_EQ = {_r: _EQ, _phi: 0}
_K = sp.lambdify([_m, _k, _L0, _g], equilibrium.stiffness_matrix(_V, [_r, _phi], _Q_EQ))
_M = sp.lambdify([_m, _k, _L0, _g], equilibrium.linearized_mass_matrix(_T, [_r, _phi], _t, _Q_EQ))


def frequencies(p):
    """(omega of the stretching mode, omega of the swinging mode) from the linearization."""
    K = np.array(_K(p.m, p.k, p.L0, p.g), dtype=float)
    M = np.array(_M(p.m, p.k, p.L0, p.g), dtype=float)
    # the matrices are diagonal: identify the modes by their coordinate
    w = multi_dof.natural_frequencies(K, M)
    shapes = multi_dof.mode_shapes(K, M)
    radial = int(np.argmax(np.abs(shapes[0, :])))
    return w[radial], w[1 - radial]


def solve(p):
    w_r, w_phi = frequencies(p)
    return {"r_static": _R_STATIC(p.m, p.k, p.L0, p.g), "omega_r": w_r, "omega_phi": w_phi}


_VARS = {"r": Variable(0.2, 3, "m"), "phi": Variable(-3, 3, "rad"), "rdot": Variable(-3, 3, "m/s"),
         "phidot": Variable(-3, 3, "rad/s"), "m": Variable(0.1, 10, "kg"), "k": Variable(1, 1000, "N/m"),
         "L0": Variable(0.1, 2, "m"), "g": Variable(1, 20, "m/s^2")}

EXERCISE = Exercise(
    id="elastic-pendulum-lagrange",
    title="The spring pendulum: Lagrange equations and small oscillations",
    source="Section 4.1",
    topics=("Lagrange equations", "polar coordinates", "equilibrium", "linearization"),
    params=(
        Uniform("m", 0.2, 3.0, step=0.1, unit="kg", symbol="m"),
        Uniform("k", 20, 400, step=5, unit="N/m", symbol="k"),
        Uniform("L0", 0.2, 1.5, step=0.05, unit="m", symbol="L_0"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        # the static stretch must be visible: using L0 for the pendulum length is then > 3 % off
        Constraint("the static stretch is at least 8 % of L0", lambda p: p.m * p.g / p.k >= 0.08 * p.L0),
        Constraint("the two frequencies differ by at least 10 %",
                   lambda p: abs(np.divide(*frequencies(p)) - 1) >= 0.1),
    ),
    statement="""
A particle of mass $m$ = {{ m }} hangs from a fixed point O on a massless linear spring of
stiffness $k$ = {{ k }} and unstretched length $L_0$ = {{ L0 }}, and moves in a vertical
plane. Describe it by the polar coordinates $r$ (distance from O) and $\\varphi$ (angle
from the downward vertical); $g$ = {{ g }}.

1. Derive the Lagrange equations and give the radial acceleration $\\ddot r$ as an
   expression in `r`, `phi`, `rdot`, `phidot`, `m`, `k`, `L0`, `g`.
2. At what distance $r_s$ from O does the particle hang at rest?
3. Linearize about this equilibrium. What are the natural angular frequencies of the
   stretching mode ($\\omega_r$) and of the swinging mode ($\\omega_\\varphi$)?
""",
    solution=r"""
A holonomic system with the two coordinates $r$, $\varphi$: Lagrange's equations from
$T$ and $V$, the equilibrium where $\partial V/\partial q = 0$, and the linearisation about
it (Section 4.1; equilibrium and linearisation, Section 4.2).

1. **Lagrange equations.** In polar coordinates
   $$T = \tfrac{1}{2} m\bigl(\dot r^2 + r^2\dot\varphi^2\bigr),\qquad
   V = \tfrac{1}{2} k (r - L_0)^2 - m g r\cos\varphi .$$
   For $r$: $\frac{d}{dt}\frac{\partial T}{\partial\dot r} - \frac{\partial T}{\partial r}
   + \frac{\partial V}{\partial r} = m\ddot r - m r\dot\varphi^2 + k(r - L_0) - m g\cos\varphi = 0$;
   for $\varphi$: $m r^2\ddot\varphi + 2 m r\dot r\dot\varphi + m g r\sin\varphi = 0$. The
   radial acceleration is
   $$\ddot r = r\dot\varphi^2 - \frac{k}{m}(r - L_0) + g\cos\varphi,$$
   written as `{{ answers.r_ddot }}`.
2. **Static equilibrium.** At rest with $\varphi = 0$: $k(r_s - L_0) = m g$, so
   $$r_s = L_0 + \frac{m g}{k};$$
   with $m$ = {{ m }}, $k$ = {{ k }}, $L_0$ = {{ L0 }} and $g$ = {{ g }}: $r_s$ = {{ answers.r_static }}.
3. **Small oscillations.** About $(r_s, 0)$ the mass matrix is
   $\operatorname{diag}(m,\; m r_s^2)$ and the stiffness matrix
   $\operatorname{diag}(k,\; m g r_s)$: the two motions decouple. Hence
   $$\omega_r = \sqrt{\frac{k}{m} },\qquad \omega_\varphi = \sqrt{\frac{g}{r_s} },$$
   that is $\omega_r$ = {{ answers.omega_r }} and $\omega_\varphi$ = {{ answers.omega_phi }}
   — a pendulum of the stretched length $r_s$, not of $L_0$.
""",
    solve=solve,
    parts=(
        Symbolic("r_ddot", "radial acceleration", points=2,
                 expected="r*phidot^2 - k/m*(r - L0) + g*cos(phi)", variables=_VARS,
                 misconceptions=(
                     Misconception("centripetal term missing", "-k/m*(r - L0) + g*cos(phi)",
                                   "dT/dr = m r phi'^2: the radial equation keeps r phi'^2."),
                     Misconception("spring force with r instead of r - L0", "r*phidot^2 - k/m*r + g*cos(phi)",
                                   "The spring is stretched by r - L0, not by r."),
                 )),
        Numeric("r_static", "static distance", unit="m", points=1,
                misconceptions=(Misconception("unstretched length", lambda p: p.L0,
                                              "The weight stretches the spring by m g / k."),)),
        Numeric("omega_r", "frequency of the stretching mode", unit="rad/s", points=1,
                misconceptions=(Misconception("f for omega", lambda p: frequencies(p)[0] / (2 * np.pi),
                                              "omega is in rad/s; f = omega/(2 pi)."),)),
        Numeric("omega_phi", "frequency of the swinging mode", unit="rad/s", points=2,
                misconceptions=(
                    Misconception("unstretched length as pendulum length", lambda p: np.sqrt(p.g / p.L0),
                                  "The pendulum swings about the stretched length r_s = L0 + m g/k."),
                    Misconception("f for omega", lambda p: frequencies(p)[1] / (2 * np.pi),
                                  "omega is in rad/s; f = omega/(2 pi)."),
                )),
    ),
)
