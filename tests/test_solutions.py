"""Worked solutions: the template's context, its checks when an exercise is built and in
``verify``, every written solution of the bank at two seeds, and three golden texts."""

import json
import re
from pathlib import Path

import pytest
from click.testing import CliRunner

from dynagrade.cli import main
from dynagrade.exercise import Constant, Exercise, Numeric, Options, Uniform, Vector, open_bank
from dynagrade.exercise.solution import SolutionError, render_solution
from dynagrade.exercise.solution_check import solution_problems, stray_numbers
from dynagrade.exercise.verify import verify_exercise
from dynagrade.render.solutions import math_problems

from bank_ids import bank_ids

GOLDEN = Path(__file__).parent / "fixtures" / "solutions"
#: the bank's ids, read without loading any exercise file (collection stays light)
BANK_IDS = bank_ids()


def _solve(p):
    return {"s": p.v * p.t, "side": "left", "r": (p.v, -p.t),
            "half_time": p.t / 2, "angle": 0.5}


def _exercise(solution, **changes):
    """A car at speed v (km/h) for a time t (min): distance s in km, and extras."""
    fields = dict(
        id="drive", title="Drive", source="Example 1.1",
        params=(Uniform("v", 36, 72, step=36, unit="km/h", symbol="v"),
                Uniform("t", 1, 2, step=1, unit="min", symbol="t"),
                Constant("m", 1500, unit="g", symbol="m")),
        statement="A car drives at {{ v }} for {{ t }}; its mass is {{ m }}.",
        solve=_solve,
        parts=(Numeric("s", "distance", unit="km"),
               Options("side", options=("left", "right")),
               Vector("r", unit="m/s", size=2)),
        solution=solution,
    )
    fields.update(changes)
    return Exercise(**fields)


# -- the template's context ---------------------------------------------------------------


def test_the_context_prints_parameters_answers_and_solver_values_as_the_contract_says():
    exercise = _exercise(
        "{{ v }}|{{ v.value }}|{{ v.unit }}|{{ v.symbol }}|{{ si.v }}|{{ si.m }}|"
        "{{ answers.s }}|{{ answers.side }}|{{ answers.r }}|{{ si.half_time }}|"
        "{{ si.angle | deg }}|{{ si.r[1] }}|{{ si.r[1] | abs }}")
    variant = exercise.variant_from_params(0, {"v": 36.0, "t": 2.0, "m": 1500.0})
    # v = 36 km/h = 10 m/s; t = 2 min = 120 s; s = 1200 m = 1.2 km; m = 1.5 kg;
    # 0.5 rad = 28.6479 degrees; r = (10 m/s, -120 m/s)
    assert render_solution(exercise, variant).strip().split("|") == [
        "36 km/h", "36", "km/h", "v", "10", "1.5", "1.2 km", "left", "[10, -120] m/s",
        "60", "28.6479", "-120", "120"]


def test_an_exercise_without_a_solution_renders_none():
    exercise = _exercise(None)
    assert render_solution(exercise, exercise.variant(0)) is None


def test_the_solvers_extra_keys_are_never_graded_answers():
    exercise = _exercise(None)
    assert set(exercise.variant(0).answers) == {"s", "side", "r"}


@pytest.mark.parametrize("template, message", [
    ("{{ speed }}", "names ['speed'], which are neither parameters nor answers or si"),
    ("{{ answers.distance }}", "prints answers.distance, but the exercise has no part "
                               "'distance'"),
    ("{{ answers['distance'] }}", "no part 'distance'"),
    ("1. ok\n2. {{ v }", "solution template, line 2"),
    ("{{ si.angle | degrees }}", "line 1: No filter named 'degrees'"),
])
def test_a_solution_naming_what_it_cannot_have_is_refused_when_the_exercise_is_built(
        template, message):
    with pytest.raises(SolutionError, match="exercise 'drive'") as error:
        _exercise(template)
    assert message in str(error.value)


def test_a_solver_value_the_solver_does_not_return_is_a_clear_error_at_rendering():
    exercise = _exercise("{{ si.t_stop }}")
    with pytest.raises(SolutionError) as error:
        render_solution(exercise, exercise.variant(0))
    assert "seed 0" in str(error.value)
    assert "si has no 't_stop'" in str(error.value)
    assert "'half_time'" in str(error.value)


# -- what verify checks ---------------------------------------------------------------------


def test_numbers_of_the_variant_small_integers_and_references_are_not_stray():
    text = ("By eq. (1.80) and Example 1.9, Section 4.3.2: $s = v t/2$ = 3.14159, "
            "(1.79), 10 and 2.5e-5; 12 but not 13 nor 2.71828.")
    assert stray_numbers(text, [3.14159265, 2.5e-5, -10.0]) == ["13", "2.71828"]


def test_verify_passes_a_solution_printing_only_the_variants_values():
    exercise = _exercise("Distance: $s = v t$ = {{ answers.s }}, half the time "
                         "{{ si.half_time }} s; side {{ answers.side }}, "
                         "$r$ = {{ answers.r }}, angle {{ si.angle | deg }} degrees.")
    report = verify_exercise(exercise, range(4), math_check=math_problems)
    assert report.ok, report.failures


