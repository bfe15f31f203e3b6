"""A rocket launched vertically: burn-out speed and height with and without gravity
(Section 2.3.2)."""

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric,
                                Symbolic, Uniform)
from dynagrade.mechanics import variable_mass


def _rate(p):
    return p.mf / p.tb


def solve(p):
    q = _rate(p)
    return {
        "F": variable_mass.thrust(p.u, q),
        "dv_free": variable_mass.rocket_speed_gain(p.u, p.m0, p.m0 - p.mf),
        "v_b": variable_mass.vertical_rocket_speed(p.tb, 0.0, p.u, p.m0, q, p.g),
        "h_b": variable_mass.vertical_rocket_height(p.tb, 0.0, p.u, p.m0, q, p.g),
    }


EXERCISE = Exercise(
    id="rocket-burnout-speed",
    title="Rocket burn-out speed",
    source="Section 2.3.2",
    topics=("variable mass", "rocket equation", "thrust"),
    params=(
        Uniform("m0", 500, 5000, step=100, unit="kg", symbol="m_0"),
        Uniform("mf", 300, 4000, step=50, unit="kg", symbol="m_f"),
        Uniform("u", 1500, 3500, step=100, unit="m/s", symbol="u"),
        Uniform("tb", 20, 120, step=5, unit="s", symbol="t_b"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("the fuel is 40 % to 85 % of the launch mass",
                   lambda p: 0.4 * p.m0 <= p.mf <= 0.85 * p.m0),
        Constraint("the thrust lifts the rocket off (F > 1.3 m0 g)",
                   lambda p: p.u * p.mf / p.tb > 1.3 * p.m0 * p.g),
    ),
    statement=r"""
A rocket of launch mass $m_0$ = {{ m0 }}, of which $m_f$ = {{ mf }} is fuel, is launched
vertically from rest. The fuel burns at a constant rate in $t_b$ = {{ tb }} and leaves
the nozzle with $u$ = {{ u }} relative to the rocket. Take $g$ = {{ g }} as constant and
neglect air drag.

1. What is the thrust?
2. Which speed would the burn give the rocket far from any gravity?
3. What is the rocket's speed at burn-out in the launch above?
4. At which height does the burn end?
5. Give the burn-out speed of question 3 as a formula in $m_0$, $m_f$, $u$, $t_b$ and $g$.
""",
    solve=solve,
    parts=(
        Numeric("F", "thrust", unit="kN", points=1),
        Numeric("dv_free", "speed gain without gravity", unit="m/s", points=1,
                misconceptions=(
                    Misconception("constant mass", lambda p: p.u * p.mf / p.tb * p.tb / p.m0,
                                  "The rocket gets lighter as it burns: integrate "
                                  "m dv = u dm to u ln(m0/m)."),
                )),
        Numeric("v_b", "burn-out speed", unit="m/s", points=2,
                misconceptions=(
                    Misconception("gravity ignored",
                                  lambda p: variable_mass.rocket_speed_gain(p.u, p.m0, p.m0 - p.mf),
                                  "Gravity takes g t_b off the speed during the burn."),
                )),
        Numeric("h_b", "burn-out height", unit="km", points=1,
                misconceptions=(
                    Misconception("constant acceleration assumed",
                                  lambda p: 0.5 * solve(p)["v_b"] * p.tb,
                                  "The acceleration grows as the rocket gets lighter; "
                                  "integrate v(t)."),
                )),
        Symbolic("v_b_formula", "burn-out speed as a formula", points=1,
                 expected="u*ln(m0/(m0-mf)) - g*tb",
                 variables=("m0", "mf", "u", "tb", "g"),
                 equals="v_b",
                 misconceptions=(
                     Misconception("gravity ignored", "u*ln(m0/(m0-mf))",
                                   "Gravity takes g t_b off the speed during the burn."),
                 )),
    ),
)
