"""Two carts joined by a spring, one of them struck: the motion split into the rigid-body
mode and the vibration mode, the largest compression of the spring and where the second
cart is at a given time (Section 4.4.4)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.apart import numbers_apart
from dynagrade.exercise.checks import Integrated, Recompute
from dynagrade.exercise.figure import arrow, block, describe, ground, new_drawing, spring
from dynagrade.mechanics import multi_dof


@per_draw
def matrices(p):
    # free-free: no spring to a wall (first spring zero), k between the carts
    return multi_dof.chain_stiffness_matrix([0.0, p.k]), multi_dof.lumped_mass_matrix([p.m1, p.m2])


@per_draw
def solve(p):
    K, M = matrices(p)
    w = multi_dof.natural_frequencies(K, M)
    Phi = multi_dof.mode_shapes(K, M)
    rate = multi_dof.modal_coordinates(K, M, [p.v0, 0.0])       # modal velocities at t = 0
    # the vibration mode's coordinate is (rate[1] / w[1]) sin(w[1] t); the spring's
    # shortening x1 - x2 follows it with the factor Phi[0, 1] - Phi[1, 1]
    x = multi_dof.modal_free_response(p.t1, K, M, [0.0, 0.0], [p.v0, 0.0])
    return {"omega": w[1], "d_max": abs((Phi[0, 1] - Phi[1, 1]) * rate[1] / w[1]),
            "x2": x[1, 0], "v_G": Phi[0, 0] * rate[0]}


def _reduced_mass(p):
    return p.m1 * p.m2 / (p.m1 + p.m2)


def _relative(p, t):
    """Centre of mass and relative coordinate u = x2 - x1 (Section 4.4.4 by hand): x_G = v_G t,
    mu u'' = -k u with u(0) = 0, u'(0) = -v0; x2 = x_G + m1 u / (m1 + m2)."""
    w = np.sqrt(p.k / _reduced_mass(p))
    u = -p.v0 / w * np.sin(w * t)
    return p.m1 * p.v0 / (p.m1 + p.m2) * t + p.m1 * u / (p.m1 + p.m2)


def _carts(t, y, p):
    """m1 x1'' = k (x2 - x1), m2 x2'' = -k (x2 - x1); y = (x1, x2, v1, v2)."""
    f = p.k * (y[1] - y[0])
    return (y[2], y[3], f / p.m1, -f / p.m2)


def _rigid_only(p):
    return p.m1 * p.v0 / (p.m1 + p.m2) * p.t1


def _vibrating(p):
    """The vibration mode adds to x2 at t1 (sin(omega t1) is not near 0): 'rigid mode only' is wrong."""
    return abs(_rigid_only(p) / solve(p)["x2"] - 1) > 0.03


def _fair(p):
    """x2 has moved at least 5 mm, the spring shortens by 15 cm at most (a spring of a
    usual length takes it), and the answers (rad/s, mm, mm) differ by 5 % or more."""
    s = solve(p)
    return (s["x2"] >= 5e-3 and s["d_max"] <= 0.15
            and numbers_apart((s["omega"], 1e3 * s["d_max"], 1e3 * s["x2"])))


def figure(p):
    """Schematic: the two carts joined by the spring on a level track, cart 1 on the left
    with the velocity it receives, x1 and x2 to the right."""
    from dynagrade.exercise.figure import Circle

    drawing, axes = new_drawing(4.6, 1.8)
    ground(axes, -0.2, 4.2, hatch=0.06)
    for centre, name in ((0.8, "m₁"), (3.0, "m₂")):
        block(axes, (centre, 0.45), 1.0, 0.6, name)
        for x in (centre - 0.3, centre + 0.3):
            axes.add_patch(Circle((x, 0.075), 0.075, facecolor="0.3", edgecolor="0.1"))
    spring(axes, (1.3, 0.45), (2.5, 0.45), coils=6, width=0.15)
    axes.text(1.9, 0.62, "k", ha="center", va="bottom", fontsize=10)
    arrow(axes, (0.3, 0.95), (1.2, 0.95), "v₀", offset=(0.0, 0.15), color="C3")
    arrow(axes, (2.7, 0.95), (3.3, 0.95), "x₂", offset=(0.0, 0.15), color="0.3")
    describe(axes, "Cart 1, on the left, has just been given the velocity v₀ to the right; "
             "cart 2 is still at rest and the spring relaxed.")
    axes.set_xlim(-0.3, 4.3)
    axes.set_ylim(-0.2, 1.35)
    return drawing


