"""A camera turned in yaw, pitch and roll about its own axes: composing turns about body
axes, active and passive use of the rotation matrix (Section 3.4.1)."""

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric, Uniform,
                                Vector, per_draw)
from dynagrade.exercise.checks import Balance, Recompute
from dynagrade.exercise.figure import angle_arc, arrow, describe, new_drawing
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import rotations

E1, E2, E3 = np.eye(3)


def _fixed_axes_rotation(p):
    """The wrong composition: the same turns about the fixed axes, yaw first."""
    return (rotations.rotation_matrix(E1, p.phi) @ rotations.rotation_matrix(E2, p.theta)
            @ rotations.rotation_matrix(E3, p.psi))


@per_draw
def _rotation(p):
    return rotations.yaw_pitch_roll_rotation(p.psi, p.theta, p.phi)


@per_draw
def solve(p):
    rot = _rotation(p)
    return {
        "n": rotations.actively_rotated_vector(rot, E1),
        "f": rotations.components_in_rotated_frame(rot, p.g * E3),
        "tilt": rotations.angle_above_horizontal(rotations.actively_rotated_vector(rot, E2)),
    }


def _optical_axis_by_hand(p, solved):
    """R e1 written out: the roll leaves e1 alone, the pitch tips it down by theta, the yaw
    turns it by psi: (cos psi cos theta, sin psi cos theta, -sin theta)."""
    return (np.cos(p.psi) * np.cos(p.theta), np.sin(p.psi) * np.cos(p.theta), -np.sin(p.theta))


def _reading_by_hand(p, solved):
    """g e3 along the camera's axes, the rows of R^T: the yaw about e3 leaves e3 alone, so
    g (-sin theta, cos theta sin phi, cos theta cos phi)."""
    return (-p.g * np.sin(p.theta), p.g * np.cos(p.theta) * np.sin(p.phi),
            p.g * np.cos(p.theta) * np.cos(p.phi))


def figure(p):
    """Schematic: the fixed axes in an oblique view and the three turns, each about the
    camera's own axis at that moment (Section 3.4.1)."""
    drawing, axes = new_drawing(4.6, 3.2)
    o = (0.0, 0.0)
    # the axes' labels past their tips: e₁'s, beside its arrow, lay on the roll's circle
    for tip, name, ha, va in (((-0.9, -0.7), "e₁", "right", "top"), ((1.5, 0.0), "e₂", "left",
                                                                     "center"),
                              ((0.0, 1.4), "e₃", "center", "bottom")):
        arrow(axes, o, tip)
        axes.text(tip[0] + (0.05 if ha == "left" else -0.05 if ha == "right" else 0.0),
                  tip[1] + (0.05 if va == "bottom" else -0.03 if va == "top" else 0.0),
                  name, ha=ha, va=va, fontsize=10, color="C0")

    def turn(centre, radius, start, end, label, label_radius):
        """A turn about an axis: an arc with an arrow head at its end, counter-clockwise
        (the right-hand rule seen from the axis' tip), and its label."""
        angle_arc(axes, centre, radius, start, end, label, label_radius=label_radius)
        tangent = np.array([-np.sin(end), np.cos(end)])
        tail = np.array(centre) + radius * np.array([np.cos(end), np.sin(end)])
        axes.annotate("", xy=tuple(tail + 0.08 * tangent), xytext=tuple(tail),
                      arrowprops={"arrowstyle": "-|>", "color": "0.2", "lw": 0.8,
                                  "shrinkA": 0, "shrinkB": 0})

    turn((0.0, 1.0), 0.25, -0.4 * np.pi, 1.3 * np.pi,
         f"1. yaw ψ = {format_number(np.degrees(p.psi))}°", 0.95)
    turn((1.1, 0.0), 0.22, 0.6 * np.pi, 2.3 * np.pi,
         f"2. pitch θ = {format_number(np.degrees(p.theta))}°", 0.75)
    turn((-0.62, -0.48), 0.2, 0.0, 1.7 * np.pi,
         f"3. roll φ = {format_number(np.degrees(p.phi))}°", 0.7)
    describe(axes, "Before the turns the camera's optical axis lies along e1, its second "
                   "axis along e2 and its third axis along e3. It is turned first about e3, "
                   "then about its own second axis, then about its own first (optical) axis, "
                   "each counter-clockwise seen from the tip of the axis.")
    axes.set_xlim(-1.6, 2.2)
    axes.set_ylim(-1.0, 1.6)
    return drawing


def _far(a, b, tol):
    return np.max(np.abs(np.asarray(a) - np.asarray(b))) > tol


