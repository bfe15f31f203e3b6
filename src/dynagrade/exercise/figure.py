"""Drawing helpers for exercise figures, drawn to scale.

An exercise may declare ``figure=draw``, where ``draw(p)`` receives the parameters in SI
and returns the drawing made by :func:`new_drawing` (see :mod:`dynagrade.exercise.drawing`:
its axes take matplotlib's ``plot``, ``text``, ``annotate`` and ``add_patch`` calls);
these helpers draw the usual parts of a mechanics sketch (arrows, angle arcs, ground,
blocks, springs, dampers, dimensions) and :class:`Circle`, :class:`Ellipse`,
:class:`Rectangle` and :class:`Polygon` are the shapes to add. Rendering the figure to
SVG is :func:`dynagrade.render.figures.figure_svg`. (A figure function may still return
a matplotlib figure, for a real plot; it is rendered by matplotlib.)

Every helper also notes, in words, what it drew (an arrow "pointing up and to the
right", an angle "turning counter-clockwise from the downward direction"); the renderer
puts these notes, every text label of the figure and the author's own sentences
(:func:`describe`) into the figure's text alternative for screen readers.

Usage::

    from dynagrade.exercise.figure import arrow, ground, new_drawing

    def draw(p):
        figure, axes = new_drawing()
        ground(axes, 0.0, 2.0)
        arrow(axes, (0, 0), (1, 0.5), "$v_0$")
        describe(axes, "The ball leaves the ground at the left end.")
        return figure
"""

from __future__ import annotations

__all__ = ["Circle", "Ellipse", "Polygon", "Rectangle", "angle_arc", "arrow", "beam_support",
           "block", "ceiling", "damper", "describe", "dimension", "direction_words", "figure_notes",
           "ground", "inclined_plane", "new_drawing", "pivot", "simply_supported_beam", "spring",
           "wall"]


# -- the figure's description in words ------------------------------------------------------

NOTES_ATTRIBUTE = "dynagrade_notes"
_DIRECTIONS = ("to the right", "up and to the right", "up", "up and to the left",
               "to the left", "down and to the left", "down", "down and to the right")


def describe(axes, sentence: str) -> None:
    """Add ``sentence`` (what the figure shows that its labels do not say: a sense of
    travel, where an angle starts, which body moves) to the figure's text alternative."""
    _notes(axes)["author"].append(sentence.strip())


def figure_notes(figure) -> dict[str, list[str]]:
    """What the helpers drew (``"drawn"``) and the author's sentences (``"author"``)."""
    return getattr(figure, NOTES_ATTRIBUTE, {"author": [], "drawn": []})


def direction_words(dx: float, dy: float) -> str:
    """The direction of the vector (dx, dy) in words, to the nearest 45°."""
    import math

    sector = round(math.degrees(math.atan2(dy, dx)) / 45.0) % 8
    return _DIRECTIONS[sector]


def _notes(axes) -> dict[str, list[str]]:
    figure = axes.get_figure()
    if not hasattr(figure, NOTES_ATTRIBUTE):
        setattr(figure, NOTES_ATTRIBUTE, {"author": [], "drawn": []})
    return getattr(figure, NOTES_ATTRIBUTE)


def _drawn(axes, words: str) -> None:
    _notes(axes)["drawn"].append(words)


def _named(kind: str, label: str) -> str:
    return f"{kind} {label}" if label else kind


# -- drawing helpers for exercise figures ---------------------------------------------------


def new_drawing(width: float = 5.0, height: float = 3.0):
    """A drawing of ``width`` x ``height`` inches with one borderless axes of equal scale
    in x and y: ``(drawing, axes)``. The axes take matplotlib's drawing calls (``plot``,
    ``text``, ``annotate``, ``add_patch``, ``set_xlim`` …, see
    :mod:`dynagrade.exercise.drawing`) and record them; the SVG is written from the record
    (:func:`dynagrade.render.figures.figure_svg`)."""
    from .drawing import Drawing

    drawing = Drawing(width, height)
    return drawing, drawing.axes[0]


