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


# -- reading files as editors save them (issue 11, item 5) --------------------------------


def test_a_sheet_saved_with_a_bom_and_crlf_reads_like_the_plain_one(projectile, tmp_path):
    variant = projectile.variant(7)
    text = write_sheet(projectile, variant, "s1").replace(
        f"{projectile.parts[0].name} = None", f'{projectile.parts[0].name} = "12 m"')
    plain, windows = tmp_path / "plain.py", tmp_path / "windows.py"
    plain.write_bytes(text.encode("utf-8"))
    windows.write_bytes(b"\xef\xbb\xbf" + text.replace("\n", "\r\n").encode("utf-8"))
    assert read_sheet(windows) == read_sheet(plain)
    assert read_sheet(windows).answers[projectile.parts[0].name] == "12 m"


def test_one_unquoted_answer_costs_only_its_own_part_and_says_how_to_fix_it():
    sheet = parse_sheet(HEADER + 'a = 6.00 m/s^2\nb = "3 m"\n')
    assert sheet.answers == {"a": None, "b": "3 m"}
    assert sheet.problems == {
        "a": 'line 4: this is not valid Python; put the answer in quotes: a = "6.00 m/s^2"'}


def test_unquoted_arithmetic_of_numbers_is_read_as_that_expression():
    sheet = parse_sheet(HEADER + "a = 8*(9.81-6.867)\nb = -2**3/4\n")
    from dynagrade.grading import read_number

    # 8*(9.81-6.867) = 8*2.943 = 23.544 and -2**3/4 = -8/4 = -2, by hand
    assert read_number(sheet.answers["a"], None) == pytest.approx(23.544)
    assert read_number(sheet.answers["b"], None) == pytest.approx(-2.0)
    assert sheet.problems == {}


@pytest.mark.parametrize("lines, names, words", [
    ("a: float = 3", ["a"], "annotated"),
    ("a += 1", ["a"], "augmented"),
    ("a, b = 1, 2", ["a", "b"], "several names"),
    ("(a := 3)", ["a"], "walrus"),
    ("if True:\n    a = 3", ["a"], "inside another statement"),
    ("for i in []:\n    a = 3", ["a"], "inside another statement"),
])
def test_every_other_assignment_shape_gets_a_message_not_silence(lines, names, words):
    sheet = parse_sheet(HEADER + lines + "\n")
    for name in names:
        assert sheet.answers[name] is None
        assert words in sheet.problems[name] and "line 4" in sheet.problems[name]


def test_a_broken_line_that_assigns_nothing_is_a_located_note():
    sheet = parse_sheet(HEADER + "hello world\na = 2\n")
    assert sheet.answers == {"a": "2"}
    assert sheet.notes == ("line 4: this is not valid Python and was ignored",)


def test_a_broken_header_line_makes_the_file_unreadable_naming_the_line():
    with pytest.raises(SheetError, match="line 1: this is not valid Python"):
        parse_sheet('EXERCISE = = "x"\nSEED = 5\n')


# -- files are data (issue 11, item 7) ----------------------------------------------------


def test_a_sheet_that_links_to_dev_zero_is_refused_before_reading(tmp_path):
    link = tmp_path / "exercise.py"
    link.symlink_to("/dev/zero")
    with pytest.raises(SheetError, match="a device, not a regular file"):
        read_sheet(link)


def test_a_fifo_is_refused_without_waiting_for_a_writer(tmp_path):
    import os

    fifo = tmp_path / "exercise.py"
    os.mkfifo(fifo)
    with pytest.raises(SheetError, match="FIFO"):
        read_sheet(fifo)
