"""Generating an exam: every student's variants, sheets, fill-in files, PDFs, answer keys,
the Moodle export and the manifest that grading reads.

Output folder::

    manifest.json                   the exam, exercises (file hash, parts, points) and every
                                    student's variants: seed, parameters, reference answers
    students/<student_id>/sheet.pdf, sheet.html, sheet.md, <exercise-id>.py,
                          figures/<exercise-id>.svg
    sheets.pdf                      every student's sheet, for printing (the students' PDFs
                                    embedded page by page)
    key.csv, key.pdf                answer keys
    moodle.xml                      a question category per exercise, a question per variant

Work per student runs in a pool of processes (``jobs``); results are put together in
roster order, so the files do not depend on the pool. Every file is written atomically and
the manifest last: a folder with a manifest holds a whole exam.
"""

from __future__ import annotations

import hashlib
import os
import re
import time
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

from .. import __name__ as _package
from ..exercise.figure import figure_svg
from ..exercise.loader import Bank, ExerciseFileError, load_file, open_bank
from ..exercise.model import ConstraintError, Exercise
from ..exercise.sheet import write_sheet
from ..exercise.units import pretty_unit
from ..render.sheets import (SheetExercise, SheetPart, StudentSheet, sheet_html,
                             sheet_markdown, sheet_typst_body, typst_preamble)
from .files import write_atomic
from .manifest import (ExamEntry, ExerciseEntry, Generator, Manifest, PartEntry,
                       StudentEntry, VariantEntry, dump)
from .spec import ExamSpec, ExamSpecError, Student, read_exam_spec, read_roster
from .variants import exam_variant

Progress = Callable[[str, int, int], None]


@dataclass
class GenerationReport:
    """What a run produced, with timings in seconds per stage."""

    out_dir: Path
    students: int
    variants: int
    redraws: int
    timings: dict[str, float] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)


# -- the work of one student (runs in a worker process) ----------------------------------

_STATE: dict = {}


def _init_worker(spec: ExamSpec, paths: dict[str, str], parts: dict, out_dir: str,
                 pdf: bool) -> None:
    exercises = {}
    for exercise_id, path in paths.items():
        exercises[exercise_id] = load_file(path)
    _STATE.update(spec=spec, exercises=exercises, parts=parts, out_dir=Path(out_dir), pdf=pdf,
                  preamble=typst_preamble(spec.to_json()))


def _student_job(student: Student) -> dict:
    """Variants, figures, sheets and the PDF of one student; returns the manifest entry
    and the typst body (for the combined PDF)."""
    spec: ExamSpec = _STATE["spec"]
    folder = _STATE["out_dir"] / "students" / student.student_id
    entries, sheet_exercises = [], []
    for number, item in enumerate(spec.exercises, 1):
        exercise: Exercise = _STATE["exercises"][item.id]
        variant, redraws = exam_variant(exercise, spec.id, student.student_id, item.set)
        entries.append(VariantEntry(exercise.id, variant.seed, variant.params,
                                    dict(variant.answers), redraws))
        fill_in = f"{exercise.id}.py"
        scaled = {entry.name: entry.points for entry in _STATE["parts"][exercise.id]}
        write_atomic(folder / fill_in,
                     write_sheet(exercise, variant, student.student_id, fill_in, scaled))
        svg = _figure(exercise, variant)
        figure_file = None
        if svg is not None:
            figure_file = f"figures/{exercise.id}.svg"
            write_atomic(folder / figure_file, svg)
        parts = tuple(SheetPart(entry.name, entry.label, entry.kind,
                                pretty_unit(entry.unit) if entry.unit else "", entry.points,
                                part.input_hint())
                      for entry, part in zip(_STATE["parts"][exercise.id], exercise.parts))
        sheet_exercises.append(SheetExercise(number, exercise.id, exercise.title,
                                             exercise.source, item.points, variant.statement,
                                             parts, fill_in, svg, figure_file))
    sheet = StudentSheet(spec.to_json(), student.student_id, student.name,
                         tuple(sheet_exercises))
    write_atomic(folder / "sheet.md", sheet_markdown(sheet))
    write_atomic(folder / "sheet.html", sheet_html(sheet))
    body = sheet_typst_body(sheet)
    if _STATE["pdf"]:
        write_atomic(folder / "sheet.pdf", compile_pdf(_STATE["preamble"] + body))
    entry = StudentEntry(student.student_id, student.name, student.email, tuple(entries))
    return {"entry": entry, "body": body}


