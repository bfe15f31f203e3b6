"""A chain falling onto a scale: weight plus momentum flux (Section 2.3.2)."""

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric,
                                Symbolic, Uniform, apart)
from dynagrade.exercise.checks import Recompute
from dynagrade.mechanics import impact, particle, variable_mass


def solve(p):
    lam = p.m / p.L
    return {
        "F_x": variable_mass.chain_on_scale_force(lam, p.x, p.g),
        "F_max": variable_mass.chain_on_scale_force(lam, p.L, p.g),
        "F_end": float(particle.weight(lam * p.L, p.g)),
        "lam": lam,
        "v_arrive": impact.impact_speed_after_fall(p.x, p.g),
    }


def _scale_force(p, solved):
    """The weight of the chain already on the scale, lam x g, plus the momentum flux of
    the links arriving at the speed of a free fall through x, lam v^2 = 2 lam g x."""
    lam = p.m / p.L
    return lam * p.x * p.g + lam * 2 * p.g * p.x


EXERCISE = Exercise(
    id="chain-falling-on-scale",
    title="Chain falling on a scale",
    source="Section 2.3.2",
    topics=("mass accretion", "momentum flux", "variable mass"),
    params=(
        Uniform("m", 0.5, 5.0, step=0.1, unit="kg", symbol="m"),
        Uniform("L", 0.5, 3.0, step=0.1, unit="m", symbol="L"),
        Uniform("x", 0.1, 2.5, step=0.05, unit="m", symbol="x"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        # two answers that agree as numbers can be swapped and score (verify's variety rule)
        Constraint("the force at x and the final weight differ (x not L/3)",
                   lambda p: apart(solve(p)["F_x"], solve(p)["F_end"])),
        Constraint("the fallen length is a clear part of the chain (0.1 L < x < 0.9 L)",
                   lambda p: 0.1 * p.L < p.x < 0.9 * p.L),
    ),
    statement=r"""
A flexible chain of mass $m$ = {{ m }} and length $L$ = {{ L }} hangs vertically with its
lower end just touching the pan of a scale. It is released from rest and falls freely
onto the pan, where the links come to rest at once ($g$ = {{ g }}).

1. What does the scale read (a force) when the length $x$ = {{ x }} has fallen onto it?
2. What does it read just before the last link lands?
3. What does it read once the whole chain lies on the pan?
4. Give the reading of question 1 as a formula in $m$, $L$, $x$ and $g$.
""",
    solution=r"""
The chain has the mass per length $\lambda = m/L$ = {{ si.lam }} kg/m (with $m$ = {{ m }},
$L$ = {{ L }}). The part still in the air falls freely: a link that has fallen the height $x$
arrives with $v = \sqrt{2gx}$. On the pan the scale must carry the weight of the chain lying
there and, in addition, stop the arriving links: by the linear momentum balance for the mass
arriving on the pan (Section 2.3.2), stopping a mass flow $\lambda v$ of speed $v$ takes the
force $\lambda v \cdot v = \lambda v^2$ (the momentum flux).

1. **Reading at $x$.** With $x$ = {{ x }} fallen, $v = \sqrt{2gx}$ = {{ si.v_arrive }} m/s and
   $F = \lambda g x + \lambda v^2 = \lambda g x + 2\lambda g x = 3\lambda g x = \frac{3mgx}{L}$,
   with $g$ = {{ g }}: $F$ = {{ answers.F_x }} — three times the weight of the chain on the pan.
2. **Just before the last link lands.** $x \to L$: $F = 3mg$ = {{ answers.F_max }}.
3. **Whole chain on the pan.** Nothing arrives any more; the scale carries only the weight,
   $F = mg$ = {{ answers.F_end }} — the reading drops to a third at once.
4. **Formula.** $F$ = `{{ answers.F_x_formula }}`.
""",
    solve=solve,
    checks=(
        Recompute("F_x", _scale_force, name="weight_plus_momentum_flux"),
        Recompute("F_max", lambda p, s: 3 * p.m * p.g, name="last_link_arriving"),
        Recompute("F_end", lambda p, s: p.m * p.g, name="at_rest"),
    ),
    parts=(
        Numeric("F_x", "reading after x has fallen", question=1, unit="N", points=2,
                misconceptions=(
                    Misconception("weight of the piled chain only",
                                  lambda p: p.m / p.L * p.x * p.g,
                                  "The pan also stops the arriving links: add the momentum "
                                  "flux λ v² = 2 λ g x."),
                    Misconception("momentum flux at half", lambda p: 2 * p.m / p.L * p.x * p.g,
                                  "The arriving links have v² = 2 g x: the flux is λ v², "
                                  "twice the weight of the piled part."),
                )),
        Numeric("F_max", "reading just before the last link lands", question=2, unit="N", points=1,
                misconceptions=(
                    Misconception("weight only", lambda p: p.m * p.g,
                                  "Just before the end the pan still stops links arriving with "
                                  "v² = 2 g L."),
                )),
        Numeric("F_end", "reading at rest", question=3, unit="N", points=1),
        Symbolic("F_x_formula", "reading as a formula", question=4, points=1, expected="3*m*g*x/L",
                 variables=("m", "L", "x", "g"),
                 equals="F_x",
                 misconceptions=(
                     Misconception("weight of the piled chain only", "m*g*x/L",
                                   "Add the momentum flux of the arriving links."),
                 )),
    ),
)
