"""Harmonically forced mass-spring-damper: amplitude, phase lag and resonance (Section 4.3.3)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.checks import Balance, Recompute
from dynagrade.mechanics import vibrations


@per_draw
def _eta_zeta(p):
    w = vibrations.natural_frequency(p.k, p.m)
    return vibrations.frequency_ratio(p.Omega, w), vibrations.damping_ratio(p.c, p.k, p.m)


def solve(p):
    eta, zeta = _eta_zeta(p)
    w = vibrations.natural_frequency(p.k, p.m)
    return {"X": vibrations.steady_state_amplitude(p.F0, p.k, eta, zeta),
            "phi": vibrations.phase_lag(eta, zeta),
            "Omega_res": w * vibrations.resonance_frequency_ratio(zeta),
            "X_max": p.F0 / p.k * vibrations.peak_amplification(zeta),
            "omega_n": w, "eta": eta, "zeta": zeta,
            "V": vibrations.amplification_factor(eta, zeta)}


def _receptance(p, Omega):
    """m x'' + c x' + k x = F0 e^(i Omega t): x = F0 e^(i Omega t) / (k - m Omega^2
    + i c Omega) (Section 4.3.3)."""
    return p.F0 / (p.k - p.m * Omega**2 + 1j * p.c * Omega)


EXERCISE = Exercise(
    id="forced-response-amplitude-phase",
    title="Harmonic forcing: amplitude, phase lag and resonance",
    source="Section 4.3.3",
    topics=("forced vibration", "amplification factor", "phase", "resonance"),
    params=(
        Uniform("m", 1.0, 20.0, step=0.5, unit="kg", symbol="m"),
        Uniform("k", 500, 20000, step=100, unit="N/m", symbol="k"),
        Uniform("c", 5, 300, step=5, unit="N*s/m", symbol="c"),
        Uniform("F0", 10, 200, step=5, unit="N", symbol="F_0"),
        Uniform("Omega", 5, 150, step=1, unit="rad/s", symbol=r"\Omega"),
    ),
    constraints=(
        Constraint("0.2 <= zeta <= 0.5", lambda p: 0.2 <= _eta_zeta(p)[1] <= 0.5),
        Constraint("the amplification factor differs from 1 by at least 5 %",
                   lambda p: abs(vibrations.amplification_factor(*_eta_zeta(p)) - 1) >= 0.05),
        Constraint("damping changes the amplitude by at least 3 %",
                   lambda p: (2 * _eta_zeta(p)[1] * _eta_zeta(p)[0]) ** 2 >= 0.07 * (_eta_zeta(p)[0] ** 2 - 1) ** 2),
        Constraint("excited above resonance, 1.15 <= eta <= 3", lambda p: 1.15 <= _eta_zeta(p)[0] <= 3.0),
    ),
    statement="""
A mass $m$ = {{ m }} on a spring $k$ = {{ k }} with a damper $c$ = {{ c }} is driven by the
force $F(t) = F_0\\cos(\\Omega t)$ with $F_0$ = {{ F0 }} and $\\Omega$ = {{ Omega }}.

1. What is the amplitude of the steady-state vibration?
2. By which phase angle (between 0° and 180°) does the displacement lag behind the force?
3. At which forcing frequency would the amplitude be largest, and how large would it be?
""",
    solution=r"""
The equation of motion $m\ddot x + c\dot x + k x = F_0\cos\Omega t$ has the steady-state
solution $x = X\cos(\Omega t - \varphi)$ (harmonic forcing, Section 4.3.3). Everything
follows from the natural frequency $\omega_n = \sqrt{k/m}$ = {{ si.omega_n }} rad/s, the
frequency ratio $\eta = \Omega/\omega_n$ = {{ si.eta }} and the damping ratio
$\zeta = c/(2\sqrt{k m})$ = {{ si.zeta }}, with $m$ = {{ m }}, $k$ = {{ k }}, $c$ = {{ c }}
and $\Omega$ = {{ Omega }}.

1. **Amplitude.** The amplitude is the static deflection $F_0/k$ times the amplification
   factor
   $$V = \frac{1}{\sqrt{(1 - \eta^2)^2 + (2\zeta\eta)^2} },$$
   here $V$ = {{ si.V }}, so with $F_0$ = {{ F0 }}: $X = \frac{F_0}{k}V$ = {{ answers.X }}.
2. **Phase lag.**
   $$\tan\varphi = \frac{2\zeta\eta}{1 - \eta^2};$$
   $\varphi$ lies below $\pi/2$ under resonance ($\eta < 1$) and between $\pi/2$ and $\pi$
   above it. Here $\varphi$ = {{ answers.phi }}.
3. **Resonance.** $V$ is largest where $(1 - \eta^2)^2 + (2\zeta\eta)^2$ is smallest,
   at $\eta = \sqrt{1 - 2\zeta^2}$:
   $$\Omega_{\mathrm{res} } = \omega_n\sqrt{1 - 2\zeta^2},\qquad
   X_{\max} = \frac{F_0}{k}\,\frac{1}{2\zeta\sqrt{1 - \zeta^2} },$$
   that is $\Omega_{\mathrm{res} }$ = {{ answers.Omega_res }} and
   $X_{\max}$ = {{ answers.X_max }}.
""",
    solve=solve,
    checks=(
        Recompute("X", lambda p, s: abs(_receptance(p, p.Omega)), name="complex_amplitude"),
        Recompute("phi", lambda p, s: -np.angle(_receptance(p, p.Omega)), name="complex_phase"),
        # the peak amplitude is the amplitude at the resonance frequency
        Balance("amplitude at resonance", lambda p, s: s["X_max"],
                lambda p, s: abs(_receptance(p, s["Omega_res"])), name="peak_at_resonance"),
    ),
    parts=(
        Numeric("X", "steady-state amplitude", question=1, unit="mm", points=2,
                misconceptions=(
                    Misconception("static deflection", lambda p: p.F0 / p.k, "The force is amplified by V(eta, zeta)."),
                    Misconception("undamped", lambda p: p.F0 / p.k / abs(1 - _eta_zeta(p)[0] ** 2),
                                  "Keep the damping term (2 zeta eta)^2 in V."),
                )),
        Numeric("phi", "phase lag", question=2, unit="deg", points=2,
                misconceptions=(Misconception("arctan without the quadrant",
                                              lambda p: np.arctan(2 * _eta_zeta(p)[1] * _eta_zeta(p)[0] / (1 - _eta_zeta(p)[0] ** 2)),
                                              "Above resonance 1 - eta^2 < 0: the lag lies between 90 and 180 degrees."),)),
        Numeric("Omega_res", "frequency of the largest amplitude", question=3,
                unit="rad/s", points=1,
                misconceptions=(Misconception("omega_n", lambda p: np.sqrt(p.k / p.m),
                                              "With damping the peak lies at omega_n sqrt(1 - 2 zeta^2)."),)),
        Numeric("X_max", "largest amplitude", question=3, unit="mm", points=1,
                misconceptions=(Misconception("amplitude at eta = 1", lambda p: p.F0 / p.k / (2 * _eta_zeta(p)[1]),
                                              "V is largest at eta = sqrt(1 - 2 zeta^2): V_max = 1/(2 zeta sqrt(1 - zeta^2))."),)),
    ),
)
