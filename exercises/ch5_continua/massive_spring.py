"""A mass on a spring whose own mass matters: Rayleigh's effective mass (Section 5.2)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Symbolic, Uniform
from dynagrade.exercise.checks import Limit, Recompute
from dynagrade.mechanics import continua, rods, vibrations


def omega(p):
    return continua.rayleigh_frequency(p.k, p.m, continua.spring_effective_mass(p.m_s))


def solve(p):
    # the spring as a continuous bar with a tip mass: c = L sqrt(k/m_s), so omega = kL sqrt(k/m_s)
    exact = rods.tip_mass_fundamental_frequency(np.sqrt(p.k / p.m_s), 1.0, p.m_s, p.m)
    return {"m_eff": continua.spring_effective_mass(p.m_s), "f": vibrations.frequency_in_hertz(omega(p)),
            "error": omega(p) / exact - 1, "omega": omega(p), "omega_exact": exact}


def _exact(p, solved):
    """The spring as a bar with the mass at its end (Section 5.2): x tan(x) = m_s / m,
    omega = x sqrt(k / m_s)."""
    from scipy.optimize import brentq

    x = brentq(lambda x: x * np.tan(x) - p.m_s / p.m, 1e-12, np.pi / 2 - 1e-12)
    return x * np.sqrt(p.k / p.m_s)


EXERCISE = Exercise(
    id="effective-mass-of-a-spring",
    title="Mass on a heavy spring: effective mass",
    source="Section 5.2",
    topics=("effective mass", "Rayleigh's method", "natural frequency"),
    params=(
        Uniform("m", 0.2, 5.0, step=0.1, unit="kg", symbol="m"),
        Uniform("m_s", 0.05, 2.0, step=0.05, unit="kg", symbol="m_s"),
        Uniform("k", 50, 3000, step=10, unit="N/m", symbol="k"),
    ),
    constraints=(
        Constraint("the spring weighs 15 % to 80 % of the mass", lambda p: 0.15 <= p.m_s / p.m <= 0.8),
    ),
    statement="""
A mass $m$ = {{ m }} hangs on a uniform helical spring of stiffness $k$ = {{ k }} whose own
mass is $m_s$ = {{ m_s }}. Assume the spring's coils move with a velocity that grows
linearly from the fixed end to the mass.

1. What effective mass does the spring add to $m$?
2. What are the natural frequency (in Hz) and the natural angular frequency of vertical vibrations?
3. Treating the spring as a continuous elastic bar of length $L$, along which longitudinal
   waves travel at $c = L\\sqrt{k/m_s}$, the exact lowest angular frequency is
   $\\omega_{\\text{exact}} = c\\,\\kappa$, where $\\kappa$ (the wavenumber) is the smallest
   positive root of $\\kappa L\\tan(\\kappa L) = m_s/m$. By what relative amount does your
   estimate exceed it ($\\omega_{\\text{est}}/\\omega_{\\text{exact}} - 1$)?
4. Give $\\omega$ of part 2 as a formula in `k`, `m`, `m_s`.
""",
    solution=r"""
Rayleigh's method: with the assumed linear velocity profile the spring's kinetic energy is
that of an effective mass moving with $m$ (effective mass, Section 5.2).

1. **Effective mass.** A coil at distance $s$ from the fixed end (spring length $L$) moves
   with $\dot x\,s/L$, so
   $$T_s = \tfrac{1}{2}\int_0^L \frac{m_s}{L}\Bigl(\frac{s}{L}\,\dot x\Bigr)^2 ds = \tfrac{1}{2}\,\frac{m_s}{3}\,\dot x^2 ,$$
   and $m_{\mathrm{eff} } = m_s/3$ = {{ answers.m_eff }} ($m_s$ = {{ m_s }}).
2. **Natural frequency.** One mass $m + m_s/3$ on the spring $k$:
   $$\omega = \sqrt{\frac{k}{m + m_s/3} };$$
   with $m$ = {{ m }} and $k$ = {{ k }}: $\omega$ = {{ answers.omega }} and
   $f = \omega/(2\pi)$ = {{ answers.f }}.
3. **Compared with the continuous bar.** The root of $\kappa L\tan(\kappa L) = m_s/m$ in
   $(0, \pi/2)$ gives the exact $\omega_{\mathrm{exact} } = c\,\kappa$ = {{ si.omega_exact }} rad/s,
   where $c = L\sqrt{k/m_s}$ is the spring's wave speed. The estimate exceeds it by
   $\omega/\omega_{\mathrm{exact} } - 1$ = {{ answers.error }}: Rayleigh's method, with an
   assumed shape, always errs high, and very little while $m_s < m$.
4. **As a formula.** `{{ answers.omega_formula }}`.
""",
    solve=solve,
    checks=(
        Recompute("omega_exact", _exact, name="frequency_equation"),
        Recompute("omega", lambda p, s: np.sqrt(p.k / (p.m + p.m_s / 3)), name="a_third_of_the_spring"),
        # a light spring: the error of the third vanishes
        Limit("error", {"m_s": 1e-6}, lambda p: 0.0, name="light_spring", atol=1e-9),
    ),
    parts=(
        Numeric("m_eff", "effective spring mass", question=1, unit="kg", points=1,
                misconceptions=(Misconception("half the spring", lambda p: p.m_s / 2,
                                              "T = int (m_s/L) (x'/L * xi)^2/2 dxi = (m_s/3) x'^2/2."),)),
        Numeric("f", "natural frequency", question=2, unit="Hz", points=2,
                misconceptions=(
                    Misconception("spring mass forgotten", lambda p: vibrations.frequency_in_hertz(np.sqrt(p.k / p.m)),
                                  "Add the spring's effective mass m_s/3."),
                    Misconception("whole spring mass", lambda p: vibrations.frequency_in_hertz(np.sqrt(p.k / (p.m + p.m_s))),
                                  "Only a third of the spring's mass is effective: its coils move slower than the mass."),
                    Misconception("omega for f", omega, "f = omega/(2 pi)."),
                )),
        Numeric("error", "relative error of the estimate", question=3, points=1, rtol=0.02),
        Numeric("omega", "natural angular frequency", question=2, unit="rad/s", points=1,
                misconceptions=(Misconception("f for omega", lambda p: omega(p) / (2 * np.pi), "omega = 2 pi f."),)),
        Symbolic("omega_formula", "omega as a formula", question=4,
                 points=1, expected="sqrt(k/(m + m_s/3))",
                 variables=("k", "m", "m_s"),
                 equals="omega",
                 misconceptions=(Misconception("spring mass forgotten", "sqrt(k/m)", "Add m_s/3."),)),
    ),
)
