"""How numbers, points and reference answers are printed on sheets, keys, fill-in files,
feedback, gradebooks and the terminal: one formatter each, used everywhere."""

from __future__ import annotations

from ..grading.feedback import show_number

#: points are shown to people rounded to this many decimals (sheets, fill-in files, keys,
#: feedback, the terminal); an exam's points are multiples of its rounding step
#: (``dynagrade.exam.points``), which the gradebooks write exactly
POINTS_DECIMALS = 4


def format_number(value: float, digits: int = 6) -> str:
    """``value`` with ``digits`` significant figures, without trailing zeros or a float's
    noise (``0.30000000000000004`` prints as ``0.3``); the grader's formatter at 6 figures."""
    return show_number(value, digits)


#: what stands for "no points" (an absent student's exercise or total)
NO_POINTS = "—"


def points_text(points: float | None, decimals: int = POINTS_DECIMALS) -> str:
    """Points as a number: rounded to ``decimals`` decimals, no trailing zeros (``2.4``,
    ``2.2857``, ``6``); :data:`NO_POINTS` for None (no grade)."""
    if points is None:
        return NO_POINTS
    return format_number(round(float(points), decimals), 15)


def percent_text(value: float | None, empty: str = NO_POINTS) -> str:
    """A percentage with two decimals; ``empty`` when there is none (an absent student)."""
    return empty if value is None else f"{value:.2f}"


def points_phrase(points: float) -> str:
    """``2 points``, ``1 point``, ``2.4 points``."""
    shown = points_text(points)
    return f"{shown} point" + ("" if shown == "1" else "s")


def answer_text(value, digits: int = 6) -> str:
    """A reference answer as text: numbers to ``digits`` significant figures, vectors in
    brackets (``[1.2, -3.4]``), several options separated by commas, formulas and option
    labels as they are."""
    if isinstance(value, bool):
        return str(value)
    if isinstance(value, (int, float)):
        return format_number(float(value), digits)
    if isinstance(value, (list, tuple)):
        if all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in value):
            return "[" + ", ".join(format_number(float(v), digits) for v in value) + "]"
        return ", ".join(str(v) for v in value)
    return str(value)
