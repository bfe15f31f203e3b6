"""Grading of vectors: every component read, converted and compared on its own.

The credit rule (docs/grading.md, "Vectors") is one function, :func:`component_answers`:
each component is held against the answers it may be, in order — the reference (full
credit), then each declared misconception that differs from the reference in that
component (its score) — and earns the credit of the first it lies within, 0 if none;
the vector scores the mean credit of its components. The Moodle export writes the same
answers as each component's alternatives (:mod:`dynagrade.render.moodle`), and Moodle
marks a field by the first alternative within tolerance and a cloze question by the
weighted mean, so an answer earns the same credit in both.

The module is the kind's grading half (:mod:`.kinds`): besides grading it reads an answer
without the reference (``read_vector``) and builds the spec of a ``dynagrade compare`` record
(``build_vector``).
"""

from __future__ import annotations

from ..i18n import N_, _
import math
from dataclasses import dataclass, replace

import numpy as np

from . import frequency, units
from .errors import AnswerError, SpecError
from .feedback import show_number, show_value
from .misconceptions import UNIT
from .basis import read_basis
from .nodes import BinOp, Expr
from .parser import parse_vector
from .quantity import quantity_from_tree, unit_cycles, unit_info
from .spec import VectorSpec
from .tolerance import allowed_error, is_close
from .verdict import Verdict, unreadable
from . import records
from .readability import Readability
from .records import Common


def _expected(spec: VectorSpec, expected) -> np.ndarray:
    try:
        values = np.array([float(x) for x in expected], dtype=np.float64)
    except (TypeError, ValueError):
        raise SpecError(f"the reference of a vector part must be a sequence of numbers, got {expected!r}") from None
    if values.shape != (spec.size,) or not np.all(np.isfinite(values)):
        raise SpecError(f"the reference must hold {spec.size} finite numbers, got {expected!r}")
    return values


def component_scale(e: np.ndarray) -> np.ndarray:
    """What each component's relative tolerance is taken of: ``max(|e_i|, 0.01*|e|)``,
    so a zero component is judged against the vector's length."""
    return np.maximum(np.abs(e), 0.01 * float(np.linalg.norm(e)))


def component_tolerance(spec: VectorSpec, e: np.ndarray) -> np.ndarray:
    """The largest error each component may have (for exports that state tolerances):
    the number rule's :func:`allowed_error` with the scale of :func:`component_scale`."""
    return allowed_error(e, spec.rtol, spec.atol, component_scale(e))


@dataclass(frozen=True)
class ComponentAnswer:
    """An answer a component may be: its ``value``, the ``credit`` it earns, the largest
    error ``allowed`` around it (the component's tolerance) and the ``feedback`` it
    carries (empty for the reference)."""

    value: float
    credit: float
    allowed: float
    feedback: str = ""


def component_answers(spec: VectorSpec, expected) -> list[tuple[ComponentAnswer, ...]]:
    """For each component, the answers it is graded against, in order: the reference
    with credit 1, then every declared misconception whose value differs from the
    reference in that component, with its score and feedback. A component earns the
    credit of the first answer it lies within; the vector, the mean of its components'
    credits (docs/grading.md, "Vectors"). A misconception of the wrong length or with a
    non-finite component there never matches and is left out."""
    e = _expected(spec, expected)
    scale = component_scale(e)
    allowed = component_tolerance(spec, e)
    targets = [(known, _known_values(known)) for known in spec.misconceptions]
    answers = []
    for i, value in enumerate(e):
        found = [ComponentAnswer(float(value), 1.0, float(allowed[i]))]
        for known, target in targets:
            if target.shape == e.shape and math.isfinite(target[i]) and not is_close(
                    float(target[i]), float(value), spec.rtol, spec.atol, float(scale[i])):
                found.append(ComponentAnswer(float(target[i]), known.score, float(allowed[i]),
                                             known.feedback))
        answers.append(tuple(found))
    return answers


def component_credits(spec: VectorSpec, expected, values: np.ndarray) -> list[float]:
    """Each component's credit under :func:`component_answers`."""
    scale = component_scale(_expected(spec, expected))
    return [next((a.credit for a in candidates
                  if is_close(float(v), a.value, spec.rtol, spec.atol, float(s))), 0.0)
            for v, s, candidates in zip(values, scale, component_answers(spec, expected))]


