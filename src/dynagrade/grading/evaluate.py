"""Float evaluation of expression trees with numpy, vectorised over sample points.

Every operation runs under ``np.errstate(all="ignore")``: overflow, division by
zero and invalid operations give inf/nan, which callers treat as "undefined at this
point". Nothing is ever computed exactly, so ``9^9^9^9`` is just ``inf``.
"""

from __future__ import annotations

import warnings
from typing import Any, Mapping

import numpy as np

from ..errors import DynagradeError
from .functions import FUNCTIONS
from .names import CONSTANTS
from .nodes import BinOp, Call, Const, Expr, Name, Neg, Num, Unit


class EvaluationError(DynagradeError):
    """A name without a value (an internal inconsistency, not an answer problem)."""


def evaluate(expr: Expr, env: Mapping[str, np.ndarray | np.floating[Any]],
             units: Mapping[str, float] | None = None, dtype=np.float64):
    """Value of ``expr`` with variables from ``env`` (arrays, or numpy scalars, broadcast together).

    ``units`` maps unit names to their factor (used for quantity answers). Returns a
    ``dtype`` array (or numpy scalar); non-finite entries mark undefined points.
    ``dtype=np.longdouble`` evaluates with the platform's extended precision (numbers
    read from their text, constants computed in it), to check float64 values.
    """
    with np.errstate(all="ignore"):
        return _eval(expr, env, units or {}, dtype, None)


def evaluate_with_magnitude(expr: Expr, env: Mapping[str, np.ndarray | np.floating[Any]],
                            dtype=np.float64):
    """The value of ``expr``, per point the largest magnitude of any value met on the
    way, and the number of nodes evaluated (its rounding error is of the order of
    ``eps`` times that magnitude times that number)."""
    largest = [np.zeros((), dtype=dtype), 0]
    with np.errstate(all="ignore"):
        value = _eval(expr, env, {}, dtype, largest)
    return value, largest[0], largest[1]


def _eval(node: Expr, env, units, dtype, largest):
    if isinstance(node, Num):
        if dtype is np.float64 or not node.text:
            value = dtype(node.value)
        else:
            with warnings.catch_warnings():  # 1e5000 overflows to inf, as in float64
                warnings.simplefilter("ignore", RuntimeWarning)
                value = dtype(node.text.replace(",", "."))
    elif isinstance(node, Name):
        try:
            value = env[node.id]
        except KeyError:
            raise EvaluationError(f"no value for '{node.id}'") from None
        if dtype is not np.float64:
            value = np.asarray(value, dtype=dtype)
    elif isinstance(node, Const):
        value = _constant(node.id, dtype)
    elif isinstance(node, Unit):
        try:
            value = dtype(units[node.id])
        except KeyError:
            raise EvaluationError(f"no factor for unit '{node.id}'") from None
    elif isinstance(node, Neg):
        value = np.negative(_eval(node.operand, env, units, dtype, largest))
    elif isinstance(node, BinOp):
        a = _eval(node.left, env, units, dtype, largest)
        b = _eval(node.right, env, units, dtype, largest)
        op = node.op
        if op == "+":
            value = np.add(a, b)
        elif op == "-":
            value = np.subtract(a, b)
        elif op == "*":
            value = np.multiply(a, b)
        elif op == "/":
            value = np.divide(a, b)
        else:
            value = _power(a, b, dtype)
    elif isinstance(node, Call):
        args = [_eval(arg, env, units, dtype, largest) for arg in node.args]
        value = FUNCTIONS[node.func].numpy(*args)
    else:
        raise EvaluationError(f"cannot evaluate {node!r}")
    if largest is not None:
        largest[0] = np.fmax(largest[0], np.abs(value))
        largest[1] += 1
    return value


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
