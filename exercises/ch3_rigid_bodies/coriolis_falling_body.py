"""Eastward deflection of a body dropped from a tower: the Coriolis term of the Earth's
rotation (Section 3.4.3)."""

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric,
                                Symbolic, Uniform)
from dynagrade.mechanics import frames


def solve(p):
    return {"d": frames.eastward_deflection_of_falling_body(p.h, p.lat, p.Omega_E, p.g)}


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
    solve=solve,
    parts=(
        Numeric("d", "eastward deflection", unit="mm", points=2,
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
        Symbolic("d_formula", "deflection as a formula", points=1,
                 expected="Omega_E*g*cos(lat)*(2*h/g)^(3/2)/3",
                 variables=("Omega_E", "g", "h", "lat"),
                 equals="d",
                 misconceptions=(
                     Misconception("sin of the latitude", "Omega_E*g*sin(lat)*(2*h/g)^(3/2)/3",
                                   "Only Ω_E cos λ deflects a vertical velocity."),
                 )),
    ),
)
