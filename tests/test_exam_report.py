"""The class report: a caution wherever a statistic rests on fewer than 30 students, and
wrong answers grouped by the mistake the grader named, with the unexplained share per
part; counts worked out by hand for a hand-built class."""

from __future__ import annotations

import html
import re

from dynagrade.classgrade.outcome import ClassOutcome
from dynagrade.classgrade.gradebook import GradebookRow, RowStatus
from dynagrade.classgrade.report import report_html
from dynagrade.classgrade.stats import (DECLARED, FOLLOW_THROUGH, FOLLOWED, MIN_STUDENTS, SLIP,
                                        Explanation, StudentParts, declared_names,
                                        part_statistics)
from dynagrade.exam.manifest import ExamEntry, PartEntry
from dynagrade.exercise.results import GradedPart, Status
from dynagrade.exercise.scoring import grade_variant
from dynagrade.grading import grade
from dynagrade.grading.spec import NumericSpec, VectorSpec

PART = PartEntry("x", "distance", "numeric", "m", 2.0, rtol=0.01, atol=None)


def _entry(status, answer, misconception=None, fraction=None):
    if fraction is None:
        fraction = {"correct": 1.0, "partial": 0.5, "follow-through": 0.5}.get(status, 0.0)
    return GradedPart("x", "distance", Status(status), fraction * PART.points, PART.points,
                      answer, "", misconception)


#: eight students handed the exercise in: one right, two sign slips (different numbers:
#: their variants differ), a declared misconception with partial credit, a follow-through,
#: two wrong answers nothing explains, one blank part
HAND_BUILT = [
    _entry("correct", "4.2 m"),
    _entry("wrong", "-4.2", "sign"),
    _entry("wrong", "-7.9", "sign"),
    _entry("partial", "3.1", "friction forgotten"),
    _entry("follow-through", "5.5"),
    _entry("wrong", "12"),
    _entry("wrong", "0.3"),
    _entry("not answered", None),
]


def _class(entries, total=10.0):
    return [StudentParts(total + i, {("e", "x"): entry}) for i, entry in enumerate(entries)]


def test_wrong_answers_are_grouped_by_what_explains_them_not_by_value():
    (stats,) = part_statistics([("e", PART)], _class(HAND_BUILT),
                               declared={("e", "x"): {"friction forgotten"}})
    # six answered wrongly (the blank part is not a wrong answer): 2 sign, 1 declared,
    # 1 follow-through, 2 unexplained
    assert stats.answered == 8 and stats.wrong == 6
    assert stats.explained == [Explanation("sign", SLIP, 2),
                               Explanation("follow-through from an earlier wrong answer",
                                           FOLLOWED, 1),
                               Explanation("friction forgotten", DECLARED, 1)]
    assert stats.unexplained == 2
    assert stats.unexplained_share == 2 / 6


def test_a_name_the_exercise_does_not_declare_is_a_slip_and_none_wrong_has_no_share():
    (stats,) = part_statistics([("e", PART)], _class([_entry("partial", "3.1", "friction forgotten"),
                                                      _entry("correct", "4.2")]))
    assert stats.explained == [Explanation("friction forgotten", SLIP, 1)]
    (right,) = part_statistics([("e", PART)], _class([_entry("correct", "4.2")] * 3))
    assert right.wrong == 0 and right.unexplained_share is None and right.explained == []


def test_a_statistic_is_flagged_below_30_students_and_not_from_30_on():
    for students, few in ((MIN_STUDENTS - 1, True), (MIN_STUDENTS, False)):
        (stats,) = part_statistics([("e", PART)], _class([_entry("correct", "4.2")] * students))
        assert stats.answered == students and stats.few_students is few


def test_the_grader_names_a_unit_of_the_wrong_dimension_so_the_report_can_count_it():
    assert grade(NumericSpec(unit="m"), 4.2, "4.2 s").misconception == "unit"
    assert grade(VectorSpec(unit="m", size=2), [1.0, 2.0], "(1, 2) kg").misconception == "unit"
    # a right number in a convertible unit stays right, with no name
    assert grade(NumericSpec(unit="m"), 4.2, "420 cm").misconception is None


def test_the_verdicts_of_a_real_exercise_feed_the_groups(bank):
    exercise = bank.get("block-sliding-down-incline")
    part = exercise.part("a")
    entries = []
    for seed, mistake in enumerate(["friction forgotten", "sign", "right", "unexplained"]):
        variant = exercise.variant(seed)
        expected = variant.answers["a"]
        params = exercise.si(variant.params)
        if mistake == "friction forgotten":
            answer = part.misconception_answer(part.misconceptions[1], params)
        else:
            answer = {"sign": f"{-expected}", "right": f"{expected}",
                      "unexplained": f"{expected * 1.37}"}[mistake]
        (result,) = [p for p in grade_variant(exercise, variant, {"a": answer}).parts
                     if p.name == "a"]
        entries.append(_entry(result.status, result.answer, result.misconception,
                              result.fraction))
    a = PartEntry("a", "acceleration", "numeric", "m/s^2", 2.0, rtol=0.01, atol=None)
    (stats,) = part_statistics([("block-sliding-down-incline", a)], [
        StudentParts(5.0 + i, {("block-sliding-down-incline", "a"): e})
        for i, e in enumerate(entries)],
        declared=declared_names({"block-sliding-down-incline": exercise}))
    assert stats.wrong == 3 and stats.unexplained == 1
    assert sorted((e.name, e.kind, e.students) for e in stats.explained) == [
        ("friction forgotten", DECLARED, 1), ("sign", SLIP, 1)]


def _report(entries, declared=None):
    stats = part_statistics([("e", PART)], _class(entries), declared=declared)
    rows = [GradebookRow(f"s{i}", "", "", {"e": 1.0}, 1.0, 2.0, RowStatus.GRADED)
            for i in range(len(entries))]
    outcome = ClassOutcome("Midterm", ["e"], rows, [], stats)
    exam = ExamEntry(id="midterm", title="Midterm", date="2025-04-14", instructions="",
                     points=2.0)
    page = report_html(exam, outcome)
    return page, " ".join(html.unescape(re.sub(r"<[^>]+>", " ", page)).split())


def test_the_report_cautions_a_small_class_and_shows_the_groups_with_their_shares():
    page, text = _report(HAND_BUILT, {("e", "x"): {"friction forgotten"}})
    assert "Caution: the statistics of every part rest on fewer than 30 students (the " \
           "fewest: 8)" in text
    assert "8 students: fewer than 30, a hint only" in text
    # the unexplained share per part: 8 answered, 6 wrong, 4 explained, 2 unexplained, 33 %
    assert "x distance 8 6 4 2 33 %" in text
    # the groups, each with its share of the six wrong answers
    assert "sign slip 2 33 %" in text
    assert f"{FOLLOW_THROUGH} follow-through 1 17 %" in text
    assert "friction forgotten the exercise's misconception 1 17 %" in text
    assert "unexplained none of these 2 33 %" in text
    # raw values are not a grouping of their own
    assert "-7.9" not in text and "12 1" not in text


def test_a_class_of_30_gets_no_caution():
    page, text = _report([_entry("correct", "4.2")] * 29 + [_entry("wrong", "1", "sign")])
    assert "Caution" not in text and "a hint only" not in text
    assert "30 students" in text
