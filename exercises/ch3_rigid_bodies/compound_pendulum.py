"""A rod with a disk at its end, pivoted at the other end: moment of inertia about the
pivot, angular acceleration at release and speed at the bottom (Section 3.2.2)."""

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric, Uniform,
                                per_draw)
from dynagrade.exercise.checks import Integrated, Recompute
from dynagrade.mechanics import inertia, rigid_kinetics


def _moment_about_pivot(p, shift_disk=True, shift_rod=True):
    rod = inertia.inertia_tensor_rod(p.m_r, p.L)[0, 0]
    disk = inertia.inertia_tensor_disk(p.m_d, p.R)[2, 2]   # disk swings in its own plane
    if shift_rod:
        rod = inertia.parallel_axis_moment(rod, p.m_r, p.L / 2)
    if shift_disk:
        disk = inertia.parallel_axis_moment(disk, p.m_d, p.L)
    return rod + disk


def _centre_distance(p):
    return (p.m_r * p.L / 2 + p.m_d * p.L) / (p.m_r + p.m_d)


@per_draw
def solve(p):
    i_o = _moment_about_pivot(p)
    mass = p.m_r + p.m_d
    return {
        "I_O": i_o,
        "alpha0": abs(rigid_kinetics.compound_pendulum_angular_acceleration(
            np.pi / 2, p.g, mass, _centre_distance(p), i_o)),
        "omega_bottom": rigid_kinetics.angular_speed_of_pendulum_from_energy(
            np.pi / 2, 0.0, p.g, mass, _centre_distance(p), i_o),
        "d_C": _centre_distance(p),
    }


def _with_moment(p, i_o):
    mass = p.m_r + p.m_d
    return abs(rigid_kinetics.compound_pendulum_angular_acceleration(np.pi / 2, p.g, mass,
                                                            _centre_distance(p), i_o))


def _pivot_moment(p):
    """Rod about its end m_r L^2 / 3, disk about its centre m_d R^2 / 2 moved by L
    (parallel axes, Section 3.2.2)."""
    return p.m_r * p.L**2 / 3 + p.m_d * p.R**2 / 2 + p.m_d * p.L**2


def _swing(t, y, p):
    """Angular momentum balance about the pivot: I_O phi'' = -(m_r L/2 + m_d L) g sin(phi)."""
    return (y[1], -(p.m_r * p.L / 2 + p.m_d * p.L) * p.g * np.sin(y[0]) / _pivot_moment(p))


