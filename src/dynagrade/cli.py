"""The ``dynagrade`` and ``grade`` commands.

Usage::

    dynagrade list
    dynagrade show projectile-range --student s1 --answers
    dynagrade sheet projectile-range --student s1 -o exercise.py
    grade exercise.py
    dynagrade verify --variants 200
    dynagrade exam exam.toml --roster roster.csv -o out/
    dynagrade grade --manifest out/manifest.json out/submissions/ -o out/grading/
    dynagrade discover out/manifest.json out/grading/
    dynagrade moodle projectile-range --variants 50 -o pool.xml
    dynagrade links out/manifest.json -o links.csv --instructor
    dynagrade serve out/manifest.json
    dynagrade policy out/manifest.json --closes 2025-04-22T23:59:00+02:00
    dynagrade rekey out/manifest.json projectile-range
"""

from __future__ import annotations

import json
import os
import sys
from pathlib import Path
from typing import Any

import click

from .config import FILE_NAME, Project, load_project
from .errors import DynagradeError
from .exercise import loader


class _ReportsErrors(click.Command):
    """The one place where dynagrade's errors become command-line errors: the message
    of any :class:`DynagradeError` raised by a command is printed as ``Error: ...`` and
    the command exits with status 1, without a traceback."""

    def invoke(self, ctx: click.Context) -> Any:
        try:
            return super().invoke(ctx)
        except DynagradeError as error:
            raise click.ClickException(str(error)) from None


class _Group(_ReportsErrors, click.Group):
    """A command group whose subcommands report dynagrade's errors as messages."""


class _Command(_ReportsErrors):
    """A command that reports dynagrade's errors as messages."""


class _Context:
    """What every subcommand shares: where exercises are looked for.

    ``folders`` are searched in the order of precedence: the command line's (from
    ``--exercises`` before and after the subcommand), ``$DYNAGRADE_EXERCISES``'s, then the
    project file's (:mod:`dynagrade.config`); the shipped bank comes last."""

    def __init__(self, folders: tuple[str, ...], project: Project):
        self.command_line = list(folders)
        self.project = project
        self._bank: loader.Bank | None = None

    @property
    def folders(self) -> tuple[str, ...]:
        return tuple(map(str, [*self.command_line, *loader.environment_folders(),
                               *self.project.exercises]))

    def add_folders(self, folders) -> None:
        """Folders named after the subcommand (searched after those named before it;
        the bank opens only when a command first asks for an exercise)."""
        self.command_line += list(folders)

    @property
    def bank(self):
        if self._bank is None:
            self._bank = loader.open_bank(self.folders)
        return self._bank

    def exercise(self, exercise_id: str, templates: bool = True):
        """The exercise; ``templates=False`` for a command that renders neither its
        statement nor its solution (its templates are then not checked)."""
        return self.bank.get(exercise_id, templates=templates)


_EXERCISES_HELP = (f"A folder of exercise files, searched before the shipped bank "
                   f"(repeatable; also ${loader.ENVIRONMENT_VARIABLE} and the "
                   f"'exercises' of {FILE_NAME}).")
_exercises_option = click.option("--exercises", "folders", multiple=True,
                                 type=click.Path(file_okay=False), help=_EXERCISES_HELP)


def _more_folders(ctx, param, folders):
    """``--exercises`` after a subcommand: added to those named before it."""
    if folders:
        ctx.find_object(_Context).add_folders(folders)


def _subcommand_exercises_option() -> click.Option:
    return click.Option(["--exercises"], multiple=True, type=click.Path(file_okay=False),
                        expose_value=False, callback=_more_folders, help=_EXERCISES_HELP)


@click.group(cls=_Group, context_settings={"help_option_names": ["-h", "--help"]})
@_exercises_option
@click.version_option(package_name="dynagrade")
@click.pass_context
def main(ctx, folders):
    """Randomized Dynamics exercises and exams, graded with units and feedback.

    Settings come from the command line, then the environment, then the project file
    dynagrade.toml (searched upward from the working folder; see docs/authoring.md)."""
    project = load_project()
    ctx.obj = _Context(folders, project)
    ctx.default_map = project.defaults()


# -- exercises ---------------------------------------------------------------------------


@main.command("list")
@click.option("--json", "as_json", is_flag=True, help="Print a JSON array.")
@click.option("--by-section", is_flag=True,
              help="Count the exercises under each section of the notes (by their source).")
