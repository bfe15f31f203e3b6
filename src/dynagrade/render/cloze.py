"""Moodle's embedded answers ("Cloze") syntax: one field of a cloze question as text.

A field is ``{WEIGHT:TYPE:alternative~alternative~...}``; an alternative is an optional
grade (``=`` for full marks, ``%50%`` for a percentage), the answer, and optionally
``#feedback``. A numerical answer is ``value:tolerance`` with an absolute tolerance::

    {2:NUMERICAL:=13.85:0.1385#Correct.~%0%27.7:0.277#Twice the range: ...}
    {1:MULTICHOICE:=comes to rest~keeps sliding}

How Moodle reads it (``qtype_multianswer_extract_question`` in
``question/type/multianswer/questiontype.php``): an answer ends at the first ``~``, ``#``
or ``}`` not preceded by a backslash or ``&``, a feedback at the first such ``~`` or
``}``; both are then HTML-entity-decoded, and only ``\\}`` and ``\\#`` lose their
backslash. So dynagrade writes every character that could end a text (``{ } # ~ \\``) as
a numeric character reference (``&#125;``), which Moodle decodes and which no separator
rule sees, and escapes the text for HTML underneath that, since the decoded text is
shown as HTML. Numbers must match Moodle's ``-?(\\d+[.,]?\\d*|[.,]\\d+)([eE][-+]?\\d+)?``:
:func:`number_text` writes at most :data:`SIGNIFICANT_FIGURES` significant figures, so no
float noise (``39.24``, not ``39.24000000000001``).
"""

from __future__ import annotations

import html
import math
from dataclasses import dataclass

#: the most significant figures a number in the export carries: far below any tolerance
#: the grader uses, far above float noise
SIGNIFICANT_FIGURES = 10

_SEPARATORS = str.maketrans({c: f"&#{ord(c)};" for c in "{}#~\\"})


def cloze_text(text: str) -> str:
    """``text`` as an answer or feedback inside a field: after Moodle decodes it, the
    HTML that shows ``text`` as written."""
    shown_as_html = html.escape(text, quote=False)
    return html.escape(shown_as_html, quote=False).translate(_SEPARATORS)


def number_text(value: float) -> str:
    """A finite number with at most :data:`SIGNIFICANT_FIGURES` significant figures, in
    the form Moodle's numerical answers accept (``39.24``, ``-1.5e-05``, ``1e+20``)."""
    value = float(value)
    if not math.isfinite(value):
        raise ValueError(f"a Moodle answer must be a finite number, not {value!r}")
    return "0" if value == 0 else f"{value:.{SIGNIFICANT_FIGURES}g}"


def percent_text(fraction: float) -> str:
    """A grade fraction (0..1) as the percentage between ``%`` signs (``50``, ``33.33``)."""
    return f"{100 * float(fraction):.5f}".rstrip("0").rstrip(".")


@dataclass(frozen=True)
class Alternative:
    """One answer of a field: ``fraction`` of the field's marks (1 for the right answer;
    None writes no grade mark, leaving it to Moodle's default), the answer (a number, or
    an option's text), its absolute ``tolerance`` for numbers, and the ``feedback`` a
    student who gives it sees."""

    answer: float | str
    fraction: float | None = 0.0
    tolerance: float | None = None
    feedback: str = ""

    def text(self) -> str:
        grade = ("" if self.fraction is None else "=" if self.fraction == 1
                 else f"%{percent_text(self.fraction)}%")
        if isinstance(self.answer, str):
            answer = cloze_text(self.answer)
        else:
            answer = number_text(self.answer)
            if self.tolerance is not None:
                answer += ":" + number_text(self.tolerance)
        feedback = f"#{cloze_text(self.feedback)}" if self.feedback else ""
        return grade + answer + feedback


def field(weight: int, kind: str, alternatives: list[Alternative]) -> str:
    """The embedded field ``{weight:kind:...}``; ``kind`` is ``NUMERICAL``,
    ``MULTICHOICE`` (a drop-down) or ``MULTIRESPONSE`` (check boxes)."""
    if not isinstance(weight, int) or weight < 0:
        raise ValueError(f"a cloze weight is a whole number >= 0, not {weight!r}")
    return f"{{{weight}:{kind}:" + "~".join(a.text() for a in alternatives) + "}"


def choice_field(weight: int, options: tuple[str, ...], right: set[str],
                 several: bool) -> str:
    """A choice among ``options`` with the ``right`` ones marked ``=``.

    With ``several`` (check boxes) Moodle gives each right option ``1/len(right)`` and,
    as no percentages are written, each wrong one ``-1/len(right)``, clamped to 0..1 in
    total: dynagrade's own rule ``max(0, (right picks - wrong picks) / right options)``.
    """
    return field(weight, "MULTIRESPONSE" if several else "MULTICHOICE",
                 [Alternative(option, 1.0 if option in right else None)
                  for option in options])
