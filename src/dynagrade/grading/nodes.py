"""Immutable expression tree and its canonical printer.

Nodes are frozen dataclasses compared structurally; the literal text of a number and
whether a product was written without an operator are kept for feedback and form
tests but ignored by ``==``. :func:`to_text` prints a tree so that parsing the text
gives an equal tree back (with the names it uses declared).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Iterator, Union


@dataclass(frozen=True, slots=True)
class Num:
    """A non-negative number literal (signs are :class:`Neg` nodes)."""

    value: float
    text: str = field(default="", compare=False)


@dataclass(frozen=True, slots=True)
class Name:
    """A declared variable."""

    id: str


@dataclass(frozen=True, slots=True)
class Const:
    """A mathematical constant (``pi``, ``e``)."""

    id: str


@dataclass(frozen=True, slots=True)
class Unit:
    """A unit of measurement as written (``km``, ``deg``), in a number-with-unit answer."""

    id: str
    pos: int | None = field(default=None, compare=False)


@dataclass(frozen=True, slots=True)
class Neg:
    operand: "Expr"


@dataclass(frozen=True, slots=True)
class BinOp:
    """``op`` is one of ``+ - * / ^``."""

    op: str
    left: "Expr"
    right: "Expr"
    implicit: bool = field(default=False, compare=False)


@dataclass(frozen=True, slots=True)
class Call:
    """A function applied to arguments; ``func`` is the canonical name."""

    func: str
    args: tuple


Expr = Union[Num, Name, Const, Unit, Neg, BinOp, Call]

_PREC = {"+": 1, "-": 1, "*": 2, "/": 2, "^": 4}
_NEG_PREC = 3
_ATOM_PREC = 5


def _prec(node: Expr) -> int:
    if isinstance(node, BinOp):
        return _PREC[node.op]
    if isinstance(node, Neg):
        return _NEG_PREC
    return _ATOM_PREC


def format_number(value: float) -> str:
    """Shortest text of a float that reads back to the same float."""
    if math.isfinite(value) and value == int(value) and abs(value) < 1e16:
        return str(int(value))
    return repr(float(value))


def to_text(node: Expr) -> str:
    """Canonical text of a tree, with the fewest parentheses that keep its structure."""
    if isinstance(node, Num):
        return format_number(node.value)
    if isinstance(node, (Name, Const, Unit)):
        return node.id
    if isinstance(node, Neg):
        inner = to_text(node.operand)
        if _prec(node.operand) < _NEG_PREC:
            inner = f"({inner})"
        return f"-{inner}"
    if isinstance(node, Call):
        return f"{node.func}({', '.join(to_text(a) for a in node.args)})"
    if isinstance(node, BinOp):
        p = _PREC[node.op]
        left, right = to_text(node.left), to_text(node.right)
        if node.op == "^":
            if _prec(node.left) <= p:
                left = f"({left})"
            if _prec(node.right) < p:
                right = f"({right})"
            return f"{left}^{right}"
        if _prec(node.left) < p:
            left = f"({left})"
        if _prec(node.right) <= p:
            right = f"({right})"
        return f"{left} {node.op} {right}"
    raise TypeError(f"not an expression node: {node!r}")


def walk(node: Expr) -> Iterator[Expr]:
    """All nodes of a tree, parents before children (iterative: deep trees are safe)."""
    stack = [node]
    while stack:
        current = stack.pop()
        yield current
        if isinstance(current, Neg):
            stack.append(current.operand)
        elif isinstance(current, BinOp):
            stack.append(current.right)
            stack.append(current.left)
        elif isinstance(current, Call):
            stack.extend(reversed(current.args))


def depth(node: Expr) -> int:
    """Height of a tree (iterative)."""
    best = 0
    stack = [(node, 1)]
    while stack:
        current, d = stack.pop()
        best = max(best, d)
        if isinstance(current, Neg):
            stack.append((current.operand, d + 1))
        elif isinstance(current, BinOp):
            stack.append((current.left, d + 1))
            stack.append((current.right, d + 1))
        elif isinstance(current, Call):
            stack.extend((a, d + 1) for a in current.args)
    return best


def names_in(node: Expr) -> set[str]:
    """Variables used by a tree."""
    return {n.id for n in walk(node) if isinstance(n, Name)}


def has_units(node: Expr) -> bool:
    return any(isinstance(n, Unit) for n in walk(node))
