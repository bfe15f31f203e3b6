"""A pendulum hanging from a cart on a spring: mass and stiffness matrices from the
Lagrange equations and the coupled natural frequencies (Section 4.4.1)."""

from functools import cache

import numpy as np

from dynagrade.exercise import (Constant, Constraint, Exercise, Misconception, Numeric, Uniform,
                                per_draw)
from dynagrade.exercise.checks import Recompute
from dynagrade.exercise.figure import angle_arc, arrow, block, describe, ground, new_drawing, \
    spring, wall
from dynagrade.mechanics import multi_dof


@cache
def _linearized():
    """(K, M) as functions of (M, m, L, k, g): the core linearizes T and V about the rest
    position. Derived on first use, not when the exercise is loaded."""
    import sympy as sp

    from dynagrade.mechanics import equilibrium

    t = sp.Symbol("t")
    x, phi = sp.Function("x")(t), sp.Function("phi")(t)
    M, m, L, k, g = sp.symbols("M m L k g", positive=True)
    xb, yb = x + L * sp.sin(phi), -L * sp.cos(phi)          # the bob
    T = M * x.diff(t) ** 2 / 2 + m * (xb.diff(t) ** 2 + yb.diff(t) ** 2) / 2
    V = k * x**2 / 2 + m * g * yb
    rest = {x: 0, phi: 0}
    return (sp.lambdify([M, m, L, k, g], equilibrium.stiffness_matrix(V, [x, phi], rest)),
            sp.lambdify([M, m, L, k, g], equilibrium.linearized_mass_matrix(T, [x, phi], t, rest)))


@per_draw
def matrices(p):
    stiffness, mass = _linearized()
    args = (p.M, p.m, p.L, p.k, p.g)
    return np.array(stiffness(*args), dtype=float), np.array(mass(*args), dtype=float)


#: the angle at which the figure draws the pendulum, to show the positive sense of phi
_SHOWN_PHI = np.radians(25)


def figure(p):
    """The cart on its track tied to the wall by the spring, and the pendulum hanging from
    it, with the positive senses of the coordinates: x to the right from where the spring
    is relaxed (dashed), phi counter-clockwise from the downward vertical, drawn at 25°.
    Lengths in units of L; the cart's displacement and the angle are examples."""
    from dynagrade.exercise.figure import Circle

    width, height, wheel = 0.8, 0.3, 0.07
    rest, shift = 0.9, 0.3                    # the cart's left side: relaxed, and displaced
    left = rest + shift
    drawing, axes = new_drawing(4.2, 3.4)
    slot = left + width / 2                   # the track is open where the rod passes
    ground(axes, -0.1, slot - 0.2, hatch=0.05)
    ground(axes, slot + 0.2, left + width + 0.9, hatch=0.05)
    wall(axes, 0.0, 0.0, 0.75, side=-1.0, hatch=0.05)
    for x in (left + 0.2 * width, left + 0.8 * width):
        axes.add_patch(Circle((x, wheel), wheel, facecolor="0.3", edgecolor="0.1", lw=0.8))
    top = 2 * wheel + height
    block(axes, (left + width / 2, 2 * wheel + height / 2), width, height, "M")
    spring(axes, (0.0, 2 * wheel + height / 2), (left, 2 * wheel + height / 2), coils=6,
           width=0.1)
    axes.text(left / 2, 2 * wheel + height / 2 + 0.1, "k", ha="center", va="bottom",
              fontsize=10)
    axes.plot([rest + width / 2] * 2, [top + 0.05, top + 0.45], color="0.5", lw=0.8, ls="--")
    arrow(axes, (rest + width / 2, top + 0.35), (left + width / 2, top + 0.35), "x",
          offset=(0.0, 0.08), color="C3")
    pivot = np.array([left + width / 2, 2 * wheel + 0.05])     # under the cart's label
    bob = pivot + np.array([np.sin(_SHOWN_PHI), -np.cos(_SHOWN_PHI)])
    axes.plot([pivot[0], pivot[0]], [pivot[1], pivot[1] - 1.1], color="0.5", lw=0.6, ls="-.")
    axes.plot(*zip(pivot, bob), color="0.2", lw=1.8, zorder=2)
    axes.add_patch(Circle(tuple(pivot), 0.03, facecolor="white", edgecolor="0.1", zorder=4))
    axes.add_patch(Circle(tuple(bob), 0.08, facecolor="C0", edgecolor="0.1", zorder=3))
    axes.text(bob[0] + 0.13, bob[1], "m", ha="left", va="center", fontsize=10)
    middle = pivot + 0.5 * (bob - pivot)
    axes.text(middle[0] + 0.1, middle[1] + 0.05, "L", ha="left", va="center", fontsize=10)
    angle_arc(axes, tuple(pivot), 0.45, -np.pi / 2, -np.pi / 2 + _SHOWN_PHI, "φ",
              label_radius=0.6)
    describe(axes, "The cart is drawn displaced to the right of the dashed line where the "
             "spring is relaxed; the arrow x points to the right. The pendulum is drawn "
             "swung counter-clockwise from the downward vertical, the positive sense of φ.")
    axes.set_xlim(-0.2, left + width + 0.95)
    axes.set_ylim(pivot[1] - 1.2, top + 0.6)
    return drawing


