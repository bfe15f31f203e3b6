"""Whose submission a file is, from where it was found.

Accepted layouts (``docs/exams.md`` lists them for the staff):

- **a folder per student**: ``SUBMISSIONS/<student_id>/...`` at any depth, or the student's
  folder itself given on the command line (``grade --manifest m.json subs/s1``). The
  nearest enclosing folder named like a roster student id decides.

A layout is a function ``(relative parts, roster ids) -> student id or None``, where the
parts are the file's path from the folder given on the command line, starting with that
folder's own name. :data:`LAYOUTS` are tried in order. A Moodle or Canvas bulk download,
whose names carry the platform's id rather than the student id, is read as the zip it
comes as, by :mod:`.downloads`.
"""

from __future__ import annotations

from typing import Callable, Collection, Sequence

Layout = Callable[[Sequence[str], Collection[str]], "str | None"]


def student_folder(parts: Sequence[str], roster: Collection[str]) -> str | None:
    """The nearest folder above the file named like a roster student id."""
    for name in reversed(parts[:-1]):
        if name in roster:
            return name
    return None


LAYOUTS: tuple[Layout, ...] = (student_folder,)


def owner(parts: Sequence[str], roster: Collection[str]) -> str | None:
    """The roster student a file at ``parts`` belongs to, or None when no layout says."""
    for layout in LAYOUTS:
        found = layout(parts, roster)
        if found is not None:
            return found
    return None
