"""A puck on a tilted plane filmed from above: the constraint r . n = 0 of the plane gives
the components the camera cannot see (constrained motion, Section 1.1.2, Example 1.4(c))."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.apart import numbers_apart
from dynagrade.exercise.checks import Recompute
from dynagrade.exercise.figure import Circle, angle_arc, arrow, describe, new_drawing
from dynagrade.mechanics import kinematics


@per_draw
def solve(p):
    n = kinematics.inclined_plane_normal(p.alpha, p.beta)
    x3 = float(kinematics.vertical_component_in_plane(n, (p.x1, p.x2)))
    v3 = float(kinematics.vertical_component_in_plane(n, (p.v1, p.v2)))
    return {
        "x3": x3,
        "v3": v3,
        "speed": float(np.linalg.norm((p.v1, p.v2, v3))),
        # for the worked solution: the unit normal's components
        "n1": float(n[0]), "n2": float(n[1]), "n3": float(n[2]),
    }


def _in_plane_coordinates(p, horizontal):
    """The second route: write the vector as a u + b l in the plane's own orthonormal
    directions, u uphill and l level (both in the plane), and return (a, b). Seen from
    above, u shrinks to cos(alpha) (cos beta, sin beta) and l is (-sin beta, cos beta),
    perpendicular to it, so a and b are projections of the horizontal components."""
    h = np.asarray(horizontal, float)
    a = (h[0] * np.cos(p.beta) + h[1] * np.sin(p.beta)) / np.cos(p.alpha)
    b = -h[0] * np.sin(p.beta) + h[1] * np.cos(p.beta)
    return np.array([a, b])


def _vertical_by_basis(horizontal):
    """The vertical component a sin(alpha) of the in-plane vector a u + b l."""
    return lambda p, s: _in_plane_coordinates(p, horizontal(p))[0] * np.sin(p.alpha)


def _speed_by_basis(p, s):
    """|a u + b l| = sqrt(a^2 + b^2): u and l are orthonormal."""
    return float(np.linalg.norm(_in_plane_coordinates(p, (p.v1, p.v2))))


def _horizontal_speed(p):
    return float(np.hypot(p.v1, p.v2))


def _slope_along_e1(first, second):
    """The wrong route "slope taken along e1" for the horizontal pair (first, second) of
    parameters: tan(alpha) times the e1 component alone; and where it is a mistake (the e2
    part and the turn beta change the rise by over 3 %)."""
    def value(p):
        return np.tan(p.alpha) * getattr(p, first)

    def applies(p):
        x1, x2 = getattr(p, first), getattr(p, second)
        uphill = x1 * np.cos(p.beta) + x2 * np.sin(p.beta)
        return abs(uphill - x1) > 0.03 * abs(uphill)
    return value, applies


HEIGHT_ALONG_E1 = _slope_along_e1("x1", "x2")
CLIMB_ALONG_E1 = _slope_along_e1("v1", "v2")


def _keys_apart(p) -> bool:
    """The answers differ pairwise by over 5 % in magnitude, and are clear of zero."""
    s = solve(p)
    values = (abs(s["x3"]), abs(s["v3"]), s["speed"])
    return min(values[:2]) >= 0.1 and numbers_apart(values)


def _drawn_apart(p) -> bool:
    """The puck, drawn at its position, keeps off the figure's axes, the uphill arrow and
    their labels: it lies 1.1 m from O and at least 30° away from e1, e2 and the uphill
    direction."""
    puck = np.array([p.x1, p.x2])
    distance = float(np.hypot(*puck))
    directions = (np.array([1.0, 0.0]), np.array([0.0, 1.0]),
                  np.array([np.cos(p.beta), np.sin(p.beta)]))
    return distance >= 1.1 and all(np.dot(puck, d) / distance < np.cos(np.radians(30))
                                   for d in directions)


def figure(p):
    """Top view (schematic): the axes e1, e2 at O, the direction of steepest ascent at the
    azimuth beta with level lines across it, the puck at (x1, x2) and its horizontal
    velocity as the camera sees it."""
    drawing, axes = new_drawing(4.6, 4.0)
    arrow(axes, (0.0, 0.0), (0.8, 0.0), color="0.3")
    arrow(axes, (0.0, 0.0), (0.0, 0.8), color="0.3")
    axes.text(0.95, 0.0, "e₁", ha="left", va="center", fontsize=10, color="0.3")
    axes.text(0.0, 0.95, "e₂", ha="center", va="bottom", fontsize=10, color="0.3")
    # O in the quadrant that neither the axes nor the uphill arrow take
    axes.text(-0.1, 0.1 if p.beta < 0 else -0.1, "O", ha="right",
              va="bottom" if p.beta < 0 else "top", fontsize=10)
    up = np.array([np.cos(p.beta), np.sin(p.beta)])
    level = np.array([-up[1], up[0]])
    for k in (-2, -1, 0, 1, 2):                                  # level lines of the plane
        middle = 0.7 * k * up
        axes.plot(*zip(middle - 2.6 * level, middle + 2.6 * level), color="0.5", lw=0.7)
    arrow(axes, (0.0, 0.0), tuple(1.3 * up), color="green")
    axes.text(*(1.5 * up), "uphill", ha="center", va="center", fontsize=10, color="green")
    angle_arc(axes, (0.0, 0.0), 0.45, 0.0, p.beta, "β", label_radius=0.62)
    puck = np.array([p.x1, p.x2])
    axes.add_patch(Circle(tuple(puck), 0.09, facecolor="C0", edgecolor="0.1", lw=1.0, zorder=3))
    heading = np.array([p.v1, p.v2]) / _horizontal_speed(p)
    arrow(axes, tuple(puck + 0.1 * heading), tuple(puck + 0.75 * heading), color="C3")
    # the label beside the arrow's middle, on the side away from O
    across = np.array([-heading[1], heading[0]])
    if np.dot(across, puck) < 0:
        across = -across
    spot = puck + 0.45 * heading + 0.3 * across
    axes.text(*spot, "v₁e₁ + v₂e₂", ha="left" if across[0] > 0.3 else "right"
              if across[0] < -0.3 else "center", va="bottom" if across[1] > 0.3 else "top"
              if across[1] < -0.3 else "center", fontsize=10, color="C3")
    describe(axes, "Seen from above: grey level lines of the tilted plane run across the "
             "green arrow from O, which points uphill at the angle beta from e1; the puck is "
             "at its measured position, its red arrow is the horizontal velocity the camera "
             "sees.")
    axes.set_xlim(-3.0, 3.0)
    axes.set_ylim(-3.0, 3.0)
    return drawing


EXERCISE = Exercise(
    id="puck-on-tilted-plane",
    title="A puck on a tilted plane filmed from above",
    source="Section 1.1.2",
    topics=("constrained motion", "kinematic constraint", "degrees of freedom"),
    params=(
        Uniform("alpha", 15, 40, step=1, unit="deg", symbol=r"\alpha"),
        Uniform("beta", -90, 90, step=5, unit="deg", symbol=r"\beta"),
        Uniform("x1", -1.8, 1.8, step=0.1, unit="m", symbol="x_1"),
        Uniform("x2", -1.8, 1.8, step=0.1, unit="m", symbol="x_2"),
        Uniform("v1", -3.0, 3.0, step=0.1, unit="m/s", symbol="v_1"),
        Uniform("v2", -3.0, 3.0, step=0.1, unit="m/s", symbol="v_2"),
    ),
    constraints=(
        Constraint("the puck moves horizontally at 0.5 m/s at least and stays 0.4 m from O",
                   lambda p: _horizontal_speed(p) >= 0.5 and np.hypot(p.x1, p.x2) >= 0.4),
        Constraint("the figure keeps the puck clear of the axes and the uphill arrow at O "
                   "(1.1 m from O and 30° off e1, e2 and uphill)", _drawn_apart),
        Constraint("the height and the vertical velocity are clear of zero (0.1 m, 0.1 m/s) "
                   "and the three answers differ by over 5 %", _keys_apart),
    ),
    statement=r"""
