"""Tuning a glockenspiel bar: the length of a free-free beam for a given pitch, where to
support it and its first overtone (Section 5.3.3)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.apart import answers_apart
from dynagrade.exercise.checks import Recompute
from dynagrade.exercise.figure import block, describe, dimension, new_drawing
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import beams, vibrations

#: each part's unit as a factor of SI, for telling the answers apart
_UNITS = {"L": 1e-3, "x_n": 1e-3, "f2": 1.0}


def _EI_rhoA(p):
    """Bending stiffness and mass per length per unit width: E h^3/12 and rho h (the width
    cancels from every frequency)."""
    return p.E * p.h**3 / 12, p.rho * p.h


def _length(p, support="free-free"):
    return beams.beam_length_for_frequency(2 * np.pi * p.f1, *_EI_rhoA(p), support)


@per_draw
def solve(p):
    L = _length(p)
    omega = beams.beam_natural_frequencies(*_EI_rhoA(p), L, "free-free", 2)
    f = vibrations.frequency_in_hertz(omega)
    return {"L": L, "x_n": beams.free_free_nodes(L, 1)[0], "f2": f[1],
            "bL1": beams.beam_eigenvalues("free-free", 1)[0],
            "bL2": beams.beam_eigenvalues("free-free", 2)[1],
            "a": beams.bending_wave_parameter(*_EI_rhoA(p))}


def _roots(n):
    """The first n roots of cos(x) cosh(x) = 1 above zero, by brentq in [j pi, (j + 1) pi]."""
    from scipy.optimize import brentq

    return [brentq(lambda x: np.cos(x) * np.cosh(x) - 1, j * np.pi + 0.1, (j + 1) * np.pi - 0.1)
            for j in range(1, n + 1)]


def _length_by_hand(p, solved):
    """L = x_1 (E h^2 / (12 rho))^(1/4) / sqrt(2 pi f_1) (Section 5.3.3)."""
    return _roots(1)[0] * (p.E * p.h**2 / (12 * p.rho)) ** 0.25 / np.sqrt(2 * np.pi * p.f1)


def _node_from_the_boundary_matrix(p, solved):
    """The first mode's first node: W = a cos + b sin + c cosh + d sinh of beta x with the
    four free-end conditions W'' = W''' = 0 at both ends as a 4 x 4 matrix, its null vector
    from numpy's SVD, then the zero of W in (0, L/2) (Section 5.3.3)."""
    from scipy.optimize import brentq

    x1 = _roots(1)[0]
    L = solved["L"]
    c, s, ch, sh = np.cos(x1), np.sin(x1), np.cosh(x1), np.sinh(x1)
    conditions = np.array([[-1, 0, 1, 0], [0, -1, 0, 1], [-c, -s, ch, sh], [s, -c, sh, ch]])
    a, b, cc, d = np.linalg.svd(conditions)[2][-1]
    beta = x1 / L

    def W(x):
        return (a * np.cos(beta * x) + b * np.sin(beta * x) + cc * np.cosh(beta * x)
                + d * np.sinh(beta * x))

    return brentq(W, 1e-9 * L, L / 2, xtol=1e-15)


def figure(p):
    """The bar lying on two cords at its nodes, struck from above; schematic."""
    L = 1.0
    t = 0.06
    drawing, axes = new_drawing(5.0, 1.7)
    block(axes, (L / 2, 0.0), L, t, color="0.7")
    # the cords at a round 0.2 L, not at the nodes' 0.224 L: measured on the figure, the
    # drawing would give the answer to part 2 away
    node = 0.2 * L
    for x in (node, L - node):
        axes.plot([x - 0.02, x + 0.02], [-t / 2 - 0.02, -t / 2 - 0.02], color="C3", lw=3)
    dimension(axes, (0.0, -0.13), (node, -0.13), "xₙ", tick=0.01, side=-1.0)
    dimension(axes, (0.0, -0.25), (L, -0.25), "L", tick=0.01, side=-1.0)
    dimension(axes, (1.04 * L, -t / 2), (1.04 * L, t / 2), f"h = {format_number(p.h * 1e3)} mm",
              tick=0.01, side=-1.0)
    axes.text(L / 2, 0.06, f"E = {format_number(p.E / 1e9)} GPa,  ρ = {format_number(p.rho)} kg/m³,"
              f"  f₁ = {format_number(p.f1)} Hz", ha="center", va="bottom", fontsize=9)
    describe(axes, "The bar lies on two soft cords, one under each node of its fundamental mode.")
    axes.set_xlim(-0.05, 1.3)
    axes.set_ylim(-0.36, 0.14)
    return drawing


EXERCISE = Exercise(
    id="tuned-free-free-bar",
    title="Tuning a glockenspiel bar: length, supports and overtone",
    source="Section 5.3.3",
    topics=("flexural vibrations", "free-free beam", "mode shapes", "nodes"),
    params=(
        Uniform("E", 70, 210, step=5, unit="GPa", symbol="E"),
        Uniform("rho", 2700, 8900, step=100, unit="kg/m^3", symbol=r"\rho"),
        Uniform("h", 4, 14, step=0.5, unit="mm", symbol="h"),
        Uniform("f1", 400, 2500, step=10, unit="Hz", symbol="f_1"),
    ),
    constraints=(
        Constraint("a real metal (aluminium, steel, copper alloys, titanium): "
                   "sqrt(E/rho) between 3 and 5.5 km/s",
                   lambda p: 3e3 <= np.sqrt(p.E / p.rho) <= 5.5e3),
        Constraint("a bar between 8 and 60 thicknesses long (slender, not a plate)",
                   lambda p: 8 <= solve(p)["L"] / p.h <= 60),
        Constraint("the three answers are over 10 % apart in SI and in their parts' units",
                   lambda p: answers_apart(solve(p), _UNITS)),
    ),
    statement="""
A glockenspiel bar is a uniform metal strip of rectangular section, thickness $h$ = {{ h }}
(it bends across the thickness), Young's modulus $E$ = {{ E }} and density
$\\rho$ = {{ rho }}. It lies on two soft cords, so that it vibrates as a free-free
Euler-Bernoulli beam, and is to sound its fundamental at $f_1$ = {{ f1 }}.

1. How long must the bar be?
2. At which distance $x_n$ from each end must the cords lie so that they do not damp the
   fundamental (at the nodes of its mode)?
3. What is the frequency of the second flexural mode, the first overtone?
""",
    solution=r"""
Flexural vibration obeys $EI\,w_{xxxx} + \rho A\,w_{tt} = 0$; standing waves have
$\omega = (\beta L)^2\sqrt{EI/(\rho A)}/L^2$, with $\beta L$ a root of the supports'
characteristic equation (flexural waves and vibrations, Section 5.3.3).

1. **Length.** Free ends carry neither moment nor shear, $W'' = W''' = 0$ at both, which
   gives $\cos(\beta L)\cosh(\beta L) = 1$ with the lowest root $\beta_1 L$ = {{ si.bL1 }}.
   For the strip $I/A = h^2/12$, so $\sqrt{EI/(\rho A)} = \sqrt{E h^2/(12\rho)}$
   = {{ si.a }} m²/s ($E$ = {{ E }}, $h$ = {{ h }}, $\rho$ = {{ rho }}) — the width
   cancels. Solving $2\pi f_1 = (\beta_1 L)^2\sqrt{EI/(\rho A)}/L^2$ for $L$:
   $$L = \beta_1 L\,\Bigl(\frac{E h^2}{12\rho}\Bigr)^{1/4}\Big/\sqrt{2\pi f_1}$$
   = {{ answers.L }} ($f_1$ = {{ f1 }}).
