"""Flexural waves on a beam: dispersion, phase and group speed (Section 5.3.3)."""

import numpy as np

from dynagrade.exercise import Exercise, Misconception, Numeric, Uniform
from dynagrade.exercise.checks import Recompute
from dynagrade.mechanics import beams, rods, stiffness


def _args(p):
    return 2 * np.pi * p.f, p.E * stiffness.rectangle_second_moment(p.b, p.h), p.rho * p.b * p.h


def solve(p):
    w, EI, rhoA = _args(p)
    k = beams.flexural_wavenumber(w, EI, rhoA)
    return {"lam": beams.wavelength(k), "c_p": beams.flexural_phase_speed(w, EI, rhoA),
            "c_g": beams.flexural_group_speed(w, EI, rhoA),
            "omega": w, "EI": EI, "rhoA": rhoA, "k": k}


def _wavenumber(p):
    """EI k^4 = rho A omega^2 (Section 5.3.3), I = b h^3 / 12, A = b h."""
    return (p.rho * 12 * (2 * np.pi * p.f) ** 2 / (p.E * p.h**2)) ** 0.25


EXERCISE = Exercise(
    id="beam-flexural-waves",
    title="Bending waves on a beam: wavelength, phase and group speed",
    source="Section 5.3.3",
    topics=("flexural waves", "dispersion", "group velocity"),
    params=(
        Uniform("E", 70, 210, step=5, unit="GPa", symbol="E"),
        Uniform("rho", 2700, 7900, step=100, unit="kg/m^3", symbol=r"\rho"),
        Uniform("b", 20, 80, step=1, unit="mm", symbol="b"),
        Uniform("h", 2, 20, step=0.5, unit="mm", symbol="h"),
        Uniform("f", 50, 2000, step=10, unit="Hz", symbol="f"),
    ),
    statement="""
A long beam with a rectangular section (width $b$ = {{ b }}, height $h$ = {{ h }},
$E$ = {{ E }}, $\\rho$ = {{ rho }}) is shaken transversely at one point with the frequency
$f$ = {{ f }}, in the direction of its height $h$, so that it bends about the axis along
its width and bending waves run along it (Euler–Bernoulli theory).

1. What is the wavelength of the bending waves?
2. What is their phase speed?
3. With which speed does the energy of a wave packet at this frequency travel (the group speed)?
""",
    solution=r"""
A harmonic bending wave $w = \hat w\cos(kx - \omega t)$ satisfies
$EI\,w'''' + \rho A\,\ddot w = 0$ only if $EI\,k^4 = \rho A\,\omega^2$: the dispersion relation
of flexural waves (Section 5.3.3). Their speed depends on the frequency.

Here $\omega = 2\pi f$ = {{ si.omega }} rad/s ($f$ = {{ f }}), $EI = E\,b h^3/12$ =
{{ si.EI }} N·m² and $\rho A = \rho b h$ = {{ si.rhoA }} kg/m ($b$ = {{ b }}, $h$ = {{ h }},
$E$ = {{ E }}, $\rho$ = {{ rho }}).

1. **Wavelength.** From the dispersion relation
   $$k = \sqrt{\omega}\,\Bigl(\frac{\rho A}{EI}\Bigr)^{1/4},$$
   here $k$ = {{ si.k }} rad/m, and $\lambda = 2\pi/k$ = {{ answers.lam }}.
2. **Phase speed.** $$c_p = \frac{\omega}{k} = \sqrt{\omega}\,\Bigl(\frac{EI}{\rho A}\Bigr)^{1/4},$$
   that is $c_p$ = {{ answers.c_p }}. It grows with $\sqrt\omega$: the beam is dispersive.
3. **Group speed.** With $\omega = \sqrt{EI/(\rho A)}\;k^2$,
   $$c_g = \frac{d\omega}{dk} = 2\sqrt{\frac{EI}{\rho A} }\;k = 2\,c_p,$$
   so a wave packet's energy travels at $c_g$ = {{ answers.c_g }}.
""",
    solve=solve,
    checks=(
        Recompute("lam", lambda p, s: 2 * np.pi / _wavenumber(p), name="wavelength"),
        Recompute("c_p", lambda p, s: 2 * np.pi * p.f / _wavenumber(p), name="phase_speed"),
        # omega grows as k^2, so d omega / d k = 2 omega / k
        Recompute("c_g", lambda p, s: 2 * s["c_p"], name="group_twice_phase"),
    ),
    parts=(
        Numeric("lam", "wavelength", question=1, unit="m", points=2,
                misconceptions=(
                    Misconception("longitudinal wave", lambda p: rods.longitudinal_wave_speed(p.E, p.rho) / p.f,
                                  "Bending waves obey omega = k^2 sqrt(EI/(rho A)), not omega = c k."),
                    Misconception("f for omega", lambda p: 2 * np.pi / beams.flexural_wavenumber(p.f, *_args(p)[1:]),
                                  "Use omega = 2 pi f in the dispersion relation."),
                )),
        Numeric("c_p", "phase speed", question=2, unit="m/s", points=1,
                misconceptions=(Misconception("longitudinal speed", lambda p: rods.longitudinal_wave_speed(p.E, p.rho),
                                              "Bending waves are dispersive: c_p = sqrt(omega) (EI/(rho A))^(1/4)."),)),
        Numeric("c_g", "group speed", question=3, unit="m/s", points=2,
                misconceptions=(Misconception("same as the phase speed", lambda p: solve(p)["c_p"],
                                              "c_g = d omega/dk = 2 k sqrt(EI/(rho A)) = 2 c_p."),)),
    ),
)
