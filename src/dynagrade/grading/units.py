"""Units: one lazily created pint registry, and angle tracked as its own dimension.

pint is imported the first time a unit name has to be looked up. A unit is reduced
to (factor to SI, dimension), where a dimension is a tuple of exponents of
(kg, m, s, A, K, mol, cd, rad). pint counts the radian as dimensionless; here the
radian is the eighth base dimension, read from pint's root units, so ``deg``,
``rad``, ``rev``, ``rpm`` and ``deg/s`` keep their angle.

Rule for angles (see :func:`compatible`): two dimensions match when all other
exponents agree and the angle exponents agree -- or one side has no angle at all,
in which case it is read in radians (SI makes the radian 1). So ``1/s`` is accepted
for ``rad/s`` (read as rad/s) and ``rpm`` for ``1/s`` (converted to rad/s), while
``30 m`` is never an angle. Hz stays 1/s here (so that parameters in Hz reach the solvers
as cycles per second); the graders read it as turns per second where the frequency rule
of :mod:`.frequency` says so.

A name is looked up in the built-in table, then in the everyday table of
:mod:`.everyday_units` (``kNm``, ``Grad``, ``U``), then in pint, whose answer the deny-list
of :mod:`.everyday_units` may refuse (``M`` is molar, ``grad`` the gradian).
"""

from __future__ import annotations

from ..i18n import N_, _
import math
from fractions import Fraction
from functools import lru_cache

from .errors import AnswerError
from .everyday_units import EVERYDAY, refusal
from .names import suggest

BASE_SYMBOLS = ("kg", "m", "s", "A", "K", "mol", "cd", "rad")
_ANGLE = 7
DIMENSIONLESS: tuple = (0.0,) * 8

_ROOTS = {  # pint root unit -> (base index, factor of one root unit in SI)
    "gram": (0, 1e-3), "meter": (1, 1.0), "second": (2, 1.0), "ampere": (3, 1.0),
    "kelvin": (4, 1.0), "mole": (5, 1.0), "candela": (6, 1.0), "radian": (7, 1.0),
}

_REFUSED = {"degC", "degF", "celsius", "fahrenheit", "degree_Celsius", "degree_Fahrenheit",
            "delta_degC", "delta_degF", "percent", "ppm", "count"}
_COMMON = ("m", "s", "kg", "g", "N", "J", "W", "Pa", "Hz", "rad", "deg", "rev", "rpm",
           "km", "cm", "mm", "h", "min", "ms", "kN", "mN", "kJ", "kW", "MPa", "kPa", "bar",
           "L", "t", "A", "V")

def _dim(kg=0.0, m=0.0, s=0.0, rad=0.0) -> tuple:
    return (float(kg), float(m), float(s), 0.0, 0.0, 0.0, 0.0, float(rad))


#: The most common units, so that typical answers never wait for pint to load
#: (tests hold every entry against pint).
BUILTIN: dict[str, tuple[float, tuple]] = {
    "m": (1.0, _dim(m=1)), "km": (1e3, _dim(m=1)), "cm": (1e-2, _dim(m=1)), "mm": (1e-3, _dim(m=1)),
    "s": (1.0, _dim(s=1)), "ms": (1e-3, _dim(s=1)), "min": (60.0, _dim(s=1)), "h": (3600.0, _dim(s=1)),
    "kg": (1.0, _dim(kg=1)), "g": (1e-3, _dim(kg=1)), "t": (1e3, _dim(kg=1)),
    "N": (1.0, _dim(kg=1, m=1, s=-2)), "kN": (1e3, _dim(kg=1, m=1, s=-2)), "mN": (1e-3, _dim(kg=1, m=1, s=-2)),
    "J": (1.0, _dim(kg=1, m=2, s=-2)), "kJ": (1e3, _dim(kg=1, m=2, s=-2)),
    "W": (1.0, _dim(kg=1, m=2, s=-3)), "kW": (1e3, _dim(kg=1, m=2, s=-3)),
    "Pa": (1.0, _dim(kg=1, m=-1, s=-2)), "kPa": (1e3, _dim(kg=1, m=-1, s=-2)),
    "MPa": (1e6, _dim(kg=1, m=-1, s=-2)), "GPa": (1e9, _dim(kg=1, m=-1, s=-2)),
    "Hz": (1.0, _dim(s=-1)),
    "rad": (1.0, _dim(rad=1)), "deg": (math.pi / 180, _dim(rad=1)), "degree": (math.pi / 180, _dim(rad=1)),
    "rev": (2 * math.pi, _dim(rad=1)), "revolution": (2 * math.pi, _dim(rad=1)),
    "rpm": (2 * math.pi / 60, _dim(s=-1, rad=1)),
}

