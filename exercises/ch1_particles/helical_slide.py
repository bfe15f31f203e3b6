"""A rider on a helical slide: the radius of curvature of a helix and the acceleration in
the space-curve frame (kinematics of space curves, Section 1.1.4, eqs. (1.40), (1.51))."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.apart import numbers_apart
from dynagrade.exercise.checks import Limit, Recompute
from dynagrade.exercise.figure import arrow, describe, dimension, new_drawing
from dynagrade.mechanics import kinematics


@per_draw
def solve(p):
    rho = float(kinematics.helix_radius_of_curvature(p.R, p.H))
    a_n = float(kinematics.path_centripetal_acceleration(p.v, rho))
    return {
        "rho": rho,
        "a_n": a_n,
        "a_abs": float(kinematics.acceleration_magnitude(p.at, a_n)),
        "phidot": float(kinematics.helix_angular_rate(p.R, p.H, p.v)),
        "c": float(p.H / (2 * np.pi)),                  # for the worked solution
    }


def _helix_motion(p):
    """Velocity and acceleration, in Cartesian components at phi = 0, of the point
    (R cos phi, R sin phi, c phi) moving with phi' = 2 pi v / L and phi'' = 2 pi s'' / L,
    L = sqrt((2 pi R)^2 + H^2) being the length of one turn."""
    turn = np.hypot(2 * np.pi * p.R, p.H)
    w, dw, c = 2 * np.pi * p.v / turn, 2 * np.pi * p.at / turn, p.H / (2 * np.pi)
    velocity = np.array([0.0, p.R * w, c * w])
    acceleration = np.array([-p.R * w**2, p.R * dw, c * dw])
    return velocity, acceleration


def _rho_from_motion(p, s):
    """rho = |v|^3 / |v x a|, eq. (1.51), with the constant-speed part of the motion."""
    velocity, acceleration = _helix_motion(p)
    acceleration[1:] = 0.0                      # s'' = 0: only the normal part is left
    return np.linalg.norm(velocity)**3 / np.linalg.norm(np.cross(velocity, acceleration))


def _keys_apart(p) -> bool:
    """The four answers differ pairwise by over 5 %."""
    values = [solve(p)[name] for name in ("rho", "a_n", "a_abs", "phidot")]
    return numbers_apart(values)


def figure(p):
    """Side view (schematic): two turns of the helix about its vertical axis, its radius R
    and its rise H per turn, and the rider's direction of travel."""
    drawing, axes = new_drawing(3.6, 4.0)
    phi = np.linspace(0.0, 4 * np.pi, 241)
    x, z = np.cos(phi), 0.9 * phi / (2 * np.pi)
    front = np.sin(phi) <= 0.0
    axes.plot(np.where(front, x, np.nan), np.where(front, z, np.nan), color="C0", lw=2.0)
    axes.plot(np.where(front, np.nan, x), np.where(front, np.nan, z), color="C0", lw=0.8, ls="--")
    axes.plot([0.0, 0.0], [-0.2, 2.1], color="0.4", lw=0.8, ls="-.")          # the axis
    dimension(axes, (0.0, -0.35), (1.0, -0.35), "R", side=-1.0)
    dimension(axes, (1.35, 0.0), (1.35, 0.9), "H", side=-1.0)
    start = 3 * np.pi / 2
    point = np.array([np.cos(start), 0.9 * start / (2 * np.pi)])
    axes.plot(*point, "o", color="C3", ms=7)
    arrow(axes, tuple(point), tuple(point - (0.45, 0.45 * 0.9 / (2 * np.pi))), "v", offset=(0, 0.12),
          color="C3")
    describe(axes, "Side view of the helical slide: the solid line is the front of the helix, "
             "the dashed line its back; the rider slides along it, its axis is the dash-dot "
             "vertical line.")
    axes.set_xlim(-1.4, 1.9)
    axes.set_ylim(-0.6, 2.2)
    return drawing


