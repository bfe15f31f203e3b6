"""One error root: every error class of dynagrade derives from DynagradeError, "not found"
is a LookupError of the root (never a raw KeyError), and an exercise definition that names
a part which does not exist fails when it is built, not when it is verified or graded."""

import ast
import importlib
import inspect
import pkgutil
from pathlib import Path

import pytest

import dynagrade
from dynagrade.errors import (DefinitionError, DynagradeError, UnknownExercise,
                              UnknownParameter, UnknownPart)
from dynagrade.exercise import Exercise, Numeric, Symbolic, Uniform, open_bank

SOURCE = Path(dynagrade.__file__).parent

#: Exceptions that are control-flow signals, not errors, and so stay outside the root
#: (see the docstring of dynagrade.errors).
SIGNALS = {"dynagrade.grading.timing.OutOfTime"}


def _modules():
    for info in pkgutil.walk_packages(dynagrade.__path__, "dynagrade."):
        yield importlib.import_module(info.name)


def test_every_exception_class_of_the_package_derives_from_the_root():
    found, outside = [], []
    for module in _modules():
        for name, value in vars(module).items():
            if (inspect.isclass(value) and issubclass(value, BaseException)
                    and value.__module__ == module.__name__):
                qualified = f"{module.__name__}.{name}"
                found.append(qualified)
                if not issubclass(value, DynagradeError) and qualified not in SIGNALS:
                    outside.append(qualified)
    assert "dynagrade.grading.errors.AnswerError" in found  # the scan sees the grader
    assert "dynagrade.exam.manifest.ManifestError" in found  # ... and the exams
    assert outside == []


def _raised_names(tree):
    for node in ast.walk(tree):
        if isinstance(node, ast.Raise) and node.exc is not None:
            exc = node.exc.func if isinstance(node.exc, ast.Call) else node.exc
            if isinstance(exc, ast.Name):
                yield exc.id, node.lineno


def test_no_module_raises_a_bare_key_error():
    offenders = [f"{path.relative_to(SOURCE)}:{line}"
                 for path in sorted(SOURCE.rglob("*.py"))
                 for name, line in _raised_names(ast.parse(path.read_text(encoding="utf-8")))
                 if name == "KeyError"]
    assert offenders == []


def test_not_found_errors_are_lookup_errors_of_the_root():
    for cls in (UnknownExercise, UnknownParameter, UnknownPart):
        assert issubclass(cls, DynagradeError) and issubclass(cls, LookupError)
    assert issubclass(DefinitionError, ValueError)


def _exercise(*parts, solve=None):
    return Exercise(id="refs", title="References", source="Example 1.9",
                    params=(Uniform("v0", 1, 2, step=0.5, unit="m/s"),),
                    statement="v0 = {{ v0 }}",
                    solve=solve or (lambda p: {"x": 2 * p.v0, "y": 3 * p.v0}),
                    parts=parts)


def test_a_typo_in_equals_fails_when_the_exercise_is_built_listing_the_parts():
    # Before: Symbolic(equals="x_typo") built fine and `dynagrade verify` crashed with
    # a raw KeyError('x_typo').
    with pytest.raises(DefinitionError) as error:
        _exercise(Numeric("x", unit="m/s"), Numeric("y", unit="m/s"),
                  Symbolic("x_formula", expected="2*v0", equals="x_typo"))
    message = str(error.value)
    assert "x_formula" in message and "'x_typo'" in message and "['x', 'y']" in message


def test_a_uses_that_names_no_part_fails_when_the_exercise_is_built():
    # Before: uses=("nope",) built fine and grading a student's wrong answer to "y"
    # crashed with KeyError in the follow-through.
    with pytest.raises(DefinitionError, match=r"part 'y': uses='nope' .* does not exist"):
        _exercise(Numeric("x"), Numeric("y", uses=("nope",),
                                        follow_through=lambda p, a: 1.5 * a["nope"]))


def test_a_reference_to_a_later_part_is_refused_too():
    with pytest.raises(DefinitionError, match=r"uses='y' names a part that comes after it"):
        _exercise(Numeric("x", uses=("y",), follow_through=lambda p, a: a["y"] / 1.5),
                  Numeric("y"))


def test_references_to_earlier_parts_are_accepted():
    exercise = _exercise(Numeric("x", unit="m/s"),
                         Numeric("y", uses=("x",), follow_through=lambda p, a: 1.5 * a["x"]),
                         Symbolic("x_formula", expected="2*v0", equals="x"))
    assert [p.name for p in exercise.parts] == ["x", "y", "x_formula"]


def test_a_solver_without_an_answer_for_a_part_is_a_definition_error():
    exercise = _exercise(Numeric("x"), Numeric("z"))
    with pytest.raises(DefinitionError, match=r"no answer for part 'z'; it returned \['x', 'y'\]"):
        exercise.variant(0)


def test_unknown_names_say_what_exists():
    exercise = _exercise(Numeric("x"), Numeric("y"))
    with pytest.raises(UnknownParameter, match=r"no parameter 'speed'; it has \['v0'\]"):
        exercise.parameter("speed")
    with pytest.raises(UnknownPart, match=r"no part 'z'; it has \['x', 'y'\]"):
        exercise.part("z")


def test_an_unknown_exercise_is_a_lookup_error_with_suggestions():
    with pytest.raises(LookupError, match="did you mean projectile-range"):
        open_bank().get("projectile-rnge")
