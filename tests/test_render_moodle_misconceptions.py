"""The Moodle export and the grader give a vector the same credit when it is a declared
misconception: the rule of docs/grading.md ("Vectors"), a component's credit is 1 when it
is right, a misconception's score when it is that misconception's component (where the
misconception differs from the reference), 0 otherwise, and the vector scores the mean.
An answer equal to a misconception that shares k of n components with the reference and
has score s is worth (k + (n - k)·s)/n, in Moodle as in `dynagrade grade`."""

from __future__ import annotations

import math

from hypothesis import given, settings
from hypothesis import strategies as st

from dynagrade.exam.manifest import PartEntry
from dynagrade.grading import KnownWrong, VectorSpec, grade
from dynagrade.render.moodle import part_fields, vector_tolerances

from moodle_reader import moodle_mark, read_fields

#: at most 9 significant figures, so the export's 10 figures write them exactly
values = st.floats(min_value=-1e5, max_value=1e5, allow_nan=False).map(lambda v: round(v, 4))
rtols = st.sampled_from([1e-3, 1e-2, 5e-2])
atols = st.one_of(st.none(), st.sampled_from([1e-3, 0.05]))
scores = st.sampled_from([0.0, 0.25, 0.5])


def _vector_text(components) -> str:
    return "[" + ", ".join(repr(float(c)) for c in components) + "]"


def _misconception(data, expected, tolerances):
    """A wrong vector that keeps some components of ``expected`` and moves the others
    well outside their tolerance (at least once); the number of kept components."""
    kept = data.draw(st.lists(st.booleans(), min_size=len(expected), max_size=len(expected))
                     .filter(lambda keep: not all(keep)))
    wrong = []
    for value, allowed, keep in zip(expected, tolerances, kept):
        if keep:
            wrong.append(value)
            continue
        step = data.draw(st.floats(min_value=3.0, max_value=50.0)) * max(allowed, 1e-3)
        wrong.append(round(value + data.draw(st.sampled_from([-1, 1])) * step, 4))
    return wrong, sum(kept)


@settings(max_examples=150, deadline=None)
@given(st.lists(values, min_size=2, max_size=3), rtols, atols, scores, st.data())
def test_a_vector_misconception_earns_the_same_credit_in_moodle_and_in_the_grader(
        expected, rtol, atol, score, data):
    tolerances = vector_tolerances(expected, rtol, atol)
    wrong, kept = _misconception(data, expected, tolerances)
    n = len(expected)
    by_hand = (kept + (n - kept) * score) / n
    spec = VectorSpec(n, rtol=rtol, atol=atol, generic_misconceptions=False,
                      misconceptions=(KnownWrong("mistake", tuple(wrong), "A known mistake.",
                                                 score),))
    verdict = grade(spec, tuple(expected), _vector_text(wrong))
    assert not verdict.correct and verdict.misconception == "mistake"
    assert math.isclose(verdict.score, by_hand, abs_tol=1e-12)

    part = PartEntry("r", "position", "vector", None, 1.0, rtol=rtol, atol=atol, size=n)
    fields = read_fields("".join(part_fields(part, tuple(expected),
                                             (("mistake", tuple(wrong), "A known mistake.",
                                               score),), [1] * n)))
    assert math.isclose(moodle_mark(fields, wrong), by_hand, abs_tol=1e-12)


def test_a_misconception_that_flips_one_component_of_two_earns_half_everywhere():
    """(3, 4) m with the declared mistake (-3, 4) m, score 0: one component of two is
    right, so 0.5 in both (it was 0 in dynagrade and 0.5 in Moodle)."""
    spec = VectorSpec(2, unit="m", misconceptions=(KnownWrong("sign of x", (-3.0, 4.0),
                                                              "Check the sign of x."),))
    verdict = grade(spec, (3.0, 4.0), "[-3, 4] m")
    assert verdict.misconception == "sign of x" and verdict.score == 0.5
    assert "Check the sign of x." in verdict.feedback