_registry = None


def registry():
    """The pint UnitRegistry of the process (pint's application registry, so other
    layers that use it share one), created on first use."""
    global _registry
    if _registry is None:
        import pint  # deferred: only answers with uncommon units pay for pint

        _registry = pint.get_application_registry()
    return _registry


def lookup(name: str) -> tuple[float, tuple]:
    """(factor to SI, dimension) of one unit name; AnswerError when unknown."""
    found = _lookup(name)
    if isinstance(found, str):
        raise AnswerError(found)
    return found


@lru_cache(maxsize=2048)
def _lookup(name: str) -> tuple[float, tuple] | str:
    """What :func:`lookup` answers, or the message why not (unknown names are asked of
    pint once, not once per answer)."""
    try:
        return _find(name)
    except AnswerError as error:
        return error.message


def _find(name: str) -> tuple[float, tuple]:
    if name in BUILTIN:
        return BUILTIN[name]
    if name in _REFUSED:
        raise AnswerError(_("the unit '{unit}' is not supported here").format(unit=name))
    if name in EVERYDAY:
        return _product(EVERYDAY[name])
    try:
        return _pint_unit(name)
    except _Refused:
        raise
    except AnswerError:
        pieces = _split(name)
        if pieces:
            return _product(tuple((p, 1) for p in pieces))
        raise


class _Refused(AnswerError):
    """A unit pint knows that no student of the course means (:mod:`.everyday_units`): it
    is refused as written, never read as a product of shorter units."""


def _product(parts) -> tuple[float, tuple]:
    factor, dim = 1.0, DIMENSIONLESS
    for unit, power in parts:
        f, d = BUILTIN.get(unit) or _pint_unit(unit)
        factor *= f ** power
        dim = add(dim, scale(d, power))
    return factor, dim


def _pint_unit(name: str) -> tuple[float, tuple]:
    if not name.replace("_", "").isalnum() or len(name) > 40 or name.startswith("_"):
        raise AnswerError(_("'{unit}' is not a unit I know").format(unit=name[:30]))
    ureg = registry()
    try:
        factor, root = ureg.get_root_units(name)
    except Exception:  # pint raises several error types for unknown names
        hint = suggest(name, _COMMON)
        if hint:
            raise AnswerError(_("'{unit}' is not a unit I know; did you mean '{hint}'?").format(
                unit=name, hint=hint)) from None
        raise AnswerError(_("'{unit}' is not a unit I know").format(unit=name)) from None
    refused = refusal(name, ureg.parse_unit_name(name))
    if refused:
        raise _Refused(refused)
    exps = [0.0] * 8
    factor = float(factor)
    for root_name, power in dict(root._units).items():
        if root_name not in _ROOTS:
            raise AnswerError(_("the unit '{unit}' is not supported here").format(unit=name))
        index, si = _ROOTS[root_name]
        exps[index] += float(power)
        factor *= si ** float(power)
    if not math.isfinite(factor) or factor == 0.0:
        raise AnswerError(_("the unit '{unit}' is not supported here").format(unit=name))
    return factor, tuple(exps)


def _split(name: str) -> list[str] | None:
    """Read ``kNm``-like names as common units written together, longest first.

    Only the built-in units are pieces, so that an unknown word (``blargs``) stays an
    unknown unit instead of a product of one-letter units pint happens to know."""
    if len(name) > 12:
        return None
    for k in range(len(name) - 1, 0, -1):
        head, tail = name[:k], name[k:]
        if head not in BUILTIN:
            continue
        if tail in BUILTIN:
            return [head, tail]
        rest = _split(tail)
        if rest:
            return [head] + rest
    return None


