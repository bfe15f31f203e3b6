"""The work of one student in an exam generation: their variant of every exercise, the
fill-in files and figures, and the sheet as Markdown, HTML and PDF.

It comes in two steps, each run in a worker process (:mod:`dynagrade.runs.workers`) with the
generation's run: :func:`student_variants` chooses the variants (what the manifest and
the answer keys need), :func:`student_files` writes the student's folder and returns the
manifest entry and the typst body of their sheet (for the printing PDF, should the PDFs
not embed). :func:`student_job` does both at once.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field

from ..exercise.model import Exercise, Variant
from ..exercise.seeds import variant_token
from ..exercise.sheet import figure_file_name, write_sheet
from ..exercise.units import pretty_unit
from ..render.pdf import ACCESSIBLE
from ..render.sheets import (SheetExercise, SheetPart, StudentSheet, sheet_html,
                             sheet_markdown, sheet_typst_body, typst_preamble)
from ..runs.files import write_atomic
from ..exam.manifest import StudentEntry, VariantEntry
from .run import GenerationRun
from .solutions import write_solution_sheet
from ..exam.spec import ExamExercise, Student
from .variants import exam_variant


@dataclass(frozen=True)
class StudentResult:
    """What one student's job hands back: the manifest entry, the sheet's typst body,
    with ``--solutions`` the solution sheet's, and the CPU seconds the job spent per
    stage (:data:`STAGES`; CPU rather than wall time, which says little on a shared
    machine)."""

    entry: StudentEntry
    body: str
    solution_body: str | None = None
    timings: dict[str, float] = field(default_factory=dict)


#: the stages of a student's work, as :attr:`StudentResult.timings` names them: choosing
#: and checking the variants, drawing the figures, writing the sheets (Markdown, HTML,
#: typst source), compiling the PDF and everything else (fill-in files, the solution
#: sheet)
STAGES = ("variants", "figures", "sheets", "PDFs", "the rest")


@dataclass(frozen=True)
class StudentVariants:
    """A student's variants, one per exercise of the exam in its order, with the manifest
    entry that records them and the CPU seconds choosing them took."""

    student: Student
    variants: tuple[Variant, ...]
    entry: StudentEntry
    seconds: float


def student_variants(run: GenerationRun, student: Student) -> StudentVariants:
    """The variant of every exercise handed to ``student`` (:func:`.variants.exam_variant`:
    redrawn while it cannot tell right from wrong)."""
    started = time.process_time()
    variants, entries = [], []
    for item in run.spec.exercises:
        exercise = run.exercises[item.id]
        variant, redraws = exam_variant(exercise, run.spec.secret, run.spec.id,
                                        student.student_id, item.set, run.problems)
        variants.append(variant)
        entries.append(VariantEntry(exercise.id, variant.seed, variant.params,
                                    dict(variant.answers), redraws))
    entry = StudentEntry(student.student_id, student.name, student.email, tuple(entries))
    return StudentVariants(student, tuple(variants), entry, time.process_time() - started)


def student_files(run: GenerationRun, chosen: StudentVariants) -> StudentResult:
    """The fill-in files, figures, sheets and the PDF of a student whose variants are
    ``chosen``."""
    started = time.process_time()
    student = chosen.student
    timings = dict.fromkeys(STAGES, 0.0)
    sheet_exercises, solved = [], []
    for number, (item, variant) in enumerate(zip(run.spec.exercises, chosen.variants), 1):
        exercise = run.exercises[item.id]
        sheet_exercises.append(_exercise_files(run, student, number, item, exercise, variant,
                                               timings))
        solved.append((exercise, variant))
    sheet = StudentSheet(run.spec.to_json(), student.student_id, student.name,
                         tuple(sheet_exercises))
    body = _write_sheets(run, student, sheet, timings)
    solution_body = None
    if run.solutions:
        solution_body = write_solution_sheet(run, student, solved)
    timings["the rest"] = time.process_time() - started - sum(timings.values())
    timings["variants"] = chosen.seconds
    return StudentResult(chosen.entry, body, solution_body, timings)


def student_job(run: GenerationRun, student: Student) -> StudentResult:
    """Variants, fill-in files, figures, sheets and the PDF of ``student``, in one go."""
    return student_files(run, student_variants(run, student))


def _exercise_files(run: GenerationRun, student: Student, number: int, item: ExamExercise,
                    exercise: Exercise, variant: Variant,
                    timings: dict[str, float]) -> SheetExercise:
    """The fill-in file and, beside it, the figure of one exercise; its section of the
    sheet (whose Markdown links the same figure file)."""
    folder = run.out_dir / "students" / student.student_id
    scaled = run.parts[exercise.id]
    fill_in = f"{exercise.id}.py"
    token = (variant_token(run.spec.secret, run.spec.id, student.student_id, exercise.id,
                           variant.seed) if run.spec.mode == "exam" else None)
    started = time.process_time()
    svg = run.figures(exercise, variant)
    timings["figures"] += time.process_time() - started
    figure_file = None
    if svg is not None:
        figure_file = figure_file_name(exercise)
        write_atomic(folder / figure_file, svg)
    write_atomic(folder / fill_in, write_sheet(exercise, variant, student.student_id, fill_in,
                                               {entry.name: entry.points for entry in scaled},
                                               token=token, exam_id=run.spec.id,
                                               figure=figure_file))
    parts = tuple(SheetPart(entry.name, entry.label, entry.kind, pretty_unit(entry.unit),
                            entry.points, part.input_hint())
                  for entry, part in zip(scaled, exercise.parts))
    return SheetExercise(number, exercise.id, exercise.title, exercise.source, item.points,
                         variant.statement, parts, fill_in, svg, figure_file,
                         exercise.figure_to_scale)


def _write_sheets(run: GenerationRun, student: Student, sheet: StudentSheet,
                  timings: dict[str, float]) -> str:
    """sheet.md, sheet.html and (with PDFs) sheet.pdf; returns the typst body."""
    started = time.process_time()
    folder = run.out_dir / "students" / student.student_id
    write_atomic(folder / "sheet.md", sheet_markdown(sheet))
    write_atomic(folder / "sheet.html", sheet_html(sheet))
    body = sheet_typst_body(sheet)
    source = typst_preamble(run.spec.to_json()) + body
    timings["sheets"] += time.process_time() - started
    if run.pdf:
        started = time.process_time()
        write_atomic(folder / "sheet.pdf", run.compiler.compile(source, standards=ACCESSIBLE))
        timings["PDFs"] += time.process_time() - started
    return body
