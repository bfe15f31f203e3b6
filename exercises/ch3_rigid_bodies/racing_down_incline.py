"""Solid cylinder, sphere (solid or thin-walled, drawn) and hoop racing down an incline,
rolling without slipping (Section 3.2.1)."""

import numpy as np

from dynagrade.exercise import (Choice, Constant, Exercise, Misconception, Numeric, Options,
                                Symbolic, Uniform)
from dynagrade.exercise.checks import Balance, Recompute
from dynagrade.mechanics import inertia, kinematics, rigid_kinetics


def _sphere_moment(p, hollow):
    """The sphere's moment of inertia about its centre: a thin-walled shell (hollow = 1)
    or a solid ball (hollow = 0)."""
    tensor = inertia.inertia_tensor_spherical_shell if hollow else inertia.inertia_tensor_sphere
    return tensor(p.m, p.R)[2, 2]


def _moments(p):
    """Axial moments of inertia about the centre of the three bodies."""
    return {
        "cylinder": inertia.inertia_tensor_cylinder(p.m, p.R, p.R)[2, 2],
        "sphere": _sphere_moment(p, p.hollow),
        "hoop": inertia.inertia_tensor_hoop(p.m, p.R)[2, 2],
    }


def _sphere_ratio(p):
    """I_C/(m R^2) of the sphere raced: 2/3 for a thin shell, 2/5 for a solid ball."""
    return 2 / 3 if p.hollow else 2 / 5


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
        "a_sphere": _acceleration(p, "sphere"),
        "a_hoop": _acceleration(p, "hoop"),
        "t_cylinder": times["cylinder"],
        "t_hoop": times["hoop"],
        "height": height,
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
        # which sphere races decides which body wins (the sphere or the cylinder)
        Choice("hollow", (0, 1), symbol="hollow"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    statement=r"""
A homogeneous solid cylinder, {% if hollow.number %}a thin-walled hollow sphere{% else %}a
homogeneous solid sphere{% endif %} and a thin-walled hoop, each of
mass $m$ = {{ m }} and radius $R$ = {{ R }}, are released together from rest on an incline
of angle $\alpha$ = {{ alpha }} and roll down without slipping ($g$ = {{ g }}).

1. What is the acceleration of the cylinder's centre?
2. How long does the sphere take to roll the distance $s$ = {{ s }} along the incline?
3. How fast is the hoop's centre after rolling that distance?
4. Which smallest coefficient of static friction lets the cylinder roll without slipping?
5. Which body arrives first at the end of the distance $s$?
6. Give the cylinder's acceleration as a formula in $g$ and $\alpha$.
""",
    solution=r"""
Each body rolls without slipping, so $v = \omega R$. The balance of linear momentum along
the incline, $m a = m g\sin\alpha - F$, and the balance of angular momentum about the
centre, $I_C\,\dot\omega = F R$ with $\dot\omega = a/R$, give (rolling on an incline,
Section 3.2.1)
$$a = \frac{g\sin\alpha}{1 + I_C/(m R^2)},\qquad F = \frac{I_C}{R^2}\,a .$$
The three bodies differ only in $I_C/(mR^2)$: ½ for the cylinder,
{% if answers.first == "cylinder" %}2/3 for the thin-walled sphere{% else %}2/5 for the solid
sphere{% endif %} and 1 for the hoop. Here $m$ = {{ m }}, $R$ = {{ R }}, $\alpha$ = {{ alpha }}, $g$ = {{ g }}.

1. **Cylinder.** $a_{\mathrm{cyl} } = \frac{g\sin\alpha}{1 + 1/2} = \tfrac{2}{3} g\sin\alpha$,
   so $a_{\mathrm{cyl} }$ = {{ answers.a_cyl }}.
2. **Time of the sphere.** $a_{\mathrm{sph} } = {% if answers.first == "cylinder" %}\tfrac{3}{5}{% else %}\tfrac{5}{7}{% endif %} g\sin\alpha$ = {{ si.a_sphere }} m/s².
   From rest at constant acceleration $s = \tfrac{1}{2} a t^2$, so over $s$ = {{ s }}
   $$t = \sqrt{\frac{2 s}{a_{\mathrm{sph} } } },$$
   that is $t$ = {{ answers.t_sphere }}.
3. **Speed of the hoop.** The work-energy balance: the hoop drops $h = s\sin\alpha$ =
   {{ si.height }} m, and its kinetic energy is $\tfrac{1}{2} m v^2 + \tfrac{1}{2} m R^2 (v/R)^2 = m v^2$:
   $$m g h = m v^2 \quad\Rightarrow\quad v = \sqrt{g h},$$
   so $v$ = {{ answers.v_hoop }}.
4. **Friction for the cylinder.** Rolling needs $F = \frac{I_C}{R^2} a = \tfrac{1}{3} m g\sin\alpha$,
   and static friction can supply at most $\mu N = \mu\, m g\cos\alpha$:
   $$\mu \ge \frac{F}{m g\cos\alpha} = \tfrac{1}{3}\tan\alpha,$$
   so $\mu_{\min}$ = {{ answers.mu_min }}.
5. **Who arrives first.** The smallest $I_C/(mR^2)$ gives the largest acceleration and the
   shortest time: $a_{\mathrm{sph} }$ = {{ si.a_sphere }} m/s², $a_{\mathrm{cyl} }$ =
   {{ answers.a_cyl }} and $a_{\mathrm{hoop} }$ = {{ si.a_hoop }} m/s², with the times
   {{ answers.t_sphere }}, {{ si.t_cylinder }} s and {{ si.t_hoop }} s. First:
   **{{ answers.first }}**, whatever $m$, $R$ and $\alpha$: only the shape counts
   ({% if answers.first == "cylinder" %}a thin shell carries its mass at $R$, which the
   solid cylinder does not{% else %}a solid ball carries more of its mass near the axis
   than the cylinder{% endif %}).
6. **As a formula.** From step 1, $a_{\mathrm{cyl} }$ = `{{ answers.a_cyl_formula }}`.
""",
    solve=solve,
    checks=(
        # rolling without slip, I = k m R^2: a = g sin(alpha) / (1 + k) (Section 3.2.1)
        Recompute("a_cyl", lambda p, s: p.g * np.sin(p.alpha) / (1 + 1 / 2), name="cylinder_k_half"),
        Recompute("t_sphere",
                  lambda p, s: np.sqrt(2 * p.s / (p.g * np.sin(p.alpha) / (1 + _sphere_ratio(p)))),
                  name="sphere_k_two_fifths_or_two_thirds"),
        # energy: m g h = m v^2 / 2 + (m R^2)(v / R)^2 / 2 = m v^2 for the hoop
        Balance("energy per unit mass", lambda p, s: p.g * p.s * np.sin(p.alpha),
                lambda p, s: s["v_hoop"]**2, name="hoop_energy"),
        Recompute("mu_min", lambda p, s: np.tan(p.alpha) / 3, name="cylinder_friction"),
    ),
    parts=(
        Numeric("a_cyl", "acceleration of the cylinder", question=1, unit="m/s^2", points=2,
                misconceptions=(
                    Misconception("sliding without friction", lambda p: p.g * np.sin(p.alpha),
                                  "Part of the weight's work goes into rotation: "
                                  "a = g sin α / (1 + I_C/(m R²))."),
                    Misconception("moment of inertia of a hoop (m R^2) used",
                                  lambda p: p.g * np.sin(p.alpha) / 2,
                                  "A solid cylinder has I_C = ½ m R², so a = (2/3) g sin α."),
                )),
        Numeric("t_sphere", "time of the sphere", question=2, unit="s", points=1,
                misconceptions=(
                    Misconception("rotation forgotten",
                                  lambda p: np.sqrt(2 * p.s / (p.g * np.sin(p.alpha))),
                                  "The sphere also spins: a = g sin α / (1 + I_C/(m R²))."),
                    Misconception("solid and hollow sphere confused",
                                  lambda p: kinematics.time_from_rest_over_distance(
                                      p.s, rigid_kinetics.rolling_acceleration_on_incline(
                                          p.alpha, p.g, p.m, p.R,
                                          _sphere_moment(p, 1 - p.hollow))),
                                  "A solid ball has I_C = (2/5) m R², a thin shell "
                                  "(2/3) m R²."),
                )),
        Numeric("v_hoop", "speed of the hoop", question=3, unit="m/s", points=1,
                misconceptions=(
                    Misconception("rotational kinetic energy forgotten",
                                  lambda p: np.sqrt(2 * p.g * p.s * np.sin(p.alpha)),
                                  "The hoop's kinetic energy is half translation, half "
                                  "rotation: m g h = m v²."),
                )),
        Numeric("mu_min", "smallest friction coefficient", question=4, points=1,
                misconceptions=(
                    Misconception("friction equal to the weight component",
                                  lambda p: np.tan(p.alpha),
                                  "The friction force is I_C a / R², only a third of "
                                  "m g sin α for the cylinder."),
                )),
        Options("first", "first to arrive", question=5,
                options=("cylinder", "sphere", "hoop"), points=1),
        Symbolic("a_cyl_formula", "acceleration of the cylinder as a formula", question=6, points=1,
                 expected="2/3*g*sin(alpha)",
                 variables=("g", "alpha"),
                 equals="a_cyl",
                 misconceptions=(
                     Misconception("sliding without friction", "g*sin(alpha)",
                                   "Part of the work goes into rotation."),
                 )),
    ),
)
