"""A mass held by a spring in a radial slot of a turning disk: relative equilibrium,
oscillation seen on the disk and the Coriolis force of the slot's wall (Section 3.4.3)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.apart import numbers_apart
from dynagrade.exercise.checks import Balance, Integrated, Limit
from dynagrade.exercise.figure import (Circle, Rectangle, block, describe,
                                       new_drawing, spring)
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import frames


@per_draw
def solve(p):
    r_e = frames.spring_slot_equilibrium_radius(p.k, p.m, p.l0, p.Omega)
    omega_rel = frames.spring_slot_relative_frequency(p.k, p.m, p.Omega)
    amplitude = r_e - p.l0
    return {
        "r_e": r_e,
        "omega_rel": omega_rel,
        "N_max": abs(frames.bead_normal_force(p.m, p.Omega, amplitude * omega_rel)),
        "amplitude": amplitude,
        "speed_max": amplitude * omega_rel,
    }


def _spring_holds(p):
    return 0.15 * p.k < p.m * p.Omega**2 < 0.75 * p.k


def _radial_motion(t, y, p):
    """The relative motion in the slot: m r'' = -k (r - l0) + m Omega^2 r (Section 3.4.3)."""
    return (y[1], -p.k / p.m * (y[0] - p.l0) + p.Omega**2 * y[0])


def _net_radial_force(t, y, p):
    """Zero where the spring just balances the centrifugal term: the fastest point."""
    return -p.k * (y[0] - p.l0) + p.m * p.Omega**2 * y[0]


def figure(p):
    """Top view, schematic: the disk turning counter-clockwise, the radial slot, the spring
    from the axis to the mass (Section 3.4.3)."""
    drawing, axes = new_drawing(4.2, 3.6)
    axes.add_patch(Circle((0.0, 0.0), 1.0, facecolor="#eeeeee", edgecolor="0.3", lw=1.0))
    axes.add_patch(Rectangle((0.0, -0.06), 0.95, 0.12, facecolor="white", edgecolor="0.2",
                             lw=1.0))
    axes.plot([0.0], [0.0], "o", color="0.1", ms=4)
    spring(axes, (0.0, 0.0), (0.5, 0.0), coils=6, width=0.07)
    block(axes, (0.56, 0.0), 0.12, 0.1, color="C0")
    axes.text(0.25, 0.1, f"k = {format_number(p.k)} N/m", ha="center", va="bottom",
              fontsize=10)
    axes.text(0.56, -0.12, f"m = {format_number(p.m)} kg", ha="center", va="top", fontsize=10)
    # the turn's sense: a counter-clockwise arrow along the arc (a bare arc shows none)
    axes.annotate("", xy=(1.12 * np.cos(0.6 * np.pi), 1.12 * np.sin(0.6 * np.pi)),
                  xytext=(1.12 * np.cos(0.3 * np.pi), 1.12 * np.sin(0.3 * np.pi)),
                  arrowprops={"arrowstyle": "-|>", "connectionstyle": "arc3,rad=0.25",
                              "color": "0.2", "lw": 1.0, "shrinkA": 0, "shrinkB": 0})
    axes.text(0.0, 1.3, f"Ω = {format_number(p.Omega)} rad/s", ha="center", va="center", fontsize=10)
    axes.text(-0.6, -0.55, f"l₀ = {format_number(p.l0)} m", ha="center", va="center",
              fontsize=10)
    describe(axes, "Seen from above: the disk turns counter-clockwise about its centre; the "
                   "spring runs along the radial slot from the axis to the mass.")
    axes.set_xlim(-1.2, 1.5)
    axes.set_ylim(-1.15, 1.45)
    return drawing


EXERCISE = Exercise(
    id="spring-mass-in-turning-slot",
    title="A spring-held mass in the slot of a turning disk",
    source="Section 3.4.3",
    topics=("non-inertial frames", "centrifugal term", "Coriolis force"),
    params=(
        Uniform("m", 0.2, 2.0, step=0.1, unit="kg", symbol="m"),
        Uniform("k", 20.0, 200.0, step=5.0, unit="N/m", symbol="k"),
        Uniform("l0", 0.1, 0.5, step=0.02, unit="m", symbol="l_0"),
        Uniform("Omega", 1.0, 15.0, step=0.5, unit="rad/s", symbol=r"\Omega"),
    ),
    constraints=(
        Constraint("the spring can hold the mass: m Omega^2 between 0.15 k and 0.75 k",
                   _spring_holds),
        Constraint("the three answers differ by over 5 %",
                   lambda p: _spring_holds(p) and numbers_apart(
                       [solve(p)[k] for k in ("r_e", "omega_rel", "N_max")])),
    ),
    statement=r"""
A disk turns in a horizontal plane about its vertical axis with the constant rate
$\Omega$ = {{ Omega }}. A mass $m$ = {{ m }} slides without friction in a long radial slot
of the disk; a spring of stiffness $k$ = {{ k }} and unstretched length $l_0$ = {{ l0 }}
joins it to the axis.

