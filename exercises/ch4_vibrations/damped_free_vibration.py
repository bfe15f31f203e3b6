"""A mass-spring-damper left to itself: natural frequency, damping ratio, damped frequency,
and the damping regime a second damper gives (Section 4.3.2).

The oscillator itself is kept underdamped (it has a damped frequency and a decrement to
ask for); the regime is asked of a second damper c2, drawn on both sides of the critical
damping, so that the class's answers differ (issue 31: it used to be "underdamped" for
everybody)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Options, Uniform
from dynagrade.exercise.checks import Integrated, Limit, Recompute
from dynagrade.exercise.figure import arrow, block, damper, ground, new_drawing, spring, wall
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import vibrations


def zeta(p):
    return vibrations.damping_ratio(p.c, p.k, p.m)


def zeta2(p):
    """The damping ratio with the second damper c2."""
    return vibrations.damping_ratio(p.c2, p.k, p.m)


def figure(p):
    """The oscillator of Section 4.3.2: a mass on a smooth floor tied to a wall by a spring
    and a viscous damper in parallel, with its displacement x from the rest position.
    Nothing here has a given length, so the sketch is drawn in fixed proportions."""
    drawing, axes = new_drawing(4.4, 1.9)
    wall(axes, 0.0, 0.0, 1.2, side=-1.0, hatch=0.08)
    ground(axes, 0.0, 3.6, hatch=0.08)
    left, size = 2.0, 1.0
    spring(axes, (0.0, 0.78), (left, 0.78), coils=6, width=0.22)
    damper(axes, (0.0, 0.42), (left, 0.42), width=0.24)
    block(axes, (left + size / 2, size / 2), size, size, f"m = {format_number(p.m)} kg")
    axes.text(left / 2, 0.93, f"k = {format_number(p.k)} N/m", ha="center", va="bottom",
              fontsize=10)
    axes.text(left / 2, 0.27, f"c = {format_number(p.c)} N·s/m", ha="center", va="top",
              fontsize=10)
    axes.plot([left + size / 2] * 2, [size + 0.05, size + 0.3], color="0.3", lw=0.8)
    arrow(axes, (left + size / 2, size + 0.2), (left + size / 2 + 0.6, size + 0.2),
          color="C3")
    axes.text(left + size / 2 + 0.68, size + 0.2, "x", color="C3", ha="left", va="center",
              fontsize=10)
    axes.set_xlim(-0.2, 3.7)
    axes.set_ylim(-0.15, 1.3)
    return drawing


def solve(p):
    w = vibrations.natural_frequency(p.k, p.m)
    wd = vibrations.damped_frequency(w, zeta(p))
    return {"omega_n": w, "zeta": zeta(p), "omega_d": wd, "T_d": vibrations.period(wd),
            "regime": vibrations.damping_regime(zeta2(p)),
            "delta": vibrations.logarithmic_decrement(zeta(p)),
            # intermediate quantity of the worked solution
            "c_cr": vibrations.critical_damping(p.k, p.m), "zeta2": zeta2(p)}


def _oscillator(t, y, p):
    """m x'' + c x' + k x = 0 (Section 4.3.2)."""
    return (y[1], -(p.c * y[1] + p.k * y[0]) / p.m)


def _horizon(p, solved):
    return 3 * 2 * np.pi * np.sqrt(p.m / p.k) / np.sqrt(max(1e-12, 1 - p.c**2 / (4 * p.k * p.m)))


def _peak(t, y, p):
    """The velocity crosses zero downward at each peak."""
    return y[1]


def _at_a_peak(p):
    """Released from rest at x = 1: a peak."""
    return (1.0, 0.0)


