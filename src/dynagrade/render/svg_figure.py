"""A recorded drawing (:mod:`dynagrade.exercise.drawing`) written straight to SVG.

The drawing is laid out as matplotlib laid out the same calls, so figures keep their
look: a ``width`` x ``height`` inch figure whose axes fill 98 % of it, shrunk to equal
scale in x and y and centred; lines and shapes clipped to the axes; line widths, marker
and font sizes in points (one SVG unit is one point); dashes scaled with the line width;
patches under lines under text unless a zorder says otherwise. Labels are SVG text
(:mod:`dynagrade.render.svg_text`) measured with DejaVu Sans' widths
(:mod:`dynagrade.render.text_metrics`); the picture is cropped to the axes and every
label and arrow, plus :data:`PAD` points. Numbers are written with two decimals and
nothing else varies, so the same drawing gives the same bytes.

Usage::

    svg = drawing_svg(drawing)          # a standalone SVG document
"""

from __future__ import annotations

import math

from ..exercise.colours import to_hex
from ..exercise.drawing import Arrow, Drawing, Label, Line
from ..exercise.shapes import Circle, Ellipse, Polygon
from .svg_text import label_runs, label_width, svg_tspans
from .text_metrics import ASCENT, DESCENT

#: the margin (pt) around everything drawn: matplotlib's 0.04 inch
PAD = 0.04 * 72
#: where the axes sit in the figure (fractions of width and height), as new_drawing had them
AXES_BOX = (0.01, 0.01, 0.98, 0.98)
FONT_FAMILY = "DejaVu Sans, Verdana, Arial, Helvetica, sans-serif"
CLIP_ID = "figure-clip"
#: matplotlib's dash patterns, in multiples of the line width
DASHES = {"--": (3.7, 1.6), ":": (1.0, 1.65), "-.": (6.4, 1.6, 1.0, 1.6)}
CAPS = {"projecting": "square", "round": "round", "butt": "butt"}
#: a filled arrow head's length and half-width, in multiples of the arrow's head size
HEAD_LENGTH, HEAD_HALF_WIDTH = 0.4, 0.2


def number(value: float) -> str:
    """``value`` with at most two decimals and no trailing zeros (``-0`` as ``0``)."""
    text = f"{value:.2f}".rstrip("0").rstrip(".")
    return "0" if text in ("", "-0") else text


class _Frame:
    """Data coordinates to SVG points for one drawing, and the running extent of what
    has been placed outside the clip (labels, arrows)."""

    def __init__(self, drawing: Drawing):
        canvas = drawing.axes[0]
        self.height = drawing.height * 72
        (x0, x1), (y0, y1) = canvas.get_xlim(), canvas.get_ylim()
        box_w, box_h = AXES_BOX[2] * drawing.width * 72, AXES_BOX[3] * self.height
        self.scale = min(box_w / (x1 - x0), box_h / (y1 - y0))
        width, height = self.scale * (x1 - x0), self.scale * (y1 - y0)
        self.left = AXES_BOX[0] * drawing.width * 72 + (box_w - width) / 2
        self.bottom = AXES_BOX[1] * self.height + (box_h - height) / 2
        self.x0, self.y0 = x0, y0
        top = self.height - self.bottom - height
        self.clip = (self.left, top, width, height)
        self.extent = [self.left, top, self.left + width, top + height]

    def point(self, x: float, y: float) -> tuple[float, float]:
        return (self.left + self.scale * (x - self.x0),
                self.height - (self.bottom + self.scale * (y - self.y0)))

    def include(self, x: float, y: float) -> None:
        self.extent[0], self.extent[1] = min(self.extent[0], x), min(self.extent[1], y)
        self.extent[2], self.extent[3] = max(self.extent[2], x), max(self.extent[3], y)


