"""Inertia tensor of a rectangular plate about a corner: parallel-axis theorem, products of
inertia, moment about a diagonal and principal moments (Section 3.2.3)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, apart
from dynagrade.exercise.checks import Recompute
from dynagrade.mechanics import inertia


def _centroidal(p):
    return inertia.inertia_tensor_box(p.m, p.a, p.b, 0.0)


def _about_corner(p):
    return inertia.parallel_axis_inertia_tensor(_centroidal(p), p.m, [p.a / 2, p.b / 2, 0.0])


def _diagonal(p):
    return np.array([p.a, p.b, 0.0])


def _diagonal_without_products(p):
    """The wrong route: n.I n with the off-diagonal entries dropped."""
    tensor = np.diag(np.diag(_about_corner(p)))
    return inertia.moment_of_inertia_about_axis(tensor, _diagonal(p))


def solve(p):
    tensor = _about_corner(p)
    return {
        "I11": tensor[0, 0],
        "I12": tensor[0, 1],
        "I33": tensor[2, 2],
        "I_diag": inertia.moment_of_inertia_about_axis(tensor, _diagonal(p)),
        "I_min": inertia.principal_axes(tensor).moments[0],
    }


EXERCISE = Exercise(
    id="plate-inertia-about-corner",
    title="Inertia tensor of a plate about its corner",
    source="Section 3.2.3",
    topics=("moment of inertia tensor", "parallel-axis theorem", "principal axes"),
    params=(
        Uniform("m", 0.5, 10.0, step=0.5, unit="kg", symbol="m"),
        Uniform("a", 0.2, 1.2, step=0.05, unit="m", symbol="a"),
        Uniform("b", 0.2, 1.2, step=0.05, unit="m", symbol="b"),
    ),
    constraints=(
        # two answers that agree as numbers can be swapped and score (verify's variety rule)
        Constraint("the moment about the diagonal and the smallest principal moment differ",
                   lambda p: apart(solve(p)["I_diag"], solve(p)["I_min"])),
        Constraint("the plate is clearly not square", lambda p: abs(p.a - p.b) > 0.2 * max(p.a, p.b)),
    ),
    statement=r"""
A thin homogeneous rectangular plate of mass $m$ = {{ m }} occupies
$0 \le x_1 \le a$, $0 \le x_2 \le b$ in the $e_1$-$e_2$ plane, with $a$ = {{ a }} and
$b$ = {{ b }}. Work with the inertia tensor about the corner O at the origin, in the basis
$e_1, e_2, e_3$ (with $I_{12} = -\int x_1 x_2\,dm$).

1. What is $I_{11}$?
2. What is the product of inertia $I_{12}$?
3. What is $I_{33}$?
4. What is the moment of inertia about the plate's diagonal through O?
5. What is the smallest principal moment of inertia at O?
""",
    solution=r"""
The inertia tensor about O has the entries $I_{ii} = \int (|x|^2 - x_i^2)\,dm$ and
$I_{ij} = -\int x_i x_j\,dm$ (moment of inertia tensor, Section 3.2.3). For the thin plate
$x_3 = 0$ and $dm = \frac{m}{ab}\,dx_1\,dx_2$; with $m$ = {{ m }}, $a$ = {{ a }} and
$b$ = {{ b }}:

1. **$I_{11}$.** $I_{11} = \int x_2^2\,dm = \frac{m}{ab}\int_0^a\!\!\int_0^b x_2^2\,dx_2\,dx_1
   = \tfrac{1}{3} m b^2$, so $I_{11}$ = {{ answers.I11 }}.
   (The same follows from the centroidal $\tfrac{1}{12} m b^2$ and the parallel-axis term
   $m (b/2)^2$.)
2. **Product of inertia.** $I_{12} = -\int x_1 x_2\,dm = -\frac{m}{ab}\,\frac{a^2}{2}\,\frac{b^2}{2}
   = -\tfrac{1}{4} m a b$, so $I_{12}$ = {{ answers.I12 }}. It does not vanish because O is a
   corner, not the centre.
