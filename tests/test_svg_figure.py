"""A drawing is written straight to SVG laid out as matplotlib laid out the same calls:
equal scale filling 98 % of the figure, sizes in points, dashes scaled with the line
width, arrow heads at the tips, labels anchored as ``ha``/``va`` say; and a figure
function that returns a matplotlib figure (a real plot) is still rendered."""

from __future__ import annotations

import dataclasses
import math
import re
import xml.etree.ElementTree as ET

import pytest

from dynagrade.errors import DefinitionError
from dynagrade.exercise.figure import Circle, new_drawing
from dynagrade.render.figures import PAD_INCHES, SVG_SETTINGS, figure_svg, tight_box
from dynagrade.render.svg_figure import drawing_svg
from deferred import deferred

matplotlib = deferred("matplotlib")
SVG = "{http://www.w3.org/2000/svg}"


def _root(drawing):
    return ET.fromstring(drawing_svg(drawing).encode())


def _path_points(d: str) -> list[tuple[float, float]]:
    return [(float(x), float(y)) for x, y in re.findall(r"[ML](-?[\d.]+) (-?[\d.]+)", d)]


def _wide_drawing():
    """5 x 3 inches, x from 0 to 10 and y from 0 to 2: the axes box is 352.8 x 211.68 pt,
    so x limits the scale to 352.8 / 10 = 35.28 pt per unit, and the 70.56 pt high axes
    sit centred: from y = 216 - 0.01 * 216 - (211.68 - 70.56) / 2 = 143.28 up to 72.72."""
    drawing, axes = new_drawing(5.0, 3.0)
    axes.set_xlim(0.0, 10.0)
    axes.set_ylim(0.0, 2.0)
    return drawing, axes


def test_data_are_drawn_at_equal_scale_in_points():
    drawing, axes = _wide_drawing()
    axes.plot([0.0, 10.0, 10.0], [0.0, 0.0, 2.0], color="0.1", lw=1.2)
    path = _root(drawing).find(f".//{SVG}path")
    drawn = [coordinate for point in _path_points(path.get("d")) for coordinate in point]
    # pytest.approx compares flat sequences only: the points as x0, y0, x1, y1, ...
    assert drawn == pytest.approx([3.6, 143.28, 356.4, 143.28, 356.4, 72.72], abs=0.006)
    assert (path.get("stroke"), path.get("stroke-width")) == ("#1a1a1a", "1.2")


def test_the_picture_is_cropped_to_the_axes_plus_the_pad():
    drawing, axes = _wide_drawing()
    root = _root(drawing)
    x, y, width, height = (float(v) for v in root.get("viewBox").split())
    pad = 0.04 * 72
    assert (x, y) == pytest.approx((3.6 - pad, 72.72 - pad), abs=0.006)
    assert (width, height) == pytest.approx((352.8 + 2 * pad, 70.56 + 2 * pad), abs=0.01)
    assert root.get("width") == f"{width:g}pt"


def test_dashes_scale_with_the_line_width_as_matplotlibs_do():
    drawing, axes = _wide_drawing()
    axes.plot([0, 1], [0, 0], "--", lw=2.0)
    axes.plot([0, 1], [1, 1], ls=":", lw=1.0)
    dashes = [p.get("stroke-dasharray") for p in _root(drawing).iter(f"{SVG}path")]
    assert dashes[:2] == ["7.4,3.2", "1,1.65"]      # (3.7, 1.6) x 2 and (1, 1.65) x 1


def test_a_label_is_anchored_where_ha_and_va_say():
    """A 10 pt label with va="top" has its baseline 7.6 pt (DejaVu Sans' ascent) below
    the point; ha="right" ends it there."""
    drawing, axes = _wide_drawing()
    axes.text(5.0, 1.0, "m", ha="right", va="top")
    text = _root(drawing).find(f".//{SVG}text")
    assert float(text.get("x")) == pytest.approx(3.6 + 5 * 35.28, abs=0.006)
    assert float(text.get("y")) == pytest.approx(108.0 + 7.6, abs=0.006)
    assert text.get("text-anchor") == "end" and text.text == "m"


def test_an_arrow_ends_in_a_head_whose_tip_is_the_end_point():
    drawing, axes = _wide_drawing()
    axes.annotate("", xy=(10.0, 0.0), xytext=(0.0, 0.0),
                  arrowprops={"arrowstyle": "-|>", "color": "C3", "lw": 1.5,
                              "shrinkA": 0, "shrinkB": 0})
    root = _root(drawing)
    head = root.find(f".//{SVG}polygon").get("points").split()
    tip, *base = [tuple(float(v) for v in p.split(",")) for p in head]
    assert tip == pytest.approx((356.4, 143.28), abs=0.006)
    # 4 pt long and 4 pt wide at the default size of 10 pt
    assert [b[0] for b in base] == pytest.approx([352.4, 352.4], abs=0.006)
    assert abs(base[0][1] - base[1][1]) == pytest.approx(4.0, abs=0.01)
    line = _path_points(root.find(f".//{SVG}path").get("d"))
    assert line[-1][0] == pytest.approx(352.4, abs=0.006)   # the line stops at the head


