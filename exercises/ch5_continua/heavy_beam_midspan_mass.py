"""A heavy simply supported beam with a mass at midspan: effective beam mass and Rayleigh's
estimate of the fundamental frequency (Section 5.2)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.apart import answers_apart
from dynagrade.exercise.checks import Limit, Recompute
from dynagrade.exercise.figure import block, describe, new_drawing, simply_supported_beam
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import continua, stiffness, vibrations


def _k(p):
    return stiffness.simply_supported_midspan_stiffness(
        p.E, stiffness.rectangle_second_moment(p.b, p.h), p.L)


def _m_b(p):
    return p.rho * p.b * p.h * p.L


def _f(p, m_extra):
    return vibrations.frequency_in_hertz(continua.rayleigh_frequency(_k(p), p.m, m_extra))


@per_draw
def solve(p):
    m_eff = continua.simply_supported_effective_mass(_m_b(p))
    return {"m_eff": m_eff, "f": _f(p, m_eff), "m_b": _m_b(p), "k": _k(p),
            "share": continua.simply_supported_effective_mass(1.0),
            "I": stiffness.rectangle_second_moment(p.b, p.h),
            "omega": continua.rayleigh_frequency(_k(p), p.m, m_eff)}


def _static_strain(p, g=9.81):
    """Largest bending strain under the weights at rest: midspan moment m g L/4 + m_b g L/8
    over the section modulus b h^2/6, divided by E."""
    moment = p.m * g * p.L / 4 + _m_b(p) * g * p.L / 8
    return moment / (p.b * p.h**2 / 6) / p.E


def _static_shape(x, L):
    """Deflection under a midspan load, normalized to 1 at midspan (symmetric):
    psi = (3 x/L - 4 (x/L)^3) for x <= L/2 (Section 5.2)."""
    s = np.minimum(x, L - x) / L
    return 3 * s - 4 * s**3


def _effective_mass_by_quadrature(p, solved):
    """m_eff = int rho A psi^2 dx with the static midspan-load shape (Section 5.2)."""
    from scipy.integrate import quad

    value, _ = quad(lambda x: p.rho * p.b * p.h * _static_shape(x, p.L) ** 2, 0.0, p.L,
                    points=[p.L / 2], epsabs=0.0, epsrel=1e-12)
    return value


def _rayleigh_quotient_frequency(p, solved):
    """f from Rayleigh's quotient with the static shape, both integrals by quadrature:
    omega^2 = int E I psi''^2 dx / (m + int rho A psi^2 dx), psi'' = -24 x / L^3 on the
    left half (Section 5.2)."""
    from scipy.integrate import quad

    EI = p.E * p.b * p.h**3 / 12
    strain, _ = quad(lambda x: EI * (24 * x / p.L**3) ** 2, 0.0, p.L / 2, epsabs=0.0, epsrel=1e-12)
    kinetic = p.m + _effective_mass_by_quadrature(p, solved)
    return np.sqrt(2 * strain / kinetic) / (2 * np.pi)


def figure(p):
    """The beam on a pin and a roller, the mass at midspan; schematic."""
    L = p.L
    drawing, axes = new_drawing(5.0, 1.9)
    t = 0.03 * L
    simply_supported_beam(axes, L, t, f"L = {format_number(L)} m")
    block(axes, (L / 2, t / 2 + 0.04 * L), 0.08 * L, 0.08 * L, "m", color="C0")
    axes.text(L / 2, 0.11 * L, f"m = {format_number(p.m)} kg", ha="center", va="bottom",
              fontsize=10)
    axes.text(0.2 * L, 0.03 * L, f"b × h = {format_number(p.b * 1e3)} × {format_number(p.h * 1e3)} mm",
              ha="center", va="bottom", fontsize=9)
    axes.text(0.8 * L, 0.03 * L,
              f"E = {format_number(p.E / 1e9)} GPa, ρ = {format_number(p.rho)} kg/m³",
              ha="center", va="bottom", fontsize=9)
    describe(axes, "The mass sits on the beam halfway between the supports.")
    axes.set_xlim(-0.08 * L, 1.08 * L)
    axes.set_ylim(-0.2 * L, 0.18 * L)
    return drawing


EXERCISE = Exercise(
    id="heavy-beam-midspan-mass",
    title="Mass at the middle of a heavy simply supported beam: Rayleigh's estimate",
    source="Section 5.2",
    topics=("effective mass", "Rayleigh's method", "beam stiffness"),
    params=(
        Uniform("E", 10, 210, step=10, unit="GPa", symbol="E"),
        Uniform("rho", 500, 7900, step=100, unit="kg/m^3", symbol=r"\rho"),
        Uniform("b", 40, 200, step=10, unit="mm", symbol="b"),
        Uniform("h", 10, 60, step=2, unit="mm", symbol="h"),
        Uniform("L", 1.0, 4.0, step=0.1, unit="m", symbol="L"),
        Uniform("m", 5, 120, step=1, unit="kg", symbol="m"),
    ),
    constraints=(
        Constraint("a real structural material (wood, concrete, aluminium, steel): "
                   "sqrt(E/rho) between 3 and 5.5 km/s",
                   lambda p: 3e3 <= np.sqrt(p.E / p.rho) <= 5.5e3),
        Constraint("the beam stays elastic: the static bending strain is at most 0.05 %",
                   lambda p: _static_strain(p) <= 5e-4),
        Constraint("the beam weighs 20 % to 300 % of the mass", lambda p: 0.2 <= _m_b(p) / p.m <= 3),
        Constraint("a fundamental frequency between 2 Hz and 100 Hz",
                   lambda p: 2 <= solve(p)["f"] <= 100),
        Constraint("the effective mass in kg and the frequency in Hz differ by over 10 %",
                   lambda p: answers_apart(solve(p), {"m_eff": 1.0, "f": 1.0})),
    ),
    statement="""
