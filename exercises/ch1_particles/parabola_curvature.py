"""Radius of curvature of a parabolic path and the normal acceleration of a particle on
it (Section 1.1.4, eqs. 1.48, 1.49 and 1.51)."""

from dynagrade.exercise import (Constraint, Exercise, Misconception, Numeric, Symbolic, Uniform)
from dynagrade.exercise.checks import Recompute
from dynagrade.mechanics import kinematics


def solve(p):
    rho = float(kinematics.parabola_radius_of_curvature(p.c, p.x1))
    return {"rho": rho, "rho_vertex": float(kinematics.parabola_radius_of_curvature(p.c, 0.0)),
            "a_n": kinematics.path_centripetal_acceleration(p.v, rho)}


def _radius(p, solved):
    """eq. (1.48) for x2 = c x1^2: rho = (1 + (2 c x1)^2)^(3/2) / |2 c|."""
    return (1 + (2 * p.c * p.x1) ** 2) ** 1.5 / (2 * p.c)


EXERCISE = Exercise(
    id="parabola-radius-of-curvature",
    title="Radius of curvature of a parabola",
    source="Section 1.1.4",
    topics=("space curves", "radius of curvature", "normal acceleration"),
    params=(
        Uniform("c", 0.1, 1.0, step=0.05, unit="1/m", symbol="c"),
        Uniform("x1", 0.3, 3.0, step=0.1, unit="m", symbol="x_1"),
        Uniform("v", 1.0, 10.0, step=0.5, unit="m/s", symbol="v"),
    ),
    constraints=(
        Constraint("the slope matters: (2 c x1)^2 > 0.1", lambda p: (2 * p.c * p.x1) ** 2 > 0.1),
    ),
    statement="""
A bead slides along a wire bent into the parabola $x_2 = c\\,x_1^2$ with $c$ = {{ c }}.

1. What is the radius of curvature of the wire at $x_1$ = {{ x1 }}?
2. What is it at the vertex $x_1 = 0$?
3. The bead passes $x_1$ = {{ x1 }} with speed $v$ = {{ v }}. What is the normal
   component of its acceleration there?
4. Write the radius of curvature as a formula in $c$ and $x_1$.
""",
    solution=r"""
For a path given as a graph $x_2 = f(x_1)$ the radius of curvature is
$\rho = \sqrt{1 + f'^2}^{\,3}/|f''|$ (eq. (1.48)).

1. **Radius of curvature.** For $f = c x_1^2$: $f' = 2cx_1$ and $f'' = 2c$, so (eq. (1.49))
   $\rho = \frac{(1 + 4c^2x_1^2)^{3/2} }{2c}$.
   With $c$ = {{ c }} and $x_1$ = {{ x1 }}: $\rho$ = {{ answers.rho }}.
2. **At the vertex.** $x_1 = 0$ leaves $\rho = 1/(2c)$ = {{ answers.rho_vertex }} — the
   tightest bend of the parabola; away from it the wire straightens out.
3. **Normal acceleration.** Along a path $a = \dot v\,e_t + \frac{v^2}{\rho}\,e_n$
   (eq. (1.51)); the normal part is $v^2/\rho$ with $v$ = {{ v }}: $a_n$ = {{ answers.a_n }}.
   It does not depend on how the speed changes.
4. **Formula.** $\rho$ = `{{ answers.rho_formula }}`.
""",
    solve=solve,
    checks=(
        Recompute("rho", _radius, name="curvature_eq_1_48"),
        Recompute("rho_vertex", lambda p, s: 1 / (2 * p.c), name="at_the_vertex"),
        Recompute("a_n", lambda p, s: p.v**2 / _radius(p, s), name="normal_acceleration"),
    ),
    parts=(
        Numeric("rho", "radius of curvature at x1", question=1, unit="m", points=2,
                misconceptions=(
                    Misconception("reciprocal of f''", lambda p: 1 / (2 * p.c),
                                  "Only at the vertex is ρ = 1/f''; elsewhere the slope enters "
                                  "as (1 + f'²)^(3/2), eq. (1.48)."),
                    Misconception("power 1/2 instead of 3/2",
                                  lambda p: (1 + (2 * p.c * p.x1) ** 2) ** 0.5 / (2 * p.c),
                                  "The numerator is (1 + f'²) to the power 3/2, eq. (1.49)."),
                )),
        Numeric("rho_vertex", "radius of curvature at the vertex", question=2, unit="m", points=1),
        Numeric("a_n", "normal acceleration", question=3, unit="m/s^2", points=1,
                misconceptions=(
                    Misconception("vertex radius used", lambda p: p.v**2 * 2 * p.c,
                                  "Use the radius of curvature at the bead's position."),
                )),
        Symbolic("rho_formula", "radius of curvature as a formula", question=4, points=1,
                 expected="(1 + 4*c^2*x1^2)^(3/2)/(2*c)",
                 variables=("c", "x1"),
                 equals="rho",
                 misconceptions=(
                     Misconception("power 1/2", "(1 + 4*c^2*x1^2)^(1/2)/(2*c)",
                                   "The power is 3/2, eq. (1.49)."),
                 )),
    ),
)
