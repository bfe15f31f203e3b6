"""A clamped rod whose free end is suddenly pulled by a constant force: the end's velocity,
the doubled stress at the clamp and the end's largest displacement (Section 5.3.1)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.apart import answers_apart
from dynagrade.exercise.checks import Recompute
from dynagrade.exercise.figure import arrow, block, describe, dimension, new_drawing, wall
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import rods, stiffness

#: each part's unit as a factor of SI, for telling the answers apart
_UNITS = {"v_end": 1.0, "sigma_max": 1e6, "t_max": 1e-3, "u_max": 1e-3}


def _A(p):
    return stiffness.circle_area(p.d)


def _c(p):
    return rods.longitudinal_wave_speed(p.E, p.rho)


@per_draw
def solve(p):
    A, c = _A(p), _c(p)
    return {"v_end": rods.particle_velocity(p.F / A, p.rho, c),
            "sigma_max": rods.clamped_end_peak_stress(p.F / A),
            "t_max": rods.travel_time(p.L, c),
            "u_max": rods.step_load_peak_displacement(p.F, p.E, A, p.L),
            "A": A, "c": c, "sigma": p.F / A, "u_static": p.F * p.L / (p.E * A)}


def _end_displacement_by_modes(p, solved, modes=40_000):
    """u(L, t) summed over the fixed-free modes sin(k_j x), modal mass rho A L / 2, each
    driven by the step F: u = sum 2 F / (rho A L omega_j^2) (1 - cos omega_j t); its
    largest value comes at t = 2 L / c, where every cosine is -1 (Section 5.3.1)."""
    A = np.pi * p.d**2 / 4
    k = (2 * np.arange(1, modes + 1) - 1) * np.pi / (2 * p.L)
    omega = np.sqrt(p.E / p.rho) * k
    return float(np.sum(4 * p.F / (p.rho * A * p.L * omega**2)))


def figure(p):
    """The rod clamped at its left end, the force at its right end; schematic."""
    L = p.L
    t = 0.035 * L
    drawing, axes = new_drawing(5.0, 1.5)
    wall(axes, 0.0, -0.08 * L, 0.08 * L, side=-1.0, hatch=0.02 * L)
    block(axes, (L / 2, 0.0), L, t, color="0.65")
    arrow(axes, (L, 0.0), (1.16 * L, 0.0), color="C3")
    axes.text(1.1 * L, 0.03 * L, f"F = {format_number(p.F / 1e3)} kN", color="C3",
              ha="center", va="bottom", fontsize=10)
    axes.text(L / 2, 0.03 * L,
              f"d = {format_number(p.d * 1e3)} mm,  E = {format_number(p.E / 1e9)} GPa,"
              f"  ρ = {format_number(p.rho)} kg/m³", ha="center", va="bottom", fontsize=9)
    dimension(axes, (0.0, -0.08 * L), (L, -0.08 * L), f"L = {format_number(L)} m",
              tick=0.01 * L, side=-1.0)
    describe(axes, "The rod's left end is clamped in a wall; at t = 0 the force starts pulling its right end to the right, along the rod.")
    axes.set_xlim(-0.05 * L, 1.22 * L)
    axes.set_ylim(-0.17 * L, 0.1 * L)
    return drawing


EXERCISE = Exercise(
    id="suddenly-loaded-rod",
    title="A clamped rod suddenly pulled at its free end",
    source="Section 5.3.1",
    topics=("longitudinal waves", "wave reflection", "dynamic load factor"),
    params=(
        Uniform("E", 70, 210, step=5, unit="GPa", symbol="E"),
        Uniform("rho", 2700, 8900, step=100, unit="kg/m^3", symbol=r"\rho"),
        Uniform("d", 6, 30, step=1, unit="mm", symbol="d"),
        Uniform("L", 0.5, 5.0, step=0.1, unit="m", symbol="L"),
        Uniform("F", 1, 60, step=0.5, unit="kN", symbol="F"),
    ),
    constraints=(
        Constraint("a real metal (aluminium, steel, copper alloys, titanium): "
                   "sqrt(E/rho) between 3 and 5.5 km/s",
                   lambda p: 3e3 <= np.sqrt(p.E / p.rho) <= 5.5e3),
        Constraint("the rod stays elastic: 2 F / A at most 200 MPa",
                   lambda p: solve(p)["sigma_max"] <= 200e6),
        Constraint("the four answers are over 10 % apart in SI and in their parts' units",
                   lambda p: answers_apart(solve(p), _UNITS)),
    ),
    statement="""
