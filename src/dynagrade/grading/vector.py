"""Grading of vectors: every component read, converted and compared on its own."""

from __future__ import annotations

import math

import numpy as np

from . import units
from .errors import AnswerError, SpecError
from .feedback import show_number, show_value
from .misconceptions import UNIT
from .nodes import BinOp
from .parser import parse_vector
from .quantity import quantity_from_tree, unit_info
from .spec import VectorSpec
from .tolerance import allowed_error, is_close
from .verdict import Verdict, unreadable


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


def grade_vector(spec: VectorSpec, expected, answer: str) -> Verdict:
    e = _expected(spec, expected)
    values = _answer_values(spec, answer)
    if isinstance(values, Verdict):
        return values
    scale = component_scale(e)
    right = is_close(values, e, spec.rtol, spec.atol, scale)
    reveal = ""
    if spec.reveal:
        reveal = " The expected answer is (" + ", ".join(show_number(x) for x in e) + ")" + \
            (f" {spec.unit}." if spec.unit else ".")
    if right.all():
        return Verdict(True, 1.0, "Correct.")
    found = _misconception(spec, e, values, scale)
    if found is not None:
        name, feedback, score = found
        return Verdict(False, score, feedback + reveal, misconception=name)
    marks = ", ".join(f"{i + 1}: {'✓ right' if ok else '✗ wrong'}" for i, ok in enumerate(right))
    score = float(right.sum()) / spec.size
    return Verdict(False, score, f"Not correct: {int(right.sum())} of {spec.size} components are right ({marks})."
                   + reveal)


def accepts_vector(spec: VectorSpec, expected, answer: str) -> bool:
    """Whether :func:`grade_vector` calls ``answer`` correct, decided without looking
    for the misconception behind a wrong answer or writing its feedback."""
    e = _expected(spec, expected)
    values = _answer_values(spec, answer)
    return not isinstance(values, Verdict) and \
        bool(is_close(values, e, spec.rtol, spec.atol, component_scale(e)).all())


def _answer_values(spec: VectorSpec, answer: str) -> np.ndarray | Verdict:
    """The answer's components in the part's unit, or the verdict on an answer that
    gives none to compare (unreadable, a unit problem, a wrong count, not finite)."""
    part_factor, part_dim = unit_info(spec.unit)
    try:
        components, unit_tree = parse_vector(answer)
        values, problem = _read(spec, components, unit_tree, answer, part_factor, part_dim)
    except AnswerError as error:
        return unreadable(str(error))
    if problem:
        return Verdict(False, 0.0, f"Unit problem: {problem}.", misconception=UNIT)
    if len(values) != spec.size:
        return Verdict(False, 0.0, f"Not correct: the answer needs {spec.size} components, you gave {len(values)}.")
    if not np.all(np.isfinite(values)):
        return unreadable("a component of your answer is not a finite number")
    return values


def _read(spec, components, unit_tree, text, part_factor, part_dim):
    values = []
    trailing_factor, trailing_dim = 1.0, None
    if unit_tree is not None:
        q = quantity_from_tree(unit_tree, text, require_number=False)
        trailing_factor, trailing_dim = q.value, q.dim
    wants_unit = not units.is_dimensionless(part_dim, ignore_angle=False)
    for k, tree in enumerate(components):
        q = quantity_from_tree(tree, text)
        dim = q.dim
        value = q.value
        if trailing_dim is not None:
            dim = units.add(dim, trailing_dim) if dim is not None else trailing_dim
            value *= trailing_factor
        if dim is None:
            if spec.require_unit and wants_unit:
                return [], f"give the unit with your answer (the answer is in {spec.unit})"
            values.append(value)
            continue
        if not units.compatible(dim, part_dim):
            wanted = f"{units.describe_dimension(part_dim)} ({spec.unit})" if wants_unit else "pure numbers"
            return [], f"component {k + 1} is {units.describe_dimension(dim)}, expected {wanted}"
        values.append(value / part_factor)
    return np.array(values, dtype=np.float64), None


def _misconception(spec: VectorSpec, e: np.ndarray, values: np.ndarray, scale: np.ndarray):
    def close(a, b) -> bool:
        return bool(np.all(is_close(a, b, spec.rtol, spec.atol, scale)))

    def matches(target) -> bool:
        target = np.asarray(target, dtype=np.float64)
        return target.shape == e.shape and close(values, target) and not close(e, target)

    for known in spec.misconceptions:
        try:
            if isinstance(known.value, float):
                raise TypeError("a number is no sequence")
            target = np.array([float(x) for x in known.value], dtype=np.float64)
        except (TypeError, ValueError):
            raise SpecError(f"misconception {known.name!r} needs a sequence of numbers") from None
        if matches(target):
            return known.name, known.feedback, known.score
    if not spec.generic_misconceptions:
        return None
    if matches(-e):
        return "sign", "Your vector points the opposite way: check the signs of the components.", 0.0
    if spec.size >= 2 and matches(e[::-1]):
        return "swapped components", "Your components are in the wrong order.", 0.0
    if matches(2 * e):
        return "factor 2", "Your vector is twice the expected one: check for an extra factor of 2.", 0.0
    if matches(e / 2):
        return "factor 1/2", "Your vector is half the expected one: check for a missing factor of 2.", 0.0
    return None
