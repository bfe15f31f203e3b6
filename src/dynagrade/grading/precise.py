"""High-precision evaluation (mpmath) for formulas whose float values cancel.

``1 - cos(x)`` at x = 1e-7, ``cosh(x)^2 - sinh(x)^2`` at x = 20 and
``sqrt(x+1) - sqrt(x)`` at x = 1e10 lose most or all of their digits in float64, so
an exact identity can look like a wrong answer. When the float comparison of a
formula fails but both sides are finite, :func:`agree_precisely` decides instead.

A value computed with unit roundoff ``u`` is *trusted* when ``u · M · n`` is at most a
thousandth of the point's tolerance, M being the largest magnitude met while
computing it and n the size of the tree (a cancellation shows as M much larger than
the value). First, at the point where the float values disagree most, both trees are
evaluated in numpy's extended precision (where the platform has one, else mpmath at
30 digits): if those values are trusted and the float values match them, the
difference is real and the answer is wrong -- the usual case, which costs one more
evaluation of each tree. Otherwise both trees are evaluated with mpmath at every
point, at 30 digits and then at the precision the magnitudes ask for (at most 960),
until every value is trusted and agrees with the previous precision; numbers are
read as typed (``0.1`` is one tenth). Those values decide under the same tolerance
rule as the float ones.

The answer is True (equivalent), False (not), or None when it cannot decide: a
value beyond 2^±4000 in between, the precision cap, or the time budget reached.
"""

from __future__ import annotations

import math
import threading

import numpy as np

from ..errors import DynagradeError
from .evaluate import evaluate_with_magnitude
from .functions import FUNCTIONS, mp_call
from .nodes import BinOp, Call, Const, Expr, Name, Neg, Num, walk
from .timing import Deadline
from .tolerance import point_tolerance

_FIRST_DIGITS = 30
_MOST_DIGITS = 960
#: Largest binary exponent followed; beyond it the check gives up.
_MAGNITUDE = 4000
#: A value is trusted when its error estimate is within this fraction of the tolerance.
_TRUSTED = 1e-3
#: Float values count as right when within this fraction of the tolerance of trusted ones.
_FLOAT_RIGHT = 0.1
#: Unit roundoff of numpy's long double, when it is more precise than float64.
_EXTENDED_ROUNDOFF = float(np.finfo(np.longdouble).eps) \
    if np.finfo(np.longdouble).eps < np.finfo(np.float64).eps else None

_CONTEXTS = threading.local()


class _GiveUp(DynagradeError):
    """The values cannot be followed (too large, too small or out of time)."""


def _context(digits: int):
    """This thread's mpmath context (contexts are not shared between threads); mpmath
    is imported on first use, or by :func:`dynagrade.grading.prepare`."""
    mp = getattr(_CONTEXTS, "mp", None)
    if mp is None:
        import mpmath

        mp = _CONTEXTS.mp = mpmath.MPContext()
    mp.dps = digits
    return mp


def extended(tree: Expr, env: dict) -> tuple[np.ndarray, np.ndarray] | None:
    """Values of ``tree`` at the points of ``env`` in the platform's extended precision
    and their error estimates (floats), or None where long double is just float64.
    A reference's are worked out once and passed to :func:`agree_precisely`."""
    if _EXTENDED_ROUNDOFF is None:
        return None
    value, largest, size = evaluate_with_magnitude(tree, env, dtype=np.longdouble)
    shape = np.broadcast(*env.values()).shape if env else ()
    value = np.broadcast_to(np.asarray(value, dtype=np.float64), shape)
    error = _EXTENDED_ROUNDOFF * size * np.broadcast_to(np.asarray(largest, dtype=np.float64), shape)
    return value, error


def agree_precisely(answer: Expr, reference: Expr, env: dict, answer_values: np.ndarray,
                    reference_values: np.ndarray, tol: np.ndarray, rtol: float, deadline: Deadline,
                    reference_extended: tuple[np.ndarray, np.ndarray] | None = None) -> bool | None:
    """Whether ``answer`` equals ``reference`` at the points of ``env`` under the formula
    tolerance rule, decided in high precision (see the module's docstring); ``tol`` is
    the float tolerance of each point, ``reference_extended`` what :func:`extended`
    gives for the reference."""
    with np.errstate(all="ignore"):
        worst = int(np.argmax(np.abs(answer_values - reference_values) / tol))
    point = {name: values[worst:worst + 1] for name, values in env.items()}
    try:
        if reference_extended is None:
            reference_extended = _checked(reference, point, deadline)
            at = 0
        else:
            at = worst
        answer_extended = _checked(answer, point, deadline)
        if _right(answer_values[worst], answer_extended, 0, tol[worst]) and \
                _right(reference_values[worst], reference_extended, at, tol[worst]):
            return False  # the float values were right: the difference is real
        sizes = (_size(answer), _size(reference))
        a, e = _settled((answer, reference), sizes, env, len(reference_values), rtol, deadline)
    except _GiveUp:
        return None
    return bool(np.all(np.abs(a - e) <= point_tolerance(e, rtol)))


