"""Numbers with units: reading an answer like ``45 km/h`` into a value in SI units.

A quantity answer is parsed in quantity mode (names are units), every unit is looked
up (pint is only imported when a unit is present), the whole expression is
evaluated in SI with :mod:`evaluate`, and its dimension found with :mod:`dims`.
"""

from __future__ import annotations

from ..i18n import _
import math
from dataclasses import dataclass
from functools import lru_cache

from . import frequency, units
from .dims import DimensionIssue, dimension
from .errors import AnswerError, SpecError
from .evaluate import evaluate_constant
from .nodes import BinOp, Call, Expr, Neg, Num, Unit, has_units, to_text, walk
from .parser import parse_quantity


@dataclass(frozen=True)
class Quantity:
    """A read answer. ``value`` is in SI when ``dim`` is set, else as typed.

    ``unit_text``/``unit_factor`` describe the unit part as written (``km/h``,
    0.2777…); ``number_text`` is the typed number when the value is one literal
    (possibly times a power of ten), for significant-figure hints; ``cycles`` is the
    power of Hz in the unit part (:mod:`.frequency`: Hz counts cycles).
    """

    value: float
    dim: tuple | None
    unit_text: str | None
    unit_factor: float
    number_text: str | None
    tree: Expr
    cycles: float = 0.0


@lru_cache(maxsize=1024)
def read_quantity(text: str, *, decimal_comma: bool = True) -> Quantity:
    """Read a number with an optional unit; AnswerError when it cannot be read. The
    quantities of the texts read last are kept (a quantity never changes): the server
    reads an answer to say how it reads, then grades it."""
    tree = parse_quantity(text, decimal_comma=decimal_comma)
    return quantity_from_tree(tree, text)


def quantity_from_tree(tree: Expr, text: str, *, require_number: bool = True) -> Quantity:
    value_part, unit_part = split_product(tree)
    number_text = _number_text(value_part)
    if not has_units(tree):
        return Quantity(evaluate_constant(tree), None, None, 1.0, number_text, tree)
    factors = {}
    for node in walk(tree):
        if isinstance(node, Unit) and node.id not in factors:
            try:
                factors[node.id] = units.lookup(node.id)[0]
            except AnswerError as error:
                if require_number and value_part is None:
                    raise AnswerError(_("'{given}' is not a number").format(given=node.id), node.pos, text) from None
                raise AnswerError(error.message, node.pos, text) from None
    if require_number and value_part is None and unit_part is not None:
        raise AnswerError(_("your answer has no number, only a unit ('{unit}')").format(
            unit=to_text(tree)))
    try:
        dim = dimension(tree, {})
    except DimensionIssue as issue:
        raise AnswerError(issue.message.replace(_("your expression"), _("your answer"))) from None
    from .evaluate import evaluate

    value = float(evaluate(tree, {}, factors))
    if units.is_dimensionless(dim, ignore_angle=False) and not _units_outside_calls(tree):
        # 144*sin(70°)/9.81: the degree sign is the argument's, the answer a bare number
        return Quantity(value, None, None, 1.0, number_text, tree)
    unit_text, unit_factor = None, 1.0
    powers = frequency.unit_powers(unit_part)
    if frequency.per_minute(powers):  # 1500 min⁻¹ is 1500 rev/min
        value, dim = value * frequency.TWO_PI, frequency.as_turns(dim, 1.0)
    if unit_part is not None:
        unit_text = to_text(unit_part)
        unit_factor = float(evaluate(unit_part, {}, factors))
        if not (math.isfinite(unit_factor) and unit_factor > 0):
            shown = unit_text if len(unit_text) <= 30 else unit_text[:30] + "…"
            raise AnswerError(_("the unit '{unit}' is too large or too small to compute with").format(
                unit=shown))
        if frequency.per_minute(powers):
            unit_factor *= frequency.TWO_PI
    return Quantity(value, dim, unit_text, unit_factor, number_text, tree, frequency.cycles(powers))


