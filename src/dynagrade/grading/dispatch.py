"""``grade(spec, expected, answer)``: one entry point for every kind of part."""

from __future__ import annotations

from .errors import AnswerError, SpecError
from .spec import ChoiceSpec, NumericSpec, SymbolicSpec, VectorSpec
from .verdict import Verdict, unreadable


def grade(spec, expected, answer: str) -> Verdict:
    """Grade ``answer`` against ``expected`` under ``spec``.

    ``expected`` is a float in ``spec.unit`` (NumericSpec), an expression string
    (SymbolicSpec), a tuple of floats in ``spec.unit`` (VectorSpec), or an option label
    or tuple of labels (ChoiceSpec). Never raises because of ``answer``: an answer that
    cannot be read gets a verdict with ``error`` set. Raises :class:`SpecError` only
    when the spec or the reference is unusable, whatever the answer.
    """
    if not isinstance(answer, str):
        return unreadable("the answer must be text")
    try:
        if isinstance(spec, NumericSpec):
            from .numeric import grade_numeric

            return grade_numeric(spec, expected, answer)
        if isinstance(spec, SymbolicSpec):
            from .symbolic import grade_symbolic

            return grade_symbolic(spec, expected, answer)
        if isinstance(spec, VectorSpec):
            from .vector import grade_vector

            return grade_vector(spec, expected, answer)
        if isinstance(spec, ChoiceSpec):
            from .choice import grade_choice

            return grade_choice(spec, expected, answer)
    except SpecError:
        raise
    except AnswerError as error:
        return unreadable(str(error))
    except RecursionError:
        return unreadable("the answer is too deeply nested to read")
    except MemoryError:
        return unreadable("the answer is too large to read")
    raise SpecError(f"unknown kind of part: {type(spec).__name__}")
