"""Float evaluation of expression trees with numpy, vectorised over sample points.

Every operation runs under ``np.errstate(all="ignore")``: overflow, division by
zero and invalid operations give inf/nan, which callers treat as "undefined at this
point". Nothing is ever computed exactly, so ``9^9^9^9`` is just ``inf``.
"""

from __future__ import annotations

from typing import Mapping

import numpy as np

from .functions import FUNCTIONS
from .names import CONSTANTS
from .nodes import BinOp, Call, Const, Expr, Name, Neg, Num, Unit


class EvaluationError(Exception):
    """A name without a value (an internal inconsistency, not an answer problem)."""


def evaluate(expr: Expr, env: Mapping[str, np.ndarray], units: Mapping[str, float] | None = None,
             dtype=np.float64):
    """Value of ``expr`` with variables from ``env`` (arrays broadcast together).

    ``units`` maps unit names to their factor (used for quantity answers). Returns a
    ``dtype`` array (or numpy scalar); non-finite entries mark undefined points.
    ``dtype=np.longdouble`` evaluates with the platform's extended precision (numbers
    read from their text, constants computed in it), to check float64 values.
    """
    with np.errstate(all="ignore"):
        return _eval(expr, env, units or {}, dtype)


def _eval(node: Expr, env, units, dtype):
    if isinstance(node, Num):
        if dtype is np.float64 or not node.text:
            return dtype(node.value)
        return dtype(node.text.replace(",", "."))
    if isinstance(node, Name):
        try:
            value = env[node.id]
        except KeyError:
            raise EvaluationError(f"no value for '{node.id}'") from None
        return value if dtype is np.float64 else np.asarray(value, dtype=dtype)
    if isinstance(node, Const):
        return _constant(node.id, dtype)
    if isinstance(node, Unit):
        try:
            return dtype(units[node.id])
        except KeyError:
            raise EvaluationError(f"no factor for unit '{node.id}'") from None
    if isinstance(node, Neg):
        return np.negative(_eval(node.operand, env, units, dtype))
    if isinstance(node, BinOp):
        a = _eval(node.left, env, units, dtype)
        b = _eval(node.right, env, units, dtype)
        op = node.op
        if op == "+":
            return np.add(a, b)
        if op == "-":
            return np.subtract(a, b)
        if op == "*":
            return np.multiply(a, b)
        if op == "/":
            return np.divide(a, b)
        return _power(a, b, dtype)
    if isinstance(node, Call):
        args = [_eval(arg, env, units, dtype) for arg in node.args]
        return FUNCTIONS[node.func].numpy(*args)
    raise EvaluationError(f"cannot evaluate {node!r}")


def _constant(name: str, dtype):
    if dtype is np.float64:
        return np.float64(CONSTANTS[name])
    one = dtype(1)
    return 4 * np.arctan(one) if name == "pi" else np.exp(one)


def _power(a, b, dtype):
    """a**b; a negative base with an odd-denominator exponent like 1/3 is still
    undefined (real powers of negative numbers are left out)."""
    a = np.asarray(a, dtype=dtype)
    b = np.asarray(b, dtype=dtype)
    result = np.power(a, b)
    return result if result.ndim else dtype(result)


def evaluate_constant(expr: Expr, units: Mapping[str, float] | None = None) -> float:
    """Value of an expression without variables, as a Python float (may be inf/nan)."""
    return float(np.asarray(evaluate(expr, {}, units), dtype=np.float64))
