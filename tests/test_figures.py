"""Every exercise figure in the bank renders to well-formed SVG, the same bytes each time,
and labels no reference answer of its variant."""

from __future__ import annotations

import dataclasses
import math
import re
import xml.etree.ElementTree as ET

import pytest

from dynagrade.exercise import open_bank
from dynagrade.render.figures import figure_svg
from dynagrade.exercise.numbers import format_number

SEEDS = (0, 1, 2)
_NUMBER = re.compile(r"-?\d+(?:\.\d+)?(?:e-?\d+)?")
_FIGURED = sorted(e.id for e in open_bank().listing() if e.figured)  # no file is run


def _label_texts(exercise, variant) -> list[str]:
    """The strings of the figure's <text> elements (its labels, written as SVG text), read
    from the SVG the sheets embed."""
    root = ET.fromstring(figure_svg(exercise, variant).encode())
    return ["".join(element.itertext()) for element in root.iter()
            if element.tag.rsplit("}", 1)[-1] == "text"]


def _answer_numbers(exercise, variant) -> set[str]:
    """Every numeric reference answer of the variant, printed as the sheets print numbers,
    both in the part's unit and in SI."""
    in_si = exercise.solve(exercise.si(variant.params))
    printed = set()
    for answers in (variant.answers, in_si):
        for name, value in answers.items():
            values = value if isinstance(value, (tuple, list)) else (value,)
            for number in values:
                if isinstance(number, (int, float)) and not isinstance(number, bool) \
                        and math.isfinite(number):
                    printed.add(format_number(float(number)))
    return printed


def _given_numbers(exercise, variant) -> set[str]:
    """The parameters as the statement prints them (declared units) and in SI: a label
    showing one of them gives nothing away, even when an answer happens to share it."""
    in_si = exercise.si(variant.params)
    return {format_number(float(value)) for name, value in variant.params.items()} \
        | {format_number(float(getattr(in_si, name))) for name in variant.params}


def _given_away(exercise, variant) -> set[str]:
    """The answers that appear as a number in one of the figure's labels, other than the
    given values."""
    shown = {number for text in _label_texts(exercise, variant)
             for number in _NUMBER.findall(text.replace("\u2212", "-"))}
    return _answer_numbers(exercise, variant) & (shown - _given_numbers(exercise, variant))


def test_a_dozen_or_more_exercises_across_the_chapters_have_figures():
    chapters = {open_bank().get(exercise_id).chapter for exercise_id in _FIGURED}
    assert len(_FIGURED) >= 12 and chapters == {1, 2, 3, 4, 5}


@pytest.mark.parametrize("exercise_id", _FIGURED)
def test_the_figure_is_well_formed_svg_with_the_same_bytes_on_every_render(bank, exercise_id):
    exercise = bank.get(exercise_id)
    for seed in SEEDS:
        variant = exercise.variant(seed)
        first = figure_svg(exercise, variant)
        root = ET.fromstring(first.encode())
        assert root.tag.endswith("svg")
        assert figure_svg(exercise, variant) == first


@pytest.mark.parametrize("exercise_id", _FIGURED)
def test_the_figure_labels_given_values_and_no_reference_answer(bank, exercise_id):
    exercise = bank.get(exercise_id)
    for seed in SEEDS:
        variant = exercise.variant(seed)
        assert _label_texts(exercise, variant), "the figure has no labels at all"
        assert not _given_away(exercise, variant), f"seed {seed}"


def test_a_figure_that_prints_an_answer_is_caught(bank):
    exercise = bank.get("block-sliding-down-incline")
    variant = exercise.variant(0)

    def telling(p):
        drawing = exercise.figure(p)
        answer = exercise.solve(p)["a"]
        drawing.axes[0].text(0.0, 0.0, f"a = {format_number(answer)} m/s²")
        return drawing

    assert _given_away(dataclasses.replace(exercise, figure=telling), variant) \
        == {format_number(exercise.solve(exercise.si(variant.params))["a"])}
