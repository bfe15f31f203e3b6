"""Wording shared by the graders: numbers, tolerances and reading hints."""

from __future__ import annotations

from ..i18n import _
import math

from .nodes import BinOp, Expr, walk
from .onpaper import notes


def show_number(value: float, digits: int = 4) -> str:
    """``value`` to ``digits`` significant figures, without trailing zeros, a float's noise
    or a padded exponent (``0.30000000000000004`` -> ``0.3``, ``1.2e+05`` -> ``1.2e5``).

    The one number formatter of dynagrade: feedback uses 4 figures, sheets and keys
    (:func:`dynagrade.exercise.numbers.format_number`) 6.
    """
    if value == 0 or not math.isfinite(value):
        return "0" if value == 0 else str(value)
    text = f"{value:.{digits}g}"
    if "e" in text:
        mantissa, exponent = text.split("e")
        return f"{mantissa}e{int(exponent)}"
    return text


def show_value(value: float, unit: str | None) -> str:
    """A number for feedback followed by its unit."""
    return f"{show_number(value)} {unit}" if unit else show_number(value)


def show_tolerance(rtol: float, atol: float | None, unit: str | None) -> str:
    """A part's tolerance in words: ``1 %``, ``0.01 m``, ``1 % or 0.01 m``, ``exactly``."""
    parts = []
    if rtol > 0:
        parts.append(f"{show_number(rtol * 100, 3)} %")
    if atol:
        parts.append(f"{show_value(atol, unit)}")
    return _(" or ").join(parts) if parts else _("exactly")


def reading_hints(tree: Expr) -> list[str]:
    """Hints about how a written product was read (``a/2g`` is ``(a/2)·g``), and about
    functions written on paper (``cos^-1`` is arccos: :func:`.onpaper.notes`)."""
    for node in walk(tree):
        if isinstance(node, BinOp) and node.op == "*" and node.implicit and \
                isinstance(node.left, BinOp) and node.left.op == "/":
            return [_("Note: a/2g is read as (a/2)·g; write a/(2g) if you mean to divide by 2g.")] \
                + notes(tree)
    return notes(tree)
