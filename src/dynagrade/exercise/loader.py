"""Finding and loading exercise files.

The bank shipped with dynagrade (``exercises/`` in the source tree, ``dynagrade/bank`` in
an installed wheel) is searched after the folders a user names with ``--exercises DIR`` or
the ``DYNAGRADE_EXERCISES`` environment variable (folders separated by ``os.pathsep``). A
user's exercise with the id of a shipped one takes its place, so a course can adapt a
shipped exercise by copying it; two files with one id in the same folder tree are an error.

Every ``.py`` file below an exercise folder is an exercise file, except ``__init__.py``
and any file or folder whose name starts with ``_``: a course's own modules, such as the
relations its keys come from (``_relations.py``, or a package ``_relations/`` with its
tests). An exercise file imports those beside it relatively, ``from ._relations import
f``: each folder of exercise files is loaded as a package of its own
(:func:`folder_package`), so two courses' ``_relations`` never meet, nothing is put on
``sys.path`` and no course module can shadow dynagrade or another library. A
file that defines no exercise, an id that is not kebab-case, two files with one id: each
is an :class:`ExerciseFileError` of one line naming the file and line, raised by every
command that looks at the bank (nothing is skipped in silence). A Symbolic formula that
names what is not one of its part's variables is one too, raised when the file is loaded,
and by ``dynagrade list`` (which reads files without running them) where the file writes
the formula and the variables' names as literals.

Exercise files are the authors' code and are imported; students' files never are.
"""

from __future__ import annotations

import hashlib
import importlib.machinery
import importlib.util
import os
import re
import sys
from dataclasses import dataclass
from pathlib import Path
from types import ModuleType
from typing import Iterable, Iterator

from ..errors import DefinitionError, DynagradeError, UnknownExercise
from .formula_check import formula_problems, written_formula_problems
from .listing import ExerciseListing, read_listing
from .model import Exercise, templates_checked_by_caller
from .source_lines import line_of_assignment, line_of_error, line_of_string

ENVIRONMENT_VARIABLE = "DYNAGRADE_EXERCISES"
#: ``id="..."`` as a file declares it. The pattern starts with the literal ``id`` (which
#: the regular expression engine finds fast); that no letter, digit or ``_`` comes
#: before it is checked by :func:`_declared_ids` (a leading ``\b`` made the scan of the
#: whole bank ten times slower).
_DECLARED_ID = re.compile(r"""id\s*=\s*["']([a-z0-9]+(?:-[a-z0-9]+)*)["']""")


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
    unique: dict[Path, Path] = {}
    for folder in folders:
        unique.setdefault(folder.resolve(), folder)
    return list(unique.values()) + [builtin_bank()]


def exercise_files(folder: Path) -> Iterator[Path]:
    """The exercise files below ``folder``, in a stable order: no file or folder on the
    way whose name starts with ``_`` (a course's own modules, ``__pycache__``)."""
    for path in sorted(folder.rglob("*.py")):
        if any(part.startswith("_") for part in path.relative_to(folder).parts):
            continue
        yield path


#: the prefix of the packages exercise files are loaded in, one per folder
FOLDER_PACKAGE = "dynagrade_course_"


def folder_package(folder: Path) -> str:
    """The name of the package the exercise files of ``folder`` are loaded in, made once
    per folder: a namespace whose one search location is ``folder``. A relative import
    in an exercise file (``from ._relations import omega``) finds the course's module
    beside it and loads it as ``<package>._relations``: two folders each with a
    ``_relations`` give two modules, and ``folder`` never goes on ``sys.path``, so an
    absolute import (``import numpy``, ``import dynagrade``) never finds a course file."""
    name = FOLDER_PACKAGE + hashlib.sha1(str(folder).encode()).hexdigest()[:12]
    if name not in sys.modules:
        spec = importlib.machinery.ModuleSpec(name, None, is_package=True)
        spec.submodule_search_locations = [str(folder)]
        package = importlib.util.module_from_spec(spec)
        sys.modules[name] = package
    return name


