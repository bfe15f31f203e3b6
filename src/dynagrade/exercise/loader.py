"""Finding and loading exercise files.

The bank shipped with dynagrade (``exercises/`` in the source tree, ``dynagrade/bank`` in
an installed wheel) is searched after the folders a user names with ``--exercises DIR`` or
the ``DYNAGRADE_EXERCISES`` environment variable (folders separated by ``os.pathsep``). A
user's exercise with the id of a shipped one takes its place, so a course can adapt a
shipped exercise by copying it; two files with one id in the same folder tree are an error.

Exercise files are the authors' code and are imported; students' files never are.
"""

from __future__ import annotations

import hashlib
import importlib.abc
import importlib.util
import os
import re
import sys
import traceback
from dataclasses import dataclass
from pathlib import Path
from typing import Iterable, Iterator

from ..errors import DynagradeError, UnknownExercise
from .listing import ExerciseListing, read_listing
from .model import Exercise

ENVIRONMENT_VARIABLE = "DYNAGRADE_EXERCISES"
_DECLARED_ID = re.compile(r"""\bid\s*=\s*["']([a-z0-9-]+)["']""")


class ExerciseFileError(DynagradeError):
    """An exercise file that cannot be loaded; the message names the file and line."""


def builtin_bank() -> Path:
    """The folder of the exercise bank shipped with dynagrade."""
    here = Path(__file__).resolve().parent.parent
    installed = here / "bank"
    if installed.is_dir():
        return installed
    return here.parent.parent / "exercises"


def environment_folders() -> list[Path]:
    """The folders ``$DYNAGRADE_EXERCISES`` names."""
    return [Path(f) for f in os.environ.get(ENVIRONMENT_VARIABLE, "").split(os.pathsep) if f]


def search_path(extra: Iterable[str | os.PathLike] = ()) -> list[Path]:
    """The folders searched for exercises, first match wins; a folder named twice is
    searched at its first place."""
    folders = [Path(f) for f in extra] + environment_folders()
    for folder in folders:
        if not folder.is_dir():
            raise ExerciseFileError(f"exercise folder {folder} does not exist")
    unique = {}
    for folder in folders:
        unique.setdefault(folder.resolve(), folder)
    return list(unique.values()) + [builtin_bank()]


def exercise_files(folder: Path) -> Iterator[Path]:
    """The exercise files below ``folder``, in a stable order."""
    for path in sorted(folder.rglob("*.py")):
        if path.name.startswith("_") or "__pycache__" in path.parts:
            continue
        yield path


def load_file(path: str | os.PathLike) -> Exercise:
    """The ``EXERCISE`` defined by the file at ``path``, as the file reads now.

    An exercise's identity is its file's content: the module is cached under a name made
    of the path and the SHA-256 of the bytes, so loading an unchanged file again costs a
    read and a hash, and loading it after an edit runs the new text (the module of the
    old text is dropped). The hash is the loaded exercise's ``fingerprint``.
    """
    path = Path(path).resolve()
    try:
        source = path.read_bytes()
    except OSError as error:
        raise ExerciseFileError(f"{path}: cannot read the file ({error.strerror})") from None
    fingerprint = hashlib.sha256(source).hexdigest()
    place = hashlib.sha1(str(path).encode()).hexdigest()[:12]
    module_name = f"dynagrade_exercise_{place}_{fingerprint[:16]}"
    cached = sys.modules.get(module_name)
    if cached is not None:
        return cached.EXERCISE
    loader = _SourceLoader(path, source)
    spec = importlib.util.spec_from_loader(module_name, loader, origin=str(path))
    module = importlib.util.module_from_spec(spec)
    try:
        loader.exec_module(module)
    except SyntaxError as error:
        raise ExerciseFileError(f"{path}, line {error.lineno}: {error.msg}") from None
    except Exception as error:
        raise ExerciseFileError(f"{path}, line {_line_in(path, error)}: "
                                f"{type(error).__name__}: {error}") from None
    exercise = getattr(module, "EXERCISE", None)
    if not isinstance(exercise, Exercise):
        raise ExerciseFileError(f"{path}: defines no EXERCISE = Exercise(...)")
    object.__setattr__(exercise, "path", str(path))
    object.__setattr__(exercise, "fingerprint", fingerprint)
    for stale in [name for name in sys.modules if name.startswith(f"dynagrade_exercise_{place}_")]:
        del sys.modules[stale]
    sys.modules[module_name] = module
    return exercise


