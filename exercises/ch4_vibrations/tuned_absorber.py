"""A tuned vibration absorber for a machine excited near resonance (Section 4.4.3)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.checks import Recompute
from dynagrade.mechanics import multi_dof, vibrations


@per_draw
def _Omega(p):
    return 2 * np.pi * p.f


def solve(p):
    k_a = multi_dof.tuned_absorber_stiffness(p.m_a, _Omega(p))
    w = multi_dof.natural_frequencies(*multi_dof.absorber_system_matrices(p.m, p.k, p.m_a, k_a))
    return {"X0": vibrations.steady_state_amplitude(p.F0, p.k, vibrations.frequency_ratio(
                _Omega(p), vibrations.natural_frequency(p.k, p.m)), 0.0),
            "k_a": k_a, "X_a": abs(multi_dof.absorber_amplitude(p.F0, k_a)),
            "f_low": vibrations.frequency_in_hertz(w[0]), "f_high": vibrations.frequency_in_hertz(w[1]),
            "Omega": _Omega(p), "omega_n": vibrations.natural_frequency(p.k, p.m)}


def _squares(p):
    """K = [[k + k_a, -k_a], [-k_a, k_a]], M = diag(m, m_a) with k_a = m_a Omega^2
    (Section 4.4.3): m m_a w^4 - (m k_a + m_a (k + k_a)) w^2 + k k_a = 0."""
    k_a = p.m_a * (2 * np.pi * p.f) ** 2
    return np.sort(np.roots([p.m * p.m_a, -(p.m * k_a + p.m_a * (p.k + k_a)), p.k * k_a]).real)


EXERCISE = Exercise(
    id="tuned-mass-absorber",
    title="Tuned vibration absorber",
    source="Section 4.4.3",
    topics=("vibration absorber", "forced vibration", "multi-DOF vibrations", "anti-resonance"),
    params=(
        Uniform("m", 50, 500, step=10, unit="kg", symbol="m"),
        Uniform("k", 1e5, 2e6, step=5e4, unit="N/m", symbol="k"),
        Uniform("F0", 50, 1000, step=50, unit="N", symbol="F_0"),
        Uniform("f", 5, 40, step=0.5, unit="Hz", symbol="f"),
        Uniform("m_a", 5, 100, step=1, unit="kg", symbol="m_a"),
    ),
    constraints=(
        Constraint("the machine runs near but not at resonance (5 % to 25 % off)",
                   lambda p: 0.05 <= abs(_Omega(p) / vibrations.natural_frequency(p.k, p.m) - 1) <= 0.25),
        Constraint("the absorber weighs 5 % to 30 % of the machine", lambda p: 0.05 <= p.m_a / p.m <= 0.3),
    ),
    statement="""
A machine of mass $m$ = {{ m }} on mounts of stiffness $k$ = {{ k }} (damping negligible)
is shaken by the force $F_0\\cos(\\Omega t)$ with $F_0$ = {{ F0 }} at the frequency
$f = \\Omega/2\\pi$ = {{ f }}.

1. What is the machine's vibration amplitude without any absorber?
2. An absorber of mass $m_a$ = {{ m_a }} is attached to the machine by a spring $k_a$.
   Which $k_a$ keeps the machine at rest at this frequency?
3. What is then the absorber's amplitude?
4. What are the two natural frequencies (in Hz) of the machine with the absorber?
""",
    solution=r"""
Without damping, the machine driven at $\Omega$ responds in phase or in antiphase with the
force; a second mass tuned to $\Omega$ can take up the force and keep the machine at rest
(vibration absorber, Section 4.4.3). Here $\Omega = 2\pi f$ = {{ si.Omega }} rad/s
($f$ = {{ f }}).

1. **Without absorber.** $\omega_n = \sqrt{k/m}$ = {{ si.omega_n }} rad/s ($m$ = {{ m }},
   $k$ = {{ k }}), $\eta = \Omega/\omega_n$, and without damping
   $$X_0 = \frac{F_0/k}{|1 - \eta^2|};$$
   with $F_0$ = {{ F0 }}: $X_0$ = {{ answers.X0 }}.
2. **Tuning.** The machine stays at rest if the absorber's spring passes exactly
   $-F_0\cos\Omega t$ to it; the absorber alone then vibrates on its spring at its own
   natural frequency, so $\sqrt{k_a/m_a} = \Omega$:
   $$k_a = m_a\,\Omega^2,$$
   that is $k_a$ = {{ answers.k_a }} ($m_a$ = {{ m_a }}).
3. **Absorber amplitude.** Its spring force $k_a X_a$ must balance $F_0$:
   $|X_a| = F_0/k_a$ = {{ answers.X_a }}.
4. **Natural frequencies with absorber.** With
   the mass matrix $\operatorname{diag}(m, m_a)$ and the stiffness matrix
   $K_{11} = k + k_a$, $K_{12} = K_{2 1} = -k_a$, $K_{2 2} = k_a$,
   $\det(\mathbf K - \omega^2\mathbf M) = 0$ gives two roots on either side of the
   operating frequency: $f_{\mathrm{low} }$ = {{ answers.f_low }} and
   $f_{\mathrm{high} }$ = {{ answers.f_high }}. The absorber splits the resonance in two,
   so it works only near the tuned speed.
""",
    solve=solve,
    checks=(
        Recompute("k_a", lambda p, s: p.m_a * (2 * np.pi * p.f) ** 2, name="tuned_to_the_forcing"),
        # tuned, the main mass stands still and the absorber's spring balances F0
        Recompute("X_a", lambda p, s: p.F0 / (p.m_a * (2 * np.pi * p.f) ** 2), name="absorber_balances_f0"),
        Recompute("f_low", lambda p, s: np.sqrt(_squares(p)[0]) / (2 * np.pi), name="lower_root"),
        Recompute("f_high", lambda p, s: np.sqrt(_squares(p)[1]) / (2 * np.pi), name="upper_root"),
        Recompute("X0", lambda p, s: p.F0 / abs(p.k - p.m * (2 * np.pi * p.f) ** 2),
                  name="without_absorber"),
    ),
    parts=(
        Numeric("X0", "amplitude without absorber", question=1, unit="mm", points=1,
                misconceptions=(Misconception("static deflection", lambda p: p.F0 / p.k,
                                              "Near resonance the force is amplified by 1/|1 - eta^2|."),)),
        Numeric("k_a", "absorber stiffness", question=2, unit="N/m", points=2,
                misconceptions=(
                    Misconception("tuned to the machine's natural frequency", lambda p: p.m_a * p.k / p.m,
                                  "Tune the absorber to the forcing frequency: k_a = m_a Omega^2."),
                    Misconception("f for Omega", lambda p: p.m_a * p.f**2, "Omega = 2 pi f."),
                )),
        Numeric("X_a", "absorber amplitude", question=3, unit="mm", points=1,
                misconceptions=(Misconception("F0/k", lambda p: p.F0 / p.k,
                                              "The absorber spring must pass -F0: X_a = F0/k_a."),)),
        Numeric("f_low", "lower natural frequency", question=4, unit="Hz", points=1,
                misconceptions=(Misconception("the machine alone",
                                              lambda p: vibrations.frequency_in_hertz(vibrations.natural_frequency(p.k, p.m)),
                                              "The absorber splits the machine's resonance in two."),)),
        Numeric("f_high", "higher natural frequency", question=4, unit="Hz", points=1,
                misconceptions=(Misconception("the forcing frequency", lambda p: p.f,
                                              "The forcing frequency lies between the two new natural frequencies."),)),
    ),
)
