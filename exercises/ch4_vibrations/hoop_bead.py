"""A bead on a spinning hoop: equilibria, their stability and small oscillations (Section 4.2).

The hoop spins faster than the critical rate (the bead has an off-axis equilibrium to
ask for), so the lowest point is unstable there; its stability is asked at a second spin
rate Omega2, drawn on both sides of the critical one, so that the class's answers differ
(issue 31: it used to be "unstable" for everybody)."""

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric,
                                Options, Uniform)
from dynagrade.exercise.checks import Recompute
from dynagrade.mechanics import equilibrium
from dynagrade.mechanics.examples import hoop


def solve(p):
    theta = hoop.hoop_equilibrium_angle(p.R, p.Omega, p.g)
    curvature = hoop.hoop_potential_curvature(0.0, p.m, p.R, p.Omega2, p.g)
    bottom = equilibrium.stability([[curvature]])
    return {
        "Omega_c": hoop.hoop_critical_spin_rate(p.R, p.g),
        "theta_star": theta,
        "bottom": bottom,
        "omega": hoop.hoop_oscillation_frequency(p.R, p.Omega, p.g),
        "curvature_bottom": curvature,
    }


def _oscillation(p, solved):
    """V(theta) = -m g R cos(theta) - m R^2 Omega^2 sin^2(theta) / 2 and T = m R^2 theta'^2 / 2
    (Section 4.2): about the off-centre equilibrium cos(theta*) = g / (R Omega^2),
    V'' = m R^2 Omega^2 sin^2(theta*)."""
    cosine = p.g / (p.R * p.Omega**2)
    if cosine < 1:
        return p.Omega * np.sqrt(1 - cosine**2)
    return np.sqrt(p.g / p.R - p.Omega**2)


