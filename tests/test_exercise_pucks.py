"""The chapter 2.1 exercise, pucks-centre-of-mass, against a variant worked by hand."""

from __future__ import annotations

import pytest

from dynagrade.exercise import open_bank
from dynagrade.exercise.scoring import grade_variant

# m = (2, 1, 0.5) kg, so M = 3.5 kg
# r1 = (1.0, 0.5), r2 = (-1.0, 1.0), r3 = (0.5, -1.5) m
# v1 = (0.5, -1.0), v2 = (1.5, 0.5), v3 = (-1.0, 2.0) m/s
# sum m x = 2 - 1 + 0.25 = 1.25, sum m y = 1 + 1 - 0.75 = 1.25  -> r_C = (0.357143, 0.357143)
# sum m u = 1 + 1.5 - 0.5 = 2,   sum m w = -2 + 0.5 + 1 = -0.5   -> v_C = (0.571429, -0.142857)
# rho_1 = r1 - r_C = (0.642857, 0.142857)
# rho_2' = v2 - v_C = (0.928571, 0.642857)
# plain mean of the positions (0.166667, 0); of the velocities (0.333333, 0.5)
HAND = {"m1": 2.0, "m2": 1.0, "m3": 0.5,
        "x1": 1.0, "y1": 0.5, "x2": -1.0, "y2": 1.0, "x3": 0.5, "y3": -1.5,
        "u1": 0.5, "w1": -1.0, "u2": 1.5, "w2": 0.5, "u3": -1.0, "w3": 2.0}


@pytest.fixture(scope="module")
def hand():
    exercise = open_bank().get("pucks-centre-of-mass")
    return exercise, exercise.variant(0, HAND)


def test_the_key_matches_the_hand_calculation(hand):
    _, variant = hand
    assert variant.answers["r_C"] == pytest.approx((1.25 / 3.5, 1.25 / 3.5))
    assert variant.answers["r_C"] == pytest.approx((0.357143, 0.357143), abs=1e-6)
    assert variant.answers["v_C"] == pytest.approx((0.571429, -0.142857), abs=1e-6)
    assert variant.answers["rho_1"] == pytest.approx((0.642857, 0.142857), abs=1e-6)
    assert variant.answers["u_2"] == pytest.approx((0.928571, 0.642857), abs=1e-6)


def test_the_hand_answers_score_full_marks(hand):
    exercise, variant = hand
    result = grade_variant(exercise, variant, {
        "r_C": "[0.357, 0.357]", "v_C": "[0.571, -0.143]", "rho_1": "[0.643, 0.143]",
        "u_2": "[0.929, 0.643]"})
    assert result.score == result.max_score == 6


@pytest.mark.parametrize("part, answer, misconception", [
    ("r_C", "[0.166667, 0]", "plain mean of the positions"),
    ("v_C", "[0.333333, 0.5]", "plain mean of the velocities"),
    ("rho_1", "[-0.642857, -0.142857]", "r_C − r_1 instead of r_1 − r_C"),
    ("rho_1", "[0.833333, 0.5]", "relative to the plain mean of the positions"),
    ("u_2", "[1.0, 1.5]", "relative to puck 1 instead of C"),
])
def test_the_misconceptions_worked_by_hand_are_recognised(hand, part, answer, misconception):
    exercise, variant = hand
    (result,) = [r for r in grade_variant(exercise, variant, {part: answer}).parts
                 if r.name == part]
    assert not result.correct and result.misconception == misconception


def test_the_figure_does_not_draw_the_centre_of_mass(hand):
    exercise, variant = hand
    axes = exercise.figure(exercise.si(variant.params)).axes[0]
    labels = {t.get_text() for t in axes.texts}
    assert {"m₁", "m₂", "m₃", "v₁", "v₂", "v₃", "O", "x", "y"} <= labels
    assert "C" not in labels
