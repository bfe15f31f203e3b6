"""Generating an exam: every student's variants, sheets, fill-in files, PDFs, answer keys,
the Moodle export and the manifest that grading reads.

Output folder::

    manifest.json                   the exam, exercises (file hash, parts, points) and every
                                    student's variants: seed, parameters, reference answers
    students/<student_id>/sheet.pdf, sheet.html, sheet.md, <exercise-id>.py and
                          beside it <exercise-id>.svg (its figure, if it draws one)
    sheets.pdf                      every student's sheet, for printing (the students' PDFs
                                    embedded page by page)
    students/<student_id>/solution.md, solution.html, solution.pdf
    solutions.pdf                   with ``solutions=True`` (``--solutions``): every
                                    student's worked solutions, for the staff
    key.csv, key.pdf                answer keys
    moodle.xml                      a question category per exercise, a question per variant

This module is the driver: it loads the exam into a run (:mod:`.run`), has a pool of
processes (:mod:`dynagrade.runs.workers`) choose every student's variants (:mod:`.student`), which
gives the manifest and the answer keys; while one worker compiles the key's PDF, the
pool writes each student's folder; then the Moodle export (in a worker) and the printing
PDFs, and the manifest. Results are put
together in roster order, so the files do not depend on the pool. Everything is built in
a staging folder beside the output folder and swapped in when complete
(:mod:`dynagrade.runs.outputs`): the output folder holds exactly one whole exam, the one before it is
kept as ``OUT.previous``. A folder that is being served or has a database (in it or
beside it) is never replaced (:func:`dynagrade.runs.outputs.refuse_if_in_use`).
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field, replace
from functools import partial
from pathlib import Path
from typing import Any, Callable, Iterable, Mapping

from .. import __name__ as _package
from ..exercise.loader import Bank, open_bank
from ..exercise.model import ConstraintError, Exercise
from ..exercise.seeds import new_secret
from ..exercise.sheet import figure_file_name
from ..render.pdf import embedded_pages_source
from ..render.sheets import typst_preamble
from ..runs.files import write_atomic
from ..exam.manifest import (ExamEntry, ExerciseEntry, Generator, Manifest, PartEntry,
                       StudentEntry, dump)
from ..runs.outputs import refuse_if_in_use, staging_folder, swap_in
from ..exam.points import Rounding, exam_part_points
from ..runs.caches import file_sha256
from .run import GenerationRun
from .skew import skew_warnings
from .solutions import solutions_title
from ..exam.spec import ExamSpec, ExamSpecError, Student, read_exam_spec, read_roster
from .student import (STAGES, StudentResult, StudentVariants, student_files,
                      student_variants)
from ..runs.workers import Pool, default_jobs

Progress = Callable[[str, int, int], None]

_PAGE_BREAK = "\n#pagebreak(weak: true)\n"
#: students per task handed to a worker: few enough that the two workers end together
_CHUNK = 4


@dataclass
class GenerationReport:
    """What a run produced, with timings in seconds per stage."""

    out_dir: Path
    students: int
    variants: int
    redraws: int
    timings: dict[str, float] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)
    skew: list[str] = field(default_factory=list)  # :func:`.skew.skew_warnings`


def generate_exam(exam_path, roster_path, out_dir, bank: Bank | None = None,
                  jobs: int | None = None, pdf: bool = True,
                  progress: Progress | None = None,
                  secret: str | None = None,
                  solutions: bool = False) -> GenerationReport:
    """Write the whole exam into ``out_dir`` (see the module docstring); ``secret`` keys
    the students' variants (a fresh random one when None, :mod:`dynagrade.exam.secret`)."""
    started = time.perf_counter()
    progress = progress or (lambda stage, done, total: None)
    target = Path(out_dir)
    notices: list[str] = []
    run, roster = open_run(exam_path, roster_path, target, bank, pdf, notices,
                           secret or new_secret())
    run.solutions = solutions
    report = GenerationReport(target, len(roster), len(roster) * len(run.spec.exercises), 0,
                              warnings=notices)
    report.timings["load"] = time.perf_counter() - started
    with Pool(run, default_jobs(jobs)) as pool:
        stage = time.perf_counter()
        chosen: list[StudentVariants] = _in_roster_order(pool, student_variants, roster,
                                                         "variants", progress)
        manifest = build_manifest(run.spec, run.exercises, run.parts,
                                  [c.entry for c in chosen])
        report.redraws = manifest.redraw_count
        report.skew = skew_warnings(manifest)
        report.timings["variants"] = time.perf_counter() - stage
        stage = time.perf_counter()
        key_pdf = (pool.submit(partial(_cpu_timed, _write_key_pdf), manifest)
                   if pdf else None)  # meanwhile
        started_files = pool.map(student_files, chosen, chunksize=_CHUNK)  # workers start
        _write_key_csv(run, manifest)  # while this process writes key.csv
        results: list[StudentResult] = _collected(started_files, len(chosen), "students",
                                                  progress)
        report.timings["students"] = time.perf_counter() - stage
        for name in STAGES:
            report.timings[f"students: {name} (worker CPU s)"] = sum(
                r.timings.get(name, 0.0) for r in results)
        stage = time.perf_counter()
        notices, export_seconds = _write_exports(run, pool, manifest, roster, results,
                                                 progress)
        report.warnings += notices
        if key_pdf is not None:
            export_seconds["key.pdf (worker CPU s)"] = key_pdf.result()[1]
        report.timings["moodle, combined PDFs, key.pdf"] = time.perf_counter() - stage
        report.timings.update(export_seconds)
    dump(manifest, run.out_dir / "manifest.json")
    report.out_dir = swap_in(run.out_dir, target)
    report.timings["total"] = time.perf_counter() - started
    return report


