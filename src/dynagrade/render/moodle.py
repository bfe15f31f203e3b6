"""Variants as Moodle XML: a question category per exercise, a question per variant.

A quiz draws a random question from each category, so every student meets one variant.
Two writers share everything below: :func:`moodle_xml` (an exam's variants, from its
manifest) and :func:`pool_xml` (a pool of variants independent of any roster,
:mod:`dynagrade.generation.pool`).

What a question holds (Moodle's XML import format, ``question/format/xml/format.php``):

- the statement (Markdown as HTML, math as TeX between ``\\(`` and ``\\)`` for Moodle's
  MathJax filter) and the variant's figure embedded as a file of the question text
  (``<file name="F.svg" path="/" encoding="base64">``, shown by
  ``<img src="@@PLUGINFILE@@/F.svg">``);
- an exercise with one numeric part: a ``numerical`` question; any other: a ``cloze``
  question with an embedded field per part (:mod:`.cloze`; a vector has one field per
  component, a choice part a drop-down of its options' text, several options check
  boxes: each kind's part class says its form, :data:`FORMS` writes each form). Numeric
  answers carry the grader's own tolerance, then every declared misconception as a
  wrong answer with its feedback (and its partial credit, if any; a vector's, by the
  grader's own rule, :func:`dynagrade.grading.vector.component_answers`);
- marks as Moodle computes them: a cloze question's full mark is the sum of its fields'
  weights (:mod:`.cloze_marks`), in the proportions of the exam's part points;
- parts Moodle cannot check (formulas) are left out of the question; the category's
  description, which only the staff see, names them and the points they carry, and
  says which maximum mark to give the quiz slot;
- an ``idnumber`` made from the exercise id and a hash of the variant's parameters
  (values the statement shows anyway): the same variant has the same id in every
  export, and no id holds a seed or anything else that leads to a key. Moodle matches
  nothing on import: importing a file again adds every question again, without its
  idnumber where the category already holds it (docs/exams.md says how to replace an
  import).

``penalty`` is 0 (no deduction per retry) on every question. The XML is written by
:mod:`xml.etree.ElementTree`, which escapes all text.
"""

from __future__ import annotations

import base64
import hashlib
import json
import math
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from typing import Callable, Mapping

from ..exam.manifest import ExerciseEntry, Manifest, PartEntry, VariantEntry
from ..exercise.kinds import MoodleForm, NotExported
from ..exercise.model import Exercise
from ..exercise.parts import PART_KINDS
from ..exercise.numbers import format_number, points_phrase
from ..exercise.statement import render_statement
from ..exercise.units import pretty_unit
from ..grading.spec import KnownWrong, VectorSpec
from ..grading.tolerance import allowed_error
from .cloze import Alternative, choice_field, field as cloze_field, number_text
from .cloze_marks import Weights, field_points, field_weights
from .markup import markdown_to_html

PENALTY = "0"
#: a variant's figure as SVG text (None: the exercise draws none)
Figure = Callable[[Exercise, VariantEntry], "str | None"]


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


# -- the fields of each part kind ---------------------------------------------------------


@dataclass(frozen=True)
class PartFields:
    """What a part's fields are written from: the manifest's part, the variant's
    reference answer and the misconceptions' wrong answers in the part's unit (name,
    value, feedback, score)."""

    part: PartEntry
    value: object
    wrong: tuple = ()


def _numeric_fields(given: PartFields, weights: list[int]) -> list[str]:
    return [cloze_field(weights[0], "NUMERICAL", _number_alternatives(given))]


def _number_alternatives(given: PartFields) -> list[Alternative]:
    """A numeric part's alternatives; a misconception is recognised within the part's
    tolerance around its own value, as the grader recognises it."""
    part, value = given.part, float(given.value)
    wrong = [(float(v), tolerance(float(v), part.rtol, part.atol), feedback, score)
             for _, v, feedback, score in given.wrong]
    return numeric_alternatives(value, tolerance(value, part.rtol, part.atol), wrong)


