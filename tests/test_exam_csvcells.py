"""Every CSV dynagrade writes is inert in a spreadsheet, and its own readers get back
exactly what was written (:mod:`dynagrade.exam.csvcells`, issue 26).

The cells below are worked out by hand from OWASP's rule: a cell starting with ``=``,
``+``, ``-``, ``@``, a tab or a carriage return gets a leading apostrophe.
"""

from __future__ import annotations

import csv
import io
import re

import pytest
from hypothesis import example, given, strategies as st

from dynagrade.exam.csvcells import csv_text, inert, restored, restored_rows
from dynagrade.exam.roster import parse_roster

#: (what is written, the cell in the file), each by hand
CELLS = [
    ('=HYPERLINK("http://x","y")', '\'=HYPERLINK("http://x","y")'),
    ("@SUM(1)", "'@SUM(1)"),
    ("=cmd|' /C calc'!A0", "'=cmd|' /C calc'!A0"),
    ("+1+1", "'+1+1"),
    ("-3+cmd|' /C calc'!A0", "'-3+cmd|' /C calc'!A0"),
    ("-3.2 m/s", "'-3.2 m/s"),
    ("\t=1", "'\t=1"),
    ("\r=1", "'\r=1"),
    # the student typed the apostrophe: one more, so that reading drops only ours
    ("'=1", "''=1"),
    ("''@x", "'''@x"),
    # plain numbers as dynagrade writes them are numbers, not formulas
    ("-3.5", "-3.5"),
    ("-1.25e-05", "-1.25e-05"),
    ("14", "14"),
    # nothing a spreadsheet runs: as it is
    ("'t Hooft", "'t Hooft"),
    ("'", "'"),
    ("", ""),
    ("Ada Muster", "Ada Muster"),
    (" =1", " =1"),
    ("'-3.5", "'-3.5"),
]


@pytest.mark.parametrize(("text", "cell"), CELLS)
def test_a_cell_a_spreadsheet_would_run_gets_an_apostrophe_and_reads_back(text, cell):
    assert inert(text) == cell
    assert restored(cell) == text


def test_the_csv_text_holds_the_inert_cells_and_plain_numbers():
    written = csv_text([("name", "total", "answer"),
                        ("=cmd|' /C calc'!A0", 3.5, "@SUM(1)"), ("Ada", None, -3)])
    assert written == ("name,total,answer\n"
                       "'=cmd|' /C calc'!A0,3.5,'@SUM(1)\n"
                       "Ada,,-3\n")


#: a cell that starts like a formula, apostrophes, or anything at all
CELL_TEXT = st.one_of(
    st.text(),
    st.builds(lambda quotes, start, rest: "'" * quotes + start + rest,
              st.integers(0, 3), st.sampled_from(["=", "+", "-", "@", "\t", "\r", "'", "1"]),
              st.text()))


@given(CELL_TEXT)
@example("'=1")
@example("-3.5")
def test_every_text_reads_back_exactly_and_no_written_cell_runs(text):
    cell = inert(text)
    assert restored(cell) == text
    assert not cell.startswith(("=", "+", "-", "@", "\t", "\r")) \
        or re.fullmatch(r"-[0-9]+(\.[0-9]+)?([eE][-+]?[0-9]+)?", cell)


@given(st.lists(st.lists(CELL_TEXT, min_size=1, max_size=5), min_size=1, max_size=5))
def test_rows_written_and_read_back_with_csv_are_the_same_rows(rows):
    read = restored_rows(csv.reader(io.StringIO(csv_text(rows), newline="")))
    assert read == rows


def test_a_roster_dynagrade_wrote_reads_back_with_the_names_as_given():
    """grades.csv and key.csv are rosters too (student_id, name, email)."""
    raw = csv_text([("student_id", "name", "email"), ("s1", "=cmd|' /C calc'!A0", "")])
    assert raw.splitlines()[1] == "s1,'=cmd|' /C calc'!A0,"
    assert parse_roster(raw.encode("utf-8"))[0].name == "=cmd|' /C calc'!A0"


@given(st.lists(st.lists(st.text(alphabet=st.characters(blacklist_characters="\r")).filter(
    lambda t: not t.lstrip("'").startswith(("=", "+", "-", "@", "\t"))),
    min_size=1, max_size=4), min_size=1, max_size=4))
def test_cells_nothing_would_run_are_written_as_the_standard_csv_writer_writes_them(rows):
    """Files of ordinary data stay byte for byte what they were before the rule."""
    buffer = io.StringIO()
    csv.writer(buffer, lineterminator="\n").writerows(rows)
    assert csv_text(rows) == buffer.getvalue()


HOSTILE_NAME = "=cmd|' /C calc'!A0"
EXAM = """\
id = "csv-cells"
title = "@SUM(1)"
date = 2025-04-14
round = 0.5

[[exercise]]
id = "projectile-range"
points = 6
"""


def test_a_roster_name_that_is_a_formula_is_inert_in_every_gradebook_and_the_key(
        tmp_path, bank):
    from dynagrade.classgrade.grade import grade_class
    from dynagrade.generation.generate import generate_exam

    (tmp_path / "exam.toml").write_text(EXAM, encoding="utf-8")
    (tmp_path / "roster.csv").write_text(
        f'student_id,name,email\ns1,"{HOSTILE_NAME}",@evil\ns2,Ada,ada@example.org\n',
        encoding="utf-8")
    generate_exam(tmp_path / "exam.toml", tmp_path / "roster.csv", tmp_path / "out",
                  bank=bank, jobs=1, pdf=False)
    (tmp_path / "responses.csv").write_text(
        'student_id,exercise_id,part,answer\ns1,projectile-range,x_max,"=HYPERLINK(""h"")"\n',
        encoding="utf-8")
    grade_class(tmp_path / "out" / "manifest.json", [tmp_path / "responses.csv"],
                tmp_path / "grading", bank=bank, jobs=1, formats=("moodle", "canvas"))

    def lines(name):
        return (tmp_path / name).read_text(encoding="utf-8").splitlines()

    # by hand: the name and the email get an apostrophe; s1's points (x_max wrong) are 0
    # of 6, a plain number in the grade columns
    assert lines("grading/grades.csv")[1] == \
        "s1,'=cmd|' /C calc'!A0,'@evil,0,0,6,0.00,graded"
    assert lines("grading/grades-moodle.csv")[0] == \
        "ID number,Email address,Full name,'@SUM(1),Feedback: @SUM(1)"
    assert lines("grading/grades-moodle.csv")[1].startswith(
        "s1,'@evil,'=cmd|' /C calc'!A0,0,0 / 6 points")
    assert lines("grading/grades-canvas.csv")[1:3] == [
        "Points Possible,,,,,6", "'=cmd|' /C calc'!A0,,s1,,,0"]
    key = [row for row in lines("out/key.csv") if row.startswith("s1,")]
    assert key and all(row.startswith("s1,'=cmd|' /C calc'!A0,") for row in key)
    # a formula nowhere in a cell's first place
    for name in ("grading/grades.csv", "grading/grades-moodle.csv",
                 "grading/grades-canvas.csv", "grading/problems.csv", "out/key.csv"):
        for row in csv.reader(io.StringIO((tmp_path / name).read_text(encoding="utf-8"))):
            assert not any(cell.startswith(("=", "@", "+")) for cell in row), (name, row)
