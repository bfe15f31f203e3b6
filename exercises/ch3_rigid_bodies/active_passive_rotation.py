"""Active and passive use of a rotation matrix (Section 3.4.1)."""

import numpy as np

from dynagrade.exercise import (Constraint, Exercise, Misconception, Numeric, Uniform, Vector,
                                per_draw)
from dynagrade.exercise.checks import Balance, Recompute
from dynagrade.mechanics import rotations

E1, E3 = np.array([1.0, 0.0, 0.0]), np.array([0.0, 0.0, 1.0])


def _rotation(p, first_about_e1=False):
    """First gamma about e3, then beta about the fixed e1: R = R1(beta) R3(gamma)."""
    r3 = rotations.rotation_matrix(E3, p.gamma)
    r1 = rotations.rotation_matrix(E1, p.beta)
    return r3 @ r1 if first_about_e1 else r1 @ r3


@per_draw
def _vector(p):
    return np.array([p.a1, p.a2, p.a3])


@per_draw
def solve(p):
    rot = _rotation(p)
    return {
        "a_rotated": rotations.actively_rotated_vector(rot, _vector(p)),
        "a_in_B": rotations.components_in_rotated_frame(rot, _vector(p)),
        "angle": rotations.rotation_angle(rot),
        "trace_R": float(np.trace(rot)),
    }


def _differ(u, w):
    return np.max(np.abs(np.asarray(u) - np.asarray(w))) > 0.05 * np.linalg.norm(u)


def _matrix_by_hand(p):
    """R = R_1(beta) R_3(gamma), each a right-handed rotation about a basis vector written
    out (Section 3.4.1): first about e3 by gamma, then about e1 by beta."""
    c, s = np.cos(p.gamma), np.sin(p.gamma)
    about_e3 = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    c, s = np.cos(p.beta), np.sin(p.beta)
    about_e1 = np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])
    return about_e1 @ about_e3


