"""Small readers for the exercise model: a number in a unit, and a formula's value."""

from __future__ import annotations

from ..i18n import _
import math
from typing import Mapping

from .errors import AnswerError


def read_number(text: str, unit: str | None = None) -> float:
    """The value of a number answer (``"45 km/h"``, ``"12,5"``, ``"2*pi"``) in ``unit``.

    A bare number is taken to be in ``unit`` already; Hz counts cycles (:mod:`.frequency`:
    ``1 Hz`` in rad/s is 2π). Raises :class:`AnswerError` when
    the text cannot be read, is not finite, or has a unit of another dimension.
    """
    from . import frequency, units
    from .quantity import read_quantity, unit_cycles, unit_info

    q = read_quantity(text)
    if not math.isfinite(q.value):
        raise AnswerError(_("the answer is not a finite number"))
    if q.dim is None:
        return q.value
    factor, dim = unit_info(unit)
    given, wanted, turns = frequency.align(q.dim, q.cycles, dim, unit_cycles(unit))
    if not units.compatible(given, wanted):
        raise AnswerError(_("you gave {given}, expected {wanted}").format(
            given=units.describe_dimension(q.dim),
            wanted=f"{units.describe_dimension(dim)} ({unit or _('no unit')})"))
    return q.value * frequency.TWO_PI ** turns / factor


def evaluate_expression(expression: str, values: Mapping[str, float]) -> float:
    """The value of a formula (parsed by the safe parser) with its variables set to
    ``values`` (numbers, typically in SI). Raises :class:`AnswerError` when it cannot be read."""
    import numpy as np

    from .evaluate import evaluate
    from .parser import parse_expression

    tree = parse_expression(expression, tuple(values))
    env = {name: np.float64(value) for name, value in values.items()}
    return float(np.asarray(evaluate(tree, env), dtype=np.float64))
