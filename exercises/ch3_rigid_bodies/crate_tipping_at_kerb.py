"""A sliding crate caught at its front edge by a low kerb: impact about a stopped edge, and
whether the crate tips over (Section 3.3)."""

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric, Options,
                                Uniform, per_draw)
from dynagrade.exercise.apart import numbers_apart
from dynagrade.exercise.checks import Balance, Limit
from dynagrade.exercise.figure import (Rectangle, arrow, block, describe, dimension, ground,
                                       new_drawing)
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import inertia, rigid_impact


def _moment_edge(p):
    """The crate's moment of inertia about its front bottom edge (a box, Steiner)."""
    i_c = inertia.inertia_tensor_box(p.m, p.b, p.h, 1.0)[2, 2]
    return inertia.parallel_axis_moment(i_c, p.m, np.hypot(p.b, p.h) / 2)


def _edge_to_centre(p):
    return np.array([-p.b / 2, p.h / 2])


@per_draw
def solve(p):
    i_e = _moment_edge(p)
    omega = rigid_impact.angular_velocity_after_edge_impact(p.m, [p.v, 0.0], _edge_to_centre(p),
                                                            i_e)
    impulse = rigid_impact.impulse_at_edge(p.m, [p.v, 0.0], omega, _edge_to_centre(p))
    rise = np.hypot(p.b, p.h) / 2 - p.h / 2
    omega_tip = rigid_impact.angular_speed_to_tip_over(p.m, p.g, rise, i_e)
    omega_per_speed = abs(rigid_impact.angular_velocity_after_edge_impact(
        p.m, [1.0, 0.0], _edge_to_centre(p), i_e))
    v_min = omega_tip / omega_per_speed
    return {
        "omega": abs(omega),
        "J": float(np.linalg.norm(impulse)),
        "v_min": v_min,
        "tips": "yes" if p.v > v_min else "no",
        "I_E": i_e,
        "J_x": float(impulse[0]),
        "J_y": float(impulse[1]),
        "rise": rise,
        "omega_tip": omega_tip,
    }


def _energy_kept_tips(p):
    """The wrong route: kinetic energy kept through the impact, 1/2 m v^2 >= m g Delta h."""
    return "yes" if p.v**2 > 2 * p.g * solve(p)["rise"] else "no"


def figure(p):
    """Side view to scale: the crate sliding to the right towards the kerb at its front
    bottom edge E (Section 3.3)."""
    b, h = p.b, p.h
    size = max(b, h)
    drawing, axes = new_drawing(4.4, 3.2)
    ground(axes, -b - 0.7 * size, 0.7 * size, hatch=0.05 * size)
    block(axes, (-b / 2, h / 2), b, h, color="#c8a26a")
    axes.add_patch(Rectangle((0.0, 0.0), 0.12 * size, 0.05 * size, facecolor="0.45",
                             edgecolor="0.1", lw=1.0))
    axes.text(0.03 * size, 0.07 * size, "E", ha="left", va="bottom", fontsize=10)
    axes.plot([-b / 2], [h / 2], "o", color="0.1", ms=4)
    axes.text(-b / 2 + 0.03 * size, h / 2 + 0.03 * size, "C", ha="left", va="bottom",
              fontsize=10)
    arrow(axes, (-b - 0.5 * size, 0.85 * h), (-b - 0.05 * size, 0.85 * h), color="C3")
    axes.text(-b - 0.3 * size, 0.85 * h + 0.04 * size, f"v = {format_number(p.v)} m/s",
              color="C3", ha="center", va="bottom", fontsize=10)
    dimension(axes, (-b, 0.0), (0.0, 0.0), f"b = {format_number(b)} m", offset=-0.14 * size,
              tick=0.03 * size, side=-1.0)
    dimension(axes, (0.0, 0.0), (0.0, h), f"h = {format_number(h)} m", offset=-0.22 * size,
              tick=0.03 * size, side=-1.0)
    axes.text(-b / 2, h + 0.04 * size, f"m = {format_number(p.m)} kg", ha="center",
              va="bottom", fontsize=10)
    describe(axes, "The crate slides to the right on the smooth floor; the low kerb stands "
                   "just in front of its front bottom edge E.")
    axes.set_xlim(-b - 0.75 * size, 0.75 * size)
    axes.set_ylim(-0.3 * size, h + 0.2 * size)
    return drawing


