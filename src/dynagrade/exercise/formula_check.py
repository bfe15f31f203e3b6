"""Formulas an exercise file writes that the grader could not read.

A Symbolic part's ``expected`` formula (and each of its misconceptions written as a
formula) is the author's text, read by the grader's own parser in the part's declared
variables only when a student's answer is graded. A name that is not one of those
variables (``k`` in ``2*x*k`` when only ``x`` is declared) would end grading, or make a
misconception that never matches; the loader reports it when the file is loaded.

Usage::

    for part_name, problem in formula_problems(exercise):
        ...   # "the expected formula '2*x*k' cannot be read: unknown name 'k' ..."
"""

from __future__ import annotations

from collections.abc import Iterator


def formula_problems(exercise) -> Iterator[tuple[str, str]]:
    """``(part name, problem)`` for every formula of the exercise's Symbolic parts that
    the grader cannot read in the part's variables."""
    # a part that declares variables holds formulas in them (the Symbolic kind)
    formulas = [(part, "expected formula", getattr(part, "expected", None))
                for part in exercise.parts if getattr(part, "variables", None) is not None]
    formulas += [(part, f"misconception {m.name!r}", m.value)
                 for part, _, _ in list(formulas) for m in part.misconceptions
                 if isinstance(m.value, str)]
    for part, what, text in formulas:
        problem = _unreadable(text, tuple(part.variables))
        if problem:
            yield part.name, f"the {what} {text!r} cannot be read: {problem}"


def _unreadable(text, variables: tuple[str, ...]) -> str | None:
    """Why the grader cannot read ``text`` in ``variables``, or ``None``."""
    from ..grading.errors import AnswerError
    from ..grading.parser import parse_expression

    if not isinstance(text, str) or not text.strip():
        return "a formula must be a non-empty string"
    try:
        parse_expression(text, variables)
    except AnswerError as error:
        return str(error).splitlines()[0]
    return None
