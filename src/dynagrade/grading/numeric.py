"""Grading of numeric parts: read the value, convert it to the part's unit, compare.

The module is the kind's grading half (:mod:`.kinds`): besides grading it reads an answer
without the reference (``read_numeric``) and builds the spec of a ``dynagrade compare`` record
(``build_numeric``).
"""

from __future__ import annotations

from ..i18n import _, ngettext
import math

from . import frequency, units
from .errors import AnswerError, SpecError
from .feedback import show_number, show_tolerance, show_value
from .latex import plain_text
from .misconceptions import CYCLES, UNIT, numeric_candidates
from .quantity import Quantity, read_quantity, unit_cycles, unit_info
from .spec import NumericSpec
from .tolerance import count_sigfigs, digits_needed, is_close, round_sig, same_sigfigs
from .verdict import Verdict, unreadable
from . import records
from .readability import Readability
from .records import Common


def expected_value(expected) -> float:
    """A numeric part's reference as a finite float; :class:`SpecError` otherwise."""
    if isinstance(expected, bool) or not isinstance(expected, (int, float)):
        try:
            import numpy as np

            if isinstance(expected, np.generic):
                expected = float(expected)
            else:
                raise TypeError
        except TypeError:
            raise SpecError(f"the reference of a numeric part must be a number, got {expected!r}") from None
    value = float(expected)
    if not math.isfinite(value):
        raise SpecError(f"the reference of a numeric part must be finite, got {value!r}")
    return value


def grade_numeric(spec: NumericSpec, expected, answer: str) -> Verdict:
    """The verdict on a number answer (see :func:`dynagrade.grading.grade`)."""
    e = expected_value(expected)
    try:
        q, reading = _read(spec, answer)
    except AnswerError as error:
        return unreadable(str(error))
    return _verdict(spec, e, q, reading)


def accepts_numeric(spec: NumericSpec, expected, answer: str) -> bool:
    """Whether :func:`grade_numeric` calls ``answer`` correct, decided without looking
    for the misconception behind a wrong answer or writing its feedback."""
    e = expected_value(expected)
    try:
        _, reading = _read(spec, answer)
    except AnswerError:
        return False
    return _accepted(spec, e, reading)


def _read(spec: NumericSpec, answer: str) -> tuple[Quantity, _Reading]:
    """The answer as typed and in the part's unit; :class:`AnswerError` when it cannot
    be read or is no finite number."""
    part_factor, part_dim = unit_info(spec.unit)
    q = read_quantity(answer)
    if not math.isfinite(q.value):
        raise AnswerError(_("your answer is not a finite number (it overflows or is undefined)"))
    return q, _read_in_part_unit(spec, q, part_factor, part_dim)


class _Reading:
    """The answer's value in the part's unit, and what is wrong with its unit.

    ``turns`` is the power of 2π the frequency rule converted with (:func:`.frequency.align`:
    1 for Hz read as rad/s, -1 for rad/s read as Hz), ``unconverted`` the value that the
    other reading (Hz taken as rad/s and back) would give."""

    def __init__(self, value: float, unit_ok: bool, unit_problem: str | None, converted: bool,
                 turns: float = 0.0, unconverted: float = math.nan):
        self.value = value
        self.unit_ok = unit_ok
        self.unit_problem = unit_problem
        self.converted = converted
        self.turns = turns
        self.unconverted = unconverted


def _read_in_part_unit(spec: NumericSpec, q: Quantity, part_factor: float, part_dim: tuple) -> _Reading:
    wants_unit = not units.is_dimensionless(part_dim, ignore_angle=False)
    if q.dim is None:
        if spec.require_unit and wants_unit:
            return _Reading(q.value, False, _("give the unit with your answer (the answer is in {unit})").format(unit=spec.unit), False)
        return _Reading(q.value, True, None, False)
    given_dim, wanted_dim, turns = frequency.align(q.dim, q.cycles, part_dim, unit_cycles(spec.unit))
    if units.compatible(given_dim, wanted_dim):
        same_unit = abs(q.unit_factor - part_factor) <= 1e-12 * part_factor and \
            units.same(q.dim, part_dim) and not turns
        return _Reading(q.value * frequency.TWO_PI ** turns / part_factor, True, None,
                        not same_unit, turns, q.value / part_factor)
    given = f"{units.describe_dimension(q.dim)} ({q.unit_text or units.format_dimension(q.dim)})"
    if wants_unit:
        wanted = f"{units.describe_dimension(part_dim)} ({spec.unit})"
    else:
        wanted = _("a pure number (no unit)")
    typed = q.value / q.unit_factor if q.unit_text else q.value
    return _Reading(typed, False, _("you gave {given}, expected {wanted}").format(given=given, wanted=wanted), False)