def test_verify_finds_a_retyped_number_and_a_missing_answer():
    # t = 1 min: the half time is 30 s; "90" is no value of this variant (t = 60 s,
    # v = 10 m/s, s = 600 m, r = (10, -60) m/s); the vector answer is missing
    exercise = _exercise("$s$ = {{ answers.s }}; {{ answers.side }}; half time 90 s.")
    variant = exercise.variant_from_params(0, {"v": 36.0, "t": 1.0, "m": 1500.0})
    problems = solution_problems(exercise, variant)
    assert any("prints 90, which is no value of this variant" in p for p in problems)
    assert any("part r's answer '[10, -60] m/s' does not appear" in p for p in problems)


def test_verify_finds_math_that_does_not_render():
    exercise = _exercise("{{ answers.s }} {{ answers.side }} {{ answers.r }} "
                         "$\\frobnicate{s}$")
    report = verify_exercise(exercise, range(2), math_check=math_problems)
    assert any("\\frobnicate" in f for f in report.failures)


def test_a_missing_solution_is_noted_and_fails_only_when_required():
    exercise = _exercise(None)
    noted = verify_exercise(exercise, range(2))
    assert noted.ok and noted.notes == ["no worked solution (solution=...) yet"]
    required = verify_exercise(exercise, range(2), require_solution=True)
    assert required.failures == ["no worked solution (solution=...) yet"]


# -- the bank's solutions --------------------------------------------------------------------


@pytest.mark.parametrize("exercise_id", BANK_IDS)
def test_every_exercise_has_a_solution_showing_each_parts_key_answer_at_two_seeds(
        bank, exercise_id):
    exercise = bank.get(exercise_id)
    assert exercise.solution is not None, "no worked solution (solution=...)"
    offset = sum(map(ord, exercise.id)) * 100
    for seed in (offset, offset + 1):
        variant = exercise.variant(seed)
        text = render_solution(exercise, variant)
        for part in exercise.parts:
            assert part.shown_answer(variant.answers[part.name]) in text, (seed, part.name)
        for error_sign in ("Undefined", "Traceback", "{{", "{%"):
            assert error_sign not in text, (seed, error_sign)
        assert not re.search(r"\b(nan|inf)\b", text), seed
        assert solution_problems(exercise, variant) == [], seed
    assert math_problems(text) == []


# -- three hand-checked solutions -------------------------------------------------------------
#
# Seed 3 of each; every number of the fixtures was recomputed by hand from the formulas
# of the notes (values rounded to 6 significant figures):
# projectile-range, v0 = 25.5 m/s, alpha = 20 deg: v0 cos a = 23.9622, v0 sin a = 8.72151,
#   t_peak = 0.889043 s, x_max = v0^2 sin 40 deg / g = 42.6068 m, h = 3.8769 m,
#   t_flight = 1.77809 s, the closing check at alpha = 45 deg v0^2 / g = 66.2844 m;
# ballistic-pendulum, m = 13 g, M = 4.1 kg, v = 540 m/s, L = 2.2 m: m v = 7.02,
#   V = 7.02/4.113 = 1.70678 m/s, h = V^2/(2g) = 14.8477 cm (below L), T1 = 1895.4 J,
#   T2 = 7.02^2/(2*4.113) = 5.99081 J, lost 1889.41 J, M/(m+M) = 4.1/4.113 = 0.996839;
# damped-free-vibration, m = 41 kg, k = 1900 N/m, c = 144 N s/m: omega_n = 6.80746,
#   c_cr = 558.211, zeta = 0.257967, omega_d = 6.57705, T_d = 0.95532 s, delta = 1.67763,
#   the closing check at c = 0 omega_d = omega_n = 6.80746; the second damper c2 = 720 N s/m
#   gives zeta2 = 720 / 558.211 = 1.28983 > 1, overdamped.

GOLDEN_PARAMS = {
    "projectile-range": {"v0": 25.5, "alpha": 20.0, "g": 9.81},
    "ballistic-pendulum": {"m": 13.0, "M": 4.1, "v": 540.0, "g": 9.81, "L": 2.2},
    "damped-free-vibration": {"m": 41.0, "k": 1900.0, "c": 144.0, "c2": 720.0},
}


@pytest.mark.parametrize("exercise_id", sorted(GOLDEN_PARAMS))
def test_the_golden_solutions_read_as_checked_by_hand(bank, exercise_id):
    exercise = bank.get(exercise_id)
    variant = exercise.variant(3)
    assert variant.params == GOLDEN_PARAMS[exercise_id]
    expected = (GOLDEN / f"{exercise_id}-seed3.md").read_text(encoding="utf-8")
    assert render_solution(exercise, variant) == expected


# -- the command line --------------------------------------------------------------------------


