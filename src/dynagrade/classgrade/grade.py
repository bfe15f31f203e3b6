"""Grading a class against an exam manifest.

Every roster student gets a row in the gradebook; a student with no submission is
``absent`` with no points (empty cells), one whose files could none be graded (corrupt, foreign,
impersonating) is ``rejected``. Faults stay where they happen: a part whose grading
fails is that part's ``error`` (0 points, the message in the feedback and problems.csv)
and the run goes on. Each submitted exercise is graded against the reference answers
*stored in the manifest* (never recomputed, so a later numpy or an edited exercise cannot
change a student's numbers); the exercise file supplies only the parts' grading rules
(tolerances, units, misconceptions). Part points are those of the manifest, split so
that an exercise's parts sum to its points in the exam. Every verdict is the one record of
graded work (:mod:`dynagrade.exercise.results`): each result is rounded to the exam's step
(:mod:`dynagrade.exam.points`), and the staff's overrides (:mod:`.overrides`) set the
points of the parts they name, the grader's points kept beside them.

Outputs (built in a staging folder and swapped in whole, :mod:`dynagrade.runs.outputs`)::

    grades.csv        student_id, name, email, <one column per exercise id: points
                      earned>, total, max_total, percent, status (graded / incomplete /
                      rejected / absent); points rounded as the exam says
    grades-moodle.csv, grades-canvas.csv
                      with ``formats``: the gradebook as Moodle's or Canvas's grade import
                      reads it (:mod:`.gradebook`)
    problems.csv      every submission that was skipped or replaced, every part whose
                      grading failed, and why
    feedback/<student_id>.md, feedback/<student_id>.html
    report.html       score histogram, difficulty and discrimination per part (with a
                      caution below 30 students), wrong answers grouped by the
                      mistake that explains them and the unexplained share per part,
                      mistakes nobody declared (:mod:`.discover`) and copied answers
                      (:mod:`.copies`)
    answers.csv       every graded part: status, answer, the mistake named (:mod:`.answered`;
                      ``dynagrade discover`` reads it)
    copies.csv        the pairs of students whose wrong answers match each other's keys
                      or answers beyond chance, with the evidence (never a grade)

A re-run with the same inputs writes the same files.
"""

from __future__ import annotations

import time
from dataclasses import replace
from pathlib import Path
from typing import Mapping

from ..errors import UnknownExercise
from ..exam.csvcells import csv_text
from ..exam.manifest import Manifest, ManifestError, PartEntry, StudentEntry, VariantEntry, load
from ..exam.points import Rounding
from ..exam.policy import Policy
from ..exam.solution_policy import with_feedback
from ..exercise.loader import Bank, open_bank
from ..exercise.model import Exercise, Variant
from ..exercise.results import ExerciseResult, GradedPart, Status
from ..exercise.scoring import grade_variant, graded_error
from ..grading import prepare
from ..runs.caches import file_sha256
from ..runs.files import write_atomic
from ..runs.outputs import staging_folder, swap_in
from ..runs.workers import Pool, default_jobs
from .answered import answered_csv
from .copies import copies_csv
from .findings import class_findings
from .gradebook import (GRADEBOOK_FILES, gradebook_csv, gradebook_row,
                        platform_gradebook)
from .overrides import Override, apply_overrides, read_overrides
from .outcome import ClassOutcome, StudentFeedback
from .run import GradingRun
from .solutions import feedback_solutions
from .stats import StudentParts, declared_names, part_statistics
from .submissions import Problem, Submission, collect

def _exercises(manifest: Manifest, bank: Bank, problems: list[Problem],
               where: str) -> dict[str, Exercise]:
    exercises = {}
    for described in manifest.exercises:
        try:
            exercise = bank.get(described.id)
        except UnknownExercise as error:
            raise ManifestError(f"{where}: {error} (needed to grade this exam; "
                                "point --exercises at the folder it came from)") from None
        names = {p.name for p in exercise.parts}
        missing = [p.name for p in described.parts if p.name not in names]
        if missing:
            raise ManifestError(f"{where}: exercise {exercise.id!r} no longer has the parts "
                                f"{missing} that the exam was generated with")
        if exercise.path and file_sha256(exercise.path) != described.sha256:
            problems.append(Problem("warning", exercise.path,
                                    "the exercise file changed since the exam was generated; "
                                    "its grading rules are used with the reference answers "
                                    "stored in the manifest", exercise_id=exercise.id))
        exercises[exercise.id] = exercise
    return exercises


