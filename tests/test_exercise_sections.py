"""Coverage per section of the notes (``dynagrade list --by-section``): which section an
exercise's source names, and the counts the command prints."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
from click.testing import CliRunner

from dynagrade.cli import main
from dynagrade.exercise import open_bank
from dynagrade.exercise.sections import ENOUGH, SECTIONS, coverage, section_of

README = Path(__file__).resolve().parents[1] / "README.md"


def _issue_sections() -> list[str]:
    """The 41 sections as issue 31 lists them, its ranges written out."""
    ranges = [("1.1", 1, 4), ("1.2", 1, 4), ("2.1",), ("2.2", 1, 3), ("2.3", 1, 2), ("3.1",),
              ("3.2", 1, 5), ("3.3",), ("3.4", 1, 4), ("3.5", 1, 2), ("4.1",), ("4.2",),
              ("4.3", 1, 3), ("4.4", 1, 4), ("5.1",), ("5.2",), ("5.3", 1, 3)]
    return [name for r in ranges for name in (
        [f"{r[0]}.{k}" for k in range(r[1], r[2] + 1)] if len(r) == 3 else [r[0]])]

def test_the_sections_are_the_41_the_issue_lists_in_the_notes_order():
    assert [number for number, _ in SECTIONS] == _issue_sections()
    assert len(SECTIONS) == 41


@pytest.mark.parametrize("source, section", [
    # read in the notes by hand: each example's heading stands between these headings
    ("Example 1.2", "1.1.1"),    # line 373, after 1.1.1 (229), before 1.1.2 (485)
    ("Example 1.4", "1.1.2"),    # line 495, after 1.1.2 (485), before 1.1.3 (535)
    ("Example 1.6", "1.1.4"),    # line 881, after 1.1.4 (701), before 1.1.5 (907)
    ("Example 1.10", "1.2.1"),   # line 1205, after 1.2.1 (957), before 1.2.2 (1227)
    ("Example 1.15", "1.2.2"),   # line 1879, before 1.2.3 (1925)
    ("Example 1.16", "1.2.3"),   # line 2111, after 1.2.3 (1925)
    # sections: a leaf itself, or the leaf that holds a finer one
    ("Section 3.2.3", "3.2.3"),
    ("Section 3.1.1", "3.1"),
    ("Section 4.2", "4.2"),
    ("Section 2.3.1 (ballistic pendulum)", "2.3.1"),
])
def test_a_source_counts_under_the_section_that_holds_it(source, section):
    assert section_of(source) == section


@pytest.mark.parametrize("source", ["Example 1.20", "Example 2.3", "Section 1.1.5",
                                    "Section 6.1", "Lecture 3", ""])
def test_a_source_that_names_no_leaf_section_counts_nowhere(source):
    assert section_of(source) is None


def test_every_exercise_of_the_bank_counts_under_one_of_the_41_sections():
    listing = open_bank().listing()
    assert listing
    sections, unplaced = coverage(listing)
    assert unplaced == []
    assert sum(len(c.exercises) for c in sections) == len(listing)


class _Listed:
    def __init__(self, id, source):
        self.id, self.source = id, source


def test_coverage_counts_each_exercise_once_and_marks_the_thin_sections():
    sections, unplaced = coverage([
        _Listed("a", "Example 1.9"), _Listed("b", "Section 1.2.1"),
        _Listed("c", "Example 1.7"), _Listed("d", "Section 3.1.2"), _Listed("e", "Notes")])
    by_number = {c.section: c for c in sections}
    assert by_number["1.2.1"].exercises == ("a", "b", "c") and by_number["1.2.1"].enough
    assert by_number["3.1"].exercises == ("d",) and not by_number["3.1"].enough
    assert unplaced == ["e"]
    assert ENOUGH == 3


def test_list_by_section_prints_every_section_and_names_those_with_fewer_than_three():
    result = CliRunner().invoke(main, ["list", "--by-section"])
    assert result.exit_code == 0, result.output
    sections, _ = coverage(open_bank().listing())
    rows = {line.split()[0]: line for line in result.output.splitlines()
            if re.match(r"\d\.\d", line)}
    assert set(rows) == {number for number, _ in SECTIONS}
    for count in sections:
        assert re.search(rf"\s{len(count.exercises)}(\s|$)", rows[count.section])
        assert ("fewer than 3" in rows[count.section]) == (len(count.exercises) < 3)
    few = [c.section for c in sections if not c.enough]
    assert f"{41 - len(few)} of 41 sections have 3 exercises or more" in result.output


def test_list_by_section_as_json_counts_what_list_lists():
    runner = CliRunner()
    data = json.loads(runner.invoke(main, ["list", "--by-section", "--json"]).output)
    listed = json.loads(runner.invoke(main, ["list", "--json"]).output)
    assert [s["section"] for s in data["sections"]] == _issue_sections()
    assert sum(s["count"] for s in data["sections"]) == len(listed)
    assert sorted(i for s in data["sections"] for i in s["exercises"]) == \
        sorted(e["id"] for e in listed)
    assert all(s["enough"] == (s["count"] >= 3) for s in data["sections"])
    assert data["unplaced"] == [] and data["enough"] == 3


def test_a_course_folder_exercise_counts_under_its_section(tmp_path):
    # a copy of a chapter-1 exercise whose source names Section 3.3 adds one there
    bank = open_bank()
    source = Path(bank.get("degrees-of-freedom").path).read_text(encoding="utf-8")
    (tmp_path / "mine.py").write_text(
        source.replace('id="degrees-of-freedom"', 'id="mine"')
        .replace('source="Example 1.4"', 'source="Section 3.3"'), encoding="utf-8")
    runner = CliRunner()
    before = json.loads(runner.invoke(main, ["list", "--by-section", "--json"]).output)
    after = json.loads(runner.invoke(main, ["--exercises", str(tmp_path), "list",
                                            "--by-section", "--json"]).output)
    count = {s["section"]: s["count"] for s in before["sections"]}
    assert {s["section"]: s["count"] for s in after["sections"]} == {**count, "3.3": count["3.3"] + 1}


def test_the_readme_states_no_bank_size_that_list_does_not_print():
    # the README says where to read the bank's size; a number it states must be true
    text = README.read_text(encoding="utf-8")
    assert "dynagrade list --by-section" in text
    size = len(open_bank().listing())
    for number in re.findall(r"(\d+) exercises\b", text):
        assert int(number) == size, f"README says {number} exercises; the bank has {size}"


def test_the_shipped_bank_has_at_least_three_exercises_for_each_of_the_41_sections():
    sections, unplaced = coverage(open_bank().listing())
    assert len(sections) == 41 and unplaced == []
    assert {c.section: len(c.exercises) for c in sections if len(c.exercises) < 3} == {}
