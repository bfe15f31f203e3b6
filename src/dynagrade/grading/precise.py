"""High-precision evaluation (mpmath) for formulas whose float values cancel.

``1 - cos(x)`` at x = 1e-7, ``cosh(x)^2 - sinh(x)^2`` at x = 20 and
``sqrt(x+1) - sqrt(x)`` at x = 1e10 lose most or all of their digits in float64, so
an exact identity can look like a wrong answer. When the float comparison of a
formula fails but both sides are finite, :func:`agree_precisely` evaluates both
trees again at the same points with 30, 60, 120, … decimal digits (numbers as
typed: ``0.1`` is one tenth) until two successive precisions agree to a thousandth
of the tolerance, then applies the same tolerance rule to those values.

It first looks at the point where the float values disagree most, with numpy's
extended precision where the platform has one, else at 30 digits: when the float
values there were already right, the answer is simply wrong and nothing more is
computed, so a wrong answer costs one more evaluation of each tree.

The answer is True (equivalent), False (not), or None when it cannot decide: a
value beyond 2^±4000 in between, the precision cap, or the time budget reached.
"""

from __future__ import annotations

import math
import threading

import mpmath
import numpy as np

from .evaluate import evaluate
from .functions import FUNCTIONS, mp_call
from .nodes import BinOp, Call, Const, Expr, Name, Neg, Num
from .timing import Deadline
from .tolerance import point_tolerance

_FIRST_DIGITS = 30
_MOST_DIGITS = 960
#: Largest binary exponent followed; beyond it the check gives up.
_MAGNITUDE = 4000
#: Two precisions agree when they differ by at most this fraction of the tolerance.
_SETTLED = 1e-3
#: Float values count as right when within this fraction of the tolerance of the precise ones.
_FLOAT_RIGHT = 0.1

#: Whether numpy's long double is more precise than float64 (x86 Linux: 64-bit mantissa).
_EXTENDED = np.finfo(np.longdouble).eps < np.finfo(np.float64).eps

_CONTEXTS = threading.local()


class _GiveUp(Exception):
    """The values cannot be followed (too large, too small or out of time)."""


def _context(digits: int):
    """This thread's mpmath context (contexts are not shared between threads)."""
    mp = getattr(_CONTEXTS, "mp", None)
    if mp is None:
        mp = _CONTEXTS.mp = mpmath.MPContext()
    mp.dps = digits
    return mp


def agree_precisely(answer: Expr, reference: Expr, env: dict, answer_values: np.ndarray,
                    reference_values: np.ndarray, tol: np.ndarray, rtol: float,
                    deadline: Deadline) -> bool | None:
    """Whether ``answer`` equals ``reference`` at the points of ``env`` under the formula
    tolerance rule, decided in high precision (see the module's docstring); ``tol`` is
    the float tolerance of each point."""
    worst = int(np.argmax(np.abs(answer_values - reference_values) / tol))
    if _EXTENDED and _floats_were_right(answer, reference, env, answer_values, reference_values, tol, worst):
        return False
    try:
        a, e = _values(answer, reference, env, [worst], _FIRST_DIGITS, deadline)
        if abs(a[0] - answer_values[worst]) <= _FLOAT_RIGHT * tol[worst] and \
                abs(e[0] - reference_values[worst]) <= _FLOAT_RIGHT * tol[worst]:
            return False  # the float values were right: the difference is real
        a, e = _settled(answer, reference, env, list(range(len(reference_values))), tol, deadline)
    except _GiveUp:
        return None
    if not (np.all(np.isfinite(a)) and np.all(np.isfinite(e))):
        return None
    return bool(np.all(np.abs(a - e) <= point_tolerance(e, rtol)))