3. **$I_{3 3}$.** For a plane body $I_{3 3} = \int (x_1^2 + x_2^2)\,dm = I_{11} + I_{2 2}
   = \tfrac{1}{3} m (a^2 + b^2)$, so $I_{3 3}$ = {{ answers.I33 }}.
4. **About the diagonal.** With the unit vector $n = (a, b, 0)/\sqrt{a^2 + b^2}$ along the
   diagonal, $I_n = n\cdot I\,n = I_{11} n_1^2 + 2 I_{12} n_1 n_2 + I_{2 2} n_2^2$:
   $$I_n = \frac{\tfrac{1}{3} m b^2 a^2 - \tfrac{1}{2} m a^2 b^2 + \tfrac{1}{3} m a^2 b^2}{a^2 + b^2}
   = \frac{m\,a^2 b^2}{6\,(a^2 + b^2)},$$
   so $I_n$ = {{ answers.I_diag }}. The product of inertia must be kept: it lowers the
   moment.
5. **Smallest principal moment.** $e_3$ is a principal axis; the other two principal
   moments are the eigenvalues of the $2\times2$ block of $I_{11}$, $I_{12}$ and
   $I_{2 2} = \tfrac{1}{3} m a^2$,
   $$I_{\min} = \frac{I_{11} + I_{2 2} }{2} - \sqrt{\Bigl(\frac{I_{11} - I_{2 2} }{2}\Bigr)^2 + I_{12}^2},$$
   which gives $I_{\min}$ = {{ answers.I_min }}.
""",
    solve=solve,
    checks=(
        # the integrals over the plate 0 < x < a, 0 < y < b of m/(a b) (y^2, -x y, x^2 + y^2)
        Recompute("I11", lambda p, s: p.m * p.b**2 / 3, name="integral_of_y_squared"),
        Recompute("I12", lambda p, s: -p.m * p.a * p.b / 4, name="product_integral"),
        Recompute("I33", lambda p, s: p.m * (p.a**2 + p.b**2) / 3, name="polar_integral"),
        # about the diagonal: the mean squared distance from it, m a^2 b^2 / (6 (a^2 + b^2))
        Recompute("I_diag", lambda p, s: p.m * p.a**2 * p.b**2 / (6 * (p.a**2 + p.b**2)),
                  name="distance_to_the_diagonal"),
    ),
    parts=(
        Numeric("I11", "I11 about the corner", question=1, unit="kg*m^2", points=1,
                misconceptions=(
                    Misconception("centroidal value", lambda p: _centroidal(p)[0, 0],
                                  "Shift to the corner: add m (b/2)²."),
                    Misconception("wrong edge", lambda p: p.m * p.a**2 / 3,
                                  "I11 sums x2² + x3²: the edge b along e2 counts."),
                )),
        Numeric("I12", "product of inertia I12", question=2, unit="kg*m^2", points=1,
                misconceptions=(
                    Misconception("sign convention", lambda p: p.m * p.a * p.b / 4,
                                  "The tensor carries −∫x1 x2 dm off the diagonal."),
                    Misconception("centroidal product", lambda p: -p.m * p.a * p.b / 12,
                                  "Shifting from the centre adds −m (a/2)(b/2) = −m a b/4."),
                )),
        Numeric("I33", "I33 about the corner", question=3, unit="kg*m^2", points=1,
                misconceptions=(
                    Misconception("centroidal value", lambda p: _centroidal(p)[2, 2],
                                  "Shift to the corner: add m (a² + b²)/4."),
                )),
        Numeric("I_diag", "moment about the diagonal", question=4, unit="kg*m^2", points=2,
                misconceptions=(
                    Misconception("products of inertia dropped", _diagonal_without_products,
                                  "n·I n needs the off-diagonal entries too."),
                )),
        Numeric("I_min", "smallest principal moment", question=5, unit="kg*m^2", points=2,
                misconceptions=(
                    Misconception("smallest diagonal entry",
                                  lambda p: min(np.diag(_about_corner(p))),
                                  "The basis e1, e2 is not principal at the corner: find the "
                                  "eigenvalues of the tensor."),
                )),
    ),
)
