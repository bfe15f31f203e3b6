"""Crank-slider mechanism: slider velocity and angular velocity of the connecting rod
(Section 3.1.1)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.checks import Recompute
from dynagrade.exercise.figure import angle_arc, block, ground, new_drawing
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import rigid_kinematics as rk


@per_draw
def _crank_rate(p):
    """Angular velocity of the crank from its speed in revolutions per time."""
    return 2 * np.pi * p.n


def figure(p):
    """The mechanism to scale at the instant considered: crank OA at theta, rod AB at the
    angle of Section 3.1.1 (l sin beta = r sin theta) and the slider B on the line through O.
    The crank is short beside the rod, so the drawing names r, l, theta and n and lists
    their values underneath."""
    from dynagrade.exercise.figure import Circle, Polygon

    beta = rk.connecting_rod_angle(p.r, p.l, p.theta)
    a = p.r * np.array([np.cos(p.theta), np.sin(p.theta)])
    b = np.array([a[0] + p.l * np.cos(beta), 0.0])
    size = p.r + p.l
    drawing, axes = new_drawing(5.0, 2.2)
    pin = 0.025 * size
    axes.add_patch(Polygon([(0, 0), (-1.6 * pin, -2.6 * pin), (1.6 * pin, -2.6 * pin)],
                           closed=True, facecolor="0.85", edgecolor="0.1", lw=1.0))
    ground(axes, -3 * pin, 3 * pin, -2.6 * pin, hatch=0.8 * pin)
    slider_h = 0.09 * size
    ground(axes, b[0] - 0.2 * size, b[0] + 0.2 * size, -slider_h / 2, hatch=0.8 * pin)
    block(axes, tuple(b), 0.14 * size, slider_h, color="0.6")
    axes.plot([0.0, a[0]], [0.0, a[1]], color="C0", lw=3.5, solid_capstyle="round")
    axes.plot([a[0], b[0]], [a[1], b[1]], color="C2", lw=3, solid_capstyle="round")
    for point in ((0.0, 0.0), tuple(a), tuple(b)):
        axes.add_patch(Circle(point, 0.5 * pin, facecolor="white", edgecolor="0.1",
                              lw=1.0, zorder=3))
    axes.plot([0.0, b[0] + 0.25 * size], [0.0, 0.0], color="0.5", lw=0.6, ls="-.")
    axes.text(-2.6 * pin, -1.2 * pin, "O", ha="right", va="center", fontsize=10)
    radial = np.array([np.cos(p.theta), np.sin(p.theta)])
    axes.text(*(a + 2.6 * pin * radial), "A", ha="center", va="center", fontsize=10)
    axes.text(b[0], b[1] + 0.6 * slider_h, "B", ha="center", va="bottom", fontsize=10)
    away = np.array([-np.sin(p.theta), np.cos(p.theta)])     # off the crank, away from B
    axes.text(*(a / 2 + 2.2 * pin * away), "r", ha="center", va="center", fontsize=10,
              color="C0")
    along = (b - a) / p.l
    # the rod's green (C2) darkened for its label, which needs 4.5:1 on white
    axes.text(*(a + 0.55 * (b - a) + 2.2 * pin * np.array([-along[1], along[0]])), "l",
              ha="center", va="center", fontsize=10, color="#23802a")
    _theta_label(axes, p.r, p.theta, a, b, pin)
    turn = p.r + 0.08 * size
    start, end = p.theta + 0.4, p.theta + 1.1
    axes.annotate("", xy=(turn * np.cos(end), turn * np.sin(end)),
                  xytext=(turn * np.cos(start), turn * np.sin(start)),
                  arrowprops={"arrowstyle": "-|>", "color": "C3", "lw": 1.3,
                              "connectionstyle": "arc3,rad=0.2", "shrinkA": 0, "shrinkB": 0})
    middle = (start + end) / 2
    axes.text(*((turn + 3 * pin) * np.array([np.cos(middle), np.sin(middle)])), "n",
              color="C3", ha="center", va="center", fontsize=10)
    values = (f"r = {format_number(p.r)} m,   l = {format_number(p.l)} m,   "
              f"θ = {format_number(np.degrees(p.theta))}°,   n = {format_number(60 * p.n)} 1/min")
    low = min(-0.1 * size, turn * np.sin(end) - 4 * pin)
    axes.text((b[0] - p.r) / 2, low, values, ha="center", va="top", fontsize=10)
    axes.set_xlim(-turn - 4 * pin, b[0] + 0.26 * size)
    axes.set_ylim(low, turn + 4 * pin)
    return drawing


def _distance_to_rod(direction, a, b) -> float:
    """How far from O the ray along ``direction`` meets the rod AB (inf if it misses)."""
    rod = b - a
    det = direction[0] * -rod[1] + rod[0] * direction[1]
    if abs(det) < 1e-12:
        return np.inf
    s = (a[0] * -rod[1] + rod[0] * a[1]) / det
    t = (direction[0] * a[1] - direction[1] * a[0]) / det
    return s if s > 0 and 0.0 <= t <= 1.0 else np.inf


def _theta_label(axes, r, theta, a, b, pin) -> None:
    """The arc of theta at O with its label beside it: inside the angle, just past the
    arc, where the wedge between OB and the crank leaves room below the rod; otherwise
    just outside the angle, tied to the arc's middle by a thin leader line."""
    bisector = np.array([np.cos(theta / 2), np.sin(theta / 2)])
    reach = _distance_to_rod(bisector, a, b)
    radius = max(min(0.3 * r, 0.5 * reach), 1.6 * pin)
    angle_arc(axes, (0.0, 0.0), radius, 0.0, theta)
    inside = radius + 1.8 * pin
    if inside * np.sin(theta / 2) >= 1.1 * pin and inside + 1.4 * pin < reach:
        axes.text(*(inside * bisector), "θ", ha="center", va="center", fontsize=10)
        return
    if theta <= np.pi / 2:      # a narrow angle: the label below the line OB
        label = np.array([radius * np.cos(theta / 2) + 2.5 * pin, -2.0 * pin])
    else:                       # the rod runs close above O: the label above the rod
        label = (reach + 2.2 * pin) * bisector
    axes.plot(*zip(radius * bisector, label - 0.8 * pin * (label - radius * bisector)
                   / np.linalg.norm(label - radius * bisector)), color="0.2", lw=0.6)
    axes.text(*label, "θ", ha="center", va="center", fontsize=10)


