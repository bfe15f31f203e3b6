"""A person on a freely rotating chair pulls a heavy mass towards the axis: conservation of
angular momentum (Example 1.19; eqs. 1.135 and 1.139)."""

from dynagrade.exercise import (Constraint, Exercise, Misconception, Numeric, Symbolic, Uniform)
from dynagrade.exercise.checks import Balance
from dynagrade.mechanics import angular_momentum as am
from dynagrade.mechanics import rigid_kinetics


def _inertia(p, r):
    return p.I + am.particle_moment_of_inertia(p.m, r)


def solve(p):
    I0, I1 = _inertia(p, p.r0), _inertia(p, p.r1)
    omega1 = am.conserved_angular_velocity(p.omega0, I0, I1)
    # rotation about the fixed vertical axis: 1x1 moment of inertia, one rate
    return {"omega1": omega1, "I_before": I0, "I_after": I1,
            "H": float(rigid_kinetics.rigid_body_angular_momentum([[I0]], [p.omega0])[0]),
            "W": (rigid_kinetics.rotational_kinetic_energy([[I1]], [omega1])
                  - rigid_kinetics.rotational_kinetic_energy([[I0]], [p.omega0]))}


EXERCISE = Exercise(
    id="rotating-chair",
    title="Heavy mass held on a rotating chair",
    source="Example 1.19",
    topics=("conservation of angular momentum", "moment of inertia"),
    params=(
        Uniform("I", 1.0, 4.0, step=0.1, unit="kg*m^2", symbol="I_0"),
        Uniform("m", 2.0, 10.0, step=0.5, unit="kg", symbol="m"),
        Uniform("r0", 0.5, 0.9, step=0.05, unit="m", symbol="r_0"),
        Uniform("r1", 0.1, 0.3, step=0.05, unit="m", symbol="r_1"),
        Uniform("omega0", 0.5, 3.0, step=0.1, unit="rad/s", symbol=r"\omega_0"),
    ),
    constraints=(
        Constraint("the mass matters: m r0^2 is at least 20 % of I",
                   lambda p: p.m * p.r0**2 > 0.2 * p.I),
    ),
    statement="""
A person sits on a chair that turns without friction about a vertical axis. Person and
chair together have the moment of inertia $I_0$ = {{ I }} about that axis. The person
holds a heavy mass $m$ = {{ m }} (treat it as a particle) at the distance
$r_0$ = {{ r0 }} from the axis while turning at $\\omega_0$ = {{ omega0 }}, then pulls it in
to $r_1$ = {{ r1 }}.

1. What is the angular velocity afterwards?
2. What is the angular momentum of the whole system about the axis?
3. How much work did the person do while pulling the mass in?
4. Write the final angular velocity as a formula in $I_0$ (`I`), $m$, $r_0$, $r_1$ and $\\omega_0$.
""",
    solution=r"""
No external moment acts about the vertical axis (the bearing is frictionless; gravity and
the bearing forces have no moment about it). The angular momentum balance
$\dot H = M = 0$ therefore keeps the system's angular momentum about the axis constant
(eq. (1.135), Example 1.19). About a fixed axis $H = I\omega$, and the mass adds $mr^2$ to the
moment of inertia (eq. (1.139)): before, $I_0 + m r_0^2$ = {{ si.I_before }} kg·m²; after,
$I_0 + m r_1^2$ = {{ si.I_after }} kg·m² (with $I_0$ = {{ I }}, $m$ = {{ m }},
$r_0$ = {{ r0 }}, $r_1$ = {{ r1 }}).

1. **Angular velocity.** $(I_0 + m r_0^2)\,\omega_0 = (I_0 + m r_1^2)\,\omega_1$, so
   $\omega_1 = \omega_0\,(I_0 + m r_0^2)/(I_0 + m r_1^2)$; with $\omega_0$ = {{ omega0 }}:
   $\omega_1$ = {{ answers.omega1 }}.
2. **Angular momentum.** $H = (I_0 + m r_0^2)\,\omega_0$ = {{ answers.H }}, the same before
   and after.
3. **Work.** The angular momentum is conserved but the kinetic energy is not: with
   $T = \tfrac{1}{2} I\omega^2$, the person's work is the change
   $W = \tfrac{1}{2}(I_0 + m r_1^2)\,\omega_1^2 - \tfrac{1}{2}(I_0 + m r_0^2)\,\omega_0^2$
   = {{ answers.W }} — positive: pulling the mass in against its tendency to fly outward
   costs work.
4. **Formula.** $\omega_1$ = `{{ answers.omega_formula }}`.
""",
    solve=solve,
    checks=(
        # angular momentum about the fixed axis is conserved, eq. (1.151)
        Balance("angular momentum", lambda p, s: (p.I + p.m * p.r0**2) * p.omega0,
                lambda p, s: (p.I + p.m * p.r1**2) * s["omega1"], name="angular_momentum"),
        # the work done equals the gain of kinetic energy, eq. (1.87)
        Balance("energy", lambda p, s: s["W"],
                lambda p, s: ((p.I + p.m * p.r1**2) * s["omega1"]**2
                              - (p.I + p.m * p.r0**2) * p.omega0**2) / 2, name="work_energy"),
    ),
    parts=(
        Numeric("omega1", "final angular velocity", question=1, unit="rad/s", points=2,
                misconceptions=(
                    Misconception("chair's inertia forgotten",
                                  lambda p: p.omega0 * (p.r0 / p.r1) ** 2,
                                  "Person and chair turn too: conserve (I0 + m r²) ω."),
                    Misconception("energy conserved instead",
                                  lambda p: p.omega0 * (_inertia(p, p.r0) / _inertia(p, p.r1)) ** 0.5,
                                  "The person does work; only the angular momentum is conserved "
                                  "(no torque about the axis, eq. 1.135)."),
                )),
        Numeric("H", "angular momentum", question=2, unit="kg*m^2/s", points=1,
                misconceptions=(
                    Misconception("mass only", lambda p: p.m * p.r0**2 * p.omega0,
                                  "Include the person and chair, I0 ω0."),
                )),
        Numeric("W", "work done by the person", question=3, unit="J", points=1),
        Symbolic("omega_formula", "final angular velocity as a formula", question=4, points=1,
                 expected="(I + m*r0^2)*omega0/(I + m*r1^2)",
                 variables=("I", "m", "r0", "r1", "omega0"),
                 equals="omega1",
                 misconceptions=(
                     Misconception("chair's inertia forgotten", "(r0/r1)^2*omega0",
                                   "The chair and person turn too."),
                 )),
    ),
)
