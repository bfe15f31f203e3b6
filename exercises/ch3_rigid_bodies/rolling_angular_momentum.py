"""Angular momentum of a rolling sphere about its centre, its contact point and a fixed
point: the angular momentum transfer formula (Section 3.2.4)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform
from dynagrade.exercise.checks import Recompute
from dynagrade.mechanics import inertia, rigid_kinetics


def _about(p, height):
    """e3 component of H about a fixed point at the given height under the centre."""
    omega = np.array([0.0, 0.0, -p.v / p.R])
    r_ac = np.array([0.0, p.R - height, 0.0])
    return rigid_kinetics.rigid_body_angular_momentum_about_point(
        inertia.inertia_tensor_sphere(p.m, p.R), omega, p.m, r_ac, [p.v, 0.0, 0.0])[2]


def solve(p):
    return {"H_C": _about(p, p.R), "H_P": _about(p, 0.0), "H_A": _about(p, p.h)}


EXERCISE = Exercise(
    id="rolling-sphere-angular-momentum",
    title="Angular momentum of a rolling sphere",
    source="Section 3.2.4",
    topics=("angular momentum transfer formula", "rolling without slipping"),
    params=(
        Uniform("m", 0.5, 8.0, step=0.1, unit="kg", symbol="m"),
        Uniform("R", 0.05, 0.3, step=0.01, unit="m", symbol="R"),
        Uniform("v", 0.5, 6.0, step=0.1, unit="m/s", symbol="v"),
        Uniform("h", 0.1, 1.0, step=0.02, unit="m", symbol="h"),
    ),
    constraints=(
        Constraint("the point A is not where the two contributions cancel (h = 7R/5)",
                   lambda p: abs(p.h - 1.4 * p.R) > 0.3 * p.R),
        Constraint("A is not at the height of the centre", lambda p: abs(p.h - p.R) > 0.2 * p.R),
    ),
    statement=r"""
A homogeneous solid sphere (mass $m$ = {{ m }}, radius $R$ = {{ R }}) rolls without
slipping along $e_1$ on level ground ($e_2$ up), its centre C moving with $v$ = {{ v }}.
Give $e_3$ components ($e_3 = e_1 \times e_2$, counter-clockwise positive) of its angular
momentum

1. about its centre C,
2. about the fixed point of the ground that the contact point P occupies at this instant,
3. about the fixed point A at height $h$ = {{ h }} above the ground, on the vertical
   through P.
""",
    solution=r"""
The angular momentum about any point A follows from the one about the centre of mass with
the transfer formula (Section 3.2.4)
$$H_A = H_C + r_{AC}\times m\,v_C .$$
Rolling without slipping to the right turns the sphere clockwise:
$\omega = -\frac{v}{R}\,e_3$. Here $m$ = {{ m }}, $R$ = {{ R }} and $v$ = {{ v }}.

1. **About the centre.** For a solid sphere $I_C = \tfrac{2}{5} m R^2$, so
   $$H_C = I_C\,\omega = -\tfrac{2}{5}\,m R\,v,$$
   that is $H_C$ = {{ answers.H_C }}.
2. **About the contact point.** C lies $R$ above P: $r_{PC} = R\,e_2$, and
   $R\,e_2\times m v\,e_1 = -m R v\,e_3$. Hence
   $$H_P = -\tfrac{2}{5}\,m R v - m R v = -\tfrac{7}{5}\,m R v,$$
   that is $H_P$ = {{ answers.H_P }}. (The same as $I_P\,\omega$ with
   $I_P = \tfrac{7}{5} m R^2$, since P is the instantaneous centre of rotation.)
3. **About A.** A lies at height $h$ = {{ h }} on the vertical through P, so
   $r_{AC} = (R - h)\,e_2$ and
   $$H_A = -\tfrac{2}{5}\,m R v - m\,(R - h)\,v,$$
   that is $H_A$ = {{ answers.H_A }}. Above the centre ($h > R$) the translation part
   changes sign.
""",
    solve=solve,
    checks=(
        # a sphere rolling to the right spins clockwise, omega = -v/R e3: about C
        # H = (2/5) m R^2 omega; about a point at height h add (r_C - r_A) x m v = -m (R - h) v
        Recompute("H_C", lambda p, s: -2 / 5 * p.m * p.R * p.v, name="spin_only"),
        Recompute("H_P", lambda p, s: -7 / 5 * p.m * p.R * p.v, name="about_the_contact"),
        Recompute("H_A", lambda p, s: -2 / 5 * p.m * p.R * p.v - p.m * (p.R - p.h) * p.v,
                  name="transfer_to_a"),
    ),
    parts=(
        Numeric("H_C", "angular momentum about C", question=1, unit="kg*m^2/s", points=1),
        Numeric("H_P", "angular momentum about P", question=2, unit="kg*m^2/s", points=2,
                misconceptions=(
                    Misconception("transfer term forgotten", lambda p: _about(p, p.R),
                                  "About P add r_PC × m v_C, here −m R v."),
                    Misconception("transfer term with the wrong sign",
                                  lambda p: 2 * _about(p, p.R) - _about(p, 0.0),
                                  "C is above P and moves along +e1: r_PC × m v_C points "
                                  "along −e3, like the spin."),
                )),
        Numeric("H_A", "angular momentum about A", question=3, unit="kg*m^2/s", points=2,
                misconceptions=(
                    Misconception("lever arm h instead of R - h",
                                  lambda p: _about(p, p.R) - p.h * p.m * p.v,
                                  "The lever arm of m v_C about A is the height of C above "
                                  "A, R − h."),
                )),
    ),
)
