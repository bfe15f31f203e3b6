"""A disk mounted off-centre on a spinning shaft: angular momentum about a bearing point
from the transfer formula, and the moment the bearings must supply (Section 3.2.4)."""


import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.apart import numbers_apart
from dynagrade.exercise.checks import Recompute
from dynagrade.exercise.figure import angle_arc, describe, dimension, new_drawing
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import inertia, rigid_kinetics


def _angular_momentum(p):
    """H about O at the instant C lies in the e1-e3 plane: r_OC = (e, 0, h)."""
    omega = np.array([0.0, 0.0, p.Omega])
    r_oc = np.array([p.e, 0.0, p.h])
    v_c = np.cross(omega, r_oc)   # C turns about the fixed axis
    return rigid_kinetics.rigid_body_angular_momentum_about_point(
        inertia.inertia_tensor_disk(p.m, p.R), omega, p.m, r_oc, v_c)


@per_draw
def solve(p):
    h_o = _angular_momentum(p)
    moment = rigid_kinetics.moment_for_steady_rotation([0.0, 0.0, p.Omega], h_o)
    return {
        "H_axial": h_o[2],
        "H_perp": float(np.hypot(h_o[0], h_o[1])),
        "M_O": float(np.linalg.norm(moment)),
    }


def _steel_thickness(p):
    """The thickness a steel disk of the drawn mass and radius has: the statement calls the
    disk thin, so a 8 kg disk of 6 cm radius (9 cm thick) is not one."""
    return p.m / (7850.0 * np.pi * p.R**2)


def _apart(p):
    s = solve(p)
    return numbers_apart((s["H_axial"], s["H_perp"], s["M_O"]))


def figure(p):
    """The shaft (e3 up) to scale from the bearing point O, the disk seen edge-on at the
    height h, its centre C off the axis by e. The labels are placed in units of the
    figure's size s, so that they keep their room whether the disk is wide or the shaft
    long."""
    drawing, axes = new_drawing(4.0, 3.4)
    s = max(p.h, p.R + p.e)
    top = p.h + 0.5 * s
    axes.plot([0.0, 0.0], [-0.08 * s, top], color="0.3", lw=3)
    axes.plot([p.e - p.R, p.e + p.R], [p.h, p.h], color="#a0724a", lw=6)
    axes.plot([p.e], [p.h], "o", color="0.1", ms=4)
    axes.text(p.e + 0.02 * s, p.h + 0.03 * s, "C", ha="left", va="bottom", fontsize=10)
    axes.plot([0.0], [0.0], "o", color="0.1", ms=5)
    axes.text(-0.04 * s, 0.0, "O", ha="right", va="center", fontsize=10)
    dimension(axes, (0.0, 0.0), (0.0, p.h), f"h = {format_number(p.h)} m",
              offset=p.R - p.e + 0.3 * s, tick=0.03 * s, side=-1.0)
    # e above the disk, its label to the left of the shaft (e is too short to hold it)
    dimension(axes, (0.0, p.h), (p.e, p.h), offset=0.16 * s)
    axes.text(-0.04 * s, p.h + 0.16 * s, f"e = {format_number(p.e)} m", ha="right",
              va="center", fontsize=10)
    # R below the disk, from C to the rim
    dimension(axes, (p.e, p.h), (p.e + p.R, p.h), f"R = {format_number(p.R)} m",
              offset=-0.12 * s, tick=0.03 * s, side=-1.0)
    angle_arc(axes, (0.0, top - 0.08 * s), 0.05 * s, -0.3 * np.pi, 1.3 * np.pi)
    axes.text(0.1 * s, top - 0.08 * s, f"Ω = {format_number(p.Omega * 30 / np.pi)} rpm",
              ha="left", va="center", fontsize=10)
    describe(axes, "Side view: the shaft is vertical (e₃ up) and turns counter-clockwise "
                   "seen from above; the disk is seen edge-on, normal to the shaft, its "
                   "centre C to the right of the axis.")
    axes.set_xlim(-(p.R - p.e) - 0.65 * s, p.e + p.R + 0.1 * s)
    axes.set_ylim(-0.15 * s, top + 0.05 * s)
    return drawing