def grade_vector(spec: VectorSpec, expected, answer: str) -> Verdict:
    e = _expected(spec, expected)
    values, note = _answer_values(spec, answer)
    if isinstance(values, Verdict):
        return _noted(values, note)
    return _noted(_verdict(spec, e, values), note)


def _verdict(spec: VectorSpec, e: np.ndarray, values: np.ndarray) -> Verdict:
    scale = component_scale(e)
    right = is_close(values, e, spec.rtol, spec.atol, scale)
    reveal = ""
    if spec.reveal:
        shown = "(" + ", ".join(show_number(x) for x in e) + ")" + \
            (f" {spec.unit}" if spec.unit else "")
        reveal = " " + _("The expected answer is {answer}.").format(answer=shown)
    if right.all():
        return Verdict(True, 1.0, _("Correct."))
    score = float(sum(component_credits(spec, e, values))) / spec.size
    found = _misconception(spec, e, values, scale)
    if found is not None:
        name, feedback = found
        return Verdict(False, score, feedback + reveal, misconception=name)
    marks = ", ".join(f"{i + 1}: {_('✓ right') if ok else _('✗ wrong')}"
                      for i, ok in enumerate(right))
    return Verdict(False, score, _("Not correct: {n} of {total} components are right ({marks}).")
                   .format(n=int(right.sum()), total=spec.size, marks=marks) + reveal)


def accepts_vector(spec: VectorSpec, expected, answer: str) -> bool:
    """Whether :func:`grade_vector` calls ``answer`` correct, decided without looking
    for the misconception behind a wrong answer or writing its feedback."""
    e = _expected(spec, expected)
    values, _note = _answer_values(spec, answer)
    return not isinstance(values, Verdict) and \
        bool(is_close(values, e, spec.rtol, spec.atol, component_scale(e)).all())


def _noted(verdict: Verdict, note: str) -> Verdict:
    """``verdict`` with the note on how the answer was read (:mod:`.basis`)."""
    if not note:
        return verdict
    return replace(verdict, feedback=f"{verdict.feedback} {note}")


def _parse(spec: VectorSpec, text: str) -> tuple[list[Expr | None], Expr | None, str]:
    """The answer's component trees (None: a basis vector left out, 0), the unit written
    after its brackets, and a note on how it was read: with basis vectors
    (:mod:`.basis`) when it uses them, else in brackets (:func:`.parser.parse_vector`)."""
    reading = read_basis(spec.size, spec.basis, text)
    if reading is not None:
        return reading.components, None, reading.note
    components, unit_tree = parse_vector(text)
    return list(components), unit_tree, ""


def answer_components(spec: VectorSpec, answer: str) -> np.ndarray | None:
    """The answer's components in the part's unit, read as the grader reads them; None
    when it gives none to compare (unreadable, a unit problem, a wrong count)."""
    values, _note = _answer_values(spec, answer)
    return values if isinstance(values, np.ndarray) else None


def _answer_values(spec: VectorSpec, answer: str) -> tuple[np.ndarray | Verdict, str]:
    """The answer's components in the part's unit, or the verdict on an answer that
    gives none to compare (unreadable, a unit problem, a wrong count, not finite); and
    the note on how it was read."""
    part_factor, part_dim = unit_info(spec.unit)
    note = ""
    try:
        components, unit_tree, note = _parse(spec, answer)
        values, problem = _read(spec, components, unit_tree, answer, part_factor, part_dim)
    except AnswerError as error:
        return unreadable(str(error)), note
    if problem:
        return Verdict(False, 0.0, _("Unit problem: {problem}.").format(problem=problem),
                       misconception=UNIT), note
    if len(values) != spec.size:
        return Verdict(False, 0.0, _("Not correct: the answer needs {size} components, you gave "
                                     "{given}.").format(size=spec.size, given=len(values))), note
    if not np.all(np.isfinite(values)):
        return unreadable(_("a component of your answer is not a finite number")), note
    return values, note