def _vector_fields(given: PartFields, weights: list[int]) -> list[str]:
    """A field per component, whose alternatives are the answers the grader holds that
    component against, in its order (:func:`dynagrade.grading.vector.component_answers`:
    the reference, then each misconception that differs there, with its score): Moodle's
    first alternative within tolerance gives the credit dynagrade gives."""
    from ..grading.vector import component_answers

    part = given.part
    spec = VectorSpec(int(part.size), rtol=part.rtol, atol=part.atol, misconceptions=tuple(
        KnownWrong(name, tuple(value), feedback, score)
        for name, value, feedback, score in given.wrong))
    return [cloze_field(w, "NUMERICAL", [Alternative(a.value, a.credit, a.allowed, a.feedback)
                                         for a in answers])
            for w, answers in zip(weights, component_answers(spec, tuple(given.value)))]


def numeric_alternatives(value: float, allowed: float, wrong) -> list[Alternative]:
    """A number's alternatives: the right answer within ``allowed``, then each wrong
    answer ``(value, tolerance, feedback, score)`` that the grader can tell from it
    (finite, outside the right answer's tolerance), in the grader's order: Moodle takes
    the first alternative an answer falls within."""
    alternatives = [Alternative(value, 1.0, allowed)]
    for target, around, feedback, score in wrong:
        if math.isfinite(target) and abs(target - value) > allowed:
            alternatives.append(Alternative(target, score, around, feedback))
    return alternatives


def _choice_fields(given: PartFields, weights: list[int]) -> list[str]:
    part, value = given.part, given.value
    right = set(value) if isinstance(value, (list, tuple)) else {value}
    return [choice_field(weights[0], tuple(part.options), right, bool(part.multiple))]


@dataclass(frozen=True)
class FormWriter:
    """How one :class:`~dynagrade.exercise.kinds.MoodleForm` is written: ``fields(part_fields,
    weights)`` gives its embedded cloze fields, ``count(part)`` of them; ``numerical``
    says that a lone part of this form becomes a ``numerical`` question (its one field's
    alternatives, :func:`_numerical_question`), which only a form of one number can."""

    fields: Callable[[PartFields, list[int]], list[str]]
    count: Callable[[PartEntry], int] = lambda part: 1
    numerical: bool = False


#: the writer of every Moodle form a part kind may take (a test holds it complete); a
#: kind's form is data on its part class (:attr:`dynagrade.exercise.parts.Part.moodle`)
FORMS: dict[MoodleForm, FormWriter] = {
    MoodleForm.NUMBER: FormWriter(_numeric_fields, numerical=True),
    MoodleForm.COMPONENTS: FormWriter(_vector_fields, count=lambda part: int(part.size)),
    MoodleForm.OPTIONS: FormWriter(_choice_fields),
}


def form_of(part) -> MoodleForm | NotExported:
    """The Moodle form of a part or a manifest's part entry, from its kind."""
    return PART_KINDS[part.kind].moodle


def writer(part) -> FormWriter | None:
    """How ``part`` is written into Moodle (None: Moodle cannot check it)."""
    form = form_of(part)
    return None if isinstance(form, NotExported) else FORMS[form]


def part_fields(part: PartEntry, value, wrong: tuple, weights: list[int]) -> list[str]:
    """The embedded fields of a manifest's part with reference ``value`` and the
    misconceptions ``wrong`` ((name, value, feedback, score) in the part's unit), each
    field of the given weight."""
    return writer(part).fields(PartFields(part, value, wrong), weights)


# -- marks --------------------------------------------------------------------------------


@dataclass(frozen=True)
class Marks:
    """How an exercise's points go into Moodle: the exported parts, each part's field
    weights, and the parts left out."""

    exercise_points: float
    exported: tuple[PartEntry, ...]
    weights: dict[str, list[int]]
    left_out: tuple[PartEntry, ...]
    exact: bool = True

    @property
    def full_mark(self) -> int:
        """Moodle's full mark of a cloze question: the sum of its weights."""
        return sum(sum(w) for w in self.weights.values())

    @property
    def exported_points(self) -> float:
        return sum(p.points for p in self.exported)


def exercise_marks(described: ExerciseEntry) -> Marks:
    """The fields' weights of ``described``'s parts, proportional to the points the exam
    gives them (a vector's split over its components)."""
    exported = tuple(p for p in described.parts if writer(p) is not None)
    left_out = tuple(p for p in described.parts if writer(p) is None)
    counts = [writer(p).count(p) for p in exported]
    points = [share for p, n in zip(exported, counts) for share in field_points(p.points, n)]
    found: Weights = field_weights(points)
    weights, start = {}, 0
    for part, n in zip(exported, counts):
        weights[part.name] = list(found.weights[start:start + n])
        start += n
    return Marks(described.points, exported, weights, left_out, found.exact)


