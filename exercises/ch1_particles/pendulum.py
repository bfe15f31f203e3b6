"""A particle on a massless string as a pendulum: equation of motion with air drag and the
small-angle period (Example 1.17, eqs. 1.145-1.149)."""

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric, Symbolic,
                                Uniform, per_draw)
from dynagrade.exercise.checks import Integrated, Recompute
from dynagrade.mechanics import angular_momentum as am


@per_draw
def solve(p):
    return {
        "T": am.pendulum_small_angle_period(p.g, p.R),
        "phi_ddot": float(am.particle_pendulum_angular_acceleration(p.phi, p.phidot, p.g, p.R, p.k, p.m)),
        "S": float(am.pendulum_string_force(p.m, p.R, p.g, p.phi, p.phidot)),
        "omega_n": am.pendulum_natural_frequency(p.g, p.R),
    }


def _swing(t, y, p):
    """The undamped pendulum, eq. (1.145): phi'' = -(g/R) sin(phi)."""
    return (y[1], -p.g / p.R * np.sin(y[0]))


def _angular_acceleration(p, solved):
    """Angular momentum balance about the pivot with the drag torque, eqs. (1.143) and
    (1.148): m R phi'' = -m g sin(phi) - k R phi'."""
    return -p.g / p.R * np.sin(p.phi) - p.k / p.m * p.phidot


