"""Worked solution sheets: one student's solutions as Markdown, HTML (MathML) and typst
(for PDF), and the check that a solution's math renders in both.

Usage::

    sheet = SolutionSheet(exam, "s1", "Ada", (SolutionSection(1, ...), ...))
    solution_markdown(sheet); solution_html(sheet)
    source = typst_preamble(exam, title) + solution_typst_body(sheet)
    math_problems(markdown)     # [] when the math renders in HTML and PDF
"""

from __future__ import annotations

from dataclasses import dataclass

from .markup import markdown_to_typst, math_warnings
from .pdf import compile_pdf
from .sheets import render_template

#: what a section says when its exercise has no worked solution yet
NO_SOLUTION = "No worked solution has been written for this exercise yet."


@dataclass(frozen=True)
class SolutionSection:
    """One exercise's statement and worked solution (Markdown, the variant's numbers)."""

    number: int
    id: str
    title: str
    source: str
    statement: str
    solution: str | None


@dataclass(frozen=True)
class SolutionSheet:
    """One student's worked solutions."""

    exam: dict  # id, title, date, instructions
    student_id: str
    name: str
    sections: tuple[SolutionSection, ...]


def solution_markdown(sheet: SolutionSheet) -> str:
    return render_template("solution.md", sheet=sheet, no_solution=NO_SOLUTION)


def solution_html(sheet: SolutionSheet) -> str:
    return render_template("solution.html", sheet=sheet, no_solution=NO_SOLUTION)


def solution_typst_body(sheet: SolutionSheet) -> str:
    """One student's solution pages; bodies of several students can follow one preamble."""
    return render_template("solution.typ", sheet=sheet, no_solution=NO_SOLUTION)


def math_problems(markdown: str) -> list[str]:
    """What keeps the math of ``markdown`` from rendering: TeX commands the HTML (MathML)
    and typst writers do not know, or typst failing to lay the text out."""
    problems = [f"the math uses {command}, which the HTML and PDF renderers do not know"
                for command in math_warnings(markdown)]
    try:
        compile_pdf(render_template("solution_check.typ", body=markdown_to_typst(markdown)))
    except Exception as error:  # typst's own error type; its message says what failed
        problems.append(f"typst cannot lay it out: {str(error).splitlines()[0]}")
    return problems