# -- the steps ----------------------------------------------------------------------------


def load_exam(exam_path, roster_path, bank: Bank | None = None,
              notices: list[str] | None = None):
    """The exam spec, the roster and the exercises by id; errors as :class:`ExamSpecError`;
    notices (a roster's ignored columns) are appended to ``notices``."""
    bank = bank or open_bank()
    spec = read_exam_spec(exam_path, bank.get)
    roster = read_roster(roster_path, notices)
    exercises = {item.id: bank.get(item.id) for item in spec.exercises}
    _check_set_values(spec, exercises)
    return spec, roster, exercises


def _check_set_values(spec: ExamSpec, exercises: dict[str, Exercise]) -> None:
    """The values an exam sets (``[exercise.set]``) must leave the constraints satisfiable
    and give finite reference answers."""
    for item in spec.exercises:
        if item.set:
            at = f"{spec.path}, line {item.line}, [[exercise]] {item.id}, field 'set'"
            try:
                exercises[item.id].draw(0, item.set)
                variant = exercises[item.id].variant(0, item.set)
            except ConstraintError as error:
                raise ExamSpecError(f"{at}: the values set break a constraint: "
                                    f"{error}") from None
            except (ArithmeticError, ValueError) as error:
                raise ExamSpecError(f"{at}: the exercise cannot be solved with the values "
                                    f"set ({type(error).__name__}: {error})") from None
            broken = non_finite_answers(variant.answers)
            if broken:
                raise ExamSpecError(f"{at}: the values set make the reference answer of "
                                    f"{', '.join(broken)} non-finite")


def non_finite_answers(answers) -> list[str]:
    """The parts whose numeric reference answer (or a component of it) is not finite."""
    import math

    def finite(value) -> bool:
        if isinstance(value, (tuple, list)):
            return all(finite(v) for v in value)
        return not isinstance(value, float) or math.isfinite(value)

    return [name for name, value in answers.items() if not finite(value)]


