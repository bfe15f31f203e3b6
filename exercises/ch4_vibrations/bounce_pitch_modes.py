"""A trailer body on two axles' springs: the natural frequencies of bounce and pitch and the
point of the body each mode leaves at rest (Section 4.4.2)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.apart import numbers_apart
from dynagrade.exercise.checks import Recompute
from dynagrade.exercise.figure import describe, dimension, ground, new_drawing, spring
from dynagrade.mechanics import multi_dof, vibrations


@per_draw
def solve(p):
    K, M = multi_dof.bounce_pitch_matrices(p.m, p.J, p.k1, p.k2, p.l1, p.l2)
    w = multi_dof.natural_frequencies(K, M)
    Phi = multi_dof.mode_shapes(K, M)
    return {"f1": vibrations.frequency_in_hertz(w[0]), "f2": vibrations.frequency_in_hertz(w[1]),
            "s1": multi_dof.node_position(Phi[0, 0], Phi[1, 0]),
            "s2": multi_dof.node_position(Phi[0, 1], Phi[1, 1]),
            "omega1": w[0], "omega2": w[1], "K11": K[0, 0], "K12": K[0, 1], "K22": K[1, 1]}


def _squares(p):
    """m J w^4 - (m K22 + J K11) w^2 + K11 K22 - K12^2 = 0 (Section 4.4.2), the entries
    from V = k1 (x + l1 theta)^2/2 + k2 (x - l2 theta)^2/2."""
    K11, K12, K22 = p.k1 + p.k2, p.k1 * p.l1 - p.k2 * p.l2, p.k1 * p.l1**2 + p.k2 * p.l2**2
    return np.sort(np.roots([p.m * p.J, -(p.m * K22 + p.J * K11), K11 * K22 - K12**2]).real)


def _node(p, i):
    """First row of (K - w^2 M) q = 0: (K11 - w^2 m) x + K12 theta = 0, so the point
    s = -x/theta = K12 / (K11 - w^2 m) ahead of G stays at rest."""
    K11, K12 = p.k1 + p.k2, p.k1 * p.l1 - p.k2 * p.l2
    return K12 / (K11 - _squares(p)[i] * p.m)


def _bounce(p):
    return np.sqrt((p.k1 + p.k2) / p.m) / (2 * np.pi)


def _pitch(p):
    return np.sqrt((p.k1 * p.l1**2 + p.k2 * p.l2**2) / p.J) / (2 * np.pi)


def _apart(p):
    """The magnitudes of the numeric answers differ by 5 % or more."""
    if abs(p.k1 * p.l1 - p.k2 * p.l2) < 0.2 * p.k1 * p.l1:   # the coupling constraint rejects it
        return True
    s = solve(p)
    return numbers_apart(abs(s[k]) for k in ("f1", "f2", "s1", "s2"))


def _guess_off(guess, key):
    """Where the coupling shifts the frequency by more than 3 %, the uncoupled guess is a
    mistake; where it does not, the guess is the key to within the tolerance."""
    return lambda p: abs(guess(p) / solve(p)[key] - 1) > 0.03


def figure(p):
    """The body as a beam on its two springs, the distances l1 and l2 to scale (the spring
    length is not given and drawn as 0.4 (l1 + l2)); G marked, front to the right."""
    drawing, axes = new_drawing(4.8, 2.4)
    span = p.l1 + p.l2
    h = 0.4 * span
    axes.plot([-p.l2 - 0.15 * span, p.l1 + 0.15 * span], [h, h], color="0.3", lw=4.0)
    for x, name in ((p.l1, "k₁"), (-p.l2, "k₂")):
        spring(axes, (x, 0.0), (x, h), coils=5, width=0.06 * span)
        axes.text(x + 0.05 * span, h / 2, name, ha="left", va="center", fontsize=10)
    ground(axes, -p.l2 - 0.2 * span, p.l1 + 0.2 * span, hatch=0.03 * span)
    axes.plot([0.0], [h], "o", color="C3", ms=5)
    # below the beam (above it the dimension lines' extension line runs up from G), on the
    # side of the longer arm, clear of the springs
    side = 1.0 if p.l1 >= p.l2 else -1.0
    axes.text(0.02 * span * side, h - 0.04 * span, "G ($m$, $J_G$)",
              ha="left" if side > 0 else "right", va="top", fontsize=10)
    dimension(axes, (0.0, h), (p.l1, h), "l₁", offset=0.2 * span, tick=0.02 * span)
    dimension(axes, (-p.l2, h), (0.0, h), "l₂", offset=0.2 * span, tick=0.02 * span)
    describe(axes, "The front spring k₁ is on the right, the rear spring k₂ on the left; "
             "G lies between them.")
    axes.set_xlim(-p.l2 - 0.3 * span, p.l1 + 0.3 * span)
    axes.set_ylim(-0.1 * span, h + 0.35 * span)
    return drawing


EXERCISE = Exercise(
    id="bounce-pitch-modes",
    title="Bounce and pitch of a trailer: natural frequencies and nodes",
    source="Section 4.4.2",
    topics=("multi-DOF vibrations", "natural frequencies", "mode shapes", "nodes"),
    params=(
        Uniform("m", 300, 1500, step=50, unit="kg", symbol="m"),
        Uniform("J", 300, 2500, step=50, unit="kg*m^2", symbol="J_G"),
        Uniform("k1", 10e3, 60e3, step=1e3, unit="N/m", symbol="k_1"),
        Uniform("k2", 10e3, 60e3, step=1e3, unit="N/m", symbol="k_2"),
        Uniform("l1", 0.6, 2.0, step=0.05, unit="m", symbol="l_1"),
        Uniform("l2", 0.6, 2.0, step=0.05, unit="m", symbol="l_2"),
    ),
    constraints=(
        Constraint("bounce and pitch are clearly coupled: |k1 l1 - k2 l2| >= 20 % of k1 l1",
                   lambda p: abs(p.k1 * p.l1 - p.k2 * p.l2) >= 0.2 * p.k1 * p.l1),
        Constraint("the answers differ by at least 5 %", _apart),
    ),
    statement="""
