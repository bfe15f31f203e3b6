"""The Moodle export's units follow the grader's frequency rule (issue 27, item 4).

A numerical question lists the units Moodle converts, each with a multiplier: how many of
that unit make one of the part's unit (Moodle divides a response by it,
question/type/numerical: ``'m/s' => 1, 'mph' => 2.2369``). Worked by hand: 1 rad/s is
1/(2π) = 0.1591549431 Hz and 60/(2π) = 9.549296586 rpm; 1 Hz is 2π = 6.283185307 rad/s and
60 rpm. Before issue 27 Moodle listed no unit, and the grader read 10.47 Hz as 10.47 rad/s.
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET

import pytest

from dynagrade.generation.pool import pool_categories
from dynagrade.grading import NumericSpec, grade
from dynagrade.render.moodle import pool_xml

SECRET = "0123456789abcdef" * 4

SPIN = '''
"""A lone {what}, for the export's unit list."""
import math

from dynagrade.exercise import Choice, Exercise, Numeric

EXERCISE = Exercise(
    id="spin-{name}", title="Spin {name}", source="Section 4.3.1",
    params=(Choice("omega", (10.47, 20.0), unit="rad/s"),),
    statement="The disc turns at omega = {{{{ omega }}}}. Give its {what}.",
    solve=lambda p: {{"x": {value}}},
    parts=(Numeric("x", "{what}", unit="{unit}"),),
)
'''


@pytest.fixture(scope="module")
def questions(tmp_path_factory):
    from dynagrade.exercise.loader import open_bank

    folder = tmp_path_factory.mktemp("spin")
    (folder / "omega.py").write_text(SPIN.format(
        name="omega", what="angular frequency", value="p.omega", unit="rad/s"), encoding="utf-8")
    (folder / "frequency.py").write_text(SPIN.format(
        name="frequency", what="frequency", value="p.omega / (2 * math.pi)", unit="Hz"),
        encoding="utf-8")
    bank = open_bank([folder])
    categories, _ = pool_categories([bank.get("spin-omega"), bank.get("spin-frequency")], 1,
                                    SECRET)
    root = ET.fromstring(pool_xml("P", categories).xml)
    found = {}
    for question in root.findall("question"):
        if question.get("type") == "numerical":
            unit = "rad/s" if "angular" in question.findtext("questiontext/text") else "Hz"
            found[unit] = question
    assert set(found) == {"rad/s", "Hz"}
    return found


def _multipliers(question) -> dict[str, float]:
    return {u.findtext("unit_name"): float(u.findtext("multiplier"))
            for u in question.findall("units/unit")}


def _moodle_value(question, number: float, unit: str) -> float:
    """A response as Moodle reads it: the number divided by its unit's multiplier."""
    return number / _multipliers(question)[unit]


def _moodle_right(question, value: float) -> bool:
    right = question.findall("answer")[0]
    return abs(value - float(right.findtext("text"))) <= float(right.findtext("tolerance"))


def test_a_rad_per_second_part_lists_Hz_and_rpm_with_the_two_pi_multipliers(questions):
    listed = _multipliers(questions["rad/s"])
    assert listed["rad/s"] == 1.0
    assert listed["Hz"] == pytest.approx(0.1591549431, rel=1e-9)      # 1/(2π), not 1
    assert listed["rpm"] == pytest.approx(9.549296586, rel=1e-9)       # 60/(2π)
    assert listed["U/min"] == listed["min^-1"] == listed["rpm"]
    assert questions["rad/s"].findtext("showunits") == "0"             # typed with the number


def test_a_Hz_part_lists_rad_per_second_with_the_mirror_multiplier(questions):
    listed = _multipliers(questions["Hz"])
    assert listed["Hz"] == 1.0 and listed["s^-1"] == 1.0
    assert listed["rad/s"] == pytest.approx(6.283185307, rel=1e-9)     # 2π
    assert listed["rpm"] == pytest.approx(60.0)


def test_moodle_and_the_grader_agree_on_each_frequency_spelling(questions):
    """For ω = 10.47 rad/s: 1.667 Hz and 100 rpm are right in both, 10.47 Hz wrong in both."""
    question = questions["rad/s"]
    omega = float(question.findall("answer")[0].findtext("text"))
    f = omega / (2 * math.pi)
    for number, unit, right in ((f, "Hz", True), (60 * f, "rpm", True), (omega, "Hz", False),
                                (60 * f, "U/min", True), (omega, "rad/s", True)):
        answer = f"{number:.6g} {unit}"
        assert _moodle_right(question, _moodle_value(question, number, unit)) is right, answer
        assert grade(NumericSpec(unit="rad/s"), omega, answer).correct is right, answer


def test_no_unit_name_starts_with_a_digit_that_moodle_would_read_as_part_of_the_number(questions):
    for question in questions.values():
        assert not any(name[:1].isdigit() for name in _multipliers(question))
