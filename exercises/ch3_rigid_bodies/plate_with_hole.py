"""A rectangular plate with an off-centre circular hole: the hole as a negative mass in the
centre of mass and the inertia tensor, and the shift to the centre of mass
(Section 3.2.3)."""


import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.apart import numbers_apart
from dynagrade.exercise.checks import Balance, Recompute
from dynagrade.exercise.figure import Circle, Rectangle, describe, dimension, new_drawing
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import inertia, systems


def _masses(p):
    """The full plate's mass and the hole's (taken out: counted negative below)."""
    return p.rho * p.a * p.b, p.rho * np.pi * p.r**2


def _hole_tensor_about_o(p, shifted=True):
    m_h = _masses(p)[1]
    disk = inertia.inertia_tensor_disk(m_h, p.r)
    return inertia.parallel_axis_inertia_tensor(disk, m_h, [p.d, 0.0, 0.0]) if shifted else disk


def _plate_tensor(p):
    return inertia.inertia_tensor_box(_masses(p)[0], p.a, p.b, 0.0)


@per_draw
def solve(p):
    m_p, m_h = _masses(p)
    tensor_o = _plate_tensor(p) - _hole_tensor_about_o(p)
    x_c = systems.centre_of_mass([m_p, -m_h], [[0.0, 0.0, 0.0], [p.d, 0.0, 0.0]])
    mass = systems.total_mass([m_p, -m_h])
    # I_O = I_C + (point-mass term of m at x_C): back to C first, then out to the corner
    tensor_c = inertia.parallel_axis_inertia_tensor(tensor_o, -mass, x_c)
    tensor_a = inertia.parallel_axis_inertia_tensor(tensor_c, mass, _corner(p) - x_c)
    return {
        "x_C": x_c[0],
        "I22": tensor_o[1, 1],
        "I_O": tensor_o[2, 2],
        "I_A": tensor_a[2, 2],
        "I_C": tensor_c[2, 2],
        "m": mass,
    }


def _corner(p):
    return np.array([p.a / 2, p.b / 2, 0.0])


def _shifted_from_o(p):
    """The wrong route: the parallel-axis theorem applied from O, which is not C."""
    s = solve(p)
    return s["I_O"] + s["m"] * (p.a**2 + p.b**2) / 4


def _full_plate_about_a(p):
    return inertia.parallel_axis_inertia_tensor(_plate_tensor(p), _masses(p)[0],
                                                _corner(p))[2, 2]


def _differs(key, wrong):
    """Where a wrong route misses the key by more than 2.5 % (the tolerance twice and a
    half): there the misconception is a mistake a variant can tell."""
    return lambda p: abs(wrong(p) - solve(p)[key]) > 0.025 * abs(solve(p)[key])


def _apart(p):
    s = solve(p)
    return numbers_apart(s[key] for key in ("x_C", "I22", "I_O", "I_A"))


def figure(p):
    """The plate to scale with its hole d to the right of the centre O."""
    drawing, axes = new_drawing(4.6, 3.2)
    a, b = p.a, p.b
    axes.add_patch(Rectangle((-a / 2, -b / 2), a, b, facecolor="#c9d6e3", edgecolor="0.1",
                             lw=1.2))
    axes.add_patch(Circle((p.d, 0.0), p.r, facecolor="white", edgecolor="0.1", lw=1.0))
    axes.plot([0.0], [0.0], "o", color="0.1", ms=4)
    axes.text(-0.02 * a, 0.02 * a, "O", ha="right", va="bottom", fontsize=10)
    axes.text(a / 2 + 0.01 * a, b / 2 + 0.01 * a, "A", ha="left", va="bottom", fontsize=10)
    dimension(axes, (-a / 2, -b / 2), (a / 2, -b / 2), f"a = {format_number(a)} m",
              offset=-0.17 * a, tick=0.02 * a, side=-1.0)
    dimension(axes, (a / 2, -b / 2), (a / 2, b / 2), f"b = {format_number(b)} m",
              offset=-0.08 * a, tick=0.02 * a, side=-1.0)
    # d below the plate, between it and a; r led out above the plate: inside the plate
    # their labels crossed the hole's rim
    dimension(axes, (0.0, 0.0), (p.d, 0.0), f"d = {format_number(p.d)} m",
              offset=-(b / 2 + 0.05 * a), tick=0.015 * a, side=-1.0)
    rim = (p.d + p.r * np.cos(np.pi / 4), p.r * np.sin(np.pi / 4))
    axes.annotate("", xy=rim, xytext=(p.d, 0.0),
                  arrowprops={"arrowstyle": "-|>", "color": "0.2", "lw": 0.8,
                              "shrinkA": 0, "shrinkB": 0, "mutation_scale": 8})
    axes.plot([rim[0], rim[0]], [rim[1], b / 2 + 0.04 * a], color="0.4", lw=0.6)
    axes.text(rim[0], b / 2 + 0.05 * a, f"r = {format_number(p.r)} m", ha="center",
              va="bottom", fontsize=10)
    describe(axes, "The plate is seen from above, e₁ to the right and e₂ up; the hole's "
                   "centre lies on the e₁ axis through O.")
    axes.set_xlim(-0.62 * a, 0.75 * a)
    axes.set_ylim(-0.5 * b - 0.26 * a, 0.5 * b + 0.12 * a)
    return drawing


