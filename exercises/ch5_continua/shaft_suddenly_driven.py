"""A long shaft whose end is suddenly driven at constant speed: the torque, the shear
stress and the free end's start (Section 5.3.2)."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.apart import answers_apart
from dynagrade.exercise.checks import Balance, Recompute
from dynagrade.exercise.figure import angle_arc, block, describe, dimension, new_drawing
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import rods, stiffness

#: each part's unit as a factor of SI, for telling the answers apart
_UNITS = {"T": 1.0, "tau": 1e6, "t_end": 1e-3, "phi_end": 1.0}


def _c(p):
    return rods.torsional_wave_speed(p.G, p.rho)


def _I_p(p):
    return stiffness.circle_polar_moment(p.d)


@per_draw
def solve(p):
    T = rods.torsional_impedance(p.rho, _c(p), _I_p(p)) * p.Omega
    return {"T": T, "tau": rods.torsion_shear_stress(T, p.d / 2, _I_p(p)),
            "t_end": rods.travel_time(p.L, _c(p)),
            # the far end turns at 2 Omega from L/c_T until the reflection is back at 2 L/c_T
            "phi_end": rods.free_end_velocity(p.Omega) * rods.travel_time(p.L, _c(p)),
            "c": _c(p), "I_p": _I_p(p)}


def _energy_flux(p, s):
    """Power carried by the wave: c_T times its kinetic and strain energy per length,
    rho I_p Omega^2 / 2 + G I_p (Omega / c_T)^2 / 2 (Section 5.3.2)."""
    c = np.sqrt(p.G / p.rho)
    I_p = np.pi * p.d**4 / 32
    return c * (p.rho * I_p * p.Omega**2 / 2 + p.G * I_p * (p.Omega / c) ** 2 / 2)


def figure(p):
    """The shaft in two bearings, the motor's end on the left, the free end on the right;
    schematic."""
    L = p.L
    t = 0.03 * L
    drawing, axes = new_drawing(5.0, 1.6)
    block(axes, (-0.06 * L, 0.0), 0.1 * L, 0.12 * L, "motor", color="0.35")
    block(axes, (L / 2, 0.0), L, t, color="0.65")
    for x in (0.3 * L, 0.92 * L):
        block(axes, (x, 0.0), 0.03 * L, 0.07 * L, color="#e6d8a8")
    angle_arc(axes, (0.03 * L, 0.0), 0.045 * L, -2.0, 2.0)
    # an arrowhead at the arc's end shows the sense of the drive
    r, tip, before = 0.045 * L, 2.0, 1.8
    axes.annotate("", xy=(0.03 * L + r * np.cos(tip), r * np.sin(tip)),
                  xytext=(0.03 * L + r * np.cos(before), r * np.sin(before)),
                  arrowprops={"arrowstyle": "-|>", "color": "0.2", "lw": 0.8,
                              "mutation_scale": 8})
    axes.text(0.03 * L, 0.07 * L, f"Ω = {format_number(p.Omega * 60 / (2 * np.pi))} rpm",
              ha="center", va="bottom", fontsize=10)
    axes.text(0.61 * L, 0.04 * L,
              f"d = {format_number(p.d * 1e3)} mm,  G = {format_number(p.G / 1e9)} GPa,"
              f"  ρ = {format_number(p.rho)} kg/m³", ha="center", va="bottom", fontsize=9)
    dimension(axes, (0.0, -0.08 * L), (L, -0.08 * L), f"L = {format_number(L)} m",
              tick=0.01 * L, side=-1.0)
    describe(axes, "The motor drives the shaft's left end, turning it about the shaft's axis "
                   "(the arc); the shaft turns freely in two bearings and its right end is free.")
    axes.set_xlim(-0.13 * L, 1.04 * L)
    axes.set_ylim(-0.15 * L, 0.13 * L)
    return drawing


EXERCISE = Exercise(
    id="shaft-suddenly-driven",
    title="A long shaft suddenly driven at one end: torsional wave",
    source="Section 5.3.2",
    topics=("torsional waves", "torsional impedance", "shear stress", "wave reflection"),
    params=(
        Uniform("G", 26, 80, step=1, unit="GPa", symbol="G"),
        Uniform("rho", 2700, 8900, step=100, unit="kg/m^3", symbol=r"\rho"),
        Uniform("d", 10, 60, step=2, unit="mm", symbol="d"),
        Uniform("L", 2.0, 30.0, step=0.5, unit="m", symbol="L"),
        Uniform("Omega", 60, 600, step=10, unit="rpm", symbol=r"\Omega"),
    ),
    constraints=(
        Constraint("a real metal (aluminium, steel, copper alloys, titanium): "
                   "sqrt(G/rho) between 2 and 3.4 km/s",
                   lambda p: 2e3 <= np.sqrt(p.G / p.rho) <= 3.4e3),
        Constraint("the shaft stays elastic: tau at most 150 MPa", lambda p: solve(p)["tau"] <= 150e6),
        Constraint("the four answers are over 10 % apart in SI and in their parts' units",
                   lambda p: answers_apart(solve(p), _UNITS)),
    ),
    statement="""
