"""``grade(spec, expected, answer)``: one entry point for every kind of part (the kinds
and their functions: :mod:`.kinds`)."""

from __future__ import annotations

from ..i18n import _
from . import decorations
from .errors import AnswerError, SpecError
from .kinds import kind_of
from .verdict import Verdict, unreadable


def grade(spec, expected, answer: str) -> Verdict:
    """Grade ``answer`` against ``expected`` under ``spec``.

    ``expected`` is a float in ``spec.unit`` (NumericSpec), an expression string
    (SymbolicSpec), a tuple of floats in ``spec.unit`` (VectorSpec), or an option label
    or tuple of labels (ChoiceSpec). The answer's decorations (``v =``, ``ca.``, a final
    remark: :mod:`.decorations`) are left out first and the feedback says so. Never
    raises because of ``answer``: an answer that
    cannot be read gets a verdict with ``error`` set. Raises :class:`SpecError` only
    when the spec or the reference is unusable, whatever the answer.
    """
    if not isinstance(answer, str):
        return unreadable(_("the answer must be text"))
    grader = _grader(spec)
    stripped = decorations.strip(answer, decorations.mode_for(spec))
    try:
        verdict = grader(spec, expected, stripped.text)
    except SpecError:
        raise
    except AnswerError as error:
        verdict = unreadable(str(error))
    except RecursionError:
        verdict = unreadable(_("the answer is too deeply nested to read"))
    except MemoryError:
        verdict = unreadable(_("the answer is too large to read"))
    return decorations.annotated(verdict, stripped, spec)


def accepts(spec, expected, answer: str) -> bool:
    """Whether :func:`grade` calls ``answer`` correct: the same decision, made faster
    where a kind can skip what only a wrong answer needs (the misconception behind it,
    the feedback). For checking a part's own reference, near misses and misconceptions.
    Raises :class:`SpecError` where :func:`grade` does, except for a misconception whose
    value is unusable: only a wrong answer's feedback reads those."""
    kind = kind_of(spec)
    if kind is None or kind.accepts is None or not isinstance(answer, str):
        return grade(spec, expected, answer).correct
    try:
        return kind.function("accepts")(spec, expected,
                                         decorations.strip(answer, decorations.mode_for(spec)).text)
    except SpecError:
        raise
    except (AnswerError, RecursionError, MemoryError):
        return False


def _grader(spec):
    """The grading function of ``spec``'s kind (:mod:`.kinds`; a subclass grades as its
    base), imported on first use so that grading a number never loads the symbolic
    machinery."""
    kind = kind_of(spec)
    if kind is None:
        raise SpecError(f"unknown kind of part: {type(spec).__name__}")
    return kind.function("grade")