def load_file(path: str | os.PathLike, *, templates: bool = True) -> Exercise:
    """The ``EXERCISE`` defined by the file at ``path``, as the file reads now.

    An exercise's identity is its file's content: the module is cached under a name made
    of the path and the SHA-256 of the bytes, so loading an unchanged file again costs a
    read and a hash, and loading it after an edit runs the new text (the module of the
    old text is dropped). The hash is the loaded exercise's ``fingerprint``.

    The statement and solution templates are checked after the file has run, with the
    same one-line error as any other mistake in it; ``templates=False`` leaves them to
    a later load or to their first rendering, for a command that renders neither
    (grading a student's file), which then does not import jinja2.
    """
    path = Path(path).resolve()
    try:
        source = path.read_bytes()
    except OSError as error:
        raise ExerciseFileError(f"{path}: cannot read the file ({error.strerror})") from None
    fingerprint = hashlib.sha256(source).hexdigest()
    place = hashlib.sha1(str(path).encode()).hexdigest()[:12]
    package = folder_package(path.parent)
    module_name = f"{package}.dynagrade_exercise_{place}_{fingerprint[:16]}"
    cached = sys.modules.get(module_name)
    if cached is not None:
        if templates:
            _require_valid_templates(path, source, cached.EXERCISE)
        return cached.EXERCISE
    module = _run(path, source, module_name)
    exercise = getattr(module, "EXERCISE", None)
    if not isinstance(exercise, Exercise):
        raise ExerciseFileError(
            f"{path}: defines no EXERCISE = Exercise(...); a helper module of an exercise "
            "folder has a name starting with '_'")
    if templates:
        _require_valid_templates(path, source, exercise)
    _require_readable_formulas(path, exercise.id, formula_problems(exercise))
    object.__setattr__(exercise, "path", str(path))
    object.__setattr__(exercise, "fingerprint", fingerprint)
    for stale in [name for name in sys.modules
                  if name.startswith(f"{package}.dynagrade_exercise_{place}_")]:
        del sys.modules[stale]
    sys.modules[module_name] = module
    return exercise


def _run(path: Path, source: bytes, module_name: str) -> ModuleType:
    """The module of the exercise file ``path`` (its bytes ``source``), run; the
    exercises it builds leave their templates to :func:`load_file`."""
    loader = _SourceLoader(module_name, path, source)
    spec = importlib.util.spec_from_loader(module_name, loader, origin=str(path))
    if spec is None:  # never: spec_from_loader makes one whenever given a loader
        raise ExerciseFileError(f"{path}: cannot be loaded as a module")
    module = importlib.util.module_from_spec(spec)
    try:
        with templates_checked_by_caller():
            loader.exec_module(module)
    except SyntaxError as error:
        raise ExerciseFileError(f"{path}, line {error.lineno}: {error.msg}") from None
    except Exception as error:
        kind = "" if isinstance(error, DynagradeError) else f"{type(error).__name__}: "
        raise ExerciseFileError(f"{path}, line {line_of_error(path, error)}: {kind}{error}") \
            from None
    return module


def _require_valid_templates(path: Path, source: bytes, exercise: Exercise) -> None:
    """The exercise's templates compile and name only what they may, else the file's
    error at the line where ``EXERCISE`` is built."""
    try:
        exercise.check_templates()
    except DefinitionError as error:
        line = line_of_assignment(source, "EXERCISE") or "?"
        raise ExerciseFileError(f"{path}, line {line}: {error}") from None


def _require_readable_formulas(path: Path, exercise_id: str, problems) -> None:
    """Raise the first of ``problems`` (``(part name, problem)``) as the file's error,
    at the line where the part's name is written."""
    unreadable = next(iter(problems), None)
    if unreadable is not None:
        part_name, problem = unreadable
        line = line_of_string(path.read_bytes(), part_name) or "?"
        raise ExerciseFileError(f"{path}, line {line}: exercise {exercise_id!r}, part "
                                f"{part_name!r}: {problem}")


class _SourceLoader(importlib.machinery.SourceFileLoader):
    """Runs the bytes that were hashed, never a cached ``.pyc`` of the path: an edit
    within the same second and of the same size would otherwise load the old code.
    (A :class:`~importlib.machinery.SourceFileLoader` rather than an ``importlib.abc``
    one: importing ``importlib.abc`` imports ``tempfile`` and more, 10 ms of a cold
    ``grade FILE``.)"""

    def __init__(self, fullname: str, path: Path, source: bytes):
        super().__init__(fullname, str(path))
        self.source = source

    def get_data(self, path: str) -> bytes:
        return self.source if path == self.path else super().get_data(path)

    def get_code(self, fullname: str):
        return self.source_to_code(self.source, self.path)


