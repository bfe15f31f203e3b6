"""A variant's figure as SVG text, the same bytes on every run.

An exercise may declare ``figure=draw``, where ``draw(p)`` receives the parameters in SI
and returns a :class:`matplotlib.figure.Figure` drawn to scale. This module renders it
with matplotlib's SVG writer (the Agg backend selected, no display needed), a fixed hash salt (so element ids do not change from run
to run), glyphs as paths (so every viewer, typst included, shows the same letters) and no
date in the metadata.

Usage::

    svg = figure_svg(exercise, variant)    # str, or None when the exercise has no figure
"""

from __future__ import annotations

import io
import re

from .model import Exercise, Variant

SVG_SETTINGS = {"svg.hashsalt": "dynagrade", "svg.fonttype": "path", "svg.image_inline": True,
                "path.simplify": False}
_HEADER = re.compile(r"^\s*<\?xml[^>]*>\s*(<!DOCTYPE[^>]*>\s*)?", re.S)


def figure_svg(exercise: Exercise, variant: Variant) -> str | None:
    """The variant's figure as a standalone SVG document, or ``None`` without a figure."""
    if exercise.figure is None:
        return None
    import sys

    import matplotlib

    if "matplotlib.pyplot" not in sys.modules:
        matplotlib.use("Agg")
    figure = exercise.figure(exercise.si(variant.params))
    buffer = io.StringIO()
    with matplotlib.rc_context(SVG_SETTINGS):
        # "tight" keeps labels that reach past the axes in the picture
        figure.savefig(buffer, format="svg", bbox_inches="tight", pad_inches=0.04,
                       metadata={"Date": None, "Creator": "dynagrade"})
    _close(figure)
    return buffer.getvalue()


def inline_svg(svg: str) -> str:
    """An SVG document without its XML declaration and DOCTYPE, to embed in HTML."""
    return _HEADER.sub("", svg, count=1)


def _close(figure) -> None:
    """Release a figure made with pyplot (a plain ``Figure`` needs nothing)."""
    import sys

    pyplot = sys.modules.get("matplotlib.pyplot")
    if pyplot is not None:
        pyplot.close(figure)


# -- drawing helpers for exercise figures ---------------------------------------------------


def new_drawing(width: float = 5.0, height: float = 3.0):
    """A figure with one borderless axes of equal scale in x and y: ``(figure, axes)``.

    Built as a plain :class:`matplotlib.figure.Figure` (no pyplot state to leak)."""
    from matplotlib.figure import Figure

    figure = Figure(figsize=(width, height))
    axes = figure.add_axes((0.01, 0.01, 0.98, 0.98))
    axes.set_aspect("equal")
    axes.set_axis_off()
    return figure, axes


def arrow(axes, start, end, label: str = "", offset=(0.0, 0.0), color="C0") -> None:
    """An arrow from ``start`` to ``end`` with ``label`` placed near its middle."""
    axes.annotate("", xy=end, xytext=start,
                  arrowprops={"arrowstyle": "-|>", "color": color, "lw": 1.5,
                              "shrinkA": 0, "shrinkB": 0})
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
