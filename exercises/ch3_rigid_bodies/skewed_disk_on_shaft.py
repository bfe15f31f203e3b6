"""A disk mounted askew on a shaft: the composite inertia tensor in the shaft's axes, its
product of inertia and the tilt of the principal axis nearest the shaft (Section 3.2.3)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.apart import numbers_apart
from dynagrade.exercise.checks import Limit, Recompute
from dynagrade.exercise.figure import angle_arc, arrow, describe, dimension, new_drawing
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import inertia, rotations


def _disk(p, beta):
    """The disk's tensor about its centre, its normal turned from e3 towards e1 by beta."""
    turn = rotations.rotation_matrix([0.0, 1.0, 0.0], beta)
    return inertia.rotated_inertia_tensor(inertia.inertia_tensor_disk(p.m_d, p.R), turn)


def _tensor(p, beta=None, shaft=True):
    tensor = _disk(p, p.beta if beta is None else beta)
    if shaft:
        tensor = tensor + inertia.inertia_tensor_rod(p.m_s, p.L)
    return tensor


def _tilt(tensor):
    """Angle between e3 and the principal axis nearest to it."""
    axes = inertia.principal_axes(tensor).axes
    return float(np.arccos(np.max(np.abs(axes[2, :]))))


@per_draw
def solve(p):
    tensor = _tensor(p)
    return {"I33": tensor[2, 2], "I13": tensor[0, 2], "I11": tensor[0, 0],
            "gamma": _tilt(tensor)}


def figure(p):
    """The shaft along e3 (to the right) and the disk seen edge-on, to scale."""
    drawing, axes = new_drawing(4.6, 3.0)
    L, R = p.L, p.R
    axes.plot([-L / 2, L / 2], [0.0, 0.0], color="0.3", lw=3)
    normal = np.array([np.cos(p.beta), np.sin(p.beta)])   # (e3, e1) components, drawn (x, y)
    edge = np.array([-normal[1], normal[0]]) * R
    axes.plot([-edge[0], edge[0]], [-edge[1], edge[1]], color="#a0724a", lw=5)
    axes.plot([-0.9 * R, 0.9 * R], [0.0, 0.0], color="0.1", lw=0.6, ls="--")
    axes.plot([0.0, 0.0], [-1.1 * R, 1.1 * R], color="0.1", lw=0.6, ls="--")
    # β is a few degrees: its label stands beside the dashed normal, on the side away from
    # the disk's top, not inside the narrow arc
    angle_arc(axes, (0.0, 0.0), 0.7 * R, np.pi / 2, np.pi / 2 + p.beta)
    away = -np.sign(edge[0]) or 1.0                  # the side the disk's top leans from
    axes.text(0.015 * away, 0.95 * R, "β", ha="left" if away > 0 else "right", va="center",
              fontsize=10)
    arrow(axes, (L / 2 + 0.02, 0.0), (L / 2 + 0.12, 0.0), "e₃", offset=(0.0, 0.025))
    arrow(axes, (-L / 2, 0.0), (-L / 2, 0.1), "e₁", offset=(-0.025, 0.0))
    dimension(axes, (-L / 2, 0.0), (L / 2, 0.0), f"L = {format_number(L)} m",
              offset=-1.25 * R, tick=0.02, side=-1.0)
    # R along the disk's lower half, labelled to its right, off the disk
    dimension(axes, (0.0, 0.0), (-edge[0], -edge[1]), f"R = {format_number(R)} m",
              offset=0.04, tick=0.015, side=1.0)
    axes.text(-L / 2, 1.2 * R, f"disk {format_number(p.m_d)} kg, shaft {format_number(p.m_s)} kg",
              ha="left", va="bottom", fontsize=10)
    describe(axes, "Side view in the plane of e₃ (along the shaft, to the right) and e₁ (up): "
                   "the disk is seen edge-on through the shaft's midpoint, turned by β from "
                   "the plane normal to the shaft.")
    axes.set_xlim(-L / 2 - 0.12, L / 2 + 0.2)
    axes.set_ylim(-1.5 * R - 0.05, 1.45 * R + 0.05)
    return drawing


