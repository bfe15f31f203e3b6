"""A coasting cart collecting load that falls in vertically (Section 2.3.2)."""

from dynagrade.exercise import (Constraint, Exercise, Misconception, Numeric, Symbolic,
                                Uniform)
from dynagrade.exercise.checks import Balance, Recompute
from dynagrade.mechanics import variable_mass


def solve(p):
    mass = variable_mass.mass_at_time(p.t, p.m0, p.q)
    return {
        "v_t": variable_mass.speed_after_accretion(p.m0, p.v0, mass),
        "F_keep": variable_mass.force_to_keep_speed_while_accreting(p.q, p.v0),
        "mass": mass,
    }


EXERCISE = Exercise(
    id="cart-collecting-load",
    title="A cart collecting falling gravel",
    source="Section 2.3.2",
    topics=("mass accretion", "momentum conservation", "variable mass"),
    params=(
        Uniform("m0", 200, 2000, step=50, unit="kg", symbol="m_0"),
        Uniform("v0", 0.5, 4.0, step=0.1, unit="m/s", symbol="v_0"),
        Uniform("q", 5, 100, step=5, unit="kg/s", symbol="q"),
        Uniform("t", 5, 60, step=1, unit="s", symbol="t"),
    ),
    constraints=(
        Constraint("the load gained is a clear fraction of the cart's mass",
                   lambda p: p.q * p.t > 0.1 * p.m0),
    ),
    statement=r"""
An open rail cart of mass $m_0$ = {{ m0 }} coasts with $v_0$ = {{ v0 }} under a hopper that
drops gravel vertically into it at the rate $q$ = {{ q }}. Rolling resistance is negligible.

1. What is the speed of the cart after it has been loading for $t$ = {{ t }}?
2. Which horizontal force would keep the cart at the speed $v_0$ while it is being loaded?
3. Give the speed of question 1 as a formula in $m_0$, $v_0$, $q$ and $t$.
""",
    solution=r"""
Take the cart together with the gravel it has collected as the system. The gravel falls in
vertically, so it brings no horizontal momentum, and no horizontal external force acts
(rolling resistance is negligible): the horizontal linear momentum of the system is
conserved (Section 2.3.2). After loading for $t$ the mass is
$m(t) = m_0 + qt$ = {{ si.mass }} kg (with $m_0$ = {{ m0 }}, $q$ = {{ q }}, $t$ = {{ t }}).

1. **Speed.** $m_0 v_0 = (m_0 + qt)\,v$, so
   $v(t) = \frac{m_0 v_0}{m_0 + qt}$;
   with $v_0$ = {{ v0 }}: $v$ = {{ answers.v_t }}. Every kilogram of gravel has to be brought
   up to the cart's speed, and the cart pays for it with its own momentum.
2. **Force to keep $v_0$.** Linear momentum balance of the system, $\dot P = F$. At constant
   speed $P = m(t)\,v_0$ grows at the rate $\dot m\,v_0 = q v_0$, so the force must be
   $F = q v_0$ = {{ answers.F_keep }}: the momentum flux needed to accelerate the arriving
   gravel from rest to $v_0$.
3. **Formula.** $v(t)$ = `{{ answers.v_t_formula }}`.
""",
    solve=solve,
    checks=(
        # no horizontal force: the momentum of cart and collected load is conserved
        Balance("momentum", lambda p, s: p.m0 * p.v0, lambda p, s: (p.m0 + p.q * p.t) * s["v_t"],
                name="momentum_balance"),
        # to keep v0 the collected mass must be brought to v0: F = q v0
        Recompute("F_keep", lambda p, s: p.q * p.v0, name="momentum_flux"),
    ),
    parts=(
        Numeric("v_t", "speed after loading for t", question=1, unit="m/s", points=2,
                misconceptions=(
                    Misconception("speed unchanged", lambda p: p.v0,
                                  "The gravel arrives without horizontal momentum: the cart's "
                                  "momentum is shared with it."),
                    Misconception("kinetic energy conserved",
                                  lambda p: p.v0 * (p.m0 / (p.m0 + p.q * p.t)) ** 0.5,
                                  "Catching the gravel is a plastic impact: momentum, not "
                                  "kinetic energy, is conserved."),
                )),
        Numeric("F_keep", "force to keep the speed", question=2, unit="N", points=1,
                misconceptions=(
                    Misconception("half the momentum flux", lambda p: 0.5 * p.q * p.v0,
                                  "The force supplies the momentum q v0 per second given to "
                                  "the gravel."),
                )),
        Symbolic("v_t_formula", "speed as a formula", question=3,
                 points=1, expected="m0*v0/(m0+q*t)",
                 variables=("m0", "v0", "q", "t"),
                 equals="v_t",
                 misconceptions=(
                     Misconception("kinetic energy conserved", "v0*sqrt(m0/(m0+q*t))",
                                   "Momentum, not kinetic energy, is conserved."),
                 )),
    ),
)
