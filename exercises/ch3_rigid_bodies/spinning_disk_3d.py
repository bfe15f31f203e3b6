"""A disk spinning on an axle that itself turns: angular velocity and omega x r in 3D
(Section 3.1.2)."""

import numpy as np

from dynagrade.exercise import (Constraint, Exercise, Misconception, Numeric, Uniform, Vector,
                                per_draw)
from dynagrade.exercise.checks import Balance, Recompute
from dynagrade.mechanics import rigid_kinematics as rk


def _omega(p):
    return np.array([p.ws, 0.0, p.Omega])


def _r(p):
    """Rim point relative to the fixed pivot O."""
    return np.array([p.d, p.R * np.sin(p.gamma), p.R * np.cos(p.gamma)])


@per_draw
def solve(p):
    v = rk.velocity_of_point(np.zeros(3), _omega(p), _r(p))
    return {"omega_vec": _omega(p), "v_P": v, "speed": float(np.linalg.norm(v))}


def _cross_by_hand(p, solved):
    """v = omega x r with omega = (omega_s, 0, Omega), r = (d, R sin(gamma), R cos(gamma))."""
    return (-p.Omega * p.R * np.sin(p.gamma),
            p.Omega * p.d - p.ws * p.R * np.cos(p.gamma),
            p.ws * p.R * np.sin(p.gamma))


EXERCISE = Exercise(
    id="spinning-disk-on-turning-axle",
    title="Disk spinning on a turning axle",
    source="Section 3.1.2",
    topics=("rigid-body kinematics in 3D", "angular velocity", "velocity transfer"),
    params=(
        Uniform("d", 0.1, 0.5, step=0.05, unit="m", symbol="d"),
        Uniform("R", 0.05, 0.3, step=0.01, unit="m", symbol="R"),
        Uniform("ws", 10, 80, step=5, unit="rad/s", symbol=r"\omega_s"),
        Uniform("Omega", 4.0, 20.0, step=0.5, unit="rad/s", symbol=r"\Omega"),
        Uniform("gamma", 0, 330, step=30, unit="deg", symbol=r"\gamma"),
    ),
    constraints=(
        Constraint("the turning of the axle changes the speed of P noticeably",
                   lambda p: abs(solve(p)["speed"] - p.ws * p.R) > 0.04 * p.ws * p.R),
    ),
    statement=r"""
A disk of radius $R$ = {{ R }} spins with $\omega_s$ = {{ ws }} relative to its horizontal
axle, about the axle, in the positive sense about $e_1$. The axle is held at the fixed
point O, the disk's centre sits at distance $d$ = {{ d }} from O along the axle, and the
axle turns about the vertical $e_3$ through O with $\Omega$ = {{ Omega }}. At the instant
considered the axle lies along $e_1$. A point P on the rim is at
$r_{OP} = d\,e_1 + R(\sin\gamma\, e_2 + \cos\gamma\, e_3)$ with $\gamma$ = {{ gamma }}.

1. What is the angular velocity vector of the disk (components along $e_1, e_2, e_3$)?
2. What is the velocity vector of P?
3. What is the speed of P?
""",
    solution=r"""
The disk's angular velocity is the sum of its spin relative to the axle and the axle's
own turning, and a point's velocity follows from the velocity transfer formula with the
fixed point O (rigid-body kinematics in 3D, Section 3.1.2). Here $\omega_s$ = {{ ws }},
$\Omega$ = {{ Omega }}, $d$ = {{ d }}, $R$ = {{ R }}, $\gamma$ = {{ gamma }}.

1. **Angular velocity.** The spin is about the axle $e_1$, the axle turns about $e_3$:
   $$\omega = \omega_s\,e_1 + \Omega\,e_3,$$
   that is $\omega$ = {{ answers.omega_vec }}.
2. **Velocity of P.** O is fixed, so $v_P = \omega\times r_{OP}$ with
   $r_{OP} = (d,\; R\sin\gamma,\; R\cos\gamma)$:
   $$v_P = \bigl(-\Omega R\sin\gamma,\;\; \Omega d - \omega_s R\cos\gamma,\;\; \omega_s R\sin\gamma\bigr),$$
   that is $v_P$ = {{ answers.v_P }}. Both rotations must be in $\omega\times r$: with
   the spin alone the axle's turning would be missing.
3. **Speed.** $|v_P| = \sqrt{v_1^2 + v_2^2 + v_3^2}$ = {{ answers.speed }}.
""",
    solve=solve,
    checks=(
        Recompute("v_P", _cross_by_hand, name="cross_product_by_hand", atol=1e-12),
        # a rotation about O moves P across both omega and r
        Balance("v_P . omega", lambda p, s: 0.0,
                lambda p, s: float(np.dot(s["v_P"], (p.ws, 0.0, p.Omega))),
                name="across_omega", atol=1e-9),
    ),
    parts=(
        Vector("omega_vec", "angular velocity", question=1, unit="rad/s", size=3, points=1,
               misconceptions=(
                   Misconception("spin only", lambda p: (p.ws, 0.0, 0.0),
                                 "The disk also turns with the axle: ω = ω_s e1 + Ω e3."),
               )),
        Vector("v_P", "velocity of P", question=2, unit="m/s", size=3, points=2,
               misconceptions=(
                   Misconception("spin only",
                                 lambda p: rk.velocity_of_point(np.zeros(3), [p.ws, 0, 0], _r(p)),
                                 "Use the total angular velocity ω = ω_s e1 + Ω e3 in ω × r."),
               )),
        Numeric("speed", "speed of P", question=3, unit="m/s", points=1,
                misconceptions=(
                    Misconception("spin only", lambda p: p.ws * p.R,
                                  "The turning axle adds Ω e3 × r_OP."),
                )),
    ),
)
