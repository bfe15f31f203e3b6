"""Formulas an exercise file writes that the grader could not read.

A Symbolic part's ``expected`` formula (and each of its misconceptions written as a
formula) is the author's text, read by the grader's own parser in the part's declared
variables only when a student's answer is graded. A name that is not one of those
variables (``k`` in ``2*x*k`` when only ``x`` is declared) would end that grading with
an error; the loader reports it when the file is loaded, and ``dynagrade list`` from the
file's text (:mod:`.listing` reads the same formulas).

A formula is given as ``(part name, what, text, variable names)``, ``what`` naming it in
the message ("expected formula", "misconception 'half'").

Usage::

    for part_name, problem in formula_problems(exercise):
        ...   # "the expected formula '2*x*k' cannot be read: unknown name 'k' ..."
    written_formula_problems(listing.formulas)   # the same, from a file's text
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator

Formula = tuple[str, str, object, tuple[str, ...]]


def formula_problems(exercise) -> Iterator[tuple[str, str]]:
    """``(part name, problem)`` for every formula of the exercise's Symbolic parts that
    the grader cannot read in the part's variables."""
    return written_formula_problems(exercise_formulas(exercise))


def exercise_formulas(exercise) -> list[Formula]:
    """The formulas of a loaded exercise: each Symbolic part's expected formula and its
    misconceptions written as formulas."""
    formulas = []
    for part in exercise.parts:
        variables = getattr(part, "variables", None)
        if variables is None:  # a part that declares variables holds formulas in them
            continue
        formulas.append((part.name, "expected formula", getattr(part, "expected", None),
                         tuple(variables)))
        formulas += [(part.name, f"misconception {m.name!r}", m.value, tuple(variables))
                     for m in part.misconceptions if isinstance(m.value, str)]
    return formulas


def written_formula_problems(formulas: Iterable[Formula]) -> Iterator[tuple[str, str]]:
    """``(part name, problem)`` for each formula the grader cannot read."""
    for part_name, what, text, variables in formulas:
        problem = _unreadable(text, variables)
        if problem:
            yield part_name, f"the {what} {text!r} cannot be read: {problem}"


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
