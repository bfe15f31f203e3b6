"""Two carts colliding head-on with a coefficient of restitution (Section 2.3.1)."""

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric,
                                Symbolic, Uniform)
from dynagrade.exercise.checks import Balance, Limit, Recompute
from dynagrade.exercise.figure import arrow, block, ground, new_drawing
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import collisions


def _after(p, e):
    return collisions.velocities_after_central_impact(p.m1, p.m2, p.v1, p.v2, e)


def _cart(axes, left, width, name):
    """A cart: a body of ``width`` with two wheels, standing on the track at ``left``."""
    from dynagrade.exercise.figure import Circle

    wheel = 0.06
    for x in (left + 0.22 * width, left + 0.78 * width):
        axes.add_patch(Circle((x, wheel), wheel, facecolor="0.3", edgecolor="0.1", lw=0.8))
    block(axes, (left + width / 2, 2 * wheel + 0.14), width, 0.28, name)


def figure(p):
    """The two carts on their track just before the impact, with velocity arrows drawn to a
    common scale in the direction of motion and labelled with the speed (Section 2.3.1).
    A cart's width grows with the cube root of its mass, like that of a solid body."""
    w1, w2 = 0.5 * p.m1 ** (1 / 3), 0.5 * p.m2 ** (1 / 3)
    scale = 0.12                                   # arrow length per m/s
    gap = 1.2
    x1, x2 = 0.0, w1 + gap
    drawing, axes = new_drawing(5.0, 2.0)
    ground(axes, -0.3 - scale * 3, x2 + w2 + 0.9, hatch=0.06)
    _cart(axes, x1, w1, "1")
    _cart(axes, x2, w2, "2")
    for left, width, m, v, name in ((x1, w1, p.m1, p.v1, "₁"), (x2, w2, p.m2, p.v2, "₂")):
        centre = left + width / 2
        axes.text(centre, 0.52, f"m{name} = {format_number(m)} kg", ha="center",
                  va="bottom", fontsize=10)
        # the arrow gives the direction, its label the speed: a left arrow labelled with
        # a negative velocity would read as a double negative
        if abs(v) > 1e-12:
            arrow(axes, (centre, 0.9), (centre + scale * v, 0.9), color="C3")
            speed = f"|v{name}| = {format_number(abs(v))} m/s"
        else:
            speed = f"v{name} = 0"
        axes.text(centre, 1.0, speed, color="C3", ha="center", va="bottom", fontsize=10)
    arrow(axes, (x2 + w2 + 0.3, 0.25), (x2 + w2 + 0.75, 0.25), color="0.3")
    axes.text(x2 + w2 + 0.52, 0.32, "+", ha="center", va="bottom", fontsize=10, color="0.3")
    axes.text(x1 + w1 + gap / 2, -0.2, f"e = {format_number(p.e)}", ha="center", va="top",
              fontsize=10)
    axes.set_xlim(-0.3 - scale * 3, x2 + w2 + 0.95)
    axes.set_ylim(-0.4, 1.3)
    return drawing


def solve(p):
    after = _after(p, p.e)
    return {
        "v1_after": after.v1,
        "v2_after": after.v2,
        "dT": collisions.kinetic_energy_lost_in_impact(p.m1, p.m2, p.v1 - p.v2, p.e),
        "v_approach": p.v1 - p.v2,
        "v_c": collisions.common_velocity_after_plastic_impact(p.m1, p.m2, p.v1, p.v2),
    }


def _distinct(a, b):
    return abs(a - b) > 0.03 * max(abs(a), abs(b))


