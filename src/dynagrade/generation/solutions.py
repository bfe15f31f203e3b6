"""Worked solutions in an exam: each student's solution sheet (``dynagrade exam
--solutions``); those that end a student's feedback after class grading are
:mod:`dynagrade.classgrade.solutions`.

Output, next to the student's exam sheet::

    students/<student_id>/solution.md, solution.html, solution.pdf

When students see them, ``exam.toml`` says (:mod:`dynagrade.exam.solution_policy`).

A variant's solution is rendered from its parameters (the manifest stores them), so the
solutions of a graded exam are the ones its students were given numbers for.
"""

from __future__ import annotations

from typing import Iterable

from ..exercise.model import Exercise, Variant
from ..exercise.solution import render_solution
from ..render.solutions import (SolutionSection, SolutionSheet, solution_html,
                                solution_markdown, solution_typst_body)
from ..render.sheets import typst_preamble
from ..exam.spec import Student
from ..runs.files import write_atomic
from .run import GenerationRun


def solution_sections(solved: Iterable[tuple[Exercise, Variant]]) -> tuple[SolutionSection, ...]:
    """One section per exercise, numbered as on the exam sheet: its statement with the
    variant's numbers and its worked solution (``None`` when it has none)."""
    return tuple(SolutionSection(number, exercise.id, exercise.title, exercise.source,
                                 variant.statement, render_solution(exercise, variant))
                 for number, (exercise, variant) in enumerate(solved, 1))


def write_solution_sheet(run: GenerationRun, student: Student,
                         solved: list[tuple[Exercise, Variant]]) -> str:
    """solution.md, solution.html and (with PDFs) solution.pdf in the student's folder;
    returns the typst body (for the staff's combined PDF, should PDFs not embed)."""
    folder = run.out_dir / "students" / student.student_id
    sheet = SolutionSheet(run.spec.to_json(), student.student_id, student.name,
                          solution_sections(solved))
    write_atomic(folder / "solution.md", solution_markdown(sheet))
    write_atomic(folder / "solution.html", solution_html(sheet))
    body = solution_typst_body(sheet)
    if run.pdf:
        preamble = typst_preamble(run.spec.to_json(), solutions_title(run.spec.title))
        write_atomic(folder / "solution.pdf", run.compiler.compile(preamble + body))
    return body


def solutions_title(exam_title: str) -> str:
    """The title of a solution sheet's PDF."""
    return f"{exam_title}: worked solutions"
