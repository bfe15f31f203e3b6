"""Dimensional analysis of expression trees with exponent vectors (see :mod:`units`).

Sums need equal dimensions, exponents must be pure numbers (and constant when the
base has a unit), and transcendental functions need pure-number arguments (trig
functions accept angles too). Angle exponents are carried but, for formulas,
compared as radians = 1.
"""

from __future__ import annotations

from ..i18n import _
from typing import Mapping

from ..errors import DynagradeError
from . import units
from .errors import AnswerError
from .evaluate import evaluate_constant
from .functions import FUNCTIONS
from .nodes import BinOp, Call, Const, Expr, Name, Neg, Num, Unit, has_units, names_in, to_text

_ANGLE = (0.0,) * 7 + (1.0,)


class DimensionIssue(DynagradeError):
    """An expression that mixes units illegally; ``message`` is written for the student."""

    def __init__(self, message: str):
        super().__init__(message)
        self.message = message


def show(dim: tuple) -> str:
    """Text of a dimension for formula feedback (radians dropped: they are 1)."""
    return units.format_dimension(tuple(dim[:7]) + (0.0,))


def dimension(expr: Expr, variables: Mapping[str, tuple]) -> tuple:
    """Dimension of ``expr``; variables map to dimensions, units are looked up."""
    return _dim(expr, variables)


def _dim(node: Expr, variables) -> tuple:
    if isinstance(node, (Num, Const)):
        return units.DIMENSIONLESS
    if isinstance(node, Name):
        return variables[node.id]
    if isinstance(node, Unit):
        try:
            return units.lookup(node.id)[1]
        except AnswerError as error:
            raise AnswerError(error.message, node.pos) from None
    if isinstance(node, Neg):
        return _dim(node.operand, variables)
    if isinstance(node, BinOp):
        a = _dim(node.left, variables)
        if node.op == "^":
            return _power(node, a, variables)
        b = _dim(node.right, variables)
        if node.op == "*":
            return units.add(a, b)
        if node.op == "/":
            return units.add(a, units.scale(b, -1.0))
        if not units.same(a, b, ignore_angle=True):
            raise DimensionIssue(
                _("your expression adds or subtracts terms with different units ({first} and "
                  "{second})").format(first=show(a), second=show(b)))
        return a if units.has_angle(a) else b
    if isinstance(node, Call):
        return _call(node, variables)
    raise TypeError(f"not an expression node: {node!r}")


def _power(node: BinOp, base: tuple, variables) -> tuple:
    if has_units(node.right):
        raise DimensionIssue(_("an exponent must be a pure number, not a unit ('{unit}')").format(
            unit=to_text(node.right)))
    exponent_dim = _dim(node.right, variables)
    if not units.is_dimensionless(exponent_dim):
        raise DimensionIssue(_("an exponent must be a pure number, but '{exponent}' has units "
                               "of {units}").format(exponent=to_text(node.right),
                                                    units=show(exponent_dim)))
    if units.is_dimensionless(base, ignore_angle=False):
        return units.DIMENSIONLESS
    if names_in(node.right):
        raise DimensionIssue(_("'{base}' has units of {units} and cannot be raised to a power "
                               "that depends on the variables").format(base=to_text(node.left),
                                                                      units=show(base)))
    power = evaluate_constant(node.right)
    if not abs(power) < 1e6:
        raise DimensionIssue(_("the exponent of '{base}' is not a usable number").format(
            base=to_text(node.left)))
    return units.scale(base, power)


def _call(node: Call, variables) -> tuple:
    args = [_dim(arg, variables) for arg in node.args]
    func = node.func
    rule = FUNCTIONS[func]
    if rule.dims == "trig":
        if not units.is_dimensionless(args[0]):
            raise DimensionIssue(_("the argument of {function} must be an angle or a pure "
                                   "number, but it has units of {units}").format(
                function=func, units=show(args[0])))
        return units.DIMENSIONLESS
    if rule.dims in ("pure", "inverse_trig"):
        if not units.is_dimensionless(args[0]):
            raise DimensionIssue(_("the argument of {function} must be a pure number, but it "
                                   "has units of {units}").format(function=func,
                                                                  units=show(args[0])))
        return _ANGLE if rule.dims == "inverse_trig" else units.DIMENSIONLESS
    if rule.dims == "atan2":
        if not units.same(args[0], args[1], ignore_angle=True):
            raise DimensionIssue(_("the two arguments of atan2 must have the same units ({first} "
                                   "and {second} given)").format(first=show(args[0]),
                                                                 second=show(args[1])))
        return _ANGLE
    return units.scale(args[0], rule.power)  # roots and abs
