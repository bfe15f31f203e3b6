"""Every CSV dynagrade writes, made inert for spreadsheets, and read back exactly.

A spreadsheet runs a cell that starts with ``=``, ``+``, ``-``, ``@``, a tab or a
carriage return as a formula (OWASP, "CSV Injection"): a student's answer
``=HYPERLINK(...)`` in ``submissions.csv`` or a roster name ``=cmd|...`` in
``grades.csv`` would run when the staff open the file. So every CSV dynagrade writes
goes through :func:`csv_text`, which writes each text cell through :func:`inert`, and
every reader of a CSV dynagrade writes (responses, overrides, rosters, ``links.csv``)
undoes it with :func:`restored`. The rule, exact both ways (``restored(inert(s)) == s``
for every text ``s``):

* a cell whose text, after any leading apostrophes, starts with one of
  :data:`FORMULA_STARTS` gets one more apostrophe in front: ``=SUM(1)`` is written
  ``'=SUM(1)``, ``'=SUM(1)`` (a student who typed the apostrophe) ``''=SUM(1)``;
* reading, one leading apostrophe is dropped from exactly those cells: an apostrophe
  followed (after any further apostrophes) by a formula start. Every other cell is read
  as written: ``'t Hooft`` stays ``'t Hooft``.
* a plain decimal number (:data:`PLAIN_NUMBER`: ``-3.5``, ``-1.25e-05``) is not a formula
  and is written as it is, so a spreadsheet still reads it as a number; ``-3.5 m/s`` or
  ``-3+1`` is text and gets the apostrophe.

Spreadsheets (Excel, LibreOffice) hide one leading apostrophe and show the rest as text,
so the staff see ``=SUM(1)`` and ``'=SUM(1)`` as the student typed them.
"""

from __future__ import annotations

import re
from typing import Iterable, Sequence

#: the first characters that make a spreadsheet read a cell as a formula (OWASP)
FORMULA_STARTS = ("=", "+", "-", "@", "\t", "\r")
#: a number as dynagrade writes one (ASCII digits only): not a formula, left as it is
PLAIN_NUMBER = re.compile(r"-?[0-9]+(?:\.[0-9]+)?(?:[eE][-+]?[0-9]+)?")
ESCAPE = "'"


def _would_run(text: str) -> bool:
    """Whether ``text`` after its leading apostrophes starts like a formula."""
    rest = text.lstrip(ESCAPE)
    return rest.startswith(FORMULA_STARTS) and not PLAIN_NUMBER.fullmatch(rest)


def inert(text: str) -> str:
    """``text`` as a cell a spreadsheet shows and never runs (see the module's rule)."""
    return ESCAPE + text if _would_run(text) else text


def restored(cell: str) -> str:
    """The text :func:`inert` made ``cell`` from: its escape apostrophe dropped."""
    return cell[1:] if cell.startswith(ESCAPE) and _would_run(cell) else cell


def csv_text(rows: Iterable[Sequence[object]]) -> str:
    """The rows as CSV text (comma, ``\\n`` line ends), every cell made inert; None is an
    empty cell, numbers are written with :class:`str`.

    Written here rather than by :func:`csv.writer`: with ``\\n`` line ends the standard
    writer leaves a carriage return in a cell unquoted, and every reader then ends the row
    there (an answer ``a\\rb`` came back as two rows). A cell is quoted, its quotes
    doubled, when it holds a comma, a quote, a line feed or a carriage return; a row of a
    single empty cell is ``""`` (not an empty line, which readers skip)."""
    lines = []
    for row in rows:
        cells = ["" if cell is None else inert(str(cell)) for cell in row]
        lines.append('""' if cells == [""] else ",".join(_quoted(c) for c in cells))
    return "".join(line + "\n" for line in lines)


def _quoted(cell: str) -> str:
    if any(mark in cell for mark in (",", '"', "\n", "\r")):
        return '"' + cell.replace('"', '""') + '"'
    return cell


def restored_rows(rows: Iterable[Sequence[str]]) -> list[list[str]]:
    """Rows read from a CSV dynagrade wrote, every cell :func:`restored`."""
    return [[restored(cell) for cell in row] for row in rows]
