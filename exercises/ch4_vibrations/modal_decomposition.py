"""Two coupled masses released from rest: modal decomposition of the free vibration
(Section 4.4.4)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.checks import Integrated, Recompute
from dynagrade.mechanics import multi_dof


def _system(p):
    return (multi_dof.chain_stiffness_matrix([p.k, p.kc, p.k], right_wall=True),
            multi_dof.lumped_mass_matrix([p.m, p.m]))


def _x(p, t):
    K, M = _system(p)
    return multi_dof.modal_free_response([t], K, M, [p.a, 0.0], [0.0, 0.0])[:, 0]


def solve(p):
    K, M = _system(p)
    w = multi_dof.natural_frequencies(K, M)
    eta0 = multi_dof.modal_coordinates(K, M, [p.a, 0.0])
    shapes = multi_dof.mode_shapes(K, M)
    x1, x2 = _x(p, p.t1)
    # the part of x1 carried by each mode: phi_i1 * eta_i(0)
    return {"omega1": w[0], "omega2": w[1], "A1": shapes[0, 0] * eta0[0], "x1": x1, "x2": x2}


@per_draw
def _first_mode_only(p):
    w = multi_dof.natural_frequencies(*_system(p))
    return p.a * np.cos(w[0] * p.t1)


def _two_masses(t, y, p):
    """m x1'' = -k x1 - kc (x1 - x2), m x2'' = -k x2 - kc (x2 - x1) (Section 4.4.4)."""
    x1, x2 = y[0], y[1]
    return (y[2], y[3], (-p.k * x1 - p.kc * (x1 - x2)) / p.m, (-p.k * x2 - p.kc * (x2 - x1)) / p.m)


def _first_pulled_aside(p):
    """Mass 1 held at a, mass 2 at rest in place, both released."""
    return (p.a, 0.0, 0.0, 0.0)


def _until_t1(p, solved):
    return p.t1


EXERCISE = Exercise(
    id="modal-decomposition-coupled-masses",
    title="Coupled masses released from rest: modal decomposition",
    source="Section 4.4.4",
    topics=("modal decomposition", "mode shapes", "free vibration", "beats"),
    params=(
        Uniform("m", 0.5, 10, step=0.5, unit="kg", symbol="m"),
        Uniform("k", 100, 2000, step=50, unit="N/m", symbol="k"),
        Uniform("kc", 20, 1000, step=10, unit="N/m", symbol="k_c"),
        Uniform("a", 5, 50, step=1, unit="mm", symbol="a"),
        Uniform("t1", 0.05, 2.0, step=0.01, unit="s", symbol="t_1"),
    ),
    constraints=(
        Constraint("the coupling is at least 10 % of the wall springs", lambda p: p.kc >= 0.1 * p.k),
        Constraint("both displacements at t1 exceed 10 % of a",
                   lambda p: np.all(np.abs(_x(p, p.t1)) >= 0.1 * p.a)),
        Constraint("keeping only the first mode is at least 10 % of a off",
                   lambda p: abs(_first_mode_only(p) - _x(p, p.t1)[0]) >= 0.1 * p.a),
    ),
    statement="""
Two equal masses $m$ = {{ m }} slide without friction between two walls. Each is tied to
its wall by a spring $k$ = {{ k }}, and they are joined by a coupling spring
$k_c$ = {{ kc }}. Mass 1 is pulled aside by $a$ = {{ a }} while mass 2 is
held in place, and both are released from rest at $t = 0$.

1. What are the natural angular frequencies $\\omega_1 < \\omega_2$?
2. Decompose the initial state into the modes: what is the amplitude of the first
   (in-phase) mode in the motion $x_1(t)$ of mass 1?
3. What are the displacements $x_1$ and $x_2$ at $t_1$ = {{ t1 }}?
""",
    solution=r"""
