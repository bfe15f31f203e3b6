"""The Markdown of exercise statements, rendered as HTML (MathML math) and as typst.

Statements use a small part of Markdown: paragraphs, numbered and bulleted lists,
headings, ``**bold**``, ``*emphasis*``, ```code``` and math between single dollar signs
(``\\$`` is a literal dollar). This module reads that subset into blocks of inline
pieces and writes them out; math goes through :mod:`dynagrade.render.mathtex`.

Usage::

    markdown_to_html("A ball of mass $m$ = 2 kg ...")    # '<p>A ball of mass <math ...'
    markdown_to_typst("1. How far ...")                  # '+ How far ...'
"""

from __future__ import annotations

import html
import re
from dataclasses import dataclass

from .mathtex import to_mathml, to_speech, to_typst, typst_string, unknown_commands

__all__ = ["markdown_to_html", "markdown_to_typst", "math_warnings", "Block", "parse_blocks"]

_ORDERED = re.compile(r"^\s{0,3}(\d+)[.)]\s+(.*)$")
_BULLET = re.compile(r"^\s{0,3}[-*+]\s+(.*)$")
_HEADING = re.compile(r"^\s{0,3}(#{1,6})\s+(.*?)\s*#*\s*$")
_INLINE = re.compile(r"(?<!\\)\$(?P<math>(?:\\.|[^$\\])+?)\$"
                     r"|\*\*(?P<bold>.+?)\*\*"
                     r"|(?<![\w*])\*(?P<em>[^*\s](?:[^*]*[^*\s])?)\*(?![\w*])"
                     r"|`(?P<code>[^`]+)`", re.S)


@dataclass(frozen=True)
class Block:
    """A paragraph, a heading (``level``) or a list (``items``, ``ordered``, ``start``)."""

    kind: str  # "paragraph", "heading", "list"
    text: str = ""
    items: tuple[str, ...] = ()
    ordered: bool = False
    start: int = 1
    level: int = 0


def parse_blocks(markdown: str) -> list[Block]:
    """The blocks of ``markdown``: blank lines separate paragraphs; list items may
    continue on the following lines."""
    blocks: list[Block] = []
    paragraph: list[str] = []
    items: list[str] = []
    ordered, start = False, 1

    def flush_paragraph():
        if paragraph:
            blocks.append(Block("paragraph", " ".join(s.strip() for s in paragraph)))
            paragraph.clear()

    def flush_list():
        if items:
            blocks.append(Block("list", items=tuple(items), ordered=ordered, start=start))
            items.clear()

    for line in markdown.splitlines():
        heading = _HEADING.match(line)
        numbered = _ORDERED.match(line)
        bullet = _BULLET.match(line)
        if not line.strip():
            flush_paragraph()
            continue
        if heading:
            flush_paragraph()
            flush_list()
            blocks.append(Block("heading", heading.group(2), level=len(heading.group(1))))
        elif numbered or bullet:
            flush_paragraph()
            is_ordered = numbered is not None
            if items and is_ordered != ordered:
                flush_list()
            if not items:
                ordered = is_ordered
                start = int(numbered.group(1)) if numbered else 1
            items.append((numbered or bullet).group(2 if numbered else 1).strip())
        elif items and not paragraph:
            items[-1] += " " + line.strip()
        else:
            flush_list()
            paragraph.append(line)
    flush_paragraph()
    flush_list()
    return blocks


def _pieces(text: str):
    """``(kind, content)`` pieces of inline text: text, math, bold, em, code."""
    position = 0
    for match in _INLINE.finditer(text):
        if match.start() > position:
            yield "text", text[position:match.start()]
        kind = match.lastgroup
        yield kind, match.group(kind)
        position = match.end()
    if position < len(text):
        yield "text", text[position:]


def _unescape_dollars(text: str) -> str:
    return text.replace("\\$", "$")


# -- HTML ---------------------------------------------------------------------------------


