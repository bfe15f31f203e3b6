"""Decorations around an answer, stripped before it is read, each with a note.

Students dress an answer the way they write it on paper: ``ω₂ = 4.5 rad/s``,
``ca. 3.2 m/s``, ``3.2 m/s (to the right)``, ``Answer: 12 N.``, Swiss thousands
``1'200 N``, a phone's ``3.2x10^-3`` and ``m/s2``. None of these changes the quantity,
so the grader leaves them out before the tokenizer (:mod:`.lexer`) sees the answer and
says what it left out ("Read as 3.2 m/s (left out 'ω₂ =')"). Each rule is narrow
enough that it cannot change a value (docs/grading.md, "What the grader strips"):

- invisible characters (zero-width space and joiners, word joiner, byte-order mark, soft
  hyphen) are removed everywhere;
- a leading ``Answer:``/``Antwort:`` and a leading ``name =`` (or ``name ≈``), where the
  name is one name in any spelling the course prints: subscripts (``ω₂``, ``v_B``,
  ``v_{B}``), an argument (``v(0)``, ``x(t_1)``), bars (``|v_B|``); never an expression
  (``2v = 6`` stays an equation and is refused);
- a final full stop, unless the answer ends in a whole number written with a point
  (``12.`` is a number);
- in numbers with units (numeric and vector parts) also: a leading ``ca.``, ``approx.``,
  ``≈``, ``~``; a final remark in brackets made of words, at least one of which is no
  unit (``(to the right)``, never ``(N m)`` or ``(2 m)``); ``x10^`` right after a
  digit (``3.2x10^-3`` is 3.2·10⁻³); ``Pi``/``PI`` as π; ``s2``, ``m2``, ``m3`` (also
  after ``mm``, ``cm``, ``km``) as powers after the number;
- Swiss thousands separators ``'`` and ``’`` between groups of exactly three digits
  (``1'200``, ``12’500’000``; ``1'20`` stays refused).

A formula (symbolic part) has variables where a quantity has units, so only the
rules that cannot touch a variable apply to it (invisible characters, ``Answer:``,
``name =``, the final full stop, Swiss thousands). A choice is read as typed.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from ..i18n import _
from .functions import FUNCTIONS
from .names import CONSTANTS, GREEK, SUBSCRIPTS, SUPERSCRIPTS

#: How an answer is read: a number or vector with units, or a formula in variables.
QUANTITY, FORMULA = "quantity", "formula"

#: Characters no one sees but a phone or a copied PDF may put into an answer.
INVISIBLE = "\u200b\u200c\u200d\u2060\ufeff\u00ad"

_LETTER = "A-Za-z" + "".join(GREEK)
_SUB = "".join(SUBSCRIPTS)
_ONE_NAME = (rf"[{_LETTER}][{_LETTER}0-9_{{}}{_SUB}\u0307\u0308]*"
             rf"(?:\([{_LETTER}0-9_.{_SUB}]{{1,8}}\))?")
_ANSWER_LABEL = re.compile(r"\s*(?:answer|antwort|lösung|loesung|result|resultat)\s*:\s*",
                           re.IGNORECASE)
_NAME_EQUALS = re.compile(rf"\s*(\|\s*{_ONE_NAME}\s*\||{_ONE_NAME})\s*[=≈]\s*(?=\S)")
_APPROXIMATELY = re.compile(r"\s*(ca\.?|approx\.?|circa|≈|~|∼|≃)\s*(?=[0-9.(+\-−])",
                            re.IGNORECASE)
_REMARK = re.compile(r"(?<![\w)\]])\s*\(\s*([^\W\d_]+(?:[\s,.'’-]+[^\W\d_]+)*)\.?\s*\)\s*$")
_WORD = re.compile(r"[^\W\d_]+")
#: words a bracket may hold in a formula: constants, functions, Greek letters
_NOT_REMARKS = frozenset(CONSTANTS) | frozenset(FUNCTIONS) | frozenset(GREEK) | \
    frozenset(GREEK.values())
_WHOLE_NUMBER_WITH_POINT = re.compile(r"(?<![0-9.])[0-9]+\.$")
_SWISS_THOUSANDS = re.compile(r"(?<![0-9.,'’])[0-9]{1,3}(?:['’][0-9]{3})+(?![0-9'’])")
_TIMES_TEN = re.compile(r"(?<=[0-9])\s*[xX]\s*10(?=\s*(?:\^|\*\*|[" + "".join(SUPERSCRIPTS) + "]))")
_PI = re.compile(r"(?<![A-Za-z_])(?:Pi|PI)(?![A-Za-z0-9_])")
_POWER_DIGIT = re.compile(r"(?<=[0-9\s/*·])(s|m|mm|cm|km)([23])(?![A-Za-z0-9_])")

#: what an answer with a decoration contains somewhere (one quick test: most answers have
#: none and are read as typed)
_MAY_BE_DRESSED = {
    FORMULA: re.compile(rf"[=≈:'’{INVISIBLE}]|\.\s*$"),
    QUANTITY: re.compile(rf"[=≈~∼≃:'’{INVISIBLE}]|[.)]\s*$|(?i:^\s*(?:ca|approx|circa))"
                         r"|[xX]\s*10|P[iI]|[sm][23]"),
}


@dataclass(frozen=True)
class Stripped:
    """The answer with its decorations left out, and one note per decoration."""

    text: str
    changes: tuple[str, ...] = ()

    def note(self) -> str:
        """The sentence shown with the verdict ("Read as 3.2 m/s (left out 'v ='))."),
        empty when nothing was stripped."""
        if not self.changes:
            return ""
        return _("Read as {answer} ({changes}).").format(answer=self.text.strip(),
                                                       changes=self.listed())

    def listed(self) -> str:
        """The notes in one line ("left out 'v ='; read '1'200' as '1200'")."""
        return "; ".join(self.changes)


def mode_for(spec) -> str | None:
    """How answers to ``spec`` are read: numbers and vectors carry a ``unit`` field,
    formulas ``variables``; anything else (a choice) is read as typed (None)."""
    if hasattr(spec, "unit"):
        return QUANTITY
    if hasattr(spec, "variables"):
        return FORMULA
    return None


def strip(text: str, mode: str | None) -> Stripped:
    """``text`` without the decorations of ``mode`` (:data:`QUANTITY`, :data:`FORMULA`;
    None strips nothing), with a note for each."""
    if mode is None or not isinstance(text, str) or not _MAY_BE_DRESSED[mode].search(text):
        return Stripped(text)
    changes: list[str] = []
    text = _invisible(text, changes)
    text = _leading(text, changes, mode)
    text = _final_stop(text, changes)
    if mode == QUANTITY:
        text = _remark(text, changes)
        text = _final_stop(text, changes)
        text = _rewrite(text, _TIMES_TEN, "*10", changes)
        text = _rewrite(text, _PI, "pi", changes)
        if _POWER_DIGIT.search(text) and any(c.isdigit() for c in text):
            text = _powers(text, changes)
    text = _swiss(text, changes)
    return Stripped(text, tuple(dict.fromkeys(changes)))


def _invisible(text: str, changes: list[str]) -> str:
    found = [c for c in INVISIBLE if c in text]
    if not found:
        return text
    for c in found:
        text = text.replace(c, "")
    changes.append(_("removed invisible characters ({codes})").format(
        codes=", ".join(f"U+{ord(c):04X}" for c in found)))
    return text


def _leading(text: str, changes: list[str], mode: str) -> str:
    """Leave out ``Answer:``, then ``name =`` (not from a chain ``x = y = 3``, which
    stays an equation), then (for quantities) ``ca.``."""
    patterns = [_ANSWER_LABEL, _NAME_EQUALS] + ([_APPROXIMATELY] if mode == QUANTITY else [])
    for pattern in patterns:
        m = pattern.match(text)
        if m and m.end() < len(text) and not (pattern is _NAME_EQUALS and "=" in text[m.end():]):
            changes.append(_("left out '{text}'").format(text=m.group().strip()))
            text = text[m.end():]
    return text


def _final_stop(text: str, changes: list[str]) -> str:
    body = text.rstrip()
    if not body.endswith(".") or body.endswith("..") or len(body) < 2 or \
            _WHOLE_NUMBER_WITH_POINT.search(body):
        return text
    changes.append(_("left out the final full stop"))
    return body[:-1]


def _remark(text: str, changes: list[str]) -> str:
    """A final remark in brackets: words only, after a space or an operator (not a
    function's or a unit's own bracket), a number before it, and at least one word of two
    letters or more that is no unit, constant, function or Greek letter (so ``12 (N m)``
    keeps its unit and ``2 (pi)`` its π)."""
    m = _REMARK.search(text)
    if m is None or not text[:m.start()].strip() or not any(c.isdigit() for c in text[:m.start()]):
        return text
    from . import units
    from .errors import AnswerError

    def is_unit(word: str) -> bool:
        try:
            units.lookup(word)
        except AnswerError:
            return False
        return True

    if not any(len(word) >= 2 and word not in _NOT_REMARKS and not is_unit(word)
               for word in _WORD.findall(m.group(1))):
        return text
    changes.append(_("left out the remark '{remark}'").format(remark=m.group().strip()))
    return text[:m.start()].rstrip()


def _read_as(typed: str, read: str) -> str:
    return _("read '{typed}' as '{read}'").format(typed=typed, read=read)


def _rewrite(text: str, pattern: re.Pattern[str], read: str, changes: list[str]) -> str:
    """Every match of ``pattern`` replaced by ``read``, noted once."""
    m = pattern.search(text)
    if m is None:
        return text
    changes.append(_read_as(m.group().strip(), read))
    return pattern.sub(read, text)


def _powers(text: str, changes: list[str]) -> str:
    """``m/s2`` as m/s², only after the first digit (the number comes first)."""
    first_digit = next(i for i, c in enumerate(text) if c.isdigit())
    head, tail = text[:first_digit + 1], text[first_digit + 1:]
    m = _POWER_DIGIT.search(tail)
    if m is None:
        return text
    changes.append(_read_as(m.group(), m.group(1) + "^" + m.group(2)))
    return head + _POWER_DIGIT.sub(r"\1^\2", tail)


def _swiss(text: str, changes: list[str]) -> str:
    if "'" not in text and "’" not in text:
        return text
    m = _SWISS_THOUSANDS.search(text)
    if m is None:
        return text
    changes.append(_read_as(m.group(), _unquoted(m.group())))
    return _SWISS_THOUSANDS.sub(lambda s: _unquoted(s.group()), text)


def _unquoted(digits: str) -> str:
    return digits.replace("'", "").replace("’", "")


def annotated(verdict, stripped: Stripped, spec):
    """``verdict`` on the stripped answer, with the note on what was stripped, and, when
    a scalar part could not read an answer written with basis vectors, a refusal that
    says a vector was given (:func:`.basis.vector_given`)."""
    from dataclasses import replace

    from .verdict import unreadable

    if verdict.error:
        given = _vector_refusal(spec, stripped.text)
        if given:
            verdict = unreadable(given)
    note = stripped.note()
    if not note:
        return verdict
    return replace(verdict, feedback=f"{verdict.feedback} {note}",
                   error=f"{verdict.error} {note}" if verdict.error else verdict.error)


def noted_reading(reading, stripped: Stripped, spec):
    """A :class:`~.readability.Readability` with the same note and refusal as
    :func:`annotated`."""
    from dataclasses import replace

    if not reading.readable:
        given = _vector_refusal(spec, stripped.text)
        if given:
            reading = replace(reading, message=given)
    if not stripped.changes:
        return reading
    return replace(reading, message=f"{reading.message} ({stripped.listed()})")


def _vector_refusal(spec, text: str) -> str:
    """Why a scalar part (a number or a formula) refuses an answer written with basis
    vectors, in words that say how to answer instead; empty for vector parts and for
    answers without basis vectors."""
    mode = mode_for(spec)
    if mode is None or hasattr(spec, "size"):
        return ""
    from .basis import vector_given

    found = vector_given(text)
    if found is None:
        return ""
    if mode == QUANTITY:
        return _("this part wants a number; a vector was given ('{name}' is a basis vector): "
                 "give one number with its unit, such as 3.2 m/s").format(name=found)
    return _("this part wants a formula; a vector was given ('{name}' is a basis vector): "
             "give one expression in the part's variables").format(name=found)
