"""A tossed book tumbling freely: principal moments, stable axes and wobble frequency
(Section 3.4.4)."""

import numpy as np

from dynagrade.exercise import (Constraint, Exercise, Misconception, Numeric, Options, Uniform,
                                per_draw)
from dynagrade.exercise.checks import Integrated, Recompute
from dynagrade.mechanics import euler_equations, inertia

AXES = ("e1", "e2", "e3")


def _moments(p):
    return np.diag(inertia.inertia_tensor_box(p.m, p.a, p.b, p.c))


def _largest(p):
    return int(np.argmax(_moments(p)))


@per_draw
def solve(p):
    moments = _moments(p)
    stable = tuple(AXES[k] for k in range(3)
                   if euler_equations.is_stable_rotation_axis(moments, k))
    return {
        "I_max": moments[_largest(p)],
        "stable": stable,
        "nu": euler_equations.wobble_frequency(moments, _largest(p), p.w),
        "I_1": moments[0], "I_2": moments[1], "I_3": moments[2],
        "axis_max": AXES[_largest(p)],
        "axis_min": AXES[int(np.argmin(moments))],
    }


def _box_moments(p):
    """A box a x b x c about its central axes: m (b^2 + c^2)/12, ... (Section 3.2)."""
    return np.array([p.b**2 + p.c**2, p.a**2 + p.c**2, p.a**2 + p.b**2]) * p.m / 12


def _euler(t, y, p):
    """Euler's equations without torque, I1 w1' = (I2 - I3) w2 w3 and cyclic."""
    i = _box_moments(p)
    return ((i[1] - i[2]) * y[1] * y[2] / i[0], (i[2] - i[0]) * y[2] * y[0] / i[1],
            (i[0] - i[1]) * y[0] * y[1] / i[2])


def _nudged_spin(p):
    """Spin w about the largest axis, the next axis's component zero and the third's
    nudged by 1e-6 w."""
    largest = int(np.argmax(_box_moments(p)))
    spin = np.zeros(3)
    spin[largest], spin[(largest + 2) % 3] = p.w, 1e-6 * p.w
    return spin


def _wobble(t, y, p):
    """The wobbling component that starts at zero: it is zero again half a period on."""
    return y[(int(np.argmax(_box_moments(p))) + 1) % 3]


EXERCISE = Exercise(
    id="torque-free-tumbling",
    title="A tumbling book: which rotations are stable?",
    source="Section 3.4.4",
    topics=("Euler equations", "torque-free rotation", "stability of rotation"),
    params=(
        Uniform("m", 0.2, 2.0, step=0.1, unit="kg", symbol="m"),
        Uniform("a", 2, 30, step=1, unit="cm", symbol="a"),
        Uniform("b", 2, 30, step=1, unit="cm", symbol="b"),
        Uniform("c", 2, 30, step=1, unit="cm", symbol="c"),
        Uniform("w", 5, 30, step=1, unit="rad/s", symbol=r"\omega_0"),
    ),
    constraints=(
        Constraint("the three edges differ clearly, so the principal moments are distinct",
                   lambda p: min(abs(p.a - p.b), abs(p.b - p.c), abs(p.a - p.c))
                   > 0.15 * max(p.a, p.b, p.c)),
        Constraint("the wobble frequency differs from the spin rate",
                   lambda p: abs(solve(p)["nu"] - p.w) > 0.04 * p.w),
    ),
    statement=r"""
A book is modelled as a homogeneous box of mass $m$ = {{ m }} with edges $a$ = {{ a }}
along $e_1$, $b$ = {{ b }} along $e_2$ and $c$ = {{ c }} along $e_3$ (body axes through its
centre). It is tossed into the air spinning about one of these axes; air drag is
negligible.

1. What is the largest principal moment of inertia about the centre?
2. About which axes is a steady spin stable against small disturbances? (List all of
   `e1`, `e2`, `e3` that are.)
3. The book spins with $\omega_0$ = {{ w }} about the axis of the largest moment and is
   disturbed slightly. With which angular frequency does its angular velocity wobble?
""",
    solution=r"""
With no moment about the centre of mass the book's rotation obeys the torque-free Euler
equations; linearised about a steady spin they tell which spins are stable (stability of
rotation, Section 3.4.4).

1. **Principal moments.** The body axes through the centre are principal axes of the box;
   about each the moment is $m/12$ times the sum of the squares of the two other edges:
   $$I_1 = \tfrac{1}{12} m (b^2 + c^2),\quad I_2 = \tfrac{1}{12} m (a^2 + c^2),\quad
   I_3 = \tfrac{1}{12} m (a^2 + b^2).$$
   With $m$ = {{ m }}, $a$ = {{ a }}, $b$ = {{ b }} and $c$ = {{ c }}: $I_1$ = {{ si.I_1 }},
   $I_2$ = {{ si.I_2 }} and $I_3$ = {{ si.I_3 }} kg·m². The largest is
   $I_{\max}$ = {{ answers.I_max }}, about `{{ si.axis_max }}`.
2. **Stable axes.** A small disturbance of a spin $\Omega$ about principal axis $k$ grows
   like $e^{\lambda t}$ with
   $$\lambda^2 = \Omega^2\,\frac{(I_k - I_i)(I_j - I_k)}{I_i\,I_j}.$$
   For the largest or the smallest moment the two factors have opposite signs,
   $\lambda^2 < 0$, and the disturbance only oscillates; for the intermediate moment
   $\lambda^2 > 0$ and it grows. The stable axes are therefore those of the largest
   (`{{ si.axis_max }}`) and the smallest (`{{ si.axis_min }}`) moment: **{{ answers.stable }}**.
3. **Wobble frequency.** About the axis of the largest moment, with $\omega_0$ = {{ w }},
   $$\nu = \omega_0\sqrt{\frac{(I_k - I_i)(I_k - I_j)}{I_i\,I_j} },$$
   which gives $\nu$ = {{ answers.nu }}.
""",
    solve=solve,
    checks=(
        Recompute("I_max", lambda p, s: max(_box_moments(p)), name="box_moments"),
        # the small wobble about the largest axis: half a period to the next zero
        Integrated("nu", _euler, _nudged_spin, lambda p, s: 4 * np.pi / s["nu"],
                   lambda t, y, p: np.pi / t, name="integrated_wobble", event=_wobble,
                   rtol=1e-4),
    ),
    parts=(
        Numeric("I_max", "largest principal moment", question=1, unit="kg*m^2", points=1,
                misconceptions=(
                    Misconception("edges squared of the largest edge only",
                                  lambda p: p.m * max(p.a, p.b, p.c) ** 2 / 12,
                                  "About an axis the box has m (sum of the squares of the "
                                  "two other edges)/12."),
                )),
        Options("stable", "stable axes", question=2, options=AXES, multiple=True, points=2),
        Numeric("nu", "wobble frequency", question=3, unit="rad/s", points=2,
                misconceptions=(
                    Misconception("spin rate", lambda p: p.w,
                                  "The wobble frequency is ω0 √((I_k − I_i)(I_k − I_j)/(I_i I_j))."),
                )),
    ),
)
