"""Units in the order a student means them: an everyday table before pint, a deny-list after.

pint knows thousands of units, and for the short names a student of this course types it
often knows an obscure one first: ``kNm`` is kilo-``number_meter`` (a yarn count, in m/kg),
``Grad`` is a giga-radian, ``U`` an enzyme unit, ``M`` molar. :mod:`.units` therefore asks
this module twice:

- :data:`EVERYDAY` is read before pint: each spelling is a product of units the grader
  knows (``kNm`` = kN·m, ``Grad`` = degree, ``U`` = revolution, the German *Umdrehung*, so
  that ``U/min`` is the rotational speed printed on every motor plate);
- :func:`refusal` is asked about every unit pint found: for a unit no Dynamics student
  means (molar, enzyme units, yarn counts, gradians, prefixed angles, physical constants
  that pint lets pass for units) it gives the message that names the likely meaning,
  and the answer is refused instead of being graded in that unit.

The rule for ``1/min`` (a rotational speed, rev/min) sits in :mod:`.frequency`, since it
depends on how the unit is written as a whole, not on one name.
"""

from __future__ import annotations

from ..i18n import N_, _

#: Spellings read before pint, as products of units (BUILTIN or pint names) and powers.
EVERYDAY: dict[str, tuple[tuple[str, int], ...]] = {
    # a torque or moment: newton metre with the prefixes of the newton (pint: number_meter)
    "Nm": (("N", 1), ("m", 1)),
    "kNm": (("kN", 1), ("m", 1)),
    "MNm": (("MN", 1), ("m", 1)),
    "mNm": (("mN", 1), ("m", 1)),
    "Nms": (("N", 1), ("m", 1), ("s", 1)),
    "kNms": (("kN", 1), ("m", 1), ("s", 1)),
    "Ns": (("N", 1), ("s", 1)),
    "kmh": (("km", 1), ("h", -1)),
    # angles and turns as written in German and in short
    "Grad": (("deg", 1),),
    "degrees": (("deg", 1),),
    "U": (("revolution", 1),),
    "rev": (("revolution", 1),),
    "revs": (("revolution", 1),),
    "Upm": (("rpm", 1),),
    "upm": (("rpm", 1),),
    "RPM": (("rpm", 1),),
    "sec": (("s", 1),),
    "secs": (("s", 1),),
}

_YARN = N_("'{unit}' is a yarn count here; for a torque write N·m or kN·m (also Nm, kNm)")
_CONSTANT = N_("'{unit}' is a physical constant here, not a unit; give a number with a unit, "
               "e.g. 12 kN")
_PREFIXED_ANGLE = N_("'{unit}' is a prefixed angle unit here; write angles in rad, mrad, deg or "
                     "rev")

#: pint's unit (without its prefix) -> the message that refuses it, naming the likely meaning
DENIED: dict[str, str] = {
    "molar": N_("'{unit}' is molar (mol/L) here; for mega write a prefix with a unit, e.g. MN"),
    "enzyme_unit": N_("'{unit}' is an enzyme unit here; a revolution is U (German Umdrehung) "
                      "or rev, without a prefix, e.g. U/min"),
    "number_meter": _YARN,
    "number_english": _YARN,
    "grade": N_("'{unit}' is the gradian (400 to a full turn) here; for degrees write ° or deg "
                "(or Grad)"),
    "boltzmann_constant": N_("'{unit}' is Boltzmann's constant here; for kilo write a prefix "
                             "with a unit, e.g. kN"),
    "gauss": N_("'{unit}' is the gauss (a magnetic unit) here; for giga write a prefix with a "
                "unit, e.g. GPa"),
    "tesla": N_("'{unit}' is the tesla (a magnetic unit) here; for tonnes write t, for tera a "
                "prefix with a unit"),
    "poise": N_("'{unit}' is the poise (a viscosity) here; for a power write W, for peta a "
                "prefix with a unit"),
    "speed_of_light": _CONSTANT,
    "elementary_charge": _CONSTANT,
    "molar_gas_constant": _CONSTANT,
    "gravitational_constant": _CONSTANT,
    "planck_constant": _CONSTANT,
    "avogadro_constant": _CONSTANT,
}
#: angle units that take no prefix but milli and micro (``krad``, ``Grad`` as giga-rad)
_ANGLES = frozenset({"radian", "degree", "turn", "arcminute", "arcsecond", "grade"})
_ANGLE_PREFIXES = frozenset({"", "milli", "micro"})


def refusal(name: str, readings) -> str | None:
    """The message that refuses unit ``name``, given pint's readings of it ((prefix, unit,
    suffix) triples, ``UnitRegistry.parse_unit_name``), or None when it may be used."""
    for prefix, unit, _suffix in readings:
        if unit in DENIED:
            return _(DENIED[unit]).format(unit=name)
        if unit in _ANGLES and prefix not in _ANGLE_PREFIXES:
            return _(_PREFIXED_ANGLE).format(unit=name)
    return None