def _checked(tree: Expr, point: dict, deadline: Deadline) -> tuple[np.ndarray, np.ndarray]:
    """Values at one point with error estimates: extended precision, else 30 digits."""
    found = extended(tree, point)
    return found if found is not None else _values(tree, _size(tree), point, 1, _FIRST_DIGITS, deadline)


def _right(float_value: float, checked: tuple[np.ndarray, np.ndarray], at: int, tol: float) -> bool:
    """Whether a float value matches a trusted value of higher precision."""
    value, error = checked[0][at], checked[1][at]
    return bool(error <= _TRUSTED * tol and abs(value - float_value) <= _FLOAT_RIGHT * tol)


def _size(tree: Expr) -> int:
    return sum(1 for _ in walk(tree))


def _settled(trees, sizes, env, count, rtol, deadline) -> tuple[np.ndarray, np.ndarray]:
    """Values of both trees at every point, at the first precision where all are
    trusted and agree with the precision before."""
    digits, previous = _FIRST_DIGITS, None
    while True:
        (a, a_error), (e, e_error) = (_values(t, n, env, count, digits, deadline) for t, n in zip(trees, sizes))
        if not (np.all(np.isfinite(a)) and np.all(np.isfinite(e))):
            raise _GiveUp()
        limit = _TRUSTED * point_tolerance(e, rtol)
        error = np.maximum(a_error, e_error)
        if np.all(error <= limit) and previous is not None and \
                np.all(np.abs(a - previous[0]) <= limit) and np.all(np.abs(e - previous[1]) <= limit):
            return a, e
        if digits >= _MOST_DIGITS:
            raise _GiveUp()
        with np.errstate(all="ignore"):
            excess = np.log10(error / limit)
        excess = excess[np.isfinite(excess)]
        wanted = digits + (math.ceil(float(excess.max())) + 3 if excess.size else 0)
        digits, previous = min(_MOST_DIGITS, max(2 * digits, wanted)), (a, e)


def _values(tree, size, env, count, digits, deadline) -> tuple[np.ndarray, np.ndarray]:
    """Values of ``tree`` at ``count`` points with ``digits`` digits, and an estimate
    of their rounding errors."""
    mp = _context(digits)
    values, errors = np.empty(count), np.empty(count)
    roundoff = 10.0 ** (1 - digits) * size
    for i in range(count):
        if deadline.expired():
            raise _GiveUp()
        point = {name: float(v[i]) for name, v in env.items()}
        largest = [mp.zero]
        value = _evaluate(mp, tree, point, largest)
        values[i] = float(value) if mp.isfinite(value) else math.nan
        errors[i] = roundoff * float(largest[0])
    return values, errors


def _evaluate(mp, node: Expr, point: dict, largest: list):
    """The value of ``node`` in ``mp``'s precision, keeping the largest magnitude met in
    ``largest[0]``; left-leaning chains of operators are followed in a loop, so a sum
    of 500 terms needs no deep recursion."""
    links = []
    while isinstance(node, BinOp) and node.op != "^":
        links.append(node)
        node = node.left
    value = _leaf_or_call(mp, node, point, largest)
    for link in reversed(links):
        value = _guard(mp, _arithmetic(mp, link.op, value, _evaluate(mp, link.right, point, largest)), largest)
    return value


def _leaf_or_call(mp, node: Expr, point: dict, largest: list):
    if isinstance(node, Num):
        return _guard(mp, mp.mpf(_decimal(node.text)) if node.text else mp.mpf(node.value), largest)
    if isinstance(node, Name):
        return _guard(mp, mp.mpf(point[node.id]), largest)
    if isinstance(node, Const):
        return +mp.pi if node.id == "pi" else +mp.e
    if isinstance(node, Neg):
        return -_evaluate(mp, node.operand, point, largest)
    if isinstance(node, BinOp):  # a power
        base = _evaluate(mp, node.left, point, largest)
        return _guard(mp, _power(mp, base, _evaluate(mp, node.right, point, largest)), largest)
    if isinstance(node, Call):
        args = [_evaluate(mp, arg, point, largest) for arg in node.args]
        if node.func in ("exp", "sinh", "cosh") and any(mp.isfinite(x) and abs(x) > 2 ** 16 for x in args):
            raise _GiveUp()  # exp of more than 65536: far beyond any float
        return _guard(mp, mp_call(mp, FUNCTIONS[node.func], args), largest)
    raise _GiveUp()  # units have no place in a formula


def _decimal(text: str) -> str:
    """A number as the student wrote it, in the spelling mpmath reads: a decimal comma as
    a point, and a 0 before a leading point (mpmath refuses ``.0``, which Python reads)."""
    text = text.replace(",", ".")
    return "0" + text if text.startswith(".") else text


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


def _guard(mp, value, largest: list):
    """``value``, noted in ``largest``; gives up beyond 2^±4000."""
    if mp.isfinite(value) and value != 0:
        if abs(mp.mag(value)) > _MAGNITUDE:
            raise _GiveUp()
        size = abs(value)
        if size > largest[0]:
            largest[0] = size
    return value
