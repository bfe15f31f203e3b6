"""Loading exercise files: the shipped bank, user folders, and clear errors."""

import textwrap

import pytest

from dynagrade.exercise import ExerciseFileError, load_file, open_bank
from dynagrade.errors import UnknownExercise
from dynagrade.exercise.loader import ENVIRONMENT_VARIABLE

GOOD = textwrap.dedent('''
    from dynagrade.exercise import Exercise, Numeric, Uniform

    EXERCISE = Exercise(
        id="{id}", title="{title}", source="Example 1.1",
        params=(Uniform("x", 1, 2, step=0.5),),
        statement="x = {{{{ x }}}}",
        solve=lambda p: {{"y": 2 * p.x}},
        parts=(Numeric("y"),),
    )
''')


def _write(folder, name, text):
    path = folder / name
    path.write_text(text)
    return path


def test_the_shipped_bank_has_the_pipeline_exercises(bank):
    ids = {e.id for e in bank.all()}
    assert {"projectile-range", "sliding-up-a-slope", "car-in-a-looping"} <= ids


def test_a_user_folder_is_searched_and_overrides_the_shipped_bank(tmp_path):
    _write(tmp_path, "mine.py", GOOD.format(id="projectile-range", title="Mine"))
    _write(tmp_path, "other.py", GOOD.format(id="my-own", title="Own"))
    bank = open_bank([tmp_path])
    assert bank.get("projectile-range").title == "Mine"
    assert bank.get("my-own").title == "Own"


def test_the_environment_variable_names_folders(tmp_path, monkeypatch):
    _write(tmp_path, "e.py", GOOD.format(id="from-env", title="Env"))
    monkeypatch.setenv(ENVIRONMENT_VARIABLE, str(tmp_path))
    assert open_bank().get("from-env").title == "Env"


def test_two_files_with_one_id_are_an_error_naming_both(tmp_path):
    a = _write(tmp_path, "a.py", GOOD.format(id="twin", title="A"))
    b = _write(tmp_path, "b.py", GOOD.format(id="twin", title="B"))
    with pytest.raises(ExerciseFileError) as error:
        open_bank([tmp_path]).all()
    assert str(a) in str(error.value) and str(b) in str(error.value)


@pytest.mark.parametrize("text, message", [
    ("EXERCISE = (\n", "line 1"),
    ("x = 1\n", "defines no EXERCISE"),
    ("import numpy\n\nraise RuntimeError('boom')\n", "line 3: RuntimeError: boom"),
    (GOOD.format(id="Bad Id", title="t"), "kebab-case"),
])
def test_a_malformed_exercise_file_names_the_file_line_and_fault(tmp_path, text, message):
    path = _write(tmp_path, "broken.py", text)
    with pytest.raises(ExerciseFileError) as error:
        load_file(path)
    assert str(path) in str(error.value) and message in str(error.value)


@pytest.mark.parametrize("template, message", [
    ('statement="x = {% if %}",', "line 4: statement template, line 1: Expected an expression"),
    ('statement="x = {{ x }}", solution="{{ speed }}",',
     "line 4: exercise 'templated': the solution template names ['speed']"),
])
def test_a_bad_template_is_the_files_error_at_the_line_building_the_exercise(
        tmp_path, template, message):
    text = GOOD.format(id="templated", title="T").replace('statement="x = {{ x }}",', template)
    path = _write(tmp_path, "t.py", text)
    with pytest.raises(ExerciseFileError) as error:
        load_file(path)
    assert str(error.value).startswith(f"{path.resolve()}, {message}")


def test_a_file_loaded_without_its_templates_checked_fails_when_they_are_asked_for(
        tmp_path):
    text = GOOD.format(id="templated", title="T").replace(
        'statement="x = {{ x }}",', 'statement="x = {{ x }}", solution="{{ speed }}",')
    path = _write(tmp_path, "t.py", text)
    exercise = load_file(path, templates=False)  # grading a file renders neither template
    variant = exercise.variant(0, with_statement=False)
    assert variant.answers["y"] == pytest.approx(2 * variant.params["x"])
    assert variant.statement == ""
    with pytest.raises(ExerciseFileError, match="line 4: .*names \\['speed'\\]"):
        load_file(path)  # the same module, from the cache: now its templates are checked
    with pytest.raises(ExerciseFileError, match="names \\['speed'\\]"):
        open_bank([tmp_path]).get("templated")


