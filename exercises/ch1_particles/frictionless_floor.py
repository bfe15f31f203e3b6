"""A block pulled across a frictionless floor by an inclined rope: normal force and
motion along the floor (Example 1.7, component-wise balance 1.69)."""

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric, Symbolic,
                                Uniform)
from dynagrade.exercise.checks import Limit, Recompute
from dynagrade.mechanics import kinematics, particle


def _forces(p):
    pull = np.array([p.F * np.cos(p.theta), p.F * np.sin(p.theta)])
    return pull, particle.weight(p.m, (0.0, -p.g))


def solve(p):
    pull, weight = _forces(p)
    N = particle.floor_normal_force_under_pull(p.m, p.g, p.F, p.theta)   # x2'' = 0
    a = particle.acceleration(p.m, pull, weight, (0.0, N))
    return {"N": N, "a": float(a[0]), "v_t": kinematics.speed_at_constant_acceleration(p.t, p.v0, float(a[0])),
            "N_free": particle.floor_normal_force(p.m, p.g)}


EXERCISE = Exercise(
    id="block-on-frictionless-floor",
    title="Block on a frictionless floor pulled by a rope",
    source="Example 1.7",
    topics=("linear momentum balance", "normal force", "constrained motion"),
    params=(
        Uniform("m", 2.0, 20.0, step=0.5, unit="kg", symbol="m"),
        Uniform("F", 5.0, 60.0, step=1.0, unit="N", symbol="F"),
        Uniform("theta", 10, 50, step=1, unit="deg", symbol=r"\theta"),
        Uniform("v0", 0.0, 3.0, step=0.1, unit="m/s", symbol="v_0"),
        Uniform("t", 1.0, 5.0, step=0.5, unit="s", symbol="t"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("the rope does not lift the block: F sin(theta) < 0.8 m g",
                   lambda p: p.F * np.sin(p.theta) < 0.8 * p.m * p.g),
        Constraint("the rope's vertical pull changes N by at least 5 %",
                   lambda p: p.F * np.sin(p.theta) > 0.05 * p.m * p.g),
        Constraint("cos(theta) matters for the acceleration", lambda p: np.cos(p.theta) < 0.97),
    ),
    statement="""
A block of mass $m$ = {{ m }} slides on a frictionless horizontal floor. At $t = 0$ it
moves with $v_0$ = {{ v0 }} along $\\boldsymbol e_1$, and from then on a rope pulls it with
the constant force $F$ = {{ F }} at the angle $\\theta$ = {{ theta }} above the horizontal
(in the direction of motion). $g$ = {{ g }}.

1. What is the normal force of the floor on the block?
2. What is the block's acceleration along the floor?
3. What is its speed at $t$ = {{ t }}?
4. What would the normal force be without the rope?
5. Write the normal force with the rope as a formula in $m$, $g$, $F$ and $\\theta$ (`theta`).
""",
    solution=r"""
Take $e_1$ along the floor and $e_2$ up. On the block act the weight $-mg\,e_2$, the normal
force $N e_2$ and the pull $F(\cos\theta\, e_1 + \sin\theta\, e_2)$; there is no friction.
The floor keeps the block at constant height, so $\ddot x_2 = 0$. Linear momentum balance
$\sum F_i = m a$, eq. (1.63), component by component (Example 1.7):

1. **Normal force.** $e_2$: $N + F\sin\theta - mg = 0$, so $N = mg - F\sin\theta$. With
   $m$ = {{ m }}, $F$ = {{ F }}, $\theta$ = {{ theta }}: $N$ = {{ answers.N }}. The rope
   carries part of the weight.
2. **Acceleration.** $e_1$: $m\ddot x_1 = F\cos\theta$, so $\ddot x_1 = F\cos\theta/m$
   = {{ answers.a }} — constant.
3. **Speed.** Constant acceleration: $v(t) = v_0 + \ddot x_1 t$; with $v_0$ = {{ v0 }} and
   $t$ = {{ t }}: $v$ = {{ answers.v_t }}.
4. **Without the rope.** $N = mg$ (eq. (1.70)) = {{ answers.N_free }}.
5. **Formula.** $N$ = `{{ answers.N_formula }}`.
""",
    solve=solve,
    checks=(
        # eq. (1.68) with the pull's vertical part: N = m g - F sin(theta)
        Recompute("N", lambda p, s: p.m * p.g - p.F * np.sin(p.theta), name="vertical_balance"),
        Recompute("v_t", lambda p, s: p.v0 + p.F * np.cos(p.theta) / p.m * p.t,
                  name="horizontal_balance"),
        # no pull: Example 1.7's N = m g and uniform motion
        Limit("N", {"F": 0.0}, lambda p: p.m * p.g, name="no_pull"),
    ),
    parts=(
        Numeric("N", "normal force", question=1, unit="N", points=2,
                misconceptions=(
                    Misconception("normal force equals the weight", lambda p: p.m * p.g,
                                  "The rope also pulls upward: N = m g − F sin θ from the "
                                  "balance in e2 (eq. 1.69)."),
                    Misconception("rope pushes down", lambda p: p.m * p.g + p.F * np.sin(p.theta),
                                  "The rope pulls upward, which relieves the floor."),
                )),
        Numeric("a", "acceleration", question=2, unit="m/s^2", points=1,
                misconceptions=(
                    Misconception("whole rope force along the floor", lambda p: p.F / p.m,
                                  "Only the component F cos θ acts along e1."),
                )),
        Numeric("v_t", "speed at t", question=3, unit="m/s", points=1),
        Numeric("N_free", "normal force without the rope", question=4, unit="N", points=1),
        Symbolic("N_formula", "normal force as a formula", question=5, points=1,
                 expected="m*g - F*sin(theta)",
                 variables=("m", "g", "F", "theta"),
                 equals="N",
                 misconceptions=(
                     Misconception("cos for sin", "m*g - F*cos(theta)",
                                   "The vertical component of the rope force is F sin θ."),
                 )),
    ),
)