def inline_html(text: str, math: str = "mathml") -> str:
    """Inline Markdown as HTML; ``math="tex"`` keeps math as TeX between ``\\(`` and
    ``\\)`` (for an LMS that typesets it itself) instead of MathML."""
    out = []
    for kind, content in _pieces(text):
        if kind == "math":
            out.append(to_mathml(content) if math == "mathml"
                       else html.escape(f"\\({content}\\)", quote=False))
        elif kind == "bold":
            out.append(f"<strong>{inline_html(content, math)}</strong>")
        elif kind == "em":
            out.append(f"<em>{inline_html(content, math)}</em>")
        elif kind == "code":
            out.append(f"<code>{html.escape(content, quote=False)}</code>")
        else:
            out.append(html.escape(_unescape_dollars(content), quote=False))
    return "".join(out)


def markdown_to_html(markdown: str, heading_offset: int = 0, math: str = "mathml") -> str:
    """HTML for ``markdown``; math as MathML, so a browser needs no script to show it
    (or, with ``math="tex"``, as ``\\(...\\)`` for an LMS's own typesetting)."""
    out = []
    for block in parse_blocks(markdown):
        if block.kind == "heading":
            level = min(6, block.level + heading_offset)
            out.append(f"<h{level}>{inline_html(block.text, math)}</h{level}>")
        elif block.kind == "list":
            tag = "ol" if block.ordered else "ul"
            start = f' start="{block.start}"' if block.ordered and block.start != 1 else ""
            lines = "".join(f"<li>{inline_html(item, math)}</li>" for item in block.items)
            out.append(f"<{tag}{start}>{lines}</{tag}>")
        else:
            out.append(f"<p>{inline_html(block.text, math)}</p>")
    return "\n".join(out)


# -- typst --------------------------------------------------------------------------------

_TYPST_MARKUP_SPECIAL = re.compile(r"([\\#$*_`<>@=\-+/\[\]~\"'])")


def typst_text(text: str) -> str:
    """Plain text safe in typst markup (every markup character escaped)."""
    escaped = _TYPST_MARKUP_SPECIAL.sub(r"\\\1", text)
    return escaped


def inline_typst(text: str) -> str:
    """Inline Markdown as typst markup; math is an equation whose alternative text is its
    spoken form (what a tagged PDF gives a screen reader; PDF/UA requires one)."""
    out = []
    for kind, content in _pieces(text):
        if kind == "math":
            # the ";" ends the call, so a "[" after the math stays text
            out.append(f'#math.equation(alt: "{typst_string(to_speech(content))}", '
                       f"block: false, ${to_typst(content)}$);")
        elif kind == "bold":
            out.append(f"#strong[{inline_typst(content)}]")
        elif kind == "em":
            out.append(f"#emph[{inline_typst(content)}]")
        elif kind == "code":
            out.append(f"#raw(\"{typst_string(content)}\")")
        else:
            out.append(typst_text(_unescape_dollars(content)))
    return "".join(out)


def markdown_to_typst(markdown: str, heading_offset: int = 0) -> str:
    """typst markup for ``markdown``."""
    out = []
    for block in parse_blocks(markdown):
        if block.kind == "heading":
            out.append("=" * min(6, block.level + heading_offset) + " "
                       + inline_typst(block.text))
        elif block.kind == "list":
            if block.ordered:
                items = ", ".join(f"[{inline_typst(item)}]" for item in block.items)
                out.append(f"#enum(start: {block.start}, {items})")
            else:
                out.append("#list(" + ", ".join(f"[{inline_typst(i)}]" for i in block.items)
                           + ")")
        else:
            out.append(inline_typst(block.text))
    return "\n\n".join(out)


def math_warnings(markdown: str) -> list[str]:
    """Commands in the math of ``markdown`` that the renderers do not know."""
    found = []
    for kind, content in _pieces(markdown):
        if kind == "math":
            found += [c for c in unknown_commands(content) if c not in found]
    return found
