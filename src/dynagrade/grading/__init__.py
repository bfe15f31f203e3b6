"""Grading: a safe expression parser and the comparison of answers with references.

Public API::

    from dynagrade.grading import grade, Verdict, AnswerError
    from dynagrade.grading.spec import NumericSpec, SymbolicSpec, VectorSpec, ChoiceSpec, Variable, KnownWrong

Importing this package does not import pint or sympy: pint is loaded when an answer
or a part uses a unit, sympy only for the optional exact check of formulas; call
``prepare()`` before grading many answers to load them outside any verdict's budget.
"""

from .dispatch import grade
from .errors import AnswerError, SpecError
from .preparation import prepare
from .reading import evaluate_expression, read_number
from .spec import ChoiceSpec, KnownWrong, NumericSpec, SymbolicSpec, Variable, VectorSpec
from .verdict import Verdict

__all__ = ["grade", "prepare", "read_number", "evaluate_expression", "AnswerError", "SpecError", "Verdict", "NumericSpec", "SymbolicSpec",
           "VectorSpec", "ChoiceSpec", "Variable", "KnownWrong"]
