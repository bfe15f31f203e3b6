"""Liquid sloshing in a U-tube: equivalent mass and stiffness of the liquid column, the
period, and the largest speed after a release (Section 4.3.1)."""

import numpy as np

from dynagrade.exercise import (Choice, Constant, Constraint, Exercise, Misconception, Numeric,
                                Uniform, per_draw)
from dynagrade.exercise.apart import numbers_apart
from dynagrade.exercise.checks import Balance, Integrated, Recompute
from dynagrade.exercise.figure import describe, dimension, new_drawing
from dynagrade.mechanics import stiffness, vibrations


@per_draw
def solve(p):
    A = stiffness.circle_area(p.d)
    m_eq = vibrations.liquid_column_mass(p.rho, A, p.L)
    k_eq = vibrations.u_tube_stiffness(p.rho, A, p.g)
    w = vibrations.natural_frequency(k_eq, m_eq)
    # released with the levels h0 apart: the column is displaced x0 = h0/2 from equilibrium
    return {"m_eq": m_eq, "k_eq": k_eq, "T_period": vibrations.period(w), "v_max": w * p.h0 / 2,
            "omega": w}


def _slosh(t, y, p):
    """rho A L x'' = -2 rho g A x: the weight of the level difference 2x drives the column."""
    return (y[1], -2 * p.g * y[0] / p.L)


def _fair(p):
    """The answers (g, N/m, s, m/s) differ by 5 % or more."""
    s = solve(p)
    return numbers_apart((1e3 * s["m_eq"], s["k_eq"], s["T_period"], s["v_max"]))


def figure(p):
    """Schematic: the U-tube with the two surfaces h0 apart at the release, the liquid column
    length L measured along the tube's axis."""
    drawing, axes = new_drawing(2.8, 3.0)
    width, radius, height = 0.12, 0.5, 2.0
    s = np.linspace(np.pi, 2 * np.pi, 61)
    for r in (radius - width / 2, radius + width / 2):
        axes.plot(r * np.cos(s), r * np.sin(s), color="0.1", lw=1.5)
        axes.plot([-r, -r], [0.0, height], color="0.1", lw=1.5)
        axes.plot([r, r], [0.0, height], color="0.1", lw=1.5)
    left, right = 1.3, 0.8                               # the surfaces at the release
    for x, top in ((-radius, left), (radius, right)):
        axes.plot([x - width / 2, x + width / 2], [top, top], color="C0", lw=2.0)
        axes.plot([x, x], [0.0, top], color="C0", lw=0.8, ls="--")
    axes.plot(radius * np.cos(s), radius * np.sin(s), color="C0", lw=0.8, ls="--")
    dimension(axes, (radius + width, right), (radius + width, left), "h₀", offset=-0.25,
              tick=0.05, side=-1.0)
    axes.plot([radius + width / 2, radius + 0.5], [left, left], color="0.5", lw=0.6, ls=":")
    axes.text(0.0, -radius - 0.1, "column length L (dashed axis)", ha="center", va="top",
              fontsize=9)
    # d across the left leg's open top; the leg is too narrow for the label, which stands
    # outside it on the left
    dimension(axes, (-radius - width / 2, height - 0.3), (-radius + width / 2, height - 0.3))
    axes.text(-radius - width / 2 - 0.06, height - 0.3, "d", ha="right", va="center", fontsize=10)
    describe(axes, "The left surface stands h₀ higher than the right one at the release; "
             "the dashed line is the tube's axis, along which the liquid column's length L "
             "is measured.")
    axes.set_xlim(-1.0, 1.2)
    axes.set_ylim(-0.9, height + 0.15)
    return drawing


