"""Generic mistakes tried automatically when a numeric answer is wrong.

Each candidate is (name, wrong value, feedback). They are tried after the part's
declared misconceptions; the first one that matches the answer (with the part's own
tolerance) names the mistake in the feedback. Candidates that coincide with the
reference itself (e.g. the sign of 0) are skipped, since they cannot discriminate.
"""

from __future__ import annotations

from ..i18n import N_, _
import math

#: the mistakes' names are stored with each verdict as they are (English keys of the reports);
#: marked for the catalogs, translated where they are shown
SIGN = N_("sign")
DOUBLE = N_("factor 2")
HALF = N_("factor 1/2")
RECIPROCAL = N_("reciprocal")
DEGREES = N_("degrees for radians")
RADIANS = N_("radians for degrees")
TWO_PI = N_("factor 2π")
POWER_OF_TEN = N_("power of ten")
#: an answer in a unit of the wrong dimension (the verdict names it; no value is tried)
UNIT = N_("unit")
#: a right number in the other kind of frequency: ω's value labelled Hz, or f's labelled rad/s
#: (:mod:`.frequency`; the numeric grader names it, no value is tried)
CYCLES = N_("Hz for rad/s")


def numeric_candidates(expected: float, *, angle_unit: str | None = None,
                       rotational: bool = False) -> list[tuple[str, float, str]]:
    """Wrong values a student commonly produces for ``expected``.

    ``angle_unit`` is ``"rad"`` or ``"deg"`` when the part asks for an angle in that
    unit; ``rotational`` enables the 2π mix-up (rev or Hz for rad/s).
    """
    e = expected
    out: list[tuple[str, float, str]] = [
        (SIGN, -e, _("Your answer has the wrong sign: check the direction you took as positive.")),
        (DOUBLE, 2 * e, _("Your answer is twice the expected value: check for an extra factor of 2.")),
        (HALF, e / 2, _("Your answer is half the expected value: check for a missing factor of 2.")),
    ]
    if angle_unit == "rad":
        out.append((DEGREES, e * 180 / math.pi,
                    _("Your answer looks like degrees, but the answer is asked in radians.")))
    if angle_unit == "deg":
        out.append((RADIANS, e * math.pi / 180,
                    _("Your answer looks like radians, but the answer is asked in degrees.")))
    if rotational:
        two_pi = _("Your answer is off by a factor 2π: check revolutions (or Hz) against radians.")
        out.append((TWO_PI, e / (2 * math.pi),
                    two_pi))
        out.append((TWO_PI, e * 2 * math.pi,
                    two_pi))
    if e != 0:
        out.append((RECIPROCAL, 1 / e,
                    _("Your answer is the reciprocal of the expected value: is a fraction upside down?")))
    for k in (3, -3, 1, -1, 2, -2, 6, -6, 9, -9, 4, -4, 5, -5, 7, -7, 8, -8):
        sign = "" if k > 0 else "-"
        out.append((POWER_OF_TEN, e * 10.0 ** k,
                    _("Your answer is off by a factor of 10^{exponent}: check unit prefixes and "
                      "conversions.").format(exponent=f"{sign}{abs(k)}")))
    return out