# -- the document -------------------------------------------------------------------------


@dataclass
class MoodleExport:
    """The XML document (UTF-8 bytes) and notices for the staff (exercises left out)."""

    xml: bytes
    notices: list[str] = field(default_factory=list)


@dataclass(frozen=True)
class Category:
    """An exercise's category: the exercise, its parts with the exam's points and the
    variants to write, in order."""

    exercise: Exercise
    described: ExerciseEntry
    variants: tuple[VariantEntry, ...]


def moodle_xml(manifest: Manifest, exercises: Mapping[str, Exercise],
               figure: Figure | None = None) -> MoodleExport:
    """Every distinct variant of ``manifest`` (by parameters), under
    ``$course$/top/<exam title>/<exercise id>``; ``figure`` gives a variant's figure (by
    default it is drawn)."""
    categories = []
    for described in manifest.exercises:
        variants = [v for s in manifest.students for v in s.variants
                    if v.exercise == described.id]
        categories.append(Category(exercises[described.id], described, distinct(variants)))
    return _document(manifest.exam.title, categories, figure or drawn_figure)


def pool_xml(title: str, categories: list[Category],
             figure: Figure | None = None) -> MoodleExport:
    """A pool of variants, a category ``$course$/top/<title>/<exercise id>`` each."""
    return _document(title, categories, figure or drawn_figure)


def distinct(variants) -> tuple[VariantEntry, ...]:
    """``variants`` without repeats of the same parameters, in order."""
    seen, kept = set(), []
    for variant in variants:
        key = variant_idnumber(variant)
        if key not in seen:
            seen.add(key)
            kept.append(variant)
    return tuple(kept)


def variant_idnumber(variant: VariantEntry) -> str:
    """``<exercise id>-<12 hex digits>``: a hash of the exercise id and the variant's
    parameters, the same in every export of that variant, and no way to its seed."""
    canonical = json.dumps({"exercise": variant.exercise,
                            "params": {k: float(v) for k, v in variant.params.items()}},
                           sort_keys=True)
    return f"{variant.exercise}-{hashlib.sha256(canonical.encode()).hexdigest()[:12]}"


def drawn_figure(exercise: Exercise, variant: VariantEntry) -> str | None:
    """The variant's figure, drawn now."""
    if exercise.figure is None:
        return None
    from .figures import figure_svg

    return figure_svg(exercise, exercise.variant_from_params(variant.seed, variant.params))


def _document(title: str, categories: list[Category], figure: Figure) -> MoodleExport:
    quiz = ET.Element("quiz")
    export = MoodleExport(b"")
    for category in categories:
        marks = exercise_marks(category.described)
        if not marks.exported:
            export.notices.append(
                f"exercise {category.described.id!r} is not in the Moodle export: none of "
                "its parts can be checked by Moodle")
            continue
        _category(quiz, title, category, marks)
        for variant in category.variants:
            _question(quiz, category, marks, variant, figure(category.exercise, variant))
    ET.indent(quiz, space=" ")
    export.xml = (b'<?xml version="1.0" encoding="UTF-8"?>\n'
                  + ET.tostring(quiz, encoding="utf-8", xml_declaration=False) + b"\n")
    return export


def _category(quiz: ET.Element, title: str, category: Category, marks: Marks) -> None:
    described = category.described
    element = _sub(quiz, "question", type="category")
    _text(element, "category", f"$course$/top/{_category_name(title)}/{described.id}")
    _text(element, "info", staff_note(title, described, marks,
                                      question_numbers(category.exercise)), format="html")


