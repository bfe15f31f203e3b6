"""The routes of `dynagrade serve` as a whole: the JSON gradebook."""

from __future__ import annotations

import csv
import io
import re

import pytest

from serve_support import exam_copy, exam_dir, reference_answers, serve  # noqa: F401


@pytest.fixture(scope="module")
def served(exam_dir, tmp_path_factory):
    """A practice exam (every route, including "new variant", is open) with tokens."""
    manifest = exam_copy(exam_dir, tmp_path_factory.mktemp("routes") / "exam",
                         mode="practice", feedback="immediate")
    with serve(manifest) as running:
        yield running


def test_the_json_gradebook_holds_the_rows_of_grades_csv(served):
    right = reference_answers(served, "s1", "projectile-range")
    served.submit("s1", "projectile-range", right)
    book = served.staff_get("/api/v1/gradebook")
    assert book.status_code == 200
    body = book.json()
    assert body["exercise_ids"] == ["projectile-range", "sliding-up-a-slope"]
    table = {row["student_id"]: row for row in csv.DictReader(io.StringIO(
        served.staff_get("/api/v1/grades.csv").text))}
    assert [row["student_id"] for row in body["rows"]] == list(table)
    for row in body["rows"]:
        line = table[row["student_id"]]
        assert (row["name"], row["email"], row["status"]) == (
            line["name"], line["email"], line["status"])
        for exercise, points in row["exercises"].items():
            assert (points is None and line[exercise] == "") or \
                points == pytest.approx(float(line[exercise]))
        assert row["max_total"] == pytest.approx(float(line["max_total"]))
    s1 = next(row for row in body["rows"] if row["student_id"] == "s1")
    assert s1["exercises"]["projectile-range"] == pytest.approx(6.0)
    assert re.fullmatch(r"graded|incomplete", s1["status"])
