"""Re-keying an exam: every student's reference answers computed again from the
exercise file as it is now, for named exercises, without drawing new variants.

After an exercise's solver is fixed, the manifest still holds the reference answers the
old solver gave; the server and ``dynagrade grade`` grade against those. :func:`rekey`
recomputes them with each variant's stored seed and the exam's ``set`` parameters,
exactly as ``dynagrade exam`` drew them (:func:`dynagrade.generation.variants.exam_variant`
keeps the seed of the draw it handed out). It refuses, writing nothing, when any
variant's parameters would come out different: the sheets the students hold show those
numbers, and a key for other numbers would grade them against a problem they were never
given. Otherwise it rewrites ``manifest.json`` atomically (a server reading it sees the
old file or the new one) with, for the named exercises, the new answers, the file's
digest and the parts' grading settings (tolerances), and ``key.csv`` beside it (a
text made from the manifest alone: a stale one next to a new key would mislead whoever
checks by hand). What a compiler renders (``key.pdf``, ``moodle.xml``, the sheets and
worked solutions) is not rendered again.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Mapping

from ..errors import DynagradeError
from ..exam.manifest import ExerciseEntry, Manifest, PartEntry, StudentEntry, dump, load
from ..exercise.loader import Bank
from ..exercise.model import ConstraintError, Exercise
from ..runs.caches import file_sha256
from ..runs.files import write_atomic

#: how many students a refusal names before "and N more"
NAMED = 3


class RekeyRefused(DynagradeError):
    """The manifest cannot be re-keyed as asked; nothing was written."""


@dataclass(frozen=True)
class Rekeyed:
    """What re-keying one exercise changed: how many students' keys, of how many, and
    the parts whose answers changed."""

    exercise_id: str
    changed: int
    students: int
    parts: tuple[str, ...]

    def line(self) -> str:
        parts = f" ({', '.join(self.parts)})" if self.parts else ""
        return (f"{self.exercise_id}: {self.changed} of {self.students} students' keys "
                f"changed{parts}")


def rekey(manifest_path: str | Path, exercise_ids: list[str], bank: Bank,
          write_key_csv: bool = True) -> list[Rekeyed]:
    """Re-key ``exercise_ids`` of the manifest at ``manifest_path`` from the ``bank``'s
    files (see the module docstring); :class:`RekeyRefused` (nothing written) when an id
    is not the exam's or a variant's parameters would change."""
    path = Path(manifest_path)
    manifest = load(path)
    unknown = [i for i in exercise_ids if manifest.exercise(i) is None]
    if unknown:
        raise RekeyRefused(f"{path}: no exercise {unknown[0]!r} in this exam; its exercises "
                           f"are {', '.join(manifest.exercise_ids)}")
    exercises = {i: bank.get(i) for i in dict.fromkeys(exercise_ids)}
    report = []
    for exercise in exercises.values():
        manifest, done = _rekey_exercise(manifest, exercise)
        report.append(done)
    dump(manifest, path)
    key = path.parent / "key.csv"
    if write_key_csv and key.exists():
        from ..render.keys import key_csv

        write_atomic(key, key_csv(manifest, _loaded(manifest, bank, exercises)), private=True)
    return report


def _loaded(manifest: Manifest, bank: Bank, have: dict[str, Exercise]) -> dict[str, Exercise]:
    """Every exercise of the exam (key.csv names each variant's given values)."""
    return {e.id: have.get(e.id) or bank.get(e.id, templates=False)
            for e in manifest.exercises}


def _rekey_exercise(manifest: Manifest, exercise: Exercise) -> tuple[Manifest, Rekeyed]:
    described = manifest.exercise(exercise.id)
    assert described is not None
    parts = _parts(described, exercise)
    moved: list[str] = []
    students, changed_parts, changed = [], set(), 0
    for student in manifest.students:
        entry = student.variant(exercise.id)
        if entry is None:
            students.append(student)
            continue
        try:
            variant = exercise.variant(int(entry.seed), dict(described.set) or None,
                                       with_statement=False)
        except ConstraintError as error:
            moved.append(f"{student.student_id}: the stored seed no longer gives a "
                         f"variant ({error})")
            continue
        differ = _differing_params(entry.params, variant.params)
        if differ:
            moved.append(f"{student.student_id}: " + ", ".join(differ))
            continue
        answers = {name: entry.answers.get(name) for name in entry.answers}
        for name, new in variant.answers.items():
            if name not in answers or not same_answer(answers[name], new):
                answers[name] = _stored(new)
                changed_parts.add(name)
        if answers != dict(entry.answers):
            changed += 1
        variants = tuple(dataclasses.replace(v, answers=answers) if v is entry else v
                         for v in student.variants)
        students.append(StudentEntry(student.student_id, student.name, student.email,
                                     variants))
    if moved:
        more = f"; and {len(moved) - NAMED} more" if len(moved) > NAMED else ""
        raise RekeyRefused(
            f"{exercise.id}: the parameters of {len(moved)} students' variants would change "
            f"({'; '.join(moved[:NAMED])}{more}), so their sheets would no longer match the "
            "key; nothing was written. Keep the parameters, their draw and the constraints "
            "of the exercise as they were; only the solver and the parts' tolerances may "
            "change")
    fresh = dataclasses.replace(described, sha256=file_sha256(exercise.file), parts=parts)
    exercises = tuple(fresh if e is described else e for e in manifest.exercises)
    order = [p.name for p in exercise.parts]
    names = tuple(sorted(changed_parts, key=order.index))
    counted = sum(1 for s in manifest.students if s.variant(exercise.id) is not None)
    return (dataclasses.replace(manifest, exercises=exercises, students=tuple(students)),
            Rekeyed(exercise.id, changed, counted, names))


def _parts(described: ExerciseEntry, exercise: Exercise) -> tuple[PartEntry, ...]:
    """The exam's parts with the grading settings the file gives them now (points and
    labels stay the exam's); refused when the parts themselves differ."""
    now = {p.name: p for p in exercise.parts}
    out = []
    for entry in described.parts:
        part = now.get(entry.name)
        if part is None or part.kind != entry.kind or (part.unit or None) != (entry.unit or None):
            raise RekeyRefused(
                f"{exercise.id}: part {entry.name!r} ({entry.kind}, unit {entry.unit!r}) is "
                "no longer in the exercise file as the exam has it; the students' sheets ask "
                "for it. Nothing was written")
        out.append(dataclasses.replace(entry, **{name: _stored(getattr(part, name))
                                                 for name in part.manifest_fields}))
    return tuple(out)


def _differing_params(stored: Mapping[str, Any], drawn: Mapping[str, float]) -> list[str]:
    """``name old → new`` for each parameter whose value differs (or that is new or gone)."""
    out = []
    for name in sorted(set(stored) | set(drawn)):
        old, new = stored.get(name), drawn.get(name)
        if old is None or new is None or not same_answer(old, new):
            out.append(f"{name} {old!r} → {new!r}")
    return out


def same_answer(old: Any, new: Any) -> bool:
    """Whether two stored values are the same: numbers equal to 12 significant figures
    (a solver run again may differ in the last bit), vectors component by component,
    anything else equal."""
    if isinstance(old, (list, tuple)) and isinstance(new, (list, tuple)):
        return len(old) == len(new) and all(same_answer(a, b) for a, b in zip(old, new))
    numbers = (int, float)
    if isinstance(old, numbers) and isinstance(new, numbers) \
            and not isinstance(old, bool) and not isinstance(new, bool):
        return math.isclose(float(old), float(new), rel_tol=1e-12, abs_tol=0.0)
    return old == new


def _stored(value: Any) -> Any:
    """A value as the manifest's records hold it (vectors and option sets as tuples)."""
    return tuple(value) if isinstance(value, list) else value
