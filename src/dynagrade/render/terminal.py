"""What the commands print in a terminal.

The grade report and the bank's listing are plain text tables (:mod:`.text_table`), so
that ``grade FILE`` and ``dynagrade list`` start without importing rich; the panels,
progress bars and the other commands' tables are rich's, imported where they are drawn.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Callable, Sequence

import click

from ..exercise.numbers import percent_text, points_text
from .text_table import text_table

if TYPE_CHECKING:
    from rich.console import Console

def _console(stderr: bool = False) -> Console:
    from rich.console import Console

    return Console(stderr=stderr, highlight=False)


def exercise_table(exercises) -> None:
    """The bank's listing: id, source, title and parts of every exercise."""
    click.echo(text_table(("id", "source", "title", "parts"), [
        (e.id, e.source, e.title, ", ".join(p.name for p in e.parts)) for e in exercises],
        title=f"{len(exercises)} exercises"), nl=False)


def section_table(sections, unplaced: Sequence[str], enough: int) -> None:
    """``list --by-section``: each section of the notes with its count of exercises, those
    with fewer than ``enough`` marked in words, then a line of totals."""
    few = [c for c in sections if not c.enough]
    click.echo(text_table(("section", "title", "exercises", ""), [
        (c.section, c.title, str(len(c.exercises)),
         "" if c.enough else f"fewer than {enough}") for c in sections],
        title=f"{sum(len(c.exercises) for c in sections)} exercises in "
              f"{len(sections)} sections"), nl=False)
    click.echo(f"{len(sections) - len(few)} of {len(sections)} sections have {enough} "
               f"exercises or more" + (f"; fewer than {enough}: "
                                       + ", ".join(c.section for c in few) if few else ""))
    if unplaced:
        click.echo(f"{len(unplaced)} exercises name no section of the notes in their "
                   f"source: {', '.join(unplaced)}")


def answers_table(exercise, variant) -> None:
    from rich.table import Table

    table = Table(title=f"{exercise.id}, seed {variant.seed}")
    table.add_column("part")
    table.add_column("answer")
    for part in exercise.parts:
        table.add_row(part.name, part.shown_answer(variant.answers[part.name]))
    _console().print(table)


def variant_panel(exercise, variant, with_answers: bool) -> None:
    from rich.markdown import Markdown
    from rich.panel import Panel

    console = _console()
    console.print(Panel(Markdown(variant.statement),
                        title=f"{exercise.title} ({exercise.source})",
                        subtitle=f"{exercise.id} · seed {variant.seed}"))
    if with_answers:
        answers_table(exercise, variant)


def solution_panel(exercise, variant, solution: str | None) -> None:
    """The variant's worked solution (Markdown), or a line saying there is none yet."""
    from rich.markdown import Markdown
    from rich.panel import Panel

    console = _console()
    if solution is None:
        console.print(f"[dim]{exercise.id} has no worked solution yet[/]")
        return
    console.print(Panel(Markdown(solution), title=f"Solution: {exercise.title}",
                        subtitle=f"{exercise.id} · seed {variant.seed}"))


def result_table(exercise, result) -> None:
    """The verdict, points and feedback of every part of a graded file, and the total."""
    click.echo(text_table(("part", "verdict", "points", "feedback"), [
        (part.name, part.status, f"{points_text(part.score)} / {points_text(part.points)}",
         part.shown_feedback()) for part in result.parts],
        title=f"{exercise.title} ({exercise.id}, seed {result.seed})",
        caption=f"total {points_text(result.score)} / {points_text(result.max_score)}"),
        nl=False)


def verify_progress(exercises: Sequence, check: Callable) -> list:
    """Run ``check`` on every exercise with a progress bar; print what failed."""
    from rich.progress import Progress

    console = _console(stderr=True)
    reports = []
    with Progress(console=console, transient=True) as progress:
        task = progress.add_task("verifying", total=len(exercises))
        for exercise in exercises:
            progress.update(task, description=f"verifying {exercise.id}")
            reports.append(check(exercise))
            progress.advance(task)
    out = _console()
    for report in reports:
        if report.ok:
            notes = "".join(f"; {note}" for note in report.notes)
            out.print(f"[green]ok[/]    {report.exercise_id}: {report.variants} variants"
                      f"{notes}")
        else:
            out.print(f"[red]FAIL[/]  {report.exercise_id}: {len(report.failures)} problems "
                      f"in {report.variants} variants")
        out.print(f"        {report.redraws.describe()}", soft_wrap=True, markup=False)
        if not report.ok:
            for failure in report.failures[:10]:
                out.print(f"        {failure}", soft_wrap=True)
            if len(report.failures) > 10:
                out.print(f"        … and {len(report.failures) - 10} more")
    failed = sum(not r.ok for r in reports)
    out.print(f"{len(reports) - failed} of {len(reports)} exercises passed")
    noted = sum(bool(r.notes) for r in reports)
    if noted:
        out.print(f"{noted} noted: " + "; ".join(sorted({n for r in reports for n in r.notes})))
    return reports


class progress_reporter:
    """A context manager giving ``progress(stage, done, total)``, shown as rich progress
    bars on stderr (one bar per stage)."""

    def __enter__(self):
        from rich.progress import Progress

        self._progress = Progress(console=_console(stderr=True), transient=False)
        self._tasks: dict[str, int] = {}
        self._progress.__enter__()
        return self.update

    def update(self, stage: str, done: int, total: int) -> None:
        if stage not in self._tasks:
            self._tasks[stage] = self._progress.add_task(stage, total=total)
        self._progress.update(self._tasks[stage], completed=done, total=total)

    def __exit__(self, *exc):
        return self._progress.__exit__(*exc)


def gradebook_table(outcome) -> None:
    """The class's grades, one row per roster student."""
    from rich.table import Table

    table = Table(title=f"{outcome.exam_title}: {len(outcome.rows)} students")
    numbers = [str(n) for n in range(1, len(outcome.exercise_ids) + 1)]
    for column in ("student", *numbers, "total", "%", "status"):
        table.add_column(column, no_wrap=column == "status", justify="left" if column in
                         ("student", "status") else "right")
    table.caption = "  ".join(f"{n}: {e}" for n, e in zip(numbers, outcome.exercise_ids))
    for row in outcome.rows:
        table.add_row(row.student_id, *(points_text(row.cells[e]) for e in outcome.exercise_ids),
                      f"{points_text(row.total)} / {points_text(row.max_total)}",
                      percent_text(row.percent), row.status)
    _console().print(table)
