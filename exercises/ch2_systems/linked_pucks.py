"""Two pucks joined by a light rigid rod on an air table: the rod's constraint fixes the
velocity component a measurement leaves open, and then the centre of mass, the rod's turning
rate and the motion relative to C follow (kinematics of systems of particles, Section 2.1,
with the constraint count of eq. (1.21))."""

import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, Vector, per_draw
from dynagrade.exercise.apart import numbers_apart
from dynagrade.exercise.checks import Balance, Recompute
from dynagrade.exercise.figure import Circle, angle_arc, arrow, describe, new_drawing
from dynagrade.mechanics import systems


@per_draw
def solve(p):
    vA = (p.aA, p.bA)
    yB = float(systems.rigid_link_second_velocity(p.theta, vA, p.uB))
    vB = (p.uB, yB)
    masses = (p.mA, p.mB)
    relative = systems.positions_relative_to_centre_of_mass(masses, (vA, vB))
    return {
        "yB": yB,
        "v_C": tuple(float(c) for c in systems.centre_of_mass_velocity(masses, (vA, vB))),
        "omega": float(systems.rigid_link_angular_velocity(p.theta, p.L, vA, vB)),
        "rel_B": float(np.linalg.norm(relative[1])),
        "M": systems.total_mass(masses),             # for the worked solution
    }


def _pivoted_rotation(p):
    """The second route: a rigid link moves puck B as vB = vA + omega e_z x (rB - rA)
    (the link turning about puck A); its e_x part uB - aA = -omega L sin(theta) fixes
    omega. Returns (omega, yB)."""
    omega = -(p.uB - p.aA) / (p.L * np.sin(p.theta))
    return omega, p.bA + omega * p.L * np.cos(p.theta)


def _speed_of_A_relative_to_C(p, s):
    return float(np.hypot(p.aA - s["v_C"][0], p.bA - s["v_C"][1]))


def _keys_apart(p) -> bool:
    """The numbers asked for (the components of v_C among them, in SI) differ pairwise by
    over 5 % in magnitude, and none is close to zero (0.1 in SI)."""
    s = solve(p)
    values = (abs(s["yB"]), abs(s["omega"]), s["rel_B"], *(abs(c) for c in s["v_C"]))
    return min(values) >= 0.1 and numbers_apart(values)


def figure(p):
    """Top view to scale: puck A at the origin of the drawing, the rod of length L at the
    angle theta to e_x, puck B at its end; A's velocity and the measured e_x part of B's
    (0.4 m of drawing per m/s). The labels carry letters, not digits, so that no label
    reads as a number of the variant."""
    scale = 0.4
    drawing, axes = new_drawing(4.6, 3.8)
    r2 = p.L * np.array([np.cos(p.theta), np.sin(p.theta)])
    v_a, u_b = scale * np.array([p.aA, p.bA]), scale * np.array([p.uB, 0.0])
    points = np.array([[0.0, 0.0], r2, v_a, r2 + u_b])
    low, high = points.min(axis=0) - 0.45, points.max(axis=0) + 0.45
    # the e_x, e_y triad (0.25 long) in the corner farthest from the rod and the arrows
    drawn = np.concatenate([np.outer(np.linspace(0, 1, 12), end - start) + start
                            for start, end in ((np.zeros(2), r2), (np.zeros(2), v_a),
                                               (r2, r2 + u_b))])
    triad = max((np.array([x, y]) for x in (low[0] + 0.05, high[0] - 0.4)
                 for y in (low[1] + 0.05, high[1] - 0.35)),
                key=lambda corner: np.min(np.hypot(*(drawn - corner - 0.12).T)))
    gap = float(max(high - low)) / 14          # a label's distance from what it names
    axes.plot([0.0, r2[0]], [0.0, r2[1]], color="0.3", lw=2.0)
    along = r2 / p.L

    def unit(vector):
        return np.asarray(vector, float) / max(float(np.hypot(*vector)), 1e-12)

    def freest(candidates, taken):
        """Of the candidate directions, the one farthest in angle from everything taken."""
        return max((unit(c) for c in candidates),
                   key=lambda c: min(np.arccos(np.clip(np.dot(c, t), -1, 1)) for t in taken))

    radii = (0.05 + 0.02 * p.mA, 0.05 + 0.02 * p.mB)
    # each velocity arrow starts at its puck's rim, so the puck does not hide it (its length
    # stays 0.4 m of drawing per m/s), labelled beside its middle on the side away from the
    # rod: at the tip the label could land on the other puck
    across = unit((-v_a[1], v_a[0]))
    if np.dot(across, along) > 0:
        across = -across
    start_a = radii[0] * unit(v_a)
    arrow(axes, tuple(start_a), tuple(start_a + v_a), color="C3")
    axes.text(*(start_a + v_a / 2 + gap * across), "$v_A$", ha="center", va="center",
              fontsize=10, color="C3")
    start_b = r2 + radii[1] * unit(u_b)
    arrow(axes, tuple(start_b), tuple(start_b + u_b), color="green")
    axes.text(*(start_b + u_b / 2 + np.array([0.0, gap])), "$\\dot x_B$", ha="center",
              va="center", fontsize=10, color="green")
    # the pucks' names where nothing else is drawn: A below its θ arc, B off the rod, its
    # arrow and that arrow's label
    name_a = freest(((-1.0, -1.0), (0.0, -1.0), (1.0, -1.0)),
                    (unit(v_a), unit(v_a / 2 + gap * across), np.array([1.0, 0.0])))
    name_b = freest(((-1.0, 1.0), (0.0, 1.0), (1.0, 1.0), (-1.0, 0.0), (1.0, 0.0)),
                    (-along, unit(u_b), unit(u_b / 2 + np.array([0.0, gap]))))
    for point, radius, name, direction in (((0.0, 0.0), radii[0], "A", name_a),
                                           (r2, radii[1], "B", name_b)):
        axes.add_patch(Circle(point, radius, facecolor="C0", edgecolor="0.1", lw=1.0,
                              zorder=3))
        axes.text(*(np.asarray(point) + (radius + gap) * direction), name, ha="center",
                  va="center", fontsize=10)
    axes.plot([0.0, 0.35], [0.0, 0.0], color="0.5", lw=0.8, ls="-.")
    angle_arc(axes, (0.0, 0.0), 0.22, 0.0, p.theta, "θ", label_radius=0.32)
    axes.text(*(r2 / 2 + gap * np.array([-np.sin(p.theta), np.cos(p.theta)])), "L",
              ha="center", va="center", fontsize=10)
    x0, y0 = triad
    arrow(axes, (x0, y0), (x0 + 0.25, y0), color="0.3")
    arrow(axes, (x0, y0), (x0, y0 + 0.25), color="0.3")
    axes.text(x0 + 0.3, y0, "$e_x$", ha="left", va="center", fontsize=10, color="0.3")
    axes.text(x0, y0 + 0.3, "$e_y$", ha="center", va="bottom", fontsize=10, color="0.3")
    describe(axes, "Seen from above: puck A and puck B at the ends of the rod; the red arrow "
             "is the velocity of A, the green arrow the measured e_x part of the velocity of B.")
    axes.set_xlim(low[0], high[0])
    axes.set_ylim(low[1], high[1])
    return drawing


