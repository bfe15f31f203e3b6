"""A hinged bar with a tip mass, held horizontal by a spring between hinge and tip:
equivalent mass and stiffness, natural frequency and static deflection of the tip
(Section 4.3.1)."""

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric, Uniform,
                                per_draw)
from dynagrade.exercise.apart import numbers_apart
from dynagrade.exercise.checks import Integrated, Recompute
from dynagrade.exercise.figure import block, describe, dimension, ground, new_drawing, pivot, \
    spring
from dynagrade.mechanics import inertia, vibrations

# the tip moves x, the bar's centre x/2, the spring's end a x/L; the bar turns x/L


def _bar_about_hinge(p):
    return inertia.parallel_axis_moment(inertia.inertia_tensor_rod(p.m_b, p.L)[0, 0], p.m_b,
                                        p.L / 2)


@per_draw
def solve(p):
    m_eq = vibrations.equivalent_mass([p.m, _bar_about_hinge(p)], [1.0, 1.0 / p.L])
    k_eq = vibrations.equivalent_stiffness([p.k], [p.a / p.L])
    return {"m_eq": m_eq, "k_eq": k_eq,
            "f": vibrations.frequency_in_hertz(vibrations.natural_frequency(k_eq, m_eq)),
            "delta": vibrations.equivalent_weight([p.m, p.m_b], [1.0, 0.5], p.g) / k_eq}


def _apart(p):
    """The answers in the parts' units (delta in mm) differ by 5 % or more."""
    s = solve(p)
    return numbers_apart((s["m_eq"], s["k_eq"], s["f"], 1e3 * s["delta"]))


def _swing(t, y, p):
    """Moments about the hinge, measured from the static position (the weights balance the
    spring's preload): (m L^2 + m_b L^2/3) phi'' = -k a^2 phi, phi = x/L."""
    return (y[1], -p.k * p.a**2 * y[0] / ((p.m + p.m_b / 3) * p.L**2))


def figure(p):
    """The bar to scale: hinged at the left, the spring a from the hinge down to the floor,
    the tip mass at L; the floor's distance is not given and is drawn as 0.35 L."""
    drawing, axes = new_drawing(4.4, 2.4)
    L, floor = p.L, -0.35 * p.L
    wall_top = 0.0
    pivot(axes, (0.0, wall_top), 0.04 * L)
    axes.plot([0.0, L], [0.0, 0.0], color="0.2", lw=3.0)
    spring(axes, (p.a, floor), (p.a, 0.0), coils=6, width=0.05 * L)
    ground(axes, p.a - 0.12 * L, p.a + 0.12 * L, y=floor, hatch=0.03 * L)
    block(axes, (L, 0.05 * L), 0.1 * L, 0.1 * L, "m")
    axes.text(0.5 * L, 0.03 * L, "$m_b$", ha="center", va="bottom", fontsize=10)
    axes.text(p.a + 0.05 * L, floor / 2, "k", ha="left", va="center", fontsize=10)
    dimension(axes, (0.0, 0.0), (p.a, 0.0), "a", offset=-0.45 * L, tick=0.02 * L, side=-1.0)
    dimension(axes, (0.0, 0.0), (L, 0.0), "L", offset=0.25 * L, tick=0.02 * L)
    describe(axes, "The bar is hinged at its left end and horizontal at rest; the spring "
             "stands vertically under it on the floor, and the tip mass sits on its right end.")
    axes.set_xlim(-0.15 * L, 1.15 * L)
    axes.set_ylim(-0.5 * L, 0.35 * L)
    return drawing


