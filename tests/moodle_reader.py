"""A reader of Moodle's embedded answers ("Cloze") fields, written for the tests from the
grammar Moodle's importer applies (question/type/multianswer/questiontype.php), and a
scorer that marks responses the way Moodle's question engine does. It shares no code
with dynagrade's writer, so the tests check the export against the format, not against
itself."""

from __future__ import annotations

import html
import re
from dataclasses import dataclass

#: a field's start: ``{weight:TYPE:``
FIELD_START = re.compile(r"\{([0-9]*):(NUMERICAL|NM|MULTICHOICE|MC|MULTIRESPONSE|MR):")
#: a number as Moodle's numerical answers accept it
NUMBER = r"-?(?:[0-9]+[.,]?[0-9]*|[.,][0-9]+)(?:[eE][-+]?[0-9]+)?"
NUMERICAL_ANSWER = re.compile(rf"({NUMBER})(?::({NUMBER}))?")
GRADE = re.compile(r"=|%(-?[0-9]+(?:[.,][0-9]*)?)%")


class ClozeSyntaxError(AssertionError):
    """The text is not a well-formed embedded-answers field."""


@dataclass(frozen=True)
class ClozeAnswer:
    """One alternative: its fraction (None: no grade mark written), the answer as the
    field holds it, the number and tolerance of a numerical answer, and the feedback
    and answer text as a student reads them (entities decoded, then the HTML read)."""

    fraction: float | None
    raw: str
    value: float | None
    tolerance: float | None
    answer_text: str
    feedback_text: str


@dataclass(frozen=True)
class ClozeField:
    weight: int
    kind: str
    answers: tuple[ClozeAnswer, ...]


def read_fields(text: str) -> list[ClozeField]:
    """Every field of a question text, in order; :class:`ClozeSyntaxError` for a field
    whose braces, weight, grades, numbers or escaping are not as Moodle reads them."""
    fields, position = [], 0
    while (start := FIELD_START.search(text, position)) is not None:
        if start.group(1) == "":
            raise ClozeSyntaxError(f"a field without a weight at {start.start()}")
        kind = {"NM": "NUMERICAL", "MC": "MULTICHOICE", "MR": "MULTIRESPONSE"}.get(
            start.group(2), start.group(2))
        pieces, begin, index = [], start.end(), start.end()
        while True:
            if index >= len(text):
                raise ClozeSyntaxError(f"the field at {start.start()} is never closed")
            character = text[index]
            if character == "{":
                raise ClozeSyntaxError(f"an unescaped '{{' inside the field at {start.start()}")
            if character in "~}" and text[index - 1] not in "\\&":
                pieces.append(text[begin:index])
                begin = index + 1
                if character == "}":
                    break
            index += 1
        answers = tuple(_answer(piece, kind) for piece in pieces)
        fields.append(ClozeField(int(start.group(1)), kind, answers))
        position = index + 1
    return fields


def _answer(piece: str, kind: str) -> ClozeAnswer:
    if "\\" in piece:
        raise ClozeSyntaxError(f"a backslash in {piece!r}: Moodle keeps it in the text")
    fraction = None
    grade = GRADE.match(piece)
    if grade:
        fraction = 1.0 if grade.group(0) == "=" else float(grade.group(1).replace(",", ".")) / 100
        piece = piece[grade.end():]
    hashes = [m.start() for m in re.finditer("#", piece) if m.start() == 0 or piece[m.start() - 1] != "&"]
    answer, feedback = (piece[:hashes[0]], piece[hashes[0] + 1:]) if hashes else (piece, "")
    if len(hashes) > 1:
        raise ClozeSyntaxError(f"an unescaped '#' in the feedback of {piece!r}")
    if not answer:
        raise ClozeSyntaxError("an empty answer")
    value = tolerance = None
    if kind == "NUMERICAL":
        number = NUMERICAL_ANSWER.fullmatch(answer)
        if number is None:
            raise ClozeSyntaxError(f"{answer!r} is not a number[:tolerance] Moodle reads")
        value = float(number.group(1).replace(",", "."))
        tolerance = float(number.group(2).replace(",", ".")) if number.group(2) else 0.0
    return ClozeAnswer(fraction, answer, value, tolerance, _as_read(answer), _as_read(feedback))


def _as_read(text: str) -> str:
    """What a student reads: Moodle decodes the entities, the browser reads the HTML."""
    return html.unescape(html.unescape(text))


def moodle_fraction(field: ClozeField, response) -> float:
    """The fraction of a field's marks Moodle gives ``response`` (a number, an option's
    text, or a set of options' texts for check boxes)."""
    if field.kind == "NUMERICAL":
        for answer in field.answers:
            if abs(float(response) - answer.value) <= answer.tolerance:
                return answer.fraction or 0.0
        return 0.0
    if field.kind == "MULTICHOICE":
        return next((a.fraction or 0.0 for a in field.answers if a.answer_text == response), 0.0)
    right = [a for a in field.answers if (a.fraction or 0) > 0]
    total = sum(a.fraction for a in right)
    specific = any(a.fraction is not None and a.fraction not in (0.0, 1.0)
                   for a in field.answers)
    marks = 0.0
    for answer in field.answers:
        if answer.answer_text in response:
            if (answer.fraction or 0) > 0:
                marks += answer.fraction / total
            elif not specific:
                marks -= 1 / total
    return min(1.0, max(0.0, marks))


def moodle_mark(fields: list[ClozeField], responses: list) -> float:
    """The share of a cloze question's full mark Moodle gives ``responses`` (one per
    field): the fields' weighted fractions over the sum of the weights."""
    total = sum(f.weight for f in fields)
    return sum(f.weight * moodle_fraction(f, r) for f, r in zip(fields, responses)) / total


def significant_figures(number: str) -> int:
    """The significant figures of a number as written (``0.0400`` -> 3, ``1e+20`` -> 1)."""
    mantissa = re.split("[eE]", number.lstrip("-"))[0].replace(",", ".")
    digits = mantissa.replace(".", "").lstrip("0")
    return len(digits) if digits else 1
