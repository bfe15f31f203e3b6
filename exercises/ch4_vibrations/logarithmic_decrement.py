"""Identifying damping from a measured decay: logarithmic decrement, damping ratio,
stiffness and damping coefficient (Section 4.3.2)."""

import numpy as np

from dynagrade.exercise import (Choice, Constraint, Exercise, Misconception, Numeric, Uniform,
                                per_draw)
from dynagrade.exercise.checks import Integrated, Limit, Recompute
from dynagrade.mechanics import vibrations


def _identified(p):
    delta = vibrations.logarithmic_decrement_from_amplitudes(p.x0, p.xn, p.n)
    zeta = vibrations.damping_ratio_from_decrement(delta)
    w = vibrations.natural_frequency_from_damped(vibrations.angular_frequency_from_period(p.Td), zeta)
    return delta, zeta, w


def solve(p):
    delta, zeta, w = _identified(p)
    k = vibrations.stiffness_from_natural_frequency(p.m, w)
    return {"delta": delta, "zeta": zeta, "omega_n": w, "k": k,
            "c": vibrations.damping_coefficient(zeta, k, p.m),
            "omega_d": vibrations.angular_frequency_from_period(p.Td)}


@per_draw
def _zeta(p):
    return _identified(p)[1]


def _identified_oscillator(t, y, p):
    """The damped oscillator the identified keys describe, m x'' + c x' + k x = 0
    (Section 4.3.2), with the solver's k and c."""
    return (y[1], -(p.c * y[1] + p.k * y[0]) / p.m)


def _decay_horizon(p, solved):
    """Longer than one damped period."""
    return 3 * p.Td


def _next_peak(t, y, p):
    """The velocity, which crosses zero downward at each peak."""
    return y[1]


def _at_a_peak(p):
    """Released from rest at x = 1: a peak."""
    return (1.0, 0.0)


