"""A cyclist riding straight past a turning carousel, as a rider on the carousel sees her:
the velocity and acceleration transfer solved for the relative motion (Section 3.4.2)."""

import numpy as np

from dynagrade.exercise import (Constraint, Exercise, Misconception, Numeric, Uniform, Vector,
                                per_draw)
from dynagrade.exercise.apart import numbers_apart
from dynagrade.exercise.checks import Recompute
from dynagrade.exercise.figure import Circle, arrow, describe, dimension, new_drawing
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import frames, kinematics

ZERO = np.zeros(3)


@per_draw
def solve(p):
    omega, omega_dot, r = [0.0, 0.0, p.Omega], [0.0, 0.0, p.Omega_dot], [p.d, 0.0, 0.0]
    v_rel = frames.relative_velocity([0.0, p.u, 0.0], ZERO, omega, r)
    a_rel = frames.relative_acceleration(ZERO, 1.0, ZERO, omega, omega_dot, r, v_rel)
    return {
        "v_rel": v_rel[:2],
        "a_rel": a_rel[:2],
        "rho": float(kinematics.radius_of_curvature(v_rel, a_rel)),
        "coriolis": frames.coriolis_acceleration(omega, v_rel)[0],
        "centrifugal": -frames.frame_centripetal_acceleration(omega, r)[0],
    }


def _curved(p):
    return abs(2 * p.Omega * p.u - p.Omega**2 * p.d) > 0.2 * p.Omega**2 * p.d


def _seen_from_carousel(p, t):
    """The cyclist's position in carousel axes: her straight path (d, u t) turned back by
    the carousel's angle Omega t + Omega_dot t^2 / 2."""
    angle = p.Omega * t + 0.5 * p.Omega_dot * t**2
    x, y = p.d, p.u * t
    return np.array([np.cos(angle) * x + np.sin(angle) * y, -np.sin(angle) * x + np.cos(angle) * y])


def _differences(p):
    """Velocity and acceleration of the seen path by central differences at t = 0."""
    dt = 1e-4 / max(p.Omega, abs(p.u) / p.d)
    before, now, after = (_seen_from_carousel(p, t) for t in (-dt, 0.0, dt))
    return (after - before) / (2 * dt), (after - 2 * now + before) / dt**2


def _curvature_radius(p, solved):
    v, a = _differences(p)
    return float(np.linalg.norm(v)**3 / abs(v[0] * a[1] - v[1] * a[0]))


def figure(p):
    """Top view to scale: the carousel turning counter-clockwise, the cyclist at the
    distance d from its axis riding straight past it (Section 3.4.2)."""
    d = p.d
    drawing, axes = new_drawing(4.6, 3.6)
    axes.add_patch(Circle((0.0, 0.0), 0.55 * d, facecolor="#eeeeee", edgecolor="0.3",
                          lw=1.0))
    axes.plot([0.0], [0.0], "o", color="0.1", ms=4)
    axes.text(-0.05 * d, -0.05 * d, "O", ha="right", va="top", fontsize=10)
    # the turn's sense: a counter-clockwise arrow along the arc (a bare arc shows none)
    axes.annotate("", xy=(0.62 * d * np.cos(0.7 * np.pi), 0.62 * d * np.sin(0.7 * np.pi)),
                  xytext=(0.62 * d * np.cos(0.3 * np.pi), 0.62 * d * np.sin(0.3 * np.pi)),
                  arrowprops={"arrowstyle": "-|>", "connectionstyle": "arc3,rad=0.25",
                              "color": "0.2", "lw": 1.0, "shrinkA": 0, "shrinkB": 0})
    axes.text(0.0, 0.75 * d, f"Ω = {format_number(p.Omega)} rad/s", ha="center", va="center", fontsize=10)
    axes.plot([d, d], [-0.6 * d, 0.6 * d], ls="--", color="0.5", lw=1.0)
    axes.plot([d], [0.0], "o", color="C3", ms=6)
    sense = 1.0 if p.u > 0 else -1.0
    arrow(axes, (d, 0.0), (d, sense * 0.4 * d), "u", offset=(0.06 * d, 0.0), color="C3")
    arrow(axes, (d, 0.0), (d + 0.3 * d, 0.0), "$e_r$", offset=(0.0, -0.06 * d), color="0.2")
    # d below the carousel: at -0.15 d its label lay across the carousel's rim
    dimension(axes, (0.0, 0.0), (d, 0.0), f"d = {format_number(d)} m", offset=-0.66 * d,
              tick=0.02 * d, side=-1.0)
    describe(axes, "Seen from above: the carousel turns counter-clockwise about O; the "
                   "cyclist rides along the dashed straight line, "
                   + ("in the sense of the carousel's turn" if p.u > 0 else "against the "
                      "sense of the carousel's turn") + ", at the distance d from O.")
    axes.set_xlim(-0.7 * d, 1.45 * d)
    axes.set_ylim(-0.85 * d, 0.9 * d)
    return drawing


