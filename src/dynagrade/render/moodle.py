"""The exam as Moodle XML: a question category per exercise, a question per variant.

A quiz then draws a random question from each category, so every student meets one of
the exam's variants. An exercise whose only gradable part is numeric becomes a
``numerical`` question; any other becomes a ``cloze`` question with one embedded answer
per part (``{2:NUMERICAL:=4.43:0.0443}``; a vector has one field per component, a
choice part a drop-down; :data:`MOODLE_KINDS` holds each kind's form). Moodle's
numerical answers take an absolute tolerance: it comes from the grader's own tolerance
functions, so Moodle accepts what ``dynagrade grade`` accepts (``max(atol, rtol*|answer|)``
with the grader's absolute floor; a vector's zero component judged against its length).
Symbolic parts cannot be checked by Moodle and are listed as not part of the quiz.
``penalty`` is set to 0 (no deduction per retry) on every question.

The XML is written by :mod:`xml.etree.ElementTree`, which escapes all text; the math of
the statements stays TeX between ``\\(`` and ``\\)`` for Moodle's MathJax filter.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from dataclasses import dataclass
from typing import Callable, Mapping

from ..exam.manifest import ExerciseEntry, Manifest, PartEntry, VariantEntry
from ..exercise.model import Exercise
from ..exercise.statement import render_statement
from ..exercise.units import pretty_unit
from ..grading.spec import VectorSpec
from ..grading.tolerance import allowed_error
from .markup import markdown_to_html

PENALTY = "0"
_CLOZE_SPECIAL = str.maketrans({c: "\\" + c for c in "}#~/\"\\"})


def tolerance(value: float, rtol: float, atol: float | None) -> float:
    """The absolute tolerance of a numeric answer: the grader's own
    :func:`~dynagrade.grading.tolerance.allowed_error` (with its absolute floor)."""
    return allowed_error(value, rtol, atol)


def vector_tolerances(values, rtol: float, atol: float | None) -> list[float]:
    """The absolute tolerance of each component of a vector answer: the grader's own
    :func:`~dynagrade.grading.vector.component_tolerance` (a zero component is judged
    against the vector's length, as dynagrade grades it)."""
    import numpy as np

    from ..grading.vector import component_tolerance

    spec = VectorSpec(len(values), rtol=rtol, atol=atol)
    return [float(t) for t in component_tolerance(spec, np.asarray(values, dtype=float))]


def _number(value: float) -> str:
    """A number as Moodle reads it, exactly (the shortest text that round-trips)."""
    return repr(float(value))


def _tolerance_text(value: float) -> str:
    """A tolerance to 15 significant figures (``0.1725``, not ``0.17250000000000001``)."""
    return f"{float(value):.15g}"


def _sub(parent: ET.Element, tag: str, text: str | None = None, **attributes) -> ET.Element:
    element = ET.SubElement(parent, tag, attributes)
    if text is not None:
        element.text = text
    return element


def _text(parent: ET.Element, tag: str, text: str, format: str | None = None) -> ET.Element:
    element = _sub(parent, tag, **({"format": format} if format else {}))
    _sub(element, "text", text)
    return element


def _numeric_field(part: PartEntry, value, weight: int) -> str:
    tol = tolerance(value, part.rtol, part.atol)
    return f"{{{weight}:NUMERICAL:={_number(value)}:{_tolerance_text(tol)}}}"


def _vector_field(part: PartEntry, value, weight: int) -> str:
    fields = [f"{{{weight}:NUMERICAL:={_number(v)}:{_tolerance_text(tol)}}}"
              for v, tol in zip(value, vector_tolerances(value, part.rtol, part.atol))]
    return "[" + ", ".join(fields) + "]"


def _choice_field(part: PartEntry, value, weight: int) -> str:
    correct = set(value) if isinstance(value, (list, tuple)) else {value}
    options = [str(o).translate(_CLOZE_SPECIAL) for o in part.options]
    if part.multiple:
        share = 100 / max(1, len(correct))
        marks = [f"%{share:g}%{o}" if raw in correct else f"%-100%{o}"
                 for raw, o in zip(part.options, options)]
        return f"{{{weight}:MULTIRESPONSE:" + "~".join(marks) + "}"
    marks = [f"={o}" if raw in correct else o for raw, o in zip(part.options, options)]
    return f"{{{weight}:MULTICHOICE:" + "~".join(marks) + "}"


@dataclass(frozen=True)
class MoodleKind:
    """How a kind of part goes into Moodle: ``field(part, value, weight)`` writes its
    embedded cloze answer (None: Moodle cannot check it, and the part is listed as not in
    the quiz, saying ``absent``); ``numerical``: a lone part of this kind becomes a
    ``numerical`` question."""

    field: Callable[[PartEntry, object, int], str] | None
    numerical: bool = False
    absent: str = ""


#: every part kind's Moodle form (a test holds it complete)
MOODLE_KINDS: dict[str, MoodleKind] = {
    "numeric": MoodleKind(_numeric_field, numerical=True),
    "vector": MoodleKind(_vector_field),
    "choice": MoodleKind(_choice_field),
    "symbolic": MoodleKind(None, absent="a formula, graded from the fill-in file"),
}


def moodle_xml(manifest: Manifest, exercises: Mapping[str, Exercise]) -> bytes:
    """The Moodle XML document (UTF-8 bytes) for every variant in ``manifest``."""
    quiz = ET.Element("quiz")
    exam = manifest.exam
    for described in manifest.exercises:
        exercise = exercises[described.id]
        category = _sub(quiz, "question", type="category")
        _text(category, "category",
              f"$course$/top/{_category_name(exam.title)}/{described.id}")
        _text(category, "info", f"{described.title} ({described.source}), "
              f"{exam.title}", format="html")
        seen = set()
        for student in manifest.students:
            for variant in student.variants:
                if variant.exercise != described.id or variant.seed in seen:
                    continue
                seen.add(variant.seed)
                _question(quiz, exercise, described, variant)
    ET.indent(quiz, space=" ")
    return (b'<?xml version="1.0" encoding="UTF-8"?>\n'
            + ET.tostring(quiz, encoding="utf-8", xml_declaration=False) + b"\n")


def _category_name(title: str) -> str:
    return title.replace("/", "//")


def _question(quiz: ET.Element, exercise: Exercise, described: ExerciseEntry,
              variant: VariantEntry) -> None:
    statement = render_statement(exercise.statement, exercise.params, variant.params)
    text = markdown_to_html(statement, math="tex")
    parts = described.parts
    if len(parts) == 1 and MOODLE_KINDS[parts[0].kind].numerical:
        _numerical_question(quiz, described, variant, text)
    else:
        _cloze_question(quiz, described, variant, text)


def _question_head(quiz: ET.Element, kind: str, described: ExerciseEntry,
                   variant: VariantEntry, text: str) -> ET.Element:
    """A question's name, text, grade and ids, the same for every type."""
    question = _sub(quiz, "question", type=kind)
    _text(question, "name", f"{described.id} (seed {variant.seed})")
    _text(question, "questiontext", text, format="html")
    _text(question, "generalfeedback", "", format="html")
    _sub(question, "defaultgrade", _number(described.points))
    _sub(question, "penalty", PENALTY)
    _sub(question, "hidden", "0")
    _sub(question, "idnumber", f"{described.id}-{variant.seed}")
    return question


def _numerical_question(quiz: ET.Element, described: ExerciseEntry, variant: VariantEntry,
                        text: str) -> None:
    """A lone numeric part: a ``numerical`` question with the grader's tolerance."""
    (part,) = described.parts
    unit = f" (in {pretty_unit(part.unit)})" if part.unit else ""
    question = _question_head(quiz, "numerical", described, variant,
                              text + f"<p>{_html(part.label)}{_html(unit)}</p>")
    value = variant.answers[part.name]
    answer = _sub(question, "answer", fraction="100", format="moodle_auto_format")
    _sub(answer, "text", _number(value))
    _sub(answer, "tolerance", _tolerance_text(tolerance(value, part.rtol, part.atol)))
    _text(answer, "feedback", "", format="html")
    for tag, setting in (("unitgradingtype", "0"), ("unitpenalty", "0"), ("showunits", "3"),
                         ("unitsleft", "0")):
        _sub(question, tag, setting)


def _cloze_question(quiz: ET.Element, described: ExerciseEntry, variant: VariantEntry,
                    text: str) -> None:
    """Every part as an embedded field (weights: the parts' relative points), or as a line
    saying why Moodle cannot check it."""
    gradable = [p for p in described.parts if MOODLE_KINDS[p.kind].field is not None]
    smallest = min((p.points for p in gradable if p.points > 0), default=1.0)
    lines = []
    for part in described.parts:
        label = _html(part.label)
        unit = f" {_html(pretty_unit(part.unit))}" if part.unit else ""
        form = MOODLE_KINDS[part.kind]
        if form.field is None:
            lines.append(f"<li>{label}: not part of this quiz ({form.absent})</li>")
            continue
        weight = max(1, round(part.points / smallest))  # Moodle wants integers
        lines.append(f"<li>{label}: {form.field(part, variant.answers[part.name], weight)}"
                     f"{unit}</li>")
    _question_head(quiz, "cloze", described, variant,
                   text + "<ol>" + "".join(lines) + "</ol>")


def _html(text: str) -> str:
    import html

    return html.escape(text, quote=False)
