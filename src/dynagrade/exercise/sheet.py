"""The student's fill-in file (``exercise.py``): writing it, and reading it back.

The file is plain Python so that an editor highlights it, but it is only ever read with
:mod:`ast`: nothing in it is imported or run. Each answer must be a literal — a number,
a quoted string, ``None``, a list of numbers, or arithmetic of plain numbers such as
``8*(9.81-6.867)`` (read as that expression) — and anything else is reported as an
error for that part alone.

Reading forgives what editors do: a byte-order mark and CRLF line ends are fine. It goes
assignment by assignment: a line that is not Python (``a = 6.00 m/s^2``) costs only the
part it assigns, with a message naming the line and the fix
(``put the answer in quotes: a = "6.00 m/s^2"``); every other shape of assignment to a
name (annotated, augmented, tuple, walrus, inside an ``if``) gets a message too.
"""

from __future__ import annotations

import ast
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Mapping

from ..errors import DynagradeError
from .datafile import DataFileError, read_data_file
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


EXAM_CHECK = """then run `grade {filename}`:
in an exam it checks only that every answer can be read (a number, a unit of the right
kind, the allowed names in a formula); whether it is right you learn when the staff
grade."""

_TOKEN = re.compile(r"[0-9a-z]{24}")


class SheetError(DynagradeError, ValueError):
    """The file is not a dynagrade sheet; the message says why and where."""


@dataclass(frozen=True)
class Sheet:
    """What a filled-in file holds: which variant, and the text of every answer.

    ``answers[name]`` is the answer as text, or ``None`` when left empty; ``problems``
    maps a part to the reason its answer could not be read (e.g. a function call);
    ``notes`` are the located problems that concern no answer (a stray broken line).
    """

    exercise_id: str
    seed: int | None  # a practice or homework sheet's seed; None on an exam sheet
    student: str | None
    answers: dict[str, str | None]
    problems: dict[str, str]
    notes: tuple[str, ...] = ()
    token: str | None = None  # an exam sheet's variant token
    exam_id: str | None = None  # the exam or homework the file belongs to

    @property
    def is_exam(self) -> bool:
        """Whether the file is an exam's (its variant known only to the staff)."""
        return self.token is not None


def figure_file_name(exercise: Exercise) -> str:
    """The name of the exercise's figure written beside its fill-in file."""
    return f"{exercise.id}.svg"


def write_sheet(exercise: Exercise, variant: Variant, student: str | None,
                filename: str = "exercise.py", points: Mapping[str, float] | None = None,
                token: str | None = None, exam_id: str | None = None,
                figure: str | None = None) -> str:
    """The text of a fill-in file for ``variant``; ``points`` gives each part's points as
    an exam scales them (the printed sheet shows the same), else the part's own.

    With ``token`` (an exam's variant token) the file carries that token instead of the
    seed, and its guide says that ``grade`` only checks that the answers can be read;
    ``exam_id`` names the exam (or homework) the file belongs to; ``figure`` names the
    variant's figure written beside the file (see :func:`figure_file_name`), which the
    header then points to."""
    points = points or {}
    guide = GUIDE.format(filename=filename)
    if token is not None:
        guide = guide.replace(f"then run `grade {filename}`.", EXAM_CHECK.format(
            filename=filename))
    lines = ['"""', f"{exercise.title} ({exercise.source})", ""]
    if figure is not None:
        lines += [f"Figure: {figure}, in the folder of this file.", ""]
    lines += _docstring_safe(variant.statement).rstrip().splitlines()
    lines += ["", *guide.rstrip().splitlines(), '"""', ""]
    lines += [f"EXAM = {exam_id!r}"] if exam_id is not None else []
    lines += [f"EXERCISE = {exercise.id!r}",
              f"VARIANT = {token!r}" if token is not None else f"SEED = {variant.seed}"]
    lines += [f"STUDENT = {student!r}" if student is not None else "STUDENT = None", ""]
    for part in exercise.parts:
        lines.append(f"# {part.describe(points.get(part.name, part.points))}")
        lines.append(f"{part.name} = None")
        lines.append("")
    return "\n".join(lines)


def read_sheet(path: str | Path) -> Sheet:
    """The answers of a filled-in file, read with :mod:`ast` only.

    Only a regular file of at most :data:`MAX_SHEET_BYTES` is read (a link to a device
    or a FIFO is refused before reading); a byte-order mark is dropped."""
    path = Path(path)
    try:
        raw = read_data_file(path, MAX_SHEET_BYTES)
    except DataFileError as error:
        raise SheetError(f"{path}: {error}") from None
    return sheet_from_bytes(raw, str(path))