EXERCISE = Exercise(
    id="logarithmic-decrement-measurement",
    title="Damping from a measured decay",
    source="Section 4.3.2",
    topics=("logarithmic decrement", "damping ratio", "system identification"),
    params=(
        Uniform("m", 1.0, 100.0, step=1.0, unit="kg", symbol="m"),
        Uniform("x0", 5.0, 30.0, step=0.5, unit="mm", symbol="x_0"),
        Uniform("xn", 0.2, 20.0, step=0.1, unit="mm", symbol="x_n"),
        Choice("n", (2, 3, 4, 5), symbol="n"),
        Uniform("Td", 0.05, 2.0, step=0.01, unit="s", symbol="T_d"),
    ),
    constraints=(
        # zeta >= 0.15 keeps the small-damping shortcuts more than 1 % off
        Constraint("0.15 <= zeta <= 0.5", lambda p: 0.15 <= _zeta(p) <= 0.5),
    ),
    statement="""
A machine part of mass $m$ = {{ m }}, mounted elastically with some viscous damping, is
knocked and its free decay recorded. One peak of the displacement is $x_0$ = {{ x0 }};
the peak $n$ = {{ n.value }} periods later is $x_n$ = {{ xn }}. The time between
successive peaks is $T_d$ = {{ Td }}.

1. What is the logarithmic decrement $\\delta$?
2. What is the damping ratio $\\zeta$ (exactly, from $\\delta$, without the small-damping
   approximation)?
3. What is the undamped natural angular frequency $\\omega_n$?
4. What are the stiffness $k$ and the damping coefficient $c$ of the mounting?
""",
    solution=r"""
A viscously damped oscillator decays so that successive peaks shrink by the same factor
$e^{\delta}$; from $\delta$ and the measured period we recover $\zeta$, $\omega_n$, $k$ and $c$
(logarithmic decrement, Section 4.3.2).

1. **Logarithmic decrement.** Over $n$ periods the peaks shrink by $e^{n\delta}$, so
   $$\delta = \frac1n\ln\frac{x_0}{x_n};$$
   with $x_0$ = {{ x0 }}, $x_n$ = {{ xn }} and $n$ = {{ n.value }}: $\delta$ = {{ answers.delta }}.
2. **Damping ratio.** $\delta = 2\pi\zeta/\sqrt{1 - \zeta^2}$, solved for $\zeta$:
   $$\zeta = \frac{\delta}{\sqrt{4\pi^2 + \delta^2} },$$
   that is $\zeta$ = {{ answers.zeta }}.
3. **Natural frequency.** The peaks come at the damped period:
   $\omega_d = 2\pi/T_d$ = {{ si.omega_d }} rad/s ($T_d$ = {{ Td }}). With
   $\omega_d = \omega_n\sqrt{1 - \zeta^2}$,
   $$\omega_n = \frac{\omega_d}{\sqrt{1 - \zeta^2} },$$
   that is $\omega_n$ = {{ answers.omega_n }}.
4. **Stiffness and damping.** With $m$ = {{ m }}: $k = m\,\omega_n^2$, so $k$ = {{ answers.k }},
   and $c = 2\zeta\sqrt{k m}$, so $c$ = {{ answers.c }}.
5. **Check.** Without decay ($x_n = x_0$, so $\zeta = 0$) the measured frequency would be
   the natural one, $2\pi/T_d$ = {{ checks.undamped }} rad/s, below the $\omega_n$ found.
""",
    solve=solve,
    checks=(
        # released at a peak (x = 1, x' = 0), the identified oscillator must peak again
        # after the measured period T_d and have shrunk by e^delta
        Integrated("omega_d", _identified_oscillator, _at_a_peak, _decay_horizon,
                   lambda t, y, p: 2 * np.pi / t, name="identified_period",
                   event=_next_peak, direction=-1, from_keys=("k", "c")),
        Integrated("delta", _identified_oscillator, _at_a_peak, _decay_horizon,
                   lambda t, y, p: -np.log(y[0]), name="identified_decay",
                   event=_next_peak, direction=-1, from_keys=("k", "c")),
        # no decay (x_n -> x_0): no damping, and omega_n is the measured 2 pi / T_d
        Limit("omega_n", {"xn": 1.0, "x0": 1.0}, lambda p: 2 * np.pi / p.Td, name="undamped"),
        # the identified oscillator must shrink by the measured x_n / x_0 after n periods
        Recompute("delta", lambda p, s: np.log(p.x0 / p.xn) / p.n, name="measured_decay"),
    ),
    parts=(
        Numeric("delta", "logarithmic decrement", question=1, points=1,
                misconceptions=(Misconception("not divided by n", lambda p: np.log(p.x0 / p.xn),
                                              "delta is the log ratio per period: divide ln(x0/xn) by n."),)),
        Numeric("zeta", "damping ratio", question=2, points=2,
                misconceptions=(Misconception("small-damping approximation", lambda p: _identified(p)[0] / (2 * np.pi),
                                              "zeta = delta / sqrt(4 pi^2 + delta^2); delta/(2 pi) holds only for small damping."),)),
        Numeric("omega_n", "natural angular frequency", question=3, unit="rad/s", points=1,
                misconceptions=(
                    Misconception("damped frequency for omega_n", lambda p: 2 * np.pi / p.Td,
                                  "The measured period is the damped one: omega_n = omega_d / sqrt(1 - zeta^2)."),
                    Misconception("1/T_d", lambda p: 1 / p.Td, "omega_d = 2 pi / T_d."),
                )),
        Numeric("k", "stiffness", question=4, unit="N/m", points=1,
                misconceptions=(Misconception("from the damped frequency", lambda p: p.m * (2 * np.pi / p.Td) ** 2,
                                              "k = m omega_n^2 with the undamped omega_n."),)),
        Numeric("c", "damping coefficient", question=4, unit="N*s/m", points=1,
                misconceptions=(Misconception("c = zeta sqrt(k m)", lambda p: solve(p)["c"] / 2,
                                              "c = 2 zeta sqrt(k m) = 2 zeta m omega_n."),)),
    ),
)