def open_run(exam_path, roster_path, target: Path, bank: Bank | None, pdf: bool,
             notices: list[str] | None = None,
             secret: str = "") -> tuple[GenerationRun, list[Student]]:
    """The generation's run (spec with its secret, exercises, scaled parts, caches) and
    the roster; once the exam reads well, the run writes into a fresh staging folder for
    ``target``."""
    refuse_if_in_use(target)  # before the work: never replace a folder students answer in
    spec, roster, exercises = load_exam(exam_path, roster_path, bank, notices)
    spec = replace(spec, secret=secret)
    parts = {item.id: exercise_parts(exercises[item.id], item.points, item.part_points,
                                     spec.rounding)
             for item in spec.exercises}
    return GenerationRun(spec, exercises, parts, staging_folder(target), pdf), roster


def exercise_parts(exercise: Exercise, points: float,
                   given: Mapping[str, float] | None = None,
                   rounding: Rounding = Rounding()) -> tuple[PartEntry, ...]:
    """The parts of ``exercise`` with their points in the exam: ``given`` by the exam
    (``[exercise.points]``) or ``points`` split over the parts in proportion to their own
    points, rounded to the exam's step and summing to ``points`` exactly
    (:func:`.points.exam_part_points`)."""
    shares = exam_part_points({p.name: p.points for p in exercise.parts}, points, given,
                              rounding)
    return tuple(PartEntry(part.name, part.label or part.name, part.kind, part.unit,
                           shares[part.name],
                           **{name: getattr(part, name) for name in part.manifest_fields})
                 for part in exercise.parts)


def _in_roster_order(pool: Pool, job: Callable, items: list, stage: str,
                     progress: Progress) -> list:
    """``job(run, item)`` for every item in the pool, results in the items' order, each
    counted as done in ``stage``."""
    return _collected(pool.map(job, items, chunksize=_CHUNK), len(items), stage, progress)


def _collected(results: Iterable, total: int, stage: str, progress: Progress) -> list:
    """The results of a pool's map as they come, in order, each counted as done in
    ``stage``."""
    collected = []
    for done, result in enumerate(results, 1):
        collected.append(result)
        progress(stage, done, total)
    return collected


def _write_key_csv(run: GenerationRun, manifest: Manifest) -> None:
    from ..render.keys import key_csv

    write_atomic(run.out_dir / "key.csv", key_csv(manifest, run.exercises), private=True)


def _write_exports(run: GenerationRun, pool: Pool, manifest: Manifest,
                   roster: list[Student], results: list[StudentResult],
                   progress: Progress) -> tuple[list[str], dict[str, float]]:
    """moodle.xml (in a worker) and, with PDFs, sheets.pdf and (with solutions)
    solutions.pdf; returns the Moodle export's notices and the CPU seconds of each."""
    moodle = pool.submit(partial(_cpu_timed, _write_moodle), manifest)
    seconds = {}
    if run.pdf:
        started = time.process_time()
        _write_printing_pdfs(run, roster, results, progress)
        seconds["combined PDFs (CPU s)"] = time.process_time() - started
    notices, seconds["moodle.xml (worker CPU s)"] = moodle.result()
    return notices, seconds


def _cpu_timed(job: Callable[[GenerationRun, Any], Any], run: GenerationRun,
               item) -> tuple[Any, float]:
    """``job(run, item)`` and the CPU seconds it took in the process that ran it: a
    worker's seconds show in no clock of this process until the pool ends, and then only
    summed (the report names each export's own)."""
    started = time.process_time()
    return job(run, item), time.process_time() - started


def _write_moodle(run: GenerationRun, manifest: Manifest) -> list[str]:
    """moodle.xml (its figures read from the students' folders, where they were drawn);
    returns the export's notices."""
    from ..render.moodle import moodle_xml

    export = moodle_xml(manifest, run.exercises, _staged_figures(run, manifest))
    write_atomic(run.out_dir / "moodle.xml", export.xml)
    return export.notices