def staff_note(title: str, described: ExerciseEntry, marks: Marks,
               numbers: Mapping[str, int | None] | None = None) -> str:
    """The category's description (seen by the staff only): where the questions come
    from, the maximum mark to give the quiz slot, the parts left out and their share."""
    lines = [f"{_html(described.title)} ({_html(described.source)}), {_html(title)}: "
             f"one question per variant, idnumber {_html(described.id)}-&lt;hash of the "
             "variant's parameters&gt;."]
    points = format_number(marks.exported_points)
    lines.append(
        f"The exercise carries {points_phrase(marks.exercise_points)}. Set "
        f"the quiz slot's maximum mark to {points} (the points of the parts in Moodle); "
        f"the questions' own full mark is {marks.full_mark}, the sum of the field weights "
        + ", ".join(f"{p.name} {'+'.join(map(str, marks.weights[p.name]))}"
                    for p in marks.exported) + ".")
    if not marks.exact:
        lines.append("The weights only approximate the parts' shares of the points.")
    if marks.left_out:
        share = sum(p.points for p in marks.left_out)
        whole = marks.exercise_points or 1.0
        lines.append(
            "Not in Moodle (grade them from the fill-in files or by hand): "
            + "; ".join(f"{_html(p.label)} ({_asked(p.name, numbers)}{p.name}, "
                        f"{form_of(p).absent}, {points_phrase(p.points)})"
                        for p in marks.left_out)
            + f"; together {points_phrase(share)}, "
              f"{format_number(100 * share / whole)} % of the exercise.")
    return "".join(f"<p>{line}</p>" for line in lines)


def _asked(name: str, numbers: Mapping[str, int | None] | None) -> str:
    number = (numbers or {}).get(name)
    return f"question {number}, " if number is not None else ""


def _question(quiz: ET.Element, category: Category, marks: Marks, variant: VariantEntry,
              svg: str | None) -> None:
    exercise, described = category.exercise, category.described
    statement = render_statement(exercise.statement, exercise.params, variant.params)
    text = markdown_to_html(statement, math="tex")
    if svg is not None:
        text += _figure_html(exercise, described.id)
    wrong = _wrong_answers(exercise, variant)
    lone = described.parts[0] if len(described.parts) == 1 else None
    if lone is not None and writer(lone) is not None and writer(lone).numerical:
        question = _numerical_question(quiz, described, variant, text, wrong[lone.name])
    else:
        question = _cloze_question(quiz, described, marks, variant, text, wrong,
                                   question_numbers(exercise))
    if svg is not None:
        _figure_file(question.find("questiontext"), described.id, svg)


def question_numbers(exercise: Exercise) -> dict[str, int | None]:
    """The number of the statement's question each part answers (None: unnumbered)."""
    return {part.name: part.question for part in exercise.parts}


def _wrong_answers(exercise: Exercise, variant: VariantEntry) -> dict[str, tuple]:
    """Each part's declared misconceptions in this variant, as the grader sees them
    (values in the part's unit)."""
    params = exercise.si(variant.params)
    wrong = {}
    for part in exercise.parts:
        known = getattr(part.spec(params), "misconceptions", ()) \
            if writer(part) is not None else ()
        wrong[part.name] = tuple((k.name, k.value, k.feedback, k.score) for k in known)
    return wrong


def _figure_html(exercise: Exercise, exercise_id: str) -> str:
    from .figures import figure_title

    return (f'<p><img src="@@PLUGINFILE@@/{exercise_id}.svg" '
            f'alt="{_html(figure_title(exercise), quote=True)}"></p>')


def _figure_file(questiontext: ET.Element, exercise_id: str, svg: str) -> None:
    """The figure as a file of the question text, which the ``<img>`` names."""
    encoded = base64.b64encode(svg.encode("utf-8")).decode("ascii")
    _sub(questiontext, "file", encoded, name=f"{exercise_id}.svg", path="/",
         encoding="base64")


def _question_head(quiz: ET.Element, kind: str, described: ExerciseEntry,
                   variant: VariantEntry, text: str, grade: float) -> ET.Element:
    """A question's name, text, grade and ids, the same for every type."""
    idnumber = variant_idnumber(variant)
    question = _sub(quiz, "question", type=kind)
    _text(question, "name", f"{described.title} [{idnumber}]")
    _text(question, "questiontext", text, format="html")
    _text(question, "generalfeedback", "", format="html")
    _sub(question, "defaultgrade", number_text(grade))
    _sub(question, "penalty", PENALTY)
    _sub(question, "hidden", "0")
    _sub(question, "idnumber", idnumber)
    return question


