"""A mass on a cantilever and a spring: series and parallel springs (Section 5.1)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.checks import Recompute
from dynagrade.mechanics import stiffness, vibrations


@per_draw
def k_beam(p):
    return stiffness.cantilever_tip_stiffness(p.E, stiffness.rectangle_second_moment(p.b, p.h), p.L)


def _f(k, m):
    return vibrations.frequency_in_hertz(vibrations.natural_frequency(k, m))


def solve(p):
    return {"k_b": k_beam(p), "f_series": _f(stiffness.series_stiffness(k_beam(p), p.k), p.m),
            "f_parallel": _f(stiffness.parallel_stiffness(k_beam(p), p.k), p.m),
            "I": stiffness.rectangle_second_moment(p.b, p.h),
            "k_series": stiffness.series_stiffness(k_beam(p), p.k),
            "k_parallel": stiffness.parallel_stiffness(k_beam(p), p.k)}


def _beam(p):
    """A cantilever's tip stiffness 3 E I / L^3 with I = b h^3 / 12 (Section 5.1)."""
    return 3 * p.E * p.b * p.h**3 / 12 / p.L**3


EXERCISE = Exercise(
    id="cantilever-spring-mass",
    title="Mass on a cantilever and a spring: series or parallel",
    source="Section 5.1",
    topics=("equivalent stiffness", "springs in series", "springs in parallel", "beam stiffness"),
    params=(
        Uniform("E", 70, 210, step=10, unit="GPa", symbol="E"),
        Uniform("b", 20, 60, step=1, unit="mm", symbol="b"),
        Uniform("h", 3, 12, step=0.5, unit="mm", symbol="h"),
        Uniform("L", 0.3, 1.2, step=0.05, unit="m", symbol="L"),
        Uniform("k", 500, 20000, step=100, unit="N/m", symbol="k"),
        Uniform("m", 1, 20, step=0.5, unit="kg", symbol="m"),
    ),
    constraints=(
        Constraint("spring and beam are comparable (ratio 0.2 to 5)", lambda p: 0.2 <= p.k / k_beam(p) <= 5),
    ),
    statement="""
A horizontal metal cantilever (Young's modulus $E$ = {{ E }}, length $L$ = {{ L }},
rectangular section of width $b$ = {{ b }} and height $h$ = {{ h }}, bent about the width)
is used to support a mass $m$ = {{ m }}. Neglect the beam's mass.

1. What is the beam's stiffness $k_b$ for a vertical force at its tip?
2. The mass hangs from the tip on a spring of stiffness $k$ = {{ k }}. What is the natural
   frequency of vertical vibrations (in Hz)?
3. Instead, the mass is fixed to the tip and the same spring connects it to the ground
   below. What is the natural frequency now?
""",
    solution=r"""
Each arrangement is one mass on one equivalent spring; what matters is whether the beam and
the spring carry the same force (series) or deform by the same amount (parallel)
(equivalent stiffness, Section 5.1).

1. **Tip stiffness of the beam.** A cantilever under a tip force $F$ deflects
   $w = F L^3/(3EI)$, so
   $$k_b = \frac{3 E I}{L^3},\qquad I = \frac{b h^3}{12},$$
   where $I$ = {{ si.I }} m⁴ (bent about the width, $b$ = {{ b }}, $h$ = {{ h }}). With $E$ = {{ E }}
   and $L$ = {{ L }}: $k_b$ = {{ answers.k_b }}.
2. **Mass hanging on the spring.** Beam and spring carry the same force and their
   deflections add: springs in series,
   $$\frac{1}{k_s} = \frac{1}{k_b} + \frac{1}{k},$$
   so with $k$ = {{ k }}, $k_s$ = {{ si.k_series }} N/m and with $m$ = {{ m }}
   $$f = \frac{1}{2\pi}\sqrt{\frac{k_s}{m} },$$
   that is $f$ = {{ answers.f_series }}. The softer element dominates.
3. **Spring to the ground.** The mass's displacement deflects the beam and the spring by
   the same amount and both push back: springs in parallel, $k_p = k_b + k$ =
   {{ si.k_parallel }} N/m, and $f = \frac{1}{2\pi}\sqrt{k_p/m}$ = {{ answers.f_parallel }}.
""",
    solve=solve,
    checks=(
        Recompute("k_b", lambda p, s: _beam(p), name="tip_stiffness"),
        # in series the compliances add, in parallel the stiffnesses
        Recompute("f_series", lambda p, s: np.sqrt(1 / (1 / _beam(p) + 1 / p.k) / p.m) / (2 * np.pi),
                  name="compliances_add"),
        Recompute("f_parallel", lambda p, s: np.sqrt((_beam(p) + p.k) / p.m) / (2 * np.pi),
                  name="stiffnesses_add"),
    ),
    parts=(
        Numeric("k_b", "beam tip stiffness", question=1, unit="N/m", points=1,
                misconceptions=(
                    Misconception("b and h swapped", lambda p: stiffness.cantilever_tip_stiffness(
                        p.E, stiffness.rectangle_second_moment(p.h, p.b), p.L), "I = b h^3/12 for bending about the width b."),
                    Misconception("simply supported 48EI/L^3", lambda p: stiffness.simply_supported_midspan_stiffness(
                        p.E, stiffness.rectangle_second_moment(p.b, p.h), p.L), "A cantilever tip: k = 3 E I / L^3."),
                )),
        Numeric("f_series", "frequency, mass hanging on the spring", question=2,
                unit="Hz", points=2,
                misconceptions=(
                    Misconception("parallel instead of series", lambda p: solve(p)["f_parallel"],
                                  "Beam and spring carry the same force one after the other: they are in series, 1/k = 1/k_b + 1/k."),
                    Misconception("omega for f", lambda p: 2 * np.pi * solve(p)["f_series"], "f = omega/(2 pi)."),
                )),
        Numeric("f_parallel", "frequency, spring to the ground", question=3, unit="Hz", points=2,
                misconceptions=(Misconception("series instead of parallel", lambda p: solve(p)["f_series"],
                                              "Beam and spring deflect together with the mass: they act in parallel, k = k_b + k."),)),
    ),
)
