"""A wheel rolling without slipping: velocity of a rim point and the instantaneous centre
of rotation (Section 3.1.1)."""

import numpy as np

from dynagrade.exercise import (Constraint, Exercise, Misconception, Numeric, Symbolic,
                                Uniform, Vector)
from dynagrade.exercise.checks import Balance, Recompute
from dynagrade.exercise.figure import (angle_arc, arrow, describe, dimension,
                                       ground, new_drawing)
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import rigid_kinematics as rk


def _rim_position(p):
    """Rim point relative to the hub, at the angle phi from the contact point."""
    return p.R * np.array([np.sin(p.phi), -np.cos(p.phi)])


def figure(p):
    """The wheel to scale on the ground with the hub's velocity, the contact point and the
    rim point P at the angle phi from it, counter-clockwise about the hub (Section 3.1.1)."""
    from dynagrade.exercise.figure import Circle

    R = p.R
    hub = np.array([0.0, R])
    point = hub + _rim_position(p)
    drawing, axes = new_drawing(4.4, 3.2)
    ground(axes, -1.6 * R, 1.7 * R, hatch=R / 14)
    axes.add_patch(Circle(tuple(hub), R, facecolor="0.93", edgecolor="0.1", lw=1.4))
    axes.plot([0.0, 0.0], [R, 0.0], color="0.4", lw=0.8, ls=":")
    axes.plot([0.0, point[0]], [R, point[1]], color="0.4", lw=0.8, ls=":")
    axes.plot(*hub, "o", color="0.1", ms=4)
    axes.plot(*point, "o", color="C0", ms=7, zorder=3)
    axes.text(*(hub + 1.15 * _rim_position(p)), "P", ha="center", va="center", fontsize=10)
    axes.text(0.06 * R, -0.08 * R, "contact", ha="left", va="top", fontsize=9, color="0.3")
    angle_arc(axes, tuple(hub), 0.22 * R, -np.pi / 2, p.phi - np.pi / 2)
    middle = (p.phi - np.pi) / 2          # the arc's middle, measured from e1
    if abs(middle) < np.radians(35):      # keep the label off the hub's velocity arrow
        middle = np.copysign(np.radians(35), middle)
    axes.text(*(hub + 0.5 * R * np.array([np.cos(middle), np.sin(middle)])),
              f"φ = {format_number(np.degrees(p.phi))}°", ha="center", va="center",
              fontsize=10)
    arrow(axes, tuple(hub), (1.0 * R, R), color="C3")
    axes.text(1.05 * R, 1.08 * R, f"v = {format_number(p.v)} m/s", color="C3", ha="left",
              va="bottom", fontsize=10)
    dimension(axes, (-1.2 * R, 0.0), (-1.2 * R, R), f"R = {format_number(R)} m",
              tick=0.05 * R)
    axes.set_xlim(-1.65 * R, 1.75 * R)
    axes.set_ylim(-0.15 * R, 2.1 * R)
    describe(axes, "A wheel rolls to the right on the ground without slipping; the hub "
             "moves to the right with speed v; the rim point P lies at the angle φ from "
             "the contact point, counter-clockwise about the hub")
    return drawing


def solve(p):
    v_point = rk.rim_point_velocity(p.v, p.R, p.phi)
    omega_e3 = -rk.rolling_angular_velocity(p.v, p.R)
    hub = np.array([0.0, p.R])
    icr = rk.instantaneous_centre_of_rotation(hub, np.array([p.v, 0.0]), omega_e3)
    return {
        "omega": rk.rolling_angular_velocity(p.v, p.R),
        "v_P": v_point,
        "speed": float(np.linalg.norm(v_point)),
        "d_ICR": float(np.linalg.norm(hub + _rim_position(p) - icr)),
    }