def one_unit_in_part_unit(name: str, part_unit: str) -> float | None:
    """How much one ``name`` is in the part's unit as the grader reads an answer ``1 name``
    (the frequency rule included: one Hz in a rad/s part is 2π), or None when the grader
    does not take ``name`` for that part. Exports that convert units themselves (Moodle's
    unit multipliers) use it, so that they convert as the grader does."""
    try:
        q = read_quantity("1 " + name, decimal_comma=False)
    except AnswerError:
        return None
    factor, dim = unit_info(part_unit)
    reading = _read_in_part_unit(NumericSpec(unit=part_unit), q, factor, dim)
    return reading.value if (q.dim is not None and reading.unit_ok) else None


def _close(spec: NumericSpec, value: float, e: float) -> bool:
    if spec.sigfigs is not None:
        return same_sigfigs(value, e, spec.sigfigs)
    return is_close(value, e, spec.rtol, spec.atol)


def _accepted(spec: NumericSpec, e: float, reading: _Reading) -> bool:
    """A right answer: its value within the tolerance and its unit right."""
    return _close(spec, reading.value, e) and reading.unit_ok


def _verdict(spec: NumericSpec, e: float, q: Quantity, reading: _Reading) -> Verdict:
    value_ok = _close(spec, reading.value, e)
    u = spec.unit_credit
    shown = show_value(reading.value, spec.unit)
    reveal = " " + _("The expected answer is {answer}.").format(
        answer=show_value(e, spec.unit)) if spec.reveal else ""
    if _accepted(spec, e, reading):
        if reading.turns:
            return Verdict(True, 1.0, _cycles_note(reading.turns).format(answer=shown))
        if reading.converted:
            return Verdict(True, 1.0, _("Correct (read as {answer}).").format(answer=shown))
        return Verdict(True, 1.0, _("Correct."))
    if not reading.unit_ok:
        return _unit_verdict(spec, reading.unit_problem, value_ok, reveal, UNIT)
    if reading.turns and _close(spec, reading.unconverted, e):
        return _unit_verdict(spec, _cycles_confusion(reading.turns, q), True, reveal, CYCLES)
    unit_score = u if u is not None else 0.0
    found = _misconception(spec, e, reading.value, q)
    if found is not None:
        name, feedback, score = found
        total = unit_score + (1.0 - unit_score) * score if u is not None else score
        return Verdict(False, min(1.0, total), feedback + reveal, misconception=name)
    if spec.sigfigs is not None:
        text = _("Not correct: {answer} does not round to the expected value at {digits} "
                 "significant figures").format(answer=shown, digits=spec.sigfigs)
    else:
        text = _("Not correct: {answer} is not within the tolerance ({tolerance})").format(
            answer=shown, tolerance=show_tolerance(spec.rtol, spec.atol, spec.unit))
    text += "." + _digits_hint(spec, e, q, reading) + reveal
    return Verdict(False, unit_score, text)


def _unit_verdict(spec: NumericSpec, problem: str | None, value_ok: bool, reveal: str,
                  name: str) -> Verdict:
    """The verdict on an answer whose unit is wrong (``unit_credit`` scores a right number)."""
    u = spec.unit_credit
    score = (1.0 - u) if (u is not None and value_ok) else 0.0
    text = _("Unit problem: {problem}.").format(problem=problem)
    if u is not None:
        text += " " + (_("The number is right.") if value_ok else
                       _("The number is not right either."))
    return Verdict(False, score, text + reveal, misconception=name)


def _cycles_note(turns: float) -> str:
    """The note of a right answer the frequency rule converted (``{answer}`` to fill)."""
    if turns > 0:
        return _("Correct (read as {answer}: a frequency in Hz or rpm counts turns, ω = 2π·f).")
    return _("Correct (read as {answer}: an angular frequency in rad/s is 2π times the "
             "frequency, f = ω/(2π)).")


def _cycles_confusion(turns: float, q: Quantity) -> str:
    """What is wrong with a number that is right but labelled in the other kind of frequency."""
    unit = q.unit_text or units.format_dimension(q.dim or units.DIMENSIONLESS)
    if turns > 0:
        return _("your number is the angular frequency ω in rad/s, but {unit} counts cycles per "
                 "time; the frequency is f = ω/(2π)").format(unit=unit)
    return _("your number is the frequency f in Hz, but {unit} measures an angle per time; the "
             "angular frequency is ω = 2π·f").format(unit=unit)


