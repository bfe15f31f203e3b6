"""The exercise model: parameters, constraints, variants, statements."""

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from dynagrade.exercise import (Choice, Constant, Constraint, ConstraintError, Exercise,
                                Numeric, Uniform)
from dynagrade.exercise.seeds import exam_seed, stable_seed, student_seed
from dynagrade.exercise.statement import render_statement
from dynagrade.exercise.units import convert, from_si, to_si


def _exercise(**changes):
    fields = dict(
        id="tiny", title="Tiny", source="Example 1.1",
        params=(Uniform("v", 1, 3, step=0.5, unit="km/h", symbol="v"),
                Uniform("alpha", 10, 80, step=1, unit="deg")),
        statement="Speed {{ v }} at {{ alpha }}.",
        solve=lambda p: {"twice": 2 * p.v},
        parts=(Numeric("twice", unit="m/s"),),
    )
    fields.update(changes)
    return Exercise(**fields)


@given(st.integers(0, 2**32 - 1))
def test_uniform_draws_lie_on_the_grid_between_the_bounds(seed):
    rng = np.random.default_rng(seed)
    parameter = Uniform("x", 0.5, 2.0, step=0.25)
    value = parameter.draw(rng)
    assert 0.5 <= value <= 2.0
    assert math.isclose((value - 0.5) / 0.25, round((value - 0.5) / 0.25), abs_tol=1e-9)


def test_a_uniform_grid_reaches_both_ends():
    rng = np.random.default_rng(0)
    values = {Uniform("x", 1, 2, step=0.1).draw(rng) for _ in range(2000)}
    assert values == {round(1 + 0.1 * k, 10) for k in range(11)}


def test_choice_draws_only_its_values_and_constant_never_varies():
    rng = np.random.default_rng(1)
    assert {Choice("m", (1, 2, 5)).draw(rng) for _ in range(200)} == {1.0, 2.0, 5.0}
    assert Constant("g", 9.81).draw(rng) == 9.81 and not Constant("g", 9.81).varies


@given(st.integers(0, 10_000))
def test_a_variant_is_determined_by_its_seed(seed):
    exercise = _exercise()
    assert exercise.variant(seed) == exercise.variant(seed)


def test_different_seeds_give_different_numbers():
    exercise = _exercise()
    assert len({tuple(exercise.variant(s).params.values()) for s in range(30)}) > 10


def test_the_solver_sees_si_and_answers_come_back_in_the_parts_unit():
    # v = 3.6 km/h is 1 m/s; the part asks for 2 v in m/s.
    variant = _exercise().variant(0, {"v": 3.6})
    assert variant.answers["twice"] == pytest.approx(2.0)


def test_the_solver_sees_angles_in_radians():
    exercise = _exercise(solve=lambda p: {"twice": p.alpha}, parts=(Numeric("twice"),))
    assert exercise.variant(0, {"alpha": 90}).answers["twice"] == pytest.approx(math.pi / 2)


@given(st.integers(0, 500))
def test_every_variant_meets_the_constraints(seed):
    exercise = _exercise(constraints=(
        Constraint("steep", lambda p: p.alpha > math.radians(60)),))
    assert exercise.variant(seed).params["alpha"] > 60


def test_constraints_that_cannot_be_met_are_reported_by_name():
    exercise = _exercise(constraints=(Constraint("impossible", lambda p: p.v < 0),))
    with pytest.raises(ConstraintError, match="impossible"):
        exercise.variant(0)


def test_overrides_that_break_a_constraint_warn_when_not_strict():
    exercise = _exercise(constraints=(Constraint("slow", lambda p: p.v < 0.5),))  # SI: m/s
    variant = exercise.variant(0, {"v": 3.0}, strict=False)
    assert variant.warnings == ("slow",)


def test_the_statement_shows_values_with_units():
    text = render_statement("{{ v }}, {{ alpha }}, {{ v.value }}, {{ v.unit }}",
                            _exercise().params, {"v": 2.5, "alpha": 30.0})
    assert text.strip() == "2.5 km/h, 30°, 2.5, km/h"


def test_a_statement_naming_an_unknown_parameter_fails_clearly():
    with pytest.raises(ValueError, match="speed"):
        _exercise(statement="{{ speed }}").variant(0)


@pytest.mark.parametrize("bad, message", [
    (dict(id="Not Kebab"), "kebab-case"),
    (dict(parts=()), "no answer parts"),
    (dict(parts=(Numeric("v"),)), "both a parameter and a part"),
    (dict(statement="{% if %}"), "line 1"),
])
def test_malformed_exercises_are_rejected_with_the_reason(bad, message):
    with pytest.raises(ValueError, match=message):
        _exercise(**bad)


def test_a_non_finite_reference_answer_is_an_error():
    exercise = _exercise(solve=lambda p: {"twice": float("nan")})
    with pytest.raises(ValueError, match="twice"):
        exercise.variant(0)


def test_the_chapter_comes_from_the_source():
    assert _exercise(source="Section 3.2.1").chapter == 3


def test_seeds_are_the_first_four_bytes_of_sha256_of_the_keys():
    import hashlib

    digest = hashlib.sha256(b"student\0projectile-range\0s1").digest()
    assert student_seed("projectile-range", "s1") == int.from_bytes(digest[:4], "big")
    assert student_seed("a", "s1") != student_seed("a", "s2")