@click.pass_obj
def list_command(context, as_json, by_section):
    """List the exercises in the bank (read from their files, which are not run)."""
    exercises = context.bank.listing()
    if by_section:
        _list_by_section(exercises, as_json)
        return
    if as_json:
        click.echo(json.dumps([e.summary() for e in exercises], indent=2, ensure_ascii=False))
        return
    from .render.terminal import exercise_table

    exercise_table(exercises)


def _list_by_section(exercises, as_json: bool) -> None:
    """``list --by-section``: the exercises per section of the notes, as a table or JSON."""
    from .exercise.sections import ENOUGH, coverage

    sections, unplaced = coverage(exercises)
    if as_json:
        click.echo(json.dumps({"enough": ENOUGH, "sections": [c.to_json() for c in sections],
                               "unplaced": unplaced}, indent=2, ensure_ascii=False))
        return
    from .render.terminal import section_table

    section_table(sections, unplaced, ENOUGH)


@main.command()
@click.argument("exercise_id")
@click.option("--seed", type=click.IntRange(0), help="The variant's seed (default 0).")
@click.option("--student", help="Show this student's variant (seed from the student id).")
@click.option("--set", "settings", multiple=True, metavar="NAME=VALUE",
              help="Fix a parameter, in its unit or with one (alpha=30 or 'alpha=0.5 rad').")
@click.option("--answers", is_flag=True, help="Show the reference answers too.")
@click.option("--solution", is_flag=True, help="Show the worked solution too.")
@click.option("--json", "as_json", is_flag=True, help="Print JSON.")
@click.option("--figure", "figure_file", type=click.Path(dir_okay=False, writable=True),
              help="Also write the variant's figure to this SVG file.")
@click.pass_obj
def show(context, exercise_id, seed, student, settings, answers, solution, as_json,
         figure_file):
    """Show an exercise's variant: its statement, and on request its answers, worked
    solution and figure."""
    exercise = context.exercise(exercise_id)
    variant = _variant(exercise, seed, student, settings, force=None)
    if figure_file:
        _write_figure(exercise, variant, figure_file)
    worked = _solution(exercise, variant) if solution else None
    if as_json:
        data = variant.to_json()
        if not answers:
            data.pop("answers")
        if solution:
            data["solution"] = worked
        click.echo(json.dumps(data, indent=2, ensure_ascii=False))
        return
    from .render.terminal import solution_panel, variant_panel

    variant_panel(exercise, variant, with_answers=answers)
    if solution:
        solution_panel(exercise, variant, worked)


@main.command()
@click.argument("exercise_id")
@click.option("--seed", type=click.IntRange(0), default=0, show_default=True,
              help="Seed for the parameters not set (they keep the values this seed "
                   "draws without --set).")
@click.option("--set", "settings", multiple=True, metavar="NAME=VALUE",
              help="Fix a parameter, in its unit or with one.")
@click.option("--json", "as_json", is_flag=True, help="Print JSON (each answer with its unit).")
@click.option("--force", is_flag=True,
              help="Compute even with values outside a parameter's physical domain "
                   "(g > 0, 0 <= e <= 1, masses > 0, ...) or non-finite answers.")
@click.pass_obj
def solve(context, exercise_id, seed, settings, as_json, force):
    """Solve an exercise for given parameters; the others are drawn from --seed."""
    from .generation.generate import non_finite_answers

    exercise = context.exercise(exercise_id)
    variant = _variant(exercise, seed, None, settings, force)
    broken = non_finite_answers(variant.answers)
    if broken and not force:
        raise click.ClickException(f"{exercise.id}: the values set make the answer of "
                                   f"{', '.join(broken)} non-finite (--force shows them)")
    data = variant.to_json()
    result = {"params": data["params"], "answers": data["answers"],
              "units": {part.name: part.unit for part in exercise.parts}}
    if as_json:
        click.echo(json.dumps(result, indent=2, ensure_ascii=False))
        return
    from .render.terminal import answers_table

    answers_table(exercise, variant)


@main.command()
@click.argument("exercise_id")
@click.option("--student", required=True, help="The student's id.")
@click.option("-o", "--output", type=click.Path(dir_okay=False, writable=True),
              help="Where to write the file (default: print it). The exercise's figure, "
                   "if it draws one, is written beside it as <exercise-id>.svg.")