def __getattr__(name: str):
    """The shapes (:class:`Circle`, :class:`Ellipse`, :class:`Polygon`,
    :class:`Rectangle`), imported when first asked for: an exercise file that only names
    the helpers loads no drawing code until it draws."""
    if name in ("Circle", "Ellipse", "Polygon", "Rectangle"):
        from . import shapes

        return getattr(shapes, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def arrow(axes, start, end, label: str = "", offset=(0.0, 0.0), color="C0") -> None:
    """An arrow from ``start`` to ``end`` with ``label`` placed near its middle."""
    axes.annotate("", xy=end, xytext=start,
                  arrowprops={"arrowstyle": "-|>", "color": color, "lw": 1.5,
                              "shrinkA": 0, "shrinkB": 0})
    _drawn(axes, _named("an arrow", label) + " pointing "
           + direction_words(end[0] - start[0], end[1] - start[1]))
    if label:
        middle = ((start[0] + end[0]) / 2 + offset[0], (start[1] + end[1]) / 2 + offset[1])
        axes.text(*middle, label, color=color, ha="center", va="center", fontsize=10)


def angle_arc(axes, center, radius: float, start: float, end: float, label: str = "",
              label_radius: float | None = None) -> None:
    """A circular arc marking the angle from ``start`` to ``end`` (radians), labelled."""
    import numpy as np

    angles = np.linspace(start, end, 40)
    axes.plot(center[0] + radius * np.cos(angles), center[1] + radius * np.sin(angles),
              color="0.2", lw=0.8)
    sense = "counter-clockwise" if end > start else "clockwise"
    _drawn(axes, _named("an angle", label) + " measured from the direction pointing "
           f"{direction_words(np.cos(start), np.sin(start)).removeprefix('to the ')}, "
           f"turning {sense}")
    if label:
        middle = (start + end) / 2
        r = label_radius if label_radius is not None else radius * 1.45
        axes.text(center[0] + r * np.cos(middle), center[1] + r * np.sin(middle), label,
                  ha="center", va="center", fontsize=10)


def ground(axes, x_start: float, x_end: float, y: float = 0.0, hatch: float = 0.0) -> None:
    """A ground line from ``x_start`` to ``x_end`` with short hatch strokes below it."""
    import numpy as np

    axes.plot([x_start, x_end], [y, y], color="0.1", lw=1.2)
    size = hatch or (x_end - x_start) / 40
    starts = np.arange(x_start, x_end, size * 1.5)
    xs = np.column_stack([starts + size, starts, np.full_like(starts, np.nan)]).ravel()
    ys = np.tile([y, y - size, np.nan], len(starts))
    axes.plot(xs, ys, color="0.4", lw=0.6)
    _drawn(axes, "the ground")


def dimension(axes, start, end, label: str = "", offset: float = 0.0, tick: float = 0.0,
              side: float = 1.0) -> None:
    """A dimension line with arrow heads at both ends from ``start`` to ``end``, shifted by
    ``offset`` normal to it (to the left of start -> end for positive values), with thin
    extension lines back to the measured points and ``label`` beside its middle on the
    ``side`` (+1 left of start -> end, -1 right), ``tick`` away from the line and aligned
    so that it reaches away from it."""
    import numpy as np

    a, b = np.asarray(start, float), np.asarray(end, float)
    length = float(np.hypot(*(b - a)))
    normal = np.array([-(b - a)[1], (b - a)[0]]) / length
    shift = offset * normal
    slope = abs(float(np.degrees(np.arctan2(*(b - a)[::-1])))) % 180
    way = "horizontal" if min(slope, 180 - slope) < 5 else \
        "vertical" if abs(slope - 90) < 5 else "slanted"
    _drawn(axes, _named(f"a {way} dimension line", label))
    if offset:
        for point in (a, b):
            axes.plot(*zip(point, point + shift + 0.04 * length * np.sign(offset) * normal),
                      color="0.5", lw=0.5)
    axes.annotate("", xy=tuple(b + shift), xytext=tuple(a + shift),
                  arrowprops={"arrowstyle": "<|-|>", "color": "0.2", "lw": 0.8,
                              "shrinkA": 0, "shrinkB": 0, "mutation_scale": 8})
    if label:
        away = side * normal
        middle = (a + b) / 2 + shift + (tick or 0.03 * length) * away
        ha = "left" if away[0] > 0.38 else "right" if away[0] < -0.38 else "center"
        va = "bottom" if away[1] > 0.38 else "top" if away[1] < -0.38 else "center"
        axes.text(*middle, label, fontsize=10, ha=ha, va=va)


def spring(axes, start, end, coils: int = 6, width: float | None = None,
           color="0.1") -> None:
    """A linear spring drawn as a zig-zag from ``start`` to ``end``: straight leads of a
    sixth of the length at each end and ``coils`` zig-zags of ``width`` between (a fifth
    of the length unless given)."""
    import numpy as np

    a, b = np.asarray(start, float), np.asarray(end, float)
    length = float(np.hypot(*(b - a)))
    along, normal = (b - a) / length, np.array([-(b - a)[1], (b - a)[0]]) / length
    width = width if width is not None else length / 5
    s = np.linspace(length / 6, 5 * length / 6, 2 * coils + 1)
    side = np.zeros_like(s)
    side[1:-1:2], side[2:-1:2] = 0.5 * width, -0.5 * width
    s, side = np.concatenate([[0.0], s, [length]]), np.concatenate([[0.0], side, [0.0]])
    points = a + np.outer(s, along) + np.outer(side, normal)
    axes.plot(points[:, 0], points[:, 1], color=color, lw=1.0)
    _drawn(axes, "a spring running " + direction_words(*(b - a)))


def damper(axes, start, end, width: float | None = None, color="0.1") -> None:
    """A viscous damper (dashpot) from ``start`` to ``end``: an open cylinder of ``width``
    (a quarter of the length unless given) on the start side and the piston on the end side."""
    import numpy as np

    a, b = np.asarray(start, float), np.asarray(end, float)
    length = float(np.hypot(*(b - a)))
    along, normal = (b - a) / length, np.array([-(b - a)[1], (b - a)[0]]) / length
    half = 0.5 * (width if width is not None else length / 4)

    def at(s, n):
        return a + s * along + n * normal

    bottom, top = 0.3 * length, 0.75 * length
    cylinder = [at(top, half), at(bottom, half), at(bottom, -half), at(top, -half)]
    axes.plot(*zip(a, at(bottom, 0.0)), color=color, lw=1.0)
    axes.plot(*zip(*cylinder), color=color, lw=1.0)
    axes.plot(*zip(at(0.55 * length, 0.75 * half), at(0.55 * length, -0.75 * half)),
              color=color, lw=1.6)
    axes.plot(*zip(at(0.55 * length, 0.0), b), color=color, lw=1.0)
    _drawn(axes, "a damper running " + direction_words(*(b - a)))


def wall(axes, x: float, y_start: float, y_end: float, side: float = -1.0,
         hatch: float = 0.0) -> None:
    """A vertical wall at ``x`` from ``y_start`` to ``y_end`` with short hatch strokes on
    its ``side`` (-1 left of the line, +1 right), the counterpart of :func:`ground`."""
    import numpy as np

    axes.plot([x, x], [y_start, y_end], color="0.1", lw=1.2)
    size = hatch or (y_end - y_start) / 20
    starts = np.arange(y_start, y_end, size * 1.5)
    xs = np.tile([x, x + side * size, np.nan], len(starts))
    ys = np.column_stack([starts + size, starts, np.full_like(starts, np.nan)]).ravel()
    axes.plot(xs, ys, color="0.4", lw=0.6)
    _drawn(axes, "a wall")


def block(axes, center, width: float, height: float, label: str = "", angle: float = 0.0,
          color="C0") -> None:
    """A rigid block: a ``width`` x ``height`` rectangle centred at ``center``, turned by
    ``angle`` (rad, counter-clockwise), with ``label`` written inside."""
    import numpy as np

    from .shapes import Polygon

    c, s = np.cos(angle), np.sin(angle)
    corners = [(-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5)]
    points = [(center[0] + c * u * width - s * v * height,
               center[1] + s * u * width + c * v * height) for u, v in corners]
    axes.add_patch(Polygon(points, closed=True, facecolor=color, edgecolor="0.1", lw=1.0))
    _drawn(axes, _named("a block", label))
    if label:
        axes.text(center[0], center[1], label, color=_label_colour(color), ha="center",
                  va="center", fontsize=9, rotation=np.degrees(angle),
                  rotation_mode="anchor")


def _label_colour(face) -> str:
    """White or black, whichever contrasts more with the colour ``face`` (WCAG 2.1
    relative luminance), for a label written on it."""
    from .colours import to_rgb

    def linear(c):
        return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4

    red, green, blue = (linear(c) for c in to_rgb(face))
    luminance = 0.2126 * red + 0.7152 * green + 0.0722 * blue
    return "white" if 1.05 / (luminance + 0.05) >= (luminance + 0.05) / 0.05 else "black"


def pivot(axes, point, size: float) -> None:
    """A fixed pin support at ``point``: the pin as a small circle on a triangle of height
    ``size`` hanging from a hatched base above it (for bodies hanging from the pin)."""
    import numpy as np

    from .shapes import Circle, Polygon

    x, y = point
    axes.add_patch(Polygon([(x, y), (x - 0.6 * size, y + size), (x + 0.6 * size, y + size)],
                           closed=True, facecolor="0.85", edgecolor="0.1", lw=1.0))
    top, step = y + size, 0.25 * size
    axes.plot([x - size, x + size], [top, top], color="0.1", lw=1.2)
    starts = np.arange(x - size, x + size, 1.5 * step)
    xs = np.column_stack([starts, starts + step, np.full_like(starts, np.nan)]).ravel()
    ys = np.tile([top, top + step, np.nan], len(starts))
    axes.plot(xs, ys, color="0.4", lw=0.6)
    axes.add_patch(Circle((x, y), 0.18 * size, facecolor="white", edgecolor="0.1", lw=1.0,
                          zorder=3))
    _drawn(axes, "a fixed pin support")


def ceiling(axes, x_start: float, x_end: float, y: float, hatch: float = 0.0) -> None:
    """A ceiling line from ``x_start`` to ``x_end`` at ``y`` with short hatch strokes above
    it, the counterpart of :func:`ground` for bodies hanging from it."""
    import numpy as np

    axes.plot([x_start, x_end], [y, y], color="0.1", lw=1.2)
    size = hatch or (x_end - x_start) / 40
    starts = np.arange(x_start, x_end, size * 1.5)
    xs = np.column_stack([starts, starts + size, np.full_like(starts, np.nan)]).ravel()
    ys = np.tile([y, y + size, np.nan], len(starts))
    axes.plot(xs, ys, color="0.4", lw=0.6)
    _drawn(axes, "a ceiling")


def inclined_plane(alpha: float, length: float = 1.0):
    """A new drawing of a wedge rising at ``alpha`` (rad) over ``length``, on hatched
    ground, its angle marked and labelled in degrees.

    Returns ``(figure, axes, along, normal)``: the unit vectors up the slope and normal
    to it, for placing a block or labels on the slope. The caller sets the y-limits."""
    import numpy as np

    from .numbers import format_number
    from .shapes import Polygon

    along = np.array([np.cos(alpha), np.sin(alpha)])
    normal = np.array([-np.sin(alpha), np.cos(alpha)])
    figure, axes = new_drawing(5.0, 1.2 + 3.0 * np.sin(alpha))
    top = length * along
    axes.add_patch(Polygon([(0, 0), (top[0], 0), tuple(top)], closed=True,
                           facecolor="0.9", edgecolor="0.1", lw=1.2))
    _drawn(axes, "a wedge rising to the right")
    ground(axes, -0.1, top[0] + 0.1, hatch=0.02)
    angle_arc(axes, (0.0, 0.0), 0.14, 0.0, alpha,
              f"α = {format_number(np.degrees(alpha))}°", label_radius=0.3)
    axes.set_xlim(-0.12, top[0] + 0.12)
    return figure, axes, along, normal


# -- beam supports (chapter 5's beams and rods) ----------------------------------------------

def beam_support(axes, point, size: float, roller: bool = False) -> None:
    """A support under a beam at ``point``: a triangle of height ``size`` standing on
    hatched ground, a fixed pin, or with ``roller=True`` a triangle on two small wheels
    (free to slide along the beam). A clamped end is a :func:`wall`."""
    from .shapes import Circle, Polygon

    x, y = point
    high = 0.75 * size if roller else size
    axes.add_patch(Polygon([(x, y), (x - 0.6 * size, y - high), (x + 0.6 * size, y - high)],
                           closed=True, facecolor="0.85", edgecolor="0.1", lw=1.0))
    if roller:
        r = 0.125 * size
        for dx in (-0.3 * size, 0.3 * size):
            axes.add_patch(Circle((x + dx, y - high - r), r, facecolor="white",
                                  edgecolor="0.1", lw=0.8))
    ground(axes, x - size, x + size, y - size, hatch=0.25 * size)
    _drawn(axes, "a roller support under the beam" if roller else "a fixed pin support under the beam")


def simply_supported_beam(axes, length: float, thickness: float, label: str = "") -> None:
    """A beam of ``length`` and drawn ``thickness`` from x = 0, centred on y = 0, on a pin
    at its left end and a roller at its right one, with its length dimensioned below and
    labelled ``label``."""
    block(axes, (length / 2, 0.0), length, thickness, color="0.7")
    beam_support(axes, (0.0, -thickness / 2), 0.06 * length)
    beam_support(axes, (length, -thickness / 2), 0.06 * length, roller=True)
    dimension(axes, (0.0, -0.1 * length), (length, -0.1 * length), label, tick=0.01 * length,
              side=-1.0)