A long round shaft (diameter $d$ = {{ d }}, length $L$ = {{ L }}, shear modulus
$G$ = {{ G }}, density $\\rho$ = {{ rho }}) lies at rest in frictionless bearings; its far
end is free. At $t = 0$ a motor suddenly drives its near end at the constant speed
$\\Omega$ = {{ Omega }}. The shaft stays elastic.

1. Which torque must the motor deliver right after $t = 0$?
2. What is the largest shear stress in the shaft before the wave reaches the far end?
3. When does the far end start to turn?
4. Through which angle has the far end turned when the wave reflected there arrives back
   at the motor?
""",
    solution=r"""
The twist angle obeys the wave equation with $c_T = \sqrt{G/\rho}$ = {{ si.c }} m/s; the
driven end sends a step wave into the shaft behind which the material turns at $\Omega$
(torsional waves, Section 5.3.2).

1. **Torque.** Behind the front the twist per length is $\theta_x = \Omega/c_T$, so the
   torque is $G I_p\,\Omega/c_T$, that is
   $$T = \rho\,c_T I_p\,\Omega,$$
   with $I_p = \tfrac{\pi}{2}(d/2)^4$ = {{ si.I_p }} m⁴ ($d$ = {{ d }}), $\rho$ = {{ rho }}
   and $\Omega$ = {{ Omega }}: $T$ = {{ answers.T }}.
2. **Shear stress.** Largest at the surface, $r = d/2$:
   $$\tau = \frac{T\,d/2}{I_p} = \rho\,c_T\,\Omega\,\frac{d}{2}$$
   = {{ answers.tau }}.
3. **Arrival.** The front crosses the shaft in $t = L/c_T$ = {{ answers.t_end }} ($L$ = {{ L }}).
4. **Free end.** A free end carries no torque: the wave is reflected with the opposite
   twist and the same angular velocity, which adds to the incident one, so the far end
   turns at $2\Omega$ from $t = L/c_T$ on. The reflected front needs another $L/c_T$ to
   get back to the motor; by then the far end has turned through
   $$\varphi_{\mathrm{end} } = 2\Omega\,\frac{L}{c_T}$$
   = {{ answers.phi_end }}.

**Check.** The motor's power $T\Omega$ equals $c_T$ times the wave's kinetic and strain
energy per length, $\rho I_p\Omega^2/2 + G I_p(\Omega/c_T)^2/2$: {{ checks.power_into_the_wave }} W.
And when the reflection reaches the motor it has cancelled the twist everywhere: the
shaft is untwisted, so the far end stands at the motor's angle
$\Omega\cdot 2L/c_T$ = {{ checks.driven_end_angle }} rad.
""",
    solve=solve,
    checks=(
        # the motor's power is the energy the wave carries away per second
        Balance("power", lambda p, s: s["T"] * p.Omega, _energy_flux, name="power_into_the_wave"),
        # tau = G gamma with the surface shear strain gamma = (d/2) theta_x = (d/2) Omega / c_T
        Recompute("tau", lambda p, s: p.G * p.d / 2 * p.Omega / np.sqrt(p.G / p.rho), name="surface_strain"),
        # at 2 L/c_T the reflected wave has cancelled the twist everywhere: the shaft is
        # untwisted and the far end stands at the motor's angle Omega * 2 L/c_T
        Recompute("phi_end", lambda p, s: p.Omega * 2 * p.L * np.sqrt(p.rho / p.G),
                  name="driven_end_angle"),
    ),
    figure=figure,
    parts=(
        Numeric("T", "torque of the motor", question=1, unit="N*m", points=2,
                misconceptions=(
                    Misconception("d as the radius in I_p", lambda p: p.rho * _c(p) * np.pi * p.d**4 / 2 * p.Omega,
                                  "I_p = pi r^4/2 with the radius r = d/2, that is pi d^4/32."),
                    Misconception("I for I_p", lambda p: p.rho * _c(p) * stiffness.circle_second_moment(p.d) * p.Omega,
                                  "Torsion of a round shaft takes the polar moment I_p = pi d^4/32."),
                )),
        Numeric("tau", "largest shear stress", question=2, unit="MPa", points=2,
                misconceptions=(
                    Misconception("d for d/2", lambda p: p.rho * _c(p) * p.Omega * p.d,
                                  "The surface is at r = d/2: tau = T (d/2)/I_p."),)),
        Numeric("t_end", "time when the far end starts to turn", question=3, unit="ms", points=1,
                misconceptions=(
                    Misconception("round trip 2L/c_T", lambda p: 2 * p.L / _c(p),
                                  "The front reaches the far end after one crossing, L/c_T."),)),
        Numeric("phi_end", "angle of the far end when the reflection is back at the motor",
                question=4, unit="rad", points=1,
                misconceptions=(
                    Misconception("the driven speed", lambda p: p.Omega * p.L / _c(p),
                                  "At a free end the reflected wave adds its angular velocity to the "
                                  "incident one: the far end turns at 2 Omega."),
                    Misconception("turning from t = 0", lambda p: 2 * p.Omega * 2 * p.L / _c(p),
                                  "The far end rests until the front arrives at L/c_T; it turns at "
                                  "2 Omega only for the reflection's return trip, L/c_T."),)),
    ),
)