A small puck slides on a large, flat, tilted plane of ice that passes through the point O.
In the fixed frame at O, $e_1$ and $e_2$ are horizontal and $e_3$ points vertically up. The
plane is inclined at $\alpha$ = {{ alpha }} to the horizontal, and its direction of steepest
ascent, seen from above, makes the angle $\beta$ = {{ beta }} with $e_1$ (counter-clockwise
toward $e_2$). The puck never leaves the plane.

A camera straight above O films the puck. At one instant it measures the horizontal position
$x_1$ = {{ x1 }}, $x_2$ = {{ x2 }} and the horizontal velocity components $v_1$ = {{ v1 }},
$v_2$ = {{ v2 }}.

1. What is the puck's height $x_3$ above O (negative below O)?
2. What is its vertical velocity component $v_3$ (positive upward)?
3. What is its speed?
""",
    solution=r"""
The plane is one kinematic constraint (Example 1.4(c)): the puck has $3 - 1 = 2$ degrees of
freedom (eq. (1.21)), so the two horizontal coordinates the camera sees fix the third. With
the plane's unit normal $n$, the constraint is $r\cdot n = 0$; here
$n = (-\sin\alpha\cos\beta,\ -\sin\alpha\sin\beta,\ \cos\alpha)$ =
({{ si.n1 }}, {{ si.n2 }}, {{ si.n3 }}) for $\alpha$ = {{ alpha }} and $\beta$ = {{ beta }}.
It holds at every instant, so its time derivative $v\cdot n = 0$ holds as well.

