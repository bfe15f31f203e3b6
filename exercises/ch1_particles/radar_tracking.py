"""A radar tracking an aircraft in level flight: the rates of its polar coordinates, and
their second rates from a = 0 (kinematics in polar coordinates, Section 1.1.3,
eqs. (1.31)-(1.33))."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.apart import numbers_apart
from dynagrade.exercise.checks import Recompute
from dynagrade.exercise.figure import angle_arc, arrow, describe, dimension, ground, new_drawing
from dynagrade.mechanics import kinematics


@per_draw
def solve(p):
    r = float(p.h / np.sin(p.phi))
    velocity = (-p.v, 0.0)                          # level flight toward the radar's side
    rdot, phidot = kinematics.polar_coordinate_rates(r, p.phi, velocity)
    rddot, phiddot = kinematics.polar_coordinate_accelerations(r, p.phi, rdot, phidot, (0.0, 0.0))
    return {"r": r, "rdot": rdot, "phidot": phidot, "rddot": rddot, "phiddot": phiddot}


def _track(p, t):
    """The radar's readings (r, phi) at time t measured from the instant considered, from
    the aircraft's Cartesian position (h / tan phi - v t, h)."""
    x = p.h / np.tan(p.phi) - p.v * t
    return np.hypot(x, p.h), np.arctan2(p.h, x)


def _derivative(p, which, order):
    """The first or second time derivative at t = 0 of the reading ``which`` (0: r,
    1: phi), by a five-point central difference of the readings themselves."""
    dt = 1e-3 * p.h / p.v
    f = [_track(p, k * dt)[which] for k in (-2, -1, 0, 1, 2)]
    if order == 1:
        return (f[0] - 8 * f[1] + 8 * f[3] - f[4]) / (12 * dt)
    return (-f[0] + 16 * f[1] - 30 * f[2] + 16 * f[3] - f[4]) / (12 * dt**2)


def _keys_apart(p) -> bool:
    """The five answers differ pairwise by over 5 % in magnitude."""
    values = [abs(value) for value in solve(p).values()]
    return numbers_apart(values)


def figure(p):
    """Side view to scale: the radar at O on the ground, the aircraft at the height h on the
    line of sight at the elevation phi, flying horizontally toward the radar's side."""
    x = p.h / np.tan(p.phi)
    drawing, axes = new_drawing(5.0, 2.8)
    ground(axes, -0.35 * x - 0.3 * p.h, 1.2 * x + 0.3 * p.h, hatch=0.05 * p.h)
    axes.plot([0.0], [0.0], "^", color="0.1", ms=9)
    axes.text(0.0, -0.22 * p.h, "O", ha="center", va="top", fontsize=10)
    axes.plot([0.0, x], [0.0, p.h], color="0.4", lw=0.9, ls="--")       # the line of sight
    axes.plot([x], [p.h], "o", color="C0", ms=8)
    arrow(axes, (x, p.h), (x - 0.35 * p.h - 0.1 * x, p.h), "v", offset=(0.0, 0.1 * p.h),
          color="C3")
    angle_arc(axes, (0.0, 0.0), 0.35 * p.h, 0.0, p.phi, "φ", label_radius=0.5 * p.h)
    dimension(axes, (x + 0.15 * p.h, 0.0), (x + 0.15 * p.h, p.h), "h", side=-1.0)
    describe(axes, "Side view: the radar at O tracks the aircraft along the dashed line of "
             "sight; the aircraft flies horizontally to the left, toward the vertical above "
             "O, at the height h.")
    axes.set_xlim(-0.35 * x - 0.3 * p.h, 1.2 * x + 0.3 * p.h)
    axes.set_ylim(-0.4 * p.h, 1.35 * p.h)
    return drawing