def _floats_were_right(answer, reference, env, answer_values, reference_values, tol, worst) -> bool:
    """Whether both float values at the worst point match the platform's extended
    precision (a cheap first look: a cancellation shows as a difference here)."""
    for tree, values in ((answer, answer_values), (reference, reference_values)):
        extended = np.broadcast_to(evaluate(tree, env, dtype=np.longdouble), values.shape)[worst]
        if not abs(float(extended) - values[worst]) <= _FLOAT_RIGHT * tol[worst]:
            return False
    return True


def _settled(answer, reference, env, points, tol, deadline) -> tuple[np.ndarray, np.ndarray]:
    """Values of both trees at ``points``, at the first precision that agrees with the
    one before it."""
    digits = _FIRST_DIGITS
    previous = _values(answer, reference, env, points, digits, deadline)
    while digits < _MOST_DIGITS:
        digits *= 2
        current = _values(answer, reference, env, points, digits, deadline)
        with np.errstate(invalid="ignore"):
            settled = all(np.all(np.abs(c - p) <= _SETTLED * tol) for c, p in zip(current, previous))
        if settled:
            return current
        previous = current
    raise _GiveUp()


def _values(answer, reference, env, points, digits, deadline) -> tuple[np.ndarray, np.ndarray]:
    mp = _context(digits)
    out = (np.empty(len(points)), np.empty(len(points)))
    for k, i in enumerate(points):
        if deadline.expired():
            raise _GiveUp()
        point = {name: float(values[i]) for name, values in env.items()}
        for tree, target in zip((answer, reference), out):
            value = _evaluate(mp, tree, point)
            target[k] = float(value) if mp.isfinite(value) else math.nan
    return out


def _evaluate(mp, node: Expr, point: dict):
    """The value of ``node`` in ``mp``'s precision; left-leaning chains of operators are
    followed in a loop, so a sum of 500 terms needs no deep recursion."""
    links = []
    while isinstance(node, BinOp) and node.op != "^":
        links.append(node)
        node = node.left
    value = _leaf_or_call(mp, node, point)
    for link in reversed(links):
        value = _guard(mp, _arithmetic(mp, link.op, value, _evaluate(mp, link.right, point)))
    return value


def _leaf_or_call(mp, node: Expr, point: dict):
    if isinstance(node, Num):
        return mp.mpf(node.text.replace(",", ".")) if node.text else mp.mpf(node.value)
    if isinstance(node, Name):
        return mp.mpf(point[node.id])
    if isinstance(node, Const):
        return +mp.pi if node.id == "pi" else +mp.e
    if isinstance(node, Neg):
        return -_evaluate(mp, node.operand, point)
    if isinstance(node, BinOp):  # a power
        return _guard(mp, _power(mp, _evaluate(mp, node.left, point), _evaluate(mp, node.right, point)))
    if isinstance(node, Call):
        args = [_evaluate(mp, arg, point) for arg in node.args]
        if any(mp.isfinite(x) and x != 0 and mp.mag(x) > 16 for x in args) and node.func in ("exp", "sinh", "cosh"):
            raise _GiveUp()  # exp of more than 2^16: far beyond any float
        return _guard(mp, mp_call(mp, FUNCTIONS[node.func], args))
    raise _GiveUp()  # units have no place in a formula


def _arithmetic(mp, op: str, a, b):
    if op == "+":
        return a + b
    if op == "-":
        return a - b
    if op == "*":
        return a * b
    return a / b if b != 0 else mp.nan


def _power(mp, a, b):
    """Real ``a^b`` (NaN for a negative base with a non-integer exponent, like numpy)."""
    if not (mp.isfinite(a) and mp.isfinite(b)):
        return mp.nan
    if a == 0:
        return mp.nan if b < 0 else (mp.one if b == 0 else mp.zero)
    if abs(b) * max(abs(mp.mag(a)), 1) > 4 * _MAGNITUDE:
        raise _GiveUp()
    if a < 0 and not mp.isint(b):
        return mp.nan
    return mp.power(a, b)


def _guard(mp, value):
    if mp.isfinite(value) and value != 0 and abs(mp.mag(value)) > _MAGNITUDE:
        raise _GiveUp()
    return value
