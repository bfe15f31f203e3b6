"""A figure recorded as data: lines, labels, arrows and shapes on equal-scale axes.

:func:`dynagrade.exercise.figure.new_drawing` gives ``(drawing, axes)``; the axes answer
the part of matplotlib's ``Axes`` that schematic figures use — ``plot`` (with a format
string such as ``"o"`` or ``"--"``), ``text``, ``annotate`` with an arrow, ``add_patch``,
``set_xlim``/``set_ylim`` — and record what is drawn, in the order drawn, as plain
objects (:class:`Line`, :class:`Label`, :class:`Arrow` and the shapes of
:mod:`dynagrade.exercise.shapes`). Nothing is laid out or rendered here: the SVG writer
(:mod:`dynagrade.render.svg_figure`) does that in one pass, so drawing a figure costs
what its data costs. A keyword the recorder does not know is an error naming it.

Usage::

    drawing, axes = new_drawing(5.0, 3.0)
    axes.plot([0, 1], [0, 0.5], "--", color="0.4", lw=0.8)
    axes.text(0.5, 0.3, "v₀", ha="center", color="C3")
    axes.set_xlim(-0.1, 1.1)
"""

from __future__ import annotations

import re

from ..errors import DefinitionError
from .shapes import LINE_ORDER, TEXT_ORDER, Shape, from_matplotlib, line_style

#: matplotlib's defaults that schematic figures rely on
LINE_WIDTH, MARKER_SIZE, FONT_SIZE = 1.5, 6.0, 10.0
MARKERS = ("o", "s", "^", "v", ".", "D")
_FORMAT = re.compile(r"^(?P<a>--|-\.|-|:)?(?P<m>[os^v.D])?(?P<b>--|-\.|-|:)?(?P<c>[krgbwcmy])?$")
_LETTERS = {"k": "black", "r": "red", "g": "green", "b": "blue", "w": "white"}


def _take(options: dict, *names, default=None):
    """The value of the first of ``names`` present in ``options`` (removed from it)."""
    value = default
    for name in names:
        if name in options:
            value = options.pop(name)
    return value


def _no_more(options: dict, where: str) -> None:
    if options:
        raise DefinitionError(f"{where}: unknown keyword {sorted(options)[0]!r}")


class Line:
    """A polyline through ``x``, ``y`` (data coordinates) and/or markers at its points."""

    order = LINE_ORDER

    def __init__(self, x, y, colour, width, style, marker, marker_size, zorder, capstyle):
        self.x, self.y = [float(v) for v in x], [float(v) for v in y]
        if len(self.x) != len(self.y):
            raise DefinitionError(f"plot: x and y differ in length ({len(self.x)} and "
                                  f"{len(self.y)})")
        self.colour, self.width, self.style = colour, float(width), style
        self.marker, self.marker_size = marker, float(marker_size)
        self.zorder, self.capstyle = float(zorder), capstyle

    def get_data(self):
        return list(self.x), list(self.y)

    def get_linestyle(self) -> str:
        return self.style or "None"

    def get_marker(self) -> str:
        return self.marker or "None"

    def get_color(self):
        return self.colour

    def get_linewidth(self) -> float:
        return self.width


class Label:
    """Text at ``(x, y)`` (data coordinates), aligned there by ``ha``/``va``, turned by
    ``rotation`` degrees about that point."""

    order = TEXT_ORDER

    def __init__(self, x, y, text, colour, size, ha, va, rotation, zorder):
        self.x, self.y, self.text = float(x), float(y), str(text)
        self.colour, self.size, self.ha, self.va = colour, float(size), ha, va
        self.rotation, self.zorder = float(rotation), float(zorder)
        if ha not in ("left", "center", "right"):
            raise DefinitionError(f"text {self.text!r}: ha={ha!r} is not left, center or right")
        if va not in ("top", "center", "bottom", "baseline", "center_baseline"):
            raise DefinitionError(f"text {self.text!r}: va={va!r} is not top, center, "
                                  "bottom or baseline")

    def get_text(self) -> str:
        return self.text

    def get_color(self):
        return self.colour

    def get_visible(self) -> bool:
        return True

    def get_position(self):
        return self.x, self.y


class Arrow:
    """An arrow from ``start`` to ``end`` with a filled head at the end (``heads`` "end")
    or at both ends ("both"), bent into an arc by ``bend`` (matplotlib's ``arc3`` radius:
    the control point lies ``bend`` times the arrow's length off its middle)."""

    order = TEXT_ORDER

    def __init__(self, start, end, colour, width, heads, head_size, bend, zorder):
        self.start = (float(start[0]), float(start[1]))
        self.end = (float(end[0]), float(end[1]))
        self.colour, self.width, self.heads = colour, float(width), heads
        self.head_size, self.bend, self.zorder = float(head_size), float(bend), float(zorder)