A slender round rod (diameter $d$ = {{ d }}, length $L$ = {{ L }}, $E$ = {{ E }},
$\\rho$ = {{ rho }}) is clamped at one end and at rest. At $t = 0$ a constant axial force
$F$ = {{ F }} suddenly starts to pull its free end. The rod stays elastic; neglect damping.

1. With which velocity does the free end move right after $t = 0$?
2. What is the largest tensile stress at the clamped end?
3. When is it first reached?
4. What is the largest displacement of the free end?
""",
    solution=r"""
The force starts a tensile step wave at the free end that runs to the clamp at
$c = \sqrt{E/\rho}$ = {{ si.c }} m/s and is reflected there; a wave of stress $\sigma$ moves
the material at $\sigma/(\rho c)$ (longitudinal waves, Section 5.3.1).

1. **Velocity of the end.** Behind the front the stress is
   $\sigma = F/A$ = {{ si.sigma }} Pa, with $A = \pi d^2/4$ = {{ si.A }} m² ($d$ = {{ d }},
   $F$ = {{ F }}), so the end moves at
   $$v = \frac{F}{\rho c A}$$
   = {{ answers.v_end }} ($\rho$ = {{ rho }}).
2. **Stress at the clamp.** The clamped end cannot move: the wave is reflected with the
   same stress, and incident and reflected waves add,
   $$\sigma_{\max} = 2\,\frac{F}{A}$$
   = {{ answers.sigma_max }}, twice the static stress.
3. **When.** The front needs $t = L/c$ = {{ answers.t_max }} to reach the clamp ($L$ = {{ L }}).
4. **Largest displacement.** The end moves at $v$ until the reflected wave comes back after
   $2L/c$ and reverses it:
   $$u_{\max} = v\,\frac{2L}{c} = 2\,\frac{F L}{E A}$$
   = {{ answers.u_max }}, twice the static elongation $F L/(E A)$ = {{ si.u_static }} m.
   The end then swings back to rest and the motion repeats every $4L/c$.

**Check.** Summed over the rod's fixed-free natural modes, the end's displacement at
$2L/c$ is {{ checks.modal_sum }} m, the same.
""",
    solve=solve,
    checks=(
        # modal superposition of the step response, Sections 4.4.4 and 5.3.1
        Recompute("u_max", _end_displacement_by_modes, name="modal_sum", rtol=1e-4),
        # the end moves at constant speed for the wave's round trip 2 L / c
        Recompute("v_end", lambda p, s: s["u_max"] / (2 * p.L / np.sqrt(p.E / p.rho)),
                  name="round_trip"),
    ),
    figure=figure,
    parts=(
        Numeric("v_end", "velocity of the free end", question=1, unit="m/s", points=1,
                misconceptions=(
                    Misconception("strain for velocity", lambda p: p.F / (p.E * _A(p)),
                                  "F/(E A) is the strain behind the front; the particle velocity is c times it, F/(rho c A)."),)),
        Numeric("sigma_max", "largest stress at the clamp", question=2, unit="MPa", points=2,
                misconceptions=(
                    Misconception("static stress F/A", lambda p: p.F / _A(p),
                                  "At the clamp the reflected wave adds to the incident one: 2 F/A."),
                    Misconception("d as radius", lambda p: 2 * p.F / (np.pi * p.d**2),
                                  "A = pi d^2/4 for the diameter d."),
                )),
        Numeric("t_max", "time of the largest stress at the clamp", question=3, unit="ms", points=1,
                misconceptions=(
                    Misconception("round trip 2L/c", lambda p: 2 * p.L / _c(p),
                                  "The clamp is reached after one crossing, L/c."),)),
        Numeric("u_max", "largest displacement of the free end", question=4, unit="mm", points=2,
                misconceptions=(
                    Misconception("static elongation", lambda p: p.F * p.L / (p.E * _A(p)),
                                  "A suddenly applied force overshoots: u_max = 2 F L/(E A)."),)),
    ),
)
