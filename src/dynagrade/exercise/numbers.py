"""How numbers are printed on sheets, keys and answer files."""

from __future__ import annotations

import math


def format_number(value: float, digits: int = 6) -> str:
    """``value`` with ``digits`` significant figures, without trailing zeros or a float's
    noise (``0.30000000000000004`` prints as ``0.3``)."""
    if value == 0 or not math.isfinite(value):
        return "0" if value == 0 else str(value)
    text = f"{value:.{digits}g}"
    if "e" in text:
        mantissa, exponent = text.split("e")
        return f"{mantissa}e{int(exponent)}"
    return text
