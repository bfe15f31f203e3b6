"""Tables as plain text: the grade report and the bank's listing in a terminal.

A column is as wide as its widest cell; when the table is wider than the terminal, the
widest columns are narrowed and their cells wrapped at spaces (a word is broken only when
whole words cannot fit). No colour and no box
drawing, so the table reads the same in a terminal, in a file and through ``grep``.
Writing one costs no import beyond the standard library (rich, which draws the other
commands' panels and progress bars, takes longer to import than ``grade`` takes to run).

Usage::

    print(text_table(("part", "verdict"), [("x_max", "correct")], title="...", caption="..."))
"""

from __future__ import annotations

import os
import textwrap
from typing import Sequence

#: The columns of a table when the output is no terminal (a pipe, a file).
DEFAULT_WIDTH = 80
_GAP = "  "
_NARROWEST = 8


def terminal_width() -> int:
    """The columns of the terminal standard output writes to: ``$COLUMNS`` when set, else
    the terminal's own width, else :data:`DEFAULT_WIDTH`."""
    columns = os.environ.get("COLUMNS", "")
    if columns.isdigit() and int(columns) > 0:
        return int(columns)
    try:
        return os.get_terminal_size(1).columns
    except (OSError, ValueError):
        return DEFAULT_WIDTH


def text_table(headers: Sequence[str], rows: Sequence[Sequence[str]], *,
               title: str | None = None, caption: str | None = None,
               width: int | None = None) -> str:
    """The table as lines of text: the title, the headers underlined, one or more lines
    per row (long cells wrapped), the caption; no line is wider than ``width`` (the
    terminal's by default) unless the headers alone are."""
    width = width or terminal_width()
    cells = [[str(cell) for cell in row] for row in rows]
    widths = _fitted_widths(headers, cells, width)
    lines = [title, ""] if title else []
    lines.append(_line(headers, widths))
    lines.append(_line(["-" * w for w in widths], widths))
    for row in cells:
        wrapped = [textwrap.wrap(cell, max(w, 1), break_on_hyphens=False) or [""]
                   for cell, w in zip(row, widths)]
        for k in range(max(len(column) for column in wrapped)):
            lines.append(_line([column[k] if k < len(column) else "" for column in wrapped],
                               widths))
    if caption:
        lines += ["", caption]
    return "\n".join(lines) + "\n"


def _fitted_widths(headers: Sequence[str], rows: list[list[str]], width: int) -> list[int]:
    """Each column's width: its widest cell, the widest columns narrowed one character at
    a time until the table fits ``width``. Words are kept whole while that is enough (an
    id stays one word to search for); then a column may narrow down to its header or
    :data:`_NARROWEST` characters, and its longest words are broken."""
    widths = [max([len(h), *(len(row[k]) for row in rows)]) for k, h in enumerate(headers)]
    room = width - len(_GAP) * (len(headers) - 1)
    whole_words = [max([len(h), *(len(word) for row in rows for word in row[k].split())])
                   for k, h in enumerate(headers)]
    for floors in (whole_words, [max(len(h), _NARROWEST) for h in headers]):
        while sum(widths) > room:
            narrowable = [k for k, w in enumerate(widths) if w > floors[k]]
            if not narrowable:
                break
            widths[max(narrowable, key=lambda k: widths[k])] -= 1
    return widths


def _line(cells: Sequence[str], widths: Sequence[int]) -> str:
    return _GAP.join(cell.ljust(w) for cell, w in zip(cells, widths)).rstrip()
