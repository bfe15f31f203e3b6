"""Flexural waves on a beam: dispersion, phase and group speed (Section 5.3.3)."""

import numpy as np

from dynagrade.exercise import Exercise, Misconception, Numeric, Uniform
from dynagrade.mechanics import beams, rods, stiffness


def _args(p):
    return 2 * np.pi * p.f, p.E * stiffness.rectangle_second_moment(p.b, p.h), p.rho * p.b * p.h


def solve(p):
    w, EI, rhoA = _args(p)
    k = beams.flexural_wavenumber(w, EI, rhoA)
    return {"lam": beams.wavelength(k), "c_p": beams.flexural_phase_speed(w, EI, rhoA),
            "c_g": beams.flexural_group_speed(w, EI, rhoA)}


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
$f$ = {{ f }}, so that bending waves run along it (Euler–Bernoulli theory).

1. What is the wavelength of the bending waves?
2. What is their phase speed?
3. With which speed does the energy of a wave packet at this frequency travel (the group speed)?
""",
    solve=solve,
    parts=(
        Numeric("lam", "wavelength", unit="m", points=2,
                misconceptions=(
                    Misconception("longitudinal wave", lambda p: rods.longitudinal_wave_speed(p.E, p.rho) / p.f,
                                  "Bending waves obey omega = k^2 sqrt(EI/(rho A)), not omega = c k."),
                    Misconception("f for omega", lambda p: 2 * np.pi / beams.flexural_wavenumber(p.f, *_args(p)[1:]),
                                  "Use omega = 2 pi f in the dispersion relation."),
                )),
        Numeric("c_p", "phase speed", unit="m/s", points=1,
                misconceptions=(Misconception("longitudinal speed", lambda p: rods.longitudinal_wave_speed(p.E, p.rho),
                                              "Bending waves are dispersive: c_p = sqrt(omega) (EI/(rho A))^(1/4)."),)),
        Numeric("c_g", "group speed", unit="m/s", points=2,
                misconceptions=(Misconception("same as the phase speed", lambda p: solve(p)["c_p"],
                                              "c_g = d omega/dk = 2 k sqrt(EI/(rho A)) = 2 c_p."),)),
    ),
)
