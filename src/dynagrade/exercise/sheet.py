"""The student's fill-in file (``exercise.py``): writing it, and reading it back.

The file is plain Python so that an editor highlights it, but it is only ever read with
:mod:`ast`: nothing in it is imported or run. Each answer must be a literal — a number,
a quoted string, ``None`` or a list of numbers — and anything else is reported as an
error for that part alone.
"""

from __future__ import annotations

import ast
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Mapping

from ..errors import DynagradeError
from .model import Exercise, Variant

MAX_SHEET_BYTES = 1_000_000
_SEED = re.compile(r"[0-9]{1,20}")

GUIDE = """\
How to answer: replace None by your answer, then run `grade {filename}`.
  numbers      12.5   1.25e3   "12,5"   "981/100"   "2*pi"
  with units   "45 km/h"   "2000 mN"   "30 deg"   "9.81 m/s^2"   (a bare number is
               read in the unit named in the comment above the answer)
  formulas     "v0^2*sin(2*alpha)/g"   "m g cos(alpha)"   "sqrt(5 g R)"
               (^ or ** for powers, implicit multiplication, Greek names spelled out
               or as letters: alpha or α)
  vectors      [1.2, -3.4]   or   "[1.2, -3.4] m/s"
  choices      "b"   or, where several are right,   "a, c"
"""


class SheetError(DynagradeError, ValueError):
    """The file is not a dynagrade sheet; the message says why and where."""


@dataclass(frozen=True)
class Sheet:
    """What a filled-in file holds: which variant, and the text of every answer.

    ``answers[name]`` is the answer as text, or ``None`` when left empty; ``problems``
    maps a part to the reason its answer could not be read (e.g. a function call).
    """

    exercise_id: str
    seed: int
    student: str | None
    answers: dict[str, str | None]
    problems: dict[str, str]


def write_sheet(exercise: Exercise, variant: Variant, student: str | None,
                filename: str = "exercise.py", points: Mapping[str, float] | None = None) -> str:
    """The text of a fill-in file for ``variant``; ``points`` gives each part's points as
    an exam scales them (the printed sheet shows the same), else the part's own."""
    points = points or {}
    lines = ['"""', f"{exercise.title} ({exercise.source})", ""]
    lines += _docstring_safe(variant.statement).rstrip().splitlines()
    lines += ["", *GUIDE.format(filename=filename).rstrip().splitlines(), '"""', ""]
    lines += [f"EXERCISE = {exercise.id!r}", f"SEED = {variant.seed}"]
    lines += [f"STUDENT = {student!r}" if student is not None else "STUDENT = None", ""]
    for part in exercise.parts:
        lines.append(f"# {part.describe(points.get(part.name, part.points))}")
        lines.append(f"{part.name} = None")
        lines.append("")
    return "\n".join(lines)


def read_sheet(path: str | Path) -> Sheet:
    """The answers of a filled-in file, read with :mod:`ast` only."""
    path = Path(path)
    try:
        raw = path.read_bytes()
    except OSError as error:
        raise SheetError(f"{path}: cannot read the file ({error.strerror})") from None
    if len(raw) > MAX_SHEET_BYTES:
        raise SheetError(f"{path}: {len(raw)} bytes is too large for an answer sheet")
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as error:
        raise SheetError(f"{path}: not UTF-8 text (byte {error.start})") from None
    return parse_sheet(text, str(path))


def parse_sheet(text: str, where: str = "<sheet>") -> Sheet:
    """The answers in the text of a sheet; ``where`` names it in error messages."""
    try:
        tree = ast.parse(text, filename=where)
    except SyntaxError as error:
        raise SheetError(f"{where}, line {error.lineno}: this is not valid Python "
                         f"({error.msg}); answers go in quotes, e.g. x = \"12 m/s\"") from None
    except (ValueError, RecursionError, MemoryError) as error:
        raise SheetError(f"{where}: cannot be read ({type(error).__name__})") from None
    header: dict[str, object] = {}
    answers: dict[str, str | None] = {}
    problems: dict[str, str] = {}
    for node in tree.body:
        if not isinstance(node, ast.Assign):
            continue
        for target in node.targets:
            if not isinstance(target, ast.Name):
                continue
            name = target.id
            try:
                value = _literal(node.value)
            except ValueError as error:
                problems[name] = f"line {node.lineno}: {error}"
                answers[name] = None
                continue
            if name in ("EXERCISE", "SEED", "STUDENT"):
                header[name] = value
            else:
                answers[name] = value
                problems.pop(name, None)
    exercise_id = header.get("EXERCISE")
    seed = header.get("SEED")
    if not isinstance(exercise_id, str):
        raise SheetError(f"{where}: not a dynagrade sheet (no line EXERCISE = \"<id>\"); "
                         "make one with `dynagrade sheet ID --student S -o exercise.py`")
    # A seed is what `dynagrade sheet` wrote: ASCII digits, no sign (numpy refuses negative
    # seeds, and int() would read other scripts' digits or refuse very long ones).
    if not isinstance(seed, str) or not _SEED.fullmatch(seed):
        raise SheetError(f"{where}: the line SEED = <whole number> is missing or changed")
    student = header.get("STUDENT")
    return Sheet(exercise_id, int(seed), student if isinstance(student, str) else None,
                 answers, problems)


def _literal(node: ast.expr) -> str | None:
    """The answer a literal node holds, as text; ``ValueError`` for anything else."""
    if isinstance(node, ast.Constant):
        if node.value is None:
            return None
        if isinstance(node.value, bool):
            raise ValueError("True/False is not an answer")
        if isinstance(node.value, (int, float, str)):
            return str(node.value)
        raise ValueError(f"a {type(node.value).__name__} literal is not an answer")
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
        inner = _literal(node.operand)
        if inner is not None and isinstance(node.operand, ast.Constant) \
                and isinstance(node.operand.value, (int, float)):
            return ("-" if isinstance(node.op, ast.USub) else "") + inner
    if isinstance(node, (ast.List, ast.Tuple)):
        items = [_literal(element) for element in node.elts]
        if any(item is None for item in items):
            raise ValueError("a vector answer must not contain None")
        return "[" + ", ".join(items) + "]"
    kind = {ast.Call: "a function call", ast.Name: "a bare name", ast.BinOp: "arithmetic",
            ast.Attribute: "an attribute"}.get(type(node), type(node).__name__)
    raise ValueError(f"the answer is {kind}; write a number or put the answer in quotes, "
                     "e.g. \"2*pi\"")


def _docstring_safe(text: str) -> str:
    """Text that can stand inside a triple-quoted docstring unchanged."""
    return text.replace("\\", "\\\\").replace('"""', '\\"\\"\\"')
