"""A block rocking without slipping on top of a fixed horizontal cylinder: its potential
energy, the stability of the upright position and the rate of small motions about it
(Section 4.2)."""

from functools import cache

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric, Options,
                                Symbolic, Uniform, Variable, per_draw)
from dynagrade.exercise.checks import Recompute
from dynagrade.exercise.figure import describe, dimension, new_drawing
from dynagrade.mechanics import equilibrium


@cache
def _system():
    """(t, theta, T, V, symbols) of the block (mass m, width w, height h) rolling on the
    cylinder of radius R. Rolling through theta puts the contact point at the cylinder's
    angle theta and turns the block by theta; its centre, h/2 above the bottom face, is at
    ((R + h/2) sin(theta) - R theta cos(theta), (R + h/2) cos(theta) + R theta sin(theta))."""
    import sympy as sp

    t = sp.Symbol("t")
    theta = sp.Function("theta")(t)
    m, R, w, h, g = sp.symbols("m R w h g", positive=True)
    b = h / 2
    x = (R + b) * sp.sin(theta) - R * theta * sp.cos(theta)
    y = (R + b) * sp.cos(theta) + R * theta * sp.sin(theta)
    J = m * (w**2 + h**2) / 12
    T = m * (x.diff(t) ** 2 + y.diff(t) ** 2) / 2 + J * theta.diff(t) ** 2 / 2
    return t, theta, T, m * g * y, (m, R, w, h, g)


@cache
def _linearized():
    """(K, omega^2) of (m, R, w, h, g) about the upright position, by the core, on first use."""
    import sympy as sp

    t, theta, T, V, symbols = _system()
    K = equilibrium.stiffness_matrix(V, [theta], {theta: 0})[0, 0]
    w2 = equilibrium.linearized_frequency_squared(T, V, [theta], t, {theta: 0})
    return sp.lambdify(symbols, K), sp.lambdify(symbols, w2)


@per_draw
def solve(p):
    stiffness, frequency_squared = _linearized()
    args = (p.m, p.R, p.w, p.h, p.g)
    K = float(stiffness(*args))
    return {"K": K, "stability": equilibrium.stability([[K]]),
            "s": float(np.sqrt(abs(frequency_squared(*args))))}


def _apart(p):
    """K and s (their magnitudes in the parts' units) differ by 5 % or more."""
    a, b = sorted((abs(solve(p)["K"]), solve(p)["s"]))
    return b >= 1.05 * a


def _potential(theta, p):
    """V = m g y_G with y_G = (R + h/2) cos(theta) + R theta sin(theta) (Section 4.2)."""
    return p.m * p.g * ((p.R + p.h / 2) * np.cos(theta) + p.R * theta * np.sin(theta))


def _curvature(p, d=1e-3):
    """V''(0) by a central difference of the potential (exact to d^2 V''''/12)."""
    return (_potential(d, p) - 2 * _potential(0.0, p) + _potential(-d, p)) / d**2


def figure(p):
    """The block upright on the cylinder, to scale: the cylinder of radius R on its stand,
    the block of width w and height h centred on its top."""
    from dynagrade.exercise.figure import Circle, Rectangle

    drawing, axes = new_drawing(3.6, 3.6)
    axes.add_patch(Circle((0.0, 0.0), p.R, facecolor="0.8", edgecolor="0.1"))
    axes.add_patch(Rectangle((-p.w / 2, p.R), p.w, p.h, facecolor="C0", edgecolor="0.1"))
    axes.plot([0.0, p.R * np.cos(np.radians(-30))], [0.0, p.R * np.sin(np.radians(-30))],
              color="0.2", lw=0.8)
    axes.text(0.55 * p.R * np.cos(np.radians(-30)), 0.55 * p.R * np.sin(np.radians(-30)) + 0.03 * p.R,
              "R", ha="center", va="bottom", fontsize=10)
    axes.plot([0.0], [0.0], "o", color="0.1", ms=3)
    size = max(p.R, p.h, p.w)
    dimension(axes, (-p.w / 2, p.R + p.h), (p.w / 2, p.R + p.h), "w", offset=0.12 * size,
              tick=0.03 * size)
    dimension(axes, (p.w / 2, p.R), (p.w / 2, p.R + p.h), "h", offset=-0.12 * size,
              tick=0.03 * size, side=-1.0)
    describe(axes, "The cylinder's axis is fixed; the block stands upright on its top, its "
             "bottom face touching the cylinder along the highest line.")
    axes.set_xlim(-max(p.R, p.w / 2) - 0.25 * size, max(p.R, p.w / 2) + 0.3 * size)
    axes.set_ylim(-p.R - 0.1 * size, p.R + p.h + 0.3 * size)
    return drawing


_VARS = {"theta": Variable(-1.5, 1.5, "rad"), "m": None, "R": None, "h": None, "g": None}

