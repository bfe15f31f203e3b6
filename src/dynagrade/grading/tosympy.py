"""Expression tree -> sympy objects, built node by node (never from text), and a
time-bounded exact check ``simplify(a - b) == 0`` used only as an optional extra.

Variables become positive real symbols when their whole domain is positive, so
``sqrt(k)/sqrt(m)`` and ``sqrt(k/m)`` agree exactly too.
"""

from __future__ import annotations

import math
from typing import Mapping

from ..errors import DynagradeError
from .functions import FUNCTIONS
from .nodes import BinOp, Call, Const, Expr, Name, Neg, Num, Unit
from .timing import OutOfTime, can_interrupt, time_limit


class NotConvertible(DynagradeError):
    """The tree holds something the exact check should not touch (huge exponents, units)."""


def to_sympy(expr: Expr, domains: Mapping[str, tuple[float, float]]):
    import sympy

    symbols = {}
    for name, (lo, hi) in domains.items():
        assumptions = {"real": True}
        if lo > 0:
            assumptions["positive"] = True
        elif hi < 0:
            assumptions["negative"] = True
        symbols[name] = sympy.Symbol(name, **assumptions)
    def convert(node: Expr):
        if isinstance(node, Num):
            value = node.value
            if value == int(value) and value < 1e6:
                return sympy.Integer(int(value))
            return sympy.Rational(node.text.replace(",", ".")) if node.text and "e" not in node.text.lower() \
                else sympy.Float(value)
        if isinstance(node, Name):
            return symbols[node.id]
        if isinstance(node, Const):
            return sympy.pi if node.id == "pi" else sympy.E
        if isinstance(node, Unit):
            raise NotConvertible("units")
        if isinstance(node, Neg):
            return -convert(node.operand)
        if isinstance(node, BinOp):
            a, b = convert(node.left), convert(node.right)
            if node.op == "+":
                return a + b
            if node.op == "-":
                return a - b
            if node.op == "*":
                return a * b
            if node.op == "/":
                return a / b
            if b.is_number and (not b.is_finite or abs(float(b)) > 64):
                raise NotConvertible("large exponent")
            return sympy.Pow(a, b)
        if isinstance(node, Call):
            return FUNCTIONS[node.func].sympy(sympy, *[convert(a) for a in node.args])
        raise NotConvertible(type(node).__name__)

    return convert(expr)


def exactly_equal(a: Expr, b: Expr, domains: Mapping[str, tuple[float, float]], seconds: float) -> bool | None:
    """True/False when sympy decides ``a == b`` within ``seconds``; None when it cannot."""
    if seconds <= 0.01 or not can_interrupt():
        return None
    import sympy  # outside the limit: an interrupted import would leave a broken module

    try:
        with time_limit(seconds):
            difference = to_sympy(a, domains) - to_sympy(b, domains)
            result = sympy.simplify(difference)
            if result == 0:
                return True
            if result.is_number and result.is_finite and not math.isclose(float(result), 0.0):
                return False
            return None
    except OutOfTime:
        return None
    except (NotConvertible, ValueError, TypeError, ZeroDivisionError, OverflowError,
            RecursionError, AttributeError):
        return None