def sheet_from_bytes(raw: bytes, where: str) -> Sheet:
    """The answers of a filled-in file given as its bytes (UTF-8, a byte-order mark
    dropped); ``where`` names it in error messages."""
    try:
        text = raw.decode("utf-8-sig")
    except UnicodeDecodeError as error:
        raise SheetError(f"{where}: not UTF-8 text (byte {error.start})") from None
    return parse_sheet(text, where)


def parse_sheet(text: str, where: str = "<sheet>") -> Sheet:
    """The answers in the text of a sheet; ``where`` names it in error messages.

    A line that is not valid Python loses only the answer it assigns (with a message
    naming the line and what to write instead); the rest of the file is still read.
    """
    tree, broken = _parse_around_broken_lines(_plain_text(text), where)
    header: dict[str, object] = {}
    answers: dict[str, str | None] = {}
    problems: dict[str, str] = {}
    notes: list[str] = []
    for line, name, message in broken:
        if name is None:
            notes.append(f"line {line}: {message}")
        else:
            problems[name] = f"line {line}: {message}"
            answers[name] = None
    for node in tree.body:
        names = [t for t in node.targets if isinstance(t, ast.Name)] \
            if isinstance(node, ast.Assign) else []
        if isinstance(node, ast.Assign) and len(names) == len(node.targets):
            for target in names:
                _take(target.id, node, header, answers, problems)
        else:
            for name, message in _other_shapes(node):
                problems[name] = f"line {node.lineno}: {message}"
                answers.setdefault(name, None)
    for name in _HEADER_NAMES:
        if name in problems:
            notes.append(problems.pop(name))
            answers.pop(name, None)
    return _sheet(header, answers, problems, tuple(notes), where)


_HEADER_NAMES = ("EXAM", "EXERCISE", "SEED", "VARIANT", "STUDENT")
_MAX_REPAIRS = 50


def _plain_text(text: str) -> str:
    """The text without a byte-order mark, with CRLF or CR line ends as LF."""
    return text.removeprefix("\ufeff").replace("\r\n", "\n").replace("\r", "\n")


def _parse_around_broken_lines(text: str, where: str):
    """The syntax tree of ``text`` with every line Python cannot read blanked out, and
    for each such line ``(line, name it assigns or None, message)``."""
    lines = text.split("\n")
    broken: list[tuple[int, str | None, str]] = []
    for _ in range(_MAX_REPAIRS):
        try:
            return ast.parse("\n".join(lines), filename=where), broken
        except SyntaxError as error:
            number = error.lineno or 0
            if (not 1 <= number <= len(lines) or not lines[number - 1].strip()
                    or error.msg.startswith("too many")):  # a parser limit: hostile
                raise SheetError(f"{where}, line {number}: this is not valid Python "
                                 f"({error.msg}); answers go in quotes, e.g. "
                                 'x = "12 m/s"') from None
            broken.append((number, *_repair_hint(lines[number - 1])))
            lines[number - 1] = ""
        except (ValueError, RecursionError, MemoryError) as error:
            raise SheetError(f"{where}: cannot be read ({type(error).__name__})") from None
    raise SheetError(f"{where}: more than {_MAX_REPAIRS} lines are not valid Python; "
                     "is this a fill-in file?")


_ASSIGNMENT = re.compile(r"\s*([A-Za-z_][A-Za-z0-9_]*)\s*=(?!=)\s*(.*?)\s*")
_MAX_QUOTED = 80


def _repair_hint(line: str) -> tuple[str | None, str]:
    """The name a broken line assigns (or None) and what to write instead."""
    match = _ASSIGNMENT.fullmatch(line)
    if not match:
        return None, "this is not valid Python and was ignored"
    name, value = match.groups()
    if name in _HEADER_NAMES:
        return name, (f"this is not valid Python; the line {name} = ... must stay as "
                      "the sheet wrote it")
    value = value.strip("\"'")
    if not value or len(value) > _MAX_QUOTED or '"' in value:
        return name, "this is not valid Python; put the answer in quotes"
    return name, f'this is not valid Python; put the answer in quotes: {name} = "{value}"'


def _take(name: str, node: ast.Assign, header: dict, answers: dict, problems: dict) -> None:
    """Record ``name = value`` as a header field or an answer (or the answer's problem)."""
    try:
        value = _literal(node.value)
    except ValueError as error:
        problems[name] = f"line {node.lineno}: {error}"
        answers[name] = None
        return
    if name in _HEADER_NAMES:
        header[name] = value
    else:
        answers[name] = value
        problems.pop(name, None)


