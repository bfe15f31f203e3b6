"""A hanging rod struck by a particle: eccentric impact on a pinned body (Section 3.3)."""

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.checks import Balance, Recompute
import numpy as np

from dynagrade.exercise.figure import arrow, block, dimension, new_drawing, pivot
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import collisions, inertia, rigid_impact


def _moment_pivot(p):
    return inertia.parallel_axis_moment(inertia.inertia_tensor_rod(p.M, p.L)[0, 0], p.M, p.L / 2)


def _impulse(p, moment):
    w_rod = rigid_impact.inverse_effective_mass_pinned_body(moment, p.d)
    return rigid_impact.eccentric_impact_impulse(1.0 / p.m, w_rod, p.v, p.e)


def figure(p):
    """The rod to scale hanging from its pivot O and the ball arriving horizontally at the
    depth d below O (Section 3.3)."""
    from dynagrade.exercise.figure import Circle

    L = p.L
    drawing, axes = new_drawing(4.0, 3.6)
    pivot(axes, (0.0, 0.0), 0.08 * L)
    block(axes, (0.0, -L / 2), 0.035 * L, L, color="#a0724a")
    axes.text(0.0, -1.03 * L, f"M = {format_number(p.M)} kg", ha="center", va="top",
              fontsize=10)
    axes.text(-0.12 * L, 0.0, "O", ha="right", va="bottom", fontsize=10)
    ball = np.array([-0.5 * L, -p.d])
    radius = 0.035 * L
    axes.add_patch(Circle(tuple(ball), radius, facecolor="C0", edgecolor="0.1", lw=1.0))
    axes.text(ball[0], ball[1] + 1.6 * radius, f"m = {format_number(p.m)} kg", ha="center",
              va="bottom", fontsize=10)
    arrow(axes, (ball[0] + 1.5 * radius, ball[1]), (-0.06 * L, ball[1]), color="C3")
    axes.text(ball[0] + 0.22 * L, ball[1] - 0.04 * L, f"v = {format_number(p.v)} m/s",
              color="C3", ha="center", va="top", fontsize=10)
    dimension(axes, (0.0, 0.0), (0.0, -p.d), f"d = {format_number(p.d)} m", offset=0.15 * L,
              tick=0.03 * L, side=1.0)
    dimension(axes, (0.0, 0.0), (0.0, -L), f"L = {format_number(L)} m", offset=0.65 * L,
              tick=0.03 * L, side=1.0)
    axes.text(-0.85 * L, -1.03 * L, f"e = {format_number(p.e)}", ha="left", va="top",
              fontsize=10)
    axes.set_xlim(-0.9 * L, 0.9 * L)
    axes.set_ylim(-1.05 * L, 0.12 * L)
    return drawing


@per_draw
def solve(p):
    i_o = _moment_pivot(p)
    impulse = _impulse(p, i_o)
    return {
        "omega": rigid_impact.angular_velocity_change(impulse, p.d, i_o),
        "v_after": collisions.velocity_after_impulse(p.m, p.v, -impulse),
        "R_pivot": abs(rigid_impact.pivot_impulse(impulse, p.d, p.M, p.L / 2, i_o)),
        "d_percussion": rigid_impact.centre_of_percussion_distance(i_o, p.M, p.L / 2),
        "I_O": i_o,
        "impulse": impulse,
    }


@per_draw
def _free_particle_rebound(p):
    """The wrong route: the rod hit as if it were a free particle of mass M."""
    return p.v - rigid_impact.eccentric_impact_impulse(1 / p.m, 1 / p.M, p.v, p.e) / p.m


def _centroidal_omega(p):
    """The wrong route: the rod's moment of inertia about its centre."""
    i_c = inertia.inertia_tensor_rod(p.M, p.L)[0, 0]
    return rigid_impact.angular_velocity_change(_impulse(p, i_c), p.d, i_c)