@dataclass
class Bank:
    """The exercises found on the search path, by id, loaded when first asked for."""

    folders: list[Path]

    def __post_init__(self):
        self._files: dict[str, Path] | None = None

    def _index(self) -> dict[str, Path]:
        """Candidate file for each id, from the ids the files declare as text; a file
        that declares none as a literal (a computed or malformed id, or no exercise at
        all) is loaded to learn its id, so that it fails loudly or is found."""
        if self._files is None:
            self._files = {}
            for folder in reversed(self.folders):  # earlier folders override later ones
                found: dict[str, tuple[Path, int | str]] = {}
                for path in exercise_files(folder):
                    for exercise_id, line in _declared_ids(path):
                        if exercise_id in found:
                            first, first_line = found[exercise_id]
                            raise ExerciseFileError(
                                f"{path}, line {line}: exercise id {exercise_id!r} is "
                                f"declared by both {first}, line {first_line} and {path}, "
                                f"line {line}; ids are unique within a folder")
                        found[exercise_id] = (path, line)
                self._files.update({i: path for i, (path, _) in found.items()})
        return self._files

    def get(self, exercise_id: str, *, templates: bool = True) -> Exercise:
        """The exercise with this id; a clear error, with suggestions, when there is none.
        ``templates=False``: its templates are not checked (:func:`load_file`)."""
        path = self._index().get(exercise_id)
        if path is not None:
            exercise = load_file(path, templates=templates)
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
        exercises: dict[str, Exercise] = {}
        for path in sorted(set(self._index().values())):
            exercise = load_file(path)
            if exercise.id in exercises:  # an id its file does not declare as a literal
                raise ExerciseFileError(
                    f"{path}: exercise id {exercise.id!r} is also the id of "
                    f"{exercises[exercise.id].path}; ids are unique")
            exercises[exercise.id] = exercise
        return sorted(exercises.values(), key=_listing_order)

    def ids(self) -> list[str]:
        """The ids the exercise files declare, sorted; no file is loaded."""
        return sorted(self._index())

    def listing(self) -> list[ExerciseListing]:
        """What ``dynagrade list`` shows of every exercise, in the order of :meth:`all`,
        read from the files without running them where they allow it (see
        :mod:`dynagrade.exercise.listing`); a listing renders no template, so a file that
        has to be run is not checked for them, as a file read statically is not."""
        listings: dict[str, ExerciseListing] = {}
        for path in sorted(set(self._index().values())):
            listing = read_listing(path) or ExerciseListing.of(load_file(path, templates=False))
            _require_readable_formulas(Path(path), listing.id,
                                       written_formula_problems(listing.formulas))
            listings.setdefault(listing.id, listing)
        return sorted(listings.values(), key=_listing_order)


def _declared_ids(path: Path) -> list[tuple[str, int | str]]:
    """``(id, line)`` for each id the file at ``path`` declares as a literal; when it
    declares none, the id of the exercise the file defines (the file is loaded, which
    raises a clear error for a file that defines none or a malformed one)."""
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as error:
        raise ExerciseFileError(f"{path}: cannot read the file ({error})") from None
    declared: list[tuple[str, int | str]] = [(match.group(1), text.count("\n", 0, match.start()) + 1)
                for match in _DECLARED_ID.finditer(text)
                if _starts_a_word(text, match.start())]
    if declared:
        return declared
    exercise = load_file(path)
    return [(exercise.id, line_of_string(text, exercise.id) or "?")]


def _starts_a_word(text: str, index: int) -> bool:
    """Whether no letter, digit or ``_`` comes right before ``text[index]``."""
    return index == 0 or not (text[index - 1].isalnum() or text[index - 1] == "_")


def open_bank(extra_folders: Iterable[str | os.PathLike] = ()) -> Bank:
    """The bank on the search path (see the module docstring)."""
    return Bank(search_path(extra_folders))


def _listing_order(exercise) -> tuple:
    """Chapter, then the numbers of the source ("Example 1.13" after "Example 1.9"), then id."""
    numbers = tuple(int(n) for n in re.findall(r"\d+", exercise.source))
    return exercise.chapter, numbers, exercise.id

