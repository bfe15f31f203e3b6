"""Lines of an exercise file, for messages that say where its author should look.

Usage::

    line_of_error(path, error)        # "12": the innermost frame of ``error`` in the file
    line_of_string(source, "x_max")   # 31: where the literal "x_max" is first written
    line_of_assignment(source, "EXERCISE")  # 40: where EXERCISE = ... is written
"""

from __future__ import annotations

import ast
import traceback
from pathlib import Path


def line_of_error(path: Path, error: BaseException) -> str:
    """The line of ``path`` where ``error`` was raised (the innermost frame in that
    file), or ``'?'``."""
    path = Path(path).resolve()
    for frame in reversed(traceback.extract_tb(error.__traceback__)):
        if Path(frame.filename).resolve() == path:
            return str(frame.lineno)
    return "?"


def line_of_string(source: str | bytes, text: str) -> int | None:
    """The line where the string literal ``text`` is first written in ``source`` (an
    exercise's id, a part's name); ``None`` when it is not written as a literal."""
    try:
        tree = ast.parse(source)
    except (SyntaxError, ValueError):
        return None
    lines = [node.lineno for node in ast.walk(tree)
             if isinstance(node, ast.Constant) and node.value == text]
    return min(lines, default=None)


def line_of_assignment(source: str | bytes, name: str) -> int | None:
    """The line where the module-level ``name = ...`` of ``source`` starts (its last
    one); ``None`` when there is none or the source does not parse."""
    try:
        tree = ast.parse(source)
    except (SyntaxError, ValueError):
        return None
    lines = [node.lineno for node in tree.body if isinstance(node, ast.Assign)
             and any(isinstance(t, ast.Name) and t.id == name for t in node.targets)]
    return lines[-1] if lines else None