@per_draw
def solve(p):
    w = _crank_rate(p)
    return {
        "v_B": rk.slider_velocity(p.r, p.l, p.theta, w),
        "omega_rod": abs(rk.connecting_rod_angular_velocity(p.r, p.l, p.theta, w)),
        "omega_crank": w,
        "beta": rk.connecting_rod_angle(p.r, p.l, p.theta),
    }


@per_draw
def _pin_only(p):
    """The wrong route: the slider moves with the horizontal velocity of the crank pin."""
    return -p.r * _crank_rate(p) * np.sin(p.theta)


def _distinct(a, b):
    return abs(a - b) > 0.04 * max(abs(a), abs(b))


def _slider_speed(p, solved):
    """The slider at x_B = r cos(theta) + sqrt(l^2 - r^2 sin^2(theta)) (the rod's length
    fixed), differentiated in time with theta' = 2 pi n (Section 3.1.1)."""
    root = np.sqrt(p.l**2 - (p.r * np.sin(p.theta)) ** 2)
    dx_dtheta = -p.r * np.sin(p.theta) - p.r**2 * np.sin(p.theta) * np.cos(p.theta) / root
    return dx_dtheta * 2 * np.pi * p.n


def _rod_rate(p, solved):
    """l sin(beta) = r sin(theta) differentiated: beta' = r cos(theta) theta' / (l cos(beta))."""
    beta = np.arcsin(p.r * np.sin(p.theta) / p.l)
    return abs(p.r * np.cos(p.theta) * 2 * np.pi * p.n / (p.l * np.cos(beta)))


