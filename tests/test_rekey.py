"""`dynagrade rekey MANIFEST EXERCISE_ID...`: the stored reference answers of the named
exercises computed again from the fixed exercise file, with each variant's stored seed;
refused, with nothing written, when a variant's parameters would change (issue 25,
item 3)."""

from __future__ import annotations

import csv
import io
import json

import pytest
from click.testing import CliRunner

from dynagrade.cli import main
from regrade_support import EXERCISE_ID, demo_exam, lengths, write_exercise


@pytest.fixture
def exam(tmp_path):
    return demo_exam(tmp_path)


def _rekey(folder, *args):
    return CliRunner().invoke(main, ["--exercises", str(folder), "rekey", *map(str, args)])


def _stored(manifest) -> dict[str, dict]:
    data = json.loads(manifest.read_text(encoding="utf-8"))
    return {s["student_id"]: s["variants"][0] for s in data["students"]}


def test_rekey_recomputes_the_keys_the_fixed_solver_changes(exam):
    manifest, folder = exam
    x = lengths(manifest)
    before = _stored(manifest)
    # the fix changes y by 1 m for the longer lengths only
    write_exercise(folder, y="2 * p.x + (1 if p.x >= 1.5 else 0)", rtol=0.05)
    longer = sorted(s for s, value in x.items() if value >= 1.5)
    assert 0 < len(longer) < len(x)  # some keys change, some do not
    result = _rekey(folder, manifest, EXERCISE_ID)
    assert result.exit_code == 0, result.output
    assert f"{EXERCISE_ID}: {len(longer)} of {len(x)} students' keys changed (y)" \
        in result.output
    assert "key.csv was rewritten" in result.output
    assert "key.pdf, moodle.xml and the students' sheets and solutions in the folder are " \
           "NOT rendered again" in result.output
    after = _stored(manifest)
    for student, value in x.items():  # worked out from x alone
        assert after[student]["answers"]["y"] == pytest.approx(
            2 * value + (1 if value >= 1.5 else 0))
        assert after[student]["answers"]["z"] == before[student]["answers"]["z"]
        assert after[student]["params"] == before[student]["params"]
        assert after[student]["seed"] == before[student]["seed"]
    data = json.loads(manifest.read_text(encoding="utf-8"))
    described = data["exercises"][0]
    import hashlib

    assert described["sha256"] == hashlib.sha256(
        (folder / "regrade_demo.py").read_bytes()).hexdigest()
    assert {p["name"]: p["rtol"] for p in described["parts"]}["z"] == 0.05
    assert [p["points"] for p in described["parts"]] == [2, 2]  # the exam's, unchanged
    key = list(csv.DictReader(io.StringIO((manifest.parent / "key.csv").read_text("utf-8"))))
    y_key = {row["student_id"]: float(row["answer"]) for row in key if row["part"] == "y"}
    assert y_key == {s: pytest.approx(2 * v + (1 if v >= 1.5 else 0)) for s, v in x.items()}
    # a second run finds nothing more to change
    again = _rekey(folder, manifest, EXERCISE_ID)
    assert f"{EXERCISE_ID}: 0 of {len(x)} students' keys changed" in again.output


def test_rekey_refuses_when_the_draw_of_the_parameters_changes(exam):
    manifest, folder = exam
    text = manifest.read_bytes()
    write_exercise(folder, y="2 * p.x + 1", low=1.25)  # x is drawn from another range
    result = _rekey(folder, manifest, EXERCISE_ID)
    assert result.exit_code == 1
    assert "parameters of" in result.output and "would change" in result.output
    assert "s1: x 1.0 → " in result.output  # the first student and parameter that differ
    assert "nothing was written" in result.output
    assert manifest.read_bytes() == text


def test_rekey_refuses_an_exercise_the_exam_or_the_bank_does_not_have(exam):
    manifest, folder = exam
    text = manifest.read_bytes()
    other = _rekey(folder, manifest, "projectile-range")
    assert other.exit_code == 1
    assert "no exercise 'projectile-range' in this exam; its exercises are regrade-demo" \
        in other.output
    unknown = _rekey(folder, manifest, "no-such-exercise")
    assert unknown.exit_code == 1 and "no exercise 'no-such-exercise'" in unknown.output
    (folder / "regrade_demo.py").unlink()  # in the exam, but no longer in any folder
    gone = _rekey(folder, manifest, EXERCISE_ID)
    assert gone.exit_code == 1 and f"no exercise with id {EXERCISE_ID!r}" in gone.output
    assert manifest.read_bytes() == text


def test_rekey_works_on_an_exam_that_is_being_served(exam):
    """The server's lock keeps `dynagrade exam` off the folder, not a re-key, which
    replaces the manifest alone, atomically."""
    from dynagrade.serve.location import serving

    manifest, folder = exam
    write_exercise(folder, y="2 * p.x + 1")
    with serving(manifest.parent):
        result = _rekey(folder, manifest, EXERCISE_ID)
    assert result.exit_code == 0, result.output
    x = lengths(manifest)
    assert {s: v["answers"]["y"] for s, v in _stored(manifest).items()} == \
        {s: pytest.approx(2 * v + 1) for s, v in x.items()}
    assert not list(manifest.parent.glob(".manifest.json.*.tmp"))
