"""Independent checks of an exercise's key (dynagrade.exercise.checks), run by verify.

Each kind of check is tried on a tiny exercise whose answer is worked out by hand; then
verify is shown catching wrong keys in shipped exercises (a key 5 % off, and the
sqrt(1 + zeta^2) slip in the core that issue 29's mutation run found no test catching).
"""

import dataclasses
import inspect
import math

import numpy as np
import pytest

from dynagrade.errors import DefinitionError
from dynagrade.exercise import Constant, Exercise, Numeric, Symbolic, Uniform, open_bank
from dynagrade.exercise.checks import Balance, Integrated, Limit, Recompute, Symmetry
from dynagrade.exercise.checks.run import check_problems
from dynagrade.exercise.numbers import answer_text
from dynagrade.exercise.solution import render_solution
from dynagrade.exercise.verify import verify_exercise
from dynagrade.mechanics import vibrations

from bank_ids import bank_ids


def _oscillator(**changes):
    """A mass on a spring: omega = sqrt(k/m), the period 2 pi sqrt(m/k)."""
    fields = dict(
        id="tiny-oscillator", title="Tiny", source="Section 4.1",
        params=(Uniform("m", 1, 4, step=0.5, unit="kg", symbol="m"),
                Uniform("k", 10, 40, step=1, unit="N/m", symbol="k")),
        statement="Mass {{ m }} on a spring {{ k }}.\n\n1. The period?",
        solve=lambda p: {"T": 2 * math.pi * math.sqrt(p.m / p.k)},
        parts=(Numeric("T", unit="s", question=1),),
    )
    fields.update(changes)
    return Exercise(**fields)


def _spring(t, y, p):
    return (y[1], -p.k / p.m * y[0])


PERIOD_BY_INTEGRATION = Integrated(
    "T", _spring, lambda p: (1.0, 0.0), lambda p, s: 3 * s["T"], lambda t, y, p: t,
    name="integrated_period", event=lambda t, y, p: y[1], direction=-1)


def _problems(exercise, seed=0):
    return check_problems(exercise, exercise.si(exercise.variant(seed).params))


def test_an_integrated_check_agrees_with_the_period_two_pi_root_m_over_k():
    assert _problems(_oscillator(checks=(PERIOD_BY_INTEGRATION,))) == []


def test_an_integrated_check_names_itself_the_key_both_numbers_and_the_tolerance():
    wrong = _oscillator(solve=lambda p: {"T": math.pi * math.sqrt(p.m / p.k)},  # half
                        checks=(PERIOD_BY_INTEGRATION,))
    params = wrong.variant(0).params
    half = math.pi * math.sqrt(params["m"] / params["k"])
    [problem] = _problems(wrong)
    assert problem == (f"check 'integrated_period' on T: the key gives {answer_text(half)}, "
                       f"the check recomputes {answer_text(2 * half)} (rtol 1e-06)")


def test_an_event_that_never_comes_is_a_disagreement():
    short = dataclasses.replace(PERIOD_BY_INTEGRATION, horizon=lambda p, s: 0.1 * s["T"])
    [problem] = _problems(_oscillator(checks=(short,)))
    assert "recomputes nan" in problem


def test_the_second_occurrence_of_an_event_is_two_periods_on():
    twice = dataclasses.replace(PERIOD_BY_INTEGRATION, occurrence=2,
                                read=lambda t, y, p: t / 2)
    assert _problems(_oscillator(checks=(twice,))) == []


def test_a_limit_re_solves_at_the_limit_and_compares_with_its_closed_form():
    damped = _oscillator(
        params=(Uniform("m", 1, 4, step=0.5, unit="kg"), Uniform("k", 10, 40, step=1, unit="N/m"),
                Uniform("zeta", 0.1, 0.5, step=0.1)),
        statement="{{ m }} {{ k }} {{ zeta }}\n\n1. The damped period?",
        solve=lambda p: {"T": 2 * math.pi * math.sqrt(p.m / p.k) / math.sqrt(1 - p.zeta**2)},
        checks=(Limit("T", {"zeta": 0.0}, lambda p: 2 * math.pi * math.sqrt(p.m / p.k),
                      name="undamped"),))
    assert _problems(damped) == []
    sign_slip = dataclasses.replace(
        damped, solve=lambda p: {"T": 2 * math.pi * math.sqrt(p.m / p.k) / (1 - p.zeta)})
    assert _problems(sign_slip) == []  # at zeta = 0 the slip is invisible: a limit is no proof


def test_a_symmetry_compares_the_key_at_mirrored_parameters():
    # T(m', k') with m' = k/10, k' = 10 m is 2 pi sqrt(k / (100 m)) = (2 pi)^2 / (10 T)
    swapped = Symmetry("T", lambda p: {"m": p.k / 10, "k": 10 * p.m}, name="swap",
                       relate=lambda T: (2 * math.pi) ** 2 / (10 * T))
    assert _problems(_oscillator(checks=(swapped,))) == []


def test_a_balance_compares_its_two_sides():
    energy = Balance("energy", lambda p, s: p.k * 0.1**2 / 2,
                     lambda p, s: p.m * (0.1 * 2 * math.pi / s["T"]) ** 2 / 2, name="energy")
    assert _problems(_oscillator(checks=(energy,))) == []
    off = dataclasses.replace(energy, before=lambda p, s: p.k * 0.1**2)
    [problem] = _problems(_oscillator(checks=(off,)))
    assert problem.startswith("check 'energy' on energy: ")


