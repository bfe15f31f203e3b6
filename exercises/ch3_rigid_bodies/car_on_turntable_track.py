"""A rail car running round a circular track on a turning platform: velocity and
acceleration transfer to the rotating frame, the Coriolis term (Section 3.4.2)."""

import numpy as np

from dynagrade.exercise import (Constraint, Exercise, Misconception, Numeric, Options, Uniform,
                                per_draw)
from dynagrade.exercise.apart import numbers_apart
from dynagrade.exercise.checks import Balance, Limit, Recompute
from dynagrade.exercise.figure import Circle, arrow, block, describe, new_drawing
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import frames, kinematics, particle


@per_draw
def solve(p):
    omega, r, v_rel = [0.0, 0.0, p.Omega], [p.r, 0.0, 0.0], [0.0, p.u, 0.0]
    a_rel = [-kinematics.path_centripetal_acceleration(p.u, p.r), 0.0, 0.0]
    v = frames.absolute_velocity(np.zeros(3), omega, r, v_rel)
    a = frames.absolute_acceleration(np.zeros(3), omega, np.zeros(3), r, v_rel, a_rel)
    coriolis = frames.coriolis_acceleration(omega, v_rel)
    return {
        "v": float(np.linalg.norm(v)),
        "a_C": float(np.linalg.norm(coriolis)),
        "coriolis_points": "outward" if coriolis[0] > 0 else "inward",
        "F": float(np.linalg.norm(particle.resultant_force(p.m, a))),
        "a_rel": -a_rel[0],
        "a_frame": p.Omega**2 * p.r,
        "a": float(np.linalg.norm(a)),
    }


def figure(p):
    """Top view: the platform turning counter-clockwise, the circular track of radius r and
    the car running along it with u relative to the platform (Section 3.4.2)."""
    r = p.r
    drawing, axes = new_drawing(4.0, 4.0)
    axes.add_patch(Circle((0.0, 0.0), 1.3 * r, facecolor="#eeeeee", edgecolor="0.3", lw=1.0))
    turn = np.linspace(0.0, 2 * np.pi, 73)
    axes.plot(r * np.cos(turn), r * np.sin(turn), ls="--", color="0.2", lw=1.0)
    axes.plot([0.0], [0.0], "o", color="0.1", ms=4)
    arrow(axes, (0.0, 0.0), (r, 0.0), f"r = {format_number(r)} m", offset=(0.0, 0.08 * r),
          color="0.2")
    # the turn's sense: a counter-clockwise arrow along the arc (a bare arc shows none)
    axes.annotate("", xy=(1.45 * r * np.cos(0.65 * np.pi), 1.45 * r * np.sin(0.65 * np.pi)),
                  xytext=(1.45 * r * np.cos(0.35 * np.pi), 1.45 * r * np.sin(0.35 * np.pi)),
                  arrowprops={"arrowstyle": "-|>", "connectionstyle": "arc3,rad=0.25",
                              "color": "0.2", "lw": 1.0, "shrinkA": 0, "shrinkB": 0})
    axes.text(0.0, 1.62 * r, f"Ω = {format_number(p.Omega)} rad/s", ha="center", va="center", fontsize=10)
    block(axes, (r, 0.0), 0.1 * r, 0.22 * r, color="C0")
    sense = np.sign(p.u)
    arrow(axes, (1.12 * r, 0.0), (1.12 * r, sense * 0.45 * r), color="C3")
    axes.text(1.16 * r, sense * 0.25 * r, "u",
              color="C3", ha="left", va="center", fontsize=10)
    describe(axes, "Seen from above: the platform turns counter-clockwise; the car runs on "
                   "the dashed track, "
                   + ("counter-clockwise" if p.u > 0 else "clockwise")
                   + " relative to the platform.")
    axes.set_xlim(-1.45 * r, 2.2 * r)
    axes.set_ylim(-1.45 * r, 1.85 * r)
    return drawing