@click.option("--solution", is_flag=True,
              help="End the file with the worked solution, as comments (for practice).")
@click.pass_obj
def sheet(context, exercise_id, student, output, solution):
    """Write a student's fill-in file for an exercise, and its figure beside it."""
    from .exercise.seeds import student_seed
    from .exercise.sheet import figure_file_name, write_sheet
    from .exercise.solution import as_comments

    exercise = context.exercise(exercise_id)
    variant = exercise.variant(student_seed(exercise.id, student))
    filename = Path(output).name if output else "exercise.py"
    figure = figure_file_name(exercise) if output and exercise.figure is not None else None
    text = write_sheet(exercise, variant, student, filename, figure=figure)
    if solution:
        text += as_comments(exercise, _solution(exercise, variant))
    if not output:
        click.echo(text)
        if exercise.figure is not None:
            click.echo(f"note: {exercise.id} has a figure; write the sheet with -o FILE to "
                       f"get it beside the file as {figure_file_name(exercise)}", err=True)
        return
    from .runs.files import write_atomic

    write_atomic(output, text)
    click.echo(f"wrote {output}: {exercise.title}, variant of {student}", err=True)
    if figure is not None:
        from .render.figures import figure_svg

        svg = figure_svg(exercise, variant)  # an exercise with a figure draws one
        if svg is not None:
            figure_path = write_atomic(Path(output).parent / figure, svg)
            click.echo(f"wrote {figure_path}: its figure", err=True)


@main.command()
@click.argument("exercise_ids", nargs=-1)
@click.option("--variants", type=click.IntRange(1), default=50, show_default=True,
              help="Seeds to check per exercise (0 .. N-1).")
@click.option("--require-solutions/--allow-missing-solutions", default=None,
              help="Whether an exercise without a worked solution fails or is only noted "
                   "(default: it fails once every exercise of the shipped bank has one).")
@click.pass_obj
def verify(context, exercise_ids, variants, require_solutions):
    """Check exercises for variants that cannot tell right from wrong, their worked
    solutions and every variant's figure."""
    from .exercise.solution_check import bank_is_complete
    from .exercise.verify import verify_exercise
    from .render.figures import figure_svg
    from .render.solutions import math_problems
    from .render.terminal import verify_progress

    exercises = ([context.exercise(i) for i in exercise_ids] if exercise_ids
                 else context.bank.all())
    if require_solutions is None:
        require_solutions = bank_is_complete()
    reports = verify_progress(exercises, lambda e: verify_exercise(
        e, range(variants), require_solution=require_solutions, math_check=math_problems,
        render_figure=figure_svg))
    if any(not r.ok for r in reports):
        sys.exit(1)


@main.command()
@click.argument("source", type=click.File("r", encoding="utf-8"), default="-")
@click.pass_obj
def compare(context, source):
    """Grade JSON lines of (expected, answer, spec) records; one JSON line out per line in."""
    from .grading.compare import compare_lines

    for line in compare_lines(source):
        click.echo(line)


@main.command("grade")
@click.argument("files", nargs=-1, required=True, type=click.Path(exists=True))
@click.option("--json", "as_json", is_flag=True, help="Print JSON.")
@click.option("--manifest", type=click.Path(exists=True, dir_okay=False),
              help="Grade a class against this exam manifest: FILES are filled-in files, "
                   "folders of them (searched recursively) or CSV files of responses "
                   "(student_id,exercise_id,part,answer).")
@click.option("-o", "--output", type=click.Path(file_okay=False),
              help="With --manifest: the folder for grades.csv, feedback and report.html.")
@click.option("--jobs", type=click.IntRange(1), default=None,
              help="With --manifest: worker processes (default: up to 2).")
@click.option("--strict", is_flag=True,
              help="With --manifest: exit 1 when any submission was skipped (corrupt, "
                   "foreign, impersonating) or any part could not be graded; the "
                   "gradebook is written all the same.")
@click.option("--roster", type=click.Path(exists=True, dir_okay=False),
              help="With --manifest: a roster with the students' platform ids (moodle_id, "
                   "canvas_id) to map a Moodle or Canvas download (a .zip among FILES).")
