"""Misconceptions limited to a regime (``applies=``) and the redraw share ``verify``
reports: which draws an exam throws away, and why."""

from __future__ import annotations

import pytest

from dynagrade.exercise import Choice, Constraint, Exercise, Misconception, Numeric, Uniform
from dynagrade.exercise.params import DrawTally
from dynagrade.exercise.redraws import RedrawShare, percent
from dynagrade.exercise.scoring import grade_variant
from dynagrade.exercise.verify import variant_problems, verify_exercise


def _square(applies=None, values=(1.0, 2.0, 3.0)) -> Exercise:
    """y = x²; the misconception "not squared" (y = x) coincides with the key at x = 1."""
    return Exercise(
        id="square-of-x", title="Square", source="Section 1.1",
        params=(Choice("x", values, unit="m"),),
        statement="What is the square of $x$ = {{ x }}?",
        solve=lambda p: {"y": p.x ** 2},
        parts=(Numeric("y", "square", unit="m^2",
                       misconceptions=(Misconception("not squared", lambda p: p.x,
                                                     "Square it.", applies=applies),)),),
    )


def _seed_with(exercise: Exercise, x: float) -> int:
    return next(seed for seed in range(200) if exercise.variant(seed).params["x"] == x)


def test_a_misconception_equal_to_the_key_makes_the_variant_unusable():
    exercise = _square()
    variant = exercise.variant(_seed_with(exercise, 1.0))
    assert variant_problems(exercise, variant) == [
        "part y: the misconception 'not squared' gives the right answer"]


def test_outside_its_regime_a_misconception_cannot_make_a_variant_unusable():
    exercise = _square(applies=lambda p: p.x != 1)
    assert variant_problems(exercise, exercise.variant(_seed_with(exercise, 1.0))) == []


def test_inside_its_regime_a_misconception_still_names_the_mistake():
    exercise = _square(applies=lambda p: p.x != 1)
    variant = exercise.variant(_seed_with(exercise, 3.0))
    result = grade_variant(exercise, variant, {"y": "3"})  # x = 3 m, not squared
    assert result.parts[0].misconception == "not squared"


def test_outside_its_regime_a_misconception_is_not_tried_on_an_answer():
    # "not squared" limited to x = 3: at x = 2 m the answer 2 (= x) earns no such feedback
    exercise = _square(applies=lambda p: p.x == 3)
    variant = exercise.variant(_seed_with(exercise, 2.0))
    result = grade_variant(exercise, variant, {"y": "2"})
    assert not result.parts[0].correct
    assert result.parts[0].misconception != "not squared"


def test_a_formula_misconception_limited_to_a_regime_is_tried_only_there():
    """A formula part checks its names when it is built, before any variant: the
    predicate, which reads the parameters, is not called then. The slip h + h is the
    formula itself, so it makes exactly the variants with x > 2 m unusable."""
    from dynagrade.exercise import Symbolic

    exercise = Exercise(
        id="twice-x", title="Twice", source="Section 1.1",
        params=(Choice("x", (1.0, 2.0, 3.0), unit="m"),),
        statement="A length $x$ = {{ x }}. Write twice it as a formula in $x$.",
        solve=lambda p: {},
        parts=(Symbolic("y", "twice x", expected="2*x", variables=("x",),
                        misconceptions=(Misconception("slip", "x + x", "Check it.",
                                                      applies=lambda p: p.x > 2),)),),
    )
    for x, expected in ((2.0, []), (3.0, ["part y: the misconception 'slip' gives the "
                                          "right answer"])):
        variant = exercise.variant(_seed_with(exercise, x))
        assert variant_problems(exercise, variant) == expected


def test_the_predicate_receives_the_parameters_in_si():
    seen = []
    exercise = _square(applies=lambda p: seen.append(p.x) or True, values=(200.0,))
    exercise.part("y").misconceptions_for(exercise.si({"x": 200.0}))
    assert seen == [200.0]  # metres are SI already; a unit check follows
    exercise = Exercise(
        id="angle", title="Angle", source="Section 1.1",
        params=(Choice("alpha", (90.0,), unit="deg"),),
        statement="$\\alpha$ = {{ alpha }}",
        solve=lambda p: {"y": p.alpha},
        parts=(Numeric("y", "angle", unit="rad", misconceptions=(Misconception(
            "degrees", lambda p: 90.0, "rad", applies=lambda p: seen.append(p.alpha)),)),))
    exercise.part("y").misconceptions_for(exercise.si({"alpha": 90.0}))
    assert seen[-1] == pytest.approx(1.5707963267948966)  # 90° = π/2 rad


def test_verify_counts_the_variants_an_exam_would_redraw_and_why():
    # x drawn from 1, 2, 3, 4 with equal chance: a quarter of the variants has x = 1
    exercise = _square(values=(1.0, 2.0, 3.0, 4.0))
    seeds = range(400)
    report = verify_exercise(exercise, seeds)
    ones = sum(exercise.variant(seed).params["x"] == 1.0 for seed in seeds)
    assert report.redraws.variants == 400
    assert report.redraws.redrawn == ones
    assert 0.2 < report.redraws.share < 0.3
    assert report.redraws.reasons == {
        "part y: the misconception 'not squared' gives the right answer": ones}
    assert "an exam redraws" in report.redraws.describe()
    assert "not squared" in report.redraws.describe()
    assert report.redraws.too_many


