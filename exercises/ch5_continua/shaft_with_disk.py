"""A disk at the free end of a heavy shaft: the exact torsional natural frequencies from
the frequency equation (Section 5.3.2)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.apart import answers_apart
from dynagrade.exercise.checks import Limit, Recompute
from dynagrade.exercise.figure import Ellipse, block, describe, dimension, new_drawing, wall
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import inertia, rods, stiffness, vibrations


def _J_disk(p):
    return inertia.inertia_tensor_disk(p.m, p.R)[2, 2]


def _J_shaft(p):
    return p.rho * stiffness.circle_polar_moment(p.d) * p.L


def _c(p):
    return rods.torsional_wave_speed(p.G, p.rho)


@per_draw
def solve(p):
    omega = rods.tip_mass_natural_frequencies(_c(p), p.L, _J_shaft(p), _J_disk(p), 2)
    f = vibrations.frequency_in_hertz(omega)
    return {"J_s": _J_shaft(p), "f1": f[0], "f2": f[1], "c": _c(p), "J_d": _J_disk(p),
            "I_p": stiffness.circle_polar_moment(p.d), "ratio": _J_shaft(p) / _J_disk(p),
            "kL1": omega[0] * p.L / _c(p), "kL2": omega[1] * p.L / _c(p)}


def _massless_shaft(p):
    k_t = stiffness.torsional_stiffness(p.G, stiffness.circle_polar_moment(p.d), p.L)
    return vibrations.frequency_in_hertz(vibrations.natural_frequency(k_t, _J_disk(p)))


def _chain(p, solved, N=300):
    """The shaft cut into N twisting springs G I_p N / L, its inertia lumped at the nodes
    and the disk's at the free end: the two lowest frequencies in Hz from numpy's
    symmetric eigen-solver (Sections 4.4.2 and 5.3.2)."""
    I_p = np.pi * p.d**4 / 32
    h = p.L / N
    k = p.G * I_p / h
    J = np.full(N, p.rho * I_p * h)
    J[-1] = p.rho * I_p * h / 2 + p.m * p.R**2 / 2
    K = 2 * k * np.eye(N) - k * np.eye(N, k=1) - k * np.eye(N, k=-1)
    K[-1, -1] = k
    scale = 1 / np.sqrt(J)
    return np.sqrt(np.linalg.eigvalsh(scale[:, None] * K * scale[None, :])[:2]) / (2 * np.pi)


def figure(p):
    """The shaft clamped at its left end, the disk on its right end; schematic."""
    L = p.L
    t = 0.04 * L
    drawing, axes = new_drawing(5.0, 1.9)
    wall(axes, 0.0, -0.12 * L, 0.12 * L, side=-1.0, hatch=0.025 * L)
    block(axes, (L / 2, 0.0), L, t, color="0.65")
    axes.add_patch(Ellipse((L, 0.0), 0.05 * L, 0.26 * L, facecolor="C0", edgecolor="0.1", lw=1.0))
    axes.text(L + 0.05 * L, 0.1 * L, f"m = {format_number(p.m)} kg", ha="left", va="center", fontsize=10)
    axes.text(L + 0.05 * L, 0.03 * L, f"R = {format_number(p.R * 1e3)} mm", ha="left", va="center",
              fontsize=10)
    axes.text(L / 2, 0.035 * L,
              f"d = {format_number(p.d * 1e3)} mm,  G = {format_number(p.G / 1e9)} GPa,"
              f"  ρ = {format_number(p.rho)} kg/m³", ha="center", va="bottom", fontsize=9)
    dimension(axes, (0.0, -0.16 * L), (L, -0.16 * L), f"L = {format_number(L)} m",
              tick=0.01 * L, side=-1.0)
    describe(axes, "The shaft's left end is clamped in a wall; the disk sits on its right end, "
                   "its plane normal to the shaft, and twists with it.")
    axes.set_xlim(-0.05 * L, 1.35 * L)
    axes.set_ylim(-0.26 * L, 0.16 * L)
    return drawing


EXERCISE = Exercise(
    id="shaft-with-end-disk",
    title="A disk on the end of a heavy shaft: torsional natural frequencies",
    source="Section 5.3.2",
    topics=("torsional vibrations", "frequency equation", "boundary conditions"),
    params=(
        Uniform("G", 26, 80, step=1, unit="GPa", symbol="G"),
        Uniform("rho", 2700, 8900, step=100, unit="kg/m^3", symbol=r"\rho"),
        Uniform("d", 20, 80, step=2, unit="mm", symbol="d"),
        Uniform("L", 0.5, 3.0, step=0.1, unit="m", symbol="L"),
        Uniform("m", 0.5, 5, step=0.1, unit="kg", symbol="m"),
        Uniform("R", 30, 150, step=5, unit="mm", symbol="R"),
    ),
    constraints=(
        Constraint("a real metal (aluminium, steel, copper alloys, titanium): "
                   "sqrt(G/rho) between 2 and 3.4 km/s",
                   lambda p: 2e3 <= np.sqrt(p.G / p.rho) <= 3.4e3),
        Constraint("the disk is at least twice as wide as the shaft", lambda p: p.R >= p.d),
        Constraint("a disk, neither a foil nor a drum: of the shaft's material its thickness "
                   "m/(rho pi R^2) lies between R/50 and R",
                   lambda p: p.R / 50 <= p.m / (p.rho * np.pi * p.R**2) <= p.R),
        Constraint("the shaft's inertia is half to five times the disk's", lambda p: 0.5 <= solve(p)["ratio"] <= 5),
        Constraint("the three answers are over 10 % apart",
                   lambda p: answers_apart(solve(p), {"J_s": 1.0, "f1": 1.0, "f2": 1.0})),
    ),
    statement="""