def _by_hand(p):
    """m_p = rho a b, m_h = rho pi r^2: first moments and the integrals of the plate minus
    the disk, the disk's m r^2/4 and m r^2/2 moved by d along e1 (Section 3.2.3)."""
    m_p, m_h = p.rho * p.a * p.b, p.rho * np.pi * p.r**2
    i_11 = m_p * p.b**2 / 12 - m_h * p.r**2 / 4
    x_c = -m_h * p.d / (m_p - m_h)
    return m_p, m_h, i_11, x_c


EXERCISE = Exercise(
    id="plate-with-hole-inertia",
    title="A plate with an off-centre hole: centre of mass and moments of inertia",
    source="Section 3.2.3",
    topics=("moment of inertia tensor", "composite body", "parallel-axis theorem",
            "centre of mass"),
    params=(
        Uniform("a", 0.4, 1.0, step=0.02, unit="m", symbol="a"),
        Uniform("b", 0.3, 0.8, step=0.02, unit="m", symbol="b"),
        Uniform("rho", 10.0, 60.0, step=1.0, unit="kg/m^2", symbol=r"\rho"),
        Uniform("r", 0.05, 0.2, step=0.005, unit="m", symbol="r"),
        Uniform("d", 0.08, 0.3, step=0.01, unit="m", symbol="d"),
    ),
    constraints=(
        Constraint("the hole lies inside the plate with a 2 cm rim",
                   lambda p: p.d + p.r < p.a / 2 - 0.02 and p.r < p.b / 2 - 0.02),
        Constraint("the hole takes out a noticeable mass (more than 4 % of the plate)",
                   lambda p: np.pi * p.r**2 > 0.04 * p.a * p.b),
        Constraint("no two answers share their number", _apart),
    ),
    statement=r"""
A thin homogeneous rectangular plate of $a$ = {{ a }} (along $e_1$) by $b$ = {{ b }}
(along $e_2$), with mass per area $\rho$ = {{ rho }}, has a circular hole of radius
$r$ = {{ r }} whose centre lies a distance $d$ = {{ d }} from the plate's centre O
along $e_1$.

1. Where is the centre of mass C of the plate with the hole: what is its coordinate
   $x_C$ along $e_1$, measured from O?
2. What is the moment of inertia $I_{2 2}$ about the $e_2$ axis through O?
3. What is the moment of inertia about the axis through O normal to the plate?
4. What is the moment of inertia about the axis normal to the plate through the corner
   A at $x_1 = a/2$, $x_2 = b/2$ (on the hole's side)?
""",
    solution=r"""
Treat the plate with the hole as the full plate plus a disk of negative mass where the
hole is: mass, first moments and inertia tensors add (Section 3.2.3). With
$\rho$ = {{ rho }}: the full plate has $m_p = \rho a b$, the hole $m_h = \rho \pi r^2$, and
the holed plate $m = m_p - m_h$ = {{ si.m }} kg.

1. **Centre of mass.** $m\,x_C = m_p \cdot 0 - m_h d$, so
   $x_C = -\dfrac{m_h d}{m_p - m_h}$ = {{ answers.x_C }}: C moves away from the hole.
2. **About $e_2$ through O.** The plate gives $\tfrac{1}{12} m_p a^2$; the hole, a disk
   whose centre lies $d$ from the $e_2$ axis, takes away its diametral
   $\tfrac{1}{4} m_h r^2$ moved by $d$:
   $I_{2 2} = \tfrac{1}{12} m_p a^2 - \bigl(\tfrac{1}{4} m_h r^2 + m_h d^2\bigr)$
   = {{ answers.I22 }}.
3. **Normal to the plate through O.** The plate gives $\tfrac{1}{12} m_p (a^2 + b^2)$;
   the hole takes away its polar $\tfrac{1}{2} m_h r^2$ moved by $d$ (parallel-axis
   theorem):
   $$I_O = \tfrac{1}{12} m_p (a^2 + b^2) - \bigl(\tfrac{1}{2} m_h r^2 + m_h d^2\bigr)$$
   = {{ answers.I_O }}.
4. **Normal to the plate through A.** The parallel-axis theorem links the centre of mass
   C with any point, not O with A. Back to C first: $I_O = I_C + m\,x_C^2$ gives
   $I_C = I_O - m\,x_C^2$ = {{ si.I_C }} kg m². Then out to A, whose distance from C is
   given by $(a/2 - x_C)^2 + (b/2)^2$:
   $$I_A = I_C + m\,\bigl[(a/2 - x_C)^2 + (b/2)^2\bigr]$$
   = {{ answers.I_A }}.

**Check.** Straight to A instead: the full plate about its corner, $m_p (a^2 + b^2)/3$, less
the hole about A, $m_h r^2/2 + m_h\bigl[(a/2 - d)^2 + (b/2)^2\bigr]$, gives
{{ checks.about_the_corner_directly }} kg·m² as well.
""",
    solve=solve,
    figure=figure,
    figure_to_scale=True,
    checks=(
        Recompute("x_C", lambda p, s: _by_hand(p)[3], name="first_moments"),
        # a plane body: I33 = I11 + I22 about the same point (perpendicular axes)
        Balance("perpendicular axes", lambda p, s: s["I_O"],
                lambda p, s: _by_hand(p)[2] + s["I22"], name="perpendicular_axes"),
        # the corner's moment integrated directly: the plate about its corner,
        # m_p (a^2 + b^2)/3, minus the hole about A, m_h r^2/2 + m_h |(d - a/2, -b/2)|^2
        Recompute("I_A", lambda p, s: _by_hand(p)[0] * (p.a**2 + p.b**2) / 3
                  - _by_hand(p)[1] * (p.r**2 / 2 + (p.a / 2 - p.d) ** 2 + p.b**2 / 4),
                  name="about_the_corner_directly"),
    ),
    parts=(
        Numeric("x_C", "position of C along e1", question=1, unit="m", points=1,
                misconceptions=(
                    Misconception("full plate's mass in the denominator",
                                  lambda p: -_masses(p)[1] * p.d / _masses(p)[0],
                                  "Divide the first moment by the mass that is left, "
                                  "m_p − m_h."),
                )),
        Numeric("I22", "I22 about O", question=2, unit="kg*m^2", points=1,
                misconceptions=(
                    Misconception("hole's shift forgotten", lambda p: _plate_tensor(p)[1, 1]
                                  - _hole_tensor_about_o(p, shifted=False)[1, 1],
                                  "The hole's centre lies d from the e2 axis: remove "
                                  "m_h r²/4 + m_h d².", applies=_differs("I22", lambda p:
                                  _plate_tensor(p)[1, 1]
                                  - _hole_tensor_about_o(p, shifted=False)[1, 1])),
                    Misconception("hole's polar moment", lambda p: solve(p)["I22"]
                                  - _masses(p)[1] * p.r**2 / 4,
                                  "About its diameter a disk has m r²/4; m r²/2 is about "
                                  "its axis.", applies=_differs("I22", lambda p: solve(p)["I22"]
                                  - _masses(p)[1] * p.r**2 / 4)),
                )),
        Numeric("I_O", "moment normal to the plate about O", question=3, unit="kg*m^2",
                points=2,
                misconceptions=(
                    Misconception("hole's shift forgotten", lambda p: _plate_tensor(p)[2, 2]
                                  - _hole_tensor_about_o(p, shifted=False)[2, 2],
                                  "The hole is off centre: remove ½ m_h r² + m_h d².",
                                  applies=_differs("I_O", lambda p: _plate_tensor(p)[2, 2]
                                  - _hole_tensor_about_o(p, shifted=False)[2, 2])),
                )),
        Numeric("I_A", "moment normal to the plate about the corner A", question=4,
                unit="kg*m^2", points=2,
                misconceptions=(
                    Misconception("parallel axes from O", _shifted_from_o,
                                  "The parallel-axis theorem starts from the centre of mass: "
                                  "O is not C once the hole is cut.",
                                  applies=_differs("I_A", _shifted_from_o)),
                    Misconception("hole ignored", _full_plate_about_a,
                                  "Take the hole's mass and its moment out as well.",
                                  applies=_differs("I_A", _full_plate_about_a)),
                )),
    ),
)
