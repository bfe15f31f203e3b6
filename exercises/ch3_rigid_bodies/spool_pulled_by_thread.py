"""A spool pulled by the thread leaving the top of its hub: acceleration, the ground's
friction and its direction, the smallest friction coefficient (Section 3.2.1)."""

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric,
                                Options, Uniform, per_draw)
from dynagrade.exercise.apart import numbers_apart
from dynagrade.exercise.checks import Balance, Recompute
from dynagrade.exercise.figure import Circle, arrow, describe, dimension, ground, new_drawing
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import rigid_kinetics


def _moment(p):
    return p.m * p.k**2  # I_C from the radius of gyration


def _pull(p, lever_arm):
    """Acceleration and friction (along the pull) with the thread at this lever arm."""
    args = (p.F, p.m, p.R, _moment(p), lever_arm)
    return (rigid_kinetics.rolling_acceleration_under_horizontal_pull(*args),
            rigid_kinetics.friction_under_horizontal_pull(*args))


@per_draw
def solve(p):
    a, f = _pull(p, p.r)
    return {
        "a": a,
        "f": abs(f),
        "direction": "forward" if f > 0 else "backward",
        "mu_min": abs(f) / (p.m * p.g),
        "f_signed": f,
    }


def _forward(p):
    return solve(p)["f_signed"] > 0


def _apart(p):
    """a, f and mu_min, whose units differ, never share their number (5 % apart)."""
    s = solve(p)
    return numbers_apart((s["a"], s["f"], s["mu_min"]))


def figure(p):
    """The spool to scale on the floor, the thread leaving the top of its hub."""
    drawing, axes = new_drawing(4.6, 2.6)
    R, r = p.R, p.r
    ground(axes, -2.3 * R, 3.0 * R, 0.0, hatch=0.08 * R)
    axes.add_patch(Circle((0.0, R), R, facecolor="#d9c39a", edgecolor="0.1", lw=1.2))
    axes.add_patch(Circle((0.0, R), r, facecolor="#a0724a", edgecolor="0.1", lw=1.0))
    axes.plot([0.0], [R], "o", color="0.1", ms=4)
    axes.text(-0.06 * R, R - 0.05 * R, "C", ha="right", va="top", fontsize=10)
    axes.plot([0.0, 2.2 * R], [R + r, R + r], color="0.1", lw=1.0)
    arrow(axes, (2.2 * R, R + r), (2.9 * R, R + r), color="C3")
    axes.text(2.55 * R, R + r + 0.08 * R, f"F = {format_number(p.F)} N", color="C3",
              ha="center", va="bottom", fontsize=10)
    # r left of the spool, R right of it, their labels outside: inside, they crossed the
    # rims; thin dashed lines carry C's height and the hub's top out to the dimensions
    axes.plot([-1.35 * R, 0.0], [R + r, R + r], color="0.5", lw=0.5, ls="--")
    axes.plot([-1.35 * R, 1.3 * R], [R, R], color="0.5", lw=0.5, ls="--")
    dimension(axes, (-1.25 * R, R), (-1.25 * R, R + r), f"r = {format_number(r)} m",
              tick=0.04 * R, side=1.0)
    dimension(axes, (1.2 * R, 0.0), (1.2 * R, R), f"R = {format_number(R)} m",
              tick=0.04 * R, side=-1.0)
    describe(axes, "The thread leaves the top of the hub horizontally and is pulled to the "
                   "right; the spool's rim rests on the floor.")
    axes.set_xlim(-2.4 * R, 3.1 * R)
    axes.set_ylim(-0.15 * R, 2.3 * R)
    return drawing


def _balances(p, s):
    """Both balances solved by hand for f (along the pull): m a = F + f and
    m k^2 a / R = F r - f R give f = F (r R - k^2) / (R^2 + k^2)."""
    return p.F * (p.r * p.R - p.k**2) / (p.R**2 + p.k**2)