def stored_variant(exercise: Exercise, entry: VariantEntry) -> Variant:
    """The student's variant as the manifest stored it (answers not recomputed)."""
    answers = {part.name: entry.answers.get(part.name) for part in exercise.parts}
    return Variant(exercise.id, int(entry.seed), dict(entry.params), answers, "")


def grade_student(student: StudentEntry, manifest_parts: dict[str, tuple[PartEntry, ...]],
                  exercises: dict[str, Exercise], submissions: dict[str, Submission]
                  ) -> dict[str, ExerciseResult | None]:
    """One roster student's results by exercise id (None: nothing handed in), each part
    worth its points in the exam and holding the reference answer the manifest stored."""
    results: dict[str, ExerciseResult | None] = {}
    for entry in student.variants:
        exercise_id = entry.exercise
        submission = submissions.get(exercise_id)
        if submission is None:
            results[exercise_id] = None
            continue
        by_name = _verdicts(exercises[exercise_id], entry, submission)
        parts = tuple(replace(by_name[part.name].scaled(part.points), label=part.label,
                              expected=entry.answers[part.name], unit=part.unit)
                      for part in manifest_parts[exercise_id])
        results[exercise_id] = ExerciseResult(exercise_id, int(entry.seed), parts,
                                              submission.source)
    return results


def _verdicts(exercise: Exercise, entry: VariantEntry,
              submission: Submission) -> dict[str, GradedPart]:
    """Each part's verdict by name; when the exercise cannot be graded at all (its
    grading rules fail on the stored variant), every part is that error."""
    try:
        result = grade_variant(exercise, stored_variant(exercise, entry),
                               submission.answers, submission.problems)
    except Exception as error:  # noqa: BLE001 - one exercise's failure stays its own
        return {part.name: graded_error(part, submission.answers.get(part.name), error)
                for part in exercise.parts}
    return {p.name: p for p in result.parts}


def _grade_one(run: GradingRun, work: tuple[StudentEntry, dict[str, Submission]]
               ) -> dict[str, ExerciseResult | None]:
    """Worker: one student's results, with the grading run's exercises and parts."""
    student, submissions = work
    return grade_student(student, run.parts, run.exercises, submissions)


def grade_class(manifest_path, paths, out_dir=None, bank: Bank | None = None,
                jobs: int | None = None, progress=None, roster=None,
                platform: str | None = None, overrides=None,
                formats: tuple[str, ...] = (), assignment: str | None = None
                ) -> ClassOutcome:
    """Grade every submission in ``paths`` and, with ``out_dir``, write the outputs; a
    platform's ``.zip`` download among ``paths`` is mapped to students by the platform
    ids of ``roster`` (:mod:`.downloads`).

    ``overrides`` is the path of an overrides file (:mod:`.overrides`), checked before
    anything is graded; ``formats`` the platform gradebooks to write besides grades.csv
    (``"moodle"``, ``"canvas"``), their grade column headed ``assignment`` (default: the
    exam's title)."""
    started = time.perf_counter()
    progress = progress or (lambda stage, done, total: None)
    manifest = load(manifest_path)
    rounding = Rounding(manifest.exam.rounding)
    staff = (read_overrides(overrides, manifest, rounding) if overrides is not None
             else ())
    problems: list[Problem] = []
    exercises = _exercises(manifest, bank or open_bank(), problems, str(manifest_path))
    manifest_parts = {e.id: e.parts for e in manifest.exercises}
    chosen, found = collect(paths, manifest, roster, platform)
    problems += found
    timings = {"collect": time.perf_counter() - started}
    stage = time.perf_counter()
    work = [(s, {e: chosen[(s.student_id, e)] for e in manifest_parts
                 if (s.student_id, e) in chosen}) for s in manifest.students]
    graded = _run(work, manifest_parts, exercises, jobs, progress)
    timings["grading"] = time.perf_counter() - stage
    outcome = class_outcome(manifest, graded, problems, timings, declared_names(exercises),
                       staff, str(overrides))
    if "moodle" in formats:
        outcome.problems += missing_emails(manifest)
    solutions = Policy.from_json(manifest.exam.policy).solutions
    with_findings(outcome, manifest, exercises)
    if out_dir is not None and with_feedback(solutions):
        _add_solutions(outcome, manifest, exercises)
    if out_dir is not None:
        stage = time.perf_counter()
        staging = staging_folder(out_dir)
        write_outputs(outcome, manifest, staging, progress, formats,
                      assignment or manifest.exam.title)
        swap_in(staging, out_dir)
        timings["outputs"] = time.perf_counter() - stage
    timings["total"] = time.perf_counter() - started
    return outcome


