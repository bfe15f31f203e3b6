"""The exam manifest: typed, frozen records of everything grading needs, and its file.

``dynagrade exam`` writes ``manifest.json``; ``dynagrade grade --manifest``, the answer
keys, the Moodle export and the server read it. Every reader takes the records below,
never the JSON dict: this module is the only place that knows the file's field names.

Usage::

    manifest = load("out/manifest.json")          # ManifestError names any bad field
    for student in manifest.students:
        for variant in student.variants:
            variant.answers["x_max"]
    dump(manifest, "copy/manifest.json")

Shape (``docs/exams.md`` shows a whole file)::

    Manifest        format, version, generator, exam, exercises[], students[]
    ExamEntry       id, title, date, instructions, [policy], [language], points,
                    [secret], [round]
    ExerciseEntry   id, title, source, points, set, file, sha256, parts[]
    PartEntry       name, label, kind, unit, points, and the settings its kind
                    stores (``Part.manifest_fields``: rtol/atol, size, options/multiple)
    StudentEntry    student_id, name, email, variants[]
    VariantEntry    exercise, seed, params, answers, redraws[]
    Redraw          seed, problems

Reading checks every field and names the path of a bad one, e.g.
``students[3].variants[1]: missing 'answers'``, so a hand-edited or older manifest fails
with a located :class:`ManifestError` rather than a ``KeyError`` deep inside grading.

Format version and when it changes
----------------------------------
``format`` is always ``"dynagrade-exam-manifest"``; ``version`` is :data:`VERSION`.

- Adding an optional field (one with a default here) does **not** change the version:
  older readers ignore it, this reader fills in the default when it is absent.
- Removing or renaming a field, changing its type, unit or meaning, or making a new
  field required **bumps** the version by one. The reader then keeps accepting every
  older version by upgrading its dict, one function per step, before checking it.
- A manifest with a version newer than :data:`VERSION` is refused with a message that
  asks for a newer dynagrade.
"""

from __future__ import annotations

import json
import os
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable, Mapping, TypeGuard, TypeVar

from ..errors import DynagradeError
from ..exercise.parts import PART_KINDS
from .points import DEFAULT_STEP

FORMAT = "dynagrade-exam-manifest"
VERSION = 1

__all__ = ["FORMAT", "VERSION", "ManifestError", "Manifest", "Generator", "ExamEntry",
           "ExerciseEntry", "PartEntry", "StudentEntry", "VariantEntry", "Redraw", "load",
           "dump", "from_dict", "to_dict", "text"]


_T = TypeVar("_T")


class ManifestError(DynagradeError, ValueError):
    """The manifest cannot be used; the message names the file and the field at fault."""


# -- records ------------------------------------------------------------------------------


@dataclass(frozen=True)
class Redraw:
    """A seed that was drawn for a student but not handed out, and why."""

    seed: int
    problems: tuple[str, ...]


@dataclass(frozen=True)
class VariantEntry:
    """One student's variant of one exercise: the seed, the parameters (declared units)
    and the reference answers (the parts' units; vectors and several options as tuples)."""

    exercise: str
    seed: int
    params: Mapping[str, Any]
    answers: Mapping[str, Any]
    redraws: tuple[Redraw, ...] = ()


@dataclass(frozen=True)
class StudentEntry:
    """A roster student and their variant of every exercise, in exam order."""

    student_id: str
    name: str
    email: str
    variants: tuple[VariantEntry, ...]

    def variant(self, exercise_id: str) -> VariantEntry | None:
        """The student's variant of ``exercise_id`` (None when the exam has no such)."""
        return next((v for v in self.variants if v.exercise == exercise_id), None)


@dataclass(frozen=True)
class PartEntry:
    """An answer part as the exam grades it: points already scaled to the exam's points.

    The settings after ``points`` are present as the part's kind stores them (its
    ``manifest_fields``); the others stay None.
    """

    name: str
    label: str
    kind: str
    unit: str | None
    points: float
    rtol: float | None = None
    atol: float | None = None
    size: int | None = None
    options: tuple[str, ...] | None = None
    multiple: bool | None = None


