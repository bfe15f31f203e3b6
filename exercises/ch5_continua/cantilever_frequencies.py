"""Natural frequencies of a cantilever from its characteristic equation (Section 5.3.3)."""

import numpy as np

from dynagrade.exercise import Exercise, Misconception, Numeric, Constraint, Uniform
from dynagrade.exercise.checks import Balance, Recompute
from dynagrade.mechanics import beams, stiffness, vibrations


def _EI(p, b=None, h=None):
    return p.E * stiffness.rectangle_second_moment(b or p.b, h or p.h)


def _rhoA(p):
    return p.rho * p.b * p.h


def _f(p, support="cantilever", n=2, EI=None):
    return vibrations.frequency_in_hertz(beams.beam_natural_frequencies(EI or _EI(p), _rhoA(p), p.L, support, n))


def solve(p):
    f = _f(p)
    roots = beams.beam_eigenvalues("cantilever", 2)
    return {"beta1": roots[0] / p.L, "f1": f[0], "f2": f[1], "beta1L": roots[0],
            "beta2L": roots[1], "EI": _EI(p), "rhoA": _rhoA(p)}


def _root(n):
    """The n-th root of the clamped-free frequency equation cos(x) cosh(x) = -1
    (Section 5.3.3), found here near (n - 1/2) pi, where cos(x) vanishes."""
    from scipy.optimize import brentq

    return brentq(lambda x: np.cos(x) + 1 / np.cosh(x), (n - 0.5) * np.pi - 1, (n - 0.5) * np.pi + 0.5)


def _frequency(n):
    """f_n = (beta_n L)^2 / (2 pi L^2) sqrt(E I / (rho A)), I = b h^3 / 12, A = b h."""
    return lambda p, s: _root(n) ** 2 / (2 * np.pi * p.L**2) * np.sqrt(p.E * p.h**2 / (12 * p.rho))


EXERCISE = Exercise(
    id="cantilever-natural-frequencies",
    title="Natural frequencies of a cantilever",
    source="Section 5.3.3",
    topics=("flexural vibration", "Euler-Bernoulli beam", "characteristic equation"),
    params=(
        Uniform("E", 70, 210, step=5, unit="GPa", symbol="E"),
        Uniform("rho", 2700, 7900, step=100, unit="kg/m^3", symbol=r"\rho"),
        Uniform("b", 20, 80, step=1, unit="mm", symbol="b"),
        Uniform("h", 2, 15, step=0.5, unit="mm", symbol="h"),
        Uniform("L", 0.2, 2.0, step=0.05, unit="m", symbol="L"),
    ),
    constraints=(
        Constraint("a flat strip (b at least 1.5 h)", lambda p: p.b >= 1.5 * p.h),
    ),
    statement="""
A flat strip of width $b$ = {{ b }}, thickness $h$ = {{ h }} and length $L$ = {{ L }}
($E$ = {{ E }}, $\\rho$ = {{ rho }}) is clamped at one end and free at the other, and
vibrates in bending across its thickness (Euler–Bernoulli beam).

1. What is the smallest positive wavenumber $\\beta_1$ (in 1/m) that satisfies the
   characteristic equation $\\cos(\\beta L)\\cosh(\\beta L) + 1 = 0$?
2. What are the two lowest natural frequencies $f_1$ and $f_2$ (in Hz)?
""",
    solution=r"""
Free bending vibrations of a uniform Euler–Bernoulli beam obey
$EI\,w'''' + \rho A\,\ddot w = 0$; separating $w = W(x)\cos\omega t$ gives
$W'''' = \beta^4 W$ with $\beta^4 = \rho A\,\omega^2/(EI)$, and the boundary conditions pick
the admissible $\beta$ (flexural vibration, Section 5.3.3).

1. **Characteristic equation.** At the clamped end $W = W' = 0$, at the free end
   $W'' = W''' = 0$ (no moment, no shear force). A non-zero solution exists only if
   $$\cos(\beta L)\cosh(\beta L) + 1 = 0 .$$
   Since $\cosh$ grows fast, the higher roots approach the zeros of $\cos(\beta L)$;
   the lowest ones must be found numerically: the first root is $\beta_1 L$ =
   {{ si.beta1L }}, the same for every clamped-free beam, the second $\beta_2 L$ =
   {{ si.beta2L }}. With $L$ = {{ L }}, $\beta_1 = (\beta_1 L)/L$ = {{ answers.beta1 }}.
2. **Natural frequencies.** Solving $\beta^4 = \rho A\,\omega^2/(EI)$ for $\omega$:
   $$\omega_j = \frac{(\beta_j L)^2}{L^2}\sqrt{\frac{EI}{\rho A} },\qquad f_j = \frac{\omega_j}{2\pi}.$$
   The strip bends across its thickness, so $I = b h^3/12$ and $EI$ = {{ si.EI }} N·m²;
   $\rho A = \rho b h$ = {{ si.rhoA }} kg/m (with $b$ = {{ b }}, $h$ = {{ h }}, $E$ = {{ E }},
   $\rho$ = {{ rho }}). With $L$ = {{ L }}: $f_1$ = {{ answers.f1 }} and
   $f_2$ = {{ answers.f2 }}, not an integer multiple of $f_1$.
""",
    solve=solve,
    checks=(
        Balance("cos(beta1 L) + 1 / cosh(beta1 L)", lambda p, s: 0.0,
                lambda p, s: np.cos(s["beta1L"]) + 1 / np.cosh(s["beta1L"]),
                name="frequency_equation", atol=1e-9),
        Recompute("beta1", lambda p, s: _root(1) / p.L, name="first_root_over_L"),
        Recompute("f1", _frequency(1), name="first_root"),
        Recompute("f2", _frequency(2), name="second_root"),
    ),
    parts=(
        Numeric("beta1", "first wavenumber beta_1", question=1, unit="1/m", points=1, rtol=1e-3,
                misconceptions=(
                    Misconception("pi/2", lambda p: np.pi / 2 / p.L,
                                  "pi/2 is the root of cos alone; cosh shifts it to "
                                  "beta_1 L = 1.875."),
                    Misconception("the clamped-clamped root", lambda p: 4.7300 / p.L,
                                  "4.730 is the first root of cos cosh = +1 (both ends "
                                  "clamped); a free end gives cos cosh = -1."),
                )),
        Numeric("f1", "first natural frequency", question=2, unit="Hz", points=2,
                misconceptions=(
                    Misconception("simply supported", lambda p: _f(p, "simply supported")[0],
                                  "The clamped-free beam has beta_1 L = 1.875, not pi."),
                    Misconception("omega for f", lambda p: 2 * np.pi * _f(p)[0], "f = omega/(2 pi)."),
                    Misconception("b and h swapped in I", lambda p: _f(p, EI=_EI(p, b=p.h, h=p.b))[0],
                                  "Bending across the thickness: I = b h^3/12."),
                )),
        Numeric("f2", "second natural frequency", question=2, unit="Hz", points=1,
                misconceptions=(Misconception("twice f1", lambda p: 2 * _f(p)[0],
                                              "Beam frequencies are not harmonics: f2/f1 = (4.694/1.875)^2 = 6.27."),)),
    ),
)
