"""A variant's figure as SVG text, the same bytes on every run.

The exercise's ``figure(p)`` (drawn with :mod:`dynagrade.exercise.figure`) gives a
recorded drawing, written straight to SVG by :mod:`dynagrade.render.svg_figure` (labels
as SVG text). A figure function that returns a matplotlib figure instead (a real plot)
is rendered with matplotlib's SVG writer (the Agg backend selected, no display needed), a
fixed hash salt (so element ids do not change from run to run), glyphs as paths and no
date in the metadata. Either way the SVG is an image with a title (the exercise's title)
and a description in words (:mod:`dynagrade.render.accessible_svg`).

Usage::

    svg = figure_svg(exercise, variant)    # str, or None when the exercise has no figure
    html = inline_svg(svg, "figure-2-")    # without the XML header, ids prefixed, to embed
"""

from __future__ import annotations

import io
import re
from typing import TYPE_CHECKING

from ..exercise.drawing import Drawing
from ..exercise.figure_checks import reported_figure_failure
from ..exercise.model import Exercise, Variant
from .accessible_svg import accessible_svg, figure_description, prefixed_ids
from .svg_figure import drawing_svg

if TYPE_CHECKING:
    from matplotlib.typing import RcKeyType

#: matplotlib's settings (rcParams) for an SVG that is the same on every run
SVG_SETTINGS: dict[RcKeyType, object] = {"svg.hashsalt": "dynagrade", "svg.fonttype": "path", "svg.image_inline": True,
                "path.simplify": False}
#: the margin (inches) around the cropped figure
PAD_INCHES = 0.04
_HEADER = re.compile(r"^\s*<\?xml[^>]*>\s*(<!DOCTYPE[^>]*>\s*)?", re.S)


def figure_svg(exercise: Exercise, variant: Variant) -> str | None:
    """The variant's figure as a standalone SVG document, or ``None`` without a figure.
    A figure function that fails raises a one-line
    :class:`~dynagrade.exercise.figure_checks.FigureError` (exercise, file, line)."""
    if exercise.figure is None:
        return None
    with reported_figure_failure(exercise, variant.seed):
        figure = exercise.figure(exercise.si(variant.params))
        if isinstance(figure, Drawing):
            svg = drawing_svg(figure)
        else:
            svg = matplotlib_svg(figure)
        return accessible_svg(svg, figure_title(exercise), figure_description(figure))


def matplotlib_svg(figure) -> str:
    """A matplotlib figure (a plot) as SVG, cropped to what is drawn on it."""
    import sys

    import matplotlib

    if "matplotlib.pyplot" not in sys.modules:
        matplotlib.use("Agg")
    buffer = io.StringIO()
    with matplotlib.rc_context(SVG_SETTINGS):
        figure.savefig(buffer, format="svg", bbox_inches=tight_box(figure, PAD_INCHES),
                       metadata={"Date": None, "Creator": "dynagrade"})
    _close(figure)
    return buffer.getvalue()


def tight_box(figure, pad: float):
    """The box (inches) around everything drawn on ``figure``, labels reaching past the
    axes included, widened by ``pad``: what ``savefig(bbox_inches="tight")`` crops to,
    measured as the SVG writer measures text (at 72 dpi) but without the extra pass
    through every artist that matplotlib's "tight" makes before the real one."""
    from matplotlib.backends.backend_mixed import MixedModeRenderer
    from matplotlib.backends.backend_svg import RendererSVG

    dpi = figure.dpi
    width, height = figure.get_size_inches()
    figure.dpi = 72
    try:
        renderer = MixedModeRenderer(figure, width, height, dpi,
                                     RendererSVG(width * 72, height * 72, io.StringIO(),
                                                 image_dpi=dpi))
        return figure.get_tightbbox(renderer).padded(pad)
    finally:
        figure.dpi = dpi


def figure_title(exercise: Exercise) -> str:
    """The name of an exercise's figure, as a screen reader announces it: whether it is
    drawn to scale is the exercise's ``figure_to_scale``."""
    return f"{exercise.title}: figure, {scale_phrase(exercise.figure_to_scale)}"


def scale_phrase(to_scale: bool) -> str:
    """What a caption says of a figure's scale: "drawn to scale" only for a figure whose
    exercise declares ``figure_to_scale=True``."""
    return "drawn to scale" if to_scale else "schematic, not to scale"


def inline_svg(svg: str, id_prefix: str = "") -> str:
    """An SVG document without its XML declaration and DOCTYPE, to embed in HTML, its ids
    starting with ``id_prefix`` (give each figure of a page its own)."""
    return prefixed_ids(_HEADER.sub("", svg, count=1), id_prefix)


def _close(figure) -> None:
    """Release a figure made with pyplot (a plain ``Figure`` needs nothing)."""
    import sys

    pyplot = sys.modules.get("matplotlib.pyplot")
    if pyplot is not None:
        pyplot.close(figure)