EXERCISE = Exercise(
    id="pendulum-with-drag",
    title="Pendulum: equation of motion and small-angle period",
    source="Example 1.17",
    topics=("angular momentum balance", "pendulum", "equation of motion", "linearization"),
    params=(
        Uniform("m", 0.1, 3.0, step=0.1, unit="kg", symbol="m"),
        Uniform("R", 0.3, 3.0, step=0.1, unit="m", symbol="R"),
        Uniform("k", 0.05, 0.5, step=0.01, unit="kg/s", symbol="k"),
        Uniform("phi", 15, 70, step=1, unit="deg", symbol=r"\varphi"),
        Uniform("phidot", 0.3, 3.0, step=0.1, unit="rad/s", symbol=r"\dot\varphi"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("the drag term is at least 5 % of the gravity term",
                   lambda p: p.k / p.m * p.phidot > 0.05 * p.g / p.R * np.sin(p.phi)),
        Constraint("the small-angle slip sin(phi) -> phi matters by 5 %",
                   lambda p: abs(p.g / p.R * (p.phi - np.sin(p.phi)))
                   > 0.05 * abs(solve(p)["phi_ddot"])),
        Constraint("the string stays taut", lambda p: solve(p)["S"] > 0),
    ),
    statement="""
A particle of mass $m$ = {{ m }} hangs from a fixed point B on a light, rigid string of
length $R$ = {{ R }}; $g$ = {{ g }}. Air drag on the particle is $\\boldsymbol F_d = -k\\boldsymbol v$ with
$k$ = {{ k }}. $\\varphi$ is the string's angle from the downward vertical.

1. What is the period of small oscillations without drag?
2. At an instant with $\\varphi$ = {{ phi }} and $\\dot\\varphi$ = {{ phidot }} (swinging
   further out), what is the angular acceleration $\\ddot\\varphi$?
3. What is the force in the string at that instant?
4. Write $\\ddot\\varphi$ as a formula in $\\varphi$ (`phi`), $\\dot\\varphi$ (`phidot`), $k$, $m$, $g$ and $R$.
""",
    solution=r"""
Use the angular momentum balance about the fixed point B, $M_B = \dot H_B$ (eq. (1.132) with
B fixed). The particle moves on a circle of radius $R$, so $H_B = mR^2\dot\varphi$ and
$\dot H_B = mR^2\ddot\varphi$ (eq. (1.140)). The string force passes through B and has no
moment; gravity has the moment $-mgR\sin\varphi$ and the drag, of size $kR\dot\varphi$
and opposite to the velocity, the moment $-kR^2\dot\varphi$. Hence (eqs. (1.145) and (1.149))
$\ddot\varphi = -\frac{k}{m}\dot\varphi - \frac{g}{R}\sin\varphi$.

1. **Small-angle period.** Without drag and with $\sin\varphi \approx \varphi$ (eq. (1.147))
   the equation is $\ddot\varphi + \frac{g}{R}\varphi = 0$: a harmonic oscillation with
   $\omega = \sqrt{g/R}$ = {{ si.omega_n }} rad/s (with $R$ = {{ R }}, $g$ = {{ g }}) and period
   $T = 2\pi/\omega = 2\pi\sqrt{R/g}$ = {{ answers.T }}. It depends neither on the mass nor on
   the amplitude.
2. **Angular acceleration.** Insert $\varphi$ = {{ phi }}, $\dot\varphi$ = {{ phidot }},
   $k$ = {{ k }}, $m$ = {{ m }} into the equation of motion: $\ddot\varphi$ = {{ answers.phi_ddot }}.
   Both terms slow the outward swing.
3. **String force.** The moment balance does not contain $S$; take the linear momentum balance
   along the string instead. The radial acceleration on the circle is $-R\dot\varphi^2$
   (towards B); the drag is perpendicular to the string. So
   $S - mg\cos\varphi = mR\dot\varphi^2$, i.e. $S = mg\cos\varphi + mR\dot\varphi^2$
   = {{ answers.S }}.
4. **Formula.** $\ddot\varphi$ = `{{ answers.eom }}`.
""",
    solve=solve,
    checks=(
        # released from rest at 0.01 rad: the swing returns to rest after one period; the
        # amplitude lengthens it by a^2/16 (6e-6) only
        Integrated("T", _swing, lambda p: (0.01, 0.0), lambda p, s: 1.5 * 2 * np.pi * np.sqrt(p.R / p.g),
                   lambda t, y, p: t, name="integrated_small_swing",
                   event=lambda t, y, p: y[1], direction=-1, rtol=1e-4),
        Recompute("phi_ddot", _angular_acceleration, name="angular_momentum_balance"),
        # radial momentum balance: S - m g cos(phi) = m R phi'^2
        Recompute("S", lambda p, s: p.m * p.R * p.phidot**2 + p.m * p.g * np.cos(p.phi),
                  name="radial_balance"),
    ),
    parts=(
        Numeric("T", "small-angle period", question=1, unit="s", points=1,
                misconceptions=(
                    Misconception("angular frequency given as the period",
                                  lambda p: am.pendulum_natural_frequency(p.g, p.R),
                                  "T = 2π/ω with ω = √(g/R)."),
                    Misconception("sqrt(g/R) upside down", lambda p: 2 * np.pi * np.sqrt(p.g / p.R),
                                  "T = 2π √(R/g)."),
                )),
        Numeric("phi_ddot", "angular acceleration", question=2, unit="rad/s^2", points=2,
                misconceptions=(
                    Misconception("drag forgotten", lambda p: -p.g / p.R * np.sin(p.phi),
                                  "The drag torque −k R² φ̇ adds −(k/m) φ̇, eq. (1.149)."),
                    Misconception("small-angle form at a large angle",
                                  lambda p: -p.k / p.m * p.phidot - p.g / p.R * p.phi,
                                  "sin φ ≈ φ only holds for |φ| ≪ 1."),
                )),
        Numeric("S", "string force", question=3, unit="N", points=1,
                misconceptions=(
                    Misconception("static string force", lambda p: p.m * p.g * np.cos(p.phi),
                                  "The string also supplies the centripetal force m R φ̇²."),
                )),
        Symbolic("eom", "angular acceleration as a formula", question=4, points=1,
                 expected="-(k/m)*phidot - (g/R)*sin(phi)",
                 variables=("k", "m", "phidot", "g", "R", "phi"),
                 equals="phi_ddot",
                 misconceptions=(
                     Misconception("linearized", "-(k/m)*phidot - (g/R)*phi",
                                   "Keep sin φ: the angle is not small."),
                     Misconception("drag forgotten", "-(g/R)*sin(phi)",
                                   "Add the drag term −(k/m) φ̇."),
                 )),
    ),
)
