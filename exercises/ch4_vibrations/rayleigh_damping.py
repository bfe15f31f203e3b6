"""A two-storey building model with Rayleigh damping C = alpha M + beta K: the modal
damping ratios and how fast the first mode dies out (Section 4.4.4)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.apart import numbers_apart
from dynagrade.exercise.checks import Recompute
from dynagrade.exercise.figure import arrow, block, describe, ground, new_drawing
from dynagrade.mechanics import multi_dof, vibrations

#: the first mode's amplitude is asked when it has fallen to this share
_SHARE = 0.1


@per_draw
def matrices(p):
    K = multi_dof.chain_stiffness_matrix([p.k1, p.k2])
    M = multi_dof.lumped_mass_matrix([p.m1, p.m2])
    return K, M, multi_dof.rayleigh_damping_matrix(M, K, p.alpha, p.beta)


@per_draw
def solve(p):
    K, M, C = matrices(p)
    w = multi_dof.natural_frequencies(K, M)
    zeta = multi_dof.modal_damping_ratios(K, M, C)
    return {"zeta1": zeta[0], "zeta2": zeta[1],
            "t_decay": vibrations.envelope_decay_time(w[0], zeta[0], _SHARE),
            "omega1": w[0], "omega2": w[1]}


def _squares(p):
    """m1 m2 w^4 - (m1 k2 + m2 (k1 + k2)) w^2 + k1 k2 = 0 for K = [[k1 + k2, -k2], [-k2, k2]]."""
    return np.sort(np.roots([p.m1 * p.m2, -(p.m1 * p.k2 + p.m2 * (p.k1 + p.k2)), p.k1 * p.k2]).real)


def _zeta_by_hand(p, i):
    """phi^T (alpha M + beta K) phi = alpha + beta w^2 for a mass-normalized mode, so
    2 zeta w = alpha + beta w^2 (Section 4.4.4)."""
    w = np.sqrt(_squares(p)[i])
    return p.alpha / (2 * w) + p.beta * w / 2


def _first_mode_decay_time(p):
    """ln 10 over the decay rate -Re(lambda) of the first mode, from the eigenvalues of the
    first-order form y' = [[0, I], [-M^-1 K, -M^-1 C]] y of the damped system, built by hand
    (no modes): the first mode's pair has the smallest |Im(lambda)|."""
    K = np.array([[p.k1 + p.k2, -p.k2], [-p.k2, p.k2]])
    Minv = np.diag([1 / p.m1, 1 / p.m2])
    C = p.alpha * np.diag([p.m1, p.m2]) + p.beta * K
    A = np.block([[np.zeros((2, 2)), np.eye(2)], [-Minv @ K, -Minv @ C]])
    lam = np.linalg.eigvals(A)
    return np.log(1 / _SHARE) / -lam[np.argmin(np.abs(lam.imag))].real


def _mass_part(p):
    return p.alpha / (2 * solve(p)["omega1"])


def _stiffness_part(p):
    return p.beta * solve(p)["omega1"] / 2


def _differs(wrong, key, by=0.03):
    return lambda p: abs(wrong(p) / solve(p)[key] - 1) > by


def _fair(p):
    """The answers differ by 5 % or more, and both parts of the damping matter (the mass
    part is 10 % to 90 % of zeta1)."""
    s = solve(p)
    share = _mass_part(p) / s["zeta1"]
    return numbers_apart((s["zeta1"], s["zeta2"], s["t_decay"])) and 0.1 <= share <= 0.9


def figure(p):
    """Schematic shear frame: two floor slabs on flexible columns above the ground, the
    storeys' stiffnesses beside their columns and the floors' horizontal sway x1, x2."""
    drawing, axes = new_drawing(3.0, 3.4)
    ground(axes, -0.9, 0.9, hatch=0.06)
    for bottom, top, name in ((0.0, 0.9, "k₁"), (1.1, 2.0, "k₂")):
        for x in (-0.5, 0.5):
            axes.plot([x, x], [bottom, top], color="0.2", lw=2.0)
        axes.text(0.58, (bottom + top) / 2, name, ha="left", va="center", fontsize=10)
    block(axes, (0.0, 1.0), 1.3, 0.2, "m₁")
    block(axes, (0.0, 2.1), 1.3, 0.2, "m₂")
    arrow(axes, (-0.35, 1.3), (0.25, 1.3), "x₁", offset=(0.0, 0.12), color="0.3")
    arrow(axes, (-0.35, 2.4), (0.25, 2.4), "x₂", offset=(0.0, 0.12), color="0.3")
    axes.text(0.0, 2.75, "C = αM + βK", ha="center", va="bottom", fontsize=10)
    describe(axes, "A model of two storeys: the first floor m₁ stands on columns of storey "
             "stiffness k₁, the roof m₂ on columns of stiffness k₂; the floors sway "
             "horizontally, x₁ and x₂ to the right.")
    axes.set_xlim(-1.0, 1.1)
    axes.set_ylim(-0.2, 3.1)
    return drawing


