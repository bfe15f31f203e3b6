"""Wording shared by the graders: numbers, tolerances and reading hints."""

from __future__ import annotations

from .nodes import BinOp, Expr, walk


def show_number(value: float, digits: int = 4) -> str:
    """A number for feedback: 4 significant figures, no float noise."""
    text = f"{value:.{digits}g}"
    return text.replace("e+0", "e").replace("e-0", "e-").replace("e+", "e")


def show_value(value: float, unit: str | None) -> str:
    return f"{show_number(value)} {unit}" if unit else show_number(value)


def show_tolerance(rtol: float, atol: float | None, unit: str | None) -> str:
    parts = []
    if rtol > 0:
        parts.append(f"{show_number(rtol * 100, 3)} %")
    if atol:
        parts.append(f"{show_value(atol, unit)}")
    return " or ".join(parts) if parts else "exactly"


def reading_hints(tree: Expr) -> list[str]:
    """Hints about how a written product was read: ``a/2g`` is ``(a/2)·g``."""
    for node in walk(tree):
        if isinstance(node, BinOp) and node.op == "*" and node.implicit and \
                isinstance(node.left, BinOp) and node.left.op == "/":
            return ["Note: a/2g is read as (a/2)·g; write a/(2g) if you mean to divide by 2g."]
    return []
