"""Closeness of numbers: the tolerance rules and significant figures.

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
#: Rounding slack of the comparison, relative to the larger of the two numbers.
_ROUNDING = 8 * 2.0 ** -52


def allowed_error(expected, rtol: float, atol: float | None, scale=None):
    """The largest ``|answer - expected|`` the rule accepts: ``max(atol, rtol*s)`` with
    ``atol`` defaulting to :data:`DEFAULT_ATOL` and ``s = |expected|`` unless ``scale``
    is given; element by element on arrays."""
    floor = DEFAULT_ATOL if atol is None else atol
    if isinstance(expected, (int, float)) and (scale is None or isinstance(scale, (int, float))):
        return max(floor, rtol * (abs(expected) if scale is None else scale))
    import numpy as np

    return np.maximum(floor, rtol * (np.abs(expected) if scale is None else scale))


def is_close(answer, expected, rtol: float, atol: float | None, scale=None):
    """The tolerance rule ``|a - e| <= allowed_error(e, ...)``; the boundary is inclusive
    up to float rounding (2.02 for 2 at 1 %), and a non-finite answer is never close.

    The one rule for numbers and vector components alike: on arrays it answers
    element by element (vectors pass the scale of each component).
    """
    if isinstance(answer, float) and isinstance(expected, float):
        floor = DEFAULT_ATOL if atol is None else atol  # allowed_error, inlined: this runs per candidate
        allowed = max(floor, rtol * (abs(expected) if scale is None else scale))
        return math.isfinite(answer) and abs(answer - expected) <= allowed + _ROUNDING * max(abs(answer), abs(expected))
    import numpy as np  # arrays come from graders that have loaded numpy already

    a = np.asarray(answer, dtype=np.float64)
    e = np.asarray(expected, dtype=np.float64)
    with np.errstate(invalid="ignore", over="ignore"):
        return np.isfinite(a) & (np.abs(a - e) <= allowed_error(e, rtol, atol, scale)
                                 + _ROUNDING * np.maximum(np.abs(a), np.abs(e)))


def point_tolerance(target, rtol: float):
    """The formula rule, per sample point: ``rtol * max(|t_i|, 1e-3*M)`` with M the
    median of |t| over the points (an absolute 1e-12 when the target is identically 0)."""
    import numpy as np

    scale = median(np.abs(target))
    floor = 1e-3 * scale if scale > 0 else 1e-12 / max(rtol, 1e-300)
    return rtol * np.maximum(np.abs(target), floor)


def median(values) -> float:
    """``np.median`` of the few values of the sample points (NaN if any is NaN), without its overhead."""
    import numpy as np

    ordered = np.sort(values, axis=None)
    n = ordered.size
    if n == 0 or np.isnan(ordered[-1]):
        return math.nan
    return float(ordered[n // 2]) if n % 2 else 0.5 * (float(ordered[n // 2 - 1]) + float(ordered[n // 2]))


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
