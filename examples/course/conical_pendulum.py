"""A conical pendulum: angular velocity and string tension (Section 1.2.1), its keys from
the course's own relations (_relations/, tested beside them)."""

from dynagrade.exercise import Constant, Exercise, Numeric, Uniform
from dynagrade.exercise.checks import Recompute

from ._relations import conical_pendulum_angular_velocity, conical_pendulum_tension


def solve(p):
    return {"omega": conical_pendulum_angular_velocity(p.L, p.theta, p.g),
            "S": conical_pendulum_tension(p.m, p.theta, p.g)}


EXERCISE = Exercise(
    id="conical-pendulum",
    title="Conical pendulum",
    source="Section 1.2.1",
    topics=("circular motion", "balance of linear momentum"),
    params=(
        Uniform("m", 0.5, 2.0, step=0.1, unit="kg", symbol="m"),
        Uniform("L", 0.5, 2.0, step=0.1, unit="m", symbol="L"),
        Uniform("theta", 20, 70, step=5, unit="deg", symbol=r"\theta"),
        Constant("g", 9.81, unit="m/s^2", symbol="g"),
    ),
    statement=r"""
A mass $m$ = {{ m }} on a string of length $L$ = {{ L }} circles steadily with the string
at the angle $\theta$ = {{ theta }} from the vertical; $g$ = {{ g }}.

1. With which angular velocity does it circle?
2. What is the tension in the string?
""",
    solution=r"""
The mass moves on a circle of radius $L\sin\theta$. Balance of linear momentum, radially
and vertically: $S\sin\theta = m\omega^2 L\sin\theta$ and $S\cos\theta = m g$.

1. Dividing the two, $\omega = \sqrt{g/(L\cos\theta)}$ = {{ answers.omega }}.
2. From the vertical balance, $S = m g/\cos\theta$ = {{ answers.S }}.
""",
    solve=solve,
    checks=(
        # the radial balance alone: S = m omega^2 L
        Recompute("S", lambda p, s: p.m * s["omega"] ** 2 * p.L, name="radial_balance"),
    ),
    parts=(
        Numeric("omega", "angular velocity", question=1, unit="rad/s"),
        Numeric("S", "tension", question=2, unit="N"),
    ),
)
