"""Eastward deflection of a body dropped from a tower: the Coriolis term of the Earth's
rotation (Section 3.4.3)."""

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric,
                                Symbolic, Uniform)
from dynagrade.exercise.checks import Integrated, Recompute
from dynagrade.mechanics import frames, kinematics


def solve(p):
    return {"d": frames.eastward_deflection_of_falling_body(p.h, p.lat, p.Omega_E, p.g),
            "t_fall": kinematics.time_from_rest_over_distance(p.h, p.g)}


def _falling_on_earth(t, y, p):
    """The fall in the Earth's rotating frame (Section 3.4.3) with east, north, up axes:
    a = -g e_up - 2 Omega x v, Omega = Omega_E (0, cos(lat), sin(lat)); the centrifugal
    term is in g."""
    ve, vn, vu = y[3], y[4], y[5]
    wn, wu = p.Omega_E * np.cos(p.lat), p.Omega_E * np.sin(p.lat)
    cross = (wn * vu - wu * vn, wu * ve, -wn * ve)
    return (ve, vn, vu, -2 * cross[0], -2 * cross[1], -p.g - 2 * cross[2])


EXERCISE = Exercise(
    id="coriolis-falling-body",
    title="Coriolis deflection of a falling body",
    source="Section 3.4.3",
    topics=("rotating frames", "Coriolis force"),
    params=(
        Uniform("h", 50, 500, step=10, unit="m", symbol="h"),
        Uniform("lat", 5, 75, step=1, unit="deg", symbol=r"\lambda"),
        Constant("Omega_E", 7.292e-5, unit="rad/s", symbol=r"\Omega_E"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("the latitude is clear of 45 degrees, where sin and cos agree",
                   lambda p: abs(p.lat - np.pi / 4) > np.radians(4)),
    ),
    statement=r"""
A stone is dropped from rest from a tower of height $h$ = {{ h }} at latitude
$\lambda$ = {{ lat }}. The Earth turns with $\Omega_E$ = {{ Omega_E }}; $g$ = {{ g }}
(the centrifugal part included). Neglect air drag.

1. How far east of the foot of the plumb line does the stone land (to first order in
   $\Omega_E$)?
2. Give this deflection as a formula in $\Omega_E$, $g$, $h$ and $\lambda$.
""",
    solution=r"""
In the frame of the rotating Earth the falling stone feels the Coriolis acceleration
$-2\,\Omega_E\times v_{\mathrm{rel} }$ (relative motion in a rotating frame, Section 3.4.3).
To first order in $\Omega_E$ we use the fall velocity of the non-rotating problem,
$v = g t$ downward.

1. **Deflection.** Only the component $\Omega_E\cos\lambda$ of the Earth's rate normal to
   the vertical turns a vertical velocity; the Coriolis acceleration points east and grows
   with the fall speed:
   $$\ddot x_{\mathrm{east} } = 2\,\Omega_E\cos\lambda\; g\,t .$$
   Integrating twice from rest, $x_{\mathrm{east} }(t) = \tfrac{1}{3}\,\Omega_E\,g\cos\lambda\;t^3$.
   The fall lasts $t_f = \sqrt{2h/g}$ = {{ si.t_fall }} s, so with $h$ = {{ h }},
   $\lambda$ = {{ lat }}, $\Omega_E$ = {{ Omega_E }} and $g$ = {{ g }}
   $$d = \tfrac{1}{3}\,\Omega_E\,g\cos\lambda\;t_f^{\,3},$$
   and the stone lands $d$ = {{ answers.d }} east of the plumb line.
2. **As a formula.** Inserting $t_f$:
   $$d = \frac{\Omega_E\,g\cos\lambda}{3}\left(\frac{2h}{g}\right)^{3/2},$$
   written as `{{ answers.d_formula }}`.
""",
    solve=solve,
    checks=(
        Integrated("d", _falling_on_earth, lambda p: (0.0,) * 6, lambda p, s: 2 * np.sqrt(2 * p.h / p.g),
                   lambda t, y, p: y[0], name="integrated_fall",
                   event=lambda t, y, p: y[2] + p.h, direction=-1, rtol=1e-4),
        Recompute("t_fall", lambda p, s: np.sqrt(2 * p.h / p.g), name="free_fall_time"),
    ),
    parts=(
        Numeric("d", "eastward deflection", question=1, unit="mm", points=2,
                misconceptions=(
                    Misconception("sin of the latitude",
                                  lambda p: frames.eastward_deflection_of_falling_body(
                                      p.h, np.pi / 2 - p.lat, p.Omega_E, p.g),
                                  "Only the component Ω_E cos λ normal to the vertical "
                                  "deflects a vertical velocity."),
                    Misconception("Coriolis acceleration at its final value throughout",
                                  lambda p: 1.5 * frames.eastward_deflection_of_falling_body(
                                      p.h, p.lat, p.Omega_E, p.g),
                                  "The Coriolis acceleration 2 Ω_E cos λ g t grows with the "
                                  "fall speed: integrate it twice."),
                )),
        Symbolic("d_formula", "deflection as a formula", question=2, points=1,
                 expected="Omega_E*g*cos(lat)*(2*h/g)^(3/2)/3",
                 variables=("Omega_E", "g", "h", "lat"),
                 equals="d",
                 misconceptions=(
                     Misconception("sin of the latitude", "Omega_E*g*sin(lat)*(2*h/g)^(3/2)/3",
                                   "Only Ω_E cos λ deflects a vertical velocity."),
                 )),
    ),
)