EXERCISE = Exercise(
    id="linked-pucks",
    title="Two pucks joined by a rigid rod",
    source="Section 2.1",
    topics=("kinematics of systems of particles", "kinematic constraint", "centre of mass"),
    params=(
        Uniform("mA", 0.2, 2.0, step=0.1, unit="kg", symbol="m_A"),
        Uniform("mB", 0.2, 2.0, step=0.1, unit="kg", symbol="m_B"),
        Uniform("L", 0.3, 1.5, step=0.05, unit="m", symbol="L"),
        Uniform("theta", 20, 160, step=1, unit="deg", symbol=r"\theta"),
        Uniform("aA", -2.0, 2.0, step=0.1, unit="m/s", symbol=r"\dot x_A"),
        Uniform("bA", -2.0, 2.0, step=0.1, unit="m/s", symbol=r"\dot y_A"),
        Uniform("uB", -2.0, 2.0, step=0.1, unit="m/s", symbol=r"\dot x_B"),
    ),
    constraints=(
        Constraint("the pucks' masses differ by 30 % of the lighter one at least",
                   lambda p: max(p.mA, p.mB) >= 1.3 * min(p.mA, p.mB)),
        Constraint("the rod turns: |uB - aA| >= 0.3 m/s", lambda p: abs(p.uB - p.aA) >= 0.3),
        Constraint("pucks on an air table: B moves at most at 3 m/s (a steep rod's cot theta "
                   "made up to 10 m/s)",
                   lambda p: np.hypot(p.uB, solve(p)["yB"]) <= 3.0),
        Constraint("the answers are clear of zero and differ pairwise by over 5 %", _keys_apart),
    ),
    statement=r"""
Two small pucks A and B, $m_A$ = {{ mA }} and $m_B$ = {{ mB }}, glide on a horizontal air
table, joined by a light rigid rod of length $L$ = {{ L }}. In the table's fixed frame
($e_x$ to the right, $e_y$ up the page, both horizontal) the rod, pointing from A to B, makes
the angle $\theta$ = {{ theta }} with $e_x$ (counter-clockwise). At this instant A moves
with $v_A = \dot x_A e_x + \dot y_A e_y$, $\dot x_A$ = {{ aA }}, $\dot y_A$ = {{ bA }}, and
a camera measures only the $e_x$ component of B's velocity, $\dot x_B$ = {{ uB }}.

1. What is the $e_y$ component $\dot y_B$ of B's velocity?
2. What is the velocity $v_C$ of the centre of mass? (as `[e_x part, e_y part]`)
3. At what rate $\omega$ does the rod turn (in rad/s, counter-clockwise positive)?
4. How fast does B move relative to the centre of mass?
""",
    solution=r"""
Two particles in the plane have $2 \cdot 2 = 4$ degrees of freedom; the rigid rod is one
kinematic constraint, $|r_B - r_A| = L$, which leaves 3 (eq. (1.21) counted for the system).
Its time derivative, $(r_B - r_A)\cdot(v_B - v_A) = 0$, fixes the component the camera
misses: the rod can only turn, so the relative velocity is perpendicular to it.

1. **Missing component.** With $r_B - r_A = L(\cos\theta, \sin\theta)$:
   $(\dot x_B - \dot x_A)\cos\theta + (\dot y_B - \dot y_A)\sin\theta = 0$, so
   $\dot y_B = \dot y_A - (\dot x_B - \dot x_A)\cot\theta$ = {{ answers.yB }}.
2. **Centre of mass.** $v_C = (m_A v_A + m_B v_B)/M$ with $M$ = {{ si.M }} kg (Section 2.1):
   $v_C$ = {{ answers.v_C }}.
3. **Turning rate.** Seen from A, B moves on a circle of radius $L$: by eq. (1.36),
   $v_B - v_A = L\omega\,e_\varphi$ with $e_\varphi = (-\sin\theta, \cos\theta)$, so
   $\omega = (v_B - v_A)\cdot e_\varphi/L$ = {{ answers.omega }}.
4. **Relative to C.** $v_B - v_C = \frac{m_A}{M}(v_B - v_A)$, whose length is
   {{ answers.rel_B }}.
5. **Check.** The momenta relative to C cancel: $m_A|v_A - v_C|$ =
   {{ checks.momentum_about_C }} kg·m/s, the same as $m_B|v_B - v_C|$.
""",
    solve=solve,
    checks=(
        # the rod turning about puck A: vB = vA + omega e_z x (rB - rA)
        Recompute("yB", lambda p, s: _pivoted_rotation(p)[1], name="rotation_about_puck_A"),
        Recompute("omega", lambda p, s: _pivoted_rotation(p)[0], name="rate_from_e1_part"),
        # v_C as the mass-weighted mean, written out
        Recompute("v_C", lambda p, s: ((p.mA * p.aA + p.mB * p.uB) / (p.mA + p.mB),
                                       (p.mA * p.bA + p.mB * s["yB"]) / (p.mA + p.mB)),
                  name="weighted_mean_velocity", atol=1e-12),
        # no momentum relative to C: mA |vA - vC| = mB |vB - vC|
        Balance("momenta relative to C", lambda p, s: p.mA * _speed_of_A_relative_to_C(p, s),
                lambda p, s: p.mB * s["rel_B"], name="momentum_about_C"),
    ),
    figure=figure,
    figure_to_scale=True,
    parts=(
        Numeric("yB", "e_y component of puck B's velocity", question=1, unit="m/s", points=2,
                misconceptions=(
                    Misconception("the rod ignored", lambda p: p.bA,
                                  "The rod keeps |r_B − r_A| = L: its rate "
                                  "(r_B − r_A)·(v_B − v_A) = 0 links the components.",
                                  applies=lambda p: abs((p.uB - p.aA) / np.tan(p.theta))
                                  > 0.03 * abs(solve(p)["yB"])),
                    Misconception("tan for cot",
                                  lambda p: p.bA - (p.uB - p.aA) * np.tan(p.theta),
                                  "Solve (ẋ_B − ẋ_A)cos θ + (ẏ_B − ẏ_A)sin θ = 0 for ẏ_B: the "
                                  "factor is cos θ / sin θ.",
                                  applies=lambda p: abs(abs(np.tan(p.theta)) - 1) > 0.1),
                )),
        Vector("v_C", "velocity of the centre of mass", question=2, unit="m/s", size=2, points=1,
               misconceptions=(
                   Misconception("plain mean of the velocities",
                                 lambda p: ((p.aA + p.uB) / 2, (p.bA + solve(p)["yB"]) / 2),
                                 "Weight each velocity with its mass: "
                                 "v_C = (m_A v_A + m_B v_B)/M."),
               )),
        Numeric("omega", "turning rate of the rod", question=3, unit="rad/s", points=2,
                misconceptions=(
                    Misconception("puck A taken as a fixed pivot",
                                  lambda p: (np.cos(p.theta) * solve(p)["yB"] - np.sin(p.theta) * p.uB) / p.L,
                                  "Puck A moves too: only the relative velocity v_B − v_A turns "
                                  "the rod, ω = (v_B − v_A)·e_φ / L.",
                                  applies=lambda p: abs(p.aA * np.sin(p.theta) - p.bA * np.cos(p.theta))
                                  > 0.03 * abs(solve(p)["omega"]) * p.L),
                )),
        Numeric("rel_B", "speed of puck B relative to C", question=4, unit="m/s", points=1,
                misconceptions=(
                    Misconception("masses swapped",
                                  lambda p: p.mB / (p.mA + p.mB) * np.hypot(p.uB - p.aA, solve(p)["yB"] - p.bA),
                                  "C lies nearer the heavier puck, which moves less relative to "
                                  "it: B's share of v_B − v_A is m_A/M."),
                )),
    ),
)