EXERCISE = Exercise(
    id="rayleigh-damping-modes",
    title="Two-storey model with Rayleigh damping: modal damping ratios",
    source="Section 4.4.4",
    topics=("modal decomposition", "proportional damping", "damping ratio", "free vibration"),
    params=(
        Uniform("m1", 2000, 20000, step=500, unit="kg", symbol="m_1"),
        Uniform("m2", 2000, 20000, step=500, unit="kg", symbol="m_2"),
        Uniform("k1", 2e6, 4e7, step=1e6, unit="N/m", symbol="k_1"),
        Uniform("k2", 2e6, 4e7, step=1e6, unit="N/m", symbol="k_2"),
        Uniform("alpha", 0.1, 3.0, step=0.05, unit="1/s", symbol=r"\alpha"),
        Uniform("beta", 1e-4, 4e-3, step=1e-4, unit="s", symbol=r"\beta"),
    ),
    constraints=(
        Constraint("both parts of the damping matter; the answers differ by 5 %", _fair),
    ),
    statement="""
A two-storey building is modelled by the floor masses $m_1$ = {{ m1 }} (first floor) and
$m_2$ = {{ m2 }} (roof) and the storey stiffnesses $k_1$ = {{ k1 }} (ground to first floor)
and $k_2$ = {{ k2 }} (first floor to roof). Its damping is taken proportional,
$\\mathbf C = \\alpha\\mathbf M + \\beta\\mathbf K$ with $\\alpha$ = {{ alpha }} and
$\\beta$ = {{ beta }}.

1. What are the modal damping ratios $\\zeta_1$ and $\\zeta_2$ of the two modes?
2. The building vibrates freely in its first mode. After what time has the amplitude fallen
   to a tenth of its initial value?
""",
    solution=r"""
With $\mathbf M = \operatorname{diag}(m_1, m_2)$, $K_{11} = k_1 + k_2$,
$K_{12} = K_{2 1} = -k_2$, $K_{2 2} = k_2$, the mass-normalized modes
($\boldsymbol\phi_i^{\mathsf T}\mathbf M\boldsymbol\phi_i = 1$,
$\boldsymbol\phi_i^{\mathsf T}\mathbf K\boldsymbol\phi_i = \omega_i^2$) also diagonalize
$\mathbf C = \alpha\mathbf M + \beta\mathbf K$, so each modal coordinate is a 1-DOF damped
oscillator $\ddot\eta_i + 2\zeta_i\omega_i\dot\eta_i + \omega_i^2\eta_i = 0$ (modal
decomposition, Section 4.4.4).

1. **Damping ratios.** $2\zeta_i\omega_i = \boldsymbol\phi_i^{\mathsf T}\mathbf C\boldsymbol\phi_i = \alpha + \beta\omega_i^2$, so
   $$\zeta_i = \frac{\alpha}{2\omega_i} + \frac{\beta\,\omega_i}{2}.$$
   $\det(\mathbf K - \omega^2\mathbf M) = 0$ gives $\omega_1$ = {{ si.omega1 }} rad/s and
   $\omega_2$ = {{ si.omega2 }} rad/s, hence $\zeta_1$ = {{ answers.zeta1 }} and
   $\zeta_2$ = {{ answers.zeta2 }}. The mass part damps the low mode more, the
   stiffness part the high one.
2. **Decay of mode 1.** Its envelope falls as $e^{-\zeta_1\omega_1 t}$; to a tenth after
   $$t = \frac{\ln 10}{\zeta_1\omega_1}$$
   = {{ answers.t_decay }}. **Check.** The eigenvalues $\lambda$ of the damped system,
   found without the modes, give the first mode's decay rate $-\operatorname{Re}\lambda$
   and with it the same time, {{ checks.damped_eigenvalue }} s.
""",
    solve=solve,
    checks=(
        Recompute("zeta1", lambda p, s: _zeta_by_hand(p, 0), name="first_ratio_by_hand"),
        Recompute("zeta2", lambda p, s: _zeta_by_hand(p, 1), name="second_ratio_by_hand"),
        Recompute("t_decay", lambda p, s: _first_mode_decay_time(p), name="damped_eigenvalue",
                  rtol=1e-6),
    ),
    figure=figure,
    parts=(
        Numeric("zeta1", "damping ratio of mode 1", question=1, points=2, misconceptions=(
            Misconception("mass part only", _mass_part, "C = alpha M + beta K: add beta omega1/2.",
                          applies=_differs(_mass_part, "zeta1")),
            Misconception("stiffness part only", _stiffness_part, "C = alpha M + beta K: add alpha/(2 omega1).",
                          applies=_differs(_stiffness_part, "zeta1")),
        )),
        Numeric("zeta2", "damping ratio of mode 2", question=1, points=1, misconceptions=(
            Misconception("same as mode 1", lambda p: solve(p)["zeta1"],
                          "zeta depends on the mode's frequency: alpha/(2 omega2) + beta omega2/2."),
        )),
        Numeric("t_decay", "time to a tenth", question=2, unit="s", points=1, misconceptions=(
            Misconception("one time constant", lambda p: solve(p)["t_decay"] / np.log(10),
                          "e^{-zeta omega t} = 1/10 needs zeta omega t = ln 10, not 1."),
        )),
    ),
)
