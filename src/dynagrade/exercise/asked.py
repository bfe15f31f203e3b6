"""What the statement asks and shows, held against the parts (checks of ``dynagrade verify``).

- Every graded part answers a numbered question of the statement (``question=N``), and
  every numbered question has a part: a part no question asks cannot be answered by a
  careful student, and a question no part grades is work thrown away.
- Every variable of a formula part is shown in the statement's math (or code) under a
  spelling the grader accepts: its printed symbol, its name or an alias.

The statement numbers its questions as a Markdown list, ``1.`` or ``1)`` at the start of
a line; these are read from the template, so a question inside ``{% if %}`` counts.
"""

from __future__ import annotations

import re

from ..grading.names import GREEK, typed_forms
from .model import Exercise

_QUESTION = re.compile(r"^\s{0,3}(\d+)[.)]\s", re.MULTILINE)
_TEMPLATE_CODE = re.compile(r"\{\{.*?\}\}|\{%.*?%\}|\{#.*?#\}", re.DOTALL)
_GREEK_COMMAND = re.compile(r"\\(var)?(" + "|".join(sorted(set(GREEK.values()), key=len, reverse=True))
                            + r")(?![A-Za-z])")
_MATH = re.compile(r"\$\$(.+?)\$\$|\$(.+?)\$|`([^`]+)`", re.DOTALL)


def numbered_questions(statement: str) -> list[int]:
    """The numbers of the questions a statement template lists, in order."""
    return [int(n) for n in _QUESTION.findall(_TEMPLATE_CODE.sub("", statement))]


def question_problems(exercise: Exercise) -> list[str]:
    """Parts whose question the statement does not number, and numbered questions that no
    part answers; empty when every graded part is asked and every question graded."""
    numbers = numbered_questions(exercise.statement)
    problems = []
    if not numbers:
        return [f"part {p.name}: question={p.question}, but the statement numbers no "
                "questions (leave question out, or number the questions 1., 2., …)"
                for p in exercise.parts if p.question is not None]
    for part in exercise.parts:
        if part.question is None:
            problems.append(f"part {part.name}: says no question it answers; the statement "
                            f"numbers {_listed(numbers)}: add question=N")
        elif part.question not in numbers:
            problems.append(f"part {part.name}: answers question {part.question}, which the "
                            f"statement does not have (it numbers {_listed(numbers)})")
    answered = {p.question for p in exercise.parts}
    problems += [f"question {n} of the statement has no part that grades it (give a part "
                 f"question={n}, or take the question out)"
                 for n in numbers if n not in answered]
    return problems


def unshown_variables(exercise: Exercise) -> list[str]:
    """Variables of formula parts that the statement never shows under a name the grader
    accepts; each with what to do about it."""
    shown = _shown_math(exercise.statement)
    problems = []
    for part in exercise.parts:
        variables = getattr(part, "variables", None)
        if not variables:
            continue
        spellings = part.spellings()
        for name, variable in variables.items():
            accepted = {name} | {s for s, n in spellings.items() if n == name}
            printed = [variable.symbol] if variable.symbol and \
                accepted & set(typed_forms(variable.symbol)) else []
            if not any(_appears(form, shown) for form in [*printed, *accepted]):
                symbol = f" (symbol {variable.symbol!r})" if variable.symbol else ""
                problems.append(
                    f"part {part.name}: the variable {name!r}{symbol} is not shown in the "
                    "statement under a name the grader accepts; print its symbol there, "
                    "or give it symbol= or aliases= as the statement writes it")
    return problems


def _listed(numbers: list[int]) -> str:
    return "questions " + ", ".join(str(n) for n in numbers)


def _flat(text: str) -> str:
    """Math without grouping braces and with Greek letters spelled as typed, so that
    ``v_{2}(0)`` shows ``v_2(0)`` and ``\\omega`` shows ``omega``."""
    return _GREEK_COMMAND.sub(r"\2", re.sub(r"[{}]", "", text)).strip()


def _shown_math(statement: str) -> list[str]:
    """The math and code spans of a statement template, flattened (:func:`_flat`)."""
    text = _TEMPLATE_CODE.sub(" ", statement).replace("\\\\", "\\")
    return [_flat(next(g for g in match.groups() if g is not None))
            for match in _MATH.finditer(text)]


def _appears(form: str, spans: list[str]) -> bool:
    """Whether ``form`` stands as a symbol of its own in one of the ``spans``."""
    flat = _flat(form)
    if not flat:
        return False
    before = "" if flat[0] == "\\" else r"(?<![A-Za-z0-9\\])"
    pattern = re.compile(before + re.escape(flat) + r"(?![A-Za-z0-9_])")
    return any(pattern.search(span) for span in spans)

