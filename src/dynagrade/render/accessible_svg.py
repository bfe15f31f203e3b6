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
from typing import Callable

from .svg_text import plain_label

__all__ = ["accessible_svg", "figure_description", "figure_labels", "prefixed_ids",
           "sentence_list", "svg_text_alternative"]

_SVG_OPEN = re.compile(r"<svg\b[^>]*>", re.S)
#: an id, a reference to one and the aria attributes naming some: each only where it
#: starts a word (an id="…" or aria-… not after a letter, digit or "_"), which
#: :func:`_word_matches` checks; a leading ``\b`` in the pattern would do it too, but
#: would keep the regex engine from its fast literal search, twenty times slower
_ID = re.compile(r'id="([^"]+)"')
_REFERENCE = re.compile(r'(id="|href="#|url\(#)([^")]+)')
_ARIA = re.compile(r'(aria-(?:labelledby|describedby)=)"([^"]*)"')
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
    label it shows, labels read as the figure draws them (``$e_\\varphi$`` as "eφ", as a
    screen reader should say it, not its TeX)."""
    from ..exercise.figure import figure_notes

    notes = figure_notes(figure)
    sentences = [s if s.endswith(".") else s + "." for s in notes["author"]]
    drawn = plain_label("; ".join(notes["drawn"]))
    if drawn:
        sentences.append(f"Drawn: {drawn}.")
    labels = [label for label in map(plain_label, figure_labels(figure))
              if not _names_word(drawn, label)]
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
    ids = {match.group(1) for match in _word_matches(_ID, svg)}
    if not ids:
        return svg

    def renamed(match: re.Match) -> str:
        return match.group(1) + prefix + match.group(2) if match.group(2) in ids \
            else match.group(0)

    svg = _replaced(_REFERENCE, svg, renamed, lambda match: match.group(1) == 'id="')

    def aria(match: re.Match) -> str:
        names = " ".join(prefix + n if n in ids else n for n in match.group(2).split())
        return f'{match.group(1)}"{names}"'

    return _replaced(_ARIA, svg, aria)


def _word_matches(pattern: re.Pattern, text: str,
                  bounded: Callable[[re.Match], bool] = lambda match: True):
    """The matches of ``pattern`` in ``text`` that a search for it with ``\\b`` in front
    finds, where ``bounded(match)`` says the ``\\b`` applies to the match (its first
    character being a word character): those after a word character are passed over,
    and the search goes on from the next character, as the regex engine's would."""
    position = 0
    while (match := pattern.search(text, position)) is not None:
        start = match.start()
        if start and bounded(match) and _is_word_character(text[start - 1]):
            position = start + 1
        else:
            yield match
            position = match.end()


def _replaced(pattern: re.Pattern, text: str, replacement: Callable[[re.Match], str],
              bounded: Callable[[re.Match], bool] = lambda match: True) -> str:
    """``text`` with each of :func:`_word_matches` replaced by ``replacement(match)``."""
    pieces, end = [], 0
    for match in _word_matches(pattern, text, bounded):
        pieces += (text[end:match.start()], replacement(match))
        end = match.end()
    return "".join(pieces) + text[end:]


def _is_word_character(character: str) -> bool:
    """What ``\\w`` matches: a letter, a digit or "_" (of any script)."""
    return character.isalnum() or character == "_"


def _names_word(text: str, word: str) -> bool:
    """Whether ``word`` occurs in ``text`` with no word character right before or after
    it (``(?<!\\w)word(?!\\w)``)."""
    start = text.find(word)
    while start != -1:
        end = start + len(word)
        if (start == 0 or not _is_word_character(text[start - 1])) and \
                (end == len(text) or not _is_word_character(text[end])):
            return True
        start = text.find(word, start + 1)
    return False


def svg_text_alternative(svg: str) -> tuple[str, str]:
    """The ``(title, description)`` that :func:`accessible_svg` gave ``svg`` (plain text;
    empty strings where missing)."""
    found = []
    for tag in ("title", "desc"):
        match = re.search(rf"<{tag}\b[^>]*>(.*?)</{tag}>", svg, re.S)
        found.append(html.unescape(match.group(1)).strip() if match else "")
    return found[0], found[1]
