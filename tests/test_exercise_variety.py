"""Variety (``dynagrade verify``): an answer the whole class shares fails its part, and
two parts whose numbers can be swapped and score make the variant unusable."""

from __future__ import annotations

import pytest

from dynagrade.exercise import Choice, Constant, Exercise, Numeric, Options, Uniform, Vector
from dynagrade.exercise.variety import MIN_VARIANTS, coincidences, one_answer_problems
from dynagrade.exercise.verify import variant_problems, verify_exercise

SEEDS = range(60)


def _regime(c_low: float, c_high: float = 40.0,
            constant_answer: str | None = None) -> Exercise:
    """An oscillator of m = 1 kg, k = 100 N/m, so c_cr = 2 sqrt(k m) = 20 N s/m: the
    damper c drawn from [c_low, c_high] is underdamped below 20 and overdamped above."""
    return Exercise(
        id="regime", title="Regime", source="Section 4.3.2",
        params=(Uniform("c", c_low, c_high, step=1.0, unit="N*s/m"),),
        statement="A damper $c$ = {{ c }} on m = 1 kg, k = 100 N/m: which regime?",
        solve=lambda p: {"regime": "underdamped" if p.c < 20 else "overdamped"},
        parts=(Options("regime", "regime", options=("underdamped", "overdamped"),
                       constant_answer=constant_answer),),
    )


def _answers(exercise: Exercise, seeds=SEEDS) -> list[dict]:
    return [exercise.variant(seed).answers for seed in seeds]


def test_a_choice_whose_right_option_never_changes_fails_with_its_share():
    # c from 1 to 19 N s/m: always below c_cr = 20, always underdamped
    always = _regime(1.0, c_high=19.0)
    problems = one_answer_problems(always, list(SEEDS), _answers(always))
    assert problems == [
        "part regime: the answer underdamped scores in 60 of 60 variants (100 %); it never "
        "differs: vary the parameters so the class's answers differ, or give the part "
        "constant_answer=\"why\" where one answer is the physics taught"]


def test_a_choice_whose_right_option_changes_passes():
    # c from 1 to 40: underdamped for 19 of the 40 grid values, overdamped for 21
    exercise = _regime(1.0)
    answers = _answers(exercise)
    assert {a["regime"] for a in answers} == {"underdamped", "overdamped"}
    assert one_answer_problems(exercise, list(SEEDS), answers) == []


def test_a_choice_right_in_more_than_nine_draws_of_ten_fails_and_names_the_other_seeds():
    # c on the grid 19, 20, ..., 40: only c = 19 is underdamped, 1 value of 22, so
    # "overdamped" is right in about 95 % of the draws
    exercise = _regime(19.0)
    seeds = list(range(200))
    answers = _answers(exercise, seeds)
    under = [s for s, a in zip(seeds, answers) if a["regime"] == "underdamped"]
    assert 0 < len(under) < 20
    (problem,) = one_answer_problems(exercise, seeds, answers)
    assert problem.startswith(f"part regime: the answer overdamped scores in "
                              f"{200 - len(under)} of 200 variants")
    assert f"it differs only at seeds {', '.join(map(str, under[:5]))}" in problem


def test_a_constant_answer_with_its_reason_is_not_asked_to_vary():
    exercise = _regime(1.0, c_high=19.0, constant_answer="every damper drawn is below c_cr")
    assert one_answer_problems(exercise, list(SEEDS), _answers(exercise)) == []


def test_a_constant_answer_needs_a_reason():
    with pytest.raises(ValueError, match="constant_answer= gives the reason"):
        Options("regime", "regime", options=("a", "b"), constant_answer=" ")


def test_fewer_variants_than_the_minimum_are_not_judged():
    exercise = _regime(1.0)
    seeds = range(MIN_VARIANTS - 1)
    always = [{"regime": "underdamped"} for _ in seeds]
    assert one_answer_problems(exercise, list(seeds), always) == []


def _number(low: float, high: float, offset: float = 0.0) -> Exercise:
    """y = offset + x, with x drawn from [low, high] in steps of 0.01 m."""
    return Exercise(
        id="number", title="Number", source="Section 1.1.1",
        params=(Uniform("x", low, high, step=0.01, unit="m"),),
        statement="A length $x$ = {{ x }}: what is y?",
        solve=lambda p: {"y": offset + p.x},
        parts=(Numeric("y", "y", unit="m"),))


def test_a_number_that_stays_within_its_tolerance_of_one_value_fails():
    # y = 100 + x with x in [0, 0.5] m stays within 100.25 +- 0.25 m: every y lies
    # within 1 % (1.0025 m and more) of 100.25 m, so one answer scores everywhere
    exercise = _number(0.0, 0.5, offset=100.0)
    (problem,) = one_answer_problems(exercise, list(SEEDS), _answers(exercise))
    assert problem.startswith("part y: the answer ") and "scores in 60 of 60 variants" in problem


def test_a_number_spread_beyond_its_tolerance_passes():
    # y = x with x in [1, 5] m: a 1 % window holds a few draws at most
    exercise = _number(1.0, 5.0)
    assert one_answer_problems(exercise, list(SEEDS), _answers(exercise)) == []


