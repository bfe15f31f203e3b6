"""Maximum height of a throw from the energy balance (Example 1.12, eq. 1.106)."""

import numpy as np

from dynagrade.exercise import (Constant, Exercise, Misconception, Numeric, Symbolic,
                                Uniform)
from dynagrade.exercise.checks import Balance, Integrated
from dynagrade.exercise.checks.motions import launched, rising, thrown
from dynagrade.mechanics import energy
from dynagrade.mechanics.examples import projectile


def solve(p):
    # at the peak the velocity is horizontal: the launch component v0 cos(alpha), kept in flight
    v_top = float(projectile.velocity(projectile.peak_time(p.v0, p.alpha, p.g),
                                      p.v0, p.alpha, p.g)[0])
    return {"v_top": v_top, "h": energy.height_gain(p.v0, v_top, p.g),
            "T_top": float(energy.particle_kinetic_energy(p.m, v_top)),
            "T0": float(energy.particle_kinetic_energy(p.m, p.v0))}


def sin_and_cos_differ(p):
    """Whether sin α and cos α differ by more than 2 % (twice the tolerance): near 45°
    taking one for the other is no mistake, so it is not tried there."""
    return abs(np.tan(p.alpha) - 1) > 0.02


def _launch(p):
    """The launch state of eq. (1.75)."""
    return launched(p.v0, p.alpha)


def _longer_than_the_rise(p, solved):
    """The rise takes v0 sin(alpha) / g at most."""
    return 2 * p.v0 / p.g


EXERCISE = Exercise(
    id="peak-height-by-energy",
    title="Peak height of a throw by the energy balance",
    source="Example 1.12",
    topics=("work-energy balance", "conservation of energy", "projectile motion"),
    params=(
        Uniform("m", 0.1, 2.0, step=0.05, unit="kg", symbol="m"),
        Uniform("v0", 5.0, 30.0, step=0.5, unit="m/s", symbol="v_0"),
        Uniform("alpha", 20, 75, step=1, unit="deg", symbol=r"\alpha"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    statement="""
A ball of mass $m$ = {{ m }} is thrown with speed $v_0$ = {{ v0 }} at $\\alpha$ = {{ alpha }}
above the horizontal; $g$ = {{ g }}, no air drag. Use the conservation of energy.

1. What is its speed at the highest point?
2. How high above the launch point does it rise?
3. What is its kinetic energy at the highest point?
4. Write the height as a formula in $v_0$, $\\alpha$ and $g$.
""",
    solution=r"""
Only gravity acts during the flight and gravity is conservative, so $T + V$ is constant
(eq. (1.102)); no integration of the trajectory is needed (Example 1.12).

1. **Speed at the top.** Gravity has no horizontal component, so the horizontal velocity
   $v_0\cos\alpha$ never changes; at the highest point the vertical velocity is zero. Hence
   $v_{\text{top} } = v_0\cos\alpha$ = {{ answers.v_top }} (with $v_0$ = {{ v0 }},
   $\alpha$ = {{ alpha }}).
2. **Peak height.** Energy conservation between launch and top,
   $\tfrac{1}{2} m v_0^2 = \tfrac{1}{2} m v_{\text{top} }^2 + mgh$, gives
   $h = \frac{v_0^2 - v_{\text{top} }^2}{2g} = \frac{v_0^2\sin^2\alpha}{2g}$
   (eq. (1.106)); with $g$ = {{ g }}: $h$ = {{ answers.h }}.
3. **Kinetic energy at the top.** $T = \tfrac{1}{2} m v_{\text{top} }^2$ with $m$ = {{ m }}:
   $T$ = {{ answers.T_top }}, out of $\tfrac{1}{2} m v_0^2$ = {{ si.T0 }} J at launch; the rest
   has become potential energy $mgh$.
4. **Formula.** $h$ = `{{ answers.h_formula }}`.
""",
    solve=solve,
    checks=(
        Integrated("h", thrown, _launch, _longer_than_the_rise,
                   lambda t, y, p: y[1], name="integrated_peak", event=rising, direction=-1),
        Integrated("v_top", thrown, _launch, _longer_than_the_rise, lambda t, y, p: np.hypot(y[2], y[3]),
                   name="integrated_speed_at_peak", event=rising, direction=-1),
        # energy conservation, eq. (1.102): T0 = T_top + m g h
        Balance("energy", lambda p, s: s["T0"], lambda p, s: s["T_top"] + p.m * p.g * s["h"],
                name="energy_balance"),
    ),
    parts=(
        Numeric("v_top", "speed at the top", question=1, unit="m/s", points=1,
                misconceptions=(
                    Misconception("at rest at the top", lambda p: 0.0,
                                  "Only the vertical velocity vanishes at the top; v0 cos α remains."),
                    Misconception("sin for cos", lambda p: p.v0 * np.sin(p.alpha),
                                  "The horizontal component is v0 cos α.",
                                  applies=sin_and_cos_differ),
                )),
        Numeric("h", "peak height", question=2, unit="m", points=2,
                misconceptions=(
                    Misconception("all kinetic energy into height", lambda p: p.v0**2 / (2 * p.g),
                                  "The horizontal motion keeps m (v0 cos α)²/2, eq. (1.105)."),
                )),
        Numeric("T_top", "kinetic energy at the top", question=3, unit="J", points=1),
        Symbolic("h_formula", "peak height as a formula", question=4, points=1,
                 expected="v0^2*sin(alpha)^2/(2*g)",
                 variables=("v0", "alpha", "g"),
                 equals="h",
                 misconceptions=(
                     Misconception("all kinetic energy into height", "v0^2/(2*g)",
                                   "The horizontal velocity is kept at the top."),
                     Misconception("cos for sin", "v0^2*cos(alpha)^2/(2*g)",
                                   "The height comes from the vertical component v0 sin α."),
                 )),
    ),
)