EXERCISE = Exercise(
    id="spool-pulled-by-thread",
    title="A spool pulled by its thread: which way does friction act?",
    source="Section 3.2.1",
    topics=("balance of linear momentum", "balance of angular momentum",
            "rolling without slipping", "static friction"),
    params=(
        Uniform("m", 0.5, 5.0, step=0.1, unit="kg", symbol="m"),
        Uniform("R", 0.1, 0.3, step=0.01, unit="m", symbol="R"),
        Uniform("r", 0.03, 0.24, step=0.01, unit="m", symbol="r"),
        Uniform("k", 0.05, 0.25, step=0.01, unit="m", symbol="k"),
        Uniform("F", 1.0, 12.0, step=0.5, unit="N", symbol="F"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("the hub is a clear step inside the rim (0.3 R <= r <= 0.8 R)",
                   lambda p: 0.3 * p.R <= p.r <= 0.8 * p.R),
        Constraint("a spool's radius of gyration (0.5 R <= k <= 0.85 R)",
                   lambda p: 0.5 * p.R <= p.k <= 0.85 * p.R),
        Constraint("the friction is clearly not zero (|r R - k^2| > 0.08 R^2)",
                   lambda p: abs(p.r * p.R - p.k**2) > 0.08 * p.R**2),
        Constraint("a pull by hand: the spool speeds up at most at 6 m/s^2 (the draws reached "
                   "6 g)", lambda p: solve(p)["a"] <= 6.0),
        Constraint("a floor can supply the friction (mu_min < 0.6)",
                   lambda p: solve(p)["mu_min"] < 0.6),
        Constraint("the three numbers asked for are 5 % apart", _apart),
    ),
    statement=r"""
A spool (mass $m$ = {{ m }}, radius of gyration $k$ = {{ k }} about its axis) rests with
its rims of radius $R$ = {{ R }} on a level floor. A thread wound on its hub of radius
$r$ = {{ r }} leaves the top of the hub horizontally and is pulled with the constant
force $F$ = {{ F }}. The spool rolls without slipping ($g$ = {{ g }}).

1. What is the acceleration of the spool's centre?
2. How large is the friction force of the floor on the spool?
3. Does it point forward (in the direction of the pull) or backward?
4. What is the smallest static friction coefficient that lets the spool roll?
""",
    solution=r"""
Balance of linear momentum of the spool (Section 3.2.1) along the floor, with the
friction $f$ counted positive in the direction of the pull, and balance of angular
momentum about the centre C (Section 3.2.2), clockwise positive; rolling ties the
angular acceleration to $a = R\,\dot\omega$, and $I_C = m k^2$:
$$m a = F + f, \qquad m k^2\,\frac{a}{R} = F r - f R .$$

1. **Acceleration.** Eliminating $f$,
   $$a = \frac{F\,(1 + r/R)}{m\,(1 + k^2/R^2)} ,$$
   with $m$ = {{ m }}, $k$ = {{ k }}, $R$ = {{ R }}, $r$ = {{ r }} and $F$ = {{ F }}:
   $a$ = {{ answers.a }}.
2. **Friction.** $f = m a - F = F\,\dfrac{r R - k^2}{R^2 + k^2}$, here
   {{ si.f_signed }} N, so its magnitude is {{ answers.f }}.
3. **Direction.** $f$ has the sign of $r R - k^2$: {{ answers.direction }}. The thread's
   moment about C alone would spin the spool faster ($r R > k^2$) or slower than rolling
   needs, and friction makes up the difference.
4. **Smallest coefficient.** The floor carries the weight, $N = m g$, and rolling needs
   $|f| \le \mu N$: $\mu_{\min} = |f|/(m g)$ = {{ answers.mu_min }}.

**Check.** By power instead: the thread's end at the top of the hub moves at $v(1 + r/R)$,
and friction at the resting contact does no work, so $F(1 + r/R) = m(1 + k^2/R^2)\,a$:
{{ checks.power_of_the_pull }} N on each side.
""",
    solve=solve,
    figure=figure,
    figure_to_scale=True,
    checks=(
        Recompute("f_signed", _balances, name="balances_solved_for_f"),
        # the power balance: F acts at the hub's top, whose speed is v (1 + r/R); friction
        # at the resting contact does no work, so F v (1 + r/R) = d/dt (m v^2/2 + m k^2 w^2/2)
        Balance("power", lambda p, s: p.F * (1 + p.r / p.R),
                lambda p, s: (p.m + p.m * p.k**2 / p.R**2) * s["a"], name="power_of_the_pull"),
    ),
    parts=(
        Numeric("a", "acceleration of the centre", question=1, unit="m/s^2", points=2,
                misconceptions=(
                    Misconception("rotation forgotten", lambda p: p.F / p.m,
                                  "The spool also spins up: m a = F + f and m k² a/R = F r − f R."),
                    Misconception("thread taken below the centre", lambda p: _pull(p, -p.r)[0],
                                  "The thread leaves the top of the hub: its moment about C "
                                  "adds F r, so a ∝ 1 + r/R."),
                )),
        Numeric("f", "magnitude of the friction force", question=2, unit="N", points=2,
                misconceptions=(
                    Misconception("thread taken below the centre",
                                  lambda p: abs(_pull(p, -p.r)[1]),
                                  "With the thread on top, f = F (r R − k²)/(R² + k²)."),
                )),
        Options("direction", "direction of the friction force", question=3,
                options=("forward", "backward"), points=1,
                misconceptions=(
                    Misconception("friction always opposes the motion", lambda p: "backward",
                                  "Static friction opposes the slip the other forces would "
                                  "cause: here the thread spins the spool too fast.",
                                  applies=_forward),
                )),
        Numeric("mu_min", "smallest static friction coefficient", question=4, points=1,
                misconceptions=(
                    Misconception("friction taken as the pull", lambda p: p.F / (p.m * p.g),
                                  "μ_min = |f|/(m g) with the friction f of question 2."),
                )),
    ),
)
