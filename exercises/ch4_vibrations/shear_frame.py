"""A two-storey shear frame: storey stiffness from the columns, natural frequencies and
mode shapes (Section 4.4.2, with the column stiffness of Section 5.1)."""

import numpy as np

from dynagrade.exercise import Choice, Constraint, Exercise, Misconception, Numeric, Uniform
from dynagrade.exercise.checks import Recompute
from dynagrade.exercise.figure import arrow, block, dimension, ground, new_drawing
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import multi_dof, stiffness, vibrations


def storey_stiffness(p, per_column=None):
    k = per_column if per_column is not None else stiffness.column_sway_stiffness(p.E, p.I, p.h)
    return stiffness.parallel_stiffness(*([k] * int(p.n_col)))


def matrices(p, per_column=None):
    k = storey_stiffness(p, per_column)
    return multi_dof.chain_stiffness_matrix([k, k]), multi_dof.lumped_mass_matrix([p.m1, p.m2])


def figure(p):
    """The frame in elevation, storey heights to scale: two rigid floors on columns clamped
    into the ground and the floors, with the floor displacements x1, x2 (Section 4.4.2).
    The floors' width is not given and is drawn as 1.6 h."""
    h = p.h
    width, slab = 1.6 * h, 0.12 * h
    drawing, axes = new_drawing(4.4, 4.2)
    ground(axes, -0.35 * h, width + 0.35 * h, hatch=h / 25)
    for storey, (mass, name) in enumerate(((p.m1, "₁"), (p.m2, "₂"))):
        bottom = storey * h
        for x in (0.06 * h, width - 0.06 * h):
            axes.plot([x, x], [bottom, bottom + h - slab / 2], color="0.2", lw=2.0)
        block(axes, (width / 2, bottom + h), width, slab, color="0.55")
        axes.text(width / 2, bottom + h + slab / 2 + 0.04 * h,
                  f"m{name} = {format_number(mass)} kg", ha="center", va="bottom",
                  fontsize=10)
        arrow(axes, (width + 0.08 * h, bottom + h), (width + 0.45 * h, bottom + h),
              color="C3")
        axes.text(width + 0.5 * h, bottom + h, f"x{name}", color="C3", ha="left",
                  va="center", fontsize=10)
    dimension(axes, (0.0, 0.0), (0.0, h), f"h = {format_number(h)} m", offset=0.2 * h,
              tick=0.04 * h)
    dimension(axes, (0.0, h), (0.0, 2 * h), f"h = {format_number(h)} m", offset=0.2 * h,
              tick=0.04 * h)
    columns = (f"{int(p.n_col)} columns per storey, E = {format_number(p.E / 1e9)} GPa, "
               f"I = {format_number(p.I)} m⁴")
    axes.text(width / 2, -0.12 * h, columns, ha="center", va="top", fontsize=10)
    axes.set_xlim(-0.45 * h, width + 0.7 * h)
    axes.set_ylim(-0.3 * h, 2 * h + 0.35 * h)
    return drawing


def solve(p):
    K, M = matrices(p)
    w = multi_dof.natural_frequencies(K, M)
    ratios = multi_dof.amplitude_ratios(K, M)
    return {"k": storey_stiffness(p), "f1": vibrations.frequency_in_hertz(w[0]),
            "f2": vibrations.frequency_in_hertz(w[1]), "r1": ratios[1, 0], "r2": ratios[1, 1],
            "k_column": stiffness.column_sway_stiffness(p.E, p.I, p.h),
            "omega1": w[0], "omega2": w[1]}


def _f1(p, per_column=None):
    return vibrations.frequency_in_hertz(multi_dof.natural_frequencies(*matrices(p, per_column))[0])


def _storey(p):
    """n columns clamped at both ends, each 12 E I / h^3 (Section 4.4.2)."""
    return p.n_col * 12 * p.E * p.I / p.h**3


def _squares(p):
    """K = k [[2, -1], [-1, 1]], M = diag(m1, m2): m1 m2 w^4 - k (m1 + 2 m2) w^2 + k^2 = 0."""
    k = _storey(p)
    return np.sort(np.roots([p.m1 * p.m2, -k * (p.m1 + 2 * p.m2), k**2]).real)


