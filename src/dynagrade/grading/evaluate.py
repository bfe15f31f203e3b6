"""Float evaluation of expression trees with numpy, vectorised over sample points.

Every operation runs under ``np.errstate(all="ignore")``: overflow, division by
zero and invalid operations give inf/nan, which callers treat as "undefined at this
point". Nothing is ever computed exactly, so ``9^9^9^9`` is just ``inf``.
"""

from __future__ import annotations

from typing import Mapping

import numpy as np

from ..errors import DynagradeError
from .nodes import BinOp, Call, Const, Expr, Name, Neg, Num, Unit
from .names import CONSTANTS


def _cot(x):
    return 1.0 / np.tan(x)


def _sec(x):
    return 1.0 / np.cos(x)


def _csc(x):
    return 1.0 / np.sin(x)


_UNARY = {
    "sin": np.sin, "cos": np.cos, "tan": np.tan, "cot": _cot, "sec": _sec, "csc": _csc,
    "asin": np.arcsin, "acos": np.arccos, "atan": np.arctan,
    "sinh": np.sinh, "cosh": np.cosh, "tanh": np.tanh,
    "exp": np.exp, "ln": np.log, "log10": np.log10, "log2": np.log2,
    "sqrt": np.sqrt, "cbrt": np.cbrt, "abs": np.abs,
}
_BINARY = {"atan2": np.arctan2}


class EvaluationError(DynagradeError):
    """A name without a value (an internal inconsistency, not an answer problem)."""


def evaluate(expr: Expr, env: Mapping[str, np.ndarray], units: Mapping[str, float] | None = None):
    """Value of ``expr`` with variables from ``env`` (arrays broadcast together).

    ``units`` maps unit names to their factor (used for quantity answers). Returns a
    float64 array (or numpy scalar); non-finite entries mark undefined points.
    """
    with np.errstate(all="ignore"):
        return _eval(expr, env, units or {})


def _eval(node: Expr, env, units):
    if isinstance(node, Num):
        return np.float64(node.value)
    if isinstance(node, Name):
        try:
            return env[node.id]
        except KeyError:
            raise EvaluationError(f"no value for '{node.id}'") from None
    if isinstance(node, Const):
        return np.float64(CONSTANTS[node.id])
    if isinstance(node, Unit):
        try:
            return np.float64(units[node.id])
        except KeyError:
            raise EvaluationError(f"no factor for unit '{node.id}'") from None
    if isinstance(node, Neg):
        return np.negative(_eval(node.operand, env, units))
    if isinstance(node, BinOp):
        a = _eval(node.left, env, units)
        b = _eval(node.right, env, units)
        op = node.op
        if op == "+":
            return np.add(a, b)
        if op == "-":
            return np.subtract(a, b)
        if op == "*":
            return np.multiply(a, b)
        if op == "/":
            return np.divide(a, b)
        return _power(a, b)
    if isinstance(node, Call):
        args = [_eval(arg, env, units) for arg in node.args]
        if node.func in _UNARY:
            return _UNARY[node.func](args[0])
        return _BINARY[node.func](*args)
    raise EvaluationError(f"cannot evaluate {node!r}")


def _power(a, b):
    """a**b in float64; a negative base with an odd-denominator exponent like 1/3 is
    still undefined (real powers of negative numbers are left out)."""
    a = np.asarray(a, dtype=np.float64)
    b = np.asarray(b, dtype=np.float64)
    result = np.power(a, b)
    return result if result.ndim else np.float64(result)


def evaluate_constant(expr: Expr, units: Mapping[str, float] | None = None) -> float:
    """Value of an expression without variables, as a Python float (may be inf/nan)."""
    return float(np.asarray(evaluate(expr, {}, units), dtype=np.float64))