A metal shaft of circular section (diameter $d$ = {{ d }}, length $L$ = {{ L }},
shear modulus $G$ = {{ G }}, density $\\rho$ = {{ rho }}) is clamped at one end. On its
other end sits a homogeneous disk, of the same metal, of mass $m$ = {{ m }} and radius $R$ = {{ R }}. The
shaft's own inertia is not negligible.

1. What is the shaft's mass moment of inertia $J_s$ about its axis?
2. What are the lowest and the second natural frequencies (in Hz) of the torsional vibration?
   (The boundary condition at the disk leads to a transcendental equation; solve it
   numerically.)
""",
    solution=r"""
The twist angle obeys the wave equation $\theta_{tt} = c_T^2\,\theta_{xx}$ with
$c_T = \sqrt{G/\rho}$ = {{ si.c }} m/s; the clamp and the disk fix the modes (torsional
waves and vibrations, Section 5.3.2).

1. **Shaft inertia.** With $I_p = \tfrac{\pi}{2}(d/2)^4$ = {{ si.I_p }} m⁴ ($d$ = {{ d }}),
   $J_s = \rho I_p L$ = {{ answers.J_s }} ($\rho$ = {{ rho }}, $L$ = {{ L }}).
2. **Frequency equation.** The modes are $\Theta = \sin(kx)$ ($\theta = 0$ at the clamp,
   $x = 0$). At $x = L$ the shaft's torque $G I_p\,\theta_x$ turns the disk,
   $J_d = m R^2/2$ = {{ si.J_d }} kg·m² ($m$ = {{ m }}, $R$ = {{ R }}):
   $-G I_p\,\theta_x = J_d\,\theta_{tt}$, so with $\omega = c_T k$,
   $G I_p\,k\cos(kL) = J_d\,c_T^2 k^2\sin(kL)$, that is
   $$kL\,\tan(kL) = \frac{\rho I_p L}{J_d} = \frac{J_s}{J_d}$$
   = {{ si.ratio }}. Its roots are $k_1 L$ = {{ si.kL1 }} in $(0, \pi/2)$ and
   $k_2 L$ = {{ si.kL2 }} in $(\pi, 3\pi/2)$; $f_j = c_T k_j/(2\pi)$:
   $f_1$ = {{ answers.f1 }} and $f_2$ = {{ answers.f2 }}.

**Check.** A massless shaft, $J_s \to 0$, would give
$\sqrt{G I_p/(L J_d)}/(2\pi)$ = {{ checks.massless_shaft }} Hz, above {{ answers.f1 }}:
the shaft's own inertia lowers the frequency.
""",
    solve=solve,
    checks=(
        # the shaft as a chain of N lumped inertias and springs, numpy's eigen-solver
        Recompute("f1", lambda p, s: _chain(p, s)[0], name="lumped_chain_first", rtol=1e-4),
        Recompute("f2", lambda p, s: _chain(p, s)[1], name="lumped_chain_second", rtol=1e-4),
        # a massless shaft (rho -> 0): a torsional spring G I_p / L turning the disk
        Limit("f1", {"rho": 1e-6}, lambda p: np.sqrt(p.G * np.pi * p.d**4 / 32 / p.L / (p.m * p.R**2 / 2))
              / (2 * np.pi), name="massless_shaft", rtol=1e-6),
    ),
    figure=figure,
    parts=(
        Numeric("J_s", "shaft's mass moment of inertia", question=1, unit="kg*m^2", points=1,
                misconceptions=(
                    Misconception("I (bending) for I_p", lambda p: p.rho * stiffness.circle_second_moment(p.d) * p.L,
                                  "About its own axis a round shaft has J = rho I_p L with I_p = pi d^4/32."),)),
        Numeric("f1", "lowest natural frequency", question=2, unit="Hz", points=2,
                misconceptions=(
                    Misconception("shaft's inertia neglected", _massless_shaft,
                                  "The shaft's own inertia lowers the frequency: solve kL tan(kL) = J_s/J_d."),
                    Misconception("disk forgotten c/(4L)", lambda p: _c(p) / (4 * p.L),
                                  "The disk's inertia sets the boundary condition at the free end: kL tan(kL) = J_s/J_d."),
                    Misconception("J_d = m R^2", lambda p: vibrations.frequency_in_hertz(rods.tip_mass_natural_frequencies(
                        _c(p), p.L, _J_shaft(p), p.m * p.R**2, 1)[0]), "A homogeneous disk has J_d = m R^2/2."),
                )),
        Numeric("f2", "second natural frequency", question=2, unit="Hz", points=2,
                misconceptions=(
                    Misconception("three times f1", lambda p: 3 * solve(p)["f1"],
                                  "3 f1 holds for a free end only; with the disk solve kL tan(kL) = J_s/J_d again, root in (pi, 3 pi/2)."),
                    Misconception("fixed-free 3c/(4L)", lambda p: 3 * _c(p) / (4 * p.L),
                                  "The disk changes the end condition: root of kL tan(kL) = J_s/J_d in (pi, 3 pi/2)."),
                )),
    ),
)