@dataclass(frozen=True)
class ExerciseEntry:
    """An exercise of the exam: where it came from (file and its SHA-256) and its parts."""

    id: str
    title: str
    source: str
    points: float
    set: Mapping[str, Any]
    file: str
    sha256: str
    parts: tuple[PartEntry, ...]

    def part(self, name: str) -> PartEntry | None:
        return next((p for p in self.parts if p.name == name), None)


@dataclass(frozen=True)
class ExamEntry:
    """The exam itself: id, title, ISO date, instructions and its total points.

    ``policy`` (optional, written only when set) holds how a server delivers the exam,
    as ``exam.toml`` declared it; this module keeps it as the JSON object it is.
    ``secret`` (optional: manifests written before exams had secrets lack it) keys the
    students' seeds and variant tokens (:mod:`dynagrade.exercise.seeds`)."""

    id: str
    title: str
    date: str
    instructions: str
    points: float
    policy: Mapping[str, Any] | None = None
    language: str = "en"  # written only when not "en"
    secret: str | None = None
    #: points are multiples of this step (exam.toml's ``round``/``decimals``); written as
    #: ``round`` only when not the default hundredths
    rounding: float = DEFAULT_STEP


@dataclass(frozen=True)
class Generator:
    """The versions that wrote the manifest (for the record; grading does not need them)."""

    dynagrade: str
    numpy: str


@dataclass(frozen=True)
class Manifest:
    """A whole exam: everything grading needs, independent of later code or numpy."""

    generator: Generator
    exam: ExamEntry
    exercises: tuple[ExerciseEntry, ...]
    students: tuple[StudentEntry, ...]
    format: str = FORMAT
    version: int = VERSION

    def exercise(self, exercise_id: str) -> ExerciseEntry | None:
        return next((e for e in self.exercises if e.id == exercise_id), None)

    @property
    def exercise_ids(self) -> list[str]:
        return [e.id for e in self.exercises]

    @property
    def redraw_count(self) -> int:
        """Draws rejected, over every student and exercise, before a variant was handed out."""
        return sum(len(v.redraws) for s in self.students for v in s.variants)


# -- writing ------------------------------------------------------------------------------


def _plain(value):
    """Tuples (vectors, several options) as JSON lists."""
    return list(value) if isinstance(value, tuple) else value


def _part_dict(part: PartEntry) -> dict[str, Any]:
    entry: dict[str, Any] = {"name": part.name, "label": part.label, "kind": part.kind, "unit": part.unit,
             "points": part.points}
    for name in PART_KINDS[part.kind].manifest_fields:
        entry[name] = _plain(getattr(part, name))
    return entry


def _exam_dict(exam: ExamEntry) -> dict[str, Any]:
    entry: dict[str, Any] = {"id": exam.id, "title": exam.title, "date": exam.date,
             "instructions": exam.instructions}
    if exam.policy is not None:
        entry["policy"] = dict(exam.policy)
    if exam.language != "en":
        entry["language"] = exam.language
    entry["points"] = exam.points
    if exam.secret is not None:
        entry["secret"] = exam.secret
    if exam.rounding != DEFAULT_STEP:
        entry["round"] = exam.rounding
    return entry


def to_dict(manifest: Manifest) -> dict[str, Any]:
    """The manifest as the JSON document stores it."""
    return {
        "format": manifest.format, "version": manifest.version,
        "generator": {"dynagrade": manifest.generator.dynagrade,
                      "numpy": manifest.generator.numpy},
        "exam": _exam_dict(manifest.exam),
        "exercises": [{
            "id": e.id, "title": e.title, "source": e.source, "points": e.points,
            "set": dict(e.set), "file": e.file, "sha256": e.sha256,
            "parts": [_part_dict(p) for p in e.parts],
        } for e in manifest.exercises],
        "students": [{
            "student_id": s.student_id, "name": s.name, "email": s.email,
            "variants": [{
                "exercise": v.exercise, "seed": v.seed, "params": dict(v.params),
                "answers": {k: _plain(a) for k, a in v.answers.items()},
                "redraws": [{"seed": r.seed, "problems": list(r.problems)}
                            for r in v.redraws],
            } for v in s.variants],
        } for s in manifest.students],
    }


def text(manifest: Manifest) -> str:
    """The manifest file's text: JSON, one-space indent, UTF-8 kept, no NaN."""
    return json.dumps(to_dict(manifest), indent=1, ensure_ascii=False,
                      allow_nan=False) + "\n"