EXERCISE = Exercise(
    id="eccentric-disk-bearing-moment",
    title="A disk mounted off-centre on a spinning shaft: angular momentum and bearing moment",
    source="Section 3.2.4",
    topics=("angular momentum transfer formula", "fixed-axis rotation", "unbalance"),
    params=(
        Uniform("m", 1.0, 10.0, step=0.1, unit="kg", symbol="m"),
        Uniform("R", 0.05, 0.2, step=0.005, unit="m", symbol="R"),
        Uniform("e", 0.01, 0.05, step=0.001, unit="m", symbol="e"),
        Uniform("h", 0.1, 0.5, step=0.01, unit="m", symbol="h"),
        Uniform("Omega", 120, 600, step=10, unit="rpm", symbol=r"\Omega"),
    ),
    constraints=(
        Constraint("the offset is a noticeable part of the disk (e > 0.15 R, e < 0.5 R)",
                   lambda p: 0.15 * p.R < p.e < 0.5 * p.R),
        Constraint("a thin steel disk: m / (7850 kg/m^3 pi R^2) is 4 mm to 30 mm thick and "
                   "at most R/4", lambda p: 0.004 <= _steel_thickness(p) <= min(0.03, p.R / 4)),
        Constraint("no two answers share their number (5 % apart)", _apart),
    ),
    statement=r"""
A thin homogeneous disk (mass $m$ = {{ m }}, radius $R$ = {{ R }}) is mounted on a
vertical shaft with its plane normal to the shaft, but off-centre: its centre C lies
$e$ = {{ e }} from the shaft's axis, at the height $h$ = {{ h }} above the point O of
the axis at the lower bearing. The shaft turns at the constant rate
$\Omega$ = {{ Omega }}, $e_3$ along the axis. Neglect the shaft's mass.

1. What is the component of the disk's angular momentum about O along the axis?
2. How large is the component of that angular momentum normal to the axis?
3. How large is the moment about O that the bearings must exert to keep the rotation
   steady?
""",
    solution=r"""
The disk turns about the fixed axis with $\omega = \Omega\,e_3$, so C moves on a circle,
$v_C = \Omega\,e_3 \times r_{OC}$. The transfer formula (Section 3.2.4) gives the angular
momentum about O from the one about C:
$$H_O = I_C\,\omega + r_{OC} \times m\,v_C .$$
At the instant C lies in the $e_1$-$e_3$ plane, $r_{OC} = (e, 0, h)$ and
$v_C = (0, \Omega e, 0)$; $e_3$ is a principal axis of the disk, $I_C\,\omega =
\tfrac{1}{2} m R^2\,\Omega\,e_3$. With $\Omega$ = {{ Omega }} = {{ si.Omega }} rad/s:
$$r_{OC} \times m\,v_C = m\,\Omega\,e\,(-h,\ 0,\ e).$$

1. **Along the axis.** $H_3 = \bigl(\tfrac{1}{2} m R^2 + m e^2\bigr)\,\Omega$
   = {{ answers.H_axial }}: the parallel-axis moment about the shaft.
2. **Normal to the axis.** $|H_\perp| = m\,e\,h\,\Omega$ = {{ answers.H_perp }}. Although
   the disk's plane is normal to the shaft, $H_O$ is not parallel to $\omega$: the offset
   C makes a product of inertia $-m e h$ about O.
3. **Bearing moment.** $H_O$ turns with the shaft, its components in the disk fixed, so
   the balance of angular momentum (Section 3.2.2) needs
   $M_O = \dot H_O = \omega \times H_O$, of magnitude
   $\Omega\,|H_\perp| = m\,e\,h\,\Omega^2$ = {{ answers.M_O }}.

**Check.** About C instead: $I_C\omega$ is constant, so the bearings' moment about O only has
to turn the momentum, the moment of $m\,a_C = m e\Omega^2$ (towards the axis) with the lever
arm $h$: {{ checks.moment_of_the_centripetal_force }} N·m.
""",
    solve=solve,
    figure=figure,
    figure_to_scale=True,
    checks=(
        # Steiner about the axis: I_axis = m R^2 / 2 + m e^2
        Recompute("H_axial", lambda p, s: (p.m * p.R**2 / 2 + p.m * p.e**2) * p.Omega,
                  name="parallel_axis_about_the_shaft"),
        # balance about C instead of O: H_C is constant (principal axis e3), so M_O is the
        # moment about O of m a_C at C, |r_OC x m (-e Omega^2 e1)| = m e h Omega^2
        Recompute("M_O", lambda p, s: float(np.linalg.norm(np.cross(
            [p.e, 0.0, p.h], [-p.m * p.e * p.Omega**2, 0.0, 0.0]))),
            name="moment_of_the_centripetal_force"),
    ),
    parts=(
        Numeric("H_axial", "axial component of H_O", question=1, unit="kg*m^2/s", points=1,
                misconceptions=(
                    Misconception("offset forgotten", lambda p: p.m * p.R**2 / 2 * p.Omega,
                                  "C moves on a circle of radius e: add m e² Ω "
                                  "(the transfer term's axial part)."),
                    Misconception("rpm used as rad/s",
                                  lambda p: solve(p)["H_axial"] * 30 / np.pi,
                                  "Convert Ω to rad/s: 1 rpm = 2π/60 rad/s."),
                )),
        Numeric("H_perp", "normal component of H_O", question=2, unit="kg*m^2/s", points=2,
                misconceptions=(
                    Misconception("lever arm e instead of h", lambda p: p.m * p.e**2 * p.Omega,
                                  "r_OC × m v_C has the component −m e h Ω along e1: the "
                                  "height h is the lever arm of the momentum m e Ω."),
                )),
        Numeric("M_O", "bearing moment", question=3, unit="N*m", points=2,
                misconceptions=(
                    Misconception("whole H turned", lambda p: p.Omega * np.hypot(
                        solve(p)["H_axial"], solve(p)["H_perp"]),
                                  "Only the part of H_O normal to ω turns: |ω × H_O| = Ω |H_⊥|."),
                    Misconception("centripetal force without its lever arm",
                                  lambda p: p.m * p.e * p.Omega**2,
                                  "That is the bearings' force; its moment about O has the "
                                  "lever arm h."),
                )),
    ),
)