EXERCISE = Exercise(
    id="damped-free-vibration",
    title="Mass-spring-damper: free damped vibration",
    source="Section 4.3.2",
    topics=("free vibration", "damping ratio", "damped frequency", "logarithmic decrement"),
    params=(
        Uniform("m", 0.5, 50.0, step=0.5, unit="kg", symbol="m"),
        Uniform("k", 200, 20000, step=100, unit="N/m", symbol="k"),
        Uniform("c", 2, 800, step=2, unit="N*s/m", symbol="c"),
        Uniform("c2", 20, 3000, step=10, unit="N*s/m", symbol="c_2"),
    ),
    constraints=(
        Constraint("underdamped with 0.2 <= zeta <= 0.7",
                   lambda p: 0.2 <= vibrations.damping_ratio(p.c, p.k, p.m) <= 0.7),
        Constraint("the second damper is clearly under- or overdamped: 0.2 <= zeta2 <= 0.8 "
                   "or 1.25 <= zeta2 <= 4", lambda p: 0.2 <= zeta2(p) <= 0.8 or 1.25 <= zeta2(p) <= 4),
    ),
    statement="""
A mass $m$ = {{ m }} on a spring of stiffness $k$ = {{ k }} is connected to a viscous
damper with coefficient $c$ = {{ c }}. It is displaced and released.

1. What are the undamped natural angular frequency $\\omega_n$ and the damping ratio $\\zeta$?
2. What are the damped angular frequency $\\omega_d$ and the period $T_d$ of the decaying oscillation?
3. The damper is exchanged for one with coefficient $c_2$ = {{ c2 }}. Which regime is the
   oscillator in then: undamped, underdamped, critically damped or overdamped?
4. What is the logarithmic decrement $\\delta$ between successive peaks?
""",
    solution=r"""
The mass is displaced by $x$ from its rest position; the spring pulls back with $k x$, the
damper with $c \dot x$. Linear momentum balance gives the equation of motion of
Section 4.3.1, $m \ddot x + c \dot x + k x = 0$, or, divided by $m$,
$\ddot x + 2 \zeta \omega_n \dot x + \omega_n^2 x = 0$ (Section 4.3.2).

1. Comparing the two forms: $\omega_n = \sqrt{k/m}$ = {{ answers.omega_n }}. The critical
   damping is $c_{\mathrm{cr}} = 2\sqrt{k m}$ = {{ si.c_cr }} N·s/m, and the damping ratio
   $\zeta = c/c_{\mathrm{cr}} = c/(2\sqrt{k m})$ = {{ answers.zeta }}.
2. For $\zeta < 1$ the solution is $x(t) = e^{-\zeta \omega_n t}(A \cos \omega_d t + B \sin \omega_d t)$
   with the damped angular frequency $\omega_d = \omega_n \sqrt{1 - \zeta^2}$ = {{ answers.omega_d }}
   and the period $T_d = 2\pi/\omega_d$ = {{ answers.T_d }}.
3. The regime follows from the damping ratio alone. With $c_2$ = {{ c2 }} it is
   $\zeta_2 = c_2/c_{\mathrm{cr}}$ = {{ si.zeta2 }}, {% if answers.regime == "underdamped" %}between 0 and 1:
   the motion is **{{ answers.regime }}**, it oscillates with an amplitude that decays like
   $e^{-\zeta_2 \omega_n t}${% else %}above 1: the motion is **{{ answers.regime }}**,
   the mass creeps back to rest without oscillating{% endif %}.
4. Successive peaks are one period $T_d$ apart, so their ratio is
   $e^{\zeta \omega_n T_d}$ and the logarithmic decrement is
   $\delta = \zeta \omega_n T_d = 2\pi\zeta/\sqrt{1 - \zeta^2}$ = {{ answers.delta }}.
5. **Check.** Without damping ($c \to 0$) the oscillator would swing at
   $\omega_d = \omega_n$ = {{ checks.undamped }} rad/s; damping only slows it.
""",
    solve=solve,
    checks=(
        # released at a peak, the next peak comes one damped period later, e^delta lower
        Integrated("T_d", _oscillator, _at_a_peak, _horizon, lambda t, y, p: t,
                   name="integrated_period", event=_peak, direction=-1),
        Integrated("delta", _oscillator, _at_a_peak, _horizon,
                   lambda t, y, p: -np.log(y[0]), name="integrated_decay", event=_peak,
                   direction=-1),
        Recompute("zeta", lambda p, s: p.c / (2 * np.sqrt(p.k * p.m)), name="c_over_c_critical"),
        # c -> 0: the damped frequency is the natural one
        Limit("omega_d", {"c": 0.0}, lambda p: np.sqrt(p.k / p.m), name="undamped"),
    ),
    figure=figure,
    parts=(
        Numeric("omega_n", "natural angular frequency", question=1, unit="rad/s", points=1,
                misconceptions=(Misconception("f for omega", lambda p: np.sqrt(p.k / p.m) / (2 * np.pi),
                                              "omega_n = sqrt(k/m) is in rad/s."),)),
        Numeric("zeta", "damping ratio", question=1, points=1,
                misconceptions=(
                    Misconception("c / sqrt(k m)", lambda p: p.c / np.sqrt(p.k * p.m),
                                  "The critical damping is c_cr = 2 sqrt(k m)."),
                    Misconception("decay rate c/(2m) for zeta", lambda p: p.c / (2 * p.m),
                                  "c/(2m) = zeta omega_n is the decay rate in 1/s; zeta is dimensionless."),
                )),
        Numeric("omega_d", "damped angular frequency", question=2, unit="rad/s", points=1,
                misconceptions=(Misconception("undamped frequency", lambda p: np.sqrt(p.k / p.m),
                                              "Damping slows the oscillation: omega_d = omega_n sqrt(1 - zeta^2)."),)),
        Numeric("T_d", "damped period", question=2, unit="s", points=1,
                misconceptions=(Misconception("1/omega_d", lambda p: 1 / vibrations.damped_frequency(
                    np.sqrt(p.k / p.m), zeta(p)), "T_d = 2 pi / omega_d."),)),
        Options("regime", "damping regime with the second damper", question=3,
                options=("undamped", "underdamped", "critically damped", "overdamped"), points=1),
        Numeric("delta", "logarithmic decrement", question=4, points=1,
                misconceptions=(Misconception("small-damping approximation 2 pi zeta", lambda p: 2 * np.pi * zeta(p),
                                              "delta = 2 pi zeta / sqrt(1 - zeta^2) exactly; 2 pi zeta only for small zeta."),)),
    ),
)
