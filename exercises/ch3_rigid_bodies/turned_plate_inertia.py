"""The inertia tensor of a plate turned in its plane, in the fixed frame: a tensor under an
active rotation, and the angular momentum it gives (Section 3.4.1)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.apart import numbers_apart
from dynagrade.exercise.checks import Balance, Recompute
from dynagrade.exercise.figure import angle_arc, arrow, block, describe, dimension, new_drawing
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import inertia, rigid_kinetics, rotations

E1, E3 = np.array([1.0, 0.0, 0.0]), np.array([0.0, 0.0, 1.0])


def _body_tensor(p):
    """About the centre, body axes b1 along the edge a, b2 along b, b3 normal (thin plate)."""
    return inertia.inertia_tensor_box(p.m, p.a, p.b, 0.0)


@per_draw
def solve(p):
    turn = rotations.rotation_matrix(E3, p.alpha)
    fixed = inertia.rotated_inertia_tensor(_body_tensor(p), turn)
    h = rigid_kinetics.rigid_body_angular_momentum(fixed, p.omega * E1)
    return {
        "I11": fixed[0, 0],
        "I12": fixed[0, 1],
        "H": float(np.linalg.norm(h)),
        "delta": rotations.angle_between(h, E1),
        "I22": fixed[1, 1],
        "A": _body_tensor(p)[0, 0],
        "B": _body_tensor(p)[1, 1],
    }


def _passive_I12(p):
    """The wrong route: R^T I R, the components in a frame turned by alpha."""
    turn = rotations.rotation_matrix(E3, p.alpha)
    return (turn.T @ _body_tensor(p) @ turn)[0, 1]


def figure(p):
    """Top view to scale: the plate turned by alpha from the fixed e1 axis about its
    centre (Section 3.4.1)."""
    size = max(p.a, p.b)
    drawing, axes = new_drawing(4.2, 3.6)
    block(axes, (0.0, 0.0), p.a, p.b, angle=p.alpha, color="#9fb7d4")
    # the labels beyond the arrows' tips and off the plate's edges: beside the arrows they
    # lay on the edges and on the b dimension
    arrow(axes, (0.0, 0.0), (0.85 * size, 0.0), color="0.2")
    axes.text(0.9 * size, 0.0, "e₁", ha="left", va="center", fontsize=10, color="0.2")
    arrow(axes, (0.0, 0.0), (0.0, 0.85 * size), color="0.2")
    axes.text(0.0, 0.9 * size, "e₂", ha="center", va="bottom", fontsize=10, color="0.2")
    along = np.array([np.cos(p.alpha), np.sin(p.alpha)])
    normal = np.array([-np.sin(p.alpha), np.cos(p.alpha)])
    arrow(axes, (0.0, 0.0), tuple(0.72 * size * along), color="C3")
    axes.text(*(0.8 * size * along), "b₁", ha="center", va="center", fontsize=10, color="C3")
    # α's arc carries a short label inside the angle, clear of e₂ when α nears 180°
    angle_arc(axes, (0.0, 0.0), 0.3 * size, 0.0, p.alpha)
    middle = p.alpha / 2 if p.alpha / 2 < np.radians(75) else np.radians(65)
    axes.text(*(0.4 * size * np.array([np.cos(middle), np.sin(middle)])), "α", ha="center",
              va="center", fontsize=10)
    corner = -0.5 * p.a * along - 0.5 * p.b * normal
    # a along the plate's lower long edge (away from e₂ and α's arc), whichever that is
    below = 1.0 if normal[1] > 0 else -1.0         # +1: the edge at -b/2 normal is lower
    start = -0.5 * p.a * along - below * 0.5 * p.b * normal
    dimension(axes, tuple(start), tuple(start + p.a * along), f"a = {format_number(p.a)} m",
              offset=-below * 0.12 * size, tick=0.03 * size, side=-below)
    # b at the end b₁ does not point to
    dimension(axes, tuple(corner), tuple(corner + p.b * normal), f"b = {format_number(p.b)} m",
              offset=0.12 * size, tick=0.03 * size, side=1.0)
    describe(axes, "Seen along e3: the plate's edge a lies along b1, turned counter-clockwise "
                   "by alpha from e1.")
    axes.set_xlim(-0.95 * size, 1.05 * size)
    axes.set_ylim(-0.95 * size, 1.0 * size)
    return drawing


EXERCISE = Exercise(
    id="turned-plate-inertia-tensor",
    title="Inertia tensor of a plate turned in its plane",
    source="Section 3.4.1",
    topics=("rotation matrices", "inertia tensor", "active and passive rotations"),
    params=(
        Uniform("m", 0.5, 5.0, step=0.1, unit="kg", symbol="m"),
        Uniform("a", 0.3, 1.2, step=0.05, unit="m", symbol="a"),
        Uniform("b", 0.1, 0.8, step=0.05, unit="m", symbol="b"),
        Uniform("alpha", 10, 170, step=5, unit="deg", symbol=r"\alpha"),
        Uniform("omega", 2.0, 20.0, step=0.5, unit="rad/s", symbol=r"\omega"),
    ),
    constraints=(
        Constraint("the plate is clearly oblong: a > 1.3 b", lambda p: p.a > 1.3 * p.b),
        Constraint("the turn mixes the axes: H deviates from e1 by over 12 degrees",
                   lambda p: solve(p)["delta"] > np.radians(12)),
        Constraint("I11, |I12| and |H| differ by over 5 %",
                   lambda p: numbers_apart([solve(p)[k] for k in ("I11", "I12", "H")])),
    ),
    statement=r"""