_ARROW_STYLES = {"-|>": "end", "<|-|>": "both", "->": "end", "<->": "both", "-": "none"}


class Canvas:
    """The axes of a drawing: equal scale in x and y, no axis lines; records what is
    drawn on it (``lines``, ``patches``, ``texts``, ``arrows``)."""

    def __init__(self, drawing: Drawing):
        self.figure = drawing
        self.lines: list[Line] = []
        self.patches: list[Shape] = []
        self.texts: list[Label] = []
        self.arrows: list[Arrow] = []
        self.xlim: tuple[float, float] | None = None
        self.ylim: tuple[float, float] | None = None
        self._cycle = 0
        self._order: list = []          # everything, in the order it was drawn

    # -- what matplotlib's Axes offers that figures use -------------------------------------

    def plot(self, *args, **options):
        """A line (or markers) through the points: ``plot(y)``, ``plot(x, y)`` or
        ``plot(x, y, fmt)``; keywords ``color``, ``lw``, ``ls``, ``marker``, ``ms``,
        ``zorder``, ``solid_capstyle``. Returns ``[line]`` as matplotlib does."""
        fmt = args[-1] if args and isinstance(args[-1], str) else ""
        data = args[:-1] if fmt else args
        if len(data) == 1:
            y = list(_sequence(data[0]))
            x = list(range(len(y)))
        elif len(data) == 2:
            x, y = _sequence(data[0]), _sequence(data[1])
        else:
            raise DefinitionError("plot: give y, or x and y (one line per call)")
        match = _FORMAT.match(fmt)
        if match is None:
            raise DefinitionError(f"plot: format {fmt!r} is not a line style, marker and "
                                  "colour (such as 'o', '--' or 'k-')")
        style = match.group("a") or match.group("b") or ""
        marker = match.group("m") or ""
        if not style and not marker:
            style = "-"
        colour = _take(options, "c", "color", default=_LETTERS.get(match.group("c") or ""))
        if colour is None:
            colour = f"C{self._cycle % 10}"
            self._cycle += 1
        width = _take(options, "lw", "linewidth", default=LINE_WIDTH)
        given_style = _take(options, "ls", "linestyle")
        if given_style is not None:
            style = line_style(given_style, "plot")
        marker = _take(options, "marker", default=marker) or ""
        if marker and marker not in MARKERS:
            raise DefinitionError(f"plot: unknown marker {marker!r} (use one of {MARKERS})")
        size = _take(options, "ms", "markersize", default=MARKER_SIZE)
        zorder = _take(options, "zorder", default=2.0)
        capstyle = _take(options, "solid_capstyle", default="projecting")
        _no_more(options, "plot")
        line = Line(x, y, colour, width, style, marker, size, zorder, capstyle)
        self.lines.append(line)
        self._order.append(line)
        return [line]

    def text(self, x, y, s, **options) -> Label:
        """A text label at ``(x, y)``; keywords ``color``, ``fontsize``, ``ha``, ``va``,
        ``rotation`` (degrees), ``rotation_mode``, ``zorder``."""
        label = self._label(x, y, s, options, "text")
        self.texts.append(label)
        self._order.append(label)
        return label

    def annotate(self, text, xy, xytext=None, arrowprops=None, **options):
        """An arrow from ``xytext`` to ``xy`` as ``arrowprops`` describe it
        (``arrowstyle`` "-|>" or "<|-|>", ``color``, ``lw``, ``mutation_scale``,
        ``connectionstyle`` "arc3,rad=r"), and ``text`` at ``xytext`` when it is not
        empty."""
        start = xytext if xytext is not None else xy
        if arrowprops is not None:
            props = dict(arrowprops)
            style = _take(props, "arrowstyle", default="-|>")
            if style not in _ARROW_STYLES:
                raise DefinitionError(f"annotate: arrow style {style!r} is not one of "
                                      f"{sorted(_ARROW_STYLES)}")
            colour = _take(props, "color", "fc", "facecolor", default="black")
            width = _take(props, "lw", "linewidth", default=1.0)
            size = _take(props, "mutation_scale", default=options.get("fontsize", FONT_SIZE))
            for shrink in ("shrinkA", "shrinkB"):
                if _take(props, shrink, default=0) != 0:
                    raise DefinitionError(f"annotate: {shrink} must be 0 (arrows run "
                                          "exactly between their points)")
            bend = _connection_bend(_take(props, "connectionstyle", default="arc3,rad=0"))
            _no_more(props, "annotate's arrowprops")
            arrow = Arrow(start, xy, colour, width, _ARROW_STYLES[style], size, bend,
                          options.pop("zorder", 3.0))
            self.arrows.append(arrow)
            self._order.append(arrow)
        if text:
            x, y = start
            return self.text(x, y, text, **options)
        _take(options, "fontsize", "size")
        _no_more(options, "annotate")
        return None

    def add_patch(self, patch):
        """Draw a shape (:mod:`dynagrade.exercise.shapes`, or a matplotlib Circle,
        Ellipse, Rectangle or Polygon)."""
        shape = patch if isinstance(patch, Shape) else from_matplotlib(patch)
        self.patches.append(shape)
        self._order.append(shape)
        return shape

    def set_xlim(self, left=None, right=None, **_):
        self.xlim = _limits(left, right, self.xlim, "set_xlim")
        return self.xlim

    def set_ylim(self, bottom=None, top=None, **_):
        self.ylim = _limits(bottom, top, self.ylim, "set_ylim")
        return self.ylim

    def get_xlim(self) -> tuple[float, float]:
        return self.xlim or self.data_limits()[0]

    def get_ylim(self) -> tuple[float, float]:
        return self.ylim or self.data_limits()[1]

    def data_limits(self):
        """What matplotlib's autoscaling picks when no limits are set: the extent of the
        lines and shapes with a margin of 5 % on each side."""
        xs = [v for line in self.lines for v in line.x]
        ys = [v for line in self.lines for v in line.y]
        for shape in self.patches:
            for x, y in shape.outline():
                xs.append(x)
                ys.append(y)
        if not xs:
            return (0.0, 1.0), (0.0, 1.0)
        limits = []
        for values in (xs, ys):
            low, high = min(values), max(values)
            margin = 0.05 * (high - low) or 0.5
            limits.append((low - margin, high + margin))
        return tuple(limits)

    def set_aspect(self, aspect, **_):
        if aspect not in ("equal", 1, 1.0):
            raise DefinitionError(f"set_aspect({aspect!r}): a drawing is always to scale "
                                  "(equal aspect)")

    def get_aspect(self) -> float:
        return 1.0

    def set_axis_off(self):
        """A drawing has no axes lines already."""

    def get_lines(self) -> list[Line]:
        return list(self.lines)

    def get_figure(self) -> Drawing:
        return self.figure

    def drawn(self) -> list:
        """Everything drawn, in the order it is painted: by zorder, then patches before
        lines before texts and arrows, then in the order drawn (matplotlib's order)."""
        ranked = sorted(enumerate(self._order), key=lambda e: (e[1].zorder, e[1].order, e[0]))
        return [item for _, item in ranked]

    def _label(self, x, y, s, options: dict, where: str) -> Label:
        colour = _take(options, "c", "color", default="black")
        size = _take(options, "fontsize", "size", default=FONT_SIZE)
        ha = _take(options, "ha", "horizontalalignment", default="left")
        va = _take(options, "va", "verticalalignment", default="baseline")
        rotation = _take(options, "rotation", default=0.0)
        _take(options, "rotation_mode")
        zorder = _take(options, "zorder", default=3.0)
        _no_more(options, where)
        return Label(x, y, s, colour, size, ha, va, rotation, zorder)