EXERCISE = Exercise(
    id="rolling-wheel-rim-velocity",
    title="Velocity of a point on a rolling wheel",
    source="Section 3.1.1",
    topics=("rigid-body kinematics in 2D", "rolling without slipping",
            "instantaneous centre of rotation"),
    params=(
        Uniform("R", 0.2, 0.8, step=0.05, unit="m", symbol="R"),
        Uniform("v", 2.0, 30.0, step=0.5, unit="m/s", symbol="v"),
        Uniform("phi", 20, 340, step=5, unit="deg", symbol=r"\varphi"),
    ),
    constraints=(
        Constraint("the point is not where its speed equals the hub's (phi = 60 or 300 deg)",
                   lambda p: abs(2 * abs(np.sin(p.phi / 2)) - 1) > 0.08),
        Constraint("the point is clear of the top, where the hub-only answer is parallel",
                   lambda p: abs(p.phi - np.pi) > np.radians(15)),
    ),
    statement=r"""
A wheel of radius $R$ = {{ R }} rolls without slipping to the right (along $e_1$) on level
ground, its hub moving with $v$ = {{ v }}. A point P on the rim sits at the angle
$\varphi$ = {{ phi }} from the contact point, measured about the hub counter-clockwise
(so $\varphi$ = 90° is the point level with the hub, ahead of it; $e_2$ points up).

1. What is the wheel's angular speed?
2. What is the velocity vector of P (components along $e_1$, $e_2$)?
3. What is the speed of P?
4. How far is P from the instantaneous centre of rotation?
5. Give the speed of P as a formula in $v$ and $\varphi$.
""",
    solution=r"""
The wheel is a rigid body in plane motion: velocities transfer as
$v_P = v_C + \omega\times r_{CP}$, and rolling without slipping makes the contact point
the instantaneous centre of rotation (Section 3.1.1). Here $R$ = {{ R }}, $v$ = {{ v }},
$\varphi$ = {{ phi }}.

1. **Angular speed.** The contact point is at rest: $v - \omega R = 0$, so
   $\omega = v/R$ = {{ answers.omega }} (clockwise, $\omega = -\frac{v}{R}\,e_3$).
2. **Velocity of P.** From the hub, $r_{CP} = R\,(\sin\varphi,\,-\cos\varphi)$ and
   $\omega\times r_{CP} = -\frac{v}{R}\,e_3\times r_{CP} = -v\,(\cos\varphi,\,\sin\varphi)$:
   $$v_P = \bigl(v\,(1 - \cos\varphi),\; -v\sin\varphi\bigr),$$
   that is $v_P$ = {{ answers.v_P }}.
3. **Speed.** $|v_P| = v\sqrt{(1 - \cos\varphi)^2 + \sin^2\varphi} = v\sqrt{2 - 2\cos\varphi}
   = 2v\,|\sin(\varphi/2)|$, so $|v_P|$ = {{ answers.speed }}.
4. **Distance from the instantaneous centre.** The contact point is the instantaneous
   centre; P is a chord of length $2R\,|\sin(\varphi/2)|$ away from it, so
   $d$ = {{ answers.d_ICR }}. Check: $|v_P| = \omega\,d$.
5. **As a formula.** From step 3, $|v_P|$ = `{{ answers.speed_formula }}`.
""",
    solve=solve,
    checks=(
        # the rim point at angle phi from the contact point moves about it: speed
        # 2 v sin(phi/2), distance 2 R sin(phi/2) (Section 3.1.1)
        Recompute("speed", lambda p, s: 2 * p.v * abs(np.sin(p.phi / 2)), name="chord_speed"),
        Recompute("d_ICR", lambda p, s: 2 * p.R * abs(np.sin(p.phi / 2)), name="chord_length"),
        Balance("speed", lambda p, s: s["speed"], lambda p, s: s["omega"] * s["d_ICR"],
                name="rotation_about_icr"),
    ),
    figure=figure, figure_to_scale=True,
    parts=(
        Numeric("omega", "angular speed", question=1, unit="rad/s", points=1),
        Vector("v_P", "velocity of P", question=2, unit="m/s", size=2, points=2,
               misconceptions=(
                   Misconception("rotation about the hub only",
                                 lambda p: rk.velocity_of_point(np.zeros(2), -p.v / p.R,
                                                                _rim_position(p)),
                                 "Add the hub's velocity: v_P = v_C + ω × r_CP."),
               )),
        Numeric("speed", "speed of P", question=3, unit="m/s", points=1,
                misconceptions=(
                    Misconception("speed of the hub", lambda p: p.v,
                                  "Points of a rolling wheel move with ω times their distance "
                                  "from the contact point, not all with v."),
                )),
        Numeric("d_ICR", "distance from the instantaneous centre", question=4, unit="m", points=1,
                misconceptions=(
                    Misconception("centre of rotation at the hub", lambda p: p.R,
                                  "Rolling without slipping: the contact point is at rest, it "
                                  "is the instantaneous centre of rotation."),
                )),
        Symbolic("speed_formula", "speed of P as a formula", question=5, points=1,
                 expected="2*v*abs(sin(phi/2))",
                 variables=("v", "phi"),
                 equals="speed",
                 misconceptions=(
                     Misconception("rotation about the hub only", "v",
                                   "The contact point, not the hub, is at rest."),
                 )),
    ),
)
