"""Closeness of numbers: the tolerance rule and significant figures.

Rule: an answer ``a`` is close to the reference ``e`` when
``|a - e| <= max(atol, rtol*|e|)``; when no ``atol`` is given the absolute floor
:data:`DEFAULT_ATOL` is used, so a reference of exactly 0 is gradable.

Significant figures: with ``sigfigs = N`` the answer is right when it *rounds to the
same N significant figures* as the reference: both are rounded half away from zero
to N significant digits (after trimming float noise to 12 digits) and must agree.
"""

from __future__ import annotations

import math
from decimal import ROUND_HALF_UP, Decimal

#: Absolute tolerance used when a part sets none, in the part's unit.
DEFAULT_ATOL = 1e-9
#: Relative tolerance of numeric and vector parts that set none.
DEFAULT_RTOL = 1e-2


def allowed_error(expected: float, rtol: float, atol: float | None) -> float:
    """The largest ``|answer - expected|`` the rule accepts: ``max(atol, rtol*|expected|)``
    with ``atol`` defaulting to :data:`DEFAULT_ATOL`."""
    floor = DEFAULT_ATOL if atol is None else atol
    return max(floor, rtol * abs(expected))


def is_close(answer: float, expected: float, rtol: float, atol: float | None) -> bool:
    """The tolerance rule; the boundary is inclusive up to float rounding (2.02 for 2 at 1 %)."""
    slack = 8 * 2.0 ** -52 * max(abs(answer), abs(expected))
    return abs(answer - expected) <= allowed_error(expected, rtol, atol) + slack


def round_sig(value: float, digits: int) -> Decimal:
    """``value`` rounded half away from zero to ``digits`` significant figures."""
    if value == 0 or not math.isfinite(value):
        return Decimal(0)
    d = Decimal(f"{value:.12g}")
    quantum = Decimal(1).scaleb(d.adjusted() - digits + 1)
    return d.quantize(quantum, rounding=ROUND_HALF_UP)


def same_sigfigs(answer: float, expected: float, digits: int) -> bool:
    return round_sig(answer, digits) == round_sig(expected, digits)


def count_sigfigs(literal: str) -> int:
    """Significant figures of a typed number: ``0.0120`` -> 3, ``1200`` -> 2, ``1.2e3`` -> 2.

    Trailing zeros of a whole number without a decimal point are not counted.
    """
    mantissa = literal.lower().split("e")[0].replace(",", ".")
    digits = mantissa.replace(".", "").lstrip("0")
    if "." not in mantissa:
        digits = digits.rstrip("0")
    return max(1, len(digits))


def digits_needed(rtol: float) -> int:
    """Significant figures that always land within ``rtol`` when correctly rounded."""
    if rtol <= 0:
        return 15
    return max(2, min(15, math.ceil(math.log10(5.0 / rtol))))
