"""State belongs to a run: caches are keyed by the exercise's file content, never by its
id alone, two runs share nothing, and worker processes give the files one process gives."""

from __future__ import annotations

import filecmp
import pickle
import textwrap

from dynagrade.generation.generate import generate_exam
from dynagrade.generation.run import GenerationRun
from dynagrade.runs.caches import VariantCache, exercise_identity, file_sha256
from dynagrade.runs.workers import Pool
from dynagrade.exercise.loader import load_file

EXERCISE = textwrap.dedent('''\
    from dynagrade.exercise import Exercise, Numeric, Uniform

    EXERCISE = Exercise(
        id="same-id", title="Falling", source="Example 1.1",
        params=(Uniform("h", 1, 5, step=1, unit="m", symbol="h"),),
        statement="A stone falls from $h = {{ h }}$.",
        solve=lambda p: {"t": FACTOR * p.h},
        parts=(Numeric("t", "time", unit="s"),),
    )
    ''')


def _write(folder, factor: float):
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / "same_id.py"
    path.write_text(f"FACTOR = {factor}\n" + EXERCISE, encoding="utf-8")
    return path


def test_a_corrected_exercise_with_the_same_id_is_not_answered_from_the_old_cache(tmp_path):
    """Two files declare exercise 'same-id' with different solvers: a cache of computed
    answers gives each its own, although the id and the parameters are the same."""
    old = load_file(_write(tmp_path / "old", 1.0))
    new = load_file(_write(tmp_path / "new", 2.0))
    assert old.id == new.id
    cache = VariantCache(lambda exercise, variant: variant.answers["t"], limit=10)
    variant_old, variant_new = old.variant(3), new.variant(3)
    assert variant_old.params == variant_new.params
    h = variant_old.params["h"]
    assert cache(old, variant_old) == 1.0 * h
    assert cache(new, variant_new) == 2.0 * h
    assert exercise_identity(old) == file_sha256(tmp_path / "old" / "same_id.py")
    assert exercise_identity(old) != exercise_identity(new)


def test_a_cache_computes_once_per_identity_and_parameters_and_stays_bounded(tmp_path):
    exercise = load_file(_write(tmp_path, 1.0))
    calls = []
    cache = VariantCache(lambda e, v: calls.append(v.seed) or len(calls), limit=2)
    variants = [exercise.variant(seed) for seed in range(40)]
    distinct = {tuple(v.params.items()) for v in variants}
    assert len(distinct) >= 3  # h takes 5 values; 40 seeds meet at least 3 of them
    first = variants[0]
    same = next(v for v in variants[1:] if v.params == first.params)
    assert cache(exercise, first) == cache(exercise, same) == 1 and len(calls) == 1
    for variant in variants:
        cache(exercise, variant)
    assert len(cache._values) <= 2


def test_two_runs_share_no_cache_or_compiler(tmp_path, bank):
    exercise = bank.get("projectile-range")
    runs = [GenerationRun(None, {exercise.id: exercise}, {}, tmp_path) for _ in range(2)]
    assert runs[0].problems is not runs[1].problems
    assert runs[0].figures is not runs[1].figures
    assert runs[0].compiler is not runs[1].compiler


def test_a_run_sent_to_a_worker_arrives_with_its_exercises_reloaded_and_empty_caches(
        tmp_path, bank):
    exercise = bank.get("projectile-range")
    run = GenerationRun(None, {exercise.id: exercise}, {}, tmp_path)
    run.problems(exercise, exercise.variant(1))
    copy = pickle.loads(pickle.dumps(run))
    assert copy.exercises["projectile-range"].path == exercise.path
    assert copy.exercises["projectile-range"].variant(1) == exercise.variant(1)
    assert copy.problems._values == {} and run.problems._values != {}


def _double(run, item):
    return (run, item * 2)


def test_a_pool_calls_each_job_with_its_run_in_order_with_and_without_workers():
    for jobs in (1, 2):
        with Pool("the run", jobs) as pool:
            assert list(pool.map(_double, range(7), chunksize=2)) == [
                ("the run", 2 * i) for i in range(7)]
            assert pool.submit(_double, 5).result() == ("the run", 10)


