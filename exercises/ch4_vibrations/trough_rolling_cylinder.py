"""A solid cylinder rolling without slipping inside a circular trough: the equation of
motion by the Lagrange equations, the angular acceleration at release and the period of
small oscillations (Section 4.1)."""

from functools import cache

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric, Symbolic, Uniform,
                                Variable, per_draw)
from dynagrade.exercise.apart import numbers_apart
from dynagrade.exercise.checks import Integrated, Recompute
from dynagrade.exercise.figure import angle_arc, describe, new_drawing
from dynagrade.mechanics import vibrations


@cache
def _system():
    """(t, theta, T, V, symbols): the cylinder of mass m and radius r whose centre moves on
    the circle of radius R - r; rolling inside the trough turns it at (R - r) theta' / r."""
    import sympy as sp

    t = sp.Symbol("t")
    theta = sp.Function("theta")(t)
    m, R, r, g = sp.symbols("m R r g", positive=True)
    spin = (R - r) * theta.diff(t) / r
    T = m * (R - r) ** 2 * theta.diff(t) ** 2 / 2 + (m * r**2 / 2) * spin**2 / 2
    V = -m * g * (R - r) * sp.cos(theta)
    return t, theta, T, V, (m, R, r, g)


@cache
def _acceleration():
    """theta''(theta, m, R, r, g) from the core's Lagrange equations, on first use."""
    import sympy as sp

    from dynagrade.mechanics import lagrange

    t, theta, T, V, symbols = _system()
    a = lagrange.in_state_symbols(lagrange.accelerations(T, V, [theta], t)[0], [theta], t)
    return sp.lambdify([sp.Symbol("theta", real=True), *symbols], a)


@cache
def _omega_squared():
    """omega^2(m, R, r, g), linearized by the core about theta = 0, on first use."""
    import sympy as sp

    from dynagrade.mechanics import equilibrium

    t, theta, T, V, symbols = _system()
    return sp.lambdify(symbols, equilibrium.linearized_frequency_squared(T, V, [theta], t,
                                                                         {theta: 0}))


@per_draw
def solve(p):
    w = float(np.sqrt(_omega_squared()(p.m, p.R, p.r, p.g)))
    return {"alpha0": float(_acceleration()(p.theta0, p.m, p.R, p.r, p.g)), "omega": w,
            "T_period": vibrations.period(w)}


def _apart(p):
    """Any two numeric answers (their magnitudes in the parts' units) differ by 5 % or more."""
    if p.r > 0.5 * p.R:        # the first constraint rejects this draw
        return True
    return numbers_apart(abs(x) for x in solve(p).values())


def _roll(t, y, p):
    """3/2 m (R - r)^2 theta'' = -m g (R - r) sin(theta): T = 3/4 m (R - r)^2 theta'^2."""
    return (y[1], -2 * p.g * np.sin(y[0]) / (3 * (p.R - p.r)))


def figure(p):
    """The trough in section, to scale: its lower half of radius R, the cylinder of radius
    r at the release angle theta0 from the downward vertical through the trough's centre."""
    from dynagrade.exercise.figure import Circle

    drawing, axes = new_drawing(4.0, 3.0)
    s = np.linspace(np.pi, 2 * np.pi, 91)
    axes.plot(p.R * np.cos(s), p.R * np.sin(s), color="0.1", lw=2.0)
    c = (p.R - p.r) * np.array([np.sin(p.theta0), -np.cos(p.theta0)])
    # light blue: a large cylinder reaches close to the trough's centre and may lie under
    # the angle's label, which stays legible on it
    axes.add_patch(Circle(tuple(c), p.r, facecolor="#a9cce8", edgecolor="0.1"))
    axes.plot([0, 0], [0, -p.R], color="0.5", lw=0.8, ls="--")
    axes.plot([0, c[0]], [0, c[1]], color="0.3", lw=0.8)
    axes.plot([0, -p.R * np.sin(np.radians(40))], [0, -p.R * np.cos(np.radians(40))],
              color="0.3", lw=0.8)
    axes.text(-0.55 * p.R * np.sin(np.radians(40)) - 0.04 * p.R,
              -0.55 * p.R * np.cos(np.radians(40)), "R", ha="right", va="center", fontsize=10)
    # r on a radius pointing left (towards the trough's inside, away from its wall and
    # from the line to the trough's centre), labelled just outside the cylinder
    left = np.array([np.cos(np.radians(200)), np.sin(np.radians(200))])
    axes.plot([c[0], c[0] + p.r * left[0]], [c[1], c[1] + p.r * left[1]], color="0.1", lw=0.8)
    axes.text(c[0] + (p.r + 0.03 * p.R) * left[0], c[1] + (p.r + 0.03 * p.R) * left[1], "r",
              ha="right", va="center", fontsize=10)
    angle_arc(axes, (0.0, 0.0), 0.38 * p.R, -np.pi / 2, -np.pi / 2 + p.theta0)
    middle = -np.pi / 2 + p.theta0 / 2
    axes.text(0.5 * p.R * np.cos(middle), 0.5 * p.R * np.sin(middle), "θ₀", ha="center",
              va="center", fontsize=10)
    describe(axes, "The cylinder is drawn at rest at the release angle, to the right of the "
             "lowest point of the trough; θ is measured at the trough's centre from the "
             "downward vertical, counter-clockwise.")
    axes.set_xlim(-1.1 * p.R, 1.1 * p.R)
    axes.set_ylim(-1.1 * p.R, 0.15 * p.R)
    return drawing


