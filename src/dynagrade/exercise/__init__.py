"""The exercise model: parameters, constraints, statement, solver, answer parts, variants.

Usage, in an exercise file::

    from dynagrade.exercise import Exercise, Uniform, Constant, Numeric, Symbolic, Variable

    EXERCISE = Exercise(id="...", title="...", source="Example 1.9", params=(...),
                        statement="...", solve=solve, parts=(...))

See ``docs/authoring.md`` for the whole format.
"""

from ..grading.spec import Variable
from .apart import apart
from .loader import Bank, ExerciseFileError, load_file, open_bank
from .model import ConstraintError, Exercise, Variant
from .params import Choice, Constant, Constraint, ParamValues, Uniform, per_draw
from .parts import Misconception, Numeric, Options, Symbolic, Vector
from .seeds import exam_seed, student_seed

__all__ = [
    "Exercise", "Variant", "ConstraintError", "Uniform", "Choice", "Constant", "Constraint",
    "ParamValues", "per_draw", "apart", "Numeric", "Vector", "Symbolic", "Options", "Variable", "Misconception",
    "Bank", "ExerciseFileError", "load_file", "open_bank", "student_seed", "exam_seed",
]