A uniform beam of length $L$ = {{ L }} rests on a pin at one end and a roller at the
other. Its rectangular section is $b$ = {{ b }} wide and $h$ = {{ h }} high (bent about the
width); its material has $E$ = {{ E }} and density $\\rho$ = {{ rho }}. A compact mass
$m$ = {{ m }} is fixed at midspan; the beam stays elastic. Assume that the beam vibrates in the shape of its static
deflection under a midspan load.

1. Which effective mass does the beam add at midspan?
2. Estimate the fundamental frequency (in Hz) of the vertical vibrations.
""",
    solution=r"""
Rayleigh's method: in the assumed shape $\psi(x)$, normalized to 1 at midspan, the beam's
kinetic energy is that of an effective mass $m_{\mathrm{eff} } = \int_0^L \rho A\,\psi^2\,dx$
moving with $m$; its stiffness is that of the massless beam (effective mass, Section 5.2).

1. **Effective mass.** A midspan load bends the beam into
   $\psi = 3x/L - 4x^3/L^3$ for $x \le L/2$ (and symmetrically), so
   $$m_{\mathrm{eff} } = 2\rho A L\int_0^{1/2}(3s - 4s^3)^2\,ds ,$$
   {{ si.share }} of the beam's mass $\rho b h L$ = {{ si.m_b }} kg ($\rho$ = {{ rho }},
   $b$ = {{ b }}, $h$ = {{ h }}, $L$ = {{ L }}): $m_{\mathrm{eff} }$ = {{ answers.m_eff }}.
2. **Fundamental frequency.** The midspan stiffness is that of the massless beam: each
   half is a cantilever of length $L/2$, clamped at midspan and loaded by half the force, so
   $k = 2\cdot 3EI/(L/2)^3$ with $I = b h^3/12$ = {{ si.I }} m⁴: $k$ = {{ si.k }} N/m
   ($E$ = {{ E }}). With $m$ = {{ m }},
   $$\omega \approx \sqrt{\frac{k}{m + m_{\mathrm{eff} } } }$$
   = {{ si.omega }} rad/s, and $f = \omega/(2\pi)$ = {{ answers.f }}. The estimate lies a
   little above the true fundamental frequency, as every Rayleigh estimate does.

**Check.** Without the beam's mass the same beam would give
$\sqrt{k/m}/(2\pi)$ = {{ checks.massless_beam }} Hz, higher than {{ answers.f }}: the
beam's mass slows the vibration.
""",
    solve=solve,
    checks=(
        # m_eff = int rho A psi^2 dx with the static midspan-load shape, by quadrature
        Recompute("m_eff", _effective_mass_by_quadrature, name="effective_mass_by_quadrature"),
        Recompute("f", _rayleigh_quotient_frequency, name="rayleigh_quotient"),
        # a massless beam: omega = sqrt(48 E I / L^3 / m)
        Limit("f", {"rho": 0.0},
              lambda p: np.sqrt(48 * p.E * p.b * p.h**3 / 12 / p.L**3 / p.m) / (2 * np.pi),
              name="massless_beam"),
    ),
    figure=figure,
    parts=(
        Numeric("m_eff", "effective beam mass at midspan", question=1, unit="kg", points=2,
                misconceptions=(
                    Misconception("cantilever's 33/140", lambda p: continua.cantilever_effective_mass(_m_b(p)),
                                  "33/140 belongs to a cantilever's tip; a simply supported beam loaded at midspan gives 17/35 of its mass."),
                    Misconception("a third of the beam", lambda p: _m_b(p) / 3,
                                  "m/3 belongs to a linear shape (a spring); integrate rho A psi^2 with the beam's bending shape."),
                    Misconception("the whole beam", _m_b,
                                  "Parts of the beam near the supports hardly move: m_eff = int rho A psi^2 dx = 17/35 rho A L."),
                )),
        Numeric("f", "fundamental frequency", question=2, unit="Hz", points=2,
                misconceptions=(
                    Misconception("beam mass neglected", lambda p: _f(p, 0.0),
                                  "Add the beam's effective mass 17/35 rho A L to m."),
                    Misconception("whole beam mass added", lambda p: _f(p, _m_b(p)),
                                  "Only the effective mass 17/35 rho A L moves with m."),
                    Misconception("omega for f", lambda p: solve(p)["omega"], "f = omega/(2 pi)."),
                )),
    ),
)