def _read(spec, components, unit_tree, text, part_factor, part_dim):
    values = []
    trailing_factor, trailing_dim, trailing_cycles = 1.0, None, 0.0
    if unit_tree is not None:
        q = quantity_from_tree(unit_tree, text, require_number=False)
        trailing_factor, trailing_dim, trailing_cycles = q.value, q.dim, q.cycles
    wants_unit = not units.is_dimensionless(part_dim, ignore_angle=False)
    for k, tree in enumerate(components):
        if tree is None:  # a basis vector the answer leaves out
            values.append(0.0)
            continue
        q = quantity_from_tree(tree, text)
        dim = q.dim
        value = q.value
        if trailing_dim is not None:
            dim = units.add(dim, trailing_dim) if dim is not None else trailing_dim
            value *= trailing_factor
        if dim is None:
            if spec.require_unit and wants_unit:
                return [], _("give the unit with your answer (the answer is in {unit})").format(
                    unit=spec.unit)
            values.append(value)
            continue
        dim, wanted_dim, turns = frequency.align(dim, q.cycles + trailing_cycles, part_dim,
                                                 unit_cycles(spec.unit))
        if not units.compatible(dim, wanted_dim):
            wanted = f"{units.describe_dimension(part_dim)} ({spec.unit})" if wants_unit \
                else _("pure numbers")
            return [], _("component {k} is {given}, expected {wanted}").format(
                k=k + 1, given=units.describe_dimension(dim), wanted=wanted)
        values.append(value * frequency.TWO_PI ** turns / part_factor)
    return np.array(values, dtype=np.float64), None


def _known_values(known) -> np.ndarray:
    """A declared misconception's vector as numbers; SpecError when it is none."""
    try:
        return np.array([float(x) for x in known.value], dtype=np.float64)
    except (TypeError, ValueError):
        raise SpecError(f"misconception {known.name!r} needs a sequence of numbers") from None


def _misconception(spec: VectorSpec, e: np.ndarray, values: np.ndarray, scale: np.ndarray):
    """The (name, feedback) of the mistake the whole answer is: a declared misconception,
    else a generic one (sign, order, factor 2). It names the mistake only; the score is
    the components' credit (:func:`component_credits`)."""
    def close(a, b) -> bool:
        return bool(np.all(is_close(a, b, spec.rtol, spec.atol, scale)))

    def matches(target) -> bool:
        target = np.asarray(target, dtype=np.float64)
        return target.shape == e.shape and close(values, target) and not close(e, target)

    for known in spec.misconceptions:
        if matches(_known_values(known)):
            return known.name, known.feedback
    if not spec.generic_misconceptions:
        return None
    if matches(-e):
        return N_("sign"), _("Your vector points the opposite way: check the signs of the "
                             "components.")
    if spec.size >= 2 and matches(e[::-1]):
        return N_("swapped components"), _("Your components are in the wrong order.")
    if matches(2 * e):
        return N_("factor 2"), _("Your vector is twice the expected one: check for an extra "
                                 "factor of 2.")
    if matches(e / 2):
        return N_("factor 1/2"), _("Your vector is half the expected one: check for a missing "
                                   "factor of 2.")
    return None


def read_vector(spec: VectorSpec, text: str) -> Readability:
    """How ``text`` reads as an answer to ``spec`` (:func:`.readability.readability`)."""
    components, unit_tree, note = _parse(spec, text)
    factor, dim = unit_info(spec.unit)
    values, problem = _read(spec, components, unit_tree, text, factor, dim)
    if problem:
        return Readability(False, _("unit problem: {problem}").format(problem=problem))
    if len(values) != spec.size:
        return Readability(False, _("the answer needs {size} components, it has {given}").format(
            size=spec.size, given=len(values)))
    if not all(math.isfinite(v) for v in values):
        return Readability(False, _("a component is not a finite number"))
    shown = ", ".join(show_value(float(v), None) for v in values)
    unit = f" {spec.unit}" if spec.unit else ""
    return Readability(True, _("reads as {answer}").format(answer=f"({shown}){unit}") +
                       (f". {note}" if note else ""))


def build_vector(record: dict, common: Common):
    """A vector record's spec and reference (``dynagrade compare``, :mod:`.compare`)."""
    expected = record["expected"]
    if not isinstance(expected, list) or not all(
            isinstance(x, (int, float)) and not isinstance(x, bool) for x in expected):
        raise records.RecordError("field 'expected' of a vector must be a list of numbers")
    size = records.number(record, "size", integer=True) or len(expected)
    try:
        spec = VectorSpec(size, unit=common.unit, **common.tolerances(),
                          misconceptions=common.misconceptions,
                          require_unit=records.flag(record, "require_unit"), reveal=common.reveal,
                          basis=tuple(records.strings(record, "basis", "the record")))
    except ValueError as error:
        raise records.RecordError(str(error)) from None
    return spec, tuple(float(x) for x in expected)