A thin homogeneous rectangular plate (mass $m$ = {{ m }}, edges $a$ = {{ a }} and
$b$ = {{ b }}) lies in the $e_1$–$e_2$ plane with its centre at the origin. Its body axes
are $b_1$ along the edge $a$, $b_2$ along $b$ and $b_3 = e_3$. Starting with $b_1 = e_1$,
the plate is turned about $e_3$ by $\alpha$ = {{ alpha }} (right-hand rule).

1. What is the entry $I_{11}$ of the plate's inertia tensor about its centre in the fixed
   frame $e_1, e_2, e_3$?
2. What is the entry $I_{12}$ of that tensor (the matrix entry, including its sign)?
3. The plate now turns with $\omega$ = {{ omega }} about the fixed axis $e_1$. How large
   is its angular momentum about the centre?
4. By which angle does the angular momentum deviate from the axis $e_1$?
""",
    solution=r"""
In the body axes the tensor is diagonal (a thin plate, Section 3.2.3):
$A = m b^2/12$ = {{ si.A }} kg·m² about $b_1$, $B = m a^2/12$ = {{ si.B }} kg·m² about
$b_2$ and $A + B$ about $b_3$. The turn $R = R_3(\alpha)$ maps $e_i$ to $b_i$ (rotations,
Section 3.4.1). The turned body's tensor in the fixed frame is the active rotation of the
tensor, $I = R\,I^B R^{\mathsf T}$ (a vector $v$ becomes $R v$, so $I$ must send $R v$ to
$R\,I^B v$).

1. With $R_3(\alpha)$ written out,
   $I_{11} = A\cos^2\alpha + B\sin^2\alpha$ = {{ answers.I11 }}.
2. $I_{12} = (A - B)\sin\alpha\cos\alpha$ = {{ answers.I12 }}; the other diagonal
   entry is $A\sin^2\alpha + B\cos^2\alpha$ = {{ si.I22 }} kg·m².
3. $H = I\,\omega e_1 = \omega\,(I_{11},\, I_{12},\, 0)$ (angular momentum of a rigid body,
   Section 3.2.2), so $|H| = \omega\sqrt{I_{11}^2 + I_{12}^2}$ = {{ answers.H }}.
4. $\tan\delta = |I_{12}|/I_{11}$: $\delta$ = {{ answers.delta }}. $H$ and $\omega$ are
   parallel only when $\omega$ lies along a principal axis ($b_1$ or $b_2$ along $e_1$).

**Check.** The eigenvalues of the fixed-frame tensor are again $A$ and $B$: the largest is
{{ checks.principal_moments }} kg·m² $= B$, since a rotation changes the components of a
tensor but not the tensor.
""",
    solve=solve,
    checks=(
        Recompute("I11", lambda p, s: p.m / 12 * (p.b**2 * np.cos(p.alpha)**2
                                                  + p.a**2 * np.sin(p.alpha)**2),
                  name="I11_by_hand"),
        # Mohr's circle: I12 = (A - B)/2 sin 2 alpha
        Recompute("I12", lambda p, s: p.m / 24 * (p.b**2 - p.a**2) * np.sin(2 * p.alpha),
                  name="mohr_circle"),
        # the eigenvalues (numpy's solver) of the fixed-frame 2x2 block are A and B
        Balance("largest principal moment",
                lambda p, s: max(np.linalg.eigvalsh([[s["I11"], s["I12"]],
                                                     [s["I12"], s["I22"]]])),
                lambda p, s: p.m * p.a**2 / 12, name="principal_moments"),
        Recompute("delta", lambda p, s: np.arctan2(abs(s["I12"]), s["I11"]),
                  name="delta_from_components"),
    ),
    figure=figure, figure_to_scale=True,
    parts=(
        Numeric("I11", "I11 in the fixed frame", question=1, unit="kg*m^2", points=1,
                misconceptions=(
                    Misconception("cos² and sin² swapped",
                                  lambda p: p.m / 12 * (p.b**2 * np.sin(p.alpha)**2
                                                        + p.a**2 * np.cos(p.alpha)**2),
                                  "b1 is turned by α from e1: I11 = A cos²α + B sin²α with "
                                  "A = m b²/12 about b1.",
                                  applies=lambda p: abs(np.cos(2 * p.alpha)) > 0.05),
                )),
        Numeric("I12", "I12 in the fixed frame", question=2, unit="kg*m^2", points=2,
                misconceptions=(
                    Misconception("passive instead of active", _passive_I12,
                                  "The plate is turned, not the frame: I = R I^B R^T, which "
                                  "gives I12 = (A − B) sin α cos α."),
                )),
        Numeric("H", "magnitude of the angular momentum", question=3, unit="kg*m^2/s",
                points=1,
                misconceptions=(
                    Misconception("H along the axis, I11 ω", lambda p: solve(p)["I11"] * p.omega,
                                  "ω is not along a principal axis: H = I ω has the component "
                                  "I12 ω along e2 as well."),
                )),
        Numeric("delta", "angle between H and e1", question=4, unit="deg", points=1,
                misconceptions=(
                    Misconception("the plate's turn", lambda p: p.alpha,
                                  "H follows from H = I ω: tan δ = |I12|/I11, not the angle "
                                  "of the plate.",
                                  applies=lambda p: abs(solve(p)["delta"] / p.alpha - 1) > 0.03),
                )),
    ),
)
