"""A car on a wavy road: base excitation of a mass on a spring and damper (Section 4.3.3)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.checks import Recompute
from dynagrade.mechanics import vibrations


def _omega_n(p):
    return vibrations.natural_frequency(p.k, p.m)


@per_draw
def _eta(p):
    return vibrations.frequency_ratio(vibrations.road_forcing_frequency(p.v, p.lam), _omega_n(p))


def solve(p):
    Omega = vibrations.road_forcing_frequency(p.v, p.lam)
    zeta = vibrations.damping_ratio(p.c, p.k, p.m)
    return {"Omega": Omega, "v_res": vibrations.road_speed_for_forcing_frequency(_omega_n(p), p.lam),
            "X": vibrations.base_excitation_amplitude(p.Y, _eta(p), zeta),
            "omega_n": _omega_n(p), "eta": _eta(p), "zeta": zeta,
            "TR": vibrations.transmissibility(_eta(p), zeta)}


def _by_impedance(p, solved):
    """Steady state of m x'' + c (x' - y') + k (x - y) = 0 with y = Y e^(i Omega t),
    Section 4.3.3: X = Y |k + i c Omega| / |k - m Omega^2 + i c Omega|, Omega = 2 pi v / lam."""
    Omega = 2 * np.pi * p.v / p.lam
    return p.Y * abs(p.k + 1j * p.c * Omega) / abs(p.k - p.m * Omega**2 + 1j * p.c * Omega)


EXERCISE = Exercise(
    id="car-wavy-road",
    title="A car on a wavy road: base excitation",
    source="Section 4.3.3",
    topics=("base excitation", "transmissibility", "resonance", "forced vibration"),
    params=(
        Uniform("m", 200, 600, step=10, unit="kg", symbol="m"),
        Uniform("k", 1e4, 6e4, step=1e3, unit="N/m", symbol="k"),
        Uniform("c", 500, 5000, step=100, unit="N*s/m", symbol="c"),
        Uniform("lam", 2.0, 20.0, step=0.5, unit="m", symbol=r"\lambda"),
        Uniform("Y", 5, 40, step=1, unit="mm", symbol="Y"),
        Uniform("v", 20, 120, step=5, unit="km/h", symbol="v"),
    ),
    constraints=(
        Constraint("0.1 <= zeta <= 0.6", lambda p: 0.1 <= vibrations.damping_ratio(p.c, p.k, p.m) <= 0.6),
        Constraint("away from resonance (15 %)", lambda p: abs(_eta(p) - 1) >= 0.15),
        Constraint("the damper's share of the transmissibility matters (2 zeta eta >= 0.2)",
                   lambda p: 2 * vibrations.damping_ratio(p.c, p.k, p.m) * _eta(p) >= 0.2),
    ),
    statement="""
A quarter-car model: a body of mass $m$ = {{ m }} rests on a suspension spring
$k$ = {{ k }} and a damper $c$ = {{ c }}; the wheel follows a road whose height varies
sinusoidally with wavelength $\\lambda$ = {{ lam }} and amplitude $Y$ = {{ Y }}. The car
drives at $v$ = {{ v }}.

1. With which angular frequency $\\Omega$ is the suspension excited?
2. At which driving speed (in km/h) would the body be excited at its natural frequency?
3. What is the amplitude of the body's vertical motion in steady state?
""",
    solution=r"""
The wheel imposes the road's profile on the lower end of spring and damper: a base
excitation $y(t) = Y\cos\Omega t$ of a single-degree-of-freedom oscillator
(Section 4.3.3). The body's absolute motion follows from
$m\ddot x + c(\dot x - \dot y) + k(x - y) = 0$.

1. **Excitation frequency.** The car covers one wavelength in $\lambda/v$, so
   $$\Omega = \frac{2\pi v}{\lambda},$$
   and with $v$ = {{ v }} and $\lambda$ = {{ lam }}: $\Omega$ = {{ answers.Omega }}.
2. **Resonant speed.** The natural frequency is $\omega_n = \sqrt{k/m}$ = {{ si.omega_n }} rad/s
   ($m$ = {{ m }}, $k$ = {{ k }}). Setting $\Omega = \omega_n$ and solving for the speed,
   $$v_{\mathrm{res} } = \frac{\omega_n\lambda}{2\pi},$$
   that is $v_{\mathrm{res} }$ = {{ answers.v_res }}.
3. **Body amplitude.** With the frequency ratio $\eta = \Omega/\omega_n$ = {{ si.eta }} and
   the damping ratio $\zeta = c/(2\sqrt{k m})$ = {{ si.zeta }} ($c$ = {{ c }}), the steady
   state has the amplitude ratio (transmissibility)
   $$\frac{X}{Y} = \sqrt{\frac{1 + (2\zeta\eta)^2}{(1 - \eta^2)^2 + (2\zeta\eta)^2} },$$
   here $X/Y$ = {{ si.TR }}. With $Y$ = {{ Y }}: $X$ = {{ answers.X }}. Spring and damper both pass
   the road's motion on, hence the $(2\zeta\eta)^2$ in the numerator.
""",
    solve=solve,
    checks=(
        Recompute("X", _by_impedance, name="complex_amplitude"),
        Recompute("TR", lambda p, s: _by_impedance(p, s) / p.Y, name="transmissibility"),
        # the road's wavelength passed at v_res takes one natural period
        Recompute("v_res", lambda p, s: np.sqrt(p.k / p.m) * p.lam / (2 * np.pi),
                  name="resonant_speed"),
    ),
    parts=(
        Numeric("Omega", "excitation frequency", question=1, unit="rad/s", points=1,
                misconceptions=(Misconception("v / lambda", lambda p: p.v / p.lam,
                                              "v/lambda is in Hz: Omega = 2 pi v / lambda."),)),
        Numeric("v_res", "resonant driving speed", question=2, unit="km/h", points=1,
                misconceptions=(Misconception("2 pi forgotten", lambda p: _omega_n(p) * p.lam,
                                              "Omega = 2 pi v / lambda = omega_n gives v = omega_n lambda / (2 pi)."),)),
        Numeric("X", "body amplitude", question=3, unit="mm", points=2,
                misconceptions=(
                    Misconception("force amplification V instead of transmissibility",
                                  lambda p: p.Y * vibrations.amplification_factor(_eta(p), vibrations.damping_ratio(p.c, p.k, p.m)),
                                  "The damper also transmits the base motion: X/Y = sqrt(1 + (2 zeta eta)^2) V."),
                    Misconception("relative motion", lambda p: vibrations.relative_base_excitation_amplitude(
                        p.Y, _eta(p), vibrations.damping_ratio(p.c, p.k, p.m)),
                                  "Y eta^2 V is the spring's deflection, not the body's absolute motion."),
                )),
    ),
)
