"""Text alternatives for SVG figures and charts, and ids that stay unique in a page.

A figure drawn by matplotlib is an unnamed picture to a screen reader: its labels are
glyph outlines. This module gives every SVG ``role="img"``, a ``<title>`` (its name) and
a ``<desc>`` (what is drawn: the helpers' notes, every text label and the author's own
sentences, see :mod:`dynagrade.exercise.figure`), and renames the SVG's ids with a
prefix so that several figures inlined in one HTML page share none.

Usage::

    svg = accessible_svg(svg, "Car in a looping", figure_description(figure))
    html = prefixed_ids(svg, "figure-2-")      # before inlining the second figure
"""

from __future__ import annotations

import html
import re

__all__ = ["accessible_svg", "figure_description", "figure_labels", "prefixed_ids",
           "sentence_list", "svg_text_alternative"]

_SVG_OPEN = re.compile(r"<svg\b[^>]*>", re.S)
_ID = re.compile(r'\bid="([^"]+)"')
TITLE_ID, DESC_ID = "figure-title", "figure-desc"


def figure_labels(figure) -> list[str]:
    """The text labels drawn on a matplotlib figure (in drawing order, once each)."""
    labels: list[str] = []
    texts = list(figure.texts)
    for axes in figure.axes:
        texts += list(axes.texts)
    for text in texts:
        words = " ".join(text.get_text().split())
        if words and text.get_visible() and words not in labels:
            labels.append(words)
    return labels


def sentence_list(items: list[str]) -> str:
    """``a, b and c``."""
    if len(items) <= 1:
        return "".join(items)
    return ", ".join(items[:-1]) + " and " + items[-1]


def figure_description(figure) -> str:
    """The description of an exercise figure: the author's sentences, then what the
    drawing helpers drew (with directions and their labels), then every other text
    label it shows."""
    from ..exercise.figure import figure_notes

    notes = figure_notes(figure)
    sentences = [s if s.endswith(".") else s + "." for s in notes["author"]]
    drawn = "; ".join(notes["drawn"])
    if drawn:
        sentences.append(f"Drawn: {drawn}.")
    labels = [label for label in figure_labels(figure)
              if not re.search(rf"(?<!\w){re.escape(label)}(?!\w)", drawn)]
    if labels:
        sentences.append("Labels: " + "; ".join(labels) + ".")
    return " ".join(sentences) or "A figure without labels."


def accessible_svg(svg: str, title: str, description: str) -> str:
    """``svg`` as an image with a name and a description: ``role="img"`` and
    ``aria-labelledby``/``aria-describedby`` on the root, ``<title>`` and ``<desc>`` its
    first children. An SVG that already has them gets them replaced."""
    svg = re.sub(r"<title\b[^>]*>.*?</title>\s*|<desc\b[^>]*>.*?</desc>\s*", "", svg,
                 flags=re.S)
    match = _SVG_OPEN.search(svg)
    if match is None:
        raise ValueError("not an SVG document: no <svg> element")
    opening = re.sub(r'\s(role|aria-labelledby|aria-describedby)="[^"]*"', "",
                     match.group(0))
    opening = (opening[:-1].rstrip("/").rstrip()
               + f' role="img" aria-labelledby="{TITLE_ID}" aria-describedby="{DESC_ID}">')
    children = (f'\n <title id="{TITLE_ID}">{html.escape(title, quote=False)}</title>'
                f'\n <desc id="{DESC_ID}">{html.escape(description, quote=False)}</desc>')
    return svg[:match.start()] + opening + children + svg[match.end():]


def prefixed_ids(svg: str, prefix: str) -> str:
    """``svg`` with every id (and every reference to one: ``#id``, ``url(#id)``, the
    aria attributes) starting with ``prefix``."""
    if not prefix:
        return svg
    ids = set(_ID.findall(svg))
    if not ids:
        return svg

    def renamed(match: re.Match) -> str:
        return match.group(1) + prefix + match.group(2) if match.group(2) in ids \
            else match.group(0)

    svg = re.sub(r'(\bid="|href="#|url\(#)([^")]+)', renamed, svg)

    def aria(match: re.Match) -> str:
        names = " ".join(prefix + n if n in ids else n for n in match.group(2).split())
        return f'{match.group(1)}"{names}"'

    return re.sub(r'(\baria-(?:labelledby|describedby)=)"([^"]*)"', aria, svg)


def svg_text_alternative(svg: str) -> tuple[str, str]:
    """The ``(title, description)`` that :func:`accessible_svg` gave ``svg`` (plain text;
    empty strings where missing)."""
    found = []
    for tag in ("title", "desc"):
        match = re.search(rf"<{tag}\b[^>]*>(.*?)</{tag}>", svg, re.S)
        found.append(html.unescape(match.group(1)).strip() if match else "")
    return found[0], found[1]