EXERCISE = Exercise(
    id="u-tube-liquid-column",
    title="Liquid sloshing in a U-tube: equivalent mass, stiffness and period",
    source="Section 4.3.1",
    topics=("equivalent mass", "equivalent stiffness", "natural frequency", "energy"),
    params=(
        Choice("rho", (800, 1000, 1260, 13546), unit="kg/m^3", symbol=r"\rho"),
        Uniform("d", 5, 30, step=1, unit="mm", symbol="d"),
        Uniform("L", 0.3, 2.0, step=0.05, unit="m", symbol="L"),
        Uniform("h0", 20, 200, step=5, unit="mm", symbol="h_0"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("the level difference is at most a fifth of the column (the column stays "
                   "in both legs)", lambda p: p.h0 <= 0.2 * p.L),
        Constraint("the answers differ by at least 5 %", _fair),
    ),
    statement="""
A U-tube of inner diameter $d$ = {{ d }} holds a liquid of density $\\rho$ = {{ rho }};
the liquid column is $L$ = {{ L }} long, measured along the tube's axis; $g$ = {{ g }}.
The liquid is pushed so that one surface stands $h_0$ = {{ h0 }} above the other, and is
released from rest. Neglect friction and surface tension; the whole column moves with one
speed. Let $x$ be the displacement of the liquid along the tube (one surface rises by $x$
while the other sinks by $x$).

1. What is the equivalent mass $m_{eq}$ with $T = m_{eq}\\dot x^2/2$?
2. What is the equivalent stiffness $k_{eq}$ with $V = k_{eq} x^2/2$?
3. What is the period of the oscillation?
4. What is the largest speed of the liquid?
""",
    solution=r"""
One degree of freedom, the column's displacement $x$ along the tube: write $T$ and $V$ in
$x$ to read off the equivalent mass and stiffness (Section 4.3.1). The cross-section is
$A = \pi d^2/4$.

1. **Equivalent mass.** All the liquid moves with the speed $\dot x$:
   $m_{eq} = \rho A L$ = {{ answers.m_eq }} ($\rho$ = {{ rho }}, $d$ = {{ d }}, $L$ = {{ L }}).
2. **Equivalent stiffness.** Displacing the column by $x$ moves a slice of length $x$ from
   the sinking leg to the top of the rising one, lifting its weight $\rho g A x$ by $x$:
   $$V = \rho g A x^2 = \tfrac{1}{2}(2\rho g A)\,x^2,\qquad k_{eq} = 2\rho g A$$
   = {{ answers.k_eq }}.
3. **Period.** $\omega = \sqrt{k_{eq}/m_{eq}} = \sqrt{2g/L}$ = {{ si.omega }} rad/s, independent
   of the liquid and the tube's width; $T = 2\pi/\omega$ = {{ answers.T_period }}.
4. **Largest speed.** The levels $h_0$ apart mean $x_0 = h_0/2$; the column passes
   $x = 0$ with $v_{\max} = \omega x_0$ = {{ answers.v_max }} ($h_0$ = {{ h0 }}).
   **Check.** Energy: $\tfrac12 k_{eq}x_0^2 = \tfrac12 m_{eq}v_{\max}^2$ =
   {{ checks.energy }} J.
""",
    solve=solve,
    checks=(
        Recompute("T_period", lambda p, s: 2 * np.pi * np.sqrt(p.L / (2 * p.g)), name="sqrt_L_over_2g"),
        # the potential energy of the raised slice h0/2, lifted by h0/2, becomes kinetic
        Balance("energy", lambda p, s: p.rho * p.g * np.pi * p.d**2 / 4 * (p.h0 / 2) ** 2,
                lambda p, s: p.rho * np.pi * p.d**2 / 4 * p.L * s["v_max"] ** 2 / 2, name="energy"),
        Integrated("v_max", _slosh, lambda p: (p.h0 / 2, 0.0), lambda p, s: 2 * s["T_period"],
                   lambda t, y, p: abs(y[1]), name="integrated_column",
                   event=lambda t, y, p: y[0], direction=-1),
    ),
    figure=figure,
    parts=(
        Numeric("m_eq", "equivalent mass", question=1, unit="g", points=1, misconceptions=(
            Misconception("diameter for radius", lambda p: p.rho * np.pi * p.d**2 * p.L,
                          "A = pi d^2/4 with the diameter d."),
        )),
        Numeric("k_eq", "equivalent stiffness", question=2, unit="N/m", points=2, misconceptions=(
            Misconception("one leg only", lambda p: p.rho * p.g * np.pi * p.d**2 / 4,
                          "Both surfaces move: the level difference is 2x, so k_eq = 2 rho g A."),
        )),
        Numeric("T_period", "period", question=3, unit="s", points=1, misconceptions=(
            Misconception("pendulum of length L", lambda p: 2 * np.pi * np.sqrt(p.L / p.g),
                          "omega^2 = k_eq/m_eq = 2g/L."),
            Misconception("1/omega", lambda p: 1 / solve(p)["omega"], "The period is 2 pi/omega."),
        )),
        Numeric("v_max", "largest speed", question=4, unit="m/s", points=1, misconceptions=(
            Misconception("h0 as the amplitude", lambda p: solve(p)["omega"] * p.h0,
                          "The level difference 2x0 = h0: the column's amplitude is h0/2."),
        )),
    ),
)