def test_a_bent_arrow_bows_to_the_right_of_its_travel_for_a_positive_radius():
    """matplotlib's arc3 puts the control point rad x (dy, -dx) off the middle: for an
    arrow travelling in +x that is below it (larger y in the SVG)."""
    drawing, axes = _wide_drawing()
    axes.annotate("", xy=(10.0, 1.0), xytext=(0.0, 1.0),
                  arrowprops={"arrowstyle": "-|>", "connectionstyle": "arc3,rad=0.2",
                              "shrinkA": 0, "shrinkB": 0})
    d = _root(drawing).find(f".//{SVG}path").get("d")
    control_y = float(re.search(r"Q(-?[\d.]+) (-?[\d.]+)", d).group(2))
    assert control_y == pytest.approx(108.0 + 0.2 * 352.8, abs=0.006)


def test_shapes_under_lines_under_labels_unless_a_zorder_says_otherwise():
    drawing, axes = _wide_drawing()
    axes.text(1.0, 1.0, "label")
    axes.plot([0, 1], [0, 1])
    axes.add_patch(Circle((5.0, 1.0), 0.5))
    axes.add_patch(Circle((6.0, 1.0), 0.5, zorder=4))
    axes.add_patch(Circle((7.0, 1.0), 0.5, zorder=3))      # a label's zorder: under it
    radii = [(e.tag.removeprefix(SVG), e.get("cx")) for e in _root(drawing).find(f"{SVG}g")]
    assert radii == [("circle", "180"), ("path", None), ("circle", "250.56"), ("text", None),
                     ("circle", "215.28")]


def test_a_matplotlib_circle_is_drawn_like_the_drawings_own():
    patches = deferred("matplotlib.patches")
    drawing, axes = _wide_drawing()
    axes.add_patch(patches.Circle((5.0, 1.0), 0.5, facecolor="white", edgecolor="0.1"))
    own, own_axes = _wide_drawing()
    own_axes.add_patch(Circle((5.0, 1.0), 0.5, facecolor="white", edgecolor="0.1"))
    assert drawing_svg(drawing) == drawing_svg(own)
    assert 'r="17.64"' in drawing_svg(own)                   # 0.5 x 35.28 pt


def test_a_keyword_the_drawing_does_not_know_is_an_error_naming_it():
    _, axes = _wide_drawing()
    with pytest.raises(DefinitionError, match="'alpha'"):
        axes.plot([0, 1], [0, 1], alpha=0.5)
    with pytest.raises(DefinitionError, match="'C11'"):
        drawing_svg(_with_colour("C11"))


def _with_colour(colour):
    drawing, axes = _wide_drawing()
    axes.plot([0, 1], [0, 1], color=colour)
    return drawing


def test_a_figure_that_returns_a_matplotlib_plot_is_rendered_by_matplotlib(bank):
    """A real plot (a matplotlib figure) still renders, cropped as matplotlib's tight box."""
    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    def plot(p):
        figure = Figure(figsize=(4.0, 2.0))
        axes = figure.add_axes((0.1, 0.1, 0.8, 0.8))
        axes.plot([0, 1, 2], [0, p.v0, 0])
        return figure

    exercise = dataclasses.replace(bank.get("projectile-range"), figure=plot)
    svg = figure_svg(exercise, exercise.variant(0))
    root = ET.fromstring(svg.encode())
    assert root.get("role") == "img" and svg == figure_svg(exercise, exercise.variant(0))


def test_the_crop_of_a_plot_is_the_box_matplotlibs_own_tight_crop_gives():
    """A label far right of the axes stays in the picture: the box measured in one pass
    is the one matplotlib's two-pass ``bbox_inches="tight"`` writes into the SVG."""
    import io

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    figure = Figure(figsize=(4.0, 2.0))
    axes = figure.add_axes((0.01, 0.01, 0.98, 0.98))
    axes.plot([0.0, 1.0], [0.0, 0.0])
    axes.text(1.6, 0.5, "$F_{far}$ a label past the axes", ha="left")
    axes.set_xlim(0.0, 1.0)
    axes.set_ylim(-0.1, 1.0)
    buffer = io.StringIO()
    with matplotlib.rc_context(SVG_SETTINGS):
        figure.savefig(buffer, format="svg", bbox_inches="tight", pad_inches=PAD_INCHES)
        box = tight_box(figure, PAD_INCHES)
    width, height = (float(re.search(rf'{name}="([\d.]+)pt"', buffer.getvalue()).group(1))
                     for name in ("width", "height"))
    assert box.width * 72 == pytest.approx(width, abs=1e-5)
    assert box.height * 72 == pytest.approx(height, abs=1e-5)
    assert box.width > 4.0 and math.isfinite(box.height)


def test_a_figure_paints_with_attributes_that_a_pages_csp_lets_through():
    """The server's pages allow no inline style (docs/serve.md, "Deployment"): every
    line, marker, shape, label and arrow is painted with presentation attributes."""
    drawing, axes = _wide_drawing()
    axes.plot([0, 1], [0, 1], "o--", color="C1", lw=1.5)
    axes.add_patch(Circle((5.0, 1.0), 0.5, facecolor="0.8", edgecolor="k"))
    axes.text(2.0, 1.0, "m = 2 kg", color="C2")
    axes.annotate("", xy=(10.0, 0.0), xytext=(0.0, 0.0), arrowprops={"arrowstyle": "-|>"})
    root = _root(drawing)
    painted = [e for e in root.iter() if e.get("fill") or e.get("stroke")]
    assert {e.tag.split("}")[1] for e in painted} >= {"path", "circle", "text", "polygon"}
    assert not [e.tag for e in root.iter() if "style" in e.attrib]
