"""A particle sliding to rest on a rough floor: stopping distance by the work-energy
balance (Example 1.11, eq. 1.91)."""

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric, Symbolic,
                                Uniform, apart)
from dynagrade.exercise.checks import Balance, Integrated, Limit
from dynagrade.mechanics import energy, particle


def solve(p):
    dx = energy.sliding_stopping_distance(p.v0, p.mu, p.g)
    return {"dx": dx, "t_stop": particle.sliding_stop_time(p.v0, p.mu, p.g),
            "W": energy.friction_work_on_floor(p.mu, p.m, p.g, dx)}


def _sliding(t, y, p):
    """Coulomb friction on level ground while sliding, eq. (1.103): x'' = -mu g."""
    return (y[1], -p.mu * p.g)


def _pushed_off(p):
    return (0.0, p.v0)


def _longer_than_the_slide(p, solved):
    """The slide lasts v0 / (mu g)."""
    return 2 * p.v0 / (p.mu * p.g)


def _speed(t, y, p):
    """The speed, zero when the block stops."""
    return y[1]


EXERCISE = Exercise(
    id="frictional-sliding-stop",
    title="Frictional sliding to rest",
    source="Example 1.11",
    topics=("work-energy balance", "Coulomb friction"),
    params=(
        Uniform("m", 0.5, 20.0, step=0.5, unit="kg", symbol="m"),
        Uniform("v0", 1.0, 15.0, step=0.5, unit="m/s", symbol="v_0"),
        Uniform("mu", 0.1, 0.8, step=0.05, symbol=r"\mu"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        # decelerating uniformly to rest, dx = v0 t_stop / 2: at v0 = 2 m/s the distance
        # in m and the time in s are one number, and swapping the formulas scores both
        Constraint("the distance and the time differ as numbers (v0 not 2 m/s)",
                   lambda p: apart(p.v0 / 2, 1.0)),
    ),
    statement="""
A crate of mass $m$ = {{ m }} slides over a level floor with initial speed $v_0$ = {{ v0 }}.
The coefficient of kinetic friction is $\\mu$ = {{ mu }}; $g$ = {{ g }}.

1. How far does it slide before it stops?
2. How long does it slide?
3. What is the work $W$ that friction does on the crate over that distance, with its sign?
4. Write the stopping distance as a formula in $v_0$, $\\mu$ and $g$.
""",
    solution=r"""
While the crate slides, gravity and the normal force do no work (they are perpendicular to
the motion) and friction $R = \mu N = \mu m g$ opposes it. Use the work–energy balance
$T_2 - T_1 = W_{12}$, eq. (1.87), between the start ($T_1 = \tfrac{1}{2} m v_0^2$) and the stop
($T_2 = 0$), eq. (1.88) (Example 1.11).

1. **Stopping distance.** The work of friction over $\Delta x$ is $W_{12} = -\mu m g\,\Delta x$,
   so $0 - \tfrac{1}{2} m v_0^2 = -\mu m g\,\Delta x$ and, eq. (1.91),
   $\Delta x = \frac{v_0^2}{2\mu g}$.
   With $v_0$ = {{ v0 }}, $\mu$ = {{ mu }} and $g$ = {{ g }}: $\Delta x$ = {{ answers.dx }}.
   The mass drops out.
2. **Sliding time.** Linear momentum balance along the floor gives the constant deceleration
   $\mu g$, so the speed $v_0 - \mu g t$ vanishes at $t = v_0/(\mu g)$ = {{ answers.t_stop }}.
3. **Work of friction.** $W = -\mu m g\,\Delta x$ with $m$ = {{ m }}: $W$ = {{ answers.W }} —
   negative, and in size exactly the kinetic energy $\tfrac{1}{2} m v_0^2$ the crate had.
4. **Formula.** $\Delta x$ = `{{ answers.dx_formula }}`.
""",
    solve=solve,
    checks=(
        Integrated("dx", _sliding, _pushed_off, _longer_than_the_slide,
                   lambda t, y, p: y[0], name="integrated_slide",
                   event=_speed, direction=-1),
        Integrated("t_stop", _sliding, _pushed_off, _longer_than_the_slide,
                   lambda t, y, p: t, name="integrated_stop_time",
                   event=_speed, direction=-1),
        # work-energy balance, eq. (1.87): the kinetic energy is spent against friction
        Balance("energy", lambda p, s: p.m * p.v0**2 / 2, lambda p, s: abs(s["W"]),
                name="work_energy"),
    ),
    parts=(
        Numeric("dx", "stopping distance", question=1, unit="m", points=2,
                misconceptions=(
                    Misconception("factor 1/2 of the kinetic energy forgotten",
                                  lambda p: p.v0**2 / (p.mu * p.g),
                                  "T = m v0²/2: Δx = v0²/(2 µ g), eq. (1.91)."),
                    Misconception("friction without g", lambda p: p.v0**2 / (2 * p.mu),
                                  "The friction force is µ N = µ m g."),
                )),
        Numeric("t_stop", "sliding time", question=2, unit="s", points=1),
        Numeric("W", "work of friction", question=3, unit="J", points=1,
                misconceptions=(
                    Misconception("sign: friction work positive",
                                  lambda p: 0.5 * p.m * p.v0**2,
                                  "Friction opposes the motion, so its work is negative: "
                                  "W = −µ m g Δx = −m v0²/2."),
                )),
        Symbolic("dx_formula", "stopping distance as a formula", question=4, points=1,
                 expected="v0^2/(2*mu*g)",
                 variables=("v0", "mu", "g"),
                 equals="dx",
                 misconceptions=(
                     Misconception("factor 1/2 forgotten", "v0^2/(mu*g)",
                                   "The kinetic energy is m v0²/2."),
                 )),
    ),
)
