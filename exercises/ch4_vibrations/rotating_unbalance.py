"""A machine on springs with a rotating unbalance: critical speed, amplitude at the
operating speed and the force passed to the floor (Section 4.3.3)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.checks import Recompute
from dynagrade.exercise.figure import (block, damper, describe, dimension,
                                       ground, new_drawing, spring)
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import vibrations


@per_draw
def _state(p):
    w = vibrations.natural_frequency(p.k, p.M)
    return w, vibrations.frequency_ratio(p.n, w)


def amplitude(p, Omega=None):
    w, eta = _state(p)
    if Omega is not None:
        eta = Omega / w
    return vibrations.unbalance_amplitude(p.m_u, p.e, p.M, eta, p.zeta)


def figure(p):
    """The machine on its mounting: springs and dampers under the frame and the rotor with
    the unbalance at the eccentricity e, turning at n (Section 4.3.3). Only e is a given
    length: the rotor is drawn with radius 3 e and the machine around it."""
    from dynagrade.exercise.figure import Circle

    e = p.e
    width, height, mount = 16 * e, 9 * e, 6 * e
    rpm = p.n * 60 / (2 * np.pi)
    drawing, axes = new_drawing(4.4, 3.6)
    ground(axes, -0.2 * width, 1.2 * width, hatch=0.4 * e)
    spring(axes, (0.25 * width, 0.0), (0.25 * width, mount), coils=5, width=2 * e)
    damper(axes, (0.75 * width, 0.0), (0.75 * width, mount), width=2 * e)
    centre = np.array([0.5 * width, mount + 0.5 * height])
    block(axes, tuple(centre), width, height, color="0.85")
    axes.add_patch(Circle(tuple(centre), 3 * e, facecolor="white", edgecolor="0.1", lw=1.0))
    where = np.radians(40)
    mass = centre + e * np.array([np.cos(where), np.sin(where)])
    axes.plot([centre[0], mass[0]], [centre[1], mass[1]], color="0.1", lw=0.8)
    axes.plot(*centre, "o", color="0.1", ms=3)
    axes.plot(*mass, "o", color="C3", ms=7)
    axes.text(centre[0] + 3.4 * e, mass[1], f"mᵤ = {format_number(p.m_u)} kg",
              ha="left", va="center", fontsize=10)
    axes.plot([mass[0], centre[0] + 3.3 * e], [mass[1], mass[1]], color="0.4", lw=0.6)
    axes.text(centre[0] - 3.4 * e, centre[1] - 1.0 * e, f"e = {format_number(1000 * e)} mm",
              ha="right", va="center", fontsize=10)
    turn, start, end = 3.6 * e, np.radians(100), np.radians(170)
    axes.annotate("", xy=tuple(centre + turn * np.array([np.cos(end), np.sin(end)])),
                  xytext=tuple(centre + turn * np.array([np.cos(start), np.sin(start)])),
                  arrowprops={"arrowstyle": "-|>", "color": "C3", "lw": 1.3,
                              "connectionstyle": "arc3,rad=0.3", "shrinkA": 0, "shrinkB": 0})
    axes.text(centre[0] - 3.6 * e, centre[1] + 3.4 * e, f"n = {format_number(rpm)} rpm",
              color="C3", ha="right", va="bottom", fontsize=10)
    axes.text(0.5 * width, mount + height + 0.5 * e, f"M = {format_number(p.M)} kg",
              ha="center", va="bottom", fontsize=10)
    axes.text(0.25 * width - 1.6 * e, 0.5 * mount, f"k = {format_number(p.k)} N/m",
              ha="right", va="center", fontsize=10)
    axes.text(0.75 * width + 1.6 * e, 0.5 * mount, f"ζ = {format_number(p.zeta)}",
              ha="left", va="center", fontsize=10)
    axes.set_xlim(-0.25 * width, 1.25 * width)
    axes.set_ylim(-0.8 * e, mount + height + 2.5 * e)
    describe(axes, "The machine frame stands on a spring and a damper side by side on the "
             "ground; inside it the rotor carries the unbalanced mass at the eccentricity "
             "e from its axis and turns counter-clockwise, as a curved arrow shows")
    return drawing


def solve(p):
    w, eta = _state(p)
    X = amplitude(p)
    c = vibrations.damping_coefficient(p.zeta, p.k, p.M)
    return {"n_crit": w, "X": X, "F_T": vibrations.transmitted_force_amplitude(X, p.k, c, p.n),
            "eta": eta, "V": vibrations.amplification_factor(eta, p.zeta), "c": c}


def _receptance(p):
    """M x'' + c x' + k x = m_u e n^2 e^(i n t) (Section 4.3.3), c = 2 zeta sqrt(k M)."""
    c = 2 * p.zeta * np.sqrt(p.k * p.M)
    return 1 / (p.k - p.M * p.n**2 + 1j * c * p.n), c