def drawing_svg(drawing: Drawing) -> str:
    """The drawing as a standalone SVG document (no title or description yet)."""
    frame = _Frame(drawing)
    body = []
    for item in drawing.axes[0].drawn():
        if isinstance(item, Line):
            body.append(_line(item, frame))
        elif isinstance(item, Label):
            body.append(_label(item, frame))
        elif isinstance(item, Arrow):
            body.append(_arrow(item, frame))
        else:
            body.append(_shape(item, frame))
    for label in drawing.texts:
        body.append(_label(label, frame))
    x0, y0, x1, y1 = frame.extent
    x0, y0, x1, y1 = x0 - PAD, y0 - PAD, x1 + PAD, y1 + PAD
    cx, cy, cw, ch = frame.clip
    return ('<?xml version="1.0" encoding="utf-8" standalone="no"?>\n'
            f'<svg xmlns="http://www.w3.org/2000/svg" version="1.1" '
            f'width="{number(x1 - x0)}pt" height="{number(y1 - y0)}pt" '
            f'viewBox="{number(x0)} {number(y0)} {number(x1 - x0)} {number(y1 - y0)}">\n'
            f' <defs><clipPath id="{CLIP_ID}"><rect x="{number(cx)}" y="{number(cy)}" '
            f'width="{number(cw)}" height="{number(ch)}"/></clipPath></defs>\n'
            f' <g font-family="{FONT_FAMILY}" stroke-linejoin="round">\n'
            + "".join(f"  {element}\n" for element in body if element)
            + " </g>\n</svg>\n")


def _stroke(colour, width: float, style: str = "-") -> dict[str, str]:
    paint = {"stroke": to_hex(colour), "stroke-width": number(width)}
    if style in DASHES:
        paint["stroke-dasharray"] = ",".join(number(d * width) for d in DASHES[style])
    return paint


def _paint(presentation: dict[str, str]) -> str:
    """``presentation`` as SVG presentation attributes (``fill="none" stroke="#000"``),
    never a ``style`` attribute, which a page's Content-Security-Policy would refuse."""
    return " ".join(f'{name}="{value}"' for name, value in presentation.items())


def _line(line: Line, frame: _Frame) -> str:
    elements = []
    if line.style and line.width > 0:
        commands, pen_down = [], False
        for x, y in zip(line.x, line.y):
            if math.isnan(x) or math.isnan(y):
                pen_down = False
                continue
            px, py = frame.point(x, y)
            commands.append(f"{'L' if pen_down else 'M'}{number(px)} {number(py)}")
            pen_down = True
        if commands:
            paint = {"fill": "none", **_stroke(line.colour, line.width, line.style),
                     "stroke-linecap": CAPS.get(line.capstyle, "square")}
            elements.append(f'<path d="{" ".join(commands)}" {_paint(paint)} '
                            f'clip-path="url(#{CLIP_ID})"/>')
    if line.marker:
        colour = to_hex(line.colour)
        for x, y in zip(line.x, line.y):
            if not (math.isnan(x) or math.isnan(y)):
                elements.append(_marker(line.marker, *frame.point(x, y), line.marker_size,
                                        colour))
    return "\n  ".join(elements)


def _marker(kind: str, x: float, y: float, size: float, colour: str) -> str:
    attributes = (f'{_paint({"fill": colour, "stroke": colour, "stroke-width": "1"})} '
                  f'clip-path="url(#{CLIP_ID})"')
    half = size / 2
    if kind in "o.":
        radius = half if kind == "o" else half / 2
        return f'<circle cx="{number(x)}" cy="{number(y)}" r="{number(radius)}" {attributes}/>'
    if kind == "s":
        return (f'<rect x="{number(x - half)}" y="{number(y - half)}" width="{number(size)}" '
                f'height="{number(size)}" {attributes}/>')
    corners = {"^": ((0, -1), (-1, 1), (1, 1)), "v": ((0, 1), (-1, -1), (1, -1)),
               "D": ((0, -1), (1, 0), (0, 1), (-1, 0))}[kind]
    points = " ".join(f"{number(x + half * u)},{number(y + half * v)}" for u, v in corners)
    return f'<polygon points="{points}" {attributes}/>'


def _shape(shape, frame: _Frame) -> str:
    fill = to_hex(shape.facecolor) if shape.facecolor is not None else "none"
    stroke = (_stroke(shape.edgecolor, shape.linewidth, shape.linestyle)
              if shape.edgecolor is not None and shape.linewidth > 0 else {"stroke": "none"})
    paint = {"fill": fill, **stroke, "stroke-linejoin": "miter"}
    attributes = f'{_paint(paint)} clip-path="url(#{CLIP_ID})"'
    if isinstance(shape, Ellipse):
        cx, cy = frame.point(*shape.center)
        rx, ry = shape.width / 2 * frame.scale, shape.height / 2 * frame.scale
        if isinstance(shape, Circle) or rx == ry:
            return (f'<circle cx="{number(cx)}" cy="{number(cy)}" r="{number(rx)}" '
                    f'{attributes}/>')
        turn = f' transform="rotate({number(-shape.angle)} {number(cx)} {number(cy)})"' \
            if shape.angle else ""
        return (f'<ellipse cx="{number(cx)}" cy="{number(cy)}" rx="{number(rx)}" '
                f'ry="{number(ry)}"{turn} {attributes}/>')
    if isinstance(shape, Polygon):
        points = " ".join(f"{number(px)},{number(py)}"
                          for px, py in (frame.point(x, y) for x, y in shape.points))
        tag = "polygon" if shape.closed else "polyline"
        return f'<{tag} points="{points}" {attributes}/>'
    raise TypeError(f"cannot draw {type(shape).__name__}")


