"""A free rod struck at one end: wave speed, arrival time, impact stress and the first
natural frequencies (Section 5.3.1)."""

import numpy as np

from dynagrade.exercise import Exercise, Misconception, Numeric, Uniform, Vector
from dynagrade.exercise.checks import Recompute
from dynagrade.exercise.figure import arrow, block, dimension, new_drawing
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import rods, vibrations


def c(p):
    return rods.longitudinal_wave_speed(p.E, p.rho)


def figure(p):
    """The free rod of length L on soft supports and the hammer blow giving its left end the
    velocity v along the rod (Section 5.3.1); the rod's thickness is not given and is drawn
    as a fortieth of its length."""
    from dynagrade.exercise.figure import Rectangle

    L = p.L
    thick = L / 40
    drawing, axes = new_drawing(5.0, 1.6)
    block(axes, (L / 2, thick / 2), L, thick, color="0.6")
    for x in (0.2 * L, 0.8 * L):
        axes.add_patch(Rectangle((x - 0.04 * L, -0.03 * L), 0.08 * L, 0.03 * L,
                                 facecolor="#e6d8a8", edgecolor="0.3", lw=0.6))
    arrow(axes, (-0.2 * L, thick / 2), (-0.01 * L, thick / 2), color="C3")
    axes.text(-0.11 * L, thick + 0.02 * L, f"v = {format_number(p.v)} m/s", color="C3",
              ha="center", va="bottom", fontsize=10)
    axes.text(L / 2, thick + 0.03 * L,
              f"E = {format_number(p.E / 1e9)} GPa,   ρ = {format_number(p.rho)} kg/m³",
              ha="center", va="bottom", fontsize=10)
    dimension(axes, (0.0, 0.0), (L, 0.0), f"L = {format_number(L)} m", offset=-0.07 * L,
              tick=0.01 * L, side=-1.0)
    axes.set_xlim(-0.22 * L, 1.02 * L)
    axes.set_ylim(-0.12 * L, 0.1 * L)
    return drawing


def solve(p):
    f = vibrations.frequency_in_hertz(rods.rod_natural_frequencies(c(p), p.L, 2, "free-free"))
    return {"c": c(p), "t_arrival": rods.travel_time(p.L, c(p)),
            "sigma": rods.impact_stress(p.rho, c(p), p.v), "f": tuple(f)}


EXERCISE = Exercise(
    id="rod-struck-at-end",
    title="A rod struck at its end: longitudinal waves",
    source="Section 5.3.1",
    topics=("longitudinal waves", "wave speed", "impact stress", "natural frequencies"),
    params=(
        Uniform("E", 70, 210, step=5, unit="GPa", symbol="E"),
        Uniform("rho", 2700, 8900, step=100, unit="kg/m^3", symbol=r"\rho"),
        Uniform("L", 0.5, 5.0, step=0.1, unit="m", symbol="L"),
        Uniform("v", 0.5, 5.0, step=0.1, unit="m/s", symbol="v"),
    ),
    statement="""
A slender metal rod of length $L$ = {{ L }} (Young's modulus $E$ = {{ E }}, density
$\\rho$ = {{ rho }}) lies free on soft supports. At $t = 0$ one end is suddenly given the
velocity $v$ = {{ v }} along the rod by a hammer blow.

1. With which speed does the disturbance travel along the rod?
2. When does it reach the far end?
3. What compressive stress does the wave carry?
4. Give the first two non-zero natural frequencies (in Hz) of longitudinal vibration of the
   free rod as a vector $[f_1, f_2]$.
""",
    solution=r"""
Longitudinal motion of a slender rod obeys the wave equation $u_{tt} = c^2 u_{xx}$ with
$c = \sqrt{E/\rho}$; a sudden end velocity starts a step wave, and the free ends fix the
natural modes (longitudinal waves, Section 5.3.1).

1. **Wave speed.** $$c = \sqrt{\frac{E}{\rho} },$$ with $E$ = {{ E }} and $\rho$ = {{ rho }}:
   $c$ = {{ answers.c }}.
2. **Arrival time.** The front covers $L$ = {{ L }} at $c$: $t = L/c$ = {{ answers.t_arrival }}.
3. **Stress in the wave.** Across the front the particles jump from rest to $v$; the
   momentum balance of the material the front sweeps in $dt$ gives
   $\sigma\,A\,dt = \rho A\,c\,dt\,v$:
   $$\sigma = \rho\,c\,v,$$
   so with $v$ = {{ v }}: $\sigma$ = {{ answers.sigma }} (compressive).
4. **Natural frequencies.** Free ends carry no force, $u_x = 0$ at both ends, so the modes are
   $\cos(n\pi x/L)$ with $\omega_n = n\pi c/L$ and
   $$f_n = \frac{n\,c}{2L}:$$
   $[f_1, f_2]$ = {{ answers.f }}.
""",
    solve=solve,
    checks=(
        # longitudinal waves at c = sqrt(E / rho) (Section 5.3.1)
        Recompute("t_arrival", lambda p, s: p.L / np.sqrt(p.E / p.rho), name="travel_time"),
        # the struck end moves at v: the stress is rho c v
        Recompute("sigma", lambda p, s: p.rho * np.sqrt(p.E / p.rho) * p.v, name="momentum_of_the_wave"),
        # free-free: half a wavelength fits the rod, f_n = n c / (2 L)
        Recompute("f", lambda p, s: tuple(n * np.sqrt(p.E / p.rho) / (2 * p.L) for n in (1, 2)),
                  name="half_wavelengths"),
    ),
    figure=figure,
    parts=(
        Numeric("c", "wave speed", question=1, unit="m/s", points=1),
        Numeric("t_arrival", "arrival time at the far end", question=2, unit="ms", points=1,
                misconceptions=(Misconception("there and back", lambda p: 2 * p.L / c(p),
                                              "The front needs L/c to reach the far end; 2L/c is the round trip."),)),
        Numeric("sigma", "stress in the wave", question=3, unit="MPa", points=2,
                misconceptions=(Misconception("dynamic pressure rho v^2", lambda p: p.rho * p.v**2,
                                              "Behind the front the strain is v/c: sigma = E v / c = rho c v."),)),
        Vector("f", "first two natural frequencies", question=4, unit="Hz", size=2, points=2,
               misconceptions=(
                   Misconception("fixed-free", lambda p: tuple(vibrations.frequency_in_hertz(
                       rods.rod_natural_frequencies(c(p), p.L, 2, "fixed-free"))),
                                 "Both ends are free: f_n = n c / (2L)."),
                   Misconception("omega for f", lambda p: tuple(rods.rod_natural_frequencies(c(p), p.L, 2, "free-free")),
                                 "omega_n = n pi c / L is in rad/s; f_n = n c/(2L)."),
               )),
    ),
)