@click.option("--platform", type=click.Choice(["moodle", "canvas"]),
              help="With --manifest: which platform made the .zip download (default: told "
                   "from its entry names).")
@click.option("--format", "formats", multiple=True, type=click.Choice(["moodle", "canvas"]),
              help="With --manifest and -o: also write the gradebook as Moodle's "
                   "(grades-moodle.csv) or Canvas's (grades-canvas.csv) grade import "
                   "reads it; repeat for both.")
@click.option("--assignment", metavar="NAME",
              help="With --format: the grade column's heading, the Moodle grade item or "
                   "Canvas assignment (e.g. \"Midterm (12345)\" for an existing Canvas "
                   "assignment); default: the exam's title.")
@click.option("--overrides", type=click.Path(exists=True, dir_okay=False),
              help="With --manifest: a CSV student_id,exercise,part,points,comment of "
                   "points set by hand; every row is checked before grading and a bad "
                   "one stops the run before anything is written.")
@click.pass_obj
def grade_command(context, files, as_json, manifest, output, jobs, strict, roster, platform,
                  formats, assignment, overrides):
    """Grade filled-in exercise files (never executing them); with --manifest, a class.

    A class is always graded whole: a bad file or a part that cannot be graded is
    reported and costs only itself. The exit status is non-zero only when nothing could
    be graded (a bad manifest, a missing exercise, an unwritable folder) or, with
    --strict, when something was reported as an error."""
    if manifest is None:
        if _given("output") or _given("jobs") or strict or roster or platform \
                or formats or assignment or overrides:
            raise click.UsageError("-o/--output, --jobs, --strict, --roster, --platform, "
                                   "--format, --assignment and --overrides need --manifest")
        for file in files:
            if Path(file).is_dir():
                raise click.BadParameter(f"File {file!r} is a directory.",
                                         param_hint="'FILES...'")
        _grade_files(context, files, as_json)
        return
    if (formats or assignment) and output is None:
        raise click.UsageError("--format and --assignment need -o/--output (the folder "
                               "the gradebooks are written to)")
    if assignment and not formats:
        raise click.UsageError("--assignment heads the grade column of a --format moodle "
                               "or canvas gradebook; give --format too")
    _grade_class(context, manifest, files, output, jobs, as_json, strict,
                 {"roster": roster, "platform": platform,
                  "formats": tuple(dict.fromkeys(formats)), "assignment": assignment,
                  "overrides": overrides})


@main.command()
@click.argument("manifest", type=click.Path(exists=True, dir_okay=False))
@click.argument("graded_dir", type=click.Path(exists=True, file_okay=False))
@click.option("--json", "as_json", is_flag=True, help="Print JSON.")
@click.pass_obj
def discover(context, manifest, graded_dir, as_json):
    """Propose misconceptions nobody declared: the mistakes of a bounded set (see
    docs/exams.md) that explain clusters of unexplained wrong answers in GRADED_DIR
    (the folder `dynagrade grade --manifest -o` wrote), each with a Misconception(...)
    to paste into the exercise file. Changes no grade."""
    from dataclasses import asdict

    from .classgrade.answered import read_answered
    from .classgrade.discover import discover as proposals_of, proposal_lines
    from .exam.manifest import load

    exam = load(manifest)
    answers = Path(graded_dir) / "answers.csv"
    if not answers.exists():
        raise click.ClickException(f"{answers} is missing: grade the class with this "
                                   "version of `dynagrade grade --manifest ... -o` first")
    exercises = {e.id: context.exercise(e.id, templates=False) for e in exam.exercises}
    try:
        records = read_answered(answers)
    except ValueError as error:
        raise click.ClickException(str(error)) from None
    proposals = proposals_of(exam, exercises, records)
    if as_json:
        click.echo(json.dumps([asdict(p) for p in proposals], indent=2, ensure_ascii=False))
        return
    for line in proposal_lines(proposals):
        click.echo(line)


@main.command()
@click.argument("exam_file", type=click.Path(exists=True, dir_okay=False))
@click.option("--roster", required=True, type=click.Path(exists=True, dir_okay=False),
              help="CSV with the header student_id,name[,email], or as Excel, Moodle "
                   "or Canvas save it (see docs/exams.md).")
@click.option("-o", "--output", required=True, type=click.Path(file_okay=False),
              help="The folder to write the exam into.")