def class_outcome(manifest: Manifest, graded: list[dict[str, ExerciseResult | None]],
             problems: list[Problem], timings: dict[str, float], declared: dict | None = None,
             overrides: tuple[Override, ...] = (), overrides_file: str = "") -> ClassOutcome:
    """The gradebook, the feedback per student and the item statistics of ``graded``
    (each roster student's results, in roster order): every result rounded to the
    exam's step, then the staff's overrides applied. Class grading and the server's
    gradebook and report both build their outcome here."""
    exercise_ids = manifest.exercise_ids
    rounding = Rounding(manifest.exam.rounding)
    max_total = rounding.total([e.points for e in manifest.exercises])
    student_ids = [s.student_id for s in manifest.students]
    rounded = {student_id: {e: r.rounded(rounding) if r is not None else None
                            for e, r in results.items()}
               for student_id, results in zip(student_ids, graded)}
    final, comments = apply_overrides(overrides, overrides_file, rounded, rounding)
    rows, analysed, feedback = [], [], {}
    rejected = rejected_files(problems)
    problems += part_errors(manifest, final)
    for student in manifest.students:
        results = final[student.student_id]
        handed_in = rejected.get(student.student_id, {})
        row = gradebook_row(student.student_id, results, exercise_ids, max_total,
                            bool(handed_in), name=student.name, email=student.email,
                            rounding=rounding)
        rows.append(row)
        feedback[student.student_id] = StudentFeedback(student, results, row, handed_in)
        submitted = {e: result for e in exercise_ids if (result := results[e]) is not None}
        # a student who handed something in has a total (only the absent have none)
        if submitted and row.total is not None:
            analysed.append(StudentParts(row.total, {
                (e, p.name): p for e, result in submitted.items() for p in result.parts}))
    ordered_parts = [(e.id, p) for e in manifest.exercises for p in e.parts]
    return ClassOutcome(manifest.exam.title, exercise_ids, rows, problems,
                        part_statistics(ordered_parts, analysed, declared=declared), feedback,
                        timings, rounding, max_total, comments, len(overrides))


def with_findings(outcome: ClassOutcome, manifest: Manifest,
                  exercises: Mapping[str, Exercise],
                  times: Mapping[tuple[str, str], str] | None = None) -> ClassOutcome:
    """``outcome`` with the mistakes nobody declared and the copied answers attached
    (:mod:`.findings`; the report shows them, no grade changes); class grading and the
    server's report both call it."""
    outcome.findings = class_findings(manifest, exercises, outcome.records(times))
    return outcome


def part_errors(manifest: Manifest,
                graded: Mapping[str, Mapping[str, ExerciseResult | None]]) -> list[Problem]:
    """A problem for every part whose grading failed, with the failure's message."""
    found = []
    for student in manifest.students:
        for exercise_id, result in graded[student.student_id].items():
            if result is None:
                continue
            for part in result.parts:
                if part.status is Status.ERROR:
                    found.append(Problem("error", result.source,
                                         f"part {part.name}: {part.feedback}",
                                         student.student_id, exercise_id))
    return found