def test_with_applies_verify_finds_nothing_to_redraw():
    exercise = _square(applies=lambda p: p.x != 1, values=(1.0, 2.0, 3.0, 4.0))
    report = verify_exercise(exercise, range(100))
    assert report.ok
    assert report.redraws.redrawn == 0 and not report.redraws.too_many


def test_verify_counts_the_draws_each_constraint_rejects():
    # x uniform on 1..10 (ten values); "x > 4" rejects 1..4, i.e. 40 % of the draws
    exercise = Exercise(
        id="big-x", title="Big x", source="Section 1.1",
        params=(Uniform("x", 1, 10, step=1, unit="m"),),
        constraints=(Constraint("x is above 4 m", lambda p: p.x > 4),),
        statement="x = {{ x }}",
        solve=lambda p: {"y": p.x},
        parts=(Numeric("y", "x", unit="m"),))
    report = verify_exercise(exercise, range(300))
    tally = report.redraws.tally
    assert tally.draws == 300 + tally.rejected  # each seed's last draw is accepted
    assert tally.broken == {"x is above 4 m": tally.rejected}
    assert 0.3 < report.redraws.constraint_share < 0.5  # 0.4 within sampling noise
    assert "constraints reject" in report.redraws.describe()
    assert "x is above 4 m" in report.redraws.describe()


def test_a_draw_breaking_two_constraints_counts_once_as_rejected():
    tally = DrawTally()
    tally.record(["a", "b"])
    tally.record([])
    assert (tally.draws, tally.rejected, tally.broken) == (2, 1, {"a": 1, "b": 1})


@pytest.mark.parametrize("share, text", [(0.0, "0 %"), (0.004, "0.4 %"), (0.12, "12 %"),
                                         (1.0, "100 %")])
def test_shares_read_as_percentages(share, text):
    assert percent(share) == text


def test_more_than_a_tenth_redrawn_is_too_many():
    share = RedrawShare()
    for index in range(100):
        share.record(["coincides"] if index < 10 else [])
    assert not share.too_many  # exactly 10 %
    share.record(["coincides"])
    assert share.too_many


# -- the bank: misconceptions limited to where they are mistakes, instead of constraints
# that kept a band of the parameters away from every class -------------------------------

REGIMES = [
    # (exercise, part, misconception, where it coincides with the key, where it does not)
    ("peak-height-by-energy", "v_top", "sin for cos", {"alpha": 45}, {"alpha": 30}),
    ("block-sliding-down-incline", "a", "sin and cos swapped", {"alpha": 45, "mu": 0.3},
     {"alpha": 30, "mu": 0.3}),
    ("projectile-range", "x_max", "sin(alpha) for sin(2 alpha)", {"alpha": 60},
     {"alpha": 30}),
]


def _mistaken(exercise, part: str, name: str, overrides: dict):
    """The variant with ``overrides`` and the answer the misconception ``name`` gives."""
    variant = exercise.variant(0, overrides)
    misconception = next(m for m in exercise.part(part).misconceptions if m.name == name)
    value = misconception.value(exercise.si(variant.params))
    return variant, exercise.part(part).in_part_unit(value)


@pytest.mark.parametrize("exercise_id, part, name, coinciding, distinct", REGIMES)
def test_where_the_misconception_equals_the_key_the_variant_is_handed_out(
        bank, exercise_id, part, name, coinciding, distinct):
    exercise = bank.get(exercise_id)
    variant, wrong = _mistaken(exercise, part, name, coinciding)
    # the key and the misconception agree here (sin 45° = cos 45°, sin 60° = sin 120°) ...
    assert wrong == pytest.approx(variant.answers[part], rel=1e-9)
    # ... so it is not tried, and the variant can be handed out
    assert variant_problems(exercise, variant) == []


@pytest.mark.parametrize("exercise_id, part, name, coinciding, distinct", REGIMES)
def test_elsewhere_the_misconception_still_names_the_mistake(
        bank, exercise_id, part, name, coinciding, distinct):
    exercise = bank.get(exercise_id)
    variant, wrong = _mistaken(exercise, part, name, distinct)
    result = grade_variant(exercise, variant, {part: f"{wrong:.6g}"})
    assert next(r for r in result.parts if r.name == part).misconception == name


@pytest.mark.parametrize("exercise_id, low, high", [
    ("peak-height-by-energy", 41, 49), ("block-sliding-down-incline", 41, 49),
    ("projectile-range", 56, 64)])
def test_the_band_around_the_coincidence_is_drawn_again(bank, exercise_id, low, high):
    exercise = bank.get(exercise_id)
    angles = {exercise.variant(seed).params["alpha"] for seed in range(300)}
    assert any(low <= angle <= high and angle not in (45, 60) for angle in angles)
