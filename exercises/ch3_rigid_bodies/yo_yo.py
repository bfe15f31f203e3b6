"""A yo-yo unwinding from its string: work-energy balance with rotation (Section 3.2.5)."""

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric, Symbolic,
                                Uniform)
from dynagrade.exercise.checks import Balance, Recompute
from dynagrade.mechanics import inertia, rigid_kinetics
from dynagrade.mechanics import rigid_kinematics as rk


def _moment(p):
    return inertia.inertia_tensor_disk(p.m, p.R)[2, 2]


def solve(p):
    v = rigid_kinetics.rolling_speed_after_drop(p.h, p.g, p.m, p.r, _moment(p))
    return {
        "v": v,
        "omega": rk.rolling_angular_velocity(v, p.r),
        # the string pulls like the friction on a body rolling down a vertical "incline"
        "S": rigid_kinetics.friction_for_rolling_on_incline(np.pi / 2, p.g, p.m, p.r,
                                                            _moment(p)),
    }


EXERCISE = Exercise(
    id="yo-yo-unwinding",
    title="Yo-yo unwinding from its string",
    source="Section 3.2.5",
    topics=("work-energy balance", "kinetic energy of a rigid body", "rolling constraint"),
    params=(
        Uniform("m", 0.05, 0.5, step=0.01, unit="kg", symbol="m"),
        Uniform("R", 3.0, 6.0, step=0.1, unit="cm", symbol="R"),
        Uniform("r", 0.8, 2.0, step=0.05, unit="cm", symbol="r"),
        Uniform("h", 0.2, 1.5, step=0.05, unit="m", symbol="h"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("the axle is thick enough that the string tension differs from the weight",
                   lambda p: p.r >= 0.22 * p.R),
    ),
    statement=r"""
A yo-yo is modelled as a homogeneous disk of mass $m$ = {{ m }} and radius $R$ = {{ R }};
its string is wound on a thin axle of radius $r$ = {{ r }} and the upper end of the string
is held fixed. The yo-yo is released from rest with the string vertical ($g$ = {{ g }}).

1. How fast does its centre move after it has dropped $h$ = {{ h }}?
2. What is then its angular speed?
3. What is the tension in the string while it unwinds?
4. Give the speed of question 1 as a formula in $g$, $h$, $R$ and $r$.
""",
    solution=r"""
The string does no work (its end is fixed and the yo-yo rolls on it), so the work-energy
balance holds between release and any later instant (Section 3.2.5). The string unwinds
from the axle, so the centre's speed and the spin are tied by $v = \omega r$.

1. **Speed after dropping $h$.** With $I_C = \tfrac{1}{2} m R^2$ for the disk,
   $$m g h = \tfrac{1}{2} m v^2 + \tfrac{1}{2} I_C\Bigl(\frac{v}{r}\Bigr)^2
   \quad\Rightarrow\quad v = \sqrt{\frac{2 g h}{1 + R^2/(2 r^2)} } .$$
   With $m$ = {{ m }}, $R$ = {{ R }}, $r$ = {{ r }}, $h$ = {{ h }} and $g$ = {{ g }}:
   $v$ = {{ answers.v }}. The mass drops out.
2. **Angular speed.** $\omega = v/r$ = {{ answers.omega }}.
3. **Tension.** The balances of linear momentum, $m a = m g - S$, and of angular momentum
   about the centre, $I_C\,\dot\omega = S r$ with $\dot\omega = a/r$, give
   $$S = \frac{m g}{1 + 2 r^2/R^2},$$
   so $S$ = {{ answers.S }}, less than the weight because the yo-yo accelerates
   downward.
4. **As a formula.** From step 1, $v$ = `{{ answers.v_formula }}`.
""",
    solve=solve,
    checks=(
        # energy: m g h = m v^2 / 2 + (m R^2 / 2)(v / r)^2 / 2 (Section 3.2.5)
        Balance("energy", lambda p, s: p.m * p.g * p.h,
                lambda p, s: p.m * s["v"]**2 / 2 + p.m * p.R**2 / 4 * (s["v"] / p.r) ** 2,
                name="energy_balance"),
        # m a = m g - S and (m R^2 / 2) a / r = S r
        Recompute("S", lambda p, s: p.m * p.g * (p.R**2 / 2) / (p.R**2 / 2 + p.r**2),
                  name="momentum_balances"),
    ),
    parts=(
        Numeric("v", "speed after dropping h", question=1, unit="m/s", points=2,
                misconceptions=(
                    Misconception("rotational kinetic energy forgotten",
                                  lambda p: np.sqrt(2 * p.g * p.h),
                                  "The yo-yo spins: m g h = ½ m v² + ½ I_C (v/r)²."),
                    Misconception("outer radius in the rolling condition",
                                  lambda p: rigid_kinetics.rolling_speed_after_drop(
                                      p.h, p.g, p.m, p.R, _moment(p)),
                                  "The string unwinds from the axle: v = ω r."),
                )),
        Numeric("omega", "angular speed", question=2, unit="rad/s", points=1),
        Numeric("S", "string tension", question=3, unit="N", points=1,
                misconceptions=(
                    Misconception("tension equal to the weight", lambda p: p.m * p.g,
                                  "The yo-yo accelerates downward: S < m g."),
                )),
        Symbolic("v_formula", "speed as a formula", question=4, points=1,
                 expected="sqrt(2*g*h/(1 + R^2/(2*r^2)))",
                 variables=("g", "h", "R", "r"),
                 equals="v",
                 misconceptions=(
                     Misconception("rotational kinetic energy forgotten", "sqrt(2*g*h)",
                                   "The yo-yo spins as well."),
                 )),
    ),
)