EXERCISE = Exercise(
    id="cyclist-seen-from-carousel",
    title="A cyclist seen from a turning carousel",
    source="Section 3.4.2",
    topics=("rotating frames", "relative velocity", "Coriolis acceleration"),
    params=(
        Uniform("Omega", 0.2, 1.0, step=0.05, unit="rad/s", symbol=r"\Omega"),
        Uniform("Omega_dot", -0.2, 0.2, step=0.02, unit="rad/s^2", symbol=r"\dot\Omega"),
        Uniform("d", 3.0, 12.0, step=0.5, unit="m", symbol="d"),
        Uniform("u", -8.0, 8.0, step=0.5, unit="m/s", symbol="u"),
    ),
    constraints=(
        Constraint("the rider sees the cyclist move: |u - Omega d| > 0.8 m/s",
                   lambda p: abs(p.u - p.Omega * p.d) > 0.8),
        Constraint("the seen path is clearly curved: |2 Omega u - Omega^2 d| > 0.2 Omega^2 d",
                   _curved),
        Constraint("the cyclist rides at least 1 m/s", lambda p: abs(p.u) >= 1.0),
        Constraint("the radius of curvature differs from d by over 5 %",
                   lambda p: _curved(p) and numbers_apart([solve(p)["rho"], p.d])),
    ),
    statement=r"""
A carousel turns counter-clockwise (seen from above) about its vertical axis through O
with $\Omega$ = {{ Omega }} and the angular acceleration $\dot\Omega$ = {{ Omega_dot }}.
A cyclist rides on the ground along a straight line at the constant velocity $u$ =
{{ u }}, counted positive in the carousel's sense of turning. At the instant considered
she is at the distance $d$ = {{ d }} from O, at the point of her line closest to O. A
rider sits on the carousel; use the carousel's unit vectors $e_r$ (from O towards the
cyclist) and $e_\varphi$ (counter-clockwise) at that instant.

1. What is the cyclist's velocity relative to the carousel (components along $e_r$,
   $e_\varphi$)?
2. What is her acceleration relative to the carousel (components along $e_r$, $e_\varphi$)?
3. What is the radius of curvature of her path as the rider sees it?
""",
    solution=r"""
The carousel is the rotating frame, origin O, angular velocity $\Omega e_3$ and angular
acceleration $\dot\Omega e_3$. Solve the velocity and acceleration transfer (rotating
frames, Section 3.4.2) for the relative quantities, with $r = d\,e_r$, the absolute
velocity $u\,e_\varphi$ and no absolute acceleration:

1. **Relative velocity.** $v_{rel} = v - \Omega \times r = u\,e_\varphi - \Omega d\,e_\varphi$,
   so $v_{rel}$ = {{ answers.v_rel }}.
2. **Relative acceleration.**
   $a_{rel} = a - \dot\Omega \times r - \Omega \times (\Omega \times r) - 2\,\Omega \times v_{rel}$.
   Here $a = 0$; $-\Omega\times(\Omega\times r) = \Omega^2 d\,e_r$ = {{ si.centrifugal }} m/s²
   along $e_r$ (centrifugal), $-2\,\Omega\times v_{rel} = 2\Omega(u - \Omega d)\,e_r$
   = {{ si.coriolis }} m/s² along $e_r$ (minus the Coriolis term), and
   $-\dot\Omega\times r = -\dot\Omega d\,e_\varphi$. Together
   $$a_{rel} = (2\Omega u - \Omega^2 d)\,e_r - \dot\Omega d\,e_\varphi$$
   = {{ answers.a_rel }}.
3. **Curvature.** $v_{rel}$ is along $e_\varphi$, so only the $e_r$ part of $a_{rel}$ bends
   the path: $\rho = |v_{rel}|^2/|a_{rel,r}|$ = {{ answers.rho }}. The rider sees the
   cyclist on a curve, though she rides straight.

**Check.** Turning the cyclist's straight path back by the carousel's angle and
differentiating it numerically gives the radius {{ checks.seen_path }} m.
""",
    solve=solve,
    checks=(
        # the seen path r_rel(t) = R(-angle(t)) r(t), differentiated by central differences
        Recompute("v_rel", lambda p, s: tuple(_differences(p)[0]), name="seen_velocity",
                  rtol=1e-5, atol=1e-6),
        Recompute("a_rel", lambda p, s: tuple(_differences(p)[1]), name="seen_acceleration",
                  rtol=1e-3, atol=1e-4),
        Recompute("rho", _curvature_radius, name="seen_path", rtol=1e-3),
    ),
    figure=figure, figure_to_scale=True,
    parts=(
        Vector("v_rel", "velocity relative to the carousel", question=1, unit="m/s",
               basis=("e_r", "e_phi"), points=1, atol=0.02,
               misconceptions=(
                   Misconception("frame velocity added", lambda p: (0.0, p.u + p.Omega * p.d),
                                 "v = Ω × r + v_rel: the relative velocity is v − Ω × r."),
               )),
        Vector("a_rel", "acceleration relative to the carousel", question=2, unit="m/s^2",
               basis=("e_r", "e_phi"), points=2, atol=0.02,
               misconceptions=(
                   Misconception("no relative acceleration: she rides straight",
                                 lambda p: (0.0, 0.0),
                                 "Straight at constant speed in the fixed frame is curved "
                                 "and accelerated as seen from the turning carousel."),
                   Misconception("Coriolis term left out",
                                 lambda p: (p.Omega**2 * p.d, -p.Omega_dot * p.d),
                                 "The cyclist moves relative to the carousel: subtract "
                                 "2 Ω × v_rel as well."),
               )),
        Numeric("rho", "radius of curvature of the seen path", question=3, unit="m", points=1,
                misconceptions=(
                    Misconception("a circle about the axis", lambda p: p.d,
                                  "The seen path is not a circle about O: ρ = v_rel²/a_n."),
                )),
    ),
)