EXERCISE = Exercise(
    id="active-passive-rotation",
    title="Active and passive rotations",
    source="Section 3.4.1",
    topics=("rotation matrices", "active and passive rotations"),
    params=(
        Uniform("gamma", -150, 150, step=10, unit="deg", symbol=r"\gamma"),
        Uniform("beta", -150, 150, step=10, unit="deg", symbol=r"\beta"),
        Uniform("a1", -3, 3, step=1, symbol="a_1"),
        Uniform("a2", -3, 3, step=1, symbol="a_2"),
        Uniform("a3", -3, 3, step=1, symbol="a_3"),
    ),
    constraints=(
        Constraint("both rotations are real turns", lambda p: min(abs(p.gamma), abs(p.beta)) > 0.1),
        Constraint("the order of the rotations and active/passive use matter",
                   lambda p: _differ(solve(p)["a_rotated"], solve(p)["a_in_B"])
                   and _differ(solve(p)["a_rotated"], _rotation(p, True) @ _vector(p))
                   and _differ(solve(p)["a_in_B"], _rotation(p, True).T @ _vector(p))),
    ),
    statement=r"""
A rigid body is turned first by $\gamma$ = {{ gamma }} about $e_3$ and then by
$\beta$ = {{ beta }} about the fixed axis $e_1$ (right-hand rule). Let $R$ be the rotation
matrix of the combined turn and $B$ the frame the body carries along, whose axes are
$R\,e_i$. Consider the vector $a = a_1 e_1 + a_2 e_2 + a_3 e_3$ with
$(a_1, a_2, a_3)$ = ({{ a1 }}, {{ a2 }}, {{ a3 }}).

1. A body-fixed arrow coincides with $a$ before the turn. What are its components in the
   fixed frame after the turn (active rotation)?
2. What are the components of the (unmoved) vector $a$ in the body frame $B$ after the
   turn (passive rotation)?
3. By which single angle (between 0° and 180°) is the body turned in total?
""",
    solution=r"""
A turn about a fixed axis that follows another multiplies its matrix from the left
(rotation matrices, Section 3.4.1), so the combined turn is
$$R = R_1(\beta)\,R_3(\gamma),$$
with $\gamma$ = {{ gamma }} and $\beta$ = {{ beta }}. The columns of $R_3(\gamma)$ are the
turned axes $(\cos\gamma, \sin\gamma, 0)$, $(-\sin\gamma, \cos\gamma, 0)$ and $(0, 0, 1)$;
those of $R_1(\beta)$ are $(1, 0, 0)$, $(0, \cos\beta, \sin\beta)$ and
$(0, -\sin\beta, \cos\beta)$.

1. **Active rotation.** The arrow turns with the body, so its new components in the fixed
   frame are $a' = R\,a$. With $a$ = ({{ a1 }}, {{ a2 }}, {{ a3 }}):
   $a' = R\,a$ = {{ answers.a_rotated }}.
2. **Passive rotation.** The vector stays where it is and we ask for its components along
   the turned axes $R\,e_i$: $a_i^B = (R\,e_i)\cdot a$, i.e. $a^B = R^{\mathsf T} a$:
   $a^B = R^{\mathsf T} a$ = {{ answers.a_in_B }}.
   Active and passive use differ: $R$ versus its inverse $R^{\mathsf T}$.
3. **Total angle.** Every rotation is a single turn by an angle $\varphi$ about one axis,
   and the trace of its matrix is $\operatorname{tr} R = 1 + 2\cos\varphi$. Here
   $\operatorname{tr} R$ = {{ si.trace_R }}, and
   $$\varphi = \arccos\frac{\operatorname{tr} R - 1}{2}$$
   turns the body by $\varphi$ = {{ answers.angle }} in total.
   The angles $\gamma$ and $\beta$ about different axes do not simply add.
""",
    solve=solve,
    checks=(
        Recompute("a_rotated", lambda p, s: tuple(_matrix_by_hand(p) @ _vector(p)),
                  name="active_by_hand", atol=1e-12),
        Recompute("a_in_B", lambda p, s: tuple(_matrix_by_hand(p).T @ _vector(p)),
                  name="passive_by_hand", atol=1e-12),
        # the trace of a rotation by theta is 1 + 2 cos(theta)
        Recompute("angle", lambda p, s: np.arccos((np.trace(_matrix_by_hand(p)) - 1) / 2),
                  name="angle_from_trace", atol=1e-9),
        # a rotation keeps lengths
        Balance("length", lambda p, s: np.linalg.norm(_vector(p)),
                lambda p, s: np.linalg.norm(s["a_rotated"]), name="length_kept"),
    ),
    parts=(
        Vector("a_rotated", "actively rotated vector", question=1, size=3, points=2, atol=0.02,
               misconceptions=(
                   Misconception("passive instead of active",
                                 lambda p: _rotation(p).T @ _vector(p),
                                 "Rotating the arrow with the body is R a; R^T a gives the "
                                 "components of a fixed vector in the turned frame."),
                   Misconception("order of the rotations swapped",
                                 lambda p: _rotation(p, True) @ _vector(p),
                                 "A turn about a fixed axis after another multiplies from "
                                 "the left: R = R1(β) R3(γ)."),
               )),
        Vector("a_in_B", "components in the body frame", question=2, size=3, points=2, atol=0.02,
               misconceptions=(
                   Misconception("active instead of passive", lambda p: _rotation(p) @ _vector(p),
                                 "Components in a turned frame are R^T a."),
               )),
        Numeric("angle", "total angle of rotation", question=3, unit="deg", points=1,
                misconceptions=(
                    Misconception("angles added", lambda p: abs(p.beta) + abs(p.gamma),
                                  "Rotations about different axes do not add: the angle "
                                  "follows from tr R = 1 + 2 cos φ."),
                )),
    ),
)