_VARS = {"theta": Variable(-3, 3, "rad"), "R": None, "r": None, "g": None}

EXERCISE = Exercise(
    id="trough-rolling-cylinder-lagrange",
    title="Cylinder rolling inside a circular trough: Lagrange equation and small oscillations",
    source="Section 4.1",
    topics=("Lagrange equations", "rolling", "linearization", "natural frequency"),
    params=(
        Uniform("m", 0.5, 10.0, step=0.5, unit="kg", symbol="m"),
        Uniform("R", 0.3, 2.0, step=0.05, unit="m", symbol="R"),
        Uniform("r", 0.03, 0.5, step=0.01, unit="m", symbol="r"),
        Uniform("theta0", 20, 60, step=1, unit="deg", symbol=r"\theta_0"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        # r >= R/10 keeps R - r and R more than 5 % apart (the "R for R - r" slip)
        Constraint("the cylinder's radius is 10 % to 50 % of the trough's",
                   lambda p: 0.1 * p.R <= p.r <= 0.5 * p.R),
        Constraint("the numeric answers differ by at least 5 %", _apart),
    ),
    statement="""
A solid homogeneous cylinder of mass $m$ = {{ m }} and radius $r$ = {{ r }} rolls without
slipping inside a fixed circular trough of radius $R$ = {{ R }} whose axis is horizontal;
$g$ = {{ g }}. Let $\\theta$ be the angle between the downward vertical and the line from
the trough's axis to the cylinder's axis.

1. Write the kinetic energy (translation and rotation) and the potential energy, and derive
   with the Lagrange equations the angular acceleration $\\ddot\\theta$ as an expression in
   `theta`, `R`, `r` and `g` (valid for large angles).
2. The cylinder is released from rest at $\\theta_0$ = {{ theta0 }}. What is $\\ddot\\theta$
   just after the release?
3. Linearize about $\\theta = 0$: what are the natural angular frequency $\\omega$ and the
   period of small oscillations?
""",
    solution=r"""
One generalized coordinate, $\theta$, and Lagrange's equation (Section 4.1)
$$\frac{d}{dt}\frac{\partial T}{\partial\dot\theta} - \frac{\partial T}{\partial\theta} + \frac{\partial V}{\partial\theta} = 0;$$
rolling without slipping is a constraint that ties the cylinder's spin to $\dot\theta$.

1. **Equation of motion.** The cylinder's axis moves on a circle of radius $R - r$ at the
   speed $(R - r)\dot\theta$. Its contact point is at rest, so it spins at
   $\omega_c = (R - r)\dot\theta/r$, and its moment of inertia is $J = \tfrac{1}{2} m r^2$:
   $$T = \tfrac{1}{2} m (R - r)^2\dot\theta^2 + \tfrac{1}{2}\cdot\tfrac{1}{2} m r^2
   \Bigl(\frac{(R - r)\dot\theta}{r}\Bigr)^2 = \tfrac{3}{4} m (R - r)^2\dot\theta^2,
   \qquad V = -m g (R - r)\cos\theta .$$
   Lagrange's equation gives $\tfrac{3}{2} m (R - r)^2\ddot\theta + m g (R - r)\sin\theta = 0$:
   $$\ddot\theta = -\frac{2g}{3(R - r)}\sin\theta,$$
   written as `{{ answers.theta_ddot }}`; the mass $m$ = {{ m }} drops out.
2. **At release.** With $\theta_0$ = {{ theta0 }}, $R$ = {{ R }} and $r$ = {{ r }}:
   $\ddot\theta$ = {{ answers.alpha0 }} (negative: back towards the bottom).
3. **Small oscillations.** With $\sin\theta \approx \theta$,
   $\ddot\theta + \frac{2g}{3(R - r)}\theta = 0$, so
   $\omega = \sqrt{2g/(3(R - r))}$ = {{ answers.omega }} and $T = 2\pi/\omega$ = {{ answers.T_period }}.
   **Check.** Without the rotation ($J = 0$, a sliding bead) the period would be
   $2\pi\sqrt{(R - r)/g}$, shorter by the factor $\sqrt{2/3}$: rolling stores a third of
   the kinetic energy in the spin, and the integrated motion gives back
   {{ checks.integrated_small_roll }} s.
""",
    solve=solve,
    checks=(
        # released from rest at 0.01 rad: back at rest (a turning point) one period later
        Integrated("T_period", _roll, lambda p: (0.01, 0.0), lambda p, s: 3 * s["T_period"],
                   lambda t, y, p: t, name="integrated_small_roll",
                   event=lambda t, y, p: y[1], direction=-1, rtol=1e-4),
        Recompute("omega", lambda p, s: np.sqrt(2 * p.g / (3 * (p.R - p.r))),
                  name="linearized_by_hand"),
        # energy: d/dt [3/4 m (R - r)^2 theta'^2 - m g (R - r) cos(theta)] = 0 at theta'= 0
        Recompute("alpha0", lambda p, s: _roll(0.0, (p.theta0, 0.0), p)[1],
                  name="energy_rate"),
    ),
    figure=figure,
    figure_to_scale=True,
    parts=(
        Symbolic("theta_ddot", "angular acceleration", question=1, points=2,
                 expected="-2*g/(3*(R - r))*sin(theta)", variables=_VARS,
                 misconceptions=(
                     Misconception("rotation forgotten", "-g/(R - r)*sin(theta)",
                                   "The rolling cylinder also spins: T = 3/4 m (R - r)^2 theta'^2."),
                     Misconception("R for R - r", "-2*g/(3*R)*sin(theta)",
                                   "The cylinder's axis moves on a circle of radius R - r."),
                     Misconception("linearized too early", "-2*g/(3*(R - r))*theta",
                                   "The equation of motion holds for large angles: keep sin(theta)."),
                 )),
        Numeric("alpha0", "angular acceleration at release", question=2, unit="rad/s^2",
                points=1, misconceptions=(
                    Misconception("rotation forgotten",
                                  lambda p: -p.g * np.sin(p.theta0) / (p.R - p.r),
                                  "Part of the potential energy goes into the spin: the "
                                  "effective inertia is 3/2 m (R - r)^2."),
                    Misconception("sin(theta0) linearized",
                                  lambda p: -2 * p.g * p.theta0 / (3 * (p.R - p.r)),
                                  "At release the angle is not small: keep sin(theta0)."),
                )),
        Numeric("omega", "natural angular frequency", question=3, unit="rad/s", points=2,
                misconceptions=(
                    Misconception("rotation forgotten", lambda p: np.sqrt(p.g / (p.R - p.r)),
                                  "omega^2 = K/M with M = 3/2 m (R - r)^2, not m (R - r)^2."),
                    Misconception("R for R - r", lambda p: np.sqrt(2 * p.g / (3 * p.R)),
                                  "The cylinder's axis moves on a circle of radius R - r."),
                    Misconception("f for omega", lambda p: solve(p)["omega"] / (2 * np.pi),
                                  "omega is in rad/s; f = omega/(2 pi) is in Hz."),
                )),
        Numeric("T_period", "period of small oscillations", question=3, unit="s", points=1,
                misconceptions=(Misconception("1/omega", lambda p: 1 / solve(p)["omega"],
                                              "The period is 2 pi / omega."),)),
    ),
)
