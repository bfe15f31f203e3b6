"""A particle circling in air at constant radius: decay of the angular velocity by
linear drag (Example 1.16, eqs. 1.142-1.144)."""

import numpy as np

from dynagrade.exercise import (Constraint, Exercise, Misconception, Numeric, Symbolic, Uniform)
from dynagrade.exercise.checks import Integrated, Recompute
from dynagrade.mechanics import angular_momentum as am
from dynagrade.mechanics import kinematics


def solve(p):
    return {
        "M0": float(-am.drag_torque(p.k, p.R, p.omega0)),
        "omega_t": float(am.drag_angular_velocity(p.t, p.omega0, p.k, p.m)),
        "t_half": kinematics.half_life(am.rotation_decay_rate(p.k, p.m)),
        "phi_total": float(am.drag_rotation_angle(np.inf, p.omega0, p.k, p.m)),
        "rate": am.rotation_decay_rate(p.k, p.m),
    }


def _spin_down(t, y, p):
    """Angular momentum balance with the drag torque, eq. (1.144): phi'' = -(k/m) phi'."""
    return (y[1], -p.k / p.m * y[1])


EXERCISE = Exercise(
    id="rotating-particle-in-air",
    title="Rotating particle slowed by air drag",
    source="Example 1.16",
    topics=("angular momentum balance", "viscous drag", "equation of motion"),
    params=(
        Uniform("m", 0.1, 2.0, step=0.05, unit="kg", symbol="m"),
        Uniform("R", 0.2, 1.5, step=0.05, unit="m", symbol="R"),
        Uniform("k", 0.01, 0.2, step=0.005, unit="kg/s", symbol="k"),
        Uniform("omega0", 2.0, 20.0, step=0.5, unit="rad/s", symbol=r"\dot\varphi_0"),
        Uniform("t", 1.0, 20.0, step=0.5, unit="s", symbol="t"),
    ),
    constraints=(
        Constraint("the decay by time t is visible but not complete: 0.3 < k t/m < 2.5",
                   lambda p: 0.3 < p.k * p.t / p.m < 2.5),
        Constraint("R is not near 1 m, where R and R^2 agree", lambda p: abs(p.R - 1.0) > 0.1),
    ),
    statement="""
A particle of mass $m$ = {{ m }} on a light rigid rod circles at the constant radius
$R$ = {{ R }} about a fixed vertical axis (gravity is perpendicular to the plane of
rotation and the bearing is frictionless). Air exerts the drag $\\boldsymbol F_d = -k\\boldsymbol v$
with $k$ = {{ k }}. At $t = 0$ it turns at $\\dot\\varphi_0$ = {{ omega0 }}.

1. What is the magnitude of the drag torque about the axis at $t = 0$?
2. What is the angular velocity at $t$ = {{ t }}?
3. After what time has the angular velocity halved?
4. Through what total angle (in rad) does the particle turn as $t \\to \\infty$, while it slows
   down towards rest (it never quite stops)?
5. Write $\\dot\\varphi(t)$ as a formula in $\\dot\\varphi_0$ (write `omega0`), $k$, $m$ and $t$.
""",
    solution=r"""
The particle moves on a circle of fixed radius $R$ about the axis, so $v = R\dot\varphi$
along $e_\varphi$. Bearing force and gravity have no moment about the axis; only the drag
does. Use the angular momentum balance about the axis (Example 1.16).

1. **Drag torque.** $F_d = -kv$ is tangential with lever arm $R$:
   $M = -kR\,v = -kR^2\dot\varphi$ (eqs. (1.142), (1.143)). At $t = 0$, with $k$ = {{ k }},
   $R$ = {{ R }} and $\dot\varphi_0$ = {{ omega0 }}: $|M_0|$ = {{ answers.M0 }}.
2. **Angular velocity.** With $\dot H = mR^2\ddot\varphi$ the balance reads
   $mR^2\ddot\varphi = -kR^2\dot\varphi$, i.e. $\ddot\varphi + \frac{k}{m}\dot\varphi = 0$
   (eq. (1.144)). The radius drops out; separating variables,
   $\dot\varphi(t) = \dot\varphi_0\,e^{-kt/m}$ with the decay rate $k/m$ = {{ si.rate }} 1/s
   ($m$ = {{ m }}). At $t$ = {{ t }}: $\dot\varphi$ = {{ answers.omega_t }}.
3. **Half-life.** $e^{-kt/m} = \tfrac{1}{2}$ gives $t_{1/2} = (m/k)\ln 2$ = {{ answers.t_half }}.
4. **Total angle.** Integrate once more: $\varphi(\infty) - \varphi(0)
   = \int_0^\infty \dot\varphi_0 e^{-kt/m}\,\mathrm dt = m\dot\varphi_0/k$
   = {{ answers.phi_total }} — finite, although the particle never quite stops.
5. **Formula.** $\dot\varphi(t)$ = `{{ answers.omega_formula }}`.
""",
    solve=solve,
    checks=(
        Integrated("omega_t", _spin_down, lambda p: (0.0, p.omega0), lambda p, s: p.t,
                   lambda t, y, p: y[1], name="integrated_spin"),
        Integrated("phi_total", _spin_down, lambda p: (0.0, p.omega0), lambda p, s: 40 * p.m / p.k,
                   lambda t, y, p: y[0], name="integrated_total_angle"),
        # eq. (1.143): the drag -k v at radius R gives the torque -k R^2 phi'
        Recompute("M0", lambda p, s: p.k * p.R**2 * p.omega0, name="drag_torque"),
        Recompute("t_half", lambda p, s: p.m * np.log(2) / p.k, name="half_life"),
    ),
    parts=(
        Numeric("M0", "drag torque at t = 0", question=1, unit="N*m", points=1,
                misconceptions=(
                    Misconception("lever arm forgotten", lambda p: p.k * p.R * p.omega0,
                                  "M = R × F_d with |F_d| = k R φ̇: M = k R² φ̇, eq. (1.143)."),
                )),
        Numeric("omega_t", "angular velocity at t", question=2, unit="rad/s", points=2,
                misconceptions=(
                    Misconception("decay rate k/(m R^2)",
                                  lambda p: p.omega0 * np.exp(-p.k * p.t / (p.m * p.R**2)),
                                  "R² cancels: m R² φ̈ = −k R² φ̇ gives φ̈ + (k/m) φ̇ = 0, eq. (1.144)."),
                    Misconception("linear decrease",
                                  lambda p: p.omega0 * (1 - p.k * p.t / p.m),
                                  "Solve φ̈ = −(k/m) φ̇: the decay is exponential."),
                )),
        Numeric("t_half", "half-life of the angular velocity", question=3, unit="s", points=1),
        Numeric("phi_total", "total angle", question=4, unit="rad", points=1),
        Symbolic("omega_formula", "angular velocity as a formula", question=5, points=1,
                 expected="omega0*exp(-k*t/m)",
                 variables=("omega0", "k", "m", "t"),
                 equals="omega_t",
                 misconceptions=(
                     Misconception("decay rate m/k", "omega0*exp(-m*t/k)",
                                   "The rate is k/m (units 1/s)."),
                 )),
    ),
)