EXERCISE = Exercise(
    id="car-on-turntable-track",
    title="Rail car on a circular track on a turning platform",
    source="Section 3.4.2",
    topics=("rotating frames", "Coriolis acceleration", "relative motion"),
    params=(
        Uniform("m", 20.0, 200.0, step=5.0, unit="kg", symbol="m"),
        Uniform("r", 1.0, 5.0, step=0.1, unit="m", symbol="r"),
        Uniform("Omega", 0.3, 1.5, step=0.05, unit="rad/s", symbol=r"\Omega"),
        Uniform("u", -3.0, 3.0, step=0.1, unit="m/s", symbol="u"),
    ),
    constraints=(
        Constraint("the car runs on the platform: |u| >= 0.3 m/s", lambda p: abs(p.u) >= 0.29),
        Constraint("a platform that can carry a track: its own centripetal acceleration "
                   "Omega^2 r stays below 4 m/s^2 (the draws reached 11 m/s^2, over 1 g)",
                   lambda p: p.Omega**2 * p.r <= 4.0),
        Constraint("the car does not stand (nearly) still in the fixed frame: "
                   "|Omega r + u| > 0.2 Omega r", lambda p: abs(p.Omega * p.r + p.u)
                   > 0.2 * p.Omega * p.r),
        Constraint("speed, Coriolis acceleration and force differ by over 5 %",
                   lambda p: numbers_apart([solve(p)[k] for k in ("v", "a_C", "F")])),
    ),
    statement=r"""
A platform turns counter-clockwise (seen from above) about a vertical axis with the
constant rate $\Omega$ = {{ Omega }}. A circular track of radius $r$ = {{ r }} centred on
the axis is laid on it, and a rail car of mass $m$ = {{ m }} runs along the track with
the constant velocity $u$ = {{ u }} relative to the platform, counted positive
counter-clockwise (a negative $u$: the car runs against the platform's turn).

1. What is the car's speed in the fixed frame?
2. How large is its Coriolis acceleration?
3. Does the Coriolis acceleration point towards the axis or away from it? (`inward` or
   `outward`)
4. How large is the horizontal force the rails exert on the car?
""",
    solution=r"""
Take the platform as the rotating frame, with $e_r$ from the axis to the car and $e_\varphi$
counter-clockwise; its angular velocity is $\Omega e_3$ (rotating frames, Section 3.4.2).
Relative to the platform the car moves on a circle: $r_{rel} = r e_r$,
$v_{rel} = u\,e_\varphi$, $a_{rel} = -\frac{u^2}{r} e_r$ ({{ si.a_rel }} m/s² inward).

1. **Velocity.** $v = \Omega \times r_{rel} + v_{rel} = (\Omega r + u)\,e_\varphi$, so
   $|v| = |\Omega r + u|$ = {{ answers.v }}.
2. **Coriolis term.** $a_{Cor} = 2\,\Omega \times v_{rel} = -2\Omega u\,e_r$:
   $|a_{Cor}| = 2\Omega|u|$ = {{ answers.a_C }}.
3. It points along $-2\Omega u\,e_r$: **{{ answers.coriolis_points }}**
   (towards the axis when the car runs with the platform, away from it against).
4. **Force.** $a = \Omega \times (\Omega \times r_{rel}) + 2\,\Omega \times v_{rel} + a_{rel}
   = -\bigl(\Omega^2 r + 2\Omega u + u^2/r\bigr) e_r = -\frac{(\Omega r + u)^2}{r} e_r$;
   the frame's own term is $\Omega^2 r$ = {{ si.a_frame }} m/s². Its magnitude is
   {{ si.a }} m/s², and the rails must supply $F = m\,|a|$ = {{ answers.F }}.

**Check.** In the fixed frame the car simply goes round a circle of radius $r$ at the
speed $|\Omega r + u|$, so $F = m(\Omega r + u)^2/r$ = {{ checks.fixed_frame_circle }} N.
""",
    solve=solve,
    checks=(
        # polar kinematics, eq. (1.33): phi_dot = Omega + u / r on a circle of radius r
        Recompute("v", lambda p, s: abs(p.r * (p.Omega + p.u / p.r)), name="polar_speed"),
        # in the fixed frame: uniform circular motion, F = m v^2 / r
        Balance("rail force", lambda p, s: s["F"],
                lambda p, s: p.m * (p.Omega * p.r + p.u)**2 / p.r, name="fixed_frame_circle"),
        # a car at rest on the platform needs only the platform's centripetal force
        Limit("F", {"u": 0.0}, lambda p: p.m * p.Omega**2 * p.r, name="car_at_rest"),
    ),
    figure=figure, figure_to_scale=True,
    parts=(
        Numeric("v", "speed in the fixed frame", question=1, unit="m/s", points=1,
                misconceptions=(
                    Misconception("the speeds added whatever the sense",
                                  lambda p: p.Omega * p.r + abs(p.u),
                                  "The car's relative velocity is u e_φ with its sign: "
                                  "v = (Ω r + u) e_φ.", applies=lambda p: p.u < 0),
                )),
        Numeric("a_C", "magnitude of the Coriolis acceleration", question=2, unit="m/s^2",
                points=1,
                misconceptions=(
                    Misconception("factor 2 forgotten", lambda p: abs(p.Omega * p.u),
                                  "The Coriolis term is 2 Ω × v_rel."),
                )),
        Options("coriolis_points", "direction of the Coriolis acceleration", question=3,
                options=("inward", "outward")),
        Numeric("F", "force of the rails", question=4, unit="N", points=2,
                misconceptions=(
                    Misconception("Coriolis term left out",
                                  lambda p: p.m * (p.Omega**2 * p.r + p.u**2 / p.r),
                                  "The car moves relative to the turning platform: add the "
                                  "Coriolis term 2 Ω × v_rel to a_rel and Ω × (Ω × r)."),
                    Misconception("relative acceleration alone",
                                  lambda p: p.m * p.u**2 / p.r,
                                  "Newton's law holds for the absolute acceleration, "
                                  "a = a_rel + Ω × (Ω × r) + 2 Ω × v_rel."),
                )),
    ),
)