def _numerical_question(quiz: ET.Element, described: ExerciseEntry, variant: VariantEntry,
                        text: str, wrong: tuple) -> ET.Element:
    """A lone numeric part: a ``numerical`` question (its ``defaultgrade`` counts) with
    the grader's tolerance and the misconceptions as wrong answers with feedback."""
    (part,) = described.parts
    unit = f" (in {pretty_unit(part.unit)})" if part.unit else ""
    question = _question_head(quiz, "numerical", described, variant,
                              text + f"<p>{_html(part.label)}{_html(unit)}</p>", part.points)
    alternatives = _number_alternatives(PartFields(part, variant.answers[part.name], wrong))
    for alternative in alternatives:
        answer = _sub(question, "answer", fraction=number_text(100 * alternative.fraction),
                      format="moodle_auto_format")
        _sub(answer, "text", number_text(alternative.answer))
        _sub(answer, "tolerance", number_text(alternative.tolerance))
        _text(answer, "feedback", _html(alternative.feedback), format="html")
    accepted = unit_multipliers(part.unit) if part.unit else []
    if accepted:
        listed = _sub(question, "units")
        for name, multiplier in accepted:
            entry = _sub(listed, "unit")
            _sub(entry, "multiplier", number_text(multiplier))
            _sub(entry, "unit_name", name)
    # units optional: typed with the number (showunits 0) and converted, or left out (3)
    for tag, setting in (("unitgradingtype", "0"), ("unitpenalty", "0"),
                         ("showunits", "0" if accepted else "3"), ("unitsleft", "0")):
        _sub(question, tag, setting)
    return question


def unit_multipliers(unit: str) -> list[tuple[str, float]]:
    """The units a numerical question converts, each with Moodle's multiplier (how many of
    it make one of the part's unit; Moodle divides a response by it): the part's unit as
    written and as printed, and for a frequency part its other spellings (rad/s, s^-1, Hz,
    rpm, U/min, min^-1). A name that starts with a digit (``1/s``) is left out: Moodle
    drops the spaces of a response, so its number would run into the unit. Every multiplier is the grader's own reading of ``1 <unit>``
    (:func:`dynagrade.grading.numeric.one_unit_in_part_unit`), so Moodle applies the same
    frequency rule: in a rad/s part a Hz is 2π rad/s (multiplier 1/(2π)), not 1 rad/s."""
    from ..grading import frequency
    from ..grading.numeric import one_unit_in_part_unit
    from ..grading.quantity import unit_info

    names = [unit.strip(), pretty_unit(unit)]
    if frequency.is_frequency(unit_info(unit)[1]):
        names += frequency.SPELLINGS
    accepted: list[tuple[str, float]] = []
    for name in names:
        value = one_unit_in_part_unit(name, unit)
        if value and not name[:1].isdigit() and name not in {known for known, _ in accepted}:
            accepted.append((name, 1.0 / value))
    return accepted


def _cloze_question(quiz: ET.Element, described: ExerciseEntry, marks: Marks,
                    variant: VariantEntry, text: str, wrong: dict,
                    numbers: Mapping[str, int | None]) -> ET.Element:
    """Every part Moodle can check as embedded fields, weighted as :func:`exercise_marks`
    says, each in a list item numbered as the statement's question it answers; the
    others are left out of the student's text."""
    lines = []
    for part in marks.exported:
        unit = f" {_html(pretty_unit(part.unit))}" if part.unit else ""
        fields = part_fields(part, variant.answers[part.name], wrong[part.name],
                             marks.weights[part.name])
        shown = fields[0] if len(fields) == 1 else "(" + ", ".join(fields) + ")"
        number = numbers.get(part.name)
        item = f'<li value="{number}">' if number is not None else "<li>"
        lines.append(f"{item}{_html(part.label)}: {shown}{unit}</li>")
    return _question_head(quiz, "cloze", described, variant,
                          text + "<ol>" + "".join(lines) + "</ol>", marks.full_mark)


# -- XML helpers --------------------------------------------------------------------------


def _category_name(title: str) -> str:
    return title.replace("/", "//")


def _sub(parent: ET.Element, tag: str, text: str | None = None, **attributes) -> ET.Element:
    element = ET.SubElement(parent, tag, attributes)
    if text is not None:
        element.text = text
    return element


def _text(parent: ET.Element, tag: str, text: str, format: str | None = None) -> ET.Element:
    element = _sub(parent, tag, **({"format": format} if format else {}))
    _sub(element, "text", text)
    return element


def _html(text: str, quote: bool = False) -> str:
    import html

    return html.escape(text, quote=quote)
