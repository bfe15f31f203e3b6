"""A shell explodes at the top of its flight: the centre of mass flies on (Section 2.2.1)."""

import numpy as np

from dynagrade.exercise import Constant, Constraint, Exercise, Misconception, Numeric, Uniform
from dynagrade.exercise.checks import Recompute
from dynagrade.mechanics import systems
from dynagrade.mechanics.examples import projectile


def _fragment_2_speed(p):
    """Momentum of the shell at the apex, now carried by fragment 2 alone (fragment 1
    is left at rest)."""
    apex_velocity = [p.v0 * np.cos(p.alpha)]
    return systems.total_momentum([p.M], [apex_velocity])[0] / (p.M - p.m1)


def solve(p):
    t_apex = projectile.peak_time(p.v0, p.alpha, p.g)
    x_apex = projectile.position(t_apex, p.v0, p.alpha, p.g)[0]
    v2 = _fragment_2_speed(p)
    # both fragments start with zero vertical velocity: they land together after t_apex
    x1, x2 = x_apex, x_apex + v2 * t_apex
    return {
        "v2": v2,
        "x2": x2,
        "x_c": systems.centre_of_mass([p.m1, p.M - p.m1], [[x1], [x2]])[0],
        "v_apex": float(projectile.velocity(t_apex, p.v0, p.alpha, p.g)[0]),
        "t_apex": t_apex,
        "x_apex": float(x_apex),
    }


EXERCISE = Exercise(
    id="exploding-shell",
    title="A shell exploding at the top of its flight",
    source="Section 2.2.1",
    topics=("centre of mass", "balance of linear momentum of a system", "projectile motion"),
    params=(
        Uniform("M", 2.0, 20.0, step=0.5, unit="kg", symbol="M"),
        Uniform("m1", 0.5, 15.0, step=0.5, unit="kg", symbol="m_1"),
        Uniform("v0", 20.0, 80.0, step=1.0, unit="m/s", symbol="v_0"),
        Uniform("alpha", 25, 70, step=1, unit="deg", symbol=r"\alpha"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("fragment 1 is a real part of the shell (0.1 M < m1 < 0.9 M)",
                   lambda p: 0.1 * p.M < p.m1 < 0.9 * p.M),
    ),
    statement=r"""
A shell of mass $M$ = {{ M }} is fired from level ground with speed $v_0$ = {{ v0 }} at
$\alpha$ = {{ alpha }} above the horizontal ($g$ = {{ g }}, no air drag). At the top of
its flight it explodes into two fragments. Fragment 1 of mass $m_1$ = {{ m1 }} is left at
rest just after the explosion and falls vertically; fragment 2 flies on horizontally.

1. What is the speed of fragment 2 just after the explosion?
2. How far from the gun does fragment 2 land?
3. Where (distance from the gun) is the centre of mass of the two fragments when both
   have landed?
""",
    solution=r"""
The explosion's forces are internal: they cannot change the total momentum of shell and
fragments, and in the short explosion gravity's impulse is negligible (Section 2.2.1). Before
the explosion the shell flies as a projectile: at the top its velocity is horizontal,
$v_0\cos\alpha$ = {{ si.v_apex }} m/s, reached at $t_{\text{top} } = v_0\sin\alpha/g$
= {{ si.t_apex }} s at the distance $x_{\text{top} } = v_0^2\sin\alpha\cos\alpha/g$
= {{ si.x_apex }} m (with $v_0$ = {{ v0 }}, $\alpha$ = {{ alpha }}, $g$ = {{ g }}).

1. **Speed of fragment 2.** Momentum just before equals momentum just after, and fragment 1
   is at rest: $M v_0\cos\alpha = (M - m_1)\,v_2$, so
   $v_2 = \frac{M}{M - m_1}\,v_0\cos\alpha$
   with $M$ = {{ M }}, $m_1$ = {{ m1 }}: $v_2$ = {{ answers.v2 }}.
2. **Landing point of fragment 2.** It starts horizontally from the top, so it falls the
   same height the shell rose and needs the same time $t_{\text{top} }$:
   $x_2 = x_{\text{top} } + v_2\,t_{\text{top} }$ = {{ answers.x2 }}.
3. **Centre of mass.** Fragment 1 falls vertically and lands at $x_1 = x_{\text{top} }$, at
   the same time as fragment 2. So
   $x_C = (m_1 x_1 + (M - m_1)\,x_2)/M$ = {{ answers.x_c }} — exactly the range
   $v_0^2\sin 2\alpha/g$ the shell would have had without exploding: only external forces
   (gravity) move the centre of mass.
4. **Check.** The intact shell's range, eq. (1.80), is $v_0^2\sin 2\alpha/g$ =
   {{ checks.centre_of_mass_range }} m: the same number as $x_C$.
""",
    solve=solve,
    checks=(
        # the explosion's forces are internal: the centre of mass flies on as the unexploded
        # shell and lands at its range, eq. (1.80)
        Recompute("x_c", lambda p, s: p.v0**2 * np.sin(2 * p.alpha) / p.g,
                  name="centre_of_mass_range"),
        Recompute("v2", lambda p, s: p.M * p.v0 * np.cos(p.alpha) / (p.M - p.m1),
                  name="momentum_balance"),
    ),
    parts=(
        Numeric("v2", "speed of fragment 2 after the explosion", question=1, unit="m/s", points=1,
                misconceptions=(
                    Misconception("speed of the shell kept", lambda p: p.v0 * np.cos(p.alpha),
                                  "Fragment 2 carries all the shell's momentum with only part "
                                  "of its mass."),
                )),
        Numeric("x2", "landing distance of fragment 2", question=2, unit="m", points=2,
                misconceptions=(
                    Misconception("lands where the shell would have landed",
                                  lambda p: projectile.horizontal_range(p.v0, p.alpha, p.g),
                                  "That is where the centre of mass lands, not fragment 2."),
                )),
        Numeric("x_c", "landing point of the centre of mass", question=3, unit="m", points=1,
                misconceptions=(
                    Misconception("centre of mass at the point below the apex",
                                  lambda p: projectile.horizontal_range(p.v0, p.alpha, p.g) / 2,
                                  "Internal forces of the explosion do not change the motion "
                                  "of the centre of mass: it lands where the shell would have."),
                )),
    ),
)