_FIGURES: dict[tuple, str | None] = {}


def _figure(exercise: Exercise, variant) -> str | None:
    key = (exercise.id, tuple(sorted(variant.params.items())))
    if key not in _FIGURES:
        if len(_FIGURES) > 2000:
            _FIGURES.clear()
        _FIGURES[key] = figure_svg(exercise, variant)
    return _FIGURES[key]


_COMPILERS: dict[str, object] = {}


def compile_pdf(source: str, root: str | None = None) -> bytes:
    """A typst document compiled in-process, with typst's own fonts only (the same PDF on
    every machine; no package downloads). One compiler per process and root is kept: it
    holds the loaded fonts and typst's caches, which makes later documents ~2x faster."""
    import typst

    key = root or ""
    if key not in _COMPILERS:
        _COMPILERS[key] = typst.Compiler(root=root, ignore_system_fonts=True)
    return _COMPILERS[key].compile(input=source.encode("utf-8"))


def _compile_to(path: str, source: str, root: str | None = None) -> str:
    write_atomic(path, compile_pdf(source, root))
    return path


_PAGE = re.compile(rb"/Type\s*/Page\b")


def combined_source(out: Path, student_ids: list[str], fallback: Callable[[], str]) -> str:
    """The typst source of the printing PDF: every student's own PDF, page by page, as
    embedded vector pages (no second layout of the sheets). ``fallback()`` gives a source
    that lays the sheets out again, used when a page count cannot be read."""
    lines = ['#set page(paper: "a4", margin: 0pt, header: none, numbering: none)']
    for student_id in student_ids:
        path = out / "students" / student_id / "sheet.pdf"
        pages = len(_PAGE.findall(path.read_bytes()))
        if pages == 0:
            return fallback()
        for page in range(1, pages + 1):
            lines.append(f'#page(image("/students/{student_id}/sheet.pdf", page: {page}, '
                         'width: 100%))')
    return "\n".join(lines) + "\n"


# -- the whole exam -----------------------------------------------------------------------


def file_sha256(path: str | os.PathLike) -> str:
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()


def load_exam(exam_path, roster_path, bank: Bank | None = None):
    """The exam spec, the roster and the exercises by id; errors as :class:`ExamSpecError`."""
    bank = bank or open_bank()

    def known(exercise_id):
        try:
            return bank.get(exercise_id)
        except ExerciseFileError as error:
            raise KeyError(str(error)) from None

    spec = read_exam_spec(exam_path, known)
    roster = read_roster(roster_path)
    exercises = {item.id: bank.get(item.id) for item in spec.exercises}
    for item in spec.exercises:
        if item.set:
            try:
                exercises[item.id].draw(0, item.set)
            except ConstraintError as error:
                raise ExamSpecError(f"{spec.path}, line {item.line}, [[exercise]] {item.id}, "
                                    f"field 'set': the values set break a constraint: "
                                    f"{error}") from None
    return spec, roster, exercises


def exercise_parts(exercise: Exercise, points: float) -> tuple[PartEntry, ...]:
    """The parts of ``exercise`` with points scaled so that they sum to ``points``."""
    total = sum(p.points for p in exercise.parts)
    scale = points / total if total else 0.0
    return tuple(PartEntry(part.name, part.label or part.name, part.kind, part.unit,
                           part.points * scale,
                           **{name: getattr(part, name) for name in part.manifest_fields})
                 for part in exercise.parts)


