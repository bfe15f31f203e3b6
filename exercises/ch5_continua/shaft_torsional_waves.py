"""Torsional waves and vibrations of a shaft clamped at one end (Section 5.3.2)."""

import numpy as np

from dynagrade.exercise import Exercise, Misconception, Numeric, Uniform
from dynagrade.exercise.checks import Recompute
from dynagrade.mechanics import rods, stiffness, vibrations


def c_T(p):
    return rods.torsional_wave_speed(stiffness.shear_modulus(p.E, p.nu), p.rho)


def _f(p, c, ends="fixed-free", n=2):
    return vibrations.frequency_in_hertz(rods.rod_natural_frequencies(c, p.L, n, ends))


def solve(p):
    f = _f(p, c_T(p))
    return {"c_T": c_T(p), "f1": f[0], "f2": f[1], "G": stiffness.shear_modulus(p.E, p.nu)}


def _speed(p):
    """c_T = sqrt(G / rho), G = E / (2 (1 + nu)) (Section 5.3.2)."""
    return np.sqrt(p.E / (2 * (1 + p.nu)) / p.rho)


EXERCISE = Exercise(
    id="shaft-torsional-waves",
    title="Torsional waves in a clamped shaft",
    source="Section 5.3.2",
    topics=("torsional waves", "wave speed", "natural frequencies", "shear modulus"),
    params=(
        Uniform("E", 70, 210, step=5, unit="GPa", symbol="E"),
        Uniform("nu", 0.25, 0.35, step=0.01, symbol=r"\nu"),
        Uniform("rho", 2700, 8900, step=100, unit="kg/m^3", symbol=r"\rho"),
        Uniform("L", 0.5, 4.0, step=0.1, unit="m", symbol="L"),
    ),
    statement="""
A circular shaft of length $L$ = {{ L }} is clamped at one end and free at the other. Its
material has $E$ = {{ E }}, Poisson's ratio $\\nu$ = {{ nu }} and density $\\rho$ = {{ rho }}.

1. With which speed do torsional waves travel along the shaft?
2. What are the two lowest natural frequencies (in Hz) of its torsional vibration?
""",
    solution=r"""
The twist angle of a circular shaft obeys the wave equation $\theta_{tt} = c_T^2\,\theta_{xx}$
with $c_T = \sqrt{G/\rho}$; the clamped and the free end fix the natural modes
(torsional waves, Section 5.3.2).

1. **Wave speed.** The shear modulus of an isotropic material is
   $$G = \frac{E}{2(1 + \nu)},$$
   here $G$ = {{ si.G }} Pa ($E$ = {{ E }}, $\nu$ = {{ nu }}), and with $\rho$ = {{ rho }}
   $$c_T = \sqrt{\frac{G}{\rho} },$$
   that is $c_T$ = {{ answers.c_T }}. It does not depend on the shaft's diameter.
2. **Natural frequencies.** Clamped at $x = 0$ ($\theta = 0$) and free at $x = L$
   (no torque, $\theta_x = 0$): the modes are $\sin\bigl((2j - 1)\pi x/(2L)\bigr)$, a quarter
   wave, three quarters, …, so
   $$f_j = \frac{(2j - 1)\,c_T}{4L};$$
   with $L$ = {{ L }}: $f_1$ = {{ answers.f1 }} and $f_2 = 3 f_1$ = {{ answers.f2 }}.
""",
    solve=solve,
    checks=(
        # fixed-free: a quarter wavelength, then three quarters, fit the shaft
        Recompute("f1", lambda p, s: _speed(p) / (4 * p.L), name="quarter_wavelength"),
        Recompute("f2", lambda p, s: 3 * _speed(p) / (4 * p.L), name="three_quarters"),
    ),
    parts=(
        Numeric("c_T", "torsional wave speed", question=1, unit="m/s", points=2,
                misconceptions=(Misconception("longitudinal speed sqrt(E/rho)", lambda p: np.sqrt(p.E / p.rho),
                                              "Torsion shears the material: c_T = sqrt(G/rho), G = E/(2(1 + nu))."),)),
        Numeric("f1", "lowest natural frequency", question=2, unit="Hz", points=2,
                misconceptions=(
                    Misconception("both ends fixed", lambda p: _f(p, c_T(p), "fixed-fixed")[0],
                                  "Fixed-free: a quarter wavelength fits the shaft, f1 = c_T/(4L)."),
                    Misconception("omega for f", lambda p: 2 * np.pi * _f(p, c_T(p))[0], "f = omega/(2 pi)."),
                )),
        Numeric("f2", "second natural frequency", question=2, unit="Hz", points=1,
                misconceptions=(Misconception("twice f1", lambda p: 2 * _f(p, c_T(p))[0],
                                              "Fixed-free shafts have only odd multiples: f2 = 3 f1."),)),
    ),
)
