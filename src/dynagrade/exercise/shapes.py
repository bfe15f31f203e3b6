"""The shapes an exercise figure is made of, recorded as plain data.

A figure is a list of these records (see :mod:`dynagrade.exercise.drawing`); the SVG
writer (:mod:`dynagrade.render.svg_figure`) turns them into elements. The filled shapes
take matplotlib's constructor arguments and keywords (``Circle((x, y), r, facecolor="C0",
edgecolor="0.1", lw=1.0, ls="--", fill=False, zorder=3)``), so an exercise written for
matplotlib's patches keeps working; a keyword they do not know is an error naming it.

Usage::

    from dynagrade.exercise.figure import Circle, Polygon

    axes.add_patch(Circle((0.0, 1.0), 0.2, facecolor="white", edgecolor="0.1"))
"""

from __future__ import annotations

import math
from abc import ABC, abstractmethod

from ..errors import DefinitionError

#: line styles by every name matplotlib accepts for them
LINE_STYLES = {"-": "-", "solid": "-", "--": "--", "dashed": "--", ":": ":",
               "dotted": ":", "-.": "-.", "dashdot": "-.", "": "", "none": "",
               "None": "", " ": ""}
#: the drawing order of kinds that share a zorder (matplotlib's: patches, lines, texts)
PATCH_ORDER, LINE_ORDER, TEXT_ORDER = 0, 1, 2


def line_style(value, where: str) -> str:
    """``value`` as one of ``"-"``, ``"--"``, ``":"``, ``"-."`` or ``""`` (no line)."""
    if value not in LINE_STYLES:
        raise DefinitionError(f"{where}: unknown line style {value!r} "
                              f"(use one of '-', '--', ':', '-.')")
    return LINE_STYLES[value]


def _point(value, where: str) -> tuple[float, float]:
    try:
        x, y = value
        return float(x), float(y)
    except (TypeError, ValueError):
        raise DefinitionError(f"{where}: expected a point (x, y), got {value!r}") from None


class Shape(ABC):
    """A filled or outlined shape: its fill and outline colours (``None`` for none), the
    outline's width (pt) and style, and its zorder (matplotlib's default 1)."""

    order = PATCH_ORDER

    def __init__(self, *, facecolor=None, edgecolor=None, color=None, fill=True,
                 linewidth=None, linestyle="-", zorder=1.0, name="shape", **aliases):
        facecolor = aliases.pop("fc", facecolor)  # matplotlib's short keyword names
        edgecolor = aliases.pop("ec", edgecolor)
        linewidth = aliases.pop("lw", linewidth)
        linestyle = aliases.pop("ls", linestyle)
        if aliases:
            raise DefinitionError(f"{name}: unknown keyword {sorted(aliases)[0]!r}")
        if color is not None:
            facecolor = facecolor if facecolor is not None else color
            edgecolor = edgecolor if edgecolor is not None else color
        self.fill = bool(fill)
        self.facecolor = (facecolor if facecolor is not None else "C0") if fill else None
        # matplotlib outlines a filled shape only when asked, an unfilled one always
        self.edgecolor = edgecolor if edgecolor is not None else (None if fill else "black")
        self.linewidth = 1.0 if linewidth is None else float(linewidth)
        self.linestyle = line_style(linestyle, name)
        self.zorder = float(zorder)

    def get_facecolor(self):
        return self.facecolor

    def get_edgecolor(self):
        return self.edgecolor

    def get_linewidth(self) -> float:
        return self.linewidth

    def get_zorder(self) -> float:
        return self.zorder

    @abstractmethod
    def outline(self) -> list[tuple[float, float]]:
        """Points on the shape's outline, in data coordinates (for its extent)."""


class Polygon(Shape):
    """A polygon through the points ``xy``; closed unless ``closed=False``."""

    def __init__(self, xy, closed: bool = True, **style):
        super().__init__(name="Polygon", **style)
        self.points = [_point(p, "Polygon") for p in xy]
        self.closed = bool(closed)

    def get_xy(self) -> list[tuple[float, float]]:
        """The points; a closed polygon repeats its first point at the end (as
        matplotlib's ``Polygon.get_xy`` does)."""
        return self.points + self.points[:1] if self.closed else list(self.points)

    def outline(self) -> list[tuple[float, float]]:
        return list(self.points)