_SHAPES = {ast.AnnAssign: "an annotated assignment", ast.AugAssign: "an augmented "
           "assignment", ast.Assign: "an assignment to several names at once",
           ast.NamedExpr: "a walrus assignment"}


def _other_shapes(node: ast.stmt):
    """``(name, message)`` for every name a statement other than ``name = literal``
    assigns: annotated, augmented, tuple, walrus, or nested in ``if``/``for``/..."""
    nested = not isinstance(node, (ast.Assign, ast.AnnAssign, ast.AugAssign, ast.Expr))
    for inner in ast.walk(node):
        shape = _SHAPES.get(type(inner))
        if shape is None:
            continue
        if isinstance(inner, ast.Assign):
            targets = inner.targets
        elif isinstance(inner, (ast.AnnAssign, ast.AugAssign, ast.NamedExpr)):
            targets = [inner.target]
        else:  # no other statement is in _SHAPES
            continue
        for target in targets:
            for name in (n.id for n in ast.walk(target) if isinstance(n, ast.Name)):
                kind = "an assignment inside another statement" if nested else shape
                yield name, (f"{kind} is not read; write the answer on its own line as "
                             f"{name} = <answer>")


def _sheet(header: dict, answers: dict, problems: dict, notes: tuple[str, ...],
           where: str) -> Sheet:
    """The sheet, once the header fields are checked."""
    located = [*notes, *problems.values()]
    broken = "".join(f"; {note}" for note in located[:3])
    exercise_id = header.get("EXERCISE")
    seed = header.get("SEED")
    if not isinstance(exercise_id, str):
        raise SheetError(f"{where}: not a dynagrade sheet (no line EXERCISE = \"<id>\"); "
                         "make one with `dynagrade sheet ID --student S -o exercise.py`"
                         + broken)
    student = header.get("STUDENT")
    student = student if isinstance(student, str) else None
    exam_id = header.get("EXAM") if isinstance(header.get("EXAM"), str) else None
    token = header.get("VARIANT")
    if "VARIANT" in header:
        if not isinstance(token, str) or not _TOKEN.fullmatch(token):
            raise SheetError(f"{where}: the line VARIANT = \"...\" is changed; it must "
                             "stay as the sheet wrote it" + broken)
        return Sheet(exercise_id, None, student, answers, problems, notes, token, exam_id)
    # A seed is what `dynagrade sheet` wrote: ASCII digits, no sign (numpy refuses negative
    # seeds, and int() would read other scripts' digits or refuse very long ones).
    if not isinstance(seed, str) or not _SEED.fullmatch(seed):
        raise SheetError(f"{where}: the line SEED = <whole number> is missing or changed"
                         + broken)
    return Sheet(exercise_id, int(seed), student, answers, problems, notes, None, exam_id)


_ARITHMETIC = (ast.Add, ast.Sub, ast.Mult, ast.Div, ast.Pow)


def _is_number_arithmetic(node: ast.expr) -> bool:
    """Whether ``node`` is arithmetic (+ - * / **) of plain numbers only."""
    if isinstance(node, ast.Constant):
        return isinstance(node.value, (int, float)) and not isinstance(node.value, bool)
    if isinstance(node, ast.UnaryOp):
        return isinstance(node.op, (ast.USub, ast.UAdd)) and _is_number_arithmetic(node.operand)
    if isinstance(node, ast.BinOp):
        return (isinstance(node.op, _ARITHMETIC) and _is_number_arithmetic(node.left)
                and _is_number_arithmetic(node.right))
    return False


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
    if isinstance(node, ast.BinOp) and _is_number_arithmetic(node):
        return ast.unparse(node)
    if isinstance(node, (ast.List, ast.Tuple)):
        items = [_literal(element) for element in node.elts]
        written = [item for item in items if item is not None]
        if len(written) < len(items):
            raise ValueError("a vector answer must not contain None")
        return "[" + ", ".join(written) + "]"
    kind = {ast.Call: "a function call", ast.Name: "a bare name", ast.BinOp: "arithmetic",
            ast.Attribute: "an attribute"}.get(type(node), type(node).__name__)
    raise ValueError(f"the answer is {kind}; write a number or put the answer in quotes, "
                     "e.g. \"2*pi\"")


def _docstring_safe(text: str) -> str:
    """Text that can stand inside a triple-quoted docstring unchanged."""
    return text.replace("\\", "\\\\").replace('"""', '\\"\\"\\"')