def test_an_exam_generated_by_two_workers_has_the_files_of_one_process(tmp_path, bank,
                                                                       exam_toml):
    exam = tmp_path / "exam.toml"
    exam.write_text(exam_toml, encoding="utf-8")
    roster = tmp_path / "roster.csv"
    roster.write_text("student_id,name\n" + "".join(f"s{i},S {i}\n" for i in range(6)),
                      encoding="utf-8")
    for jobs in (1, 2):  # the same secret, so that the variants are the same
        generate_exam(exam, roster, tmp_path / f"out{jobs}", bank=bank, jobs=jobs, pdf=False,
                      secret="f" * 64)
    compared = filecmp.dircmp(tmp_path / "out1", tmp_path / "out2")

    def differences(node) -> list[str]:
        found = node.diff_files + node.left_only + node.right_only
        return found + [f for sub in node.subdirs.values() for f in differences(sub)]

    assert differences(compared) == []


FORMULA_EXERCISE = textwrap.dedent('''\
    from dynagrade.exercise import Exercise, Misconception, Symbolic, Uniform

    EXERCISE = Exercise(
        id="same-id", title="Doubling", source="Example 1.1",
        params=(Uniform("h", 1, 6, step=1, unit="m", symbol="h"),),
        statement="A rod of length $h = {{ h }}$.\\n\\n1. Write twice its length in $h$.",
        solve=lambda p: {},
        parts=(Symbolic("y", "twice the length", question=1, expected="2*h",
                        variables=("h",),
                        misconceptions=(Misconception("slip", SLIP, "Check the factor.",
                                                      applies=lambda p: p.h > 3),)),),
    )
    ''')
SLIP_ACCEPTED = "part y: the misconception 'slip' gives the right answer"


def _write_formula(folder, slip: str):
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / "same_id.py"
    path.write_text(f"SLIP = {slip!r}\n" + FORMULA_EXERCISE, encoding="utf-8")
    return load_file(path)


def test_a_formula_checked_from_the_cache_gets_the_problems_an_unchecked_one_gets(tmp_path):
    """The misconception 'slip' is the formula itself written otherwise (h + h), so it is
    accepted wherever it applies: for h > 3 m, never below. The run checks the formula
    once per set of misconceptions that apply, and every variant still gets its own
    verdict."""
    from dynagrade.generation.variants import check_variant

    exercise = _write_formula(tmp_path, "h + h")
    run = GenerationRun(None, {exercise.id: exercise}, {}, tmp_path)
    seen = set()
    for seed in range(40):
        variant = exercise.variant(seed)
        expected = (SLIP_ACCEPTED,) if variant.params["h"] > 3 else ()
        assert check_variant(exercise, variant, run.part_problems) == expected
        assert check_variant(exercise, variant) == expected
        seen.add(expected)
    assert seen == {(), (SLIP_ACCEPTED,)}
    assert len(run.part_problems._values) == 2


def test_an_edited_formula_is_not_answered_from_the_old_ones_cached_checks(tmp_path):
    """Two files declare exercise 'same-id' with the same formula and parameters; in the
    corrected one the misconception is a real mistake (3 h), so its variants pass."""
    old = _write_formula(tmp_path / "old", "h + h")
    new = _write_formula(tmp_path / "new", "3*h")
    run = GenerationRun(None, {}, {}, tmp_path)
    variant = next(old.variant(seed) for seed in range(40)
                   if old.variant(seed).params["h"] > 3)
    assert new.variant(variant.seed).params == variant.params
    assert run.problems(old, variant) == (SLIP_ACCEPTED,)
    assert run.problems(new, new.variant(variant.seed)) == ()
    assert run.problems(old, variant) == (SLIP_ACCEPTED,)


def test_the_example_exams_variants_get_the_same_problems_with_and_without_the_cache(
        tmp_path, bank):
    """Every part kind of the example exam's exercises, 30 seeds each: the run's cached
    checks list the problems, in order, that checking each variant anew lists."""
    from dynagrade.generation.variants import check_variant
    from dynagrade.exercise.model import ConstraintError

    ids = ("projectile-range", "sliding-up-a-slope", "car-in-a-looping",
           "release-under-gravity", "block-sliding-down-incline", "particle-on-a-string")
    exercises = {i: bank.get(i) for i in ids}
    run = GenerationRun(None, exercises, {}, tmp_path)
    checked = 0
    for exercise in exercises.values():
        for seed in range(30):
            try:
                variant = exercise.variant(seed)
            except ConstraintError:
                continue
            assert run.problems(exercise, variant) == check_variant(exercise, variant)
            checked += 1
    assert checked >= 150 and run.part_problems._values