EXERCISE = Exercise(
    id="two-storey-shear-frame",
    title="Two-storey shear frame: natural frequencies and mode shapes",
    source="Section 4.4.2",
    topics=("multi-DOF vibrations", "natural frequencies", "mode shapes", "shear frame"),
    params=(
        Uniform("m1", 2000, 20000, step=500, unit="kg", symbol="m_1"),
        Uniform("m2", 1000, 20000, step=500, unit="kg", symbol="m_2"),
        Choice("n_col", (2, 4), symbol="n"),
        Uniform("h", 2.5, 4.0, step=0.1, unit="m", symbol="h"),
        Uniform("E", 30, 210, step=10, unit="GPa", symbol="E"),
        Uniform("I", 1.0e-6, 5.0e-5, step=1e-6, unit="m^4", symbol="I"),
    ),
    constraints=(
        Constraint("the floors differ in mass by at least 10 %", lambda p: abs(p.m1 / p.m2 - 1) >= 0.1),
    ),
    statement="""
A two-storey frame has rigid floors of masses $m_1$ = {{ m1 }} (first floor) and
$m_2$ = {{ m2 }} (roof). Each storey stands on {{ n_col.value }} identical columns of
height $h$ = {{ h }}, Young's modulus $E$ = {{ E }} and second moment of area
$I$ = {{ I }}; the columns are clamped into the ground and into the rigid floors, so each
acts as a spring $12EI/h^3$ for the sway of its storey. Neglect the columns' mass and
consider horizontal floor displacements $x_1$, $x_2$ only.

1. What is the stiffness $k$ of one storey?
2. What are the two natural frequencies $f_1 < f_2$ in Hz?
3. For each mode, give the amplitude ratio $x_2/x_1$ (roof over first floor).
""",
    solution=r"""
With rigid floors and massless columns the frame is a chain of two masses and two springs
(multi-degree-of-freedom vibrations, Section 4.4.2); each storey's spring is its columns
in parallel (column stiffness, Section 5.1).

1. **Storey stiffness.** A column clamped at both ends and swayed by $x$ resists with
   $12 E I/h^3$; with $E$ = {{ E }}, $I$ = {{ I }} and $h$ = {{ h }} that is
   {{ si.k_column }} N/m per column. The {{ n_col.value }} columns of a storey add:
   $$k = n\,\frac{12 E I}{h^3},$$
   so $k$ = {{ answers.k }}.
2. **Natural frequencies.** With $x_1$, $x_2$ the floor displacements,
   the mass matrix is $\operatorname{diag}(m_1, m_2)$ and the stiffness matrix has
   $K_{11} = 2k$ (both storeys resist $x_1$), $K_{12} = K_{2 1} = -k$ and $K_{2 2} = k$,
   and $\det(\mathbf K - \omega^2\mathbf M) = 0$ reads
   $$m_1 m_2\,\omega^4 - k\,(m_1 + 2m_2)\,\omega^2 + k^2 = 0 .$$
   With $m_1$ = {{ m1 }} and $m_2$ = {{ m2 }} its roots are $\omega_1$ = {{ si.omega1 }} rad/s
   and $\omega_2$ = {{ si.omega2 }} rad/s, so $f_1 = \omega_1/(2\pi)$ = {{ answers.f1 }}
   and $f_2 = \omega_2/(2\pi)$ = {{ answers.f2 }}.
3. **Mode shapes.** The first row of $(\mathbf K - \omega^2\mathbf M)\,\hat x = 0$ gives
   $$\frac{x_2}{x_1} = \frac{2k - \omega^2 m_1}{k}:$$
   in mode 1, $x_2/x_1$ = {{ answers.r1 }} (both floors sway the same way, the roof more);
   in mode 2, $x_2/x_1$ = {{ answers.r2 }} (the floors move against each other).
""",
    solve=solve,
    checks=(
        Recompute("k", lambda p, s: _storey(p), name="clamped_columns"),
        Recompute("f1", lambda p, s: np.sqrt(_squares(p)[0]) / (2 * np.pi), name="lower_root"),
        Recompute("f2", lambda p, s: np.sqrt(_squares(p)[1]) / (2 * np.pi), name="upper_root"),
        # the first row of (K - w^2 M) x = 0: x2 / x1 = (2 k - m1 w^2) / k
        Recompute("r1", lambda p, s: (2 * _storey(p) - p.m1 * _squares(p)[0]) / _storey(p),
                  name="first_mode_shape"),
        Recompute("r2", lambda p, s: (2 * _storey(p) - p.m1 * _squares(p)[1]) / _storey(p),
                  name="second_mode_shape"),
    ),
    figure=figure,
    parts=(
        Numeric("k", "storey stiffness", question=1, unit="N/m", points=1,
                misconceptions=(
                    Misconception("cantilever columns 3EI/h^3",
                                  lambda p: storey_stiffness(p, stiffness.cantilever_tip_stiffness(p.E, p.I, p.h)),
                                  "The floors stop the column tops from rotating: 12 EI/h^3 per column."),
                    Misconception("one column", lambda p: stiffness.column_sway_stiffness(p.E, p.I, p.h),
                                  "The columns of a storey act in parallel: their stiffnesses add."),
                )),
        Numeric("f1", "first natural frequency", question=2, unit="Hz", points=2,
                misconceptions=(
                    Misconception("omega for f", lambda p: 2 * np.pi * _f1(p), "f = omega/(2 pi)."),
                    Misconception("cantilever columns", lambda p: _f1(p, stiffness.cantilever_tip_stiffness(p.E, p.I, p.h)),
                                  "Clamped-clamped columns: 12 EI/h^3."),
                )),
        Numeric("f2", "second natural frequency", question=2, unit="Hz", points=1,
                misconceptions=(Misconception("omega for f", lambda p: 2 * np.pi * solve(p)["f2"], "f = omega/(2 pi)."),)),
        Numeric("r1", "x2/x1 in mode 1", question=3, points=1,
                misconceptions=(Misconception("inverted ratio", lambda p: 1 / solve(p)["r1"],
                                              "The ratio asked is roof over first floor, x2/x1."),)),
        Numeric("r2", "x2/x1 in mode 2", question=3, points=1),
    ),
)