def _label(label: Label, frame: _Frame) -> str:
    runs = label_runs(label.text)
    if not runs:
        return ""
    x, y = frame.point(label.x, label.y)
    size = label.size
    width = label_width(runs, size)
    start = {"left": 0.0, "center": -width / 2, "right": -width}[label.ha]
    baseline = {"top": ASCENT * size, "center": (ASCENT - DESCENT) / 2 * size,
                "bottom": -DESCENT * size}.get(label.va, 0.0)
    turn = math.radians(label.rotation)
    cos, sin = math.cos(turn), math.sin(turn)
    for u in (start, start + width):
        for v in (baseline - ASCENT * size, baseline + DESCENT * size):
            frame.include(x + u * cos + v * sin, y - u * sin + v * cos)
    anchor = {"left": "start", "center": "middle", "right": "end"}[label.ha]
    rotate = (f' transform="rotate({number(-label.rotation)} {number(x)} {number(y)})"'
              if label.rotation else "")
    return (f'<text x="{number(x)}" y="{number(y + baseline)}" font-size="{number(size)}" '
            f'text-anchor="{anchor}" fill="{to_hex(label.colour)}"{rotate}>'
            f'{svg_tspans(runs, size)}</text>')


def _arrow(arrow: Arrow, frame: _Frame) -> str:
    ax, ay = frame.point(*arrow.start)
    bx, by = frame.point(*arrow.end)
    length = math.hypot(bx - ax, by - ay)
    if length == 0:
        return ""
    colour = to_hex(arrow.colour)
    head, half = HEAD_LENGTH * arrow.head_size, HEAD_HALF_WIDTH * arrow.head_size
    # matplotlib's arc3: the control point lies bend x (dy, -dx) off the middle, y up;
    # here y points down
    cx = (ax + bx) / 2 - arrow.bend * (by - ay)
    cy = (ay + by) / 2 + arrow.bend * (bx - ax)
    heads = []
    if arrow.heads in ("end", "both"):
        heads.append(((bx, by), (bx - cx, by - cy)))
    if arrow.heads == "both":
        heads.append(((ax, ay), (ax - cx, ay - cy)))
    elements = []
    if arrow.bend:
        path = f"M{number(ax)} {number(ay)} Q{number(cx)} {number(cy)} {number(bx)} {number(by)}"
    else:
        ux, uy = (bx - ax) / length, (by - ay) / length
        tail = (ax + ux * head, ay + uy * head) if arrow.heads == "both" else (ax, ay)
        tip = (bx - ux * head, by - uy * head) if arrow.heads != "none" else (bx, by)
        path = f"M{number(tail[0])} {number(tail[1])} L{number(tip[0])} {number(tip[1])}"
    elements.append(f'<path d="{path}" '
                    f'{_paint({"fill": "none", **_stroke(arrow.colour, arrow.width)})}/>')
    for (tx, ty), (dx, dy) in heads:
        norm = math.hypot(dx, dy) or 1.0
        ux, uy = dx / norm, dy / norm
        corners = [(tx, ty), (tx - head * ux - half * uy, ty - head * uy + half * ux),
                   (tx - head * ux + half * uy, ty - head * uy - half * ux)]
        for px, py in corners:
            frame.include(px, py)
        points = " ".join(f"{number(px)},{number(py)}" for px, py in corners)
        paint = {"fill": colour, **_stroke(arrow.colour, arrow.width),
                 "stroke-linejoin": "miter"}
        elements.append(f'<polygon points="{points}" {_paint(paint)}/>')
    frame.include(ax, ay)
    frame.include(bx, by)
    return "\n  ".join(elements)