@click.option("--jobs", type=click.IntRange(1), default=None,
              help="Worker processes (default: up to 2).")
@click.option("--no-pdf", is_flag=True, help="Skip the PDFs (faster drafts).")
@click.option("--secret-file", type=click.Path(dir_okay=False),
              help="Read the exam's secret from this file (created with a new random "
                   "secret when missing): the same secret gives the same variants and "
                   "byte-identical files. Default: a new random secret every run.")
@click.option("--solutions", is_flag=True,
              help="Write each student's worked solutions (students/<id>/solution.*) and "
                   "solutions.pdf with all of them, for the staff.")
@click.pass_obj
def exam(context, exam_file, roster, output, jobs, no_pdf, secret_file, solutions):
    """Generate an exam: every student's variants, sheets, keys, Moodle XML, manifest."""
    from .generation.generate import generate_exam
    from .exam.secret import load_secret
    from .render.terminal import progress_reporter

    secret = load_secret(secret_file) if secret_file else None
    with progress_reporter() as progress:
        report = generate_exam(exam_file, roster, output, bank=context.bank, jobs=jobs,
                               pdf=not no_pdf, progress=progress, secret=secret,
                               solutions=solutions)
    for warning in report.warnings:
        click.echo(f"notice: {warning}", err=True)
    for warning in report.skew:
        click.echo(f"warning: {warning}", err=True)
    warned = f"; {len(report.skew)} warning(s) above" if report.skew else ""
    click.echo(f"wrote {output}: {report.students} students, {report.variants} variants "
               f"({report.redraws} draws replaced because they could not discriminate; see "
               f"manifest.json{warned}) in {report.timings['total']:.1f} s", err=True)


@main.command()
@click.argument("manifest", type=click.Path(exists=True, dir_okay=False))
@click.argument("exercise_ids", nargs=-1, required=True)
@click.pass_obj
def rekey(context, manifest, exercise_ids):
    """Recompute the reference answers of EXERCISE_IDS in MANIFEST from the exercise
    files as they are now (each variant's seed, the exam's `set` values); refused, with
    nothing written, when any variant's parameters would change. Safe while the exam is
    served: the manifest is replaced atomically."""
    from .generation.rekey import rekey as rekey_manifest

    for line in rekey_manifest(manifest, list(exercise_ids), context.bank):
        click.echo(line.line())
    folder = Path(manifest).parent
    rewritten = " key.csv was rewritten;" if (folder / "key.csv").exists() else ""
    click.echo(f"rewrote {manifest};{rewritten} key.pdf, moodle.xml and the students' "
               "sheets and solutions in the folder are NOT rendered again (they keep the "
               "old answers). A server goes on grading new submits with the old key until "
               "a regrade is applied on its staff page (/i/<token>/regrade).", err=True)


@main.command()
@click.argument("exercise_ids", nargs=-1, required=True)
@click.option("--variants", type=click.IntRange(1, 1000), default=20, show_default=True,
              help="Distinct variants per exercise.")
@click.option("-o", "--output", required=True, type=click.Path(dir_okay=False),
              help="The Moodle XML file to write.")
@click.option("--title", default="dynagrade pool", show_default=True,
              help="The question category the exercises' categories go under.")
@click.option("--secret-file", type=click.Path(dir_okay=False),
              help="Key the variants with the secret in this file (created when "
                   "missing): the same secret gives the same pool. Default: a new "
                   "random pool every run.")
@click.pass_obj
def moodle(context, exercise_ids, variants, output, title, secret_file):
    """Write a Moodle question pool: --variants variants of each exercise, a category
    per exercise, for a quiz's random questions (no roster needed)."""
    from .runs.files import write_atomic
    from .generation.pool import pool_categories
    from .exam.secret import load_secret
    from .exercise.seeds import new_secret
    from .render.moodle import pool_xml

    exercises = [context.exercise(exercise_id) for exercise_id in exercise_ids]
    secret = load_secret(secret_file) if secret_file else new_secret()
    categories, notices = pool_categories(exercises, variants, secret)
    export = pool_xml(title, categories)
    try:
        write_atomic(output, export.xml)
    except OSError as error:
        raise click.ClickException(f"{output}: cannot write the pool ({error.strerror})")
    for notice in notices + export.notices:
        click.echo(f"notice: {notice}", err=True)
    written = sum(len(c.variants) for c in categories)
    click.echo(f"wrote {output}: {written} questions in {len(categories)} categories",
               err=True)


