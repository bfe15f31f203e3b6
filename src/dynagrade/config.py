"""The project file ``dynagrade.toml``: a course's exercise folders and command defaults.

The commands look for ``dynagrade.toml`` in the working folder and then in each folder
above it; the first one found is the project's. Every key is optional::

    exercises = ["exercises", "../shared/exercises"]  # folders of exercise files
    jobs = 2                                          # worker processes: exam, grade

    [exam]
    output = "out"                 # dynagrade exam's -o
    secret_file = "exam.secret"    # dynagrade exam's --secret-file

    [grade]
    output = "out/grading"         # dynagrade grade --manifest's -o

    [verify]
    variants = 200                 # dynagrade verify's --variants

Paths are relative to the folder of the file. A setting on the command line wins over
the environment (``$DYNAGRADE_EXERCISES``), which wins over the file, which wins over the
built-in default; exercise folders from all three are searched, in that order, before
the shipped bank. A file that cannot be used is one error naming the file, the line and
the key, never a traceback.

This module is a leaf beside :mod:`dynagrade.errors`: it reads the file and nothing else.
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable

from .errors import DynagradeError

FILE_NAME = "dynagrade.toml"


class ConfigError(DynagradeError, ValueError):
    """A ``dynagrade.toml`` that cannot be used; the message names the file, line and key."""


@dataclass(frozen=True)
class Project:
    """What a project file says; empty (every field ``None``) when there is no file."""

    path: Path | None = None
    exercises: tuple[Path, ...] = ()
    jobs: int | None = None
    exam_output: Path | None = None
    secret_file: Path | None = None
    grade_output: Path | None = None
    variants: int | None = None

    def defaults(self) -> dict[str, dict[str, Any]]:
        """The file's settings as defaults of the commands' options (click's
        ``default_map``: command name to option name to value)."""
        commands: dict[str, dict[str, Any]] = {}

        def put(command: str, option: str, value) -> None:
            if value is not None:
                commands.setdefault(command, {})[option] = (
                    str(value) if isinstance(value, Path) else value)

        for command in ("exam", "grade"):
            put(command, "jobs", self.jobs)
        put("exam", "output", self.exam_output)
        put("exam", "secret_file", self.secret_file)
        put("grade", "output", self.grade_output)
        put("verify", "variants", self.variants)
        return commands


def find_project_file(start: str | os.PathLike | None = None) -> Path | None:
    """The first ``dynagrade.toml`` in ``start`` (default: the working folder) or above."""
    folder = Path(start or Path.cwd()).resolve()
    for candidate in (folder, *folder.parents):
        path = candidate / FILE_NAME
        if path.is_file():
            return path
    return None


def load_project(start: str | os.PathLike | None = None) -> Project:
    """The project file found from ``start`` (:func:`find_project_file`), read; an empty
    :class:`Project` when there is none."""
    path = find_project_file(start)
    return read_project(path) if path else Project()


def read_project(path: str | os.PathLike) -> Project:
    """The project file at ``path``; :class:`ConfigError` for anything wrong in it."""
    import tomllib  # here: a command run without a project file never parses TOML

    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
        data = tomllib.loads(text)
    except OSError as error:
        raise ConfigError(f"{path}: cannot read the file ({error.strerror})") from None
    except UnicodeDecodeError:
        raise ConfigError(f"{path}: not UTF-8 text") from None
    except tomllib.TOMLDecodeError as error:
        raise ConfigError(f"{path}: not valid TOML: {error}") from None
    reader = _Reader(path, text)
    reader.refuse_unknown(data, "", {"exercises", "jobs", "exam", "grade", "verify"})
    tables = {name: reader.table(data, name, keys)
              for name, keys in (("exam", {"output", "secret_file"}), ("grade", {"output"}),
                                 ("verify", {"variants"}))}
    return Project(
        path=path,
        exercises=reader.folders(data, "exercises"),
        jobs=reader.value(data, "jobs", _positive_integer),
        exam_output=reader.value(tables["exam"], "exam.output", reader.path),
        secret_file=reader.value(tables["exam"], "exam.secret_file", reader.path),
        grade_output=reader.value(tables["grade"], "grade.output", reader.path),
        variants=reader.value(tables["verify"], "verify.variants", _positive_integer),
    )


class _Reader:
    """Reads keys of one file, each error naming the file, the key's line and the key."""

    def __init__(self, path: Path, text: str):
        self.file, self.text = path, text

    def error(self, key: str, message: str) -> ConfigError:
        return ConfigError(f"{self.file}, line {self.line_of(key)}, key '{key}': {message}")

    def line_of(self, key: str) -> str:
        """The line where ``key`` ("exercises", "exam.output") is set, or '?'."""
        *tables, name = key.split(".")
        wanted_table = ".".join(tables)
        table = ""
        for number, line in enumerate(self.text.splitlines(), 1):
            header = re.match(r"^\s*\[\s*([A-Za-z0-9_.\s]+?)\s*\]", line)
            if header:
                table = header.group(1).replace(" ", "")
                if not name and table == wanted_table:
                    return str(number)
                continue
            if table == wanted_table and re.match(rf"^\s*{re.escape(name)}\s*=", line):
                return str(number)
        return "?"

    def refuse_unknown(self, data: dict, prefix: str, known: set[str]) -> None:
        for key in data:
            if key not in known:
                raise self.error(prefix + key, f"unknown key; the keys are "
                                               f"{', '.join(sorted(known))}")

    def table(self, data: dict, name: str, known: set[str]) -> dict:
        table = data.get(name, {})
        if not isinstance(table, dict):
            raise self.error(name, f"must be a table ([{name}])")
        self.refuse_unknown(table, f"{name}.", known)
        return table

    def value(self, data: dict, key: str, convert: Callable[[Any], Any]):
        name = key.rsplit(".", 1)[-1]
        if name not in data:
            return None
        try:
            return convert(data[name])
        except (TypeError, ValueError) as error:
            raise self.error(key, str(error)) from None

    def path(self, value) -> Path:
        if not isinstance(value, str) or not value:
            raise ValueError(f"must be a path in quotes, got {value!r}")
        return (self.file.parent / value).resolve()

    def folders(self, data: dict, key: str) -> tuple[Path, ...]:
        values = data.get(key, [])
        if isinstance(values, str):
            values = [values]
        if not isinstance(values, list):
            raise self.error(key, f"must be a list of folders, got {values!r}")
        folders = []
        for value in values:
            folder = self.value({key: value}, key, self.path)
            if not folder.is_dir():
                raise self.error(key, f"the folder {folder} does not exist")
            folders.append(folder)
        return tuple(folders)


def _positive_integer(value) -> int:
    if isinstance(value, bool) or not isinstance(value, int) or value < 1:
        raise ValueError(f"must be a whole number of at least 1, got {value!r}")
    return value