EXERCISE = Exercise(
    id="rod-and-disk-pendulum",
    title="Pendulum of a rod and a disk",
    source="Section 3.2.2",
    topics=("balance of angular momentum", "parallel-axis theorem", "work-energy balance"),
    params=(
        Uniform("m_r", 0.5, 3.0, step=0.1, unit="kg", symbol="m_r"),
        Uniform("L", 0.4, 1.0, step=0.05, unit="m", symbol="L"),
        Uniform("m_d", 0.5, 5.0, step=0.1, unit="kg", symbol="m_d"),
        Uniform("R", 0.15, 0.4, step=0.01, unit="m", symbol="R"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("the disk's own moment of inertia is a noticeable part of I_O",
                   lambda p: inertia.inertia_tensor_disk(p.m_d, p.R)[2, 2]
                   > 0.04 * _moment_about_pivot(p)),
        Constraint("the rod's mass and the disk's size change the swing noticeably",
                   lambda p: abs(solve(p)["omega_bottom"] - np.sqrt(2 * p.g / p.L))
                   > 0.04 * solve(p)["omega_bottom"]),
        Constraint("the disk fits below the pivot (R < L)", lambda p: p.R < 0.8 * p.L),
    ),
    statement=r"""
A pendulum is made of a slender rod (mass $m_r$ = {{ m_r }}, length $L$ = {{ L }}) pivoted
without friction at its upper end O, and a homogeneous disk (mass $m_d$ = {{ m_d }}, radius
$R$ = {{ R }}) whose centre is fixed to the rod's lower end. Rod and disk swing in the
plane of the disk. The pendulum is released from rest with the rod horizontal
($g$ = {{ g }}).

1. What is the moment of inertia of the pendulum about the pivot axis?
2. What is its angular acceleration just after release?
3. What is its angular speed when the rod passes the vertical?
""",
    solution=r"""
The pendulum turns about the fixed pivot O, so we use the balance of angular momentum about
O and the work-energy balance (Section 3.2.2), both with the moment of inertia about O.

1. **Moment of inertia about O.** The rod about its end: $\tfrac{1}{3} m_r L^2$ (its centroidal
   $\tfrac{1}{12} m_r L^2$ shifted by $L/2$). The disk swings in its own plane: its own
   $\tfrac{1}{2} m_d R^2$, shifted by $L$ with the parallel-axis theorem:
   $$I_O = \tfrac{1}{3} m_r L^2 + \tfrac{1}{2} m_d R^2 + m_d L^2.$$
   With $m_r$ = {{ m_r }}, $L$ = {{ L }}, $m_d$ = {{ m_d }} and $R$ = {{ R }}:
   $I_O$ = {{ answers.I_O }}.
2. **Angular acceleration at release.** The centre of mass lies at
   $$d_C = \frac{m_r L/2 + m_d L}{m_r + m_d},$$
   here $d_C$ = {{ si.d_C }} m below O. With the rod horizontal the weight's moment about O is $(m_r + m_d)\,g\,d_C$,
   and $I_O\ddot\varphi = (m_r + m_d)\,g\,d_C$ gives
   $$\ddot\varphi = \frac{(m_r + m_d)\,g\,d_C}{I_O},$$
   so just after release $\ddot\varphi$ = {{ answers.alpha0 }}.
3. **Angular speed at the vertical.** From the horizontal to the vertical the centre of
   mass drops by $d_C$; the work of gravity becomes kinetic energy of rotation about O:
   $$\tfrac{1}{2} I_O\,\omega^2 = (m_r + m_d)\,g\,d_C
   \quad\Rightarrow\quad \omega = \sqrt{\frac{2(m_r + m_d)\,g\,d_C}{I_O} },$$
   and the rod passes the vertical at $\omega$ = {{ answers.omega_bottom }}.
""",
    solve=solve,
    checks=(
        Recompute("I_O", lambda p, s: _pivot_moment(p), name="parallel_axes"),
        Recompute("alpha0", lambda p, s: abs(_swing(0.0, (np.pi / 2, 0.0), p)[1]),
                  name="released_horizontal"),
        # released horizontal, the speed at the bottom by integrating the swing
        Integrated("omega_bottom", _swing, lambda p: (np.pi / 2, 0.0),
                   lambda p, s: 20 * np.sqrt(p.L / p.g), lambda t, y, p: abs(y[1]),
                   name="integrated_swing", event=lambda t, y, p: y[0], direction=-1),
    ),
    parts=(
        Numeric("I_O", "moment of inertia about O", question=1, unit="kg*m^2", points=2,
                misconceptions=(
                    Misconception("disk not shifted to the pivot",
                                  lambda p: _moment_about_pivot(p, shift_disk=False),
                                  "Use the parallel-axis theorem for the disk as well: "
                                  "½ m_d R² + m_d L²."),
                    Misconception("centroidal moment of the rod",
                                  lambda p: _moment_about_pivot(p, shift_rod=False),
                                  "About its end the rod has m_r L²/3, not m_r L²/12."),
                    Misconception("disk as a point mass",
                                  lambda p: _moment_about_pivot(p) - inertia.inertia_tensor_disk(
                                      p.m_d, p.R)[2, 2],
                                  "The disk's own rotation adds ½ m_d R²."),
                )),
        Numeric("alpha0", "angular acceleration at release", question=2, unit="rad/s^2", points=1,
                misconceptions=(
                    Misconception("disk not shifted to the pivot",
                                  lambda p: _with_moment(p, _moment_about_pivot(p, shift_disk=False)),
                                  "The disk's moment of inertia about O needs m_d L²."),
                )),
        Numeric("omega_bottom", "angular speed at the vertical", question=3, unit="rad/s", points=1,
                misconceptions=(
                    Misconception("all mass at the disk's centre",
                                  lambda p: np.sqrt(2 * p.g / p.L),
                                  "The rod's mass and the disk's size change the moment of "
                                  "inertia; use ½ I_O ω² = m g d_C."),
                )),
    ),
)
