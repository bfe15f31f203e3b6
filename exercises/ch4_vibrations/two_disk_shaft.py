"""Two disks on a twisted shaft: the free-free torsional system, its natural frequency and
the node of the mode (Section 4.4.2)."""

import numpy as np

from dynagrade.exercise import Constant, Constraint, Exercise, Misconception, Numeric, Uniform
from dynagrade.exercise.checks import Recompute
from dynagrade.mechanics import inertia, multi_dof, stiffness, vibrations


def _J(m, R):
    return inertia.inertia_tensor_disk(m, R)[2, 2]


def _system(p):
    kt = stiffness.torsional_stiffness(p.G, stiffness.circle_polar_moment(p.d), p.L)
    K = multi_dof.chain_stiffness_matrix([0.0, kt])
    M = multi_dof.lumped_mass_matrix([_J(p.m1, p.R1), _J(p.m2, p.R2)])
    return K, M


def solve(p):
    K, M = _system(p)
    w = multi_dof.natural_frequencies(K, M)[1]
    shape = multi_dof.mode_shapes(K, M)[:, 1]
    # the twist varies linearly along the shaft: its zero lies at L * phi1 / (phi1 - phi2)
    node = p.L * shape[0] / (shape[0] - shape[1])
    return {"kt": K[1, 1], "f": vibrations.frequency_in_hertz(w), "node": node,
            "I_p": stiffness.circle_polar_moment(p.d), "J1": M[0, 0], "J2": M[1, 1], "omega": w}


def _moments(p):
    """Disks about their axes m R^2 / 2; the shaft's stiffness G (pi d^4 / 32) / L."""
    return p.m1 * p.R1**2 / 2, p.m2 * p.R2**2 / 2, p.G * np.pi * p.d**4 / 32 / p.L