EXERCISE = Exercise(
    id="hinged-bar-tip-mass",
    title="Hinged bar with a tip mass on a spring: equivalent mass and stiffness",
    source="Section 4.3.1",
    topics=("equivalent mass", "equivalent stiffness", "natural frequency", "static deflection"),
    params=(
        Uniform("m", 0.5, 10.0, step=0.1, unit="kg", symbol="m"),
        Uniform("m_b", 0.5, 10.0, step=0.1, unit="kg", symbol="m_b"),
        Uniform("L", 0.5, 2.0, step=0.05, unit="m", symbol="L"),
        Uniform("a", 0.1, 1.8, step=0.05, unit="m", symbol="a"),
        Uniform("k", 1000, 50000, step=500, unit="N/m", symbol="k"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        # below 0.9 L the "ratio not squared" and "spring at the tip" slips are 10 % off
        Constraint("the spring sits between 20 % and 90 % of the bar's length from the hinge",
                   lambda p: 0.2 * p.L <= p.a <= 0.9 * p.L),
        Constraint("the bar weighs at least a quarter of the tip mass (it is not negligible)",
                   lambda p: p.m_b >= 0.25 * p.m),
        Constraint("the answers differ by at least 5 %", _apart),
    ),
    statement="""
A uniform bar of mass $m_b$ = {{ m_b }} and length $L$ = {{ L }} is hinged at its left end
and carries a small mass $m$ = {{ m }} at its right end. A vertical spring of stiffness
$k$ = {{ k }}, standing on the floor, supports it at the distance $a$ = {{ a }} from the
hinge and holds it horizontal at rest; $g$ = {{ g }}. Let $x$ be the small vertical
displacement of the tip from this rest position.

1. What is the equivalent mass $m_{eq}$ with $T = m_{eq}\\dot x^2/2$?
2. What is the equivalent stiffness $k_{eq}$ with $V = k_{eq} x^2/2$ (measured from the
   rest position)?
3. What is the natural frequency $f$ in Hz of small vertical vibrations?
4. By how much did the tip sink when the bar and the mass were put onto the relaxed
   spring (the static deflection of the tip)?
""",
    solution=r"""
One degree of freedom, the tip's displacement $x$; the bar turns by $\varphi = x/L$, its
centre sinks $x/2$ and the spring's end $a\,x/L$. Writing $T$ and $V$ in $x$ gives the
equivalent mass and stiffness, $\omega = \sqrt{k_{eq}/m_{eq}}$ (Section 4.3.1).

1. **Equivalent mass.** About the hinge the bar has $J_O = \tfrac{1}{3} m_b L^2$:
   $$T = \tfrac12 m\dot x^2 + \tfrac12\cdot\tfrac{1}{3} m_b L^2\Bigl(\frac{\dot x}{L}\Bigr)^2
   \quad\Rightarrow\quad m_{eq} = m + \frac{m_b}{3}$$
   = {{ answers.m_eq }} ($m$ = {{ m }}, $m_b$ = {{ m_b }}).
2. **Equivalent stiffness.** The spring is compressed $a\,x/L$ more than at rest (the
   weights and the spring's preload cancel in the motion about the rest position):
   $$V = \tfrac12 k\Bigl(\frac aL x\Bigr)^2 \quad\Rightarrow\quad k_{eq} = k\frac{a^2}{L^2}$$
   = {{ answers.k_eq }} ($k$ = {{ k }}, $a$ = {{ a }}, $L$ = {{ L }}).
3. **Natural frequency.** $f = \frac{1}{2\pi}\sqrt{k_{eq}/m_{eq}}$ = {{ answers.f }}.
4. **Static deflection.** The weights do the virtual work $\bigl(m + \tfrac{1}{2} m_b\bigr) g\,\delta x$
   (the bar's centre moves half as far as the tip), and the spring's generalized force is
   $k_{eq} x$, so
   $$\delta = \frac{(m + m_b/2)\,g}{k_{eq}}$$
   = {{ answers.delta }}. **Check.** Unlike a single mass on a spring, here
   $\omega^2 \ne g/\delta$: the bar's weight counts with the factor $1/2$, its inertia with
   $1/3$. The moment equation about the hinge, integrated over one swing, gives back
   $f$ = {{ checks.integrated_swing }} Hz.
""",
    solve=solve,
    checks=(
        Recompute("m_eq", lambda p, s: p.m + p.m_b / 3, name="energy_by_hand"),
        Recompute("delta", lambda p, s: (p.m * p.L + p.m_b * p.L / 2) * p.g / (p.k * p.a)
                  * p.L / p.a, name="moment_balance"),
        # released from a small tilt: back at rest one period (1/f) later
        Integrated("f", _swing, lambda p: (1e-3, 0.0), lambda p, s: 3 / s["f"],
                   lambda t, y, p: 1 / t, name="integrated_swing",
                   event=lambda t, y, p: y[1], direction=-1, rtol=1e-4),
    ),
    figure=figure,
    figure_to_scale=True,
    parts=(
        Numeric("m_eq", "equivalent mass", question=1, unit="kg", points=1, misconceptions=(
            Misconception("the bar's whole mass", lambda p: p.m + p.m_b,
                          "The bar's points move less than the tip: T_bar = J_O phi'^2/2 with J_O = m_b L^2/3."),
            Misconception("inertia about the centre", lambda p: p.m + p.m_b / 12,
                          "The bar turns about the hinge: J_O = m_b L^2/3 (parallel axes)."),
        )),
        Numeric("k_eq", "equivalent stiffness", question=2, unit="N/m", points=1,
                misconceptions=(
                    Misconception("ratio not squared", lambda p: p.k * p.a / p.L,
                                  "V = k (a x/L)^2/2: the lever ratio enters squared."),
                    Misconception("spring at the tip", lambda p: p.k,
                                  "The spring's end moves only a/L times as far as the tip."),
                )),
        Numeric("f", "natural frequency", question=3, unit="Hz", points=2, misconceptions=(
            Misconception("omega for f", lambda p: 2 * np.pi * solve(p)["f"], "f = omega/(2 pi)."),
            Misconception("sqrt(g/delta)", lambda p: np.sqrt(p.g / solve(p)["delta"]) / (2 * np.pi),
                          "omega^2 = g/delta holds for a single mass only; use k_eq/m_eq.",
                          applies=lambda p: (p.m + p.m_b / 2) / (p.m + p.m_b / 3) > 1.045),
        )),
        Numeric("delta", "static deflection of the tip", question=4, unit="mm", points=1,
                misconceptions=(
                    Misconception("bar's weight at the tip",
                                  lambda p: (p.m + p.m_b) * p.g / solve(p)["k_eq"],
                                  "The bar's weight acts at its centre, which moves half as far as the tip."),
                    Misconception("the spring's compression",
                                  lambda p: solve(p)["delta"] * p.a / p.L,
                                  "The spring's end sinks a/L of the tip's deflection; the tip's is asked."),
                )),
    ),
)
