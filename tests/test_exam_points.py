"""Points of an exam: the rounding exam.toml declares, the split of an exercise's points
over its parts (largest remainder, worked by hand below) and points given per part."""

from __future__ import annotations

import pytest
from hypothesis import given, strategies as st

from dynagrade.generation.generate import exercise_parts
from dynagrade.exam.manifest import from_dict, to_dict
from dynagrade.exam.points import Rounding, split_points
from dynagrade.exam.spec import ExamSpecError, read_exam_spec
from dynagrade.exercise.loader import open_bank

HEAD = 'id = "points-exam"\ntitle = "Points"\ndate = 2025-04-14\n'


@pytest.fixture(scope="module")
def bank():
    return open_bank()


def write(tmp_path, text):
    path = tmp_path / "exam.toml"
    path.write_text(HEAD + text, encoding="utf-8")
    return path


@pytest.mark.parametrize("total, weights, step, expected", [
    # 20 half points: quotas 20/7, 40/7, 80/7 = 2.857, 5.714, 11.43 → 2, 5, 11 and the two
    # half points left go to the remainders .857 and .714
    (10, (1, 2, 4), 0.5, (1.5, 3.0, 5.5)),
    # 800 hundredths over 2:1:1:1:1:1 → 228.57, 114.29 ×5 → 228 + 5 × 114 = 798; the two
    # left go to .571 (first part) and the first of the tied .286 (second part)
    (8, (2, 1, 1, 1, 1, 1), 0.01, (2.29, 1.15, 1.14, 1.14, 1.14, 1.14)),
    # 6 points over 2:1:1:1 divide exactly
    (6, (2, 1, 1, 1), 0.01, (2.4, 1.2, 1.2, 1.2)),
    # whole points: 7 over 1:1:1 → 2.33 each → 2, 2, 2 and one left for the first part
    (7, (1, 1, 1), 1, (3.0, 2.0, 2.0)),
])
def test_points_are_split_by_largest_remainder_as_worked_by_hand(total, weights, step,
                                                                  expected):
    assert split_points(total, weights, Rounding(step)) == expected


@given(total_steps=st.integers(1, 400), step=st.sampled_from([0.01, 0.1, 0.25, 0.5, 1.0]),
       weights=st.lists(st.integers(1, 20), min_size=1, max_size=8))
def test_split_parts_are_multiples_of_the_step_summing_to_the_total_and_near_their_quota(
        total_steps, step, weights):
    """Every part is a whole number of steps, the parts add up to the total exactly, and
    no part is a whole step or more away from its exact proportional share."""
    rounding = Rounding(step)
    total = rounding.points(total_steps)
    parts = split_points(total, weights, rounding)
    assert all(rounding.is_multiple(p) for p in parts)
    assert sum(rounding.steps(p) for p in parts) == total_steps
    for part, weight in zip(parts, weights):
        assert abs(part - total * weight / sum(weights)) < step + 1e-9


def test_a_total_that_is_not_a_multiple_of_the_step_cannot_be_split():
    with pytest.raises(ValueError, match="multiples of 0.5"):
        split_points(6.25, (1, 1), Rounding(0.5))


def test_rounding_goes_to_the_nearest_step_a_half_upwards_and_prints_without_noise():
    half, hundredths = Rounding(0.5), Rounding.to_decimals(2)
    assert [half.round(v) for v in (2.24, 2.25, 2.74, 2.75)] == [2.0, 2.5, 2.5, 3.0]
    assert hundredths.round(1.0 / 3) == 0.33 and hundredths.round(0.125) == 0.13
    assert hundredths.total([0.1, 0.1, 0.1]) == 0.3  # not 0.30000000000000004
    assert (half.text(3.0), half.text(2.5), hundredths.text(2.285714)) == ("3", "2.5", "2.29")