def test_an_unknown_id_suggests_close_ones(bank):
    with pytest.raises(UnknownExercise, match="projectile-range"):
        bank.get("projectile-rnge")


def test_a_missing_folder_is_an_error(tmp_path):
    with pytest.raises(ExerciseFileError, match="does not exist"):
        open_bank([tmp_path / "nope"])


def test_an_edited_file_is_loaded_anew_in_the_same_process(tmp_path):
    # An exercise's identity is its file's content: a corrected exercise must not keep
    # the definition (and so the verdicts) of the text it replaced. "Old" and "New" have
    # the same length, so the file's size does not change with the edit either.
    path = _write(tmp_path, "e.py", GOOD.format(id="edited", title="Old"))
    first = load_file(path)
    assert first.title == "Old"
    assert load_file(path) is first  # unchanged text: the cached module
    path.write_text(GOOD.format(id="edited", title="New"))
    second = load_file(path)
    assert second.title == "New"
    assert open_bank([tmp_path]).get("edited").title == "New"


def test_the_fingerprint_is_the_sha256_of_the_file(tmp_path):
    import hashlib

    path = _write(tmp_path, "e.py", GOOD.format(id="printed", title="Print"))
    assert load_file(path).fingerprint == hashlib.sha256(path.read_bytes()).hexdigest()
    (tmp_path / "copy").mkdir()
    twin = _write(tmp_path / "copy", "e.py", GOOD.format(id="printed", title="Print"))
    assert load_file(twin).fingerprint == load_file(path).fingerprint
    assert load_file(twin).path == str(twin.resolve())


def _exercise_modules():
    import sys

    # each is loaded in its folder's package: dynagrade_course_<folder>.dynagrade_exercise_...
    return {name for name in sys.modules
            if name.rpartition(".")[2].startswith("dynagrade_exercise_")}


def test_finding_one_exercise_loads_only_its_file(tmp_path):
    for name in ("a", "b", "c"):
        _write(tmp_path, f"{name}.py", GOOD.format(id=f"only-{name}", title=name))
    before = _exercise_modules()
    assert open_bank([tmp_path]).get("only-b").title == "b"
    loaded = _exercise_modules() - before
    assert len(loaded) == 1
    load_file(tmp_path / "b.py")
    assert _exercise_modules() - before == loaded  # the one module loaded was b.py's


def test_the_listing_reads_the_files_without_running_them(tmp_path):
    # A file whose module level would fail if run is still listed: listing never runs it.
    text = GOOD.format(id="listed", title="Listed") + "\nraise SystemExit('ran')\n"
    _write(tmp_path, "listed.py", text)
    before = _exercise_modules()
    (entry,) = [e for e in open_bank([tmp_path]).listing() if e.id == "listed"]
    assert _exercise_modules() == before
    assert entry.summary() == {
        "id": "listed", "title": "Listed", "source": "Example 1.1", "chapter": 1,
        "topics": [],
        "parts": [{"name": "y", "kind": "numeric", "unit": None, "points": 1.0, "label": ""}],
        "params": [{"name": "x", "unit": None, "symbol": "x"}]}


def test_the_static_listing_equals_the_loaded_exercises_summaries(bank):
    listed = [e.summary() for e in bank.listing()]
    assert listed == [e.summary() for e in bank.all()]


def test_a_file_that_computes_its_listing_fields_is_loaded_to_list_it(tmp_path):
    text = GOOD.format(id="computed", title="Computed").replace(
        'title="Computed"', 'title="Com" + "puted"')
    _write(tmp_path, "computed.py", text)
    (entry,) = [e for e in open_bank([tmp_path]).listing() if e.id == "computed"]
    assert entry.title == "Computed"