def generate_exam(exam_path, roster_path, out_dir, bank: Bank | None = None,
                  jobs: int | None = None, pdf: bool = True,
                  progress: Progress | None = None) -> GenerationReport:
    """Write the whole exam into ``out_dir`` (see the module docstring)."""
    from ..render.keys import key_csv, key_typst
    from ..render.moodle import moodle_xml

    started = time.perf_counter()
    out = Path(out_dir)
    progress = progress or (lambda stage, done, total: None)
    spec, roster, exercises = load_exam(exam_path, roster_path, bank)
    parts = {item.id: exercise_parts(exercises[item.id], item.points)
             for item in spec.exercises}
    paths = {exercise_id: exercise.path for exercise_id, exercise in exercises.items()}
    report = GenerationReport(out, len(roster), len(roster) * len(spec.exercises), 0)
    report.timings["load"] = time.perf_counter() - started

    jobs = max(1, jobs if jobs is not None else min(2, os.cpu_count() or 1))
    init_args = (spec, paths, parts, str(out), pdf)
    stage = time.perf_counter()
    results = []
    executor = _executor(jobs, init_args)
    try:
        if executor is None:
            _init_worker(*init_args)
            mapped = map(_student_job, roster)
        else:
            mapped = executor.map(_student_job, roster, chunksize=4)
        for done, result in enumerate(mapped, 1):
            results.append(result)
            progress("students", done, len(roster))
        report.timings["students"] = time.perf_counter() - stage

        manifest = build_manifest(spec, exercises, parts, [r["entry"] for r in results])
        report.redraws = sum(len(v.redraws) for s in manifest.students for v in s.variants)
        stage = time.perf_counter()
        write_atomic(out / "key.csv", key_csv(manifest))
        write_atomic(out / "moodle.xml", moodle_xml(manifest, exercises))
        if pdf:
            key_source = typst_preamble(spec.to_json(), f"{spec.title}: answer key") \
                + key_typst(manifest)
            key_job = (executor.submit(_compile_to, str(out / "key.pdf"), key_source)
                       if executor is not None else None)
            preamble = typst_preamble(spec.to_json(), f"{spec.title}: all sheets")
            combined = combined_source(
                out, [s.student_id for s in roster],
                lambda: preamble + "\n#pagebreak(weak: true)\n".join(r["body"] for r in results))
            if not combined.startswith("#set document"):
                combined = preamble + combined
            try:
                _compile_to(str(out / "sheets.pdf"), combined, str(out.resolve()))
            except Exception:  # a typst without PDF images: lay the sheets out again
                _compile_to(str(out / "sheets.pdf"), preamble + "\n#pagebreak(weak: true)\n"
                            .join(r["body"] for r in results))
            progress("combined PDFs", 1, 2)
            if key_job is None:
                _compile_to(str(out / "key.pdf"), key_source)
            else:
                key_job.result()
            progress("combined PDFs", 2, 2)
        report.timings["keys, moodle, combined PDFs"] = time.perf_counter() - stage
    finally:
        if executor is not None:
            executor.shutdown()
    dump(manifest, out / "manifest.json")
    report.timings["total"] = time.perf_counter() - started
    return report


def _executor(jobs: int, init_args) -> ProcessPoolExecutor | None:
    if jobs <= 1:
        return None
    import multiprocessing

    methods = multiprocessing.get_all_start_methods()
    context = multiprocessing.get_context("fork" if "fork" in methods else "spawn")
    return ProcessPoolExecutor(max_workers=jobs, mp_context=context,
                               initializer=_init_worker, initargs=init_args)


def build_manifest(spec: ExamSpec, exercises: dict[str, Exercise],
                   parts: dict[str, tuple[PartEntry, ...]],
                   students: list[StudentEntry]) -> Manifest:
    """The manifest: everything grading needs, independent of later code or numpy."""
    import numpy

    described = tuple(
        ExerciseEntry(exercises[item.id].id, exercises[item.id].title,
                      exercises[item.id].source, item.points, dict(item.set),
                      "/".join(Path(exercises[item.id].path).parts[-2:]),
                      file_sha256(exercises[item.id].path), parts[item.id])
        for item in spec.exercises)
    exam = ExamEntry(spec.id, spec.title, spec.date, spec.instructions, spec.total_points,
                     spec.policy.to_json() if spec.policy != type(spec.policy)() else None)
    return Manifest(Generator(_version(), numpy.__version__), exam, described,
                    tuple(students))


def _version() -> str:
    try:
        from importlib.metadata import version

        return version(_package)
    except Exception:  # running from a source tree that is not installed
        return "source"