def test_the_exam_reads_round_or_decimals_and_splits_every_exercise(tmp_path, bank):
    spec = read_exam_spec(write(tmp_path, 'round = 0.5\n[[exercise]]\nid = "car-in-a-looping"'
                                          '\npoints = 8\n'), bank.get)
    assert spec.rounding == Rounding(0.5)
    exercise = bank.get("car-in-a-looping")  # parts weighted 2:1:1:1:1:1
    points = [p.points for p in exercise_parts(exercise, 8, None, spec.rounding)]
    # 16 half points: 4.571, 2.286 ×5 → 4 + 5 × 2 = 14; two left: .571, then the first .286
    assert points == [2.5, 1.5, 1.0, 1.0, 1.0, 1.0]
    assert read_exam_spec(write(tmp_path, 'decimals = 1\n[[exercise]]\nid = '
                                          '"car-in-a-looping"\npoints = 8\n'),
                          bank.get).rounding == Rounding(0.1)
    assert read_exam_spec(write(tmp_path, '[[exercise]]\nid = "car-in-a-looping"\npoints = '
                                          '8\n'), bank.get).rounding == Rounding(0.01)


def test_an_exam_may_give_every_parts_points_and_the_exercise_is_worth_their_sum(
        tmp_path, bank):
    spec = read_exam_spec(write(tmp_path, '[[exercise]]\nid = "projectile-range"\n'
                                          '[exercise.points]\nx_max = 3\nh_max = 1.5\n'
                                          't_flight = 1\nx_max_formula = 0.5\n'), bank.get)
    item = spec.exercises[0]
    assert item.points == 6.0 and spec.total_points == 6.0
    parts = exercise_parts(bank.get("projectile-range"), item.points, item.part_points,
                           spec.rounding)
    assert [(p.name, p.points) for p in parts] == [
        ("x_max", 3.0), ("h_max", 1.5), ("t_flight", 1.0), ("x_max_formula", 0.5)]


@pytest.mark.parametrize("text, expected", [
    ('round = 0.5\ndecimals = 2\n[[exercise]]\nid = "projectile-range"\npoints = 6\n',
     "line 5: give 'round' or 'decimals', not both"),
    ('round = -1\n[[exercise]]\nid = "projectile-range"\npoints = 6\n',
     "line 4, field 'round': -1"),
    ('decimals = 2.5\n[[exercise]]\nid = "projectile-range"\npoints = 6\n',
     "field 'decimals': 2.5; give a whole number from 0 to 6"),
    ('round = 0.5\n[[exercise]]\nid = "projectile-range"\npoints = 6.25\n',
     "field 'points': 6.25 cannot be split into the exam's rounding (multiples of 0.5)"),
    ('[[exercise]]\nid = "projectile-range"\n[exercise.points]\nx_max = 3\n',
     "field 'points': give every part's points; missing h_max, t_flight, x_max_formula"),
    ('[[exercise]]\nid = "projectile-range"\n[exercise.points]\nx_maximum = 3\n',
     "field 'points.x_maximum': the exercise has no part 'x_maximum'"),
    ('[[exercise]]\nid = "projectile-range"\n[exercise.points]\nx_max = "three"\n',
     "field 'points.x_max': 'three'"),
    ('round = 0.5\n[[exercise]]\nid = "projectile-range"\n[exercise.points]\nx_max = 1.25\n'
     'h_max = 1\nt_flight = 1\nx_max_formula = 1\n',
     "field 'points.x_max': 1.25 is not one of the exam's multiples of 0.5"),
])
def test_bad_rounding_or_part_points_are_refused_naming_line_and_field(tmp_path, bank, text,
                                                                       expected):
    with pytest.raises(ExamSpecError) as caught:
        read_exam_spec(write(tmp_path, text), bank.get)
    assert expected in str(caught.value)


def test_the_manifest_keeps_a_rounding_other_than_hundredths(tmp_path):
    manifest = {"format": "dynagrade-exam-manifest", "version": 1,
                "generator": {"dynagrade": "x", "numpy": "y"},
                "exam": {"id": "e", "title": "t", "date": "2025-04-14", "instructions": "",
                         "points": 6, "round": 0.5},
                "exercises": [], "students": []}
    assert from_dict(manifest).exam.rounding == 0.5
    assert to_dict(from_dict(manifest))["exam"]["round"] == 0.5
    del manifest["exam"]["round"]
    assert from_dict(manifest).exam.rounding == 0.01
    assert "round" not in to_dict(from_dict(manifest))["exam"]