def solve(p):
    K, M = matrices(p)
    w = multi_dof.natural_frequencies(K, M)
    return {"M11": M[0, 0], "M12": M[0, 1], "K22": K[1, 1], "omega1": w[0], "omega2": w[1],
            "M22": M[1, 1], "K11": K[0, 0]}


def _apart(p):
    w = multi_dof.natural_frequencies(*matrices(p))
    return all(abs(guess / wi - 1) >= 0.05
               for guess in (np.sqrt(p.k / p.M), np.sqrt(p.g / p.L)) for wi in w)


def _frequencies(p):
    """T = M x'^2 / 2 + m ((x' + L phi' cos(phi))^2 + (L phi' sin(phi))^2) / 2 and
    V = k x^2 / 2 - m g L cos(phi), linearized by hand (Section 4.4.1):
    M = [[M + m, m L], [m L, m L^2]], K = diag(k, m g L); det(K - w^2 M) = 0 is
    M m L^2 w^4 - (k m L^2 + (M + m) m g L) w^2 + k m g L = 0."""
    squares = np.roots([p.M * p.m * p.L**2, -(p.k * p.m * p.L**2 + (p.M + p.m) * p.m * p.g * p.L),
                        p.k * p.m * p.g * p.L])
    return np.sqrt(np.sort(squares.real))