1. **Height.** $n_1x_1 + n_2x_2 + n_3x_3 = 0$ gives
   $x_3 = \tan\alpha\,(x_1\cos\beta + x_2\sin\beta)$ = {{ answers.x3 }}: the horizontal
   distance along the uphill direction times the slope.
2. **Vertical velocity.** In the same way from $v\cdot n = 0$:
   $v_3 = \tan\alpha\,(v_1\cos\beta + v_2\sin\beta)$ = {{ answers.v3 }}.
3. **Speed.** $|v| = \sqrt{v_1^2 + v_2^2 + v_3^2}$ = {{ answers.speed }}, more than the
   camera's horizontal speed: part of the motion is vertical.
4. **Check.** Written in the plane's own directions, uphill and level, the same velocity
   has the length {{ checks.speed_in_plane }} m/s.
""",
    solve=solve,
    checks=(
        # the vector written as a u + b l in the plane's orthonormal directions (uphill u,
        # level l): its vertical part is a sin(alpha), its length sqrt(a^2 + b^2)
        Recompute("x3", _vertical_by_basis(lambda p: (p.x1, p.x2)), name="height_in_plane"),
        Recompute("v3", _vertical_by_basis(lambda p: (p.v1, p.v2)), name="climb_in_plane"),
        Recompute("speed", _speed_by_basis, name="speed_in_plane"),
    ),
    figure=figure,
    parts=(
        Numeric("x3", "height above O", question=1, unit="m", points=1,
                misconceptions=(
                    Misconception("sin for tan",
                                  lambda p: np.sin(p.alpha) * (p.x1 * np.cos(p.beta) + p.x2 * np.sin(p.beta)),
                                  "x₁cos β + x₂sin β is a horizontal distance: the rise over it "
                                  "is the distance times tan α (r·n = 0, Example 1.4(c)).",
                                  applies=lambda p: np.cos(p.alpha) < 0.97),
                    Misconception("slope taken along e1", HEIGHT_ALONG_E1[0],
                                  "The plane rises along the direction at β, not along e₁: "
                                  "use r·n = 0 with the whole normal.",
                                  applies=HEIGHT_ALONG_E1[1]),
                )),
        Numeric("v3", "vertical velocity", question=2, unit="m/s", points=2,
                misconceptions=(
                    Misconception("slope taken along e1", CLIMB_ALONG_E1[0],
                                  "Differentiate the whole constraint: v·n = 0 with "
                                  "n = (−sin α cos β, −sin α sin β, cos α).",
                                  applies=CLIMB_ALONG_E1[1]),
                )),
        Numeric("speed", "speed", question=3, unit="m/s", points=1,
                misconceptions=(
                    Misconception("the camera's speed", _horizontal_speed,
                                  "The camera sees only the horizontal part; the puck also "
                                  "moves vertically at v₃.",
                                  applies=lambda p: abs(solve(p)["v3"]) > 0.25 * _horizontal_speed(p)),
                )),
    ),
)