class _SourceLoader(importlib.abc.SourceLoader):
    """Runs the bytes that were hashed, never a cached ``.pyc`` of the path: an edit
    within the same second and of the same size would otherwise load the old code."""

    def __init__(self, path: Path, source: bytes):
        self.path, self.source = path, source

    def get_filename(self, fullname: str) -> str:
        return str(self.path)

    def get_data(self, path: str) -> bytes:
        return self.source


@dataclass
class Bank:
    """The exercises found on the search path, by id, loaded when first asked for."""

    folders: list[Path]

    def __post_init__(self):
        self._files: dict[str, Path] | None = None

    def _index(self) -> dict[str, Path]:
        """Candidate file for each id, from the ids the files declare as text."""
        if self._files is None:
            self._files = {}
            for folder in reversed(self.folders):  # earlier folders override later ones
                found: dict[str, Path] = {}
                for path in exercise_files(folder):
                    for exercise_id in _DECLARED_ID.findall(path.read_text(encoding="utf-8")):
                        if exercise_id in found:
                            raise ExerciseFileError(
                                f"exercise id {exercise_id!r} is declared by both "
                                f"{found[exercise_id]} and {path}")
                        found[exercise_id] = path
                self._files.update(found)
        return self._files

    def get(self, exercise_id: str) -> Exercise:
        """The exercise with this id; a clear error, with suggestions, when there is none."""
        path = self._index().get(exercise_id)
        if path is not None:
            exercise = load_file(path)
            if exercise.id == exercise_id:
                return exercise
        for exercise in self.all():
            if exercise.id == exercise_id:
                return exercise
        import difflib

        close = difflib.get_close_matches(exercise_id, sorted(self._index()), n=3)
        hint = f"; did you mean {', '.join(close)}?" if close else ""
        raise UnknownExercise(f"no exercise with id {exercise_id!r}{hint}")

    def all(self) -> list[Exercise]:
        """Every exercise, sorted by chapter, source and id (every file is loaded)."""
        exercises = {}
        for path in sorted(set(self._index().values())):
            exercise = load_file(path)
            exercises.setdefault(exercise.id, exercise)
        return sorted(exercises.values(), key=_listing_order)

    def ids(self) -> list[str]:
        """The ids the exercise files declare, sorted; no file is loaded."""
        return sorted(self._index())

    def listing(self) -> list[ExerciseListing]:
        """What ``dynagrade list`` shows of every exercise, in the order of :meth:`all`,
        read from the files without running them where they allow it (see
        :mod:`dynagrade.exercise.listing`)."""
        listings = {}
        for path in sorted(set(self._index().values())):
            listing = read_listing(path) or ExerciseListing.of(load_file(path))
            listings.setdefault(listing.id, listing)
        return sorted(listings.values(), key=_listing_order)


def open_bank(extra_folders: Iterable[str | os.PathLike] = ()) -> Bank:
    """The bank on the search path (see the module docstring)."""
    return Bank(search_path(extra_folders))


def _listing_order(exercise) -> tuple:
    """Chapter, then the numbers of the source ("Example 1.13" after "Example 1.9"), then id."""
    numbers = tuple(int(n) for n in re.findall(r"\d+", exercise.source))
    return exercise.chapter, numbers, exercise.id


def _line_in(path: Path, error: BaseException) -> str:
    """The line of ``path`` where ``error`` was raised, or '?'."""
    for frame in reversed(traceback.extract_tb(error.__traceback__)):
        if Path(frame.filename).resolve() == path:
            return str(frame.lineno)
    return "?"