def _staged_figures(run: GenerationRun, manifest: Manifest):
    """A variant's figure as a student who has it got it: the file beside the student's
    fill-in file (:func:`dynagrade.exercise.sheet.figure_file_name`)."""
    holder = {(v.exercise, v.seed): s.student_id
              for s in manifest.students for v in s.variants}

    def figure(exercise: Exercise, variant) -> str | None:
        path = (run.out_dir / "students" / holder[(variant.exercise, variant.seed)]
                / figure_file_name(exercise))
        return path.read_text(encoding="utf-8") if path.is_file() else None

    return figure


def _write_key_pdf(run: GenerationRun, manifest: Manifest) -> None:
    """key.pdf: every student's given values and answers (:func:`dynagrade.render.keys.key_typst`)."""
    from ..render.keys import key_typst

    source = (typst_preamble(run.spec.to_json(), f"{run.spec.title}: answer key")
              + key_typst(manifest, run.exercises))
    write_atomic(run.out_dir / "key.pdf", run.compiler.compile(source))


def _write_printing_pdfs(run: GenerationRun, roster: list[Student],
                         results: list[StudentResult], progress: Progress) -> None:
    """sheets.pdf and, with solutions, solutions.pdf."""
    steps = 2 if run.solutions else 1
    _write_combined_pdf(run, roster, "sheet.pdf", [r.body for r in results],
                        f"{run.spec.title}: all sheets", "sheets.pdf")
    progress("combined PDFs", 1, steps)
    if run.solutions:
        _write_combined_pdf(run, roster, "solution.pdf", _solution_bodies(results),
                            solutions_title(run.spec.title), "solutions.pdf")
        progress("combined PDFs", 2, steps)


def _solution_bodies(results: list[StudentResult]) -> list[str]:
    """Every student's solution sheet body, which each student's job writes when the run
    has ``--solutions``."""
    bodies = [r.solution_body for r in results]
    missing = [r.entry.student_id for r, body in zip(results, bodies) if body is None]
    if missing:
        raise RuntimeError(f"no solution sheet was written for {missing}")
    return [body for body in bodies if body is not None]


def _write_combined_pdf(run: GenerationRun, roster: list[Student], student_pdf: str,
                        bodies: list[str], title: str, combined_pdf: str) -> None:
    """``combined_pdf``: every student's ``student_pdf`` embedded page by page, or, where
    typst cannot embed PDFs, their typst ``bodies`` laid out again."""
    preamble = typst_preamble(run.spec.to_json(), title)

    def laid_out() -> str:
        return preamble + _PAGE_BREAK.join(bodies)

    combined = embedded_pages_source(
        run.out_dir, [f"students/{s.student_id}/{student_pdf}" for s in roster], laid_out)
    if not combined.startswith("#set document"):
        combined = preamble + combined
    try:
        pdf = run.compiler.compile(combined, str(run.out_dir.resolve()))
    except Exception:  # a typst without PDF images: lay the pages out again
        pdf = run.compiler.compile(laid_out())
    write_atomic(run.out_dir / combined_pdf, pdf)


def build_manifest(spec: ExamSpec, exercises: dict[str, Exercise],
                   parts: dict[str, tuple[PartEntry, ...]],
                   students: list[StudentEntry]) -> Manifest:
    """The manifest: everything grading needs, independent of later code or numpy."""
    import numpy

    described = tuple(
        ExerciseEntry(exercises[item.id].id, exercises[item.id].title,
                      exercises[item.id].source, item.points, dict(item.set),
                      "/".join(Path(exercises[item.id].file).parts[-2:]),
                      file_sha256(exercises[item.id].file), parts[item.id])
        for item in spec.exercises)
    exam = ExamEntry(spec.id, spec.title, spec.date, spec.instructions, spec.total_points,
                     spec.policy.to_json() if spec.policy != type(spec.policy)() else None,
                     language=spec.language, secret=spec.secret or None,
                     rounding=spec.rounding.step)
    return Manifest(Generator(_version(), numpy.__version__), exam, described,
                    tuple(students))


def _version() -> str:
    try:
        from importlib.metadata import version

        return version(_package)
    except Exception:  # running from a source tree that is not installed
        return "source"
