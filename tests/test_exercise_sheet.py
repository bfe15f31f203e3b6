"""The student's fill-in file: written for a variant, read back with ast only."""

import pytest
from hypothesis import given
from hypothesis import strategies as st

from dynagrade.exercise.sheet import SheetError, parse_sheet, read_sheet, write_sheet


@pytest.fixture(scope="module")
def projectile(bank):
    return bank.get("projectile-range")


def test_a_written_sheet_reads_back_with_every_part_unanswered(projectile):
    variant = projectile.variant(42)
    sheet = parse_sheet(write_sheet(projectile, variant, "s1"))
    assert (sheet.exercise_id, sheet.seed, sheet.student) == ("projectile-range", 42, "s1")
    assert sheet.answers == {p.name: None for p in projectile.parts}
    assert sheet.problems == {}


def test_the_statement_is_in_the_docstring(projectile):
    variant = projectile.variant(42)
    text = write_sheet(projectile, variant, "s1")
    docstring = text.split('"""')[1]
    assert f"{variant.params['v0']:g} m/s" in docstring


HEADER = 'EXERCISE = "x"\nSEED = 5\nSTUDENT = "s"\n'


@pytest.mark.parametrize("line, expected", [
    ("a = 12.5", "12.5"), ("a = -3", "-3"), ('a = "45 km/h"', "45 km/h"),
    ("a = [1.5, -2]", "[1.5, -2]"), ("a = (1, 2)", "[1, 2]"), ("a = None", None),
    ("a = 1e3", "1000.0"),
])
def test_literal_answers_are_read_as_text(line, expected):
    assert parse_sheet(HEADER + line).answers["a"] == expected


@pytest.mark.parametrize("line", [
    "a = __import__('os').system('touch /tmp/dynagrade-pwned')",
    "a = open('/etc/passwd').read()",
    "a = b", "a = 2*pi", "a = lambda: 1", "a = x.y", "a = [f() for f in g]",
    "a = True",
])
def test_non_literal_answers_are_problems_not_code(line, tmp_path):
    sheet = parse_sheet(HEADER + line)
    assert sheet.answers["a"] is None
    assert "line 4" in sheet.problems["a"]


def test_nothing_in_a_sheet_is_ever_run(tmp_path):
    marker = tmp_path / "ran"
    path = tmp_path / "exercise.py"
    path.write_text(HEADER + f"import os\nos.system('touch {marker}')\n"
                    f"a = __import__('os').system('touch {marker}')\n")
    read_sheet(path)
    assert not marker.exists()


@pytest.mark.parametrize("text, message", [
    ("a = (", "line 1"),
    ("a = 1\n", "not a dynagrade sheet"),
    ('EXERCISE = "x"\n', "SEED"),
    ('EXERCISE = "x"\nSEED = "abc"\n', "SEED"),
    ('EXERCISE = "x"\nSEED = -5\n', "SEED"),
    ('EXERCISE = "x"\nSEED = "\u00b3"\n', "SEED"),
    ('EXERCISE = "x"\nSEED = ' + "9" * 5000 + "\n", "line 2"),
])
def test_files_that_are_not_sheets_get_a_clear_error(text, message):
    with pytest.raises(SheetError, match=message):
        parse_sheet(text)


def test_a_binary_or_huge_file_is_refused(tmp_path):
    binary = tmp_path / "b.py"
    binary.write_bytes(b"\xff\xfe\x00garbage")
    with pytest.raises(SheetError, match="UTF-8"):
        read_sheet(binary)
    huge = tmp_path / "h.py"
    huge.write_text("#" * 2_000_000)
    with pytest.raises(SheetError, match="too large"):
        read_sheet(huge)


@given(st.text(max_size=300))
def test_any_text_is_either_a_sheet_or_a_sheet_error(text):
    try:
        parse_sheet(text)
    except SheetError:
        pass


def test_deeply_nested_brackets_are_a_sheet_error():
    with pytest.raises(SheetError):
        parse_sheet(HEADER + "a = " + "[" * 100_000 + "]" * 100_000)