EXERCISE = Exercise(
    id="two-cart-collision",
    title="Two carts colliding head-on",
    source="Section 2.3.1",
    topics=("particle collisions", "coefficient of restitution", "momentum conservation"),
    params=(
        Uniform("m1", 0.5, 5.0, step=0.1, unit="kg", symbol="m_1"),
        Uniform("m2", 0.5, 5.0, step=0.1, unit="kg", symbol="m_2"),
        Uniform("v1", 1.0, 6.0, step=0.1, unit="m/s", symbol="v_1"),
        Uniform("v2", -3.0, 1.0, step=0.1, unit="m/s", symbol="v_2"),
        Uniform("e", 0.1, 0.8, step=0.05, symbol="e"),
    ),
    constraints=(
        Constraint("cart 1 catches up with cart 2", lambda p: p.v1 - p.v2 > 0.5),
        Constraint("the carts' speeds after the impact are not close to zero",
                   lambda p: min(abs(_after(p, p.e).v1), abs(_after(p, p.e).v2)) > 0.05),
        # the figure names the carts "1" and "2": an answer printed so would read as shown
        Constraint("no answer prints as a cart's name, 1 or 2",
                   lambda p: not {format_number(float(v)) for v in solve(p).values()}
                   & {"1", "2", "-1", "-2"}),
        Constraint("the elastic and plastic answers differ from the right one",
                   lambda p: _distinct(_after(p, p.e).v1, _after(p, 1.0).v1)
                   and _distinct(_after(p, p.e).v1, _after(p, 0.0).v1)
                   and _distinct(_after(p, p.e).v2, _after(p, 1.0).v2)),
    ),
    statement=r"""
Cart 1 ($m_1$ = {{ m1 }}) rolls along a straight track with $v_1$ = {{ v1 }} and hits
cart 2 ($m_2$ = {{ m2 }}), which moves along the same line with $v_2$ = {{ v2 }}
(velocities positive in the direction of cart 1's motion). The coefficient of
restitution is $e$ = {{ e }}. Treat the carts as particles and neglect friction.

1. What is the velocity of cart 1 just after the impact?
2. What is the velocity of cart 2 just after the impact?
3. How much kinetic energy is lost in the impact?
4. Give the energy lost as a formula in $m_1$, $m_2$, $v_1$, $v_2$ and $e$.
""",
    solution=r"""
Central impact of two particles (Section 2.3.1). During the short impact only the internal
contact force acts along the track, so the total momentum is conserved; the coefficient of
restitution relates the relative speeds after and before:
$m_1 v_1' + m_2 v_2' = m_1 v_1 + m_2 v_2, \qquad v_2' - v_1' = e\,(v_1 - v_2)$.
Here $v_1$ = {{ v1 }}, $v_2$ = {{ v2 }}, so the carts approach with $v_1 - v_2$
= {{ si.v_approach }} m/s; the centre of mass moves with
$(m_1 v_1 + m_2 v_2)/(m_1 + m_2)$ = {{ si.v_c }} m/s before and after (with $m_1$ = {{ m1 }},
$m_2$ = {{ m2 }}).

1. **Cart 1.** Solving the two equations:
   $v_1' = v_1 - \frac{(1 + e)\,m_2}{m_1 + m_2}(v_1 - v_2)$;
   with $e$ = {{ e }}: $v_1'$ = {{ answers.v1_after }}.
2. **Cart 2.** $v_2' = v_2 + \frac{(1 + e)\,m_1}{m_1 + m_2}(v_1 - v_2)$ = {{ answers.v2_after }}.
   (Check: $v_2' - v_1' = e\,(v_1 - v_2)$.)
3. **Energy lost.** The centre-of-mass motion keeps its kinetic energy; only the energy of
   the relative motion, $\tfrac{1}{2}\mu (v_1 - v_2)^2$ with $\mu = m_1 m_2/(m_1 + m_2)$, is
   reduced, by the factor $e^2$:
   $\Delta T = \frac{m_1 m_2\,(1 - e^2)\,(v_1 - v_2)^2}{2\,(m_1 + m_2)}$
   = {{ answers.dT }}.
4. **Formula.** $\Delta T$ = `{{ answers.dT_formula }}`.
5. **Check.** With $e = 1$ the factor $1 - e^2$ vanishes: an elastic impact loses
   $\Delta T$ = {{ checks.elastic }} J.
""",
    solve=solve,
    checks=(
        Balance("momentum", lambda p, s: p.m1 * p.v1 + p.m2 * p.v2,
                lambda p, s: p.m1 * s["v1_after"] + p.m2 * s["v2_after"], name="momentum_balance"),
        Balance("relative speed", lambda p, s: p.e * (p.v1 - p.v2),
                lambda p, s: s["v2_after"] - s["v1_after"], name="restitution"),
        Balance("energy", lambda p, s: (p.m1 * p.v1**2 + p.m2 * p.v2**2) / 2,
                lambda p, s: (p.m1 * s["v1_after"]**2 + p.m2 * s["v2_after"]**2) / 2 + s["dT"],
                name="energy_balance"),
        Recompute("v_c", lambda p, s: (p.m1 * p.v1 + p.m2 * p.v2) / (p.m1 + p.m2),
                  name="plastic_common_speed"),
        # e = 1: no kinetic energy is lost
        Limit("dT", {"e": 1.0}, lambda p: 0.0, name="elastic", atol=1e-9),
    ),
    figure=figure,
    parts=(
        Numeric("v1_after", "velocity of cart 1 after the impact", question=1, unit="m/s", points=2,
                misconceptions=(
                    Misconception("elastic impact assumed", lambda p: _after(p, 1.0).v1,
                                  "That is the elastic result (e = 1); the relative velocity "
                                  "after the impact is only −e times that before."),
                    Misconception("plastic impact assumed", lambda p: _after(p, 0.0).v1,
                                  "The carts do not move on together unless e = 0."),
                )),
        Numeric("v2_after", "velocity of cart 2 after the impact", question=2, unit="m/s", points=2,
                misconceptions=(
                    Misconception("elastic impact assumed", lambda p: _after(p, 1.0).v2,
                                  "That is the elastic result (e = 1)."),
                )),
        Numeric("dT", "kinetic energy lost", question=3, unit="J", points=1,
                misconceptions=(
                    Misconception("(1 - e) instead of (1 - e^2)",
                                  lambda p: collisions.kinetic_energy_lost_in_impact(
                                      p.m1, p.m2, p.v1 - p.v2, p.e) / (1 + p.e),
                                  "The loss is ½ μ (1 − e²) v_rel² with the reduced mass μ."),
                )),
        Symbolic("dT_formula", "energy lost as a formula", question=4, points=1,
                 expected="m1*m2*(1-e^2)*(v1-v2)^2/(2*(m1+m2))",
                 variables=("m1", "m2", "v1", "v2", "e"),
                 equals="dT",
                 misconceptions=(
                     Misconception("total mass instead of reduced mass",
                                   "(m1+m2)*(1-e^2)*(v1-v2)^2/2",
                                   "Only the relative motion loses energy: its mass is the "
                                   "reduced mass m1 m2/(m1 + m2)."),
                 )),
    ),
)