def test_show_solution_prints_it_in_the_terminal_and_as_json_text():
    runner = CliRunner()
    shown = runner.invoke(main, ["show", "damped-free-vibration", "--seed", "3", "--solution"])
    assert shown.exit_code == 0, shown.output
    assert "Solution" in shown.output and "558.211" in shown.output
    as_json = runner.invoke(main, ["show", "damped-free-vibration", "--seed", "3",
                                   "--solution", "--json"])
    data = json.loads(as_json.output)
    assert data["solution"] == (GOLDEN / "damped-free-vibration-seed3.md").read_text("utf-8")
    assert "answers" not in data


def _bare_exercise(folder: Path) -> str:
    """ballistic-pendulum without its solution, saved in ``folder`` as the exercise
    ``bare``; returns the id."""
    source = Path(open_bank().get("ballistic-pendulum").path).read_text(encoding="utf-8")
    start = source.index('    solution=r"""')
    end = source.index('""",', start) + len('""",\n')
    (folder / "bare.py").write_text(
        (source[:start] + source[end:]).replace('id="ballistic-pendulum"', 'id="bare"'),
        "utf-8")
    return "bare"


def test_show_solution_of_an_exercise_without_one_says_so(tmp_path):
    exercise_id = _bare_exercise(tmp_path)
    runner = CliRunner()
    shown = runner.invoke(main, ["--exercises", str(tmp_path), "show", exercise_id,
                                 "--solution"])
    assert shown.exit_code == 0 and "has no worked solution yet" in shown.output
    as_json = json.loads(runner.invoke(main, ["--exercises", str(tmp_path), "show",
                                              exercise_id, "--solution", "--json"]).output)
    assert as_json["solution"] is None


def test_a_practice_sheet_ends_with_the_solution_as_comments_and_still_grades(bank, tmp_path):
    from dynagrade.cli import grade_main

    runner = CliRunner()
    sheet = tmp_path / "exercise.py"
    written = runner.invoke(main, ["sheet", "ballistic-pendulum", "--student", "s1",
                                   "--solution", "-o", str(sheet)])
    assert written.exit_code == 0, written.output
    text = sheet.read_text(encoding="utf-8")
    seed = int(re.search(r"^SEED = (\d+)$", text, re.M).group(1))
    exercise = bank.get("ballistic-pendulum")
    variant = exercise.variant(seed)
    solution = render_solution(exercise, variant)
    tail = text[text.index("# -- Worked solution"):]
    assert all(line.startswith("#") for line in tail.splitlines())
    assert [line[2:] for line in tail.splitlines()[2:]] == \
        [line.rstrip() for line in solution.splitlines()]
    # the comments are not answers: with V filled in, V is graded and the rest is unanswered
    V = exercise.part("V").answer_text(variant.answers["V"])
    sheet.write_text(text.replace("V = None", f"V = {V}"), encoding="utf-8")
    graded = json.loads(runner.invoke(grade_main, [str(sheet), "--json"]).output)
    statuses = {p["name"]: p["status"] for p in graded["parts"]}
    assert statuses == {"V": "correct", "h": "not answered", "T_lost": "not answered",
                        "V_formula": "not answered"}


def test_grade_solution_prints_the_solution_after_the_verdicts(bank, tmp_path):
    from dynagrade.cli import grade_main

    runner = CliRunner()
    sheet = tmp_path / "exercise.py"
    runner.invoke(main, ["sheet", "damped-free-vibration", "--student", "s2", "-o", str(sheet)])
    shown = runner.invoke(grade_main, [str(sheet), "--solution"])
    assert shown.exit_code == 0, shown.output
    assert shown.output.index("total") < shown.output.index("Solution")
    as_json = json.loads(runner.invoke(grade_main, [str(sheet), "--solution", "--json"]).output)
    seed = as_json["seed"]
    exercise = bank.get("damped-free-vibration")
    assert as_json["solution"] == render_solution(exercise, exercise.variant(seed))


def test_a_bank_is_complete_when_every_exercise_file_declares_a_solution(bank, tmp_path):
    from dynagrade.exercise.solution_check import bank_is_complete

    source = Path(bank.get("ballistic-pendulum").path).read_text(encoding="utf-8")
    (tmp_path / "with_solution.py").write_text(source, encoding="utf-8")
    assert bank_is_complete(tmp_path)
    _bare_exercise(tmp_path)
    assert not bank_is_complete(tmp_path)


def test_verify_fails_a_missing_solution_on_request_and_notes_it_when_allowed(tmp_path):
    exercise_id = _bare_exercise(tmp_path)
    runner = CliRunner()
    required = runner.invoke(main, ["--exercises", str(tmp_path), "verify", exercise_id,
                                    "--variants", "2", "--require-solutions"])
    assert required.exit_code == 1 and "no worked solution" in required.output
    allowed = runner.invoke(main, ["--exercises", str(tmp_path), "verify", exercise_id,
                                   "--variants", "2", "--allow-missing-solutions"])
    assert allowed.exit_code == 0 and "no worked solution" in allowed.output