def missing_emails(manifest: Manifest) -> list[Problem]:
    """A warning when students of the roster have no email: Moodle's grade import cannot
    map them by email address (it stops at the first row it cannot match)."""
    without = [s.student_id for s in manifest.students if not s.email]
    if not without:
        return []
    shown = ", ".join(without[:5]) + (", ..." if len(without) > 5 else "")
    return [Problem("warning", GRADEBOOK_FILES["moodle"],
                    f"{len(without)} student(s) have no email on the roster ({shown}); in "
                    "Moodle's import map users from 'ID number', not 'Email address'")]


def rejected_files(problems: list[Problem]) -> dict[str, dict[str, list[str]]]:
    """Per student and exercise, why the files they handed in were not graded (the
    feedback says so instead of "Not submitted")."""
    rejected: dict[str, dict[str, list[str]]] = {}
    for problem in problems:
        if problem.level == "error" and problem.handed_in_by and problem.student_id \
                and problem.exercise_id:
            name = Path(problem.source.split(", row ")[0]).name
            rejected.setdefault(problem.student_id, {}).setdefault(
                problem.exercise_id, []).append(f"{name}: {problem.message}")
    return rejected


def _add_solutions(outcome: ClassOutcome, manifest: Manifest,
                   exercises: dict[str, Exercise]) -> None:
    """Each student's worked solutions, to end their feedback (:mod:`.solutions`)."""
    for student in manifest.students:
        def warn(exercise_id: str, message: str, student_id=student.student_id) -> None:
            outcome.problems.append(Problem("warning", "solution", message, student_id,
                                            exercise_id))

        solved = [(exercises[e.exercise], stored_variant(exercises[e.exercise], e))
                  for e in student.variants]
        outcome.feedback[student.student_id].solutions = feedback_solutions(solved, warn)


def _run(work, manifest_parts, exercises, jobs, progress) -> list[dict]:
    """Every student's results in roster order; a class of fewer than 40 is graded here,
    a larger one in worker processes (in chunks, so that progress moves)."""
    jobs = default_jobs(jobs) if len(work) >= 40 else 1
    size = max(1, len(work) // (jobs * 8))
    prepare()  # before any verdict's time budget starts (forked workers inherit it)
    results = []
    with Pool(GradingRun(exercises, manifest_parts), jobs) as pool:
        for done, result in enumerate(pool.map(_grade_one, work, chunksize=size), 1):
            results.append(result)
            progress("grading", done, len(work))
    return results


def problems_csv(problems: list[Problem]) -> str:
    return csv_text([("level", "source", "student_id", "exercise_id", "message"),
                     *(problem.to_row() for problem in problems)])


def write_outputs(outcome: ClassOutcome, manifest: Manifest, out: Path, progress,
                  formats: tuple[str, ...] = (), assignment: str = "") -> None:
    from .report import feedback_html, feedback_markdown, report_html

    exercises = {e.id: e for e in manifest.exercises}
    total = len(outcome.feedback)
    for done, (student_id, data) in enumerate(outcome.feedback.items(), 1):
        write_atomic(out / "feedback" / f"{student_id}.md",
                     feedback_markdown(manifest.exam, exercises, data))
        write_atomic(out / "feedback" / f"{student_id}.html",
                     feedback_html(manifest.exam, exercises, data))
        progress("feedback", done, total)
    write_atomic(out / "report.html", report_html(manifest.exam, outcome))
    write_atomic(out / "problems.csv", problems_csv(outcome.problems))
    write_atomic(out / GRADEBOOK_FILES["csv"], gradebook_csv(outcome))
    write_atomic(out / "answers.csv", answered_csv(outcome.records()))
    if outcome.findings is not None:
        write_atomic(out / "copies.csv", copies_csv(outcome.findings.copies))
    for layout in formats:
        write_atomic(out / GRADEBOOK_FILES[layout],
                     platform_gradebook(outcome, layout, assignment or manifest.exam.title))
