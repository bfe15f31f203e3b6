"""A puck sliding and spinning on ice: its angular momentum about its centre and about a
fixed point beside its path, and where it vanishes (Section 3.2.4)."""


import numpy as np

from dynagrade.exercise import Constraint, Exercise, Misconception, Numeric, Uniform, per_draw
from dynagrade.exercise.apart import numbers_apart
from dynagrade.exercise.checks import Recompute
from dynagrade.exercise.figure import Circle, arrow, describe, dimension, new_drawing
from dynagrade.exercise.numbers import format_number
from dynagrade.mechanics import inertia, rigid_kinetics


def _moment(p):
    return inertia.inertia_tensor_disk(p.m, p.R)[2, 2]


def _about_b(p, moment):
    """e3 component of H about B, the point y_B off the path (C at the origin)."""
    return rigid_kinetics.rigid_body_angular_momentum_about_point(
        np.diag([0.0, 0.0, moment]), [0.0, 0.0, p.omega], p.m, [0.0, -p.y_B, 0.0],
        [p.v, 0.0, 0.0])[2]


@per_draw
def solve(p):
    return {
        "H_C": rigid_kinetics.rigid_body_angular_momentum(
            inertia.inertia_tensor_disk(p.m, p.R), [0.0, 0.0, p.omega])[2],
        "H_B": _about_b(p, _moment(p)),
        "y_0": rigid_kinetics.zero_angular_momentum_offset(_moment(p), p.omega, p.m, p.v),
    }


def _apart(p):
    s = solve(p)
    return numbers_apart((s["H_C"], s["H_B"], s["y_0"]))


def _particles(p):
    """H about B summed over mass points of the disk (Section 2.2.3): Gauss-Legendre rings
    in r (exact for the r^3 of the disk's integral) times 16 equal angles."""
    nodes, weights = np.polynomial.legendre.leggauss(4)
    radii = p.R * (nodes + 1) / 2
    ring_masses = p.m * weights * radii / p.R     # m 2 r dr / R^2 with dr = R w / 2
    total = 0.0
    for angle in np.arange(16) * np.pi / 8:
        x, y = radii * np.cos(angle), radii * np.sin(angle)
        vx, vy = p.v - p.omega * y, p.omega * x       # v_C + omega e3 x r
        total += np.sum(ring_masses / 16 * (x * vy - (y - p.y_B) * vx))
    return total


def figure(p):
    """Schematic: the path along e1, the puck moving right and spinning, B beside the path."""
    drawing, axes = new_drawing(4.6, 2.8)
    side = np.sign(p.y_B)
    axes.plot([-2.2, 2.2], [0.0, 0.0], color="0.5", lw=0.8, ls="--")
    axes.add_patch(Circle((0.0, 0.0), 0.35, facecolor="0.2", edgecolor="0.1", lw=1.0))
    axes.text(-0.4, side * 0.4, "C", ha="right", va="center", fontsize=10)
    # v on B's side of the path, the spin (a counter-clockwise arrow) on the other side
    arrow(axes, (0.45, 0.0), (1.3, 0.0), f"v = {format_number(p.v)} m/s", offset=(0.0, side * 0.2),
          color="C3")
    ends = ((0.4, -side * 0.4), (-0.4, -side * 0.4))
    start, end = ends if side < 0 else ends[::-1]
    axes.annotate("", xy=end, xytext=start,
                  arrowprops={"arrowstyle": "-|>", "connectionstyle": "arc3,rad=0.5",
                              "color": "0.2", "lw": 1.0, "shrinkA": 0, "shrinkB": 0})
    axes.text(0.0, -side * 0.9, f"ω = {format_number(p.omega)} rad/s", ha="center",
              va="center", fontsize=10)
    axes.plot([-1.5], [side * 1.0], "o", color="C2", ms=5)
    axes.text(-1.6, side * 1.0, "B", ha="right", va="center", fontsize=10)
    dimension(axes, (-1.5, 0.0), (-1.5, side * 1.0), f"|y_B| = {format_number(abs(p.y_B))} m",
              offset=0.0, tick=0.05, side=side)
    axes.text(2.2, side * 1.05, f"m = {format_number(p.m)} kg, R = {format_number(p.R)} m",
              ha="right", va="center", fontsize=10)
    describe(axes, "The puck slides to the right along the dashed path and spins "
                   "counter-clockwise. B is fixed on the ice "
                   + ("to the left of the path." if p.y_B > 0 else "to the right of the path."))
    axes.set_xlim(-2.6, 2.4)
    axes.set_ylim(-1.4, 1.4)
    return drawing


