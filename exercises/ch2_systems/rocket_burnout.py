"""A rocket launched vertically: burn-out speed and height with and without gravity
(Section 2.3.2)."""

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric,
                                Symbolic, Uniform)
from dynagrade.exercise.checks import Integrated, Recompute
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
        "q": q,
        "m_b": variable_mass.mass_at_time(p.tb, p.m0, -q),
    }


def _ascent(t, y, p):
    """Vertical flight with thrust u q against gravity, the mass falling as m0 - q t
    (variable-mass momentum balance): v' = u q / (m0 - q t) - g."""
    q = p.mf / p.tb
    return (y[1], p.u * q / (p.m0 - q * t) - p.g)


def _on_the_pad(p):
    return (0.0, 0.0)


def _until_burnout(p, solved):
    return p.tb


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
    solution=r"""
Linear momentum balance for a body of variable mass (Section 2.3.2): the fuel leaves at
$u$ relative to the rocket, at the constant rate $q = m_f/t_b$ = {{ si.q }} kg/s (with
$m_f$ = {{ mf }}, $t_b$ = {{ tb }}). Over $\mathrm dt$ the rocket gains the momentum that
the exhaust carries backwards, so
$m(t)\,\dot v = q u - m(t)\,g, \qquad m(t) = m_0 - qt$.

1. **Thrust.** The term $qu$ acts like a force: $F = qu$; with $u$ = {{ u }}:
   $F$ = {{ answers.F }}.
2. **Without gravity.** $m\,\dot v = qu$ with $\mathrm dm = -q\,\mathrm dt$ gives
   $\mathrm dv = -u\,\mathrm dm/m$, and integrating from $m_0$ to the burn-out mass
   $m_0 - m_f$ = {{ si.m_b }} kg (with $m_0$ = {{ m0 }}) gives the rocket equation
   $\Delta v = u\ln\frac{m_0}{m_0 - m_f}$
   = {{ answers.dv_free }}. The burn time does not matter.
3. **Burn-out speed with gravity.** Gravity adds $-g$ to the acceleration throughout
   the burn, so it costs $g\,t_b$: $v_b = u\ln\frac{m_0}{m_0 - m_f} - g\,t_b$; with $g$ = {{ g }}: $v_b$ = {{ answers.v_b }}.
4. **Burn-out height.** Integrate $v(t) = u\ln\frac{m_0}{m(t)} - gt$ over the burn:
   $h_b = u\left[t_b - \frac{m_0 - m_f}{q}\ln\frac{m_0}{m_0 - m_f}\right] - \tfrac{1}{2} g t_b^2$
   = {{ answers.h_b }}.
5. **Formula.** $v_b$ = `{{ answers.v_b_formula }}`.
""",
    solve=solve,
    checks=(
        Integrated("v_b", _ascent, _on_the_pad, _until_burnout, lambda t, y, p: y[1],
                   name="integrated_speed"),
        Integrated("h_b", _ascent, _on_the_pad, _until_burnout, lambda t, y, p: y[0],
                   name="integrated_height"),
        Recompute("F", lambda p, s: p.u * p.mf / p.tb, name="thrust"),
    ),
    parts=(
        Numeric("F", "thrust", question=1, unit="kN", points=1),
        Numeric("dv_free", "speed gain without gravity", question=2, unit="m/s", points=1,
                misconceptions=(
                    Misconception("constant mass", lambda p: p.u * p.mf / p.tb * p.tb / p.m0,
                                  "The rocket gets lighter as it burns: integrate "
                                  "m dv = u dm to u ln(m0/m)."),
                )),
        Numeric("v_b", "burn-out speed", question=3, unit="m/s", points=2,
                misconceptions=(
                    Misconception("gravity ignored",
                                  lambda p: variable_mass.rocket_speed_gain(p.u, p.m0, p.m0 - p.mf),
                                  "Gravity takes g t_b off the speed during the burn."),
                )),
        Numeric("h_b", "burn-out height", question=4, unit="km", points=1,
                misconceptions=(
                    Misconception("constant acceleration assumed",
                                  lambda p: 0.5 * solve(p)["v_b"] * p.tb,
                                  "The acceleration grows as the rocket gets lighter; "
                                  "integrate v(t)."),
                )),
        Symbolic("v_b_formula", "burn-out speed as a formula", question=5, points=1,
                 expected="u*ln(m0/(m0-mf)) - g*tb",
                 variables=("m0", "mf", "u", "tb", "g"),
                 equals="v_b",
                 misconceptions=(
                     Misconception("gravity ignored", "u*ln(m0/(m0-mf))",
                                   "Gravity takes g t_b off the speed during the burn."),
                 )),
    ),
)