EXERCISE = Exercise(
    id="struck-carts-modal-decomposition",
    title="Two carts on a spring, one struck: rigid-body and vibration modes",
    source="Section 4.4.4",
    topics=("modal decomposition", "rigid-body mode", "free vibration", "initial conditions"),
    params=(
        Uniform("m1", 1.0, 20.0, step=0.5, unit="kg", symbol="m_1"),
        Uniform("m2", 1.0, 20.0, step=0.5, unit="kg", symbol="m_2"),
        Uniform("k", 100, 5000, step=50, unit="N/m", symbol="k"),
        Uniform("v0", 0.2, 3.0, step=0.1, unit="m/s", symbol="v_0"),
        Uniform("t1", 0.1, 2.0, step=0.05, unit="s", symbol="t_1"),
    ),
    constraints=(
        Constraint("cart 2 has moved 5 mm by t1, the spring shortens by 15 cm at most; the "
                   "answers differ by at least 5 %", _fair),
    ),
    statement="""
Two carts of masses $m_1$ = {{ m1 }} and $m_2$ = {{ m2 }} stand on a level track, joined by
a relaxed spring of stiffness $k$ = {{ k }}, long enough never to close up; friction is
negligible. At $t = 0$ a blow
gives cart 1 the velocity $v_0$ = {{ v0 }} towards cart 2; cart 2 is still at rest. Let
$x_1$, $x_2$ be the carts' displacements in the direction of $v_0$.

1. What is the non-zero natural angular frequency $\\omega$ of the system?
2. Decompose the motion into the modes. By how much is the spring shortened at most?
3. Where is cart 2 at $t_1$ = {{ t1 }}, i.e. what is $x_2(t_1)$?
""",
    solution=r"""
With $\mathbf M = \operatorname{diag}(m_1, m_2)$ and $K_{11} = K_{2 2} = k$,
$K_{12} = K_{2 1} = -k$ the system is free-free: $\det\mathbf K = 0$, so one mode is a
rigid-body mode ($\omega = 0$). Each modal coordinate moves on its own, started by
$\eta_i(0) = \boldsymbol\phi_i^{\mathsf T}\mathbf M\mathbf x(0) = 0$ and
$\dot\eta_i(0) = \boldsymbol\phi_i^{\mathsf T}\mathbf M\dot{\mathbf x}(0)$ (modal
decomposition, Section 4.4.4).

1. **Frequencies.** $\det(\mathbf K - \omega^2\mathbf M) = \omega^2\bigl(m_1 m_2\omega^2 - k(m_1 + m_2)\bigr) = 0$:
   $\omega = 0$ and $\omega = \sqrt{k(m_1 + m_2)/(m_1 m_2)}$ = {{ answers.omega }}.
2. **Modes.** The rigid-body mode $\boldsymbol\phi_1 \propto (1, 1)$ carries the centre of
   mass at $v_G = m_1 v_0/(m_1 + m_2)$ = {{ si.v_G }} m/s (momentum is conserved). The
   vibration mode $\boldsymbol\phi_2 \propto (m_2, -m_1)$ leaves the centre of mass at
   rest; its coordinate is $\eta_2 = \frac{\dot\eta_2(0)}{\omega}\sin\omega t$, and the
   spring's shortening $x_1 - x_2$ swings with the amplitude
   $$d_{\max} = \frac{v_0}{\omega} = v_0\sqrt{\frac{m_1 m_2}{k(m_1 + m_2)}}$$
   = {{ answers.d_max }}.
3. **Superposition.** $x_2 = v_G t - \frac{m_1}{m_1 + m_2}\frac{v_0}{\omega}\sin\omega t$, so
   at $t_1$ = {{ t1 }}: $x_2(t_1)$ = {{ answers.x2 }}. **Check.** Integrating the two
   carts' equations of motion numerically gives $x_2(t_1)$ = {{ checks.integrated_carts }} m;
   $x_2$ never runs backwards (its velocity $v_G(1 - \cos\omega t) \ge 0$).
""",
    solve=solve,
    checks=(
        Integrated("x2", _carts, lambda p: (0.0, 0.0, p.v0, 0.0), lambda p, s: p.t1,
                   lambda t, y, p: y[1], name="integrated_carts", rtol=1e-6, atol=1e-9),
        Recompute("x2", lambda p, s: _relative(p, p.t1), name="centre_and_relative"),
        Recompute("d_max", lambda p, s: p.v0 * np.sqrt(_reduced_mass(p) / p.k), name="reduced_mass"),
    ),
    figure=figure,
    parts=(
        Numeric("omega", "natural angular frequency", question=1, unit="rad/s", points=1,
                misconceptions=(
                    Misconception("cart 2 held", lambda p: np.sqrt(p.k / p.m1),
                                  "Both carts move: omega^2 = k (m1 + m2)/(m1 m2)."),
                    Misconception("total mass", lambda p: np.sqrt(p.k / (p.m1 + p.m2)),
                                  "The spring acts on the reduced mass m1 m2/(m1 + m2), not the sum."),
                )),
        Numeric("d_max", "largest shortening of the spring", question=2, unit="mm", points=2,
                misconceptions=(
                    Misconception("all kinetic energy into the spring", lambda p: p.v0 * np.sqrt(p.m1 / p.k),
                                  "The rigid-body mode keeps m1 v0^2/2 * m1/(m1 + m2): only the "
                                  "vibration mode compresses the spring."),
                )),
        Numeric("x2", "position of cart 2 at t1", question=3, unit="mm", points=2,
                misconceptions=(
                    Misconception("rigid-body mode only", _rigid_only,
                                  "Add the vibration mode: x2 = v_G t - m1/(m1 + m2) (v0/omega) sin(omega t).",
                                  applies=_vibrating),
                )),
    ),
)
