"""Item analysis of a graded class, against values worked out by hand."""

from __future__ import annotations

import math

import numpy as np

from dynagrade.exam.manifest import PartEntry
from dynagrade.classgrade.stats import (StudentParts, correlation, part_statistics,
                                        upper_lower_index)
from dynagrade.exercise.results import GradedPart, Status


def test_correlation_agrees_with_numpy_and_is_none_without_variation():
    xs, ys = [1.0, 0.0, 1.0, 1.0, 0.0], [7.0, 2.0, 5.0, 9.0, 4.0]
    assert math.isclose(correlation(xs, ys), np.corrcoef(xs, ys)[0, 1], rel_tol=1e-12)
    assert correlation([1.0, 1.0, 1.0], [1.0, 2.0, 3.0]) is None
    assert correlation([1.0], [2.0]) is None


def test_the_upper_lower_index_compares_the_best_and_weakest_27_percent():
    # 10 students: ceil(2.7) = 3 in each group. Totals rank students 0..9 in order.
    totals = [float(i) for i in range(10)]
    fractions = [0, 0, 1, 0, 1, 1, 0, 1, 1, 1]
    # weakest three (0, 1, 2): mean 1/3; best three (7, 8, 9): mean 1
    assert math.isclose(upper_lower_index(fractions, totals), 1 - 1 / 3)
    assert upper_lower_index([1.0], [3.0]) is None


def test_part_statistics_use_the_rest_of_the_exam_and_count_wrong_answers():
    part = PartEntry("x", "x", "numeric", "m", 2.0, rtol=0.01, atol=None)
    def graded_part(score, status, answer, misconception=None):
        return GradedPart("x", "x", status, score, 2.0, answer, "", misconception)

    graded = [
        StudentParts(10.0, {("e", "x"): graded_part(2.0, Status.CORRECT, "4.2")}),
        StudentParts(3.0, {("e", "x"): graded_part(0.0, Status.WRONG, " 8.4 ", "factor 2")}),
        StudentParts(6.0, {("e", "x"): graded_part(0.0, Status.WRONG, "8.4", "factor 2")}),
        StudentParts(5.0, {}),  # did not hand in exercise e
    ]
    (stats,) = part_statistics([("e", part)], graded)
    assert stats.answered == 3
    assert math.isclose(stats.difficulty, 1 / 3)
    # the rest of the exam: 10 - 2, 3 - 0, 6 - 0
    assert math.isclose(stats.point_biserial, np.corrcoef([1, 0, 0], [8, 3, 6])[0, 1])
    assert stats.wrong_answers == [("8.4", 2, "factor 2")]
    assert stats.misconceptions == [("factor 2", 2)]