EXERCISE = Exercise(
    id="hoop-bead-equilibrium",
    title="Bead on a spinning hoop: equilibria and stability",
    source="Section 4.2",
    topics=("equilibrium", "stability", "effective potential", "linearization"),
    params=(
        Uniform("m", 0.01, 0.2, step=0.01, unit="kg", symbol="m"),
        Uniform("R", 0.1, 1.0, step=0.05, unit="m", symbol="R"),
        Uniform("Omega", 60, 300, step=5, unit="rpm", symbol=r"\Omega"),
        Uniform("Omega2", 20, 120, step=5, unit="rpm", symbol=r"\Omega_2"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("the hoop spins at least 25 % faster than the critical rate",
                   lambda p: p.Omega >= 1.25 * np.sqrt(p.g / p.R)),
        Constraint("the off-axis angle stays below 80 degrees (the bead visibly oscillates)",
                   lambda p: p.g / (p.R * p.Omega**2) >= np.cos(np.radians(80))),
        Constraint("the oscillation frequency differs from the plain pendulum's by at least 3 %",
                   lambda p: abs(hoop.hoop_oscillation_frequency(p.R, p.Omega, p.g)
                                 / np.sqrt(p.g / p.R) - 1) >= 0.03),
        Constraint("the second spin rate is at least 10 % away from the critical rate",
                   lambda p: abs(p.Omega2 / np.sqrt(p.g / p.R) - 1) >= 0.1),
    ),
    statement="""
A small bead of mass $m$ = {{ m }} slides without friction on a circular hoop of radius
$R$ = {{ R }}. The hoop spins about its vertical diameter at the constant rate
$\\Omega$ = {{ Omega }}; $g$ = {{ g }}. Let $\\theta$ be the bead's angle from the lowest
point of the hoop, measured at the hoop's centre.

1. Above which spin rate $\\Omega_c$ (in rad/s) does the lowest point stop being a stable equilibrium?
2. At the given spin rate, at which angle $\\theta^* \\in (0, 90°)$ does the bead rest relative to the hoop?
3. The motor is then set to the spin rate $\\Omega_2$ = {{ Omega2 }}. Is the lowest point a
   stable or an unstable equilibrium at $\\Omega_2$?
4. With which angular frequency does the bead oscillate about $\\theta^*$ when slightly disturbed?
""",
    solution=r"""
Seen from the spinning hoop the bead has one degree of freedom, $\theta$, and moves in the
effective potential of gravity and the centrifugal term (equilibrium and stability,
Section 4.2):
$$V^*(\theta) = -m g R\cos\theta - \tfrac{1}{2} m R^2\Omega^2\sin^2\theta .$$
Equilibria are where $V^{*\prime} = m R\sin\theta\,(g - R\Omega^2\cos\theta) = 0$; they are
stable where $V^{*\prime\prime} = m R\,(g\cos\theta - R\Omega^2\cos 2\theta) > 0$.
Here $m$ = {{ m }}, $R$ = {{ R }}, $g$ = {{ g }} and $\Omega$ = {{ Omega }} = {{ si.Omega }} rad/s.

1. **Critical spin rate.** At the lowest point $V^{*\prime\prime}(0) = m R\,(g - R\Omega^2)$,
   positive only for $\Omega^2 < g/R$:
   $$\Omega_c = \sqrt{g/R},$$
   that is $\Omega_c$ = {{ answers.Omega_c }}.
2. **Off-axis equilibrium.** The second factor of $V^{*\prime}$ vanishes at
   $$\cos\theta^* = \frac{g}{R\,\Omega^2},$$
   which needs $\Omega > \Omega_c$; here $\theta^*$ = {{ answers.theta_star }}.
3. **Lowest point at $\Omega_2$.** With $\Omega_2$ = {{ Omega2 }} = {{ si.Omega2 }} rad/s
   {% if answers.bottom == "stable" %}below{% else %}above{% endif %} $\Omega_c$,
   $V^{*\prime\prime}(0) = m R\,(g - R\Omega_2^2)$ = {{ si.curvature_bottom }} J is
   {% if answers.bottom == "stable" %}positive{% else %}negative{% endif %}, so the lowest
   point is **{{ answers.bottom }}**.
4. **Small oscillations about $\theta^*$.** With $\cos\theta^* = g/(R\Omega^2)$ the curvature
   becomes $V^{*\prime\prime}(\theta^*) = m R^2\Omega^2\sin^2\theta^*$, and the equivalent
   mass is $m R^2$, so
   $$\omega = \sqrt{\frac{V^{*\prime\prime}(\theta^*)}{m R^2} } = \Omega\sin\theta^*,$$
   that is $\omega$ = {{ answers.omega }}.
""",
    solve=solve,
    checks=(
        Recompute("Omega_c", lambda p, s: np.sqrt(p.g / p.R), name="critical_spin"),
        Recompute("omega", _oscillation, name="curvature_of_v"),
        # about the bottom V'' = m R (g - R Omega2^2), from V(theta) above at theta = 0
        Recompute("curvature_bottom", lambda p, s: p.m * p.R * (p.g - p.R * p.Omega2**2),
                  name="curvature_at_the_bottom"),
    ),
    parts=(
        Numeric("Omega_c", "critical spin rate", question=1, unit="rad/s", points=1,
                misconceptions=(Misconception("sqrt(R/g)", lambda p: np.sqrt(p.R / p.g),
                                              "Omega_c^2 = g/R: check the dimension (1/s)."),)),
        Numeric("theta_star", "equilibrium angle", question=2, unit="deg", points=2,
                misconceptions=(
                    Misconception("arcsin for arccos", lambda p: np.arcsin(p.g / (p.R * p.Omega**2)),
                                  "The equilibrium condition is cos(theta*) = g/(R Omega^2)."),
                    Misconception("spin rate in rpm used as rad/s",
                                  lambda p: np.arccos(min(1.0, p.g / (p.R * (p.Omega * 60 / (2 * np.pi))**2))),
                                  "Convert rpm to rad/s: multiply by 2 pi / 60."),
                )),
        Options("bottom", "stability of the lowest point at Omega_2", question=3,
                options=("stable", "unstable"), points=1),
        Numeric("omega", "frequency of small oscillations about theta*", question=4,
                unit="rad/s", points=2,
                misconceptions=(
                    Misconception("the spin rate", lambda p: p.Omega,
                                  "Linearize: V*''(theta*) = m R^2 Omega^2 sin^2(theta*), so omega = Omega sin(theta*)."),
                    Misconception("the pendulum frequency", lambda p: np.sqrt(p.g / p.R),
                                  "The spin changes the restoring curvature: omega = Omega sin(theta*)."),
                    Misconception("cos for sin", lambda p: p.Omega * p.g / (p.R * p.Omega**2),
                                  "omega^2 = V*''/(m R^2) = Omega^2 sin^2(theta*)."),
                )),
    ),
)