EXERCISE = Exercise(
    id="spinning-puck-angular-momentum",
    title="A sliding, spinning puck: angular momentum about a point beside its path",
    source="Section 3.2.4",
    topics=("angular momentum transfer formula", "plane motion"),
    params=(
        Uniform("m", 0.1, 0.5, step=0.01, unit="kg", symbol="m"),
        Uniform("R", 0.05, 0.15, step=0.005, unit="m", symbol="R"),
        Uniform("v", 0.5, 4.0, step=0.1, unit="m/s", symbol="v"),
        Uniform("omega", 5.0, 40.0, step=1.0, unit="rad/s", symbol=r"\omega"),
        Uniform("y_B", -0.5, 0.5, step=0.01, unit="m", symbol="y_B"),
    ),
    constraints=(
        Constraint("B lies clearly beside the path (|y_B| > 2 R)", lambda p: abs(p.y_B) > 2 * p.R),
        Constraint("spin and orbital parts both count (ratio between 0.15 and 6)",
                   lambda p: 0.15 * abs(p.m * p.v * p.y_B) < _moment(p) * p.omega
                   < 6.0 * abs(p.m * p.v * p.y_B)),
        Constraint("no two answers share their number (5 % apart)", _apart),
    ),
    statement=r"""
A homogeneous puck, a disk of mass $m$ = {{ m }} and radius $R$ = {{ R }}, slides on
frictionless ice. Its centre C moves along the $e_1$ axis with $v$ = {{ v }} while the
puck spins counter-clockwise (seen from above, about $e_3$) at $\omega$ = {{ omega }}.
The fixed point B lies on the ice at $y_B$ = {{ y_B }} along $e_2$ from the path
($e_3 = e_1 \times e_2$ points up; $y_B > 0$ is to the left of the direction of motion).
Give $e_3$ components, counter-clockwise positive.

1. What is the angular momentum about C?
2. What is the angular momentum about B at the instant C passes closest to B?
3. About the points of which line parallel to the path does the angular momentum vanish?
   Give the line's $e_2$ coordinate $y_0$.
""",
    solution=r"""
The angular momentum about any point B follows from that about the centre of mass with
the transfer formula (Section 3.2.4),
$$H_B = H_C + r_{BC} \times m\,v_C .$$
Here $m$ = {{ m }}, $R$ = {{ R }}, $v$ = {{ v }}, $\omega$ = {{ omega }}.

1. **About C.** $I_C = \tfrac{1}{2} m R^2$ for the disk, so
   $H_C = \tfrac{1}{2} m R^2 \omega$ = {{ answers.H_C }}.
2. **About B.** $r_{BC} = -y_B\,e_2$ (plus a part along $e_1$, which has no cross product
   with $v_C = v\,e_1$), and $-y_B\,e_2 \times m v\,e_1 = m v\,y_B\,e_3$:
   $$H_B = \tfrac{1}{2} m R^2 \omega + m v\,y_B ,$$
   with $y_B$ = {{ y_B }}: $H_B$ = {{ answers.H_B }}. The same holds at every other
   instant: no force acts in the plane of the ice, so $H_B$ is conserved.
3. **Where it vanishes.** $H_B = 0$ for $y_B = y_0 = -\dfrac{R^2\omega}{2 v}$
   = {{ answers.y_0 }}: on that line the orbital part cancels the spin.

**Check.** Without the transfer formula: summing $r_B \times m_i v_i$ over the disk cut into
rings of mass points, each moving with $v_C + \omega \times r_{Ci}$, gives
$H_B$ = {{ checks.sum_over_mass_points }} kg·m²/s again.
""",
    solve=solve,
    figure=figure,
    checks=(
        # the disk as mass points, sum of r_B x m v (no transfer formula)
        Recompute("H_B", lambda p, s: _particles(p), name="sum_over_mass_points", rtol=1e-9),
        Recompute("y_0", lambda p, s: -p.R**2 * p.omega / (2 * p.v), name="zero_by_hand"),
    ),
    parts=(
        Numeric("H_C", "angular momentum about C", question=1, unit="kg*m^2/s", points=1,
                misconceptions=(
                    Misconception("disk taken as a ring", lambda p: p.m * p.R**2 * p.omega,
                                  "A homogeneous disk has I_C = ½ m R²."),
                )),
        Numeric("H_B", "angular momentum about B", question=2, unit="kg*m^2/s", points=2,
                misconceptions=(
                    Misconception("transfer term with the wrong sign",
                                  lambda p: 2 * solve(p)["H_C"] - solve(p)["H_B"],
                                  "r_BC = −y_B e2 and −y_B e2 × m v e1 = + m v y_B e3."),
                    Misconception("spin forgotten", lambda p: p.m * p.v * p.y_B,
                                  "H_B also holds the spin about C: add I_C ω."),
                    Misconception("spin shifted with the parallel-axis theorem",
                                  lambda p: (_moment(p) + p.m * p.y_B**2) * p.omega,
                                  "B is not a point of a body turning about B: the transfer "
                                  "term is r_BC × m v_C, not m y_B² ω."),
                )),
        Numeric("y_0", "e2 coordinate of the line where H vanishes", question=3, unit="m",
                points=1,
                misconceptions=(
                    Misconception("wrong side", lambda p: -solve(p)["y_0"],
                                  "Counter-clockwise spin is cancelled by an orbital part "
                                  "m v y_B < 0: the line lies to the right of the path."),
                )),
    ),
)