# -- grade exercise.py -------------------------------------------------------------------


@click.command(cls=_Command, context_settings={"help_option_names": ["-h", "--help"]})
@click.argument("file", type=click.Path(exists=True, dir_okay=False))
@click.option("--json", "as_json", is_flag=True, help="Print JSON.")
@click.option("--solution", is_flag=True, help="Print the worked solution after the verdicts.")
@_exercises_option
def grade_main(file, as_json, solution, folders):
    """Grade one filled-in exercise file and print feedback per part.

    The file is read, never run: each answer must be a number, a quoted string, a list
    of numbers or None.
    """
    _one_blas_thread()
    _grade_files(_Context(folders, load_project()), (file,), as_json, solution)


def _one_blas_thread() -> None:
    """Let numpy's BLAS start one thread, unless the environment says otherwise: grading
    one file multiplies no large matrices, and starting a thread per core costs a cold
    ``grade FILE`` more CPU than its grading. numpy reads the setting when it is first
    imported (here, when the exercise file is loaded); once it is loaded, nothing is
    changed."""
    if "numpy" in sys.modules or any(variable in os.environ for variable in (
            "OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS")):
        return
    os.environ["OPENBLAS_NUM_THREADS"] = "1"


def _grade_files(context, files, as_json, solution=False):
    """Grade practice and homework files; an exam's file (it carries a variant token)
    gets the key-free self-check only (and no solution: its variant is the staff's).
    Grading renders no statement, so the exercises' templates are checked (and jinja2
    imported) only for ``--solution``."""
    from .exercise.sheet import read_sheet

    results = []
    for file in files:
        sheet = read_sheet(file)
        exercise = context.exercise(sheet.exercise_id, templates=solution)
        notes = [f"{file}: no part named {name!r} in {exercise.id}; it was ignored"
                 for name in sheet.answers if name not in {p.name for p in exercise.parts}]
        notes += [f"{file}: {note}" for note in sheet.notes]
        for note in notes:
            click.echo(f"warning: {note}", err=True)
        if sheet.is_exam:
            results.append((exercise, None, _self_check(exercise, sheet)))
        else:
            results.append((exercise, *_full_verdicts(file, exercise, sheet)))
    if as_json:
        data = [r if isinstance(r, dict) else r.to_json() for _, _, r in results]
        if solution:
            for entry, (exercise, variant, _) in zip(data, results):
                if variant is not None:
                    entry["solution"] = _solution(exercise, variant)
        click.echo(json.dumps(data[0] if len(data) == 1 else data, indent=2,
                              ensure_ascii=False))
        return
    from .render.terminal import result_table, solution_panel

    for exercise, variant, result in results:
        if isinstance(result, dict):
            _print_self_check(result)
            continue
        result_table(exercise, result)
        if solution:
            solution_panel(exercise, variant, _solution(exercise, variant))


def _full_verdicts(file, exercise, sheet):
    """The variant of a practice or homework file (it is public) and the verdicts."""
    from .exercise.scoring import grade_variant
    from .exercise.seeds import student_seed

    if sheet.student and not sheet.exam_id and \
            sheet.seed != student_seed(exercise.id, sheet.student):
        click.echo(f"warning: {file}: this is not the practice variant of student "
                   f"{sheet.student!r}; graded the variant the file names", err=True)
    variant = exercise.variant(sheet.seed, with_statement=False)
    return variant, grade_variant(exercise, variant, sheet.answers, sheet.problems)


def _self_check(exercise, sheet) -> dict:
    from .exercise.selfcheck import self_check_json

    return self_check_json(exercise, sheet)


def _print_self_check(checked: dict) -> None:
    click.echo(f"{checked['exercise']}: {checked['message']}")
    for part in checked["parts"]:
        mark = "readable" if part["readable"] else "NOT READABLE"
        click.echo(f"  {part['name']}: {mark}: {part['message']}")