EXERCISE = Exercise(
    id="block-rocking-on-cylinder",
    title="A block rocking on a fixed cylinder: is the upright position stable?",
    source="Section 4.2",
    topics=("equilibrium", "stability", "potential energy", "rolling", "linearization"),
    params=(
        Uniform("m", 0.5, 10.0, step=0.5, unit="kg", symbol="m"),
        Uniform("R", 0.05, 0.3, step=0.01, unit="m", symbol="R"),
        Uniform("w", 0.05, 0.5, step=0.01, unit="m", symbol="w"),
        Uniform("h", 0.1, 0.6, step=0.01, unit="m", symbol="h"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("R differs from h/2 by at least 15 % (the stability is clear-cut)",
                   lambda p: abs(2 * p.R / p.h - 1) >= 0.15),
        Constraint("the numeric answers differ by at least 5 %", _apart),
    ),
    statement="""
A homogeneous rectangular block of mass $m$ = {{ m }}, width $w$ = {{ w }} and height
$h$ = {{ h }} rests upright on top of a fixed horizontal cylinder of radius $R$ = {{ R }},
its bottom face touching the cylinder's highest line; $g$ = {{ g }}. The block can rock
on the cylinder without slipping; let $\\theta$ be the angle through which it has turned
(then the contact line is at the angle $\\theta$ from the top of the cylinder, and the
length $R\\theta$ of the bottom face has rolled off).

1. Give the potential energy $V(\\theta)$ of the block, zero level at the cylinder's
   axis, as an expression in `theta`, `m`, `R`, `h` and `g`.
2. Is the upright position $\\theta = 0$ a stable or an unstable equilibrium?
3. What is the stiffness $K = V''(0)$ of the linearized system?
4. The linearized motion obeys $J_P\\ddot\\theta + K\\theta = 0$. Give its rate
   $s = \\sqrt{|K|/J_P}$: the angular frequency of small oscillations if the position is
   stable, the growth rate of $\\theta \\propto e^{st}$ if it is unstable.
""",
    solution=r"""
Equilibria are the stationary points of the potential, and an equilibrium is stable where
$V$ has a minimum, $V'' > 0$ (Lagrange-Dirichlet, Section 4.2).

1. **Potential.** When the block has rolled through $\theta$, the contact point sits at
   $(R\sin\theta, R\cos\theta)$, the bottom face is tangent there and the centre of mass
   lies $h/2$ along the normal, shifted back along the face by the rolled-off length
   $R\theta$:
   $$y_G = \Bigl(R + \frac h2\Bigr)\cos\theta + R\theta\sin\theta,
   \qquad V = m g\,y_G ,$$
   written as `{{ answers.V }}`.
2. **Stability.** $V'(\theta) = m g\bigl(R\theta\cos\theta - \tfrac h2\sin\theta\bigr)$
   vanishes at $\theta = 0$, and
   $$V''(0) = m g\Bigl(2R - R - \frac h2\Bigr) = m g\Bigl(R - \frac h2\Bigr).$$
   With $R$ = {{ R }} and $h$ = {{ h }} the upright position is
   **{{ answers.stability }}**: it is stable exactly when the cylinder's radius exceeds the
   height of the centre of mass above the contact, $R > h/2$.
3. **Stiffness.** $K = m g (R - h/2)$ = {{ answers.K }} ($m$ = {{ m }}).
4. **Rate.** At $\theta = 0$ the contact point is at rest, so the block turns about it:
   $J_P = \frac{m}{12}(w^2 + h^2) + m\bigl(\frac h2\bigr)^2 = \frac m{12}(w^2 + 4h^2)$, and
   $$s = \sqrt{\frac{|K|}{J_P}} = \sqrt{\frac{12\,g\,|R - h/2|}{w^2 + 4h^2}}$$
   = {{ answers.s }}. **Check.** A second difference of $V$ about $\theta = 0$ gives back
   $K$ = {{ checks.curvature_by_difference }} N·m.
""",
    solve=solve,
    checks=(
        Recompute("K", lambda p, s: _curvature(p), name="curvature_by_difference", rtol=1e-5),
        Recompute("s", lambda p, s: np.sqrt(12 * p.g * abs(p.R - p.h / 2) / (p.w**2 + 4 * p.h**2)),
                  name="rate_by_hand"),
    ),
    figure=figure,
    figure_to_scale=True,
    parts=(
        Symbolic("V", "potential energy", question=1, points=2,
                 expected="m*g*((R + h/2)*cos(theta) + R*theta*sin(theta))", variables=_VARS,
                 up_to_constant=("theta",),
                 misconceptions=(
                     Misconception("rolled-off length forgotten", "m*g*(R + h/2)*cos(theta)",
                                   "The block rolls: its centre moves back along the face by R theta."),
                     Misconception("full height for the centre", "m*g*((R + h)*cos(theta) + R*theta*sin(theta))",
                                   "The centre of mass is h/2 above the bottom face."),
                 )),
        Options("stability", "stability of the upright position", question=2,
                options=("stable", "unstable"), points=1, misconceptions=(
                    Misconception("like an inverted pendulum", lambda p: "unstable",
                                  "Rolling moves the contact towards the tilted side: V''(0) = m g (R - h/2).",
                                  applies=lambda p: p.R > p.h / 2),
                    Misconception("a curved support always restores", lambda p: "stable",
                                  "Stable only if R > h/2: V''(0) = m g (R - h/2).",
                                  applies=lambda p: p.R < p.h / 2),
                )),
        Numeric("K", "stiffness V''(0)", question=3, unit="N*m", points=1, misconceptions=(
            Misconception("rolled-off length forgotten", lambda p: -p.m * p.g * (p.R + p.h / 2),
                          "The term R theta sin(theta) adds 2 m g R to V''(0)."),
            Misconception("full height", lambda p: p.m * p.g * (p.R - p.h),
                          "The centre of mass is h/2 above the contact: K = m g (R - h/2)."),
        )),
        Numeric("s", "rate of the linearized motion", question=4, unit="1/s", points=2,
                misconceptions=(
                    Misconception("inertia about the centre", lambda p: np.sqrt(12 * p.g * abs(p.R - p.h / 2)
                                                                             / (p.w**2 + p.h**2)),
                                  "The block turns about its contact point: add m (h/2)^2 (parallel axes)."),
                    Misconception("point mass", lambda p: np.sqrt(4 * p.g * abs(p.R - p.h / 2) / p.h**2),
                                  "The block is a body: J_P = m (w^2 + 4 h^2)/12, not m (h/2)^2."),
                )),
    ),
)