class Ellipse(Shape):
    """An ellipse centred at ``xy`` with full ``width`` and ``height``, turned by
    ``angle`` degrees counter-clockwise."""

    def __init__(self, xy, width: float, height: float, angle: float = 0.0, **style):
        super().__init__(name=type(self).__name__, **style)
        self.center = _point(xy, type(self).__name__)
        self.width, self.height, self.angle = float(width), float(height), float(angle)

    def outline(self) -> list[tuple[float, float]]:
        turn = math.radians(self.angle)
        points = []
        for k in range(16):
            t = 2 * math.pi * k / 16
            u, v = 0.5 * self.width * math.cos(t), 0.5 * self.height * math.sin(t)
            points.append((self.center[0] + u * math.cos(turn) - v * math.sin(turn),
                           self.center[1] + u * math.sin(turn) + v * math.cos(turn)))
        return points


class Circle(Ellipse):
    """A circle of ``radius`` centred at ``xy``."""

    def __init__(self, xy, radius: float = 5.0, **style):
        super().__init__(xy, 2 * float(radius), 2 * float(radius), **style)
        self.radius = float(radius)

    def get_radius(self) -> float:
        return self.radius


class Rectangle(Polygon):
    """A rectangle with its lower left corner at ``xy``, ``width`` by ``height``, turned
    by ``angle`` degrees counter-clockwise about that corner."""

    def __init__(self, xy, width: float, height: float, angle: float = 0.0, **style):
        x, y = _point(xy, "Rectangle")
        c, s = math.cos(math.radians(angle)), math.sin(math.radians(angle))
        corners = [(x + c * u - s * v, y + s * u + c * v)
                   for u, v in ((0, 0), (width, 0), (width, height), (0, height))]
        super().__init__(corners, closed=True, **style)
        self.corner, self.width, self.height = (x, y), float(width), float(height)


def from_matplotlib(patch) -> Shape:
    """The shape of a matplotlib patch (Circle, Ellipse, Rectangle or Polygon), for
    exercises that draw with ``matplotlib.patches``; any other patch is an error."""
    kind = type(patch).__name__
    style = {"linewidth": patch.get_linewidth(), "zorder": patch.get_zorder(),
             "linestyle": _matplotlib_dashes(patch), "fill": patch.get_fill(),
             "facecolor": _visible(patch.get_facecolor()),
             "edgecolor": _visible(patch.get_edgecolor())}
    if not style["fill"]:
        style["facecolor"] = None
    shape: Shape
    if kind == "Circle":
        shape = Circle(patch.center, patch.radius, **style)
    elif kind == "Ellipse":
        shape = Ellipse(patch.center, patch.width, patch.height, patch.angle, **style)
    elif kind == "Rectangle":
        shape = Rectangle(patch.get_xy(), patch.get_width(), patch.get_height(),
                          patch.angle, **style)
    elif kind == "Polygon":
        points = [tuple(p) for p in patch.get_xy()]
        if patch.get_closed() and len(points) > 1 and points[0] == points[-1]:
            points = points[:-1]
        shape = Polygon(points, closed=patch.get_closed(), **style)
    else:
        raise DefinitionError(f"a figure cannot draw a matplotlib {kind}: use Circle, "
                              "Ellipse, Rectangle or Polygon from dynagrade.exercise.figure")
    if style["edgecolor"] is None:
        shape.edgecolor = None
    return shape


def _visible(rgba):
    """An RGBA tuple as ``(r, g, b)``, or ``None`` when it is fully transparent."""
    return None if rgba[3] == 0 else tuple(float(c) for c in rgba[:3])


def _matplotlib_dashes(patch) -> str:
    style = patch.get_linestyle()
    return style if style in LINE_STYLES else "-"