EXERCISE = Exercise(
    id="camera-gimbal-yaw-pitch-roll",
    title="A camera on a gimbal: yaw, pitch and roll about its own axes",
    source="Section 3.4.1",
    topics=("rotation matrices", "composition of rotations", "active and passive rotations"),
    params=(
        Uniform("psi", -170, 170, step=10, unit="deg", symbol=r"\psi"),
        Uniform("theta", -60, 60, step=5, unit="deg", symbol=r"\theta"),
        Uniform("phi", -60, 60, step=5, unit="deg", symbol=r"\varphi"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("all three turns are real: |psi| >= 20 deg, |theta| >= 15 deg, "
                   "|phi| >= 15 deg",
                   lambda p: abs(p.psi) >= np.radians(19) and abs(p.theta) >= np.radians(14)
                   and abs(p.phi) >= np.radians(14)),
        Constraint("turning about the fixed axes moves the optical axis elsewhere",
                   lambda p: _far(solve(p)["n"], _fixed_axes_rotation(p) @ E1, 0.1)),
        Constraint("active and passive use of R differ (R is not close to a half turn)",
                   lambda p: _far(_rotation(p) @ E1, _rotation(p).T @ E1, 0.1)
                   and _far(_rotation(p) @ E3, _rotation(p).T @ E3, 0.1)),
        Constraint("the pitch changes the tilt of the second axis by over 2 degrees",
                   lambda p: abs(solve(p)["tilt"] - p.phi) > np.radians(2)),
    ),
    statement=r"""
A camera sits in a gimbal. Its body axes $b_1$ (the optical axis), $b_2$, $b_3$ first
coincide with the fixed axes $e_1$, $e_2$, $e_3$ ($e_3$ vertical, up). The gimbal turns
it, each turn by the right-hand rule,

- first by the yaw $\psi$ = {{ psi }} about $e_3$,
- then by the pitch $\theta$ = {{ theta }} about the camera's own (turned) axis $b_2$
  (positive $\theta$ tips the optical axis downward),
- then by the roll $\varphi$ = {{ phi }} about its own optical axis $b_1$.

An accelerometer fixed in the camera shows, at rest, the vector $g\,e_3$ with
$g$ = {{ g }} (the mount holds it up against gravity).

1. What are the components of the optical axis $b_1$ along $e_1, e_2, e_3$ after the turns?
2. What are the components of the accelerometer's vector $g\,e_3$ along the camera axes
   $b_1, b_2, b_3$?
3. By which angle is the camera's axis $b_2$ raised above the horizontal (negative if it
   points below)?
""",
    solution=r"""
Let $R$ map the fixed axes onto the camera's: $b_i = R\,e_i$ (rotations, Section 3.4.1).
A turn about a *fixed* axis that follows another multiplies from the left; a turn about
the body's *own* axis multiplies from the right, because the turned axis is
$R\,e_2$ and $R_{Re_2}(\theta)\,R = R\,R_2(\theta)$. So the three turns give
$$R = R_3(\psi)\,R_2(\theta)\,R_1(\varphi),$$
with $\psi$ = {{ psi }}, $\theta$ = {{ theta }}, $\varphi$ = {{ phi }}; the same $R$
results from the turns about the fixed axes in the opposite order: roll, pitch, yaw.

1. **Optical axis (active use).** $b_1 = R\,e_1$. The roll leaves $e_1$ in place, the pitch
   tips it to $(\cos\theta, 0, -\sin\theta)$, the yaw turns that about $e_3$:
   $$b_1 = (\cos\psi\cos\theta,\; \sin\psi\cos\theta,\; -\sin\theta)$$
   = {{ answers.n }}.
2. **Accelerometer (passive use).** The components of a fixed vector along the camera axes
   are $R^{\mathsf T}$ times its fixed components. The yaw about $e_3$ does not change
   $e_3$, so
   $$R^{\mathsf T} g\,e_3 = g\,(-\sin\theta,\; \cos\theta\sin\varphi,\; \cos\theta\cos\varphi)$$
   = {{ answers.f }}.
3. **Tilt of $b_2$.** Its vertical component is $b_2\cdot e_3$, the second entry above
   divided by $g$: $\cos\theta\sin\varphi$. Hence the angle
   $\arcsin(\cos\theta\sin\varphi)$ = {{ answers.tilt }} — not simply the roll
   $\varphi$, because the pitch tipped the roll's axis first.

**Check.** Questions 1 and 2 are the same rotation used both ways: the reading along the
optical axis is $g\,e_3\cdot b_1$, $g$ times the vertical component of $b_1$ from question
1: {{ checks.reading_along_the_optical_axis }} m/s², the first entry of question 2.
""",
    solve=solve,
    checks=(
        Recompute("n", _optical_axis_by_hand, name="optical_axis_by_hand", atol=1e-12),
        Recompute("f", _reading_by_hand, name="reading_by_hand", atol=1e-12),
        Recompute("tilt", lambda p, s: np.arcsin(np.cos(p.theta) * np.sin(p.phi)),
                  name="tilt_by_hand", atol=1e-12),
        # active and passive use agree: the reading along b1 is g e3 . b1, g times n's third
        # entry (a length check would pass for any rotation, composed right or wrong)
        Balance("reading along the optical axis", lambda p, s: p.g * s["n"][2],
                lambda p, s: s["f"][0], name="reading_along_the_optical_axis"),
        # a rotation keeps lengths
        Balance("length of the reading", lambda p, s: p.g,
                lambda p, s: np.linalg.norm(s["f"]), name="reading_length"),
    ),
    figure=figure,
    parts=(
        Vector("n", "optical axis in the fixed frame", question=1, size=3, points=2, atol=0.02,
               misconceptions=(
                   Misconception("turns about the fixed axes",
                                 lambda p: _fixed_axes_rotation(p) @ E1,
                                 "The pitch and the roll turn about the camera's own axes: "
                                 "they multiply from the right, R = R3(ψ) R2(θ) R1(φ)."),
                   Misconception("passive instead of active",
                                 lambda p: _rotation(p).T @ E1,
                                 "The camera's axis is the turned vector R e1; R^T e1 gives "
                                 "the components of the fixed e1 along the camera axes."),
               )),
        Vector("f", "accelerometer reading in camera axes", question=2, size=3, unit="m/s^2",
               points=2, atol=0.05,
               misconceptions=(
                   Misconception("active instead of passive",
                                 lambda p: _rotation(p) @ (p.g * E3),
                                 "The vector g e3 does not turn with the camera: its "
                                 "components along the camera axes are R^T (g e3)."),
               )),
        Numeric("tilt", "tilt of b2 above the horizontal", question=3, unit="deg", points=1,
                misconceptions=(
                    Misconception("the roll angle alone", lambda p: p.phi,
                                  "The roll turns about the pitched optical axis: the tilt is "
                                  "arcsin(cos θ sin φ)."),
                )),
    ),
)
