"""Lines of an exercise file, for messages that say where its author should look.

Usage::

    line_of_error(path, error)        # "12": the innermost frame of ``error`` in the file
    line_of_string(source, "x_max")   # 31: where the literal "x_max" is first written
    line_of_assignment(source, "EXERCISE")  # 40: where EXERCISE = ... is written
    failure_line(path, function, error)  # "FILE, line 12: " for a message about the error
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


#: the longest error message a one-line report of an author's code quotes
MESSAGE_LENGTH = 300


def failure_line(path: str | None, function, error: BaseException, what: str) -> str:
    """One line for a failure of an exercise author's code: the file and line where it
    arose (the innermost frame in ``path``, else the line that defines ``function``), what
    failed and the error, its message folded onto one line and cut to
    :data:`MESSAGE_LENGTH` characters: ``FILE, line 12: <what>: TypeError: ...``."""
    code = getattr(function, "__code__", None)
    path = path or (code.co_filename if code is not None else None)
    place = ""
    if path is not None:
        line = line_of_error(Path(path), error)
        if line == "?" and code is not None and \
                Path(code.co_filename).resolve() == Path(path).resolve():
            line = str(code.co_firstlineno)
        place = f"{path}, line {line}: "
    text = " ".join(str(error).split())
    if len(text) > MESSAGE_LENGTH:
        text = text[:MESSAGE_LENGTH] + " ..."
    return f"{place}{what}: {type(error).__name__}" + (f": {text}" if text else "")


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
