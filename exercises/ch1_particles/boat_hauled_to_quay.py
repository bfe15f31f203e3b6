"""A boat hauled toward a quay by a rope wound on a winch above the water: the rope is a
kinematic constraint whose length the winch prescribes (Section 1.1.2, Example 1.4(d)),
and differentiating it gives the boat's speed and acceleration."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.apart import numbers_apart
from dynagrade.exercise.checks import Integrated, Limit, Recompute
from dynagrade.exercise.figure import arrow, block, describe, dimension, new_drawing, wall
from dynagrade.mechanics import kinematics


@per_draw
def solve(p):
    return {
        "v": float(kinematics.hauled_speed(p.x, p.h, p.u)),
        "a": float(kinematics.hauled_acceleration(p.x, p.h, p.u)),
        "t_half": float(kinematics.hauling_time(p.x, p.x / 2, p.h, p.u)),
        # for the worked solution: the rope's length now and at x/2
        "l0": float(np.hypot(p.x, p.h)),
        "l1": float(np.hypot(p.x / 2, p.h)),
    }


def _bow(t, y, p):
    """The constraint solved for the boat's motion: x' = -u sqrt(x^2 + h^2)/x."""
    return (-p.u * np.sqrt(y[0]**2 + p.h**2) / y[0],)


def _keys_apart(p) -> bool:
    """The three answers (speed, acceleration, time, in SI) differ pairwise by over 5 %."""
    s = solve(p)
    values = (s["v"], s["a"], s["t_half"])
    return numbers_apart(values)


def figure(p):
    """Side view to scale: the quay wall, the winch at the height h above the bow, the rope
    from the winch down to the bow, the boat at the horizontal distance x."""
    drawing, axes = new_drawing(5.0, 2.6)
    wall(axes, 0.0, -0.3 * p.h, 1.15 * p.h, side=-1.0, hatch=0.04 * p.x)
    axes.plot([0.0, 1.25 * p.x], [0.0, 0.0], color="C0", lw=0.8, ls="--")   # the water line
    axes.plot([0.0, p.x], [p.h, 0.0], color="0.2", lw=1.2)                   # the rope
    axes.plot([0.0], [p.h], "o", color="0.1", ms=6)                          # the winch
    block(axes, (p.x + 0.12 * p.x, 0.0), 0.24 * p.x, 0.12 * p.x, color="C1")
    dimension(axes, (0.0, -0.22 * p.h), (p.x, -0.22 * p.h), "x", side=-1.0)
    dimension(axes, (-0.12 * p.x, 0.0), (-0.12 * p.x, p.h), "h", side=1.0)
    arrow(axes, (0.35 * p.x, 0.65 * p.h), (0.15 * p.x, 0.85 * p.h), "u", offset=(0.0, 0.08 * p.h),
          color="C3")
    describe(axes, "Side view: the rope runs from the bow of the boat, on the water line, up "
             "to the winch on the quay wall at the height h; the winch winds the rope in at "
             "the rate u, pulling the boat to the left, toward the wall.")
    axes.set_xlim(-0.3 * p.x, 1.35 * p.x)
    axes.set_ylim(-0.45 * p.h, 1.25 * p.h)
    return drawing


EXERCISE = Exercise(
    id="boat-hauled-to-quay",
    title="A boat hauled to the quay by a winch",
    source="Section 1.1.2",
    topics=("constrained motion", "kinematic constraint", "rope"),
    params=(
        Uniform("h", 1.0, 4.0, step=0.1, unit="m", symbol="h"),
        Uniform("u", 0.3, 1.5, step=0.05, unit="m/s", symbol="u"),
        Uniform("x", 2.0, 8.0, step=0.1, unit="m", symbol="x"),
    ),
    constraints=(
        Constraint("the rope is clearly inclined, h >= 0.35 x (else the boat moves almost "
                   "as the rope does)", lambda p: p.h >= 0.35 * p.x),
        Constraint("the three answers differ by over 5 %", _keys_apart),
    ),
    statement=r"""
A boat is hauled toward a quay by a rope tied to its bow. The rope runs in a straight line
up to a winch on the quay wall, at the height $h$ = {{ h }} above the bow, and the winch
winds it in at the constant rate $u$ = {{ u }}. The bow stays on the water surface; the
rope stays taut and does not stretch.

