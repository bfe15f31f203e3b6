"""The exam manifest's records and file: a round trip keeps every field, and every kind of
bad field is refused with the path of the field at fault."""

from __future__ import annotations

import copy
import json

import pytest
from click.testing import CliRunner

from dynagrade.cli import main
from dynagrade.exam import manifest as mf
from dynagrade.generation.generate import generate_exam


def small_manifest() -> dict:
    """A two-exercise, two-student manifest written out by hand (one part of every kind)."""
    return {
        "format": "dynagrade-exam-manifest", "version": 1,
        "generator": {"dynagrade": "0.1", "numpy": "2.0.0"},
        "exam": {"id": "t-1", "title": "Test", "date": "2026-01-30", "instructions": "",
                 "points": 5.0},
        "exercises": [
            {"id": "one", "title": "One", "source": "Example 1.1", "points": 3.0,
             "set": {"g": 9.81}, "file": "ch1/one.py", "sha256": "ab" * 32,
             "parts": [
                 {"name": "v", "label": "speed", "kind": "numeric", "unit": "m/s",
                  "points": 1.5, "rtol": 0.01, "atol": None},
                 {"name": "r", "label": "r", "kind": "vector", "unit": "m", "points": 1.0,
                  "rtol": 0.01, "atol": 0.001, "size": 2},
                 {"name": "f", "label": "f", "kind": "symbolic", "unit": None,
                  "points": 0.5},
             ]},
            {"id": "two", "title": "Two", "source": "Example 2.1", "points": 2.0, "set": {},
             "file": "ch2/two.py", "sha256": "cd" * 32,
             "parts": [{"name": "c", "label": "which", "kind": "choice", "unit": None,
                        "points": 2.0, "options": ["a", "b", "c"], "multiple": True}]},
        ],
        "students": [
            {"student_id": f"s{i}", "name": f"S {i}", "email": "",
             "variants": [
                 {"exercise": "one", "seed": 10 + i, "params": {"v0": 12.5, "kind": "x"},
                  "answers": {"v": 3.5, "r": [1.0, -2.0], "f": "v0*t"},
                  "redraws": [{"seed": 99, "problems": ["sin equals cos"]}] if i else []},
                 {"exercise": "two", "seed": 20 + i, "params": {},
                  "answers": {"c": ["a", "c"]}, "redraws": []},
             ]} for i in range(2)],
    }


def test_a_manifest_survives_the_round_trip_through_records_and_file(tmp_path):
    data = small_manifest()
    manifest = mf.from_dict(data)
    assert mf.to_dict(manifest) == data
    assert mf.from_dict(json.loads(json.dumps(data))) == manifest
    path = mf.dump(manifest, tmp_path / "manifest.json")
    assert mf.load(path) == manifest
    assert json.loads(path.read_text(encoding="utf-8")) == data


def test_an_optional_field_may_be_absent_or_present_without_a_new_version():
    data = small_manifest()
    assert mf.from_dict(data).exam.policy is None
    data["exam"] = {**data["exam"], "policy": {"feedback": "score"}}
    manifest = mf.from_dict(data)
    assert manifest.exam.policy == {"feedback": "score"} and manifest.version == 1
    assert mf.to_dict(manifest) == data
    data["exam"]["policy"] = "open"
    with pytest.raises(mf.ManifestError, match=r'^exam\.policy: expected an object, got "open"$'):
        mf.from_dict(data)


def test_the_records_hold_the_typed_values_a_reader_needs():
    manifest = mf.from_dict(small_manifest())
    one = manifest.exercise("one")
    assert one.part("v").rtol == 0.01 and one.part("v").atol is None
    assert one.part("r").size == 2 and one.part("f").rtol is None
    assert manifest.exercise("two").part("c").options == ("a", "b", "c")
    variant = manifest.students[1].variant("one")
    assert variant.answers["r"] == (1.0, -2.0)  # vectors as tuples, as solvers give them
    assert variant.redraws == (mf.Redraw(99, ("sin equals cos",)),)
    assert manifest.exercise_ids == ["one", "two"]


def test_a_generated_manifest_reads_back_to_the_same_bytes(tmp_path, bank, exam_toml):
    exam = tmp_path / "exam.toml"
    exam.write_text(exam_toml, encoding="utf-8")
    roster = tmp_path / "roster.csv"
    roster.write_text("student_id,name\na,A\nb,B\n", encoding="utf-8")
    generate_exam(exam, roster, tmp_path / "out", bank=bank, jobs=1, pdf=False)
    path = tmp_path / "out" / "manifest.json"
    assert mf.text(mf.load(path)) == path.read_text(encoding="utf-8")


def _broken(edit) -> dict:
    data = copy.deepcopy(small_manifest())
    edit(data)
    return data