A trailer body of mass $m$ = {{ m }} and moment of inertia $J_G$ = {{ J }} about its
centre of mass $G$ rests on a front spring $k_1$ = {{ k1 }} at the distance
$l_1$ = {{ l1 }} ahead of $G$ and a rear spring $k_2$ = {{ k2 }} at $l_2$ = {{ l2 }}
behind it. It moves in bounce ($x$, the upward displacement of $G$) and pitch ($\\theta$,
front up), small; damping is negligible.

1. What are the two natural frequencies $f_1 < f_2$ in Hz?
2. In each mode one point on the line through the springs stays at rest (a node). Give
   its position $s_1$ (mode 1) and $s_2$ (mode 2) as the distance ahead of $G$
   (negative behind $G$).
""",
    solution=r"""
With $\mathbf q = (x, \theta)$ the spring ends move $x + l_1\theta$ and $x - l_2\theta$,
so $\mathbf M = \operatorname{diag}(m, J_G)$ and
$$K_{11} = k_1 + k_2,\quad K_{12} = K_{2 1} = k_1 l_1 - k_2 l_2,\quad K_{2 2} = k_1 l_1^2 + k_2 l_2^2;$$
the free undamped vibrations solve $(\mathbf K - \omega^2\mathbf M)\hat{\mathbf q} = \mathbf 0$
(Section 4.4.2). Here $K_{11}$ = {{ si.K11 }} N/m, $K_{12}$ = {{ si.K12 }} N and
$K_{2 2}$ = {{ si.K22 }} N·m.

1. **Natural frequencies.** $\det(\mathbf K - \omega^2\mathbf M) = 0$ reads
   $$m J_G\,\omega^4 - (m K_{2 2} + J_G K_{11})\,\omega^2 + K_{11}K_{2 2} - K_{12}^2 = 0,$$
   with the roots $\omega_1$ = {{ si.omega1 }} rad/s and $\omega_2$ = {{ si.omega2 }} rad/s:
   $f_1$ = {{ answers.f1 }} and $f_2$ = {{ answers.f2 }}.
2. **Nodes.** The point the distance $s$ ahead of $G$ moves $x + s\theta$; it rests where
   $s = -x/\theta$. The first row of the eigenvalue problem,
   $(K_{11} - \omega^2 m)\,x + K_{12}\,\theta = 0$, gives
   $$s = \frac{K_{12}}{K_{11} - \omega^2 m}:$$
   $s_1$ = {{ answers.s1 }} and $s_2$ = {{ answers.s2 }}. A node far outside the
   wheelbase marks a nearly pure bounce, a node near $G$ a nearly pure pitch.
   **Check.** The modes are orthogonal with respect to $\mathbf M$,
   $m\,x_1 x_2 + J_G\,\theta_1\theta_2 = 0$, so the nodes obey $s_1 s_2 = -J_G/m$: from
   $s_1$ alone, $s_2 = -J_G/(m s_1)$ = {{ checks.mass_orthogonality }} m.
""",
    solve=solve,
    checks=(
        Recompute("f1", lambda p, s: np.sqrt(_squares(p)[0]) / (2 * np.pi), name="lower_root"),
        Recompute("f2", lambda p, s: np.sqrt(_squares(p)[1]) / (2 * np.pi), name="upper_root"),
        Recompute("s1", lambda p, s: _node(p, 0), name="first_node", rtol=1e-6),
        Recompute("s2", lambda p, s: _node(p, 1), name="second_node", rtol=1e-6),
        # M-orthogonality of the modes: m x1 x2 + J theta1 theta2 = 0, i.e. s1 s2 = -J/m
        Recompute("s2", lambda p, s: -p.J / (p.m * _node(p, 0)), name="mass_orthogonality",
                  rtol=1e-6),
    ),
    figure=figure,
    figure_to_scale=True,
    parts=(
        Numeric("f1", "lower natural frequency", question=1, unit="Hz", points=2, misconceptions=(
            Misconception("uncoupled bounce", _bounce,
                          "K12 couples bounce and pitch: solve det(K - omega^2 M) = 0.",
                          applies=_guess_off(_bounce, "f1")),
            Misconception("uncoupled pitch", _pitch,
                          "K12 couples bounce and pitch: solve det(K - omega^2 M) = 0.",
                          applies=_guess_off(_pitch, "f1")),
            Misconception("omega for f", lambda p: solve(p)["omega1"], "f = omega/(2 pi)."),
        )),
        Numeric("f2", "higher natural frequency", question=1, unit="Hz", points=1, misconceptions=(
            Misconception("uncoupled bounce", _bounce, "Solve det(K - omega^2 M) = 0.",
                          applies=_guess_off(_bounce, "f2")),
            Misconception("uncoupled pitch", _pitch, "Solve det(K - omega^2 M) = 0.",
                          applies=_guess_off(_pitch, "f2")),
        )),
        Numeric("s1", "node of mode 1, ahead of G", question=2, unit="m", points=1,
                misconceptions=(Misconception("x/theta", lambda p: -solve(p)["s1"],
                                              "The point s ahead moves x + s theta: s = -x/theta."),)),
        Numeric("s2", "node of mode 2, ahead of G", question=2, unit="m", points=1,
                misconceptions=(Misconception("x/theta", lambda p: -solve(p)["s2"],
                                              "The point s ahead moves x + s theta: s = -x/theta."),)),
    ),
)