EXERCISE = Exercise(
    id="rod-struck-by-particle",
    title="Hanging rod struck by a particle",
    source="Section 3.3",
    topics=("eccentric impact", "coefficient of restitution", "angular momentum"),
    params=(
        Uniform("M", 1.0, 10.0, step=0.5, unit="kg", symbol="M"),
        Uniform("L", 0.5, 2.0, step=0.1, unit="m", symbol="L"),
        Uniform("m", 0.1, 2.0, step=0.05, unit="kg", symbol="m"),
        Uniform("v", 2.0, 20.0, step=0.5, unit="m/s", symbol="v"),
        Uniform("d", 0.2, 2.0, step=0.05, unit="m", symbol="d"),
        Uniform("e", 0.1, 0.9, step=0.05, symbol="e"),
    ),
    constraints=(
        Constraint("the particle hits the rod clear of its ends", lambda p: 0.3 * p.L <= p.d <= 0.95 * p.L),
        Constraint("the blow is clear of the centre of percussion (2L/3), where the pivot "
                   "takes no impulse", lambda p: abs(p.d - 2 * p.L / 3) > 0.08 * p.L),
        Constraint("the rod's effective mass at the contact, M L^2/(3 d^2), differs from M "
                   "enough to change the ball's rebound",
                   lambda p: abs(_free_particle_rebound(p) - solve(p)["v_after"])
                   > 0.04 * abs(solve(p)["v_after"])),
        Constraint("the particle's velocity after the impact is not close to zero",
                   lambda p: abs(solve(p)["v_after"]) > 0.05 * p.v),
    ),
    statement=r"""
A slender rod (mass $M$ = {{ M }}, length $L$ = {{ L }}) hangs at rest from a frictionless
pivot O at its upper end. A small ball of mass $m$ = {{ m }} moving horizontally with
$v$ = {{ v }} hits it at the distance $d$ = {{ d }} below O; the coefficient of
restitution is $e$ = {{ e }}. Gravity plays no part during the short impact.

1. What is the rod's angular speed just after the impact?
2. What is the ball's velocity just after the impact (positive in its original direction)?
3. How large is the impulse the pivot exerts on the rod during the impact?
4. At which distance below O would the blow cause no impulse at the pivot?
""",
    solution=r"""
During the short impact only the contact impulse $\hat F$ and the pivot's impulse act on
the rod, so we use the impulse balances of an eccentric impact on a body pinned at O
together with the coefficient of restitution (impact of rigid bodies, Section 3.3).

**Moment of inertia and impulse.** About its end the rod has
$I_O = \tfrac{1}{3} M L^2$ = {{ si.I_O }} kg·m² ($M$ = {{ M }}, $L$ = {{ L }}). The ball
changes its momentum by $-\hat F$; the rod its angular momentum about O by $\hat F d$:
$$m v' = m v - \hat F,\qquad I_O\,\omega = \hat F d .$$
Restitution says the hit point of the rod, moving at $\omega d$, separates from the ball
with $e$ times the approach speed: $\omega d - v' = e\,v$. Together,
$$\hat F = \frac{(1 + e)\,v}{1/m + d^2/I_O},$$
where $d^2/I_O$ is the rod's effective inverse mass at the hit point. With $m$ = {{ m }},
$v$ = {{ v }}, $d$ = {{ d }} and $e$ = {{ e }}: $\hat F$ = {{ si.impulse }} N·s.

1. **Angular speed of the rod.** $\omega = \hat F d / I_O$, so $\omega$ = {{ answers.omega }}.
2. **Velocity of the ball.** $v' = v - \hat F/m$, so $v'$ = {{ answers.v_after }}
   (a negative value means the ball bounces back).
3. **Pivot impulse.** The linear impulse balance of the rod, whose centre moves at
   $\omega L/2$ afterwards: $M\,\omega\,\tfrac{L}{2} = \hat F + \hat R$, so
   $$|\hat R| = \Bigl|M\,\omega\,\frac{L}{2} - \hat F\Bigr|,$$
   that is $|\hat R|$ = {{ answers.R_pivot }}.
4. **Centre of percussion.** The pivot impulse vanishes when
   $M\,\frac{L}{2}\,\frac{\hat F d}{I_O} = \hat F$, i.e.
   $$d_P = \frac{I_O}{M\,L/2} = \tfrac{2}{3} L,$$
   so $d_P$ = {{ answers.d_percussion }}, whatever the ball and its speed.
""",
    solve=solve,
    checks=(
        # angular momentum about the pivot is conserved through the impact (Section 3.3)
        Balance("angular momentum about the pivot", lambda p, s: p.m * p.v * p.d,
                lambda p, s: p.m * s["v_after"] * p.d + p.M * p.L**2 / 3 * s["omega"],
                name="angular_momentum"),
        # Newton's restitution at the struck point
        Balance("separation speed", lambda p, s: p.e * p.v,
                lambda p, s: s["omega"] * p.d - s["v_after"], name="restitution"),
        Recompute("d_percussion", lambda p, s: 2 * p.L / 3, name="rod_two_thirds"),
        # the rod's linear momentum: M (L/2) omega = J + R, so the pivot's impulse is the rest
        Recompute("R_pivot", lambda p, s: abs(p.M * p.L / 2 * s["omega"] - s["impulse"]),
                  name="rod_linear_momentum"),
    ),
    figure=figure, figure_to_scale=True,
    parts=(
        Numeric("omega", "angular speed of the rod", question=1, unit="rad/s", points=2,
                misconceptions=(
                    Misconception("centroidal moment of inertia", _centroidal_omega,
                                  "The rod turns about O: use I_O = M L²/3 (parallel-axis "
                                  "theorem), not M L²/12."),
                )),
        Numeric("v_after", "velocity of the ball after the impact", question=2,
                unit="m/s", points=2,
                misconceptions=(
                    Misconception("rod treated as a free particle of mass M",
                                  lambda p: _free_particle_rebound(p),
                                  "The rod is pinned and turns: its effective mass at the "
                                  "contact is I_O / d²."),
                )),
        Numeric("R_pivot", "impulse at the pivot", question=3, unit="N*s", points=1),
        Numeric("d_percussion", "centre of percussion", question=4, unit="m", points=1,
                misconceptions=(
                    Misconception("centre of mass", lambda p: p.L / 2,
                                  "A blow at the centre of mass makes the pivot push back; "
                                  "the centre of percussion is at I_O/(M d_C) = 2L/3."),
                )),
    ),
)