class Drawing:
    """A figure of ``width`` x ``height`` inches holding one :class:`Canvas`."""

    def __init__(self, width: float = 5.0, height: float = 3.0):
        self.width, self.height = float(width), float(height)
        self.axes = [Canvas(self)]
        self.texts: list[Label] = []

    def get_size_inches(self) -> tuple[float, float]:
        return self.width, self.height

    def set_size_inches(self, width: float, height: float) -> None:
        self.width, self.height = float(width), float(height)


def _sequence(values):
    try:
        return [float(v) for v in values]
    except TypeError:
        return [float(values)]


def _limits(low, high, current, where: str) -> tuple[float, float]:
    if high is None and isinstance(low, (tuple, list)):
        low, high = low
    old = current or (None, None)
    low = old[0] if low is None else low
    high = old[1] if high is None else high
    try:
        low, high = float(low), float(high)
    except (TypeError, ValueError):
        raise DefinitionError(f"{where}: give both limits as numbers") from None
    if not low < high:
        raise DefinitionError(f"{where}({low}, {high}): the first limit must be the smaller")
    return low, high


def _connection_bend(style: str) -> float:
    match = re.fullmatch(r"\s*arc3\s*(?:,\s*rad\s*=\s*(-?[\d.]+)\s*)?", str(style))
    if match is None:
        raise DefinitionError(f"annotate: connection style {style!r} is not 'arc3,rad=r'")
    return float(match.group(1) or 0.0)