EXERCISE = Exercise(
    id="two-disk-torsional-shaft",
    title="Two disks on a shaft: torsional natural frequency and node",
    source="Section 4.4.2",
    topics=("torsional vibration", "rigid-body mode", "mode shape", "natural frequency"),
    params=(
        Uniform("m1", 5, 100, step=1, unit="kg", symbol="m_1"),
        Uniform("R1", 0.1, 0.5, step=0.01, unit="m", symbol="R_1"),
        Uniform("m2", 5, 100, step=1, unit="kg", symbol="m_2"),
        Uniform("R2", 0.1, 0.5, step=0.01, unit="m", symbol="R_2"),
        Uniform("d", 10, 60, step=1, unit="mm", symbol="d"),
        Uniform("L", 0.5, 3.0, step=0.1, unit="m", symbol="L"),
        Constant("G", 80, unit="GPa", symbol="G"),
    ),
    constraints=(
        Constraint("the disks' inertias differ by at least 20 %",
                   lambda p: abs(_J(p.m1, p.R1) / _J(p.m2, p.R2) - 1) >= 0.2),
        Constraint("disk 2 is not so heavy that disk 1 vibrates as if against a wall",
                   lambda p: _J(p.m1, p.R1) / _J(p.m2, p.R2) >= 0.1),
    ),
    statement="""
Two homogeneous disks, $m_1$ = {{ m1 }} with radius $R_1$ = {{ R1 }} and $m_2$ = {{ m2 }}
with radius $R_2$ = {{ R2 }}, sit at the two ends of a steel shaft of diameter
$d$ = {{ d }}, length $L$ = {{ L }} and shear modulus $G$ = {{ G }}. The shaft turns in
frictionless bearings; neglect its mass.

1. What is the torsional stiffness $k_t$ of the shaft?
2. The system can turn as a whole ($\\omega = 0$). What is the frequency (in Hz) of its torsional vibration?
3. How far from disk 1 is the cross-section of the shaft that does not rotate in this mode?
""",
    solution=r"""
Two rotors on a massless elastic shaft and no support moment: the system has a rigid-body
mode ($\omega = 0$) and one torsional mode, in which the total angular momentum stays zero
(multi-degree-of-freedom vibrations, Section 4.4.2).

1. **Torsional stiffness.** For a solid circular shaft $I_p = \frac{\pi}{2}\bigl(\frac{d}{2}\bigr)^4$ = {{ si.I_p }} m⁴
   ($d$ = {{ d }}), and
   $$k_t = \frac{G I_p}{L},$$
   so with $G$ = {{ G }} and $L$ = {{ L }}: $k_t$ = {{ answers.kt }}.
2. **Natural frequency.** The disks have $J_i = \tfrac{1}{2} m_i R_i^2$: $J_1$ = {{ si.J1 }} and
   $J_2$ = {{ si.J2 }} kg·m² ($m_1$ = {{ m1 }}, $R_1$ = {{ R1 }}, $m_2$ = {{ m2 }},
   $R_2$ = {{ R2 }}). The equations $J_1\ddot\varphi_1 = k_t(\varphi_2 - \varphi_1)$ and
   $J_2\ddot\varphi_2 = -k_t(\varphi_2 - \varphi_1)$ give
   $\omega^2\bigl(J_1 J_2\,\omega^2 - k_t (J_1 + J_2)\bigr) = 0$, so besides $\omega = 0$
   $$\omega = \sqrt{\frac{k_t\,(J_1 + J_2)}{J_1 J_2} },$$
   here $\omega$ = {{ si.omega }} rad/s, and $f = \omega/(2\pi)$ = {{ answers.f }}.
3. **Node.** In this mode $J_1\varphi_1 + J_2\varphi_2 = 0$: the disks turn against each
   other. The twist varies linearly along the shaft, so it vanishes at
   $$x_{\mathrm{node} } = \frac{J_2}{J_1 + J_2}\,L$$
   from disk 1, that is $x_{\mathrm{node} }$ = {{ answers.node }} — closer to the disk with the larger moment of inertia.
""",
    solve=solve,
    checks=(
        # the disks twist against each other about a node that keeps the momentum zero
        # (Section 4.4.2): omega^2 = k_t (J1 + J2) / (J1 J2), node at L J2 / (J1 + J2)
        Recompute("f", lambda p, s: np.sqrt(_moments(p)[2] * (_moments(p)[0] + _moments(p)[1])
                                             / (_moments(p)[0] * _moments(p)[1])) / (2 * np.pi),
                  name="two_disk_frequency"),
        Recompute("node", lambda p, s: p.L * _moments(p)[1] / (_moments(p)[0] + _moments(p)[1]),
                  name="node_position"),
        Recompute("kt", lambda p, s: _moments(p)[2], name="shaft_stiffness"),
    ),
    parts=(
        Numeric("kt", "torsional stiffness", question=1, unit="N*m", points=1,
                misconceptions=(Misconception("second moment I instead of I_p",
                                              lambda p: stiffness.torsional_stiffness(p.G, stiffness.circle_second_moment(p.d), p.L),
                                              "Torsion uses the polar moment I_p = pi d^4/32."),)),
        Numeric("f", "torsional natural frequency", question=2, unit="Hz", points=2,
                misconceptions=(
                    Misconception("disk 2 clamped", lambda p: vibrations.frequency_in_hertz(
                        vibrations.natural_frequency(_system(p)[0][1, 1], _J(p.m1, p.R1))),
                                  "Both disks turn: omega^2 = k_t (J1 + J2)/(J1 J2)."),
                    Misconception("omega for f", lambda p: 2 * np.pi * solve(p)["f"], "f = omega/(2 pi)."),
                )),
        Numeric("node", "distance of the node from disk 1", question=3, unit="m", points=2,
                misconceptions=(
                    Misconception("the middle", lambda p: p.L / 2, "The node lies nearer to the heavier disk."),
                    Misconception("J1 and J2 swapped", lambda p: p.L - solve(p)["node"],
                                  "The node divides L in the ratio J2 : J1 (from disk 1)."),
                )),
    ),
)