def _misconception(spec: NumericSpec, e: float, value: float, q: Quantity):
    for known in spec.misconceptions:
        try:
            if isinstance(known.value, tuple):
                raise TypeError("a tuple is no number")
            wrong = float(known.value)
        except (TypeError, ValueError):
            raise SpecError(f"misconception {known.name!r} needs a number, got {known.value!r}") from None
        if math.isfinite(wrong) and not _close(spec, wrong, e) and _close(spec, value, wrong):
            return known.name, known.feedback, known.score
    if not spec.generic_misconceptions:
        return None
    part_dim = unit_info(spec.unit)[1]
    angle_unit = None
    if units.has_angle(part_dim) and units.is_dimensionless(part_dim):
        angle_unit = "rad" if abs(unit_info(spec.unit)[0] - 1.0) < 1e-12 else "deg"
    rotational = units.has_angle(part_dim) or (
        units.same(part_dim, (0, 0, -1, 0, 0, 0, 0, 0), ignore_angle=True))
    for name, wrong, feedback in numeric_candidates(e, angle_unit=angle_unit, rotational=rotational):
        if math.isfinite(wrong) and not _close(spec, wrong, e) and _close(spec, value, wrong):
            return name, feedback, 0.0
    return None


def _digits_hint(spec: NumericSpec, e: float, q: Quantity, reading: _Reading) -> str:
    """A hint when the answer is the reference correctly rounded, but too coarsely."""
    if q.number_text is None:
        return ""
    typed = count_sigfigs(q.number_text)
    needed = spec.sigfigs if spec.sigfigs is not None else digits_needed(spec.rtol)
    if typed >= needed:
        return ""
    # The reference expressed in the unit the student wrote.
    scale = 1.0
    if q.dim is not None and q.unit_text:
        scale = unit_info(spec.unit)[0] / q.unit_factor
    typed_value = reading.value * scale
    if round_sig(e * scale, typed) == round_sig(typed_value, typed):
        return " " + ngettext("You gave {typed} significant figure; give at least {needed}.",
                              "You gave {typed} significant figures; give at least {needed}.",
                              typed).format(typed=typed, needed=needed)
    return ""


__all__ = ["grade_numeric", "accepts_numeric", "expected_value", "show_number"]


def read_numeric(spec: NumericSpec, text: str) -> Readability:
    """How ``text`` reads as an answer to ``spec`` (:func:`.readability.readability`)."""
    quantity = read_quantity(text)
    if not math.isfinite(quantity.value):
        return Readability(False, _("the answer is not a finite number"))
    factor, dim = unit_info(spec.unit)
    reading = _read_in_part_unit(spec, quantity, factor, dim)
    if not reading.unit_ok:
        return Readability(False, _("unit problem: {problem}").format(problem=reading.unit_problem))
    shown = show_value(reading.value, spec.unit)
    if quantity.dim is None:
        if spec.unit:
            return Readability(True, _("reads as {answer} (a bare number is read in {unit})")
                               .format(answer=shown, unit=spec.unit))
        return Readability(True, _("reads as {answer}").format(answer=shown))
    if not reading.converted:
        return Readability(True, _("reads as {answer}").format(answer=shown))
    written = plain_text(text.strip(), quantity=True)
    return Readability(True, _("reads as {answer}").format(answer=f"{written} = {shown}"))


def build_numeric(record: dict, common: Common):
    """A numeric record's spec and reference (``dynagrade compare``, :mod:`.compare`)."""
    expected, unit = _numeric_expected(record, common.unit)
    sigfigs = records.number(record, "sigfigs", integer=True)
    unit_credit = records.number(record, "unit_credit")
    spec = NumericSpec(unit=unit, **common.tolerances(), sigfigs=sigfigs,
                       misconceptions=common.misconceptions,
                       require_unit=records.flag(record, "require_unit"),
                       unit_credit=None if unit_credit is None else float(unit_credit),
                       reveal=common.reveal)
    return spec, expected


def _numeric_expected(record: dict, unit: str | None):
    """The reference as a float in the part's unit, and the unit (which a string
    reference like "12.5 m/s" may define)."""
    expected = record["expected"]
    if isinstance(expected, bool):
        raise records.RecordError("field 'expected' must be a number or a string with a unit")
    if isinstance(expected, (int, float)):
        if not math.isfinite(expected):
            raise records.RecordError("field 'expected' must be finite")
        return float(expected), unit
    if not isinstance(expected, str):
        raise records.RecordError("field 'expected' must be a number or a string with a unit")
    try:
        q = read_quantity(expected)
    except AnswerError as error:
        raise records.RecordError(f"cannot read 'expected': {error.message}") from None
    if q.dim is None:
        return q.value, unit
    if unit is None:
        if q.unit_text is None:
            raise records.RecordError("cannot tell the unit of 'expected'; give the field 'unit'")
        return q.value / q.unit_factor, q.unit_text.replace(" ", "")
    factor, dim = unit_info(unit)
    if not units.compatible(q.dim, dim):
        raise records.RecordError(f"'expected' ({expected}) cannot be converted to '{unit}'")
    return q.value / factor, unit
