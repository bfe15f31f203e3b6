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
    """A function applied to arguments; ``func`` is the canonical name. ``written`` is
    how an inverse function was written on paper (``cos^-1``), kept for the note that
    says how it was read, and ignored by ``==``."""

    func: str
    args: tuple
    written: str = field(default="", compare=False)


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


#: Operators that form associative chains, by chain.
_CHAINS = {"+": "sum", "-": "sum", "*": "product", "/": "product"}


def nesting_and_terms(node: Expr) -> tuple[int, int]:
    """The height of a tree once chains of ``+ -`` and of ``* /`` are flattened into one
    node each (a sum of 500 terms has height 2, like ``a + b``), and the most terms in
    one chain. Iterative, so any tree is safe to measure."""
    height, most = 0, 1
    terms: dict[int, int] = {}  # id of a chain's top link -> its terms so far
    stack: list = [(node, 1, None, None)]
    while stack:
        current, level, parent_kind, key = stack.pop()
        kind = _CHAINS.get(current.op) if isinstance(current, BinOp) else None
        if kind is not None and kind == parent_kind:
            level -= 1  # a link of the parent's chain sits at the chain's level
        if level > height:
            height = level
        if isinstance(current, BinOp):
            if kind is None:
                stack.append((current.left, level + 1, None, None))
                stack.append((current.right, level + 1, None, None))
                continue
            if kind != parent_kind:
                key = id(current)
            count = terms[key] = terms.get(key, 1) + 1
            if count > most:
                most = count
            stack.append((current.left, level + 1, kind, key))
            stack.append((current.right, level + 1, kind, key))
        elif isinstance(current, Neg):
            stack.append((current.operand, level + 1, None, None))
        elif isinstance(current, Call):
            stack.extend((a, level + 1, None, None) for a in current.args)
    return height, most


def names_in(node: Expr) -> set[str]:
    """Variables used by a tree."""
    return {n.id for n in walk(node) if isinstance(n, Name)}


def has_units(node: Expr) -> bool:
    return any(isinstance(n, Unit) for n in walk(node))
