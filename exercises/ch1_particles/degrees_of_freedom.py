"""Counting the degrees of freedom of free and constrained particles (Example 1.4,
eqs. 1.2 and 1.21)."""

from dynagrade.exercise import Choice, Exercise, Options
from dynagrade.exercise.checks import Recompute
from dynagrade.mechanics import kinematics

COUNTS = ("0", "1", "2", "3")
CASES = ("free particle", "particle sliding on a flat ground", "particle on a rigid link about a fixed point",
         "particle on a spring about a fixed point")
#: the cases by the words the statement's questions 1-4 give them
SHORT = ("free", "ground", "link", "spring")


def solve(p):
    d = int(p.d)
    return {
        "free": str(kinematics.degrees_of_freedom(d)),
        "ground": str(kinematics.degrees_of_freedom(d, 1)),
        "link": str(kinematics.degrees_of_freedom(d, 1)),
        "spring": str(kinematics.degrees_of_freedom(d)),
        "reaction": (CASES[1], CASES[2]),
    }


EXERCISE = Exercise(
    id="degrees-of-freedom",
    title="Degrees of freedom of constrained particles",
    source="Example 1.4",
    topics=("kinematics", "constrained motion", "degrees of freedom"),
    params=(Choice("d", (2, 3), symbol="d"),),
    statement="""
Consider a single particle in $d$ = {{ d }} dimensions (rotations of a particle are not
counted). How many degrees of freedom does it have when it

1. moves freely;
2. slides on a flat rigid ground (a line in 2D, a plane in 3D);
3. is attached to a fixed point O by a rigid, massless link;
4. is attached to a fixed point O by an elastic spring?
5. Which of these cases need a constraint (reaction) force to enforce the motion? Name
   the cases by their numbers 1–4.
""",
    solution=r"""
A particle in $d$ dimensions has $d$ degrees of freedom (eq. (1.2)); every kinematic
constraint removes one, so with $k$ constraints it has $d - k$ (eq. (1.21), Example 1.4).
Here $d$ = {{ d }}.

1. **Free particle.** No constraint: all $d$ coordinates are free, **{{ answers.free }}**.
2. **On flat ground.** The ground fixes the height, one constraint: $d - 1$ =
   **{{ answers.ground }}**.
3. **Rigid link.** The link fixes the distance $|r - r_O|$, one constraint: $d - 1$ =
   **{{ answers.link }}** (the particle moves on a {% if answers.link == "1" %}circle{% else %}sphere{% endif %}).
4. **Spring.** A spring stretches; it exerts a force but does not fix any coordinate, so
   there is no constraint: **{{ answers.spring }}**.
5. **Reaction forces.** Every kinematic constraint needs a constraint force to enforce it:
   the normal force of the ground and the force in the rigid link. The spring force is a
   given force, not a reaction. Cases: **{{ answers.reaction }}**.
""",
    solve=solve,
    checks=(
        # eq. (1.2) and (1.21): d DOFs, d - k with k constraints
        Recompute("free", lambda p, s: p.d, name="free_particle"),
        Recompute("ground", lambda p, s: p.d - 1, name="one_constraint"),
    ),
    parts=(
        Options("free", "free particle", question=1, options=COUNTS, points=1),
        Options("ground", "on the ground", question=2, options=COUNTS, points=1),
        Options("link", "on a rigid link", question=3, options=COUNTS, points=1),
        Options("spring", "on a spring", question=4, options=COUNTS, points=1),
        Options("reaction", "cases with a reaction force", question=5, options=CASES,
                multiple=True, points=2, numbered=True, aliases=dict(zip(SHORT, CASES)),
                constant_answer="the ground and the link are the constraints, in 2D as in 3D: "
                                "each needs a reaction force and the free particle and the "
                                "spring need none, which is what question 5 teaches"),
    ),
)
