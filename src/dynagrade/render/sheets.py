"""A student's exam sheet as Markdown, HTML (MathML, inline SVG) and typst (for PDF).

The three renderers read one description of the sheet (:class:`StudentSheet`), built by
:mod:`dynagrade.generation.generate`. Numbers are formatted in Python before they reach a
template; typst only lays out text.

Usage::

    markdown = sheet_markdown(sheet)
    page = sheet_html(sheet)
    source = typst_preamble(sheet.exam) + sheet_typst_body(sheet)
"""

from __future__ import annotations

import re

from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import jinja2
from markupsafe import Markup

from .accessible_svg import svg_text_alternative
from .figures import inline_svg, scale_phrase
from ..exercise.numbers import format_number, points_phrase, points_text
from .markup import inline_html, inline_typst, markdown_to_html, markdown_to_typst, typst_text
from .mathtex import typst_string

TEMPLATES = Path(__file__).resolve().parent.parent / "templates"


@dataclass(frozen=True)
class SheetPart:
    """One answer part as the sheet lists it (points already scaled to the exam)."""

    name: str
    label: str
    kind: str
    unit: str
    points: float
    hint: str = ""


@dataclass(frozen=True)
class SheetExercise:
    """One exercise on a student's sheet."""

    number: int
    id: str
    title: str
    source: str
    points: float
    statement: str  # Markdown with $...$ math, the variant's numbers filled in
    parts: tuple[SheetPart, ...]
    fill_in: str  # the name of the fill-in file
    svg: str | None = None
    figure_file: str | None = None  # relative to the sheet, for the Markdown link
    to_scale: bool = False  # the exercise's figure_to_scale

    @property
    def scale_phrase(self) -> str:
        """The caption's words on the figure's scale."""
        return scale_phrase(self.to_scale)


@dataclass(frozen=True)
class StudentSheet:
    """Everything on one student's sheet."""

    exam: dict  # id, title, date, instructions
    student_id: str
    name: str
    exercises: tuple[SheetExercise, ...]

    @property
    def total_points(self) -> float:
        return sum(e.points for e in self.exercises)

    def figure_number(self, exercise: SheetExercise) -> int:
        """The figure's number on the sheet: figures count 1, 2, 3, ... and an exercise
        without a figure skips no number."""
        with_figures = [e.id for e in self.exercises if e.svg]
        return with_figures.index(exercise.id) + 1

    @property
    def language(self) -> str:
        """The sheet's language tag (the exam's ``language``, English by default)."""
        return self.exam.get("language") or "en"


@lru_cache(maxsize=4)
def _environment(kind: str) -> jinja2.Environment:
    options = {"loader": jinja2.FileSystemLoader(str(TEMPLATES)),
               "undefined": jinja2.StrictUndefined, "keep_trailing_newline": True,
               "trim_blocks": True, "lstrip_blocks": True}
    if kind == "html":
        options["autoescape"] = True
    else:
        options["autoescape"] = False
        options["comment_start_string"] = "{##"
        options["comment_end_string"] = "##}"
    environment = jinja2.Environment(**options)
    environment.filters.update({
        "points": points_phrase, "points_number": points_text, "number": format_number,
        "md_text": markdown_text,
        "md_html": lambda text, offset=0: Markup(markdown_to_html(text, offset)),
        "inline_html": lambda text: Markup(inline_html(text)),
        "md_typst": markdown_to_typst, "inline_typst": inline_typst, "typst_text": typst_text,
        "typst_string": typst_string,
        "svg_inline": lambda svg, prefix="": Markup(inline_svg(svg, prefix)),
        "figure_text": figure_text,
    })
    return environment


_MARKDOWN_SPECIAL = re.compile(r"([\\`*_\[\]<>|~&#!])")


def markdown_text(text: str) -> str:
    """``text`` (a roster name, say) shown literally in Markdown: every character that
    could start markup or HTML is backslash-escaped, line breaks become spaces."""
    return _MARKDOWN_SPECIAL.sub(r"\\\1", " ".join(str(text).split()))


def figure_text(svg: str) -> str:
    """The title and description of a figure's SVG in one sentence, the PDF's alt text."""
    title, description = svg_text_alternative(svg)
    return f"{title}. {description}" if description else title


def render_template(name: str, **context) -> str:
    """Render ``templates/<name>``; ``.html`` templates escape HTML automatically."""
    kind = "html" if name.endswith(".html") else "text"
    return _environment(kind).get_template(name).render(**context)


def sheet_markdown(sheet: StudentSheet) -> str:
    return render_template("sheet.md", sheet=sheet)


def sheet_html(sheet: StudentSheet) -> str:
    return render_template("sheet.html", sheet=sheet)


def typst_date(iso: str) -> str:
    year, month, day = (int(x) for x in iso.split("-"))
    return f"datetime(year: {year}, month: {month}, day: {day})"


def typst_language(tag: str) -> str:
    """typst's text settings for a language tag: ``lang`` and, for "de-CH", ``region``."""
    language, _, rest = (tag or "en").partition("-")
    region = rest.split("-")[0] if rest else ""
    settings = f'lang: "{typst_string(language.lower())}"'
    if len(region) == 2 and region.isalpha():
        settings += f', region: "{typst_string(region.upper())}"'
    return settings


def typst_preamble(exam: dict, title: str | None = None) -> str:
    """Page, font and document settings: title, language and a fixed date (so PDFs
    reproduce)."""
    return render_template("preamble.typ", exam=exam, title=title or exam["title"],
                           date=typst_date(exam["date"]),
                           language=typst_language(exam.get("language") or "en"))


def sheet_typst_body(sheet: StudentSheet) -> str:
    """One student's pages; bodies of several students can follow one preamble."""
    return render_template("sheet.typ", sheet=sheet)
