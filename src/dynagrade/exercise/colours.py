"""Colours as exercise figures name them, read without matplotlib.

A figure names its colours the way matplotlib does, and the same names keep working:
``"C0"`` … ``"C9"`` (matplotlib's default cycle, "tab10"), a grey level as a string of a
number from 0 (black) to 1 (white) such as ``"0.1"``, ``"#rrggbb"``/``"#rgb"``, a
``(r, g, b)`` tuple of fractions, and the handful of CSS names below.

Usage::

    to_hex("C3")            # "#d62728"
    to_rgb("0.1")           # (0.1, 0.1, 0.1)
"""

from __future__ import annotations

from functools import lru_cache

from ..errors import DefinitionError

#: matplotlib's default colour cycle ("tab10"): what ``"C0"`` … ``"C9"`` mean
CYCLE = ("#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2",
         "#7f7f7f", "#bcbd22", "#17becf")
NAMED = {"black": "#000000", "white": "#ffffff", "red": "#ff0000", "green": "#008000",
         "blue": "#0000ff", "gray": "#808080", "grey": "#808080", "orange": "#ffa500",
         "k": "#000000", "w": "#ffffff", "r": "#ff0000", "g": "#008000", "b": "#0000ff"}


def to_rgb(colour) -> tuple[float, float, float]:
    """``colour`` as red, green and blue fractions; a :class:`DefinitionError` naming it
    when it is none of the forms the module's docstring lists."""
    if isinstance(colour, (tuple, list)) and len(colour) in (3, 4) \
            and all(isinstance(c, (int, float)) and 0 <= c <= 1 for c in colour):
        return float(colour[0]), float(colour[1]), float(colour[2])
    if not isinstance(colour, str):
        raise DefinitionError(f"figure colour {colour!r}: expected a name such as 'C0', "
                              "'0.1', '#a0724a' or 'white'")
    text = colour.strip().lower()
    if len(text) == 2 and text[0] == "c" and text[1].isdigit():
        text = CYCLE[int(text[1])]
    text = NAMED.get(text, text)
    if text.startswith("#") and len(text) in (4, 7):
        digits = text[1:] if len(text) == 7 else "".join(c * 2 for c in text[1:])
        if all(c in "0123456789abcdef" for c in digits):
            red, green, blue = (int(digits[i:i + 2], 16) / 255 for i in (0, 2, 4))
            return red, green, blue
    else:
        try:
            level = float(text)
        except ValueError:
            level = -1.0
        if 0.0 <= level <= 1.0:
            return level, level, level
    raise DefinitionError(f"figure colour {colour!r}: expected a name such as 'C0', "
                          "'0.1', '#a0724a' or 'white'")


def to_hex(colour) -> str:
    """``colour`` as ``#rrggbb`` (each channel rounded as matplotlib rounds it)."""
    if isinstance(colour, str):
        return _named_hex(colour)
    return _hex(to_rgb(colour))


@lru_cache(maxsize=256)
def _named_hex(colour: str) -> str:
    """:func:`to_hex` of a colour given as text, kept: a figure names a few colours over
    and over (every line, label and arrow of every student's figure)."""
    return _hex(to_rgb(colour))


def _hex(rgb: tuple[float, float, float]) -> str:
    return "#" + "".join(f"{round(c * 255):02x}" for c in rgb)
