"""A bead sliding on a rod that spins in a horizontal plane: centrifugal and Coriolis terms
in the rotating frame (Section 3.4.3)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, apart
from dynagrade.exercise.checks import Integrated, Recompute
from dynagrade.mechanics import frames


def solve(p):
    rdot = frames.bead_radial_speed(p.t, p.r0, 0.0, p.Omega)
    return {
        "r_t": frames.bead_radial_position(p.t, p.r0, 0.0, p.Omega),
        "rdot_t": rdot,
        "N": frames.bead_normal_force(p.m, p.Omega, rdot),
    }


def _on_the_rod(t, y, p):
    """The bead's radial equation in the rod's rotating frame (Section 3.4.3): no force
    along the smooth rod, so r'' = Omega^2 r."""
    return (y[1], p.Omega**2 * y[0])


def _at_rest_on_the_rod(p):
    """At r0, at rest relative to the rod."""
    return (p.r0, 0.0)


def _until_t(p, solved):
    return p.t


EXERCISE = Exercise(
    id="bead-on-rotating-rod",
    title="Bead on a rotating rod",
    source="Section 3.4.3",
    topics=("rotating frames", "Coriolis force", "centrifugal force"),
    params=(
        Uniform("m", 0.05, 0.5, step=0.01, unit="kg", symbol="m"),
        Uniform("Omega", 1.0, 6.0, step=0.25, unit="rad/s", symbol=r"\Omega"),
        Uniform("r0", 0.05, 0.3, step=0.01, unit="m", symbol="r_0"),
        Uniform("t", 0.2, 1.5, step=0.05, unit="s", symbol="t"),
    ),
    constraints=(
        # two answers that agree as numbers can be swapped and score (verify's variety rule)
        Constraint("the radial speed and the normal force differ as numbers",
                   lambda p: apart(solve(p)["rdot_t"], solve(p)["N"])),
        Constraint("the bead is still on a 1.5 m rod at time t",
                   lambda p: frames.bead_radial_position(p.t, p.r0, 0.0, p.Omega) < 1.5),
        Constraint("the bead has moved well beyond the start (Omega t > 1.1), where r0 cosh differs "
                   "from a uniform acceleration", lambda p: p.Omega * p.t > 1.1),
    ),
    statement=r"""
A rod turns in a horizontal plane about a vertical axis through its end O with the
constant rate $\Omega$ = {{ Omega }}. A bead of mass $m$ = {{ m }} slides on it without
friction. At $t = 0$ the bead is at $r_0$ = {{ r0 }} from O and at rest relative to the rod.
Gravity is carried by the rod's vertical reaction and plays no further part.

1. How far from O is the bead at $t$ = {{ t }}?
2. How fast does it slide along the rod then?
3. How large is the horizontal force of the rod on the bead then?
""",
    solution=r"""
Describe the bead in the frame that turns with the rod (relative motion in a rotating
frame, Section 3.4.3). Along the frictionless rod only the centrifugal term acts; normal
to the rod, in the horizontal plane, the rod must supply the Coriolis term.

1. **Motion along the rod.** The radial balance in the rotating frame reads
   $m\ddot r = m\Omega^2 r$, i.e. $\ddot r - \Omega^2 r = 0$. With $r(0) = r_0$ and
   $\dot r(0) = 0$ its solution is
   $$r(t) = r_0\cosh(\Omega t).$$
   With $r_0$ = {{ r0 }}, $\Omega$ = {{ Omega }} and $t$ = {{ t }}:
   $r(t)$ = {{ answers.r_t }}.
2. **Sliding speed.** Differentiating,
   $$\dot r(t) = r_0\,\Omega\sinh(\Omega t),$$
   so the bead slides outward at $\dot r$ = {{ answers.rdot_t }}.
3. **Force of the rod.** Normal to the rod the relative acceleration is zero, so the rod's
   force balances the Coriolis term $2m\,\Omega\times v_{\mathrm{rel} }$:
   $$N = 2m\,\Omega\,\dot r,$$
   and with $m$ = {{ m }} the rod pushes with $N$ = {{ answers.N }},
   forward in the sense of rotation. The centrifugal term is along the rod and needs no force there.
""",
    solve=solve,
    checks=(
        Integrated("r_t", _on_the_rod, _at_rest_on_the_rod, _until_t,
                   lambda t, y, p: y[0], name="integrated_position"),
        Integrated("rdot_t", _on_the_rod, _at_rest_on_the_rod, _until_t,
                   lambda t, y, p: y[1], name="integrated_speed"),
        # the rod supplies the Coriolis force across it: N = 2 m Omega r'
        Recompute("N", lambda p, s: 2 * p.m * p.Omega * s["rdot_t"], name="coriolis_force"),
    ),
    parts=(
        Numeric("r_t", "distance from O", question=1, unit="m", points=2,
                misconceptions=(
                    Misconception("uniform acceleration r0 Omega^2",
                                  lambda p: p.r0 + 0.5 * p.r0 * p.Omega**2 * p.t**2,
                                  "The centrifugal term Ω² r grows with r: r'' = Ω² r gives "
                                  "r = r0 cosh(Ω t)."),
                )),
        Numeric("rdot_t", "sliding speed", question=2, unit="m/s", points=1,
                misconceptions=(
                    Misconception("speed of the rod point at r0", lambda p: p.r0 * p.Omega,
                                  "That is the circumferential speed at r0, not the speed "
                                  "along the rod."),
                )),
        Numeric("N", "force of the rod", question=3, unit="N", points=2,
                misconceptions=(
                    Misconception("centripetal force instead of Coriolis",
                                  lambda p: p.m * p.Omega**2 * solve(p)["r_t"],
                                  "Along the rod nothing pushes (frictionless); normal to it "
                                  "the rod supplies the Coriolis term 2 m Ω ṙ."),
                    Misconception("Coriolis term without the factor 2",
                                  lambda p: p.m * p.Omega * solve(p)["rdot_t"],
                                  "The Coriolis acceleration is 2 Ω × v_rel."),
                )),
    ),
)