def test_a_check_that_raises_is_reported_with_its_error():
    broken = Recompute("missing", lambda p, s: 1.0, name="typo")
    [problem] = _problems(_oscillator(checks=(broken,)))
    assert problem.startswith("check 'typo' fails: DefinitionError: the solver returns "
                              "no 'missing'") and "'T'" in problem


@pytest.mark.parametrize("name", ["two words", "", "1st"])
def test_a_check_name_must_be_an_identifier(name):
    with pytest.raises(DefinitionError, match="no identifier"):
        _oscillator(checks=(Recompute("T", lambda p, s: 0.0, name=name),))


def test_two_checks_cannot_share_a_name():
    check = Recompute("T", lambda p, s: 0.0, name="same")
    with pytest.raises(DefinitionError, match="twice"):
        _oscillator(checks=(check, check))


def test_verify_finds_a_formula_whose_dimension_is_not_the_parts():
    # sqrt(k/m) is 1/s, but the part it equals is a time
    odd = _oscillator(
        statement="Mass {{ m }} on a spring {{ k }}.\n\n1. The period?\n2. As a formula?",
        solve=lambda p: {"T": math.sqrt(p.k / p.m)},
        parts=(Numeric("T", unit="s", question=1),
               Symbolic("T_formula", question=2, expected="sqrt(k/m)", variables=("m", "k"),
                        equals="T")))
    report = verify_exercise(odd, range(1))
    assert ("check 'dimensions' on T_formula: the formula 'sqrt(k/m)' has the dimension "
            in "\n".join(report.failures))


BANK = open_bank()


def test_verify_names_the_check_that_catches_sqrt_one_plus_zeta_squared(monkeypatch):
    exercise = BANK.get("logarithmic-decrement-measurement")
    assert verify_exercise(exercise, range(3)).ok
    monkeypatch.setattr(vibrations, "natural_frequency_from_damped",
                        lambda omega_d, zeta: omega_d / np.sqrt(1.0 + zeta**2))
    report = verify_exercise(exercise, range(3))
    period = exercise.variant(0).params["Td"]
    # the key omega_d = 2 pi / T_d is right; the identified k and c no longer reproduce it
    expected = f"seed 0: check 'identified_period' on omega_d: the key gives " \
               f"{answer_text(2 * math.pi / period)}, the check recomputes "
    assert any(f.startswith(expected) and f.endswith("(rtol 1e-06)") for f in report.failures), \
        report.failures


def test_verify_names_the_check_that_catches_a_key_five_percent_off():
    exercise = BANK.get("block-sliding-down-incline")
    solve = exercise.solve
    off = dataclasses.replace(exercise, solve=lambda p: {**solve(p), "a": 1.05 * solve(p)["a"]})
    report = verify_exercise(off, range(2))
    named = [f for f in report.failures if "check 'momentum_balance_along_slope' on a:" in f]
    assert [f.split(":")[0] for f in named] == ["seed 0", "seed 1"]


def test_a_closing_sanity_line_prints_what_its_check_recomputed():
    exercise = BANK.get("projectile-range")
    variant = exercise.variant(0)
    v0 = variant.params["v0"]  # m/s; at alpha = pi/4 the range is v0^2 / g (Example 1.9)
    assert f"= {answer_text(v0**2 / 9.81)}\n   m, the longest range" in \
        render_solution(exercise, variant)


def test_every_shipped_exercise_has_an_independent_check():
    without = sorted(exercise.id for exercise in BANK.all() if not exercise.checks)
    assert without == [], f"exercises without a check: {without}"


def _core_names(function, seen=None) -> set[str]:
    """The mechanics-core modules and functions ``function`` names, directly or through
    the helpers of its own module it calls (and the functions its closure holds)."""
    seen = set() if seen is None else seen
    if function in seen or not hasattr(function, "__code__"):
        return set()
    seen.add(function)
    found = set()
    codes = [function.__code__]
    while codes:
        code = codes.pop()
        codes += [c for c in code.co_consts if hasattr(c, "co_names")]
        for name in code.co_names:
            value = function.__globals__.get(name)
            where = getattr(value, "__name__", "") if inspect.ismodule(value) else \
                getattr(value, "__module__", "") or ""
            if where.startswith("dynagrade.mechanics"):
                found.add(name)
            elif inspect.isfunction(value) and value.__module__ == function.__module__:
                found |= _core_names(value, seen)
    for cell in function.__closure__ or ():
        if inspect.isfunction(cell.cell_contents):
            found |= _core_names(cell.cell_contents, seen)
    return found


def _routes(check):
    """The functions a check computes its side of the comparison with (a limit's and a
    symmetry's re-solving goes through the solver by design, not through these)."""
    return [getattr(check, f.name) for f in dataclasses.fields(check)
            if inspect.isfunction(getattr(check, f.name))]


def _helper_reaching_the_core(p):
    return vibrations.natural_frequency(p.k, p.m)


def test_the_search_for_core_calls_finds_one_directly_and_through_a_helper():
    def route(p, s):
        return vibrations.natural_frequency(p.k, p.m)

    assert _core_names(route) == {"vibrations"}
    assert _core_names(lambda p, s: _helper_reaching_the_core(p)) == {"vibrations"}
    assert _core_names(lambda p, s: np.sqrt(p.k / p.m)) == set()


@pytest.mark.parametrize("exercise_id", bank_ids())
def test_no_check_computes_with_the_mechanics_core(exercise_id):
    exercise = BANK.get(exercise_id)
    reached = {check.name: sorted(set().union(*map(_core_names, _routes(check))))
               for check in exercise.checks}
    assert {name: core for name, core in reached.items() if core} == {}
