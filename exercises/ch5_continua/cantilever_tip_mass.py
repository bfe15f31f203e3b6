"""A heavy beam carrying a tip mass: effective beam mass and Rayleigh's estimate (Section 5.2)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.checks import Limit, Recompute
from dynagrade.mechanics import continua, stiffness, vibrations


def _k(p):
    return stiffness.cantilever_tip_stiffness(p.E, stiffness.circle_second_moment(p.d), p.L)


@per_draw
def _m_b(p):
    return p.rho * stiffness.circle_area(p.d) * p.L


def _f(m_extra, p):
    return vibrations.frequency_in_hertz(continua.rayleigh_frequency(_k(p), p.m, m_extra))


def solve(p):
    return {"m_eff": continua.cantilever_effective_mass(_m_b(p)),
            "f": _f(continua.cantilever_effective_mass(_m_b(p)), p),
            "m_b": _m_b(p), "I": stiffness.circle_second_moment(p.d), "k": _k(p),
            "omega": continua.rayleigh_frequency(_k(p), p.m, continua.cantilever_effective_mass(_m_b(p)))}


def _tip_stiffness(p):
    """3 E I / L^3 with I = pi d^4 / 64 (Section 5.2)."""
    return 3 * p.E * np.pi * p.d**4 / 64 / p.L**3


EXERCISE = Exercise(
    id="cantilever-tip-mass-rayleigh",
    title="Cantilever with a tip mass: effective beam mass",
    source="Section 5.2",
    topics=("effective mass", "Rayleigh's method", "beam stiffness"),
    params=(
        Uniform("E", 70, 210, step=10, unit="GPa", symbol="E"),
        Uniform("rho", 2700, 7900, step=100, unit="kg/m^3", symbol=r"\rho"),
        Uniform("d", 10, 40, step=1, unit="mm", symbol="d"),
        Uniform("L", 0.5, 2.0, step=0.05, unit="m", symbol="L"),
        Uniform("m", 0.5, 10, step=0.1, unit="kg", symbol="m"),
    ),
    constraints=(
        Constraint("the beam weighs 30 % to 300 % of the tip mass", lambda p: 0.3 <= _m_b(p) / p.m <= 3),
    ),
    statement="""
A round bar (diameter $d$ = {{ d }}, length $L$ = {{ L }}, $E$ = {{ E }},
density $\\rho$ = {{ rho }}) is clamped horizontally at one end and carries a small mass
$m$ = {{ m }} at the other. Assume it vibrates in the shape of its static deflection under a
tip load.

1. Which effective mass does the bar add at its tip?
2. Estimate the fundamental frequency (in Hz) of vertical vibrations.
""",
    solution=r"""
Rayleigh's method: assume the bar vibrates in the shape of its static deflection under a
tip load, so its kinetic energy is that of an effective mass moving with the tip; then the
system is one mass on the tip spring (effective mass and Rayleigh's estimate, Section 5.2).

1. **Effective mass.** The bar's mass is $m_b = \rho\,\frac{\pi d^2}{4}\,L$ = {{ si.m_b }} kg
   ($d$ = {{ d }}, $L$ = {{ L }}, $\rho$ = {{ rho }}). With the static tip-load shape
   $w(x) = w_L\,\frac{x^2(3L - x)}{2L^3}$ the kinetic energy
   $\tfrac{1}{2}\int_0^L \rho A\,\dot w^2\,dx$ equals $\tfrac{1}{2} m_{\mathrm{eff} }\dot w_L^2$ with
   $$m_{\mathrm{eff} } = \frac{\rho A}{w_L^2}\int_0^L w^2\,dx,$$
   which evaluates to {{ answers.m_eff }}, about a quarter of $m_b$: the parts near the
   clamp hardly move.
2. **Fundamental frequency.** The tip stiffness is $k = 3EI/L^3$ with
   $I = \frac{\pi}{4}\bigl(\frac d2\bigr)^4$ = {{ si.I }} m⁴, so with $E$ = {{ E }}:
   $k$ = {{ si.k }} N/m. With the tip mass $m$ = {{ m }},
   $$\omega \approx \sqrt{\frac{k}{m + m_{\mathrm{eff} } } },$$
   here $\omega$ = {{ si.omega }} rad/s, and $f = \omega/(2\pi)$ = {{ answers.f }}.
3. **Check.** Were the beam massless ($\rho \to 0$), the tip mass alone would give
   $\sqrt{k/m}/(2\pi)$ = {{ checks.massless_beam }} Hz: the beam's own mass lowers the frequency.
""",
    solve=solve,
    checks=(
        # Rayleigh's static deflection shape gives the beam 33/140 of its mass at the tip
        Recompute("f", lambda p, s: np.sqrt(_tip_stiffness(p) / (p.m + 33 / 140 * p.rho * np.pi * p.d**2 / 4 * p.L))
                  / (2 * np.pi), name="rayleigh_by_hand"),
        # a massless beam: the spring-mass frequency
        Limit("f", {"rho": 0.0}, lambda p: np.sqrt(_tip_stiffness(p) / p.m) / (2 * np.pi),
              name="massless_beam"),
    ),
    parts=(
        Numeric("m_eff", "effective beam mass", question=1, unit="kg", points=2,
                misconceptions=(
                    Misconception("a third (as for a spring)", lambda p: _m_b(p) / 3,
                                  "The static deflection of a cantilever is cubic: m_eff = 33/140 m_b."),
                    Misconception("the whole beam", _m_b, "Most of the beam moves less than its tip."),
                )),
        Numeric("f", "fundamental frequency", question=2, unit="Hz", points=2,
                misconceptions=(
                    Misconception("beam mass forgotten", lambda p: _f(0.0, p), "Add 33/140 of the beam's mass."),
                    Misconception("whole beam mass", lambda p: _f(_m_b(p), p), "Only 33/140 of the beam's mass is effective."),
                    Misconception("omega for f", lambda p: 2 * np.pi * solve(p)["f"], "f = omega/(2 pi)."),
                )),
    ),
)
