"""Two carts pushed apart by a compressed spring: internal work (Section 2.2.2)."""

import numpy as np

from dynagrade.exercise import (Constraint, Exercise, Misconception, Numeric, Symbolic,
                                Uniform)
from dynagrade.exercise.checks import Balance
from dynagrade.mechanics import energy, systems


def _relative_speed(p):
    spring_work = float(energy.spring_potential_of_stretch(p.k, p.delta))
    return systems.relative_speed_from_internal_work(p.m1, p.m2, spring_work)


def solve(p):
    v_rel = _relative_speed(p)
    speeds = systems.speeds_relative_to_centre_of_mass(p.m1, p.m2, v_rel)  # C stays at rest
    return {"v1": speeds.v1, "v2": speeds.v2, "v_rel": v_rel,
            "V": float(energy.spring_potential_of_stretch(p.k, p.delta))}


def _equal_share(p, m):
    """The wrong route: each cart receives half of the spring energy."""
    return np.sqrt(0.5 * p.k * p.delta**2 / m)


EXERCISE = Exercise(
    id="spring-between-carts",
    title="Two carts pushed apart by a spring",
    source="Section 2.2.2",
    topics=("work-energy balance", "internal forces", "momentum conservation"),
    params=(
        Uniform("m1", 0.5, 5.0, step=0.1, unit="kg", symbol="m_1"),
        Uniform("m2", 0.5, 5.0, step=0.1, unit="kg", symbol="m_2"),
        Uniform("k", 200, 2000, step=50, unit="N/m", symbol="k"),
        Uniform("delta", 2, 10, step=0.5, unit="cm", symbol=r"\delta"),
    ),
    constraints=(
        Constraint("the masses differ, so that the energy is not shared equally",
                   lambda p: abs(p.m1 - p.m2) > 0.15 * max(p.m1, p.m2)),
    ),
    statement=r"""
Two carts, $m_1$ = {{ m1 }} and $m_2$ = {{ m2 }}, stand at rest on a level frictionless
track with a massless spring (stiffness $k$ = {{ k }}) compressed by $\delta$ = {{ delta }}
between them, held by a thread. The thread is cut.

1. With which speed does cart 1 move once the spring has released?
2. With which speed does cart 2 move?
3. With which speed do the carts move apart?
4. Give the speed of cart 1 as a formula in $m_1$, $m_2$, $k$ and $\delta$.
""",
    solution=r"""
Take both carts and the spring as the system. No external horizontal force acts
(frictionless track), so its total momentum stays zero and the centre of mass stays at rest
(Section 2.2.1). The spring force is internal: it does work on the carts, so the kinetic
energy grows by the energy the spring stored, $\tfrac{1}{2} k\delta^2$ = {{ si.V }} J (with
$k$ = {{ k }}, $\delta$ = {{ delta }}; work–energy balance, Section 2.2.2).

1. **Cart 1.** Momentum: $m_1 v_1 = m_2 v_2$. Energy:
   $\tfrac{1}{2} m_1 v_1^2 + \tfrac{1}{2} m_2 v_2^2 = \tfrac{1}{2} k\delta^2$. Eliminating $v_2$:
   $v_1 = \delta\sqrt{\frac{k\,m_2}{m_1(m_1 + m_2)} }$;
   with $m_1$ = {{ m1 }} and $m_2$ = {{ m2 }}: $v_1$ = {{ answers.v1 }}.
2. **Cart 2.** $v_2 = \frac{m_1}{m_2}v_1$ = {{ answers.v2 }}, in the opposite direction; the
   lighter cart gets the larger speed and the larger share of the energy.
3. **Separation speed.** $v_1 + v_2 = \delta\sqrt{k(m_1 + m_2)/(m_1 m_2)}$
   = {{ answers.v_rel }}, i.e. $\tfrac{1}{2}\mu v_{\text{rel} }^2 = \tfrac{1}{2} k\delta^2$ with the
   reduced mass $\mu = m_1 m_2/(m_1 + m_2)$.
4. **Formula.** $v_1$ = `{{ answers.v1_formula }}`.
""",
    solve=solve,
    checks=(
        # starting from rest: the momenta cancel, the spring's energy becomes kinetic
        Balance("momentum magnitude", lambda p, s: p.m1 * abs(s["v1"]), lambda p, s: p.m2 * abs(s["v2"]),
                name="momentum_balance"),
        Balance("energy", lambda p, s: p.k * p.delta**2 / 2,
                lambda p, s: (p.m1 * s["v1"]**2 + p.m2 * s["v2"]**2) / 2, name="energy_balance"),
    ),
    parts=(
        Numeric("v1", "speed of cart 1", question=1, unit="m/s", points=2,
                misconceptions=(
                    Misconception("equal share of the energy", lambda p: _equal_share(p, p.m1),
                                  "The carts do not share the energy equally: momentum "
                                  "m1 v1 = m2 v2 fixes the split."),
                    Misconception("all the energy to cart 1",
                                  lambda p: np.sqrt(p.k * p.delta**2 / p.m1),
                                  "Both carts move: the centre of mass stays at rest."),
                )),
        Numeric("v2", "speed of cart 2", question=2, unit="m/s", points=1,
                misconceptions=(
                    Misconception("equal share of the energy", lambda p: _equal_share(p, p.m2),
                                  "Use momentum conservation to split the energy."),
                )),
        Numeric("v_rel", "relative speed", question=3, unit="m/s", points=1),
        Symbolic("v1_formula", "speed of cart 1 as a formula", question=4, points=1,
                 expected="delta*sqrt(k*m2/(m1*(m1+m2)))",
                 variables=("m1", "m2", "k", "delta"),
                 equals="v1",
                 misconceptions=(
                     Misconception("all the energy to cart 1", "delta*sqrt(k/m1)",
                                   "Both carts move: the centre of mass stays at rest."),
                 )),
    ),
)