EXERCISE = Exercise(
    id="crate-tipping-at-kerb",
    title="Sliding crate caught by a kerb: does it tip over?",
    source="Section 3.3",
    topics=("impact about an edge", "angular momentum", "tipping over"),
    params=(
        Uniform("m", 5.0, 60.0, step=1.0, unit="kg", symbol="m"),
        Uniform("b", 0.2, 1.0, step=0.05, unit="m", symbol="b"),
        Uniform("h", 0.2, 1.2, step=0.05, unit="m", symbol="h"),
        Uniform("v", 0.5, 5.0, step=0.1, unit="m/s", symbol="v"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("the speed is clear of the least speed to tip over (by over 8 %)",
                   lambda p: abs(p.v / solve(p)["v_min"] - 1) > 0.08),
        Constraint("the three numeric answers differ from each other by over 5 %",
                   lambda p: numbers_apart([solve(p)[k] for k in ("omega", "J", "v_min")])),
    ),
    statement=r"""
A crate, modelled as a homogeneous box of mass $m$ = {{ m }}, length $b$ = {{ b }} in the
direction of motion and height $h$ = {{ h }}, slides without turning over a smooth floor
with $v$ = {{ v }}. Its front bottom edge E strikes a low kerb; the impact is perfectly
plastic and E neither rebounds nor slips, so the crate starts to turn about E.
Take $g$ = {{ g }}.

1. What is the crate's angular speed just after the impact?
2. How large is the impulse the kerb exerts on the crate?
3. What is the least sliding speed for which the crate tips over the kerb?
4. Does this crate tip over? (`yes` or `no`)
""",
    solution=r"""
During the short impact the kerb's impulse acts at E; gravity and the floor are not
impulsive. The impulse has no moment about E, so the angular momentum about E is kept
(impact of rigid bodies, Section 3.3).

1. **Angular speed.** Before: the crate translates, $H_E = m v\,\tfrac{h}{2}$ (the centre
   C is $h/2$ above the floor). After: it turns about E with
   $I_E = \tfrac{1}{3} m (b^2 + h^2)$ = {{ si.I_E }} kg·m². So
   $$\omega = \frac{m v h/2}{I_E} = \frac{3 v h}{2 (b^2 + h^2)},$$
   $\omega$ = {{ answers.omega }}.
2. **Kerb impulse.** After the impact C moves on a circle about E:
   $v_C' = \omega\,(h/2,\; b/2)$ (forward and up). The linear impulse balance
   $\hat F = m (v_C' - v_C)$ gives
   $\hat F_x = m(\omega h/2 - v)$ = {{ si.J_x }} N·s and $\hat F_y = m\,\omega b/2$ =
   {{ si.J_y }} N·s, so $|\hat F|$ = {{ answers.J }}.
3. **Tipping over.** Turning about E, C must rise from $h/2$ to $\tfrac12\sqrt{b^2+h^2}$
   above E, by $\Delta h$ = {{ si.rise }} m. The energy balance after the impact,
   $\tfrac12 I_E \omega^2 = m g\,\Delta h$, asks for $\omega \ge$ {{ si.omega_tip }} rad/s,
   and since $\omega$ grows in proportion to $v$,
   $$v_{\min} = \frac{2 I_E}{m h}\sqrt{\frac{2 m g\,\Delta h}{I_E}},$$
   $v_{\min}$ = {{ answers.v_min }}.
4. The crate slides with $v$ = {{ v }}, so the answer is **{{ answers.tips }}**.
   Kinetic energy is not kept in the impact: only the fraction
   $3h^2/(4(b^2+h^2))$ of it is left for turning.

**Check.** A thin slab ($b \to 0$) would turn with $3v/(2h)$ = {{ checks.thin_slab }} rad/s.
""",
    solve=solve,
    checks=(
        # angular momentum about E kept, I_E = m (b^2 + h^2)/3 written out
        Balance("angular momentum about E", lambda p, s: p.m * p.v * p.h / 2,
                lambda p, s: p.m * (p.b**2 + p.h**2) / 3 * s["omega"], name="angular_momentum"),
        # angular impulse about C: r_CE x F_hat = I_C (omega' - 0), omega' clockwise
        Balance("angular impulse about C",
                lambda p, s: p.b / 2 * s["J_y"] + p.h / 2 * s["J_x"],
                lambda p, s: -p.m * (p.b**2 + p.h**2) / 12 * s["omega"], name="angular_impulse"),
        # just tipping: 1/2 I_E omega^2 = m g Delta h at v = v_min, omega = 3 v h / (2(b^2+h^2))
        Balance("energy to tip over at v_min",
                lambda p, s: 0.5 * p.m * (p.b**2 + p.h**2) / 3
                * (1.5 * s["v_min"] * p.h / (p.b**2 + p.h**2))**2,
                lambda p, s: p.m * p.g * (np.hypot(p.b, p.h) - p.h) / 2, name="tipping_energy"),
        Limit("omega", {"b": 1e-9}, lambda p: 1.5 * p.v / p.h, name="thin_slab"),
    ),
    figure=figure, figure_to_scale=True,
    parts=(
        Numeric("omega", "angular speed after the impact", question=1, unit="rad/s", points=2,
                misconceptions=(
                    Misconception("moment of inertia about the centre",
                                  lambda p: p.m * p.v * p.h / 2 / (p.m * (p.b**2 + p.h**2) / 12),
                                  "The crate turns about E: I_E = m(b² + h²)/3, not the "
                                  "centroidal m(b² + h²)/12."),
                    Misconception("kinetic energy kept in the impact",
                                  lambda p: p.v * np.sqrt(p.m / _moment_edge(p)),
                                  "A plastic impact dissipates energy; the impulse at E has "
                                  "no moment about E, so use H_E = m v h/2 = I_E ω."),
                )),
        Numeric("J", "impulse of the kerb", question=2, unit="N*s", points=1,
                misconceptions=(
                    Misconception("horizontal part only", lambda p: abs(solve(p)["J_x"]),
                                  "The kerb also pushes up: C moves up at ω b/2 after the "
                                  "impact, so F̂_y = m ω b/2."),
                )),
        Numeric("v_min", "least speed to tip over", question=3, unit="m/s", points=2,
                misconceptions=(
                    Misconception("kinetic energy kept in the impact",
                                  lambda p: np.sqrt(2 * p.g * solve(p)["rise"]),
                                  "Energy is lost at the kerb: find ω after the impact from "
                                  "H_E, then ½ I_E ω² = m g Δh."),
                )),
        Options("tips", "does it tip over", question=4, options=("yes", "no"),
                misconceptions=(
                    Misconception("kinetic energy kept in the impact", _energy_kept_tips,
                                  "Only part of the kinetic energy survives the impact.",
                                  applies=lambda p: _energy_kept_tips(p) != solve(p)["tips"]),
                )),
    ),
)