2. **Nodes.** The first mode is
   $W = \cosh\beta x + \cos\beta x - s(\sinh\beta x + \sin\beta x)$,
   $s = (\cosh\beta L - \cos\beta L)/(\sinh\beta L - \sin\beta L)$; it vanishes at
   $x_n$ = {{ answers.x_n }} from each end (by symmetry).
3. **Overtone.** The second root is $\beta_2 L$ = {{ si.bL2 }}, so
   $f_2 = f_1\,(\beta_2 L/\beta_1 L)^2$ = {{ answers.f2 }}: not twice $f_1$ as for a string;
   the bar's overtones are not harmonic.

**Check.** The null vector of the four free-end conditions, found numerically, gives the
node at {{ checks.boundary_matrix_node }} m as well.
""",
    solve=solve,
    checks=(
        # cos x cosh x = 1 solved again, and L from omega = x^2 sqrt(E h^2/(12 rho)) / L^2
        Recompute("L", _length_by_hand, name="characteristic_equation"),
        Recompute("x_n", _node_from_the_boundary_matrix, name="boundary_matrix_node", rtol=1e-6),
        # the frequencies scale with beta_j^2 at one length
        Recompute("f2", lambda p, s: p.f1 * (_roots(2)[1] / _roots(1)[0]) ** 2, name="eigenvalue_ratio"),
    ),
    figure=figure,
    parts=(
        Numeric("L", "length of the bar", question=1, unit="mm", points=2,
                misconceptions=(
                    Misconception("simply supported beta L = pi", lambda p: _length(p, "simply supported"),
                                  "The bar's ends are free: beta_1 L = 4.730 from cos(bL) cosh(bL) = 1."),
                    Misconception("cantilever beta L = 1.875", lambda p: _length(p, "cantilever"),
                                  "Neither end is clamped: free-free, beta_1 L = 4.730."),
                    Misconception("f for omega", lambda p: _length(p) * np.sqrt(2 * np.pi),
                                  "The dispersion relation gives the angular frequency: omega = 2 pi f1."),
                )),
        Numeric("x_n", "distance of the nodes from the ends", question=2, unit="mm", points=2,
                misconceptions=(
                    Misconception("quarter points", lambda p: solve(p)["L"] / 4,
                                  "The nodes are the zeros of the free-free mode shape W(x), not the quarter points."),)),
        Numeric("f2", "frequency of the second mode", question=3, unit="Hz", points=2,
                misconceptions=(
                    Misconception("harmonic 2 f1", lambda p: 2 * p.f1,
                                  "A bar is not a string: f2/f1 = (beta_2 L/beta_1 L)^2 = 2.756."),
                    Misconception("simply supported ratio 4", lambda p: 4 * p.f1,
                                  "(beta_2/beta_1)^2 = 4 holds for a simply supported beam; free-free bars have 2.756."),
                )),
    ),
)
