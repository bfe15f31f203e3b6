"""The Moodle export and the grader use one tolerance rule: an answer inside the tolerance
written into moodle.xml is right for `dynagrade grade`, one just outside is wrong."""

from __future__ import annotations

import math

from hypothesis import given, settings
from hypothesis import strategies as st

from dynagrade.grading import NumericSpec, VectorSpec, grade
from dynagrade.render.moodle import tolerance, vector_tolerances

values = st.floats(min_value=-1e6, max_value=1e6, allow_nan=False).map(lambda v: round(v, 6))
rtols = st.sampled_from([1e-3, 5e-3, 1e-2, 2e-2, 5e-2])
atols = st.one_of(st.none(), st.sampled_from([1e-4, 1e-3, 0.05, 1.0]))


def _text(value: float) -> str:
    return repr(float(value))


@settings(max_examples=150, deadline=None)
@given(values, rtols, atols, st.sampled_from([-1, 1]))
def test_a_number_within_the_moodle_tolerance_is_right_for_the_grader_and_beyond_it_wrong(
        expected, rtol, atol, sign):
    tol = tolerance(expected, rtol, atol)
    spec = NumericSpec(rtol=rtol, atol=atol)
    assert grade(spec, expected, _text(expected + sign * 0.999 * tol)).correct
    assert not grade(spec, expected, _text(expected + sign * 1.001 * tol)).correct


@settings(max_examples=150, deadline=None)
@given(st.lists(values, min_size=2, max_size=3), rtols, atols, st.data())
def test_a_vector_component_within_its_moodle_tolerance_is_right_and_beyond_it_wrong(
        expected, rtol, atol, data):
    tols = vector_tolerances(expected, rtol, atol)
    index = data.draw(st.integers(0, len(expected) - 1))
    sign = data.draw(st.sampled_from([-1, 1]))
    spec = VectorSpec(len(expected), rtol=rtol, atol=atol)

    def answer(factor: float) -> str:
        moved = list(expected)
        moved[index] += sign * factor * tols[index]
        return "[" + ", ".join(_text(v) for v in moved) + "]"

    assert grade(spec, tuple(expected), answer(0.999)).correct
    assert not grade(spec, tuple(expected), answer(1.001)).correct


def test_a_zero_component_gets_the_tolerance_dynagrade_grades_it_with():
    """(3, 0) m at 1 %: dynagrade accepts [3, 0.0002] m (the zero component is judged
    against 1 % of the length, 0.01·0.01·3 = 0.0003), so Moodle must too (it had 0)."""
    tols = vector_tolerances([3.0, 0.0], 1e-2, None)
    assert math.isclose(tols[0], 0.03) and math.isclose(tols[1], 3e-4)
    assert grade(VectorSpec(2, unit="m"), (3.0, 0.0), "[3, 0.0002] m").correct


def test_a_zero_number_keeps_the_graders_absolute_floor():
    """A reference of exactly 0 with no atol: the grader accepts within 1e-9, so the
    Moodle tolerance is 1e-9, not 0 (which no typed answer but 0 itself could meet)."""
    assert tolerance(0.0, 1e-2, None) == 1e-9
    assert grade(NumericSpec(), 0.0, "5e-10").correct


def test_the_ten_figures_move_moodles_boundary_by_a_few_parts_in_ten_billion():
    """docs/exams.md: for 2/3 at 1 % Moodle holds 0.6666666667 within 0.006666666667, so
    its upper edge is 0.673333333367 where the grader's is 0.673333333333...: an
    11-figure response between the two, 0.67333333335, is right in Moodle and wrong for
    the grader; 0.6733333333 is right in both."""
    from dynagrade.render.cloze import number_text

    written, allowed = number_text(2 / 3), number_text(tolerance(2 / 3, 1e-2, None))
    assert (written, allowed) == ("0.6666666667", "0.006666666667")
    assert abs(0.67333333335 - float(written)) <= float(allowed)
    assert not grade(NumericSpec(), 2 / 3, "0.67333333335").correct
    assert abs(0.6733333333 - float(written)) <= float(allowed)
    assert grade(NumericSpec(), 2 / 3, "0.6733333333").correct
