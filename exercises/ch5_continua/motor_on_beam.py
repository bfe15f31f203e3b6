"""A motor at the middle of a simply supported beam: static deflection, natural frequency
and whether it runs above or below resonance (Section 5.1)."""

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric, Options,
                                Uniform, per_draw)
from dynagrade.exercise.checks import Recompute
from dynagrade.exercise.figure import block, describe, new_drawing, simply_supported_beam
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import stiffness, vibrations


def _I(p, b=None, h=None):
    return stiffness.rectangle_second_moment(p.b if b is None else b, p.h if h is None else h)


@per_draw
def _k(p):
    return stiffness.simply_supported_midspan_stiffness(p.E, _I(p), p.L)


def _delta(k, p):
    return vibrations.static_deflection(p.m, k, p.g)


def _f(k, p):
    return vibrations.frequency_in_hertz(vibrations.natural_frequency(k, p.m))


@per_draw
def solve(p):
    omega_n = vibrations.natural_frequency(_k(p), p.m)
    Omega = p.n  # the speed in rpm, given to the solver in SI: rad/s
    return {"delta": _delta(_k(p), p), "f": _f(_k(p), p),
            "regime": "above resonance" if Omega > omega_n else "below resonance",
            "I": _I(p), "k": _k(p), "omega_n": omega_n, "Omega": Omega,
            "eta": vibrations.frequency_ratio(Omega, omega_n)}


def figure(p):
    """The beam on a pin (left) and a roller (right), the motor at midspan; schematic."""
    L = p.L
    drawing, axes = new_drawing(5.0, 1.9)
    t = 0.02 * L
    simply_supported_beam(axes, L, t, f"L = {format_number(L)} m")
    block(axes, (L / 2, t / 2 + 0.05 * L), 0.14 * L, 0.1 * L, "m", color="C0")
    axes.text(L / 2, 0.13 * L, f"m = {format_number(p.m)} kg,  n = {format_number(p.n * 60 / (2 * np.pi))} rpm",
              ha="center", va="bottom", fontsize=10)
    # the beam's data on either side of the motor (one line across it ran into the block)
    axes.text(0.22 * L, 0.03 * L, f"E = {format_number(p.E / 1e9)} GPa", ha="center",
              va="bottom", fontsize=9)
    axes.text(0.78 * L, 0.03 * L, f"b × h = {format_number(p.b * 1e3)} × {format_number(p.h * 1e3)} mm",
              ha="center", va="bottom", fontsize=9)
    describe(axes, "The motor sits on the beam halfway between the supports.")
    axes.set_xlim(-0.08 * L, 1.08 * L)
    axes.set_ylim(-0.2 * L, 0.2 * L)
    return drawing