def _units_outside_calls(tree: Expr) -> bool:
    """Whether a unit stands outside every function's argument (``2 m``, not ``sin(70°)``);
    iterative, like :func:`.nodes.walk`, so that deep trees are safe."""
    stack = [tree]
    while stack:
        node = stack.pop()
        if isinstance(node, Unit):
            return True
        if isinstance(node, BinOp):
            stack.extend((node.left, node.right))
        elif isinstance(node, Neg):
            stack.append(node.operand)
    return False


def split_product(tree: Expr) -> tuple[Expr | None, Expr | None]:
    """Split a product/quotient into its number part and its unit part.

    ``12.5 km/h`` -> (12.5, km/h). When units sit inside sums or functions the whole
    tree is returned as the unit part's owner: (None, None).
    """
    factors: list[tuple[Expr, int]] = []

    def collect(node: Expr, sign: int) -> bool:
        if isinstance(node, BinOp) and node.op in "*/":
            return collect(node.left, sign) and collect(node.right, sign if node.op == "*" else -sign)
        factors.append((node, sign))
        return True

    collect(tree, 1)
    value_factors = [(f, s) for f, s in factors if not has_units(f)]
    unit_factors = [(f, s) for f, s in factors if has_units(f)]
    if any(not _pure_unit(f) for f, _ in unit_factors):
        return None, None
    return _rebuild(value_factors), _rebuild(unit_factors)


def _pure_unit(node: Expr) -> bool:
    if isinstance(node, Unit):
        return True
    if isinstance(node, BinOp) and node.op == "^":
        return isinstance(node.left, Unit) and not has_units(node.right)
    return False


def _rebuild(factors: list[tuple[Expr, int]]) -> Expr | None:
    if not factors:
        return None
    up = [f for f, s in factors if s > 0]
    down = [f for f, s in factors if s < 0]
    result: Expr = up[0] if up else Num(1.0, "1")
    for f in up[1:]:
        result = BinOp("*", result, f)
    for f in down:
        result = BinOp("/", result, f)
    return result


def _number_text(value_part: Expr | None) -> str | None:
    node = value_part
    if isinstance(node, Neg):
        node = node.operand
    if isinstance(node, Num):
        return node.text or None
    # 1.2 × 10^3 and 1.2·10⁻³
    if isinstance(node, BinOp) and node.op == "*" and isinstance(node.left, Num):
        right = node.right
        if isinstance(right, BinOp) and right.op == "^" and isinstance(right.left, Num) \
                and right.left.value == 10:
            return node.left.text or None
    return None


@lru_cache(maxsize=512)
def unit_info(unit: str | None) -> tuple[float, tuple]:
    """(factor to SI, dimension) of a part's unit text; ``None``/``""``/``"1"`` is a pure number."""
    return _part_unit(unit)[:2]


@lru_cache(maxsize=512)
def unit_cycles(unit: str | None) -> float:
    """The power of Hz in a part's unit text (:mod:`.frequency`): 1 for ``Hz``, 0 for ``rad/s``."""
    return _part_unit(unit)[2]


def _part_unit(unit: str | None) -> tuple[float, tuple, float]:
    if unit is None or unit.strip() in ("", "1", "dimensionless", "-"):
        return 1.0, units.DIMENSIONLESS, 0.0
    try:
        tree = parse_quantity(unit, decimal_comma=False)
        quantity = quantity_from_tree(tree, unit, require_number=False) if has_units(tree) else None
    except AnswerError as error:
        raise SpecError(f"cannot read the unit {unit!r}: {error.message}") from None
    if quantity is None or quantity.dim is None:
        raise SpecError(f"the unit {unit!r} contains no unit")
    if not (math.isfinite(quantity.value) and quantity.value > 0):
        raise SpecError(f"the unit {unit!r} is not a usable unit")
    return quantity.value, quantity.dim, quantity.cycles