def dump(manifest: Manifest, path: str | os.PathLike) -> Path:
    """Write ``manifest`` to ``path`` atomically, readable by its owner only (it holds
    the exam's secret and every student's answers)."""
    from ..runs.files import write_atomic

    return write_atomic(path, text(manifest), private=True)


# -- reading ------------------------------------------------------------------------------


def load(path: str | os.PathLike) -> Manifest:
    """The manifest at ``path``, every field checked; :class:`ManifestError` otherwise."""
    path = Path(path)
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as error:
        raise ManifestError(f"{path}: not a readable exam manifest ({error})") from None
    try:
        return from_dict(data)
    except ManifestError as error:
        raise ManifestError(f"{path}: {error}") from None


def from_dict(data: Any) -> Manifest:
    """The records of a manifest's JSON document; :class:`ManifestError` names the path
    of the first bad field (``students[3].variants[1]: missing 'answers'``)."""
    if not isinstance(data, dict) or data.get("format") != FORMAT:
        raise ManifestError("not a dynagrade exam manifest (written by `dynagrade exam`)")
    version = data.get("version")
    if isinstance(version, bool) or not isinstance(version, int) or version < 1:
        raise ManifestError(f"version: expected a positive whole number, got {version!r}")
    if version > VERSION:
        raise ManifestError(f"version {version} is newer than this dynagrade reads "
                            f"(up to {VERSION}); install a newer dynagrade")
    root = _Object(data, "")
    generator = root.object("generator")
    exam = root.object("exam")
    manifest = Manifest(
        generator=Generator(generator.string("dynagrade"), generator.string("numpy")),
        exam=ExamEntry(exam.string("id"), exam.string("title"), exam.string("date"),
                       exam.string("instructions"), exam.number("points"),
                       exam.optional_mapping("policy"),
                       exam.string("language") if "language" in exam.data else "en",
                       exam.string("secret") if "secret" in exam.data else None,
                       _step(exam) if "round" in exam.data else DEFAULT_STEP),
        exercises=tuple(_exercise(item) for item in root.objects("exercises")),
        students=tuple(_student(item) for item in root.objects("students")),
        version=version)
    _check_references(manifest)
    return manifest


class _Object:
    """A JSON object at ``where`` (``students[3].variants[1]``), read field by field."""

    def __init__(self, data: Any, where: str):
        if not isinstance(data, dict):
            raise ManifestError(f"{where or 'the manifest'}: expected an object, "
                                f"got {_shown(data)}")
        self.data, self.where = data, where

    def path(self, key: str) -> str:
        return f"{self.where}.{key}" if self.where else key

    def _get(self, key: str) -> object:
        if key not in self.data:
            raise ManifestError(f"{self.where or 'the manifest'}: missing {key!r}")
        return self.data[key]

    def _typed(self, key: str, check: Callable[[object], TypeGuard[_T]], expected: str) -> _T:
        value = self._get(key)
        if not check(value):
            raise ManifestError(f"{self.path(key)}: expected {expected}, got {_shown(value)}")
        return value

    def string(self, key: str) -> str:
        return self._typed(key, _is_text, "text")

    def string_or_null(self, key: str) -> str | None:
        return None if self._get(key) is None else self.string(key)

    def number(self, key: str) -> float:
        return self._typed(key, _is_number, "a number")

    def number_or_null(self, key: str) -> float | None:
        return None if self._get(key) is None else self.number(key)

    def integer(self, key: str) -> int:
        return self._typed(key, _is_integer, "a whole number")

    def boolean(self, key: str) -> bool:
        return self._typed(key, _is_boolean, "true or false")

    def strings(self, key: str) -> tuple[str, ...]:
        values = self._typed(key, _is_list, "a list of texts")
        for index, value in enumerate(values):
            if not isinstance(value, str):
                raise ManifestError(f"{self.path(key)}[{index}]: expected text, "
                                    f"got {_shown(value)}")
        return tuple(values)

    def mapping(self, key: str) -> dict[str, Any]:
        return self._typed(key, _is_object, "an object")

    def optional_mapping(self, key: str) -> dict[str, Any] | None:
        """The object at ``key``, None when the field is absent (not when it is null)."""
        return self.mapping(key) if key in self.data else None

    def object(self, key: str) -> _Object:
        return _Object(self._get(key), self.path(key))

    def objects(self, key: str) -> list[_Object]:
        values = self._typed(key, _is_list, "a list")
        return [_Object(value, f"{self.path(key)}[{index}]")
                for index, value in enumerate(values)]


