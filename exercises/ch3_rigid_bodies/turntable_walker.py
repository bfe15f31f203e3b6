"""A person walking outward on a turning turntable: absolute acceleration in the rotating
frame (Section 3.4.2)."""

import numpy as np

from dynagrade.exercise import (Constraint, Exercise, Misconception, Numeric, Uniform, Vector,
                                per_draw)
from dynagrade.exercise.checks import Recompute
from dynagrade.mechanics import frames, particle


@per_draw
def _acceleration(p):
    """Absolute acceleration, components along e_r, e_phi, e_3 of the rotating frame."""
    return frames.absolute_acceleration(np.zeros(3), [0, 0, p.Omega], [0, 0, p.Omega_dot],
                                        [p.r, 0, 0], [p.u, 0, 0], [p.a_rel, 0, 0])


def solve(p):
    a = _acceleration(p)
    return {"a": a[:2], "F": float(np.linalg.norm(particle.resultant_force(p.m, a)))}


def _without_coriolis(p):
    """The wrong route: the Coriolis term left out."""
    return _acceleration(p) - frames.coriolis_acceleration([0, 0, p.Omega], [p.u, 0, 0])


def _polar_acceleration(p, solved):
    """Polar components, eq. (1.33), with r' = u, r'' = a_rel, phi' = Omega:
    (a_rel - r Omega^2, 2 u Omega + r Omega')."""
    return (p.a_rel - p.r * p.Omega**2, 2 * p.u * p.Omega + p.r * p.Omega_dot)


EXERCISE = Exercise(
    id="turntable-walker",
    title="Walking outward on a turntable",
    source="Section 3.4.2",
    topics=("rotating frames", "Coriolis acceleration", "centripetal acceleration"),
    params=(
        Uniform("m", 40, 100, step=5, unit="kg", symbol="m"),
        Uniform("r", 0.5, 4.0, step=0.1, unit="m", symbol="r"),
        Uniform("u", 0.5, 2.0, step=0.1, unit="m/s", symbol="u"),
        Uniform("a_rel", 0.0, 1.0, step=0.1, unit="m/s^2", symbol="a_{rel}"),
        Uniform("Omega", 0.3, 2.0, step=0.05, unit="rad/s", symbol=r"\Omega"),
        Uniform("Omega_dot", 0.0, 0.5, step=0.05, unit="rad/s^2", symbol=r"\dot\Omega"),
    ),
    constraints=(
        Constraint("the Coriolis term changes the result noticeably",
                   lambda p: 2 * p.Omega * p.u > 0.1 * np.linalg.norm(_acceleration(p))),
        Constraint("the result is not dominated by a near-zero radial part",
                   lambda p: abs(_acceleration(p)[0]) > 0.05),
    ),
    statement=r"""
A person of mass $m$ = {{ m }} walks radially outward on a turntable. At the instant
considered the person is at $r$ = {{ r }} from the axis, walks with $u$ = {{ u }} relative
to the turntable and speeds up at $a_{rel}$ = {{ a_rel }} (relative, along the radius).
The turntable turns counter-clockwise with $\Omega$ = {{ Omega }} and speeds up at
$\dot\Omega$ = {{ Omega_dot }}. Use the turntable's radial and circumferential unit
vectors $e_r$, $e_\varphi$ at the person's position.

1. What is the person's absolute acceleration (components along $e_r$, $e_\varphi$)?
2. What is the magnitude of the horizontal force the floor must exert on the person?
""",
    solution=r"""
The person's motion is known relative to the turning turntable, so the absolute
acceleration follows from the acceleration formula for a rotating frame
(Section 3.4.2), with the origin on the fixed axis:
$$a = \dot\Omega\times r + \Omega\times(\Omega\times r) + 2\,\Omega\times v_{\mathrm{rel} } + a_{\mathrm{rel} } .$$
Here $r = r\,e_r$, $v_{\mathrm{rel} } = u\,e_r$, $a_{\mathrm{rel} } = a_{rel}\,e_r$,
$\Omega = \Omega\,e_3$, with $r$ = {{ r }}, $u$ = {{ u }}, $a_{rel}$ = {{ a_rel }},
$\Omega$ = {{ Omega }} and $\dot\Omega$ = {{ Omega_dot }}.

1. **Absolute acceleration.** Term by term: $\dot\Omega\times r = \dot\Omega r\,e_\varphi$
   (the turntable speeds up), $\Omega\times(\Omega\times r) = -\Omega^2 r\,e_r$
   (centripetal), $2\Omega\times v_{\mathrm{rel} } = 2\Omega u\,e_\varphi$ (Coriolis) and
   $a_{rel}\,e_r$. Collected:
   $$a = \bigl(a_{rel} - \Omega^2 r\bigr)\,e_r + \bigl(\dot\Omega r + 2\Omega u\bigr)\,e_\varphi,$$
   that is $a$ = {{ answers.a }}.
2. **Floor force.** By the balance of linear momentum the floor's horizontal force
   provides all of it (gravity and the vertical reaction cancel): $F = m\,|a|$ with
   $m$ = {{ m }}, so $F$ = {{ answers.F }}. Its circumferential part, which includes the
   Coriolis term, is what pushes the walker sideways.
""",
    solve=solve,
    checks=(
        Recompute("a", _polar_acceleration, name="polar_coordinates"),
        Recompute("F", lambda p, s: p.m * np.hypot(*_polar_acceleration(p, s)),
                  name="momentum_balance"),
    ),
    parts=(
        Vector("a", "absolute acceleration", question=1, unit="m/s^2", size=2, points=3, atol=0.01,
               misconceptions=(
                   Misconception("Coriolis term forgotten", lambda p: _without_coriolis(p)[:2],
                                 "Walking in a rotating frame adds 2 Ω × v_rel along e_φ."),
               )),
        Numeric("F", "horizontal floor force", question=2, unit="N", points=1,
                misconceptions=(
                    Misconception("Coriolis term forgotten",
                                  lambda p: p.m * float(np.linalg.norm(_without_coriolis(p))),
                                  "The floor must also supply m · 2 Ω u along e_φ."),
                )),
    ),
)