EXERCISE = Exercise(
    id="helical-slide",
    title="A rider on a helical slide: curvature of a helix",
    source="Section 1.1.4",
    topics=("space curves", "radius of curvature", "tangential and normal acceleration"),
    params=(
        Uniform("R", 1.5, 3.0, step=0.1, unit="m", symbol="R"),
        Uniform("H", 3.0, 8.0, step=0.1, unit="m", symbol="H"),
        Uniform("v", 2.0, 5.0, step=0.1, unit="m/s", symbol="v"),
        Uniform("at", 1.0, 5.0, step=0.1, unit="m/s^2", symbol=r"\ddot s"),
    ),
    constraints=(
        Constraint("the helix climbs clearly, H/(2 pi) >= 0.3 R (rho differs from R)",
                   lambda p: p.H / (2 * np.pi) >= 0.3 * p.R),
        Constraint("the four answers differ pairwise by over 5 %", _keys_apart),
    ),
    statement=r"""
A water slide winds down around a vertical tower as a helix of radius $R$ = {{ R }} (the
distance of the rider's path from the tower's axis) that drops by $H$ = {{ H }} per full
turn. At one instant a rider (taken as a particle) slides along it at the speed
$v$ = {{ v }}, speeding up at the rate $\ddot s$ = {{ at }}.

1. What is the radius of curvature $\rho$ of the rider's path?
2. What is the normal component $v^2/\rho$ of the rider's acceleration?
3. What is the magnitude of the rider's acceleration?
4. At what rate $\dot\varphi$ does the rider go round the tower (in rad/s)?
""",
    solution=r"""
Describe the motion along the path: $a = \ddot s\,e_t + \frac{v^2}{\rho}\,e_n$ (eq. (1.51)),
with $v = \dot s$ (eq. (1.40)). With the angle $\varphi$ round the tower the path is
$r = (R\cos\varphi,\ R\sin\varphi,\ -c\varphi)$ with $c = H/(2\pi)$ = {{ si.c }} m.

1. **Radius of curvature.** Going round at a constant rate, $|v| = \dot\varphi\sqrt{R^2+c^2}$
   and the acceleration $R\dot\varphi^2$ points horizontally to the axis, perpendicular to
   $v$; so $\rho = |v|^3/|v\times a| = (R^2+c^2)/R$ = {{ answers.rho }} with $R$ = {{ R }}:
   larger than $R$, since the helix also descends.
2. **Normal acceleration.** $v^2/\rho$ = {{ answers.a_n }}.
3. **Magnitude.** $e_t$ and $e_n$ are perpendicular:
   $|a| = \sqrt{\ddot s^2 + (v^2/\rho)^2}$ = {{ answers.a_abs }}.
4. **Rate round the tower.** One turn is $\sqrt{(2\pi R)^2 + H^2}$ long, so
   $ds = \sqrt{R^2+c^2}\,d\varphi$ and $\dot\varphi = v/\sqrt{R^2+c^2}$ = {{ answers.phidot }}.
5. **Check.** A flat circle ($H = 0$) would have $\rho = R$ = {{ checks.flat_circle }} m
   (Example 1.6).
""",
    solve=solve,
    checks=(
        # rho = |v|^3 / |v x a| from the helix's Cartesian motion, eq. (1.51)
        Recompute("rho", _rho_from_motion, name="rho_from_motion"),
        # |a| of the Cartesian acceleration with the tangential part s'' included
        Recompute("a_abs", lambda p, s: float(np.linalg.norm(_helix_motion(p)[1])),
                  name="cartesian_acceleration"),
        # one turn of length sqrt((2 pi R)^2 + H^2) at the speed v takes 2 pi / phi'
        Recompute("phidot", lambda p, s: 2 * np.pi * p.v / np.hypot(2 * np.pi * p.R, p.H),
                  name="time_per_turn"),
        Limit("rho", {"H": 0.0}, lambda p: p.R, name="flat_circle"),
    ),
    figure=figure,
    parts=(
        Numeric("rho", "radius of curvature", question=1, unit="m", points=2,
                misconceptions=(
                    Misconception("the helix's radius", lambda p: p.R,
                                  "The path also descends: ρ = (R² + c²)/R with c = H/(2π), "
                                  "from ρ = |v|³/|v × a|, eq. (1.51)."),
                )),
        Numeric("a_n", "normal acceleration", question=2, unit="m/s^2", points=1,
                misconceptions=(
                    Misconception("v²/R", lambda p: p.v**2 / p.R,
                                  "Divide by the radius of curvature ρ, not the helix's radius."),
                )),
        Numeric("a_abs", "magnitude of the acceleration", question=3, unit="m/s^2", points=1,
                misconceptions=(
                    Misconception("components added", lambda p: p.at + solve(p)["a_n"],
                                  "e_t and e_n are perpendicular: |a| = √(s̈² + (v²/ρ)²), "
                                  "eq. (1.51)."),
                )),
        Numeric("phidot", "rate round the tower", question=4, unit="rad/s", points=1,
                misconceptions=(
                    Misconception("v/R", lambda p: p.v / p.R,
                                  "Only the horizontal part of the velocity goes round: "
                                  "ds = √(R² + c²) dφ."),
                )),
    ),
)