EXERCISE = Exercise(
    id="motor-on-simply-supported-beam",
    title="Motor at the middle of a simply supported beam: static sag and resonance",
    source="Section 5.1",
    topics=("beam stiffness", "static deflection", "natural frequency", "resonance"),
    params=(
        Uniform("E", 70, 210, step=10, unit="GPa", symbol="E"),
        Uniform("b", 40, 120, step=5, unit="mm", symbol="b"),
        Uniform("h", 10, 40, step=1, unit="mm", symbol="h"),
        Uniform("L", 0.8, 3.0, step=0.1, unit="m", symbol="L"),
        Uniform("m", 5, 80, step=1, unit="kg", symbol="m"),
        Uniform("n", 200, 1800, step=50, unit="rpm", symbol="n"),
        Constant("g", 9.81, unit="m/s^2"),
    ),
    constraints=(
        Constraint("a static sag between 0.2 mm and 5 mm",
                   lambda p: 2e-4 <= solve(p)["delta"] <= 5e-3),
        Constraint("the running speed is at least 15 % away from resonance",
                   lambda p: abs(solve(p)["eta"] - 1) >= 0.15),
    ),
    statement="""
An electric motor of mass $m$ = {{ m }} is bolted to the middle of a horizontal beam of
length $L$ = {{ L }} that rests on a pin at one end and a roller at the other. The beam has
a rectangular section of width $b$ = {{ b }} and height $h$ = {{ h }} (bent about the
width) and Young's modulus $E$ = {{ E }}; neglect its mass and the motor's size. Take
$g$ = {{ g }}.

1. How far does the motor's weight deflect the middle of the beam?
2. What is the natural frequency (in Hz) of the motor's vertical vibrations?
3. The motor runs at $n$ = {{ n }}; a small unbalance shakes the beam at that speed. Does
   it run above or below resonance?
""",
    solution=r"""
The massless beam is a spring under the motor: its midspan deflection $w$ is
proportional to the force there, $F = k w$, so the motor moves as a mass on a spring,
$m\ddot w + k w = 0$ (massless deformable bodies, Section 5.1).

1. **Static deflection.** By symmetry the beam does not turn at midspan, so each half is
   a cantilever of length $L/2$ clamped there and loaded at its free end by the support's
   reaction $F/2$: a midspan force $F$ lowers the middle by $(F/2)(L/2)^3/(3EI)$ relative
   to the supports, so the midspan stiffness is
   $$k = 2\cdot\frac{3 E I}{(L/2)^3} .$$
   With $I = b h^3/12$ = {{ si.I }} m⁴ ($b$ = {{ b }}, $h$ = {{ h }}), $E$ = {{ E }} and
   $L$ = {{ L }}: $k$ = {{ si.k }} N/m, and the weight deflects the middle by
   $\delta_{st} = m g/k$ = {{ answers.delta }}.
2. **Natural frequency.** $\omega_n = \sqrt{k/m}$ = {{ si.omega_n }} rad/s, so
   $$f_n = \frac{1}{2\pi}\sqrt{\frac{k}{m} } = \frac{1}{2\pi}\sqrt{\frac{g}{\delta_{st} } },$$
   $f_n$ = {{ answers.f }}.
3. **Running speed.** $n$ = {{ n }} is $\Omega$ = {{ si.Omega }} rad/s; the
   frequency ratio is $\eta = \Omega/\omega_n$ = {{ si.eta }}, so the motor runs
   **{{ answers.regime }}**.

**Check.** From the sag alone, $\sqrt{g/\delta_{st} }/(2\pi)$ = {{ checks.from_static_sag }} Hz,
the same frequency: a beam that sags more vibrates more slowly.
""",
    solve=solve,
    checks=(
        # Section 5.1: omega_n^2 = k/m = g/delta_st, read from the sag alone
        Recompute("f", lambda p, s: np.sqrt(p.g / s["delta"]) / (2 * np.pi), name="from_static_sag"),
        # midspan deflection of a simply supported beam, F L^3/(48 E I), I = b h^3/12
        Recompute("delta", lambda p, s: p.m * p.g * p.L**3 / (48 * p.E * p.b * p.h**3 / 12),
                  name="beam_deflection_by_hand"),
    ),
    figure=figure,
    parts=(
        Numeric("delta", "static deflection at midspan", question=1, unit="mm", points=2,
                misconceptions=(
                    Misconception("cantilever 3EI/L^3", lambda p: _delta(stiffness.cantilever_tip_stiffness(p.E, _I(p), p.L), p),
                                  "The beam is supported at both ends and loaded at midspan: k = 48 E I / L^3."),
                    Misconception("b and h swapped", lambda p: _delta(
                        stiffness.simply_supported_midspan_stiffness(p.E, _I(p, p.h, p.b), p.L), p),
                                  "Bent about the width b: I = b h^3/12.",
                                  applies=lambda p: abs(np.log(p.b / p.h)) > 0.02),
                    Misconception("mass for weight", lambda p: p.m / _k(p),
                                  "The static load is the weight m g: delta = m g / k."),
                )),
        Numeric("f", "natural frequency", question=2, unit="Hz", points=2,
                misconceptions=(
                    Misconception("omega for f", lambda p: vibrations.natural_frequency(_k(p), p.m),
                                  "sqrt(k/m) is the angular frequency in rad/s; f = omega/(2 pi)."),
                    Misconception("clamped ends 192EI/L^3", lambda p: _f(stiffness.clamped_midspan_stiffness(p.E, _I(p), p.L), p),
                                  "A pin and a roller do not hold the ends' slope: k = 48 E I / L^3."),
                )),
        Options("regime", "running speed relative to resonance", question=3,
                options=("below resonance", "above resonance"), points=1),
    ),
)