def test_exam_seeds_are_keyed_by_the_exams_secret_not_public_data():
    """Reproducer: an exam seed was sha256 of public data, so anyone could forge it."""
    import hashlib
    import hmac

    digest = hmac.new(b"k" * 32, b"exam\0e\0s\0x", hashlib.sha256).digest()
    assert exam_seed("k" * 32, "e", "s", "x") == int.from_bytes(digest[:4], "big")
    assert exam_seed("k" * 32, "e", "s", "x") != stable_seed("exam", "e", "s", "x")
    assert exam_seed("j" * 32, "e", "s", "x") != exam_seed("k" * 32, "e", "s", "x")


@given(st.floats(-1e6, 1e6, allow_nan=False))
def test_si_conversion_round_trips(value):
    for unit in ("km/h", "deg", "mN", "rpm", None):
        assert from_si(to_si(value, unit), unit) == pytest.approx(value, rel=1e-12, abs=1e-12)


def test_conversions_match_hand_values_and_refuse_other_dimensions():
    assert convert(45, "km/h", "m/s") == pytest.approx(12.5)
    assert convert(180, "deg", "rad") == pytest.approx(math.pi)
    with pytest.raises(ValueError):
        convert(1, "m", "s")
    with pytest.raises(ValueError):
        convert(1, "1/s", "rad/s")


# -- symbols of symbolic parts default to the parameters' domains -------------------------

from dynagrade.errors import DefinitionError  # noqa: E402
from dynagrade.exercise import Symbolic, Variable  # noqa: E402
from dynagrade.exercise.params import symbol_domain  # noqa: E402


@pytest.mark.parametrize("parameter, domain", [
    # a quarter of the span added on each side ...
    (Uniform("x", 10, 50, step=1, unit="m"), (5, 60)),  # 10 - 10 reaches zero: held at 10/2
    (Uniform("v2", -3, 1, step=0.5, unit="m/s"), (-4, 2)),
    # ... a constant widened by half its value, and no bound pushed across zero
    (Constant("g", 9.81, unit="m/s^2"), (4.905, 14.715)),
    (Uniform("a", 0, 0.3, step=0.01, unit="m"), (0, 0.375)),
    (Uniform("y", -5, -1, step=1), (-6, -0.5)),
    (Choice("m", (0.2, 0.5, 1.0), unit="kg"), (0.1, 1.2)),
])
def test_a_parameter_symbol_is_tested_beyond_the_drawn_values(parameter, domain):
    variable = symbol_domain(parameter)
    assert (variable.min, variable.max) == pytest.approx(domain)
    assert variable.unit == parameter.unit


def test_symbols_named_without_a_domain_take_their_parameters_domains():
    exercise = _exercise(parts=(
        Numeric("twice", unit="m/s"),
        Symbolic("formula", expected="2*v", variables=("v",), equals="twice"),
        Symbolic("mixed", expected="v*sin(theta)",
                 variables={"theta": Variable(-1, 1, "rad"), "v": None})))
    formula, mixed = exercise.parts[1], exercise.parts[2]
    # 1..3 km/h, margin 0.5; the parameter's printed symbol comes along
    assert formula.variables == {"v": Variable(0.5, 3.5, "km/h", symbol="v")}
    assert mixed.variables == {"theta": Variable(-1, 1, "rad"),
                               "v": Variable(0.5, 3.5, "km/h", symbol="v")}
    assert list(mixed.variables) == ["theta", "v"]  # the author's order, as sheets show it


def test_a_symbol_without_a_domain_must_be_a_parameter():
    with pytest.raises(DefinitionError, match=r"\['theta'\] are no parameters.*Variable\(min"):
        _exercise(parts=(Numeric("twice", unit="m/s"),
                         Symbolic("s", expected="v*theta", variables=("v", "theta"))))


# -- the solver runs once per draw -------------------------------------------------------

from dynagrade.exercise import per_draw  # noqa: E402


def _counted_solver():
    """A per-draw solver and the list of the speeds (SI) it was called for."""
    calls = []

    @per_draw
    def solve(p):
        calls.append(p.v)
        return {"twice": 2 * p.v}

    return solve, calls


def test_constraints_and_answers_share_one_solution_per_draw():
    solve, calls = _counted_solver()
    exercise = _exercise(solve=solve, constraints=(
        Constraint("positive", lambda p: solve(p)["twice"] > 0),
        Constraint("below 2 m/s", lambda p: solve(p)["twice"] < 2)))  # v <= 3 km/h: always
    variant = exercise.variant(seed=3)
    assert len(calls) == 1  # two constraints and the answers, one solution
    assert variant.answers["twice"] == pytest.approx(2 * variant.params["v"] / 3.6)


def test_each_draw_gets_its_own_solution():
    solve, calls = _counted_solver()
    draws = []
    # v > 2 km/h only: draws at 1, 1.5 and 2 km/h are redrawn; none is solved twice
    exercise = _exercise(solve=solve, constraints=(
        Constraint("counted", lambda p: draws.append(p.v) is None),
        Constraint("fast", lambda p: solve(p)["twice"] > 2 * 2 / 3.6 + 1e-9)))
    variant = exercise.variant(seed=1)
    assert variant.params["v"] > 2 and len(draws) > 1  # seed 1 draws 2 km/h first
    assert len(calls) <= len(draws)
    assert calls[-1] == pytest.approx(variant.params["v"] / 3.6)  # the answers' solution
