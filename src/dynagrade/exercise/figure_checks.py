"""What is checked of an exercise's figure, and how a figure that fails is reported.

An exercise's ``figure(p)`` is its author's code, run for every variant an exam hands
out. A figure that raises is reported on one line naming the exercise, its file and the
line of that file where it failed (:class:`FigureError`), never as a traceback. A figure
that renders is checked on the SVG text it yields, whatever drew it:

- the SVG is well formed XML with an ``<svg>`` root (:func:`svg_problems`);
- no text it carries (labels, title, description) shows a reference answer of the
  variant, as the sheets print numbers, in the part's unit or in SI, unless that number
  is also one of the given values (:func:`given_away`).

Usage::

    with reported_figure_failure(exercise, variant.seed):
        figure = exercise.figure(exercise.si(variant.params))
    problems = figure_problems(exercise, variant, figure_svg)   # as dynagrade verify does
"""

from __future__ import annotations

import math
import re
from contextlib import contextmanager
from typing import Callable, Iterator

from ..errors import DynagradeError
from .model import Exercise, Variant
from .numbers import format_number
from .source_lines import failure_line

#: a number as a label writes it (not a subscript such as the 2 of ``m_2`` or ``v₂``)
_NUMBER = re.compile(r"(?<![A-Za-z_{^])-?\d+(?:\.\d+)?(?:[eE]-?\d+)?")
#: the SVG elements whose text a reader sees or hears
_TEXT_ELEMENTS = {"text", "tspan", "textPath", "title", "desc"}


class FigureError(DynagradeError):
    """An exercise's figure function failed; the message names exercise, file and line."""


@contextmanager
def reported_figure_failure(exercise: Exercise, seed: int) -> Iterator[None]:
    """Run the body (drawing and rendering ``exercise``'s figure of ``seed``); any
    exception it raises becomes a :class:`FigureError` of one line."""
    try:
        yield
    except FigureError:
        raise
    except Exception as error:
        raise FigureError(figure_failure(exercise, seed, error)) from None


def figure_failure(exercise: Exercise, seed: int, error: BaseException) -> str:
    """``FILE, line N: exercise 'id', seed S: the figure fails: TypeError: ...``."""
    return failure_line(exercise.path, exercise.figure, error,
                        f"exercise {exercise.id!r}, seed {seed}: the figure fails")


def figure_problems(exercise: Exercise, variant: Variant,
                    render: Callable[[Exercise, Variant], str | None]) -> list[str]:
    """Why the variant's figure, rendered to SVG by ``render``, cannot be handed out:
    it fails, is not well formed, or shows a reference answer (each message names the
    seed). Empty without a figure."""
    if exercise.figure is None:
        return []
    try:
        svg = render(exercise, variant)
    except FigureError as error:
        return [str(error)]
    if svg is None:
        return []
    problems = svg_problems(svg)
    if not problems:
        shown = given_away(exercise, variant, svg)
        if shown:
            problems = [f"the figure shows the reference answer {', '.join(sorted(shown))}; "
                        "a figure may label given values only"]
    return [f"seed {variant.seed}: {problem}" for problem in problems]


def svg_problems(svg: str) -> list[str]:
    """Why ``svg`` is not a well formed SVG document; empty when it is."""
    root = _parsed(svg)
    if isinstance(root, str):
        return [f"the figure is not well formed SVG: {root}"]
    if _local(root.tag) != "svg":
        return [f"the figure's root element is <{_local(root.tag)}>, not <svg>"]
    return []


def svg_texts(svg: str) -> list[str]:
    """The text of every element of ``svg`` that a reader sees or hears: its labels
    (where kept as text), its title and its description."""
    root = _parsed(svg)
    if isinstance(root, str):
        return []
    return ["".join(element.itertext()) for element in root.iter()
            if isinstance(element.tag, str) and _local(element.tag) in _TEXT_ELEMENTS]


def given_away(exercise: Exercise, variant: Variant, svg: str) -> set[str]:
    """The reference answers of ``variant`` that the figure's text shows as a number,
    other than the given values (a label showing a given value gives nothing away, even
    when an answer happens to share it)."""
    shown = {number for text in svg_texts(svg)
             for number in _NUMBER.findall(text.replace("\u2212", "-"))}
    return answer_numbers(exercise, variant) & (shown - given_numbers(exercise, variant))


def answer_numbers(exercise: Exercise, variant: Variant) -> set[str]:
    """Every number the solver gives for the variant, printed as the sheets print numbers:
    the parts' answers in their units, and everything the solver returns, in SI."""
    in_si = exercise.solve(exercise.si(variant.params))
    printed = set()
    for answers in (variant.answers, in_si):
        for value in answers.values():
            for number in value if isinstance(value, (tuple, list)) else (value,):
                if isinstance(number, (int, float)) and not isinstance(number, bool) \
                        and math.isfinite(number):
                    printed.add(format_number(float(number)))
    return printed


def given_numbers(exercise: Exercise, variant: Variant) -> set[str]:
    """The parameters as the statement prints them (declared units) and in SI."""
    in_si = exercise.si(variant.params)
    return {format_number(float(value)) for value in variant.params.values()} \
        | {format_number(float(getattr(in_si, name))) for name in variant.params}


def _parsed(svg: str):
    """The root element of ``svg``, or the parser's complaint."""
    import xml.etree.ElementTree as ET

    try:
        return ET.fromstring(svg.encode("utf-8"))
    except ET.ParseError as error:
        return str(error)


def _local(tag: str) -> str:
    return tag.rsplit("}", 1)[-1]
