"""Solid cylinder, solid sphere and hoop racing down an incline, rolling without slipping
(Section 3.2.1)."""

import numpy as np

from dynagrade.exercise import (Constant, Exercise, Misconception, Numeric, Options, Symbolic,
                                Uniform)
from dynagrade.mechanics import inertia, kinematics, rigid_kinetics


def _moments(p):
    """Axial moments of inertia about the centre of the three bodies."""
    return {
        "cylinder": inertia.inertia_tensor_cylinder(p.m, p.R, p.R)[2, 2],
        "sphere": inertia.inertia_tensor_sphere(p.m, p.R)[2, 2],
        "hoop": inertia.inertia_tensor_hoop(p.m, p.R)[2, 2],
    }


def _acceleration(p, body):
    return rigid_kinetics.rolling_acceleration_on_incline(p.alpha, p.g, p.m, p.R,
                                                          _moments(p)[body])


def solve(p):
    times = {body: kinematics.time_from_rest_over_distance(p.s, _acceleration(p, body))
             for body in _moments(p)}
    height = p.s * np.sin(p.alpha)
    return {
        "a_cyl": _acceleration(p, "cylinder"),
        "t_sphere": times["sphere"],
        "v_hoop": rigid_kinetics.rolling_speed_after_drop(height, p.g, p.m, p.R,
                                                          _moments(p)["hoop"]),
        "mu_min": rigid_kinetics.minimum_friction_coefficient_for_rolling(
            p.alpha, p.g, p.m, p.R, _moments(p)["cylinder"]),
        "first": min(times, key=times.get),
    }


EXERCISE = Exercise(
    id="racing-down-incline",
    title="Cylinder, sphere and hoop racing down an incline",
    source="Section 3.2.1",
    topics=("balance of linear momentum", "balance of angular momentum",
            "rolling without slipping", "work-energy balance"),
    params=(
        Uniform("m", 0.5, 5.0, step=0.1, unit="kg", symbol="m"),
        Uniform("R", 0.05, 0.3, step=0.01, unit="m", symbol="R"),
        Uniform("alpha", 5, 40, step=1, unit="deg", symbol=r"\alpha"),
        Uniform("s", 1.0, 10.0, step=0.5, unit="m", symbol="s"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    statement=r"""
A homogeneous solid cylinder, a homogeneous solid sphere and a thin-walled hoop, each of
mass $m$ = {{ m }} and radius $R$ = {{ R }}, are released together from rest on an incline
of angle $\alpha$ = {{ alpha }} and roll down without slipping ($g$ = {{ g }}).

1. What is the acceleration of the cylinder's centre?
2. How long does the sphere take to roll the distance $s$ = {{ s }} along the incline?
3. How fast is the hoop's centre after rolling that distance?
4. Which smallest coefficient of static friction lets the cylinder roll without slipping?
5. Which body arrives first at the end of the distance $s$?
6. Give the cylinder's acceleration as a formula in $g$ and $\alpha$.
""",
    solve=solve,
    parts=(
        Numeric("a_cyl", "acceleration of the cylinder", unit="m/s^2", points=2,
                misconceptions=(
                    Misconception("sliding without friction", lambda p: p.g * np.sin(p.alpha),
                                  "Part of the weight's work goes into rotation: "
                                  "a = g sin α / (1 + I_C/(m R²))."),
                    Misconception("moment of inertia of a hoop (m R^2) used",
                                  lambda p: p.g * np.sin(p.alpha) / 2,
                                  "A solid cylinder has I_C = ½ m R², so a = (2/3) g sin α."),
                )),
        Numeric("t_sphere", "time of the sphere", unit="s", points=1,
                misconceptions=(
                    Misconception("rotation forgotten",
                                  lambda p: np.sqrt(2 * p.s / (p.g * np.sin(p.alpha))),
                                  "The sphere's acceleration is (5/7) g sin α."),
                )),
        Numeric("v_hoop", "speed of the hoop", unit="m/s", points=1,
                misconceptions=(
                    Misconception("rotational kinetic energy forgotten",
                                  lambda p: np.sqrt(2 * p.g * p.s * np.sin(p.alpha)),
                                  "The hoop's kinetic energy is half translation, half "
                                  "rotation: m g h = m v²."),
                )),
        Numeric("mu_min", "smallest friction coefficient", points=1,
                misconceptions=(
                    Misconception("friction equal to the weight component",
                                  lambda p: np.tan(p.alpha),
                                  "The friction force is I_C a / R², only a third of "
                                  "m g sin α for the cylinder."),
                )),
        Options("first", "first to arrive", options=("cylinder", "sphere", "hoop"), points=1),
        Symbolic("a_cyl_formula", "acceleration of the cylinder as a formula", points=1,
                 expected="2/3*g*sin(alpha)",
                 variables=("g", "alpha"),
                 equals="a_cyl",
                 misconceptions=(
                     Misconception("sliding without friction", "g*sin(alpha)",
                                   "Part of the work goes into rotation."),
                 )),
    ),
)