The equations of motion $\mathbf M\ddot x + \mathbf K x = 0$ decouple in modal coordinates:
the free motion is a sum of the modes, each oscillating at its own natural frequency with
an amplitude fixed by the initial state (modal decomposition, Section 4.4.4).

1. **Natural frequencies.** With $\mathbf M = m\,\mathbf I$ and the stiffness matrix
   $K_{11} = K_{2 2} = k + k_c$, $K_{12} = K_{2 1} = -k_c$,
   $\det(\mathbf K - \omega^2\mathbf M) = 0$ gives the in-phase mode $(1, 1)$, which does not
   stretch the coupling spring, and the opposite-phase mode $(1, -1)$, which stretches it
   twice:
   $$\omega_1 = \sqrt{\frac{k}{m} },\qquad \omega_2 = \sqrt{\frac{k + 2k_c}{m} } .$$
   With $m$ = {{ m }}, $k$ = {{ k }} and $k_c$ = {{ kc }}: $\omega_1$ = {{ answers.omega1 }}
   and $\omega_2$ = {{ answers.omega2 }}.
2. **Modal amplitudes.** Released from rest, each mode moves as $\cos\omega_i t$. The
   initial displacement splits into the modes:
   $$(a,\; 0) = \frac a2\,(1,\; 1) + \frac a2\,(1,\; -1),$$
   so the first mode carries $A_1 = a/2$ = {{ answers.A1 }} of $x_1$ ($a$ = {{ a }}).
3. **Displacements at $t_1$.** Adding the modes,
   $$x_1(t) = \frac a2\bigl(\cos\omega_1 t + \cos\omega_2 t\bigr),\qquad
   x_2(t) = \frac a2\bigl(\cos\omega_1 t - \cos\omega_2 t\bigr);$$
   at $t_1$ = {{ t1 }}: $x_1$ = {{ answers.x1 }} and $x_2$ = {{ answers.x2 }}. The energy
   passes back and forth between the masses (beats when $k_c \ll k$).
""",
    solve=solve,
    checks=(
        Integrated("x1", _two_masses, _first_pulled_aside, _until_t1,
                   lambda t, y, p: y[0], name="integrated_x1", atol=1e-9),
        Integrated("x2", _two_masses, _first_pulled_aside, _until_t1,
                   lambda t, y, p: y[1], name="integrated_x2", atol=1e-9),
        # in phase the coupling spring is idle; in antiphase it is stretched twice
        Recompute("omega1", lambda p, s: np.sqrt(p.k / p.m), name="in_phase"),
        Recompute("omega2", lambda p, s: np.sqrt((p.k + 2 * p.kc) / p.m), name="antiphase"),
        Recompute("A1", lambda p, s: p.a / 2, name="half_in_each_mode"),
    ),
    parts=(
        Numeric("omega1", "lower natural frequency", question=1, unit="rad/s", points=1,
                misconceptions=(Misconception("f for omega", lambda p: np.sqrt(p.k / p.m) / (2 * np.pi),
                                              "omega is in rad/s."),)),
        Numeric("omega2", "higher natural frequency", question=1, unit="rad/s", points=1,
                misconceptions=(Misconception("coupling spring counted once", lambda p: np.sqrt((p.k + p.kc) / p.m),
                                              "In the out-of-phase mode the coupling spring is stretched by 2x: omega^2 = (k + 2 k_c)/m."),)),
        Numeric("A1", "first-mode amplitude in x1", question=2, unit="mm", points=1,
                misconceptions=(Misconception("all of a", lambda p: p.a,
                                              "The initial state (a, 0) is half in-phase mode, half out-of-phase mode."),)),
        Numeric("x1", "x1 at t1", question=3, unit="mm", points=2,
                misconceptions=(Misconception("first mode only", _first_mode_only,
                                              "Superpose both modes: x1 = a/2 (cos omega1 t + cos omega2 t)."),)),
        Numeric("x2", "x2 at t1", question=3, unit="mm", points=2),
    ),
)