# -- dimension algebra ---------------------------------------------------------------------
def add(a: tuple, b: tuple) -> tuple:
    return tuple(x + y for x, y in zip(a, b))


def scale(a: tuple, k: float) -> tuple:
    return tuple(x * k for x in a)


def same(a: tuple, b: tuple, *, ignore_angle: bool = False) -> bool:
    n = _ANGLE if ignore_angle else 8
    return all(abs(a[i] - b[i]) < 1e-9 for i in range(n))


def compatible(given: tuple, wanted: tuple) -> bool:
    """Whether a value of dimension ``given`` can be converted to ``wanted`` (angle rule)."""
    if not same(given, wanted, ignore_angle=True):
        return False
    ga, wa = given[_ANGLE], wanted[_ANGLE]
    return abs(ga - wa) < 1e-9 or abs(ga) < 1e-9 or abs(wa) < 1e-9


def is_dimensionless(a: tuple, *, ignore_angle: bool = True) -> bool:
    return same(a, DIMENSIONLESS, ignore_angle=ignore_angle)


def has_angle(a: tuple) -> bool:
    return abs(a[_ANGLE]) > 1e-9


_SUPERSCRIPT_DIGITS = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")


def _power_text(symbol: str, power: float) -> str:
    frac = Fraction(power).limit_denominator(12)
    if frac == 1:
        return symbol
    if frac.denominator == 1:
        return symbol + str(frac.numerator).translate(_SUPERSCRIPT_DIGITS)
    return f"{symbol}^({frac.numerator}/{frac.denominator})"


def format_dimension(dim: tuple) -> str:
    """SI text of a dimension: ``kg·m/s²``, ``m²/s``, ``1/s``, ``1`` for none."""
    up = [_power_text(s, p) for s, p in zip(BASE_SYMBOLS, dim) if p > 1e-9]
    down = [_power_text(s, -p) for s, p in zip(BASE_SYMBOLS, dim) if p < -1e-9]
    top = "·".join(up) if up else "1"
    if not down:
        return top
    bottom = "·".join(down)
    return f"{top}/({bottom})" if len(down) > 1 else f"{top}/{bottom}"


#: words for dimensions, marked for the catalogs and translated where described
_NAMES = {
    (0, 1, 0): N_("a length"), (1, 0, 0): N_("a mass"), (0, 0, 1): N_("a time"),
    (0, 1, -1): N_("a velocity"), (0, 1, -2): N_("an acceleration"), (1, 1, -2): N_("a force"),
    (1, 2, -2): N_("an energy (or torque)"), (1, 2, -3): N_("a power"), (1, -1, -2): N_("a pressure"),
    (1, 1, -1): N_("a momentum (or impulse)"), (0, 0, -1): N_("a frequency (1/s)"),
    (0, 0, -2): N_("a quantity in 1/s²"), (0, 2, 0): N_("an area"), (0, 3, 0): N_("a volume"),
    (1, -3, 0): N_("a density"), (1, 0, -2): N_("a stiffness (N/m)"), (1, 0, -1): N_("a damping coefficient (N·s/m)"),
    (1, 2, 0): N_("a moment of inertia"), (1, 2, -1): N_("an angular momentum"), (0, 0, 0): N_("a pure number"),
}
_ANGLE_NAMES = {(0, 0, 0): N_("an angle"), (0, 0, -1): N_("an angular velocity"),
                (0, 0, -2): N_("an angular acceleration")}


def describe_dimension(dim: tuple) -> str:
    """Words for a dimension: 'a velocity', 'an angle', 'a quantity in kg·m/s³'."""
    if all(abs(x) < 1e-9 for x in dim[3:7]):
        key = tuple(int(round(x)) if abs(x - round(x)) < 1e-9 else None for x in dim[:3])
        if None not in key:
            if has_angle(dim) and abs(dim[_ANGLE] - 1) < 1e-9 and key in _ANGLE_NAMES:
                return _(_ANGLE_NAMES[key])
            if not has_angle(dim) and key in _NAMES:
                return _(_NAMES[key])
    return _("a quantity in {units}").format(units=format_dimension(dim))