At the instant when the bow is at the horizontal distance $x$ = {{ x }} from the wall:

1. how fast does the boat move?
2. what is the magnitude of its acceleration?
3. how long does the winch take to bring the bow to the distance $x/2$ from the wall?
""",
    solution=r"""
The boat is constrained twice (Section 1.1.2, eq. (1.21)): the water surface keeps the bow
at the height of the water line, and the taut rope keeps the bow at the rope's length
$l(t)$ from the winch (as the rigid link of Example 1.4(d), here of a prescribed length):
$x^2 + h^2 = l^2$ with $\dot l = -u$ and $\ddot l = 0$. Nothing is left free: the winch
prescribes the motion, and differentiating the constraint in time gives it.

1. **Speed.** $x\dot x = l\dot l$, so $|\dot x| = u\,l/x = u\sqrt{x^2+h^2}/x$. Now
   $l$ = {{ si.l0 }} m, so with $u$ = {{ u }} and $x$ = {{ x }}: $v$ = {{ answers.v }}.
   The boat is faster than the rope: $u$ is only the component of the boat's velocity
   along the rope, $u = |\dot x|\,x/l$.
2. **Acceleration.** Differentiating once more, $x\ddot x + \dot x^2 = \dot l^2 = u^2$, so
   $|\ddot x| = (\dot x^2 - u^2)/x = u^2h^2/x^3$ = {{ answers.a }}, toward the wall: the
   boat speeds up although the rope runs at a constant rate.
3. **Time.** At $x/2$ the rope is $\sqrt{x^2/4+h^2}$ = {{ si.l1 }} m long, and it
   shortens at the rate $u$: $t = (l - \sqrt{x^2/4+h^2})/u$ = {{ answers.t_half }}.
4. **Check.** With the winch at the water line ($h \to 0$) the rope would be horizontal and
   the boat would move exactly as the rope does, at {{ checks.winch_at_water_level }} m/s.
""",
    solve=solve,
    checks=(
        # the constraint solved for x(t) and integrated until the bow reaches x/2
        Integrated("t_half", _bow, lambda p: (p.x,), lambda p, s: 3 * s["t_half"],
                   lambda t, y, p: t, name="integrated_haul",
                   event=lambda t, y, p: y[0] - p.x / 2, direction=-1),
        # the constraint differentiated twice: x x'' + x'^2 = u^2
        Recompute("a", lambda p, s: (s["v"]**2 - p.u**2) / p.x, name="second_derivative"),
        # a horizontal rope moves the boat at the rope's own speed
        Limit("v", {"h": 0.0}, lambda p: p.u, name="winch_at_water_level"),
    ),
    figure=figure,
    figure_to_scale=True,
    parts=(
        Numeric("v", "speed of the boat", question=1, unit="m/s", points=2,
                misconceptions=(
                    Misconception("boat as fast as the rope", lambda p: p.u,
                                  "The rope shortens at u, but the boat moves horizontally: "
                                  "differentiate the constraint x² + h² = l², x ẋ = l l̇."),
                    Misconception("rope speed projected on the water",
                                  lambda p: p.u * p.x / np.hypot(p.x, p.h),
                                  "It is the boat's velocity whose component along the rope is "
                                  "u, not the other way round: |ẋ| = u l/x."),
                )),
        Numeric("a", "magnitude of the acceleration", question=2, unit="m/s^2", points=2,
                misconceptions=(
                    Misconception("product rule slip", lambda p: p.u**2 / p.x,
                                  "Differentiating x ẋ = l l̇ gives x ẍ + ẋ² = l̇²: the term ẋ² "
                                  "is missing.",
                                  applies=lambda p: abs((p.h / p.x)**2 - 1) > 0.05),
                )),
        Numeric("t_half", "time to reach x/2", question=3, unit="s", points=1,
                misconceptions=(
                    Misconception("the boat's speed taken as constant",
                                  lambda p: p.x / 2 / solve(p)["v"],
                                  "The boat speeds up as it nears the wall; the rope's length, "
                                  "not the boat's speed, changes at a constant rate."),
                    Misconception("the rope shortens by x/2", lambda p: p.x / 2 / p.u,
                                  "The rope shortens by l(x) − l(x/2), less than the boat's "
                                  "horizontal travel x/2."),
                )),
    ),
)