EXERCISE = Exercise(
    id="crank-slider-velocity",
    title="Crank-slider mechanism",
    source="Section 3.1.1",
    topics=("rigid-body kinematics in 2D", "velocity transfer", "mechanisms"),
    params=(
        Uniform("r", 0.03, 0.15, step=0.005, unit="m", symbol="r"),
        Uniform("l", 0.12, 0.6, step=0.01, unit="m", symbol="l"),
        Uniform("theta", 10, 170, step=5, unit="deg", symbol=r"\theta"),
        Uniform("n", 300, 3000, step=100, unit="1/min", symbol="n"),
    ),
    constraints=(
        Constraint("the rod is at least 2.5 times the crank", lambda p: p.l >= 2.5 * p.r),
        Constraint("the slider is clearly moving (theta away from the dead centres)",
                   lambda p: np.sin(p.theta) > 0.2),
        Constraint("the rod's own motion matters (theta away from 90 deg)",
                   lambda p: p.l >= 2.5 * p.r
                   and _distinct(solve(p)["v_B"], _pin_only(p))
                   and _distinct(solve(p)["omega_rod"], p.r * _crank_rate(p) / p.l)),
    ),
    statement=r"""
In a crank-slider mechanism the crank OA (length $r$ = {{ r }}) turns about the fixed
pivot O at $n$ = {{ n }}. The connecting rod AB (length $l$ = {{ l }}) drives the slider B
along the horizontal line through O; B is to the right of O. At the instant considered
the crank pin A is above that line and the crank makes the angle $\theta$ = {{ theta }}
with OB, measured counter-clockwise from OB; the crank turns counter-clockwise too, so
$\theta$ grows.

1. What is the velocity of the slider, positive to the right (away from O) and negative
   toward O?
2. What is the angular speed of the connecting rod?
""",
    solution=r"""
Crank and rod are rigid bodies in plane motion; we transfer the velocity of the crank pin
A to the slider B with $v_B = v_A + \omega_{AB}\times r_{AB}$ (velocity transfer in a rigid
body, Section 3.1.1), knowing that $v_B$ lies along the slider line.

**Geometry and crank rate.** The crank turns at $\omega = 2\pi n$ = {{ si.omega_crank }} rad/s
($n$ = {{ n }}). The rod's angle $\beta$ below the slider line follows from
$l\sin\beta = r\sin\theta$: with $r$ = {{ r }}, $l$ = {{ l }} and $\theta$ = {{ theta }},
$\beta$ = {{ si.beta | deg }}°.

1. **Slider velocity.** The pin A moves normal to the crank with $|v_A| = r\omega$. The
   component of $v_B = v_A + \omega_{AB}\times r_{AB}$ normal to the slider line must vanish,
   which fixes $\omega_{AB}$ (step 2); the component along it gives
   $$v_B = -r\,\omega\,\frac{\sin(\theta + \beta)}{\cos\beta},$$
   so $v_B$ = {{ answers.v_B }} (a negative value means the slider moves toward O).
2. **Angular speed of the rod.** The vertical component of the transfer equation
   (counter-clockwise positive), $r\omega\cos\theta + \omega_{AB}\,l\cos\beta = 0$, gives
   $$\omega_{AB} = -\frac{r\,\omega\cos\theta}{l\cos\beta},$$
   and the rod turns at $|\omega_{AB}|$ = {{ answers.omega_rod }}.
""",
    solve=solve,
    checks=(
        Recompute("v_B", _slider_speed, name="differentiated_position"),
        Recompute("omega_rod", _rod_rate, name="differentiated_constraint", atol=1e-9),
        Recompute("beta", lambda p, s: np.arcsin(p.r * np.sin(p.theta) / p.l), name="sine_rule"),
    ),
    figure=figure, figure_to_scale=True,
    parts=(
        Numeric("v_B", "slider velocity", question=1, unit="m/s", points=2,
                misconceptions=(
                    Misconception("horizontal velocity of the crank pin", _pin_only,
                                  "The rod turns as well: transfer the velocity from A to B "
                                  "with v_B = v_A + ω_AB × r_AB."),
                )),
        Numeric("omega_rod", "angular speed of the rod", question=2, unit="rad/s", points=2,
                misconceptions=(
                    Misconception("rod turning with r omega / l",
                                  lambda p: p.r * _crank_rate(p) / p.l,
                                  "Only the component of v_A normal to the rod turns it, and "
                                  "B's velocity is along the slider line."),
                )),
    ),
)