EXERCISE = Exercise(
    id="radar-tracking-level-flight",
    title="A radar tracking an aircraft in level flight",
    source="Section 1.1.3",
    topics=("polar coordinates", "angular velocity", "Coriolis term"),
    params=(
        Uniform("h", 300, 3000, step=50, unit="m", symbol="h"),
        Uniform("v", 50, 250, step=5, unit="m/s", symbol="v"),
        Uniform("phi", 20, 75, step=1, unit="deg", symbol=r"\varphi"),
    ),
    constraints=(
        Constraint("the five answers differ pairwise by over 5 %", _keys_apart),
    ),
    statement=r"""
A radar station at the point O on flat ground tracks an aircraft that flies in a vertical
plane through O, horizontally and at the constant speed $v$ = {{ v }}, at the height
$h$ = {{ h }}; it approaches the vertical above O. The radar measures the distance $r$ to the
aircraft and the elevation angle $\varphi$ of its line of sight above the horizontal
(counter-clockwise in the figure). At the instant considered, $\varphi$ = {{ phi }}.

Give the rates with their signs ($\dot r > 0$ when the distance grows, $\dot\varphi > 0$ when
the elevation grows):

1. What distance $r$ does the radar measure?
2. What is $\dot r$?
3. What is $\dot\varphi$ (in rad/s)?
4. What is $\ddot r$?
5. What is $\ddot\varphi$ (in rad/s²)?
""",
    solution=r"""
Use the polar coordinates $(r, \varphi)$ of the aircraft about O with the co-rotating basis
$e_r = (\cos\varphi, \sin\varphi)$, $e_\varphi = (-\sin\varphi, \cos\varphi)$ (eq. (1.27)).
The aircraft's velocity is $v = -v\,e_1$ and its acceleration is zero (level flight at
constant speed).

1. **Distance.** $h = r\sin\varphi$, so $r = h/\sin\varphi$ = {{ answers.r }}.
2. **Rate of the distance.** By eq. (1.30), $\dot r = v\cdot e_r = -v\cos\varphi$ =
   {{ answers.rdot }}: the aircraft approaches.
3. **Rate of the elevation.** $r\dot\varphi = v\cdot e_\varphi = v\sin\varphi$, so
   $\dot\varphi = v\sin\varphi/r = v\sin^2\varphi/h$ = {{ answers.phidot }}.
4. **Second rate of the distance.** The acceleration vanishes, so both polar components of
   eq. (1.33) vanish: $a_r = \ddot r - r\dot\varphi^2 = 0$ gives $\ddot r = r\dot\varphi^2$ =
   {{ answers.rddot }}. Although the aircraft does not accelerate, $\ddot r \neq 0$: the
   components of $a$ in the rotating frame are not the derivatives of those of $v$
   (eq. (1.35)).
5. **Second rate of the elevation.** $a_\varphi = 2\dot r\dot\varphi + r\ddot\varphi = 0$
   gives $\ddot\varphi = -2\dot r\dot\varphi/r$ = {{ answers.phiddot }}: the line of sight
   turns faster and faster as the aircraft nears the vertical.
6. **Check.** Differencing the radar's readings $r(t)$ in time from the aircraft's
   Cartesian track gives $\ddot r$ = {{ checks.differenced_rddot }} m/s².
""",
    solve=solve,
    checks=(
        # the readings r(t), phi(t) of the Cartesian track (h / tan(phi) - v t, h),
        # differenced in time: no polar relation used
        Recompute("rdot", lambda p, s: _derivative(p, 0, 1), name="differenced_rdot", rtol=1e-6),
        Recompute("phidot", lambda p, s: _derivative(p, 1, 1), name="differenced_phidot", rtol=1e-6),
        Recompute("rddot", lambda p, s: _derivative(p, 0, 2), name="differenced_rddot", rtol=1e-5),
        Recompute("phiddot", lambda p, s: _derivative(p, 1, 2), name="differenced_phiddot",
                  rtol=1e-5),
    ),
    figure=figure,
    figure_to_scale=True,
    parts=(
        Numeric("r", "distance", question=1, unit="m", points=1,
                misconceptions=(
                    Misconception("cos for sin", lambda p: p.h / np.cos(p.phi),
                                  "The height is the side opposite the elevation angle: "
                                  "h = r sin φ.",
                                  applies=lambda p: abs(np.tan(p.phi) - 1) > 0.03),
                )),
        Numeric("rdot", "rate of the distance", question=2, unit="m/s", points=1,
                misconceptions=(
                    Misconception("the whole speed", lambda p: -p.v,
                                  "Only the velocity's component along the line of sight "
                                  "changes r: ṙ = v·e_r, eq. (1.30)."),
                    Misconception("sin for cos", lambda p: -p.v * np.sin(p.phi),
                                  "e_r makes the angle φ with the horizontal velocity: "
                                  "ṙ = −v cos φ.",
                                  applies=lambda p: abs(np.tan(p.phi) - 1) > 0.03),
                )),
        Numeric("phidot", "rate of the elevation", question=3, unit="rad/s", points=1,
                misconceptions=(
                    Misconception("whole speed over r", lambda p: p.v * np.sin(p.phi) / p.h,
                                  "Only the component v·e_φ = v sin φ turns the line of "
                                  "sight: φ̇ = v sin φ / r, eq. (1.30)."),
                )),
        Numeric("rddot", "second rate of the distance", question=4, unit="m/s^2", points=2,
                misconceptions=(
                    Misconception("a_r taken as r̈ − rφ̇² with the sign turned",
                                  lambda p: -p.v**2 * np.sin(p.phi)**3 / p.h,
                                  "a_r = r̈ − rφ̇² = 0, eq. (1.33): r̈ = +rφ̇²."),
                )),
        Numeric("phiddot", "second rate of the elevation", question=5, unit="rad/s^2", points=2,
                misconceptions=(
                    Misconception("Coriolis factor 2 missing",
                                  lambda p: p.v**2 * np.sin(p.phi)**3 * np.cos(p.phi) / p.h**2,
                                  "a_φ = 2ṙφ̇ + rφ̈, eq. (1.33): the factor 2 of the "
                                  "Coriolis term."),
                )),
    ),
)