def _grade_class(context, manifest, files, output, jobs, as_json, strict, options):
    from .classgrade.grade import grade_class
    from .render.terminal import progress_reporter

    with progress_reporter() as progress:
        outcome = grade_class(manifest, files, output, bank=context.bank, jobs=jobs,
                              progress=progress, **options)
    for problem in outcome.problems:
        click.echo(f"{problem.level}: {problem.source}: {problem.message}", err=True)
    if as_json:
        click.echo(json.dumps(outcome.summary(), indent=2, ensure_ascii=False))
    else:
        from .render.terminal import gradebook_table

        gradebook_table(outcome)
    if output:
        from .classgrade.gradebook import GRADEBOOK_FILES

        written = ["grades.csv", *(GRADEBOOK_FILES[f] for f in options["formats"])]
        click.echo(f"wrote {output}: {', '.join(written)}, problems.csv, answers.csv, "
                   "copies.csv, feedback/, report.html", err=True)
    errors = sum(p.level == "error" for p in outcome.problems)
    if strict and errors:
        click.echo(f"--strict: {errors} problem(s) reported as errors", err=True)
        sys.exit(1)


# -- helpers -----------------------------------------------------------------------------


def _given(option: str) -> bool:
    """Whether the running command's ``option`` was set on the command line (or in the
    environment), not taken from a default or from dynagrade.toml."""
    source = click.get_current_context().get_parameter_source(option)
    return source in (click.core.ParameterSource.COMMANDLINE,
                      click.core.ParameterSource.ENVIRONMENT)


def _variant(exercise, seed, student, settings, force=False):
    from .exam.spec import domain_problem
    from .exercise.seeds import student_seed

    if seed is not None and student is not None:
        raise click.UsageError("give --seed or --student, not both")
    if student is not None:
        seed = student_seed(exercise.id, student)
    overrides = _parse_settings(exercise, settings)
    for name, value in overrides.items():
        outside = domain_problem(exercise.parameter(name), value)
        if outside and not force:
            raise click.BadParameter(f"{name}: {outside}"
                                     + (" (--force computes anyway)" if force is not None
                                        else ""), param_hint="--set")
    try:
        variant = exercise.variant_set(seed or 0, overrides, finite=force is None) \
            if overrides else exercise.variant(seed or 0)
    except (ArithmeticError, ValueError) as error:
        if isinstance(error, DynagradeError):
            raise
        raise click.ClickException(f"{exercise.id}: cannot be solved with these values "
                                   f"({type(error).__name__}: {error})") from None
    for warning in variant.warnings:
        click.echo(f"warning: the values set break the constraint '{warning}'", err=True)
    return variant


def _write_figure(exercise, variant, figure_file) -> None:
    """Write the variant's figure as SVG to ``figure_file``; an error when the exercise
    draws none."""
    from .render.figures import figure_svg
    from .runs.files import write_atomic

    svg = figure_svg(exercise, variant)
    if svg is None:
        raise click.ClickException(f"{exercise.id} draws no figure (it has no figure=)")
    write_atomic(figure_file, svg)
    click.echo(f"wrote {figure_file}: the figure of {exercise.id}, seed {variant.seed}",
               err=True)


def _solution(exercise, variant) -> str | None:
    """The variant's worked solution (Markdown), ``None`` when the exercise has none."""
    from .exercise.solution import render_solution

    return render_solution(exercise, variant)


def _parse_settings(exercise, settings) -> dict[str, float]:
    """``NAME=VALUE`` pairs as values in each parameter's unit."""
    from .exercise.units import convert

    overrides = {}
    for setting in settings:
        name, sep, text = setting.partition("=")
        if not sep:
            raise click.BadParameter(f"{setting!r} is not NAME=VALUE", param_hint="--set")
        parameter = exercise.parameter(name.strip())
        number, _, unit = text.strip().partition(" ")
        try:
            value = float(number)
            overrides[parameter.name] = (convert(value, unit.strip(), parameter.unit)
                                         if unit.strip() else value)
        except ValueError as error:
            raise click.BadParameter(f"{setting!r}: {error}", param_hint="--set") from None
    return overrides


from .serve.commands import links as _links, policy as _policy, serve as _serve  # noqa: E402  (light: click only)
from .serve.lti.commands import lti as _lti  # noqa: E402  (light: click only)

main.add_command(_serve)
main.add_command(_links)
main.add_command(_policy)
main.add_command(_lti)
for _subcommand in main.commands.values():  # --exercises after any subcommand, too
    _subcommand.params.append(_subcommand_exercises_option())

if __name__ == "__main__":
    main()
