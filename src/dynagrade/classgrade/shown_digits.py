"""How closely a typed number pins its value, and what an agreement to every digit it
shows is worth to copy detection (:mod:`.copies`).

``12.3468`` stands for any value in ``12.3468 ± 0.00005``; ``12.3`` for ``12.3 ± 0.05``;
``1200`` for ``1200 ± 50`` (the trailing zeros of a whole number are not taken as
digits). An answer that agrees with a classmate's number to every digit it shows is a
narrower coincidence than one that only lies within the part's tolerance of it.

The width is found with the grader's own reader, never by evaluating the text: the first
number of the answer has its last shown digit changed by one, the changed text is read
like the answer, and half the difference of the two values is the width, in the part's
unit (so ``45 km/h`` in a part asked in m/s, or ``3.2 pi``, come out right). An answer
whose changed text cannot be read, or whose value is not a single number, shows no
digits (None).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

import numpy as np

from ..exam.manifest import PartEntry
from .answer_values import Value, answer_value, as_rows, window

#: the students beyond a pair who hand in one wrong number that make it a common mistake
COMMON = 2

_NUMBER = re.compile(r"(?P<mantissa>\d+(?:[.,]\d*)?|[.,]\d+)(?:[eE][+-]?\d+)?")


def last_digit_halfwidth(entry: PartEntry, text: str | None, value: Value | None) -> float | None:
    """Half a unit of the last digit ``text`` shows, in the part's unit (None: none)."""
    if not text or not isinstance(value, float) or not math.isfinite(value):
        return None
    found = _NUMBER.search(text)
    if found is None:
        return None
    mantissa = found.group("mantissa")
    has_point = any(c in mantissa for c in ".,")
    digits = [k for k, c in enumerate(mantissa) if c.isdigit() and (has_point or c != "0")]
    if not digits:
        return None
    k = found.start("mantissa") + digits[-1]
    changed_digit = "8" if text[k] == "9" else str(int(text[k]) + 1)
    changed = answer_value(entry, text[:k] + changed_digit + text[k + 1:])
    if not isinstance(changed, float) or changed == value:
        return None
    return abs(changed - value) / 2


@dataclass(frozen=True)
class DigitAgreement:
    """One wrong answer's last shown digit, held against the class's keys and wrong
    answers (one entry per student with a variant, in the same order)."""

    #: half a unit of the answer's last shown digit, in the part's unit
    halfwidth: float
    #: the part's tolerance around the answer, the same way
    tolerance: float
    #: per student, whether their key lies within ``halfwidth`` of the answer
    on_keys: np.ndarray
    #: per student, whether their wrong answer does
    on_answers: np.ndarray

    @classmethod
    def of(cls, entry: PartEntry, text: str | None, value: Value, key_rows: np.ndarray,
           answer_rows: np.ndarray, wrong: list[int]) -> "DigitAgreement | None":
        """The agreement of the answer ``text`` (read as ``value``); ``answer_rows`` holds
        the values of the wrong answers of the students ``wrong``. None: the answer shows
        no digits finer than the part's tolerance."""
        halfwidth = last_digit_halfwidth(entry, text, value)
        if halfwidth is None:
            return None
        assert isinstance(value, float)  # only a single number shows digits
        tolerance = float(window(entry, as_rows([value]))[0, 0])
        if not halfwidth < tolerance:
            return None
        slack = halfwidth * (1 + 1e-9)
        on_answers = np.zeros(len(key_rows), dtype=bool)
        on_answers[wrong] = np.abs(answer_rows[:, 0] - value) <= slack
        return cls(halfwidth, tolerance, np.abs(key_rows[:, 0] - value) <= slack, on_answers)

    def agrees(self, j: int, with_key: bool) -> bool:
        """Whether student ``j``'s key (or wrong answer) agrees to every shown digit."""
        return bool((self.on_keys if with_key else self.on_answers)[j])

    def narrowed(self, chance: float, others: np.ndarray, with_key: bool, identical: float,
                 near_keys: float | None) -> float:
        """The chance of an agreement to every digit: ``chance`` (the tolerance's) times
        the share of the tolerance window the digits leave, and at least

        - ``identical``, the share of the class's pairs of different variants whose keys
          of the part are the same number (:mod:`.coinciding_keys`);
        - when the two keys lie within ``near_keys`` tolerances of each other, the
          chance that an honest slip anywhere in that window lands on the number;
        - for a match on a wrong answer, the share of the rest of the class (``others``)
          that hands in the same number, when :data:`COMMON` or more do (a wrong number
          that several students hand in is a common mistake; one more is what a group
          of copiers shows)."""
        floors = [chance * self.halfwidth / self.tolerance, identical]
        if near_keys is not None:
            floors.append(self.halfwidth / (near_keys * self.tolerance))
        if not with_key:
            same = int((self.on_answers & others).sum())
            if same >= COMMON:
                floors.append(same / max(int(others.sum()), 1))
        return max(floors)
