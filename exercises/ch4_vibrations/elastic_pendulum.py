"""The elastic (spring) pendulum: Lagrange equations in polar coordinates, the static
equilibrium and the two linearized natural frequencies (Sections 4.1 and 4.2)."""

from functools import cache
from types import SimpleNamespace

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric, Symbolic,
                                Uniform, Variable, per_draw)
from dynagrade.exercise.checks import Recompute
from dynagrade.mechanics import multi_dof


@cache
def _model():
    """T and V in polar coordinates, derived by the core on first use (not at load):
    ``r_static``, ``K`` and ``M`` are functions of (m, k, L0, g)."""
    import sympy as sp

    from dynagrade.mechanics import equilibrium

    t = sp.Symbol("t")
    r, phi = sp.Function("r")(t), sp.Function("phi")(t)
    m, k, L0, g = sp.symbols("m k L0 g", positive=True)
    T = m * (r.diff(t) ** 2 + r**2 * phi.diff(t) ** 2) / 2
    V = k * (r - L0) ** 2 / 2 - m * g * r * sp.cos(phi)
    # the hanging equilibrium: phi = 0 and the r that makes dV/dr vanish
    r_static = [e for e in equilibrium.equilibrium_positions(V.subs(phi, 0), [r])][0][r]
    at_rest = {r: r_static, phi: 0}
    return SimpleNamespace(
        t=t, q=[r, phi], T=T, V=V,
        r_static=sp.lambdify([m, k, L0, g], r_static),
        K=sp.lambdify([m, k, L0, g], equilibrium.stiffness_matrix(V, [r, phi], at_rest)),
        M=sp.lambdify([m, k, L0, g], equilibrium.linearized_mass_matrix(T, [r, phi], t, at_rest)))


def accelerations():
    """(r'', phi'') in state symbols, as the core derives them with the Lagrange equations
    (tests hold the statement's formula against the radial one)."""
    from dynagrade.mechanics import lagrange

    model = _model()
    return [lagrange.in_state_symbols(a, model.q, model.t)
            for a in lagrange.accelerations(model.T, model.V, model.q, model.t)]


@per_draw
def frequencies(p):
    """(omega of the stretching mode, omega of the swinging mode) from the linearization."""
    model = _model()
    K = np.array(model.K(p.m, p.k, p.L0, p.g), dtype=float)
    M = np.array(model.M(p.m, p.k, p.L0, p.g), dtype=float)
    # the matrices are diagonal: identify the modes by their coordinate
    w = multi_dof.natural_frequencies(K, M)
    shapes = multi_dof.mode_shapes(K, M)
    radial = int(np.argmax(np.abs(shapes[0, :])))
    return w[radial], w[1 - radial]


def solve(p):
    w_r, w_phi = frequencies(p)
    return {"r_static": _model().r_static(p.m, p.k, p.L0, p.g), "omega_r": w_r, "omega_phi": w_phi}


_VARS = {"r": Variable(0.2, 3, "m"), "phi": Variable(-3, 3, "rad"), "rdot": Variable(-3, 3, "m/s"),
         "phidot": Variable(-3, 3, "rad/s"), "m": None, "k": None, "L0": None, "g": None}

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
    checks=(
        # at rest the spring carries the weight: k (r - L0) = m g (Section 4.1)
        Recompute("r_static", lambda p, s: p.L0 + p.m * p.g / p.k, name="static_stretch"),
        # about the rest position the two motions decouple: a spring-mass oscillator and a
        # pendulum of length r_static
        Recompute("omega_r", lambda p, s: np.sqrt(p.k / p.m), name="spring_mode"),
        Recompute("omega_phi", lambda p, s: np.sqrt(p.g / (p.L0 + p.m * p.g / p.k)),
                  name="pendulum_mode"),
    ),
    parts=(
        Symbolic("r_ddot", "radial acceleration", question=1, points=2,
                 expected="r*phidot^2 - k/m*(r - L0) + g*cos(phi)", variables=_VARS,
                 misconceptions=(
                     Misconception("centripetal term missing", "-k/m*(r - L0) + g*cos(phi)",
                                   "dT/dr = m r phi'^2: the radial equation keeps r phi'^2."),
                     Misconception("spring force with r instead of r - L0", "r*phidot^2 - k/m*r + g*cos(phi)",
                                   "The spring is stretched by r - L0, not by r."),
                 )),
        Numeric("r_static", "static distance", question=2, unit="m", points=1,
                misconceptions=(Misconception("unstretched length", lambda p: p.L0,
                                              "The weight stretches the spring by m g / k."),)),
        Numeric("omega_r", "frequency of the stretching mode", question=3, unit="rad/s", points=1,
                misconceptions=(Misconception("f for omega", lambda p: frequencies(p)[0] / (2 * np.pi),
                                              "omega is in rad/s; f = omega/(2 pi)."),)),
        Numeric("omega_phi", "frequency of the swinging mode", question=3, unit="rad/s", points=2,
                misconceptions=(
                    Misconception("unstretched length as pendulum length", lambda p: np.sqrt(p.g / p.L0),
                                  "The pendulum swings about the stretched length r_s = L0 + m g/k."),
                    Misconception("f for omega", lambda p: frequencies(p)[1] / (2 * np.pi),
                                  "omega is in rad/s; f = omega/(2 pi)."),
                )),
    ),
)