def _by_hand(p):
    """The disk's I_a = m R^2/2 about its normal n = (sin b, 0, cos b) and I_t = m R^2/4
    about any diameter give I = I_t 1 + (I_a - I_t) n n^T; the shaft adds m_s L^2/12 to
    I11 and I22 (Section 3.2.3)."""
    difference = p.m_d * p.R**2 / 4
    return (p.m_d * p.R**2 / 4 + difference * np.cos(p.beta) ** 2,
            difference * np.sin(p.beta) * np.cos(p.beta),
            p.m_d * p.R**2 / 4 + difference * np.sin(p.beta) ** 2 + p.m_s * p.L**2 / 12)


def _tilt_by_hand(p, s):
    """In the e1-e3 plane the principal directions satisfy tan 2 gamma = 2 I13/(I33 - I11)."""
    i33, i13, i11 = _by_hand(p)
    return 0.5 * np.arctan2(2 * i13, i33 - i11)


def _apart(p):
    """I33, I13 and gamma (in degrees and in radians) never share their number."""
    s = solve(p)
    return numbers_apart((s["I33"], s["I13"], s["gamma"], np.degrees(s["gamma"])))


EXERCISE = Exercise(
    id="skewed-disk-on-shaft",
    title="A disk mounted askew on a shaft: products of inertia and principal axes",
    source="Section 3.2.3",
    topics=("moment of inertia tensor", "composite body", "principal axes",
            "products of inertia"),
    params=(
        Uniform("m_d", 2.0, 10.0, step=0.1, unit="kg", symbol="m_d"),
        Uniform("R", 0.1, 0.3, step=0.01, unit="m", symbol="R"),
        Uniform("m_s", 0.1, 1.5, step=0.05, unit="kg", symbol="m_s"),
        Uniform("L", 0.3, 0.9, step=0.05, unit="m", symbol="L"),
        Uniform("beta", 5, 30, step=1, unit="deg", symbol=r"\beta"),
    ),
    constraints=(
        Constraint("the shaft is longer than the disk is wide (L > 2.2 R)",
                   lambda p: p.L > 2.2 * p.R),
        Constraint("the axis nearest the shaft stays the disk's largest moment "
                   "(I33 > 1.2 I11)", lambda p: solve(p)["I33"] > 1.2 * solve(p)["I11"]),
        Constraint("the shaft tilts the principal axis noticeably beyond beta",
                   lambda p: solve(p)["gamma"] > 1.08 * p.beta),
        Constraint("no two answers share their number", _apart),
    ),
    statement=r"""
A thin homogeneous disk (mass $m_d$ = {{ m_d }}, radius $R$ = {{ R }}) is welded with its
centre to the midpoint O of a slender shaft (mass $m_s$ = {{ m_s }}, length
$L$ = {{ L }}) lying along $e_3$. The disk is mounted askew: its normal is turned from
$e_3$ towards $e_1$ by $\beta$ = {{ beta }}. Work with the inertia tensor of the whole
body about O in the basis $e_1, e_2, e_3$ (off the diagonal $I_{13} = -\int x_1 x_3\,dm$).

1. What is the moment of inertia $I_{33}$ about the shaft's axis?
2. What is the tensor component $I_{13}$?
3. By what angle is the principal axis nearest the shaft tilted from $e_3$?
""",
    solution=r"""
The inertia tensor of a composite body about one point is the sum of its parts' tensors
about that point (Section 3.2.3). Both parts have their centre at O, so no parallel-axis
terms are needed.

- **Disk.** About its centre its principal moments are $I_a = \tfrac{1}{2} m_d R^2$ about
  its normal $n = (\sin\beta, 0, \cos\beta)$ and $I_t = \tfrac{1}{4} m_d R^2$ about every
  diameter, so $I_{d} = I_t\,\mathbf{1} + (I_a - I_t)\,n\,n^T$.
- **Shaft.** $\tfrac{1}{12} m_s L^2$ about $e_1$ and $e_2$, nothing about $e_3$.

1. **About the shaft.** $I_{3 3} = I_t + (I_a - I_t)\cos^2\beta
   = \tfrac{1}{4} m_d R^2\,(1 + \cos^2\beta)$; with $m_d$ = {{ m_d }}, $R$ = {{ R }},
   $\beta$ = {{ beta }}: $I_{3 3}$ = {{ answers.I33 }}.
2. **Product of inertia.** $I_{1 3} = (I_a - I_t)\sin\beta\cos\beta
   = \tfrac{1}{4} m_d R^2 \sin\beta\cos\beta$ = {{ answers.I13 }}. It does not vanish:
   $e_3$ is no principal axis, and a spinning shaft needs bearing moments.
3. **Principal axis.** $e_2$ is principal; in the $e_1$-$e_3$ plane we also need
   $I_{11} = I_t + (I_a - I_t)\sin^2\beta + \tfrac{1}{12} m_s L^2$ = {{ si.I11 }} kg m²
   (with $m_s$ = {{ m_s }}, $L$ = {{ L }}). The principal direction
   $(\sin\gamma, 0, \cos\gamma)$ nearest $e_3$ satisfies
   $$\tan 2\gamma = \frac{2 I_{1 3}}{I_{3 3} - I_{11}},$$
   so $\gamma$ = {{ answers.gamma }}. The shaft adds to $I_{11}$ only, which tilts the
   axis beyond the disk's own normal.

**Check.** Without the shaft ($m_s \to 0$) the principal axis would be the disk's
normal, tilted by $\beta$ itself: {{ checks.disk_alone }} rad.
""",
    solve=solve,
    figure=figure,
    figure_to_scale=True,
    checks=(
        Recompute("I33", lambda p, s: _by_hand(p)[0], name="disk_normal_and_diameters"),
        Recompute("I13", lambda p, s: _by_hand(p)[1], name="product_by_hand"),
        Recompute("gamma", _tilt_by_hand, name="tan_two_gamma"),
        # without the shaft the disk's normal is a principal axis: gamma = beta
        Limit("gamma", {"m_s": 0.0}, lambda p: p.beta, name="disk_alone"),
    ),
    parts=(
        Numeric("I33", "moment about the shaft axis", question=1, unit="kg*m^2", points=1,
                misconceptions=(
                    Misconception("disk taken square to the shaft",
                                  lambda p: p.m_d * p.R**2 / 2,
                                  "The disk is askew: I33 = I_t + (I_a − I_t) cos²β.",
                                  applies=lambda p: np.sin(p.beta) ** 2
                                  > 0.025 * (1 + np.cos(p.beta) ** 2)),
                    Misconception("sin and cos swapped", lambda p: _tensor(p)[0, 0]
                                  - p.m_s * p.L**2 / 12,
                                  "n makes the angle β with e3: its e3 component is cos β."),
                )),
        Numeric("I13", "tensor component I13", question=2, unit="kg*m^2", points=2,
                misconceptions=(
                    Misconception("sign of the product", lambda p: -_tensor(p)[0, 2],
                                  "I = I_t 1 + (I_a − I_t) n⊗n: the entry is "
                                  "+(I_a − I_t) sin β cos β."),
                    Misconception("I_a taken for I_a - I_t",
                                  lambda p: 2 * _tensor(p)[0, 2],
                                  "Only the difference I_a − I_t = m R²/4 makes a product of "
                                  "inertia."),
                )),
        Numeric("gamma", "tilt of the principal axis", question=3, unit="deg", points=2,
                misconceptions=(
                    Misconception("the disk's normal", lambda p: p.beta,
                                  "The shaft adds m_s L²/12 to I11: the principal axis of the "
                                  "whole body is not the disk's normal."),
                )),
    ),
)