def test_a_vector_that_never_changes_fails():
    exercise = Exercise(
        id="vector", title="Vector", source="Section 1.1.1",
        params=(Uniform("x", 1.0, 5.0, step=0.5, unit="m"),),
        statement="A length $x$ = {{ x }}: what is the unit vector e1?",
        solve=lambda p: {"e": (1.0, 0.0)},
        parts=(Vector("e", "e1", size=2),))
    (problem,) = one_answer_problems(exercise, list(SEEDS), _answers(exercise))
    assert problem.startswith("part e: the answer [1, 0] scores in 60 of 60 variants")


# -- two parts that coincide --------------------------------------------------------------

def _stopping(require_unit: bool = False) -> Exercise:
    """A block at v0 on a floor with mu = 0.4, g = 9.81 m/s^2: it stops after
    d = v0^2/(2 mu g) and t = v0/(mu g), so d/t = v0/2: at v0 = 2 m/s the two numbers
    agree, 4/7.848 = 2/3.924 = 0.509684 (m and s)."""
    return Exercise(
        id="stopping", title="Stopping", source="Section 1.1.4",
        params=(Choice("v0", (2.0, 3.0), unit="m/s"), Constant("mu", 0.4),
                Constant("g", 9.81, unit="m/s^2")),
        statement="A block at $v_0$ = {{ v0 }} slides on a floor, $\\mu$ = {{ mu }}, "
                  "$g$ = {{ g }}: how far and how long until it stops?",
        solve=lambda p: {"d": p.v0**2 / (2 * p.mu * p.g), "t": p.v0 / (p.mu * p.g)},
        parts=(Numeric("d", "distance", unit="m"),
               Numeric("t", "time", unit="s", require_unit=require_unit)))


def _variant_at(exercise: Exercise, name: str, value: float):
    return next(v for v in map(exercise.variant, range(100)) if v.params[name] == value)


def test_two_numbers_of_different_units_that_agree_exactly_make_the_variant_unusable():
    exercise = _stopping()
    variant = _variant_at(exercise, "v0", 2.0)
    assert variant_problems(exercise, variant) == [
        "parts d and t coincide: d = 0.509684 m and t = 0.509684 s, so swapping their "
        "formulas scores both"]


def test_at_another_speed_the_two_numbers_differ_and_the_variant_is_usable():
    # v0 = 3 m/s: d = 9/7.848 = 1.14679 m, t = 3/3.924 = 0.764526 s
    exercise = _stopping()
    assert variant_problems(exercise, _variant_at(exercise, "v0", 3.0)) == []


def test_a_part_that_reads_no_bare_number_cannot_take_the_other_parts_number():
    # t requires its unit, and d's 0.509684 typed as "0.509684 m" is no time; d takes a
    # bare number, so the swap scores there
    exercise = _stopping(require_unit=True)
    variant = _variant_at(exercise, "v0", 2.0)
    assert len(coincidences(exercise, variant.answers)) == 1


def _pair(first: tuple[str, str], second: tuple[str, str], factor: float) -> Exercise:
    """Two parts (name, unit): ``first`` is x, ``second`` is ``factor`` times x, with x
    drawn from 1, 1.5 and 2 in the first part's unit."""
    (a, a_unit), (b, b_unit) = first, second
    return Exercise(
        id="pair", title="Pair", source="Section 1.1.1",
        params=(Uniform("x", 1.0, 2.0, step=0.5, unit=a_unit),),
        statement="A value $x$ = {{ x }}.",
        solve=lambda p: {a: p.x, b: factor * p.x},
        parts=(Numeric(a, a, unit=a_unit), Numeric(b, b, unit=b_unit)))


def test_numbers_of_one_dimension_are_compared_in_si_within_the_tolerance():
    # a = x in m and b = 1.005 x, shown in cm: 2 m typed as a length for b is 200 cm,
    # within 1 % of b = 201 cm
    exercise = _pair(("a", "m"), ("b", "cm"), 1.005)
    assert coincidences(exercise, _variant_at(exercise, "x", 2.0).answers) == [
        "parts a and b coincide: a = 2 m and b = 201 cm, so swapping their formulas "
        "scores both"]


def test_numbers_of_different_dimensions_within_one_percent_but_not_equal_pass():
    # t = 2 s and d = 2.01 m: a chance agreement within 1 %, not the same number
    exercise = _pair(("t", "s"), ("d", "m"), 1.005)
    assert coincidences(exercise, _variant_at(exercise, "x", 2.0).answers) == []


def test_verify_reports_the_coincidence_with_its_seed_and_the_shared_answer():
    exercise = _stopping()
    seed = _variant_at(exercise, "v0", 2.0).seed
    report = verify_exercise(exercise, range(60))
    assert (f"seed {seed}: parts d and t coincide: d = 0.509684 m and t = 0.509684 s, so "
            "swapping their formulas scores both") in report.failures


def test_apart_keeps_two_numbers_more_than_two_percent_of_the_larger_apart():
    from dynagrade.exercise import apart

    # 1.02 - 1 = 0.02 is within 2 % of 1.02 (0.0204); 1.03 - 1 = 0.03 is not
    assert not apart(1.0, 1.02) and apart(1.0, 1.03) and apart(-1.0, 1.0)
    assert not apart(2.0, 2.0, share=0.0)