EXERCISE = Exercise(
    id="cart-pendulum-matrices",
    title="Pendulum on a sprung cart: mass and stiffness matrices",
    source="Section 4.4.1",
    topics=("Lagrange equations", "mass matrix", "stiffness matrix", "coupled vibrations"),
    params=(
        Uniform("M", 1.0, 10.0, step=0.5, unit="kg", symbol="M"),
        Uniform("m", 0.5, 5.0, step=0.1, unit="kg", symbol="m"),
        Uniform("L", 0.2, 1.5, step=0.05, unit="m", symbol="L"),
        Uniform("k", 20, 500, step=5, unit="N/m", symbol="k"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    constraints=(
        Constraint("the pendulum is heavy enough to couple (m >= 0.25 M)", lambda p: p.m >= 0.25 * p.M),
        Constraint("L is not 1 m (else m g and m g L agree)", lambda p: abs(p.L - 1.0) >= 0.05),
        Constraint("the uncoupled guesses are at least 5 % off both frequencies", _apart),
    ),
    statement="""
A cart of mass $M$ = {{ M }} rolls without friction on a horizontal track and is tied to
a wall by a spring of stiffness $k$ = {{ k }}. From the cart hangs a pendulum: a point
mass $m$ = {{ m }} on a massless rod of length $L$ = {{ L }}; $g$ = {{ g }}. Use the
cart's displacement $x$ from the position where the spring is relaxed (positive to the
right) and the pendulum's angle $\\varphi$ from the downward vertical as generalized
coordinates, $\\varphi$ positive counter-clockwise: the bob is then at
$(x + L\\sin\\varphi,\\; -L\\cos\\varphi)$ from where the pivot is when the spring is relaxed.

1. Linearize the Lagrange equations about $x = 0$, $\\varphi = 0$ into
   $\\mathbf M\\ddot{\\mathbf q} + \\mathbf K\\mathbf q = \\mathbf 0$ with $\\mathbf q = (x, \\varphi)$.
   Give the entries $M_{11}$, $M_{12}$ and $K_{22}$.
2. What are the two natural angular frequencies $\\omega_1 < \\omega_2$?
""",
    solution=r"""
Two degrees of freedom, $q = (x, \varphi)$: we set up the kinetic and potential energies,
linearise the Lagrange equations about the rest position and solve the eigenvalue problem
(coupled vibrations, Section 4.4.1).

1. **Mass and stiffness matrices.** The bob sits at $(x + L\sin\varphi,\; -L\cos\varphi)$, so
   $$T = \tfrac{1}{2} M\dot x^2 + \tfrac{1}{2} m\bigl(\dot x^2 + 2L\dot x\dot\varphi\cos\varphi + L^2\dot\varphi^2\bigr),
   \qquad V = \tfrac{1}{2} k x^2 - m g L\cos\varphi .$$
   Linearised about $x = 0$, $\varphi = 0$ ($\cos\varphi \approx 1$ in $T$,
   $\cos\varphi \approx 1 - \varphi^2/2$ in $V$), $T = \tfrac{1}{2}\dot q^{\mathsf T}\mathbf M\dot q$ and
   $V = \tfrac{1}{2} q^{\mathsf T}\mathbf K q$ + const with
   $$M_{11} = M + m,\quad M_{12} = M_{2 1} = mL,\quad M_{2 2} = mL^2,\qquad
   K_{11} = k,\quad K_{12} = K_{2 1} = 0,\quad K_{2 2} = m g L .$$
   With $M$ = {{ M }}, $m$ = {{ m }}, $L$ = {{ L }}, $k$ = {{ k }} and $g$ = {{ g }}:
   $M_{11}$ = {{ answers.M11 }}, $M_{12}$ = {{ answers.M12 }} (the coupling: the cart's
   acceleration swings the pendulum) and $K_{2 2}$ = {{ answers.K22 }}; further
   $M_{2 2}$ = {{ si.M22 }} kg·m² and $K_{11}$ = {{ si.K11 }} N/m.
2. **Natural frequencies.** Non-trivial solutions $q = \hat q\cos\omega t$ need
   $\det(\mathbf K - \omega^2\mathbf M) = 0$:
   $$\bigl(k - \omega^2 (M + m)\bigr)\bigl(m g L - \omega^2 m L^2\bigr) - \omega^4 m^2 L^2 = 0,$$
   a quadratic in $\omega^2$. Its two roots give $\omega_1$ = {{ answers.omega1 }} and
   $\omega_2$ = {{ answers.omega2 }}. Neither is $\sqrt{k/M}$ or $\sqrt{g/L}$: the
   coupling moves both.
""",
    solve=solve,
    checks=(
        Recompute("M11", lambda p, s: p.M + p.m, name="mass_by_hand"),
        Recompute("M12", lambda p, s: p.m * p.L, name="coupling_by_hand"),
        Recompute("K22", lambda p, s: p.m * p.g * p.L, name="gravity_stiffness"),
        Recompute("omega1", lambda p, s: _frequencies(p)[0], name="lower_root"),
        Recompute("omega2", lambda p, s: _frequencies(p)[1], name="upper_root"),
    ),
    figure=figure,
    parts=(
        Numeric("M11", "mass matrix entry M11", question=1, unit="kg", points=1,
                misconceptions=(Misconception("cart only", lambda p: p.M, "The bob moves with the cart: M11 = M + m."),)),
        Numeric("M12", "mass matrix entry M12", question=1, unit="kg*m", points=1,
                misconceptions=(Misconception("uncoupled", lambda p: 0.0,
                                              "The bob's velocity contains x' + L phi' cos(phi): T has the term m L x' phi'."),)),
        Numeric("K22", "stiffness matrix entry K22", question=1, unit="N*m", points=1,
                misconceptions=(Misconception("m g", lambda p: p.m * p.g, "V = -m g L cos(phi): K22 = m g L."),)),
        Numeric("omega1", "lower natural frequency", question=2, unit="rad/s", points=2,
                misconceptions=(
                    Misconception("uncoupled cart", lambda p: np.sqrt(p.k / p.M), "The two motions are coupled through M12."),
                    Misconception("uncoupled pendulum", lambda p: np.sqrt(p.g / p.L), "The two motions are coupled through M12."),
                )),
        Numeric("omega2", "higher natural frequency", question=2, unit="rad/s", points=2,
                misconceptions=(
                    Misconception("uncoupled cart", lambda p: np.sqrt(p.k / p.M), "Solve det(K - omega^2 M) = 0."),
                    Misconception("uncoupled pendulum", lambda p: np.sqrt(p.g / p.L), "Solve det(K - omega^2 M) = 0."),
                )),
    ),
)
