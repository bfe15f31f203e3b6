"""How wide text is, for laying out figure labels: the advance widths of DejaVu Sans.

DejaVu Sans is the font matplotlib drew figure labels with; its widths (in ems, read
from the font's ``hmtx`` table, three decimals) are at least those of the fonts a viewer
falls back on (Arial, Helvetica, Libertinus in typst), so a figure cropped to labels
measured here never cuts one off. A character not listed counts as :data:`OTHER` wide;
combining marks (a dot over a letter) take no width.

Usage::

    text_width("v₀ = 3 m/s", 10.0)     # points, at 10 pt
"""

from __future__ import annotations

import unicodedata

#: the height above the baseline and the depth below it (ems) that matplotlib gives a line
#: of DejaVu Sans text whatever its letters (from "l" and "p")
ASCENT, DESCENT = 0.760, 0.208
#: the width (ems) of a character not in the table
OTHER = 0.65

_BY_WIDTH = {
    0.227: '′',
    0.275: "'",
    0.278: 'ijl',
    0.295: 'IJΙₜ',
    0.318: ' ,.·',
    0.337: '/:;\\|',
    0.338: 'ι',
    0.352: 'f',
    0.361: '-',
    0.374: '″',
    0.39: '()[]',
    0.392: 'tₐ',
    0.398: 'ₙ',
    0.401: '!²³¹⁰⁴⁵⁶⁷⁸⁹₀₁₂₃₄₅₆₇₈₉',
    0.411: 'r',
    0.414: 'ₒ',
    0.417: 'ₑ',
    0.444: 'ₓ',
    0.46: '"',
    0.5: '*_`°–',
    0.517: '∂',
    0.521: 's∫',
    0.525: 'z',
    0.528: '⁺⁻₊₋',
    0.531: '?',
    0.541: 'ε',
    0.544: 'ζ',
    0.55: 'c',
    0.557: 'LΓ',
    0.558: 'ξ',
    0.559: 'ν',
    0.575: 'F',
    0.578: 'χ',
    0.579: 'kυ',
    0.587: 'ς',
    0.589: 'κ',
    0.592: 'vxyγλ',
    0.602: 'πτ',
    0.603: 'PΡ',
    0.611: 'TYΤΥ',
    0.612: 'oδθο',
    0.613: 'a',
    0.615: 'e',
    0.619: 'ϑ',
    0.632: 'EΕΞΣ',
    0.634: 'hnuησ',
    0.635: 'Sbdgpqρ',
    0.636: '$0123456789{}μµ',
    0.637: '√',
    0.638: 'β',
    0.656: 'KΚ',
    0.659: 'α',
    0.66: 'φψϕ',
    0.684: 'AVΑΔΛ',
    0.685: 'XZΖΧ',
    0.686: 'BΒ',
    0.695: 'R',
    0.698: 'C',
    0.732: 'U',
    0.748: 'NΝ',
    0.752: 'HΗΠ',
    0.764: 'Ω',
    0.77: 'D',
    0.775: 'G',
    0.78: '&',
    0.787: 'OQΘΟΦΨ',
    0.818: 'w',
    0.833: '∞',
    0.837: 'ωϖ',
    0.838: '#+<=>^~−±×÷≤≥≈',
    0.863: 'MΜ',
    0.95: '%',
    0.974: 'm',
    0.989: 'W',
    1.0: '@—…',
}
_WIDTH = {char: width for width, chars in _BY_WIDTH.items() for char in chars}


def text_width(text: str, size: float) -> float:
    """The advance width of ``text`` set at ``size`` points, in points."""
    total = 0.0
    for char in text:
        width = _WIDTH.get(char)
        if width is None:
            width = 0.0 if unicodedata.combining(char) else OTHER
        total += width
    return total * size