def _step(exam: _Object) -> float:
    step = exam.number("round")
    if not step > 0:
        raise ManifestError(f"{exam.path('round')}: expected a positive number, got {step!r}")
    return float(step)


def _is_number(value: object) -> TypeGuard[float]:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def _is_integer(value: object) -> TypeGuard[int]:
    return isinstance(value, int) and not isinstance(value, bool)


def _is_boolean(value: object) -> TypeGuard[bool]:
    return isinstance(value, bool)


def _is_text(value: object) -> TypeGuard[str]:
    return isinstance(value, str)


def _is_list(value: object) -> TypeGuard[list[Any]]:
    return isinstance(value, list)


def _is_object(value: object) -> TypeGuard[dict[str, Any]]:
    """A JSON object: its keys are always text."""
    return isinstance(value, dict)


def _shown(value) -> str:
    shown = json.dumps(value, ensure_ascii=False) if value is not None else "null"
    return shown if len(shown) <= 40 else shown[:37] + "..."


_SETTING_READERS: dict[str, Callable[[_Object, str], Any]] = {
    "rtol": lambda o, k: o.number(k),
    "atol": lambda o, k: o.number_or_null(k),
    "size": lambda o, k: o.integer(k),
    "options": lambda o, k: o.strings(k),
    "multiple": lambda o, k: o.boolean(k),
}


def _part(item: _Object) -> PartEntry:
    kind = item.string("kind")
    if kind not in PART_KINDS:
        raise ManifestError(f"{item.path('kind')}: unknown part kind {kind!r} (known: "
                            f"{', '.join(sorted(PART_KINDS))})")
    settings = {name: _SETTING_READERS[name](item, name)
                for name in PART_KINDS[kind].manifest_fields}
    return PartEntry(item.string("name"), item.string("label"), kind,
                     item.string_or_null("unit"), item.number("points"), **settings)


def _exercise(item: _Object) -> ExerciseEntry:
    return ExerciseEntry(item.string("id"), item.string("title"), item.string("source"),
                         item.number("points"), item.mapping("set"), item.string("file"),
                         item.string("sha256"),
                         tuple(_part(part) for part in item.objects("parts")))


def _answer(value):
    return tuple(value) if isinstance(value, list) else value


def _variant(item: _Object) -> VariantEntry:
    redraws = tuple(Redraw(r.integer("seed"), r.strings("problems"))
                    for r in item.objects("redraws"))
    answers = {name: _answer(value) for name, value in item.mapping("answers").items()}
    return VariantEntry(item.string("exercise"), item.integer("seed"),
                        item.mapping("params"), answers, redraws)


def _student(item: _Object) -> StudentEntry:
    return StudentEntry(item.string("student_id"), item.string("name"),
                        item.string("email"), tuple(_variant(v) for v in
                                                    item.objects("variants")))


def _check_references(manifest: Manifest) -> None:
    """Every variant names an exercise of the exam and answers each of its parts; no
    exercise or student appears twice."""
    parts = {}
    for index, exercise in enumerate(manifest.exercises):
        if exercise.id in parts:
            raise ManifestError(f"exercises[{index}].id: {exercise.id!r} appears twice")
        parts[exercise.id] = [p.name for p in exercise.parts]
    seen = set()
    for s, student in enumerate(manifest.students):
        if student.student_id in seen:
            raise ManifestError(f"students[{s}].student_id: {student.student_id!r} "
                                "appears twice")
        seen.add(student.student_id)
        for v, variant in enumerate(student.variants):
            where = f"students[{s}].variants[{v}]"
            if variant.exercise not in parts:
                raise ManifestError(f"{where}.exercise: {variant.exercise!r} is not an "
                                    f"exercise of the exam ({', '.join(parts)})")
            missing = [n for n in parts[variant.exercise] if n not in variant.answers]
            if missing:
                raise ManifestError(f"{where}.answers: no answer for the parts {missing}")