@pytest.mark.parametrize("edit, message", [
    (lambda d: d["students"][1]["variants"][1].pop("answers"),
     "students[1].variants[1]: missing 'answers'"),
    (lambda d: d.pop("exam"), "the manifest: missing 'exam'"),
    (lambda d: d["exercises"][0].update(points="three"),
     'exercises[0].points: expected a number, got "three"'),
    (lambda d: d["exercises"][0].update(points=True),
     "exercises[0].points: expected a number, got true"),
    (lambda d: d["students"][0]["variants"][0].update(seed=1.5),
     "students[0].variants[0].seed: expected a whole number, got 1.5"),
    (lambda d: d["exam"].update(title=None), "exam.title: expected text, got null"),
    (lambda d: d["exercises"][1]["parts"][0].update(options=["a", 3]),
     "exercises[1].parts[0].options[1]: expected text, got 3"),
    (lambda d: d["exercises"][1]["parts"][0].update(multiple="yes"),
     'exercises[1].parts[0].multiple: expected true or false, got "yes"'),
    (lambda d: d["exercises"][0]["parts"][0].pop("rtol"),
     "exercises[0].parts[0]: missing 'rtol'"),
    (lambda d: d["exercises"][0]["parts"][1].pop("size"),
     "exercises[0].parts[1]: missing 'size'"),
    (lambda d: d["exercises"][0]["parts"][2].update(kind="essay"),
     "exercises[0].parts[2].kind: unknown part kind 'essay' (known: choice, numeric, "
     "symbolic, vector)"),
    (lambda d: d["students"].__setitem__(1, "s1"),
     'students[1]: expected an object, got "s1"'),
    (lambda d: d.update(students={}), "students: expected a list, got {}"),
    (lambda d: d["students"][0]["variants"][1].update(exercise="three"),
     "students[0].variants[1].exercise: 'three' is not an exercise of the exam (one, two)"),
    (lambda d: d["students"][1]["variants"][0]["answers"].pop("r"),
     "students[1].variants[0].answers: no answer for the parts ['r']"),
    (lambda d: d["students"][1].update(student_id="s0"),
     "students[1].student_id: 's0' appears twice"),
    (lambda d: d["exercises"][1].update(id="one"), "exercises[1].id: 'one' appears twice"),
    (lambda d: d.update(version=2),
     "version 2 is newer than this dynagrade reads (up to 1); install a newer dynagrade"),
    (lambda d: d.update(version="1"), "version: expected a positive whole number, got '1'"),
    (lambda d: d.update(format="something else"),
     "not a dynagrade exam manifest (written by `dynagrade exam`)"),
])
def test_each_kind_of_bad_field_is_named_with_its_path(edit, message):
    with pytest.raises(mf.ManifestError) as caught:
        mf.from_dict(_broken(edit))
    assert str(caught.value) == message


def test_a_file_that_is_not_json_or_not_readable_names_the_file(tmp_path):
    broken = tmp_path / "manifest.json"
    broken.write_text("{not json", encoding="utf-8")
    with pytest.raises(mf.ManifestError, match=r"manifest\.json: not a readable exam manifest"):
        mf.load(broken)
    with pytest.raises(mf.ManifestError, match="not a readable exam manifest"):
        mf.load(tmp_path / "missing.json")


def test_grading_against_a_hand_edited_manifest_reports_the_field_not_a_key_error(tmp_path):
    data = small_manifest()
    del data["students"][1]["variants"][0]["answers"]
    path = tmp_path / "manifest.json"
    path.write_text(json.dumps(data), encoding="utf-8")
    result = CliRunner().invoke(main, ["grade", "--manifest", str(path), str(tmp_path)])
    assert result.exit_code != 0
    assert "students[1].variants[0]: missing 'answers'" in result.output
    assert not isinstance(result.exception, KeyError)


def test_no_module_but_the_manifest_reads_the_manifests_fields_by_string():
    """Readers take the records: no ``x["students"]``, ``x["variants"]``, … outside
    exam/manifest.py (the names below are the manifest's own; a stage of the timings
    shares one)."""
    import ast
    from pathlib import Path

    fields = {"students", "exercises", "variants", "redraws", "sha256", "generator"}
    src = Path(mf.__file__).resolve().parent.parent
    found = []
    for path in sorted(src.rglob("*.py")):
        if path.name == "manifest.py" and path.parent.name == "exam":
            continue
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            key = node.slice if isinstance(node, ast.Subscript) else None
            timing = "timings" in ast.unparse(node.value) if key is not None else False
            if isinstance(key, ast.Constant) and key.value in fields and not timing:
                found.append(f"{path.relative_to(src)}:{node.lineno}: {ast.unparse(node)}")
    assert found == []