1. At which distance from the axis does the mass stay at rest relative to the disk?
2. With which angular frequency does it oscillate along the slot, seen on the disk,
   when disturbed from there?
3. The mass is released at $r = l_0$ at rest relative to the disk. How large is the
   largest horizontal force the slot's wall exerts on it in the motion that follows?
""",
    solution=r"""
In the disk's frame (turning at $\Omega$, $\dot\Omega = 0$, origin on the axis) the balance
of linear momentum holds with the fictitious forces $-m\,\Omega\times(\Omega\times r)$
(centrifugal) and $-2m\,\Omega\times v_{rel}$ (Coriolis) (non-inertial frames,
Section 3.4.3). Along the slot: spring and centrifugal term; across it: the wall's force
$N$ and the Coriolis term,
$$m\ddot r = -k\,(r - l_0) + m\,\Omega^2 r,\qquad N = 2 m\,\Omega\,\dot r .$$

1. **Relative equilibrium.** $\ddot r = 0$: $k(r_e - l_0) = m\Omega^2 r_e$, so
   $$r_e = \frac{k\,l_0}{k - m\Omega^2}$$
   = {{ answers.r_e }}, further out than $l_0$ = {{ l0 }}.
2. **Oscillation.** With $r = r_e + x$: $m\ddot x = -(k - m\Omega^2)\,x$, so
   $\omega_{rel} = \sqrt{k/m - \Omega^2}$ = {{ answers.omega_rel }}: the centrifugal
   term softens the spring.
3. **Wall force.** Released at $l_0$ at rest on the disk, the mass oscillates about $r_e$
   with the amplitude $r_e - l_0$ = {{ si.amplitude }} m; it is fastest as it passes
   $r_e$, $\dot r_{\max} = (r_e - l_0)\,\omega_{rel}$ = {{ si.speed_max }} m/s. The wall
   must supply the Coriolis term, so
   $N_{\max} = 2 m\,\Omega\,\dot r_{\max}$ = {{ answers.N_max }}.

**Check.** A disk at rest ($\Omega \to 0$) leaves a plain spring oscillator:
$\sqrt{k/m}$ = {{ checks.disk_at_rest }} rad/s, faster than {{ answers.omega_rel }}.
""",
    solve=solve,
    checks=(
        # seen from the fixed frame: the spring pulls the mass round its circle
        Balance("centripetal force at r_e", lambda p, s: p.k * (s["r_e"] - p.l0),
                lambda p, s: p.m * p.Omega**2 * s["r_e"], name="spring_pulls_round"),
        # the radial equation integrated from r = l0 at rest to where the net radial force
        # vanishes (fastest point); the wall gives 2 m Omega r'
        Integrated("N_max", _radial_motion, lambda p: (p.l0, 0.0),
                   lambda p, s: 10 / s["omega_rel"], lambda t, y, p: 2 * p.m * p.Omega * y[1],
                   name="integrated_wall_force", event=_net_radial_force, direction=-1,
                   rtol=1e-5),
        Limit("omega_rel", {"Omega": 0.0}, lambda p: np.sqrt(p.k / p.m), name="disk_at_rest"),
    ),
    figure=figure,
    parts=(
        Numeric("r_e", "radius of relative rest", question=1, unit="m", points=2,
                misconceptions=(
                    Misconception("centrifugal term with the wrong sign",
                                  lambda p: p.k * p.l0 / (p.k + p.m * p.Omega**2),
                                  "On the disk the centrifugal term m Ω² r pulls outward: "
                                  "k (r − l0) = m Ω² r."),
                )),
        Numeric("omega_rel", "angular frequency along the slot", question=2, unit="rad/s",
                points=1,
                misconceptions=(
                    Misconception("rotation ignored", lambda p: np.sqrt(p.k / p.m),
                                  "The centrifugal term m Ω² r grows with r and softens the "
                                  "spring: ω_rel² = k/m − Ω²."),
                    Misconception("centrifugal term stiffens", lambda p: np.sqrt(p.k / p.m
                                                                                 + p.Omega**2),
                                  "The centrifugal term pushes outward as r grows: it "
                                  "subtracts, ω_rel² = k/m − Ω²."),
                )),
        Numeric("N_max", "largest force of the slot's wall", question=3, unit="N", points=2,
                misconceptions=(
                    Misconception("factor 2 of the Coriolis term forgotten",
                                  lambda p: solve(p)["N_max"] / 2,
                                  "The Coriolis term is 2 m Ω × v_rel."),
                    Misconception("centrifugal force at r_e",
                                  lambda p: p.m * p.Omega**2 * solve(p)["r_e"],
                                  "The centrifugal term acts along the slot and is taken by "
                                  "the spring; across the slot acts the Coriolis term "
                                  "2 m Ω ṙ.",
                                  applies=lambda p: abs(solve(p)["N_max"]
                                                        / (p.m * p.Omega**2 * solve(p)["r_e"])
                                                        - 1) > 0.03),
                )),
    ),
)
