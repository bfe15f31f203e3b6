"""How numbers are printed on sheets, keys and answer files."""

from __future__ import annotations

from ..grading.feedback import show_number


def format_number(value: float, digits: int = 6) -> str:
    """``value`` with ``digits`` significant figures, without trailing zeros or a float's
    noise (``0.30000000000000004`` prints as ``0.3``); the grader's formatter at 6 figures."""
    return show_number(value, digits)