EXERCISE = Exercise(
    id="machine-rotating-unbalance",
    title="Machine with a rotating unbalance on an elastic mounting",
    source="Section 4.3.3",
    topics=("forced vibration", "rotating unbalance", "resonance", "transmissibility"),
    params=(
        Uniform("M", 50, 500, step=10, unit="kg", symbol="M"),
        Uniform("k", 1e5, 2e6, step=5e4, unit="N/m", symbol="k"),
        Uniform("zeta", 0.05, 0.3, step=0.01, symbol=r"\zeta"),
        Uniform("m_u", 0.1, 2.0, step=0.1, unit="kg", symbol="m_u"),
        Uniform("e", 5, 50, step=1, unit="mm", symbol="e"),
        Uniform("n", 300, 3000, step=50, unit="rpm", symbol="n"),
    ),
    constraints=(
        Constraint("the operating speed is at least 15 % away from resonance",
                   lambda p: abs(_state(p)[1] - 1) >= 0.15),
        Constraint("damping matters for the transmitted force (2 zeta eta >= 0.15)",
                   lambda p: 2 * p.zeta * _state(p)[1] >= 0.15),
        # near eta = sqrt(2) the mounting passes the force unchanged (TR = 1)
        Constraint("the transmissibility differs from 1 by at least 5 %",
                   lambda p: abs(vibrations.transmissibility(_state(p)[1], p.zeta) - 1) >= 0.05),
        # far above resonance X tends to m_u e / M whatever the speed
        Constraint("the amplitude still depends on the speed (a wrong speed unit changes it by 5 %)",
                   lambda p: abs(amplitude(p, p.n * 60 / (2 * np.pi)) / amplitude(p) - 1) >= 0.05),
    ),
    statement="""
A machine of total mass $M$ = {{ M }} stands on elastic mounts of total stiffness
$k$ = {{ k }} with damping ratio $\\zeta$ = {{ zeta }}. Its rotor carries an unbalance
$m_u$ = {{ m_u }} at eccentricity $e$ = {{ e }} and runs at $n$ = {{ n }}. Only vertical
motion is possible.

1. At which rotor speed (in rpm) is the mounting in resonance ($\\Omega = \\omega_n$)?
2. What is the amplitude of the machine's vertical vibration at the operating speed?
3. What is the amplitude of the force transmitted to the floor through springs and dampers?
""",
    solution=r"""
The unbalance $m_u$ at eccentricity $e$ spinning at $\Omega$ shakes the machine with the
vertical force $m_u e\,\Omega^2\cos\Omega t$: a harmonic forcing whose amplitude grows with
$\Omega^2$ (rotating unbalance, Section 4.3.3). The operating speed is
$n$ = {{ n }}, i.e. $\Omega$ = {{ si.n }} rad/s (one revolution is $2\pi$).

1. **Critical speed.** Resonance when $\Omega = \omega_n = \sqrt{k/M}$; with $M$ = {{ M }} and
   $k$ = {{ k }}, $\omega_n$ = {{ si.n_crit }} rad/s, that is $n_{\mathrm{crit} }$ = {{ answers.n_crit }}.
2. **Amplitude.** With $\eta = \Omega/\omega_n$ = {{ si.eta }}, $\zeta$ = {{ zeta }} and the
   amplification factor $V = 1/\sqrt{(1 - \eta^2)^2 + (2\zeta\eta)^2}$ = {{ si.V }},
   $$X = \frac{m_u e}{M}\,\eta^2 V;$$
   with $m_u$ = {{ m_u }} and $e$ = {{ e }}: $X$ = {{ answers.X }}.
3. **Transmitted force.** Spring and damper push on the floor with $k x + c\dot x$, whose
   parts are a quarter period apart. With $c = 2\zeta\sqrt{k M}$ = {{ si.c }} N·s/m,
   $$F_T = X\sqrt{k^2 + (c\,\Omega)^2},$$
   that is $F_T$ = {{ answers.F_T }}.
""",
    solve=solve,
    checks=(
        Recompute("X", lambda p, s: abs(p.m_u * p.e * p.n**2 * _receptance(p)[0]),
                  name="complex_amplitude"),
        # the force through spring and damper: |k + i c n| X
        Recompute("F_T", lambda p, s: abs(p.m_u * p.e * p.n**2 * _receptance(p)[0])
                  * abs(p.k + 1j * _receptance(p)[1] * p.n), name="transmitted_force"),
        Recompute("n_crit", lambda p, s: np.sqrt(p.k / p.M), name="natural_frequency"),
    ),
    figure=figure,
    parts=(
        Numeric("n_crit", "critical speed", question=1, unit="rpm", points=1,
                misconceptions=(Misconception("rad/s read as rpm", lambda p: np.sqrt(p.k / p.M) * 2 * np.pi / 60,
                                              "omega_n = sqrt(k/M) is in rad/s: multiply by 60/(2 pi) for rpm."),)),
        Numeric("X", "vibration amplitude", question=2, unit="mm", points=2,
                misconceptions=(
                    Misconception("rpm used as rad/s", lambda p: amplitude(p, p.n * 60 / (2 * np.pi)),
                                  "Convert the speed to rad/s: Omega = 2 pi n / 60."),
                    Misconception("static deflection m_u e Omega^2 / k", lambda p: p.m_u * p.e * p.n**2 / p.k,
                                  "The force m_u e Omega^2 is amplified by V(eta, zeta)."),
                )),
        Numeric("F_T", "transmitted force amplitude", question=3, unit="N", points=2,
                misconceptions=(
                    Misconception("spring force only", lambda p: p.k * amplitude(p),
                                  "The damper also passes c Omega X, out of phase with the spring force."),
                    Misconception("the unbalance force", lambda p: p.m_u * p.e * p.n**2,
                                  "The mounting changes the force: F_T = TR m_u e Omega^2."),
                )),
    ),
)
