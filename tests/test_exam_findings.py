"""Copied answers and mistakes nobody declared, found in a graded class
(dynagrade.classgrade.copies, .discover, .perturbations, .findings; issue 32).

The figures of the issue are measured on a synthetic class of 200 (tests/synthetic_class.py,
made once per session); the chance and the perturbations are checked against hand
calculations on classes of a few students."""

from __future__ import annotations

import csv
import io
import math

import numpy as np
import pytest
from click.testing import CliRunner

from dynagrade.classgrade.answer_values import answer_value, compared, is_near, key_value
from dynagrade.classgrade.answered import Answered, answered_csv, read_answered
from dynagrade.classgrade.copies import COPIES_HEADER, copies_csv, detect
from dynagrade.classgrade.discover import discover, proposal_lines
from dynagrade.classgrade.findings import class_findings
from dynagrade.classgrade.outcome import ClassOutcome
from dynagrade.classgrade.perturbations import space
from dynagrade.classgrade.report import report_html
from dynagrade.exam.csvcells import restored_rows
from dynagrade.exam.manifest import (ExamEntry, ExerciseEntry, Generator, Manifest, PartEntry,
                                     StudentEntry, VariantEntry, dump)
from dynagrade.exercise import Misconception, ParamValues
from dynagrade.exercise.results import Status
from dynagrade.grading import evaluate_expression
from dynagrade.i18n import language

from synthetic_class import exercises, measure, synthetic_class


@pytest.fixture(scope="session")
def measured():
    """The synthetic class of 200 and what the findings got right, made once."""
    synthetic = synthetic_class(200, seed=1)
    findings = class_findings(synthetic.manifest, synthetic.exercises, synthetic.records)
    return synthetic, findings, measure(synthetic, findings)


def test_copied_answers_of_whole_exams_are_found_with_95_percent_recall(measured):
    _, _, figures = measured
    assert figures.copied_answers[0] >= 20
    assert figures.answer_recall(whole=True) >= 0.95


def test_copied_answers_of_whole_exams_and_of_single_exercises_together_are_found_with_95_percent_recall(
        measured):
    _, _, figures = measured
    assert figures.copied_answers[1] >= 10
    found, copied = sum(figures.copied_answers_found), sum(figures.copied_answers)
    assert found / copied >= 0.95


def test_a_misreader_whose_variant_shares_a_key_by_symmetry_is_paired_with_nobody():
    # In the class of seed 15, misreader s136 (v0 = 9, alpha = 22) misread v0 as 8 and
    # handed in the keys of (8, 22). The range v0^2 sin(2 alpha) / g is the same at 22 and
    # 68 degrees, and s159 holds (8, 68): s136's x_max is s159's key to every digit. That
    # alone once listed the pair; now the class's identical keys of different variants
    # bound the chance, and nobody is paired with an honest student.
    synthetic = synthetic_class(200, seed=15)
    keys = {s.student_id: s.variant("projectile-range") for s in synthetic.manifest.students}
    assert "s136" in synthetic.misreaders
    assert (keys["s136"].params["alpha"], keys["s159"].params["alpha"]) == (22.0, 68.0)
    answer = next(r.answer for r in synthetic.records
                  if (r.student_id, r.exercise_id, r.part) == ("s136", "projectile-range", "x_max"))
    assert float(answer) == pytest.approx(keys["s159"].answers["x_max"], abs=5e-5)
    findings = class_findings(synthetic.manifest, synthetic.exercises, synthetic.records)
    assert not [p.students for p in findings.copies.pairs
                if not set(p.students) & synthetic.copying]


def test_no_pair_of_two_honest_students_is_listed(measured):
    _, findings, figures = measured
    assert findings.copies.pairs, "the class has copiers: some pair must be listed"
    assert figures.false_pairs == 0


def test_planted_mistakes_are_recovered_as_their_perturbation_in_90_percent_of_clusters(
        measured):
    _, _, figures = measured
    assert figures.clusters >= 5
    assert figures.recovery >= 0.9


def test_listed_pairs_that_share_a_student_form_one_cluster(measured):
    synthetic, findings, _ = measured
    trios = [g for g in synthetic.groups if len(g) == 3]
    found = {frozenset(c) for c in findings.copies.clusters}
    assert any(frozenset(trio) in found for trio in trios)


def test_attaching_the_findings_changes_no_grade_and_no_feedback(measured):
    from copy import deepcopy

    from dynagrade.classgrade.grade import class_outcome, with_findings

    synthetic, _, _ = measured
    outcome = class_outcome(synthetic.manifest, deepcopy(synthetic.results), [], {})
    rows, feedback = deepcopy(outcome.rows), deepcopy(outcome.feedback)
    with_findings(outcome, synthetic.manifest, synthetic.exercises)
    assert outcome.findings is not None and outcome.findings.copies.pairs
    assert outcome.rows == rows and outcome.feedback == feedback


# -- the chance of a match, by hand -------------------------------------------------------

def _class(keys: list, kind: str = "numeric") -> Manifest:
    """A one-part exam: student k has ``keys[k]`` as the reference (tolerance 1 %)."""
    part = PartEntry("v", "speed", kind, "m/s", 1.0, rtol=0.01,
                     size=2 if kind == "vector" else None)
    students = tuple(StudentEntry(f"s{k}", "", "", (VariantEntry("ex", k, {}, {"v": key}),))
                     for k, key in enumerate(keys))
    return Manifest(Generator("test", ""), ExamEntry("t", "T", "2026-01-01", "", 1.0),
                    (ExerciseEntry("ex", "Ex", "", 1.0, {}, "", "", (part,)),), students)


def _answers(*answers: str | None, misconception: str | None = None) -> list[Answered]:
    return [Answered(f"s{k}", "ex", "v", Status.WRONG if k == 0 else Status.CORRECT, text,
                     misconception if k == 0 else None) for k, text in enumerate(answers)]


def test_a_match_s_chance_is_the_share_of_other_keys_within_ten_tolerances_smoothed_by_one():
    # s0 answers 20 (wrong for its key 10): the key of s1 within 1 %. Of the others (s2,
    # s3, s4: keys 21, 40, 50) only 21 lies within 10 tolerances (2.1) of 20: c = 1, so
    # p = (1 + 1) / ((5 - 1) * 10) = 0.05, and a class of 5 has 10 pairs: E = 0.5.
    manifest = _class([10.0, 20.0, 21.0, 40.0, 50.0])
    found = detect(manifest, _answers("20", "20", "21", "40", "50"), threshold=1.0)
    (pair,) = found.pairs
    assert pair.students == ("s0", "s1")
    (match,) = pair.matches
    assert (match.student, match.other, match.against) == ("s0", "s1", "key")
    assert match.chance == pytest.approx(0.05)
    assert pair.expected == pytest.approx(0.5)
    assert pair.score == pytest.approx(-math.log10(0.5))


def test_a_single_matching_part_is_not_listed_at_the_documented_threshold():
    manifest = _class([10.0, 20.0, 21.0, 40.0, 50.0])
    assert detect(manifest, _answers("20", "20", "21", "40", "50")).pairs == ()


def test_an_answer_near_the_key_of_a_twin_variant_is_no_evidence():
    # keys 10 and 10.2 lie within 3 tolerances (0.306) of each other: s0's 10.2 is a slip
    manifest = _class([10.0, 10.2, 40.0])
    assert detect(manifest, _answers("10.2", "10.2", "40"), threshold=1e9).pairs == ()


def test_an_answer_the_grader_explains_by_a_mistake_on_its_own_numbers_is_no_evidence():
    manifest = _class([10.0, 20.0, 40.0])
    records = _answers("20", "20", "40", misconception="factor 2")
    assert detect(manifest, records, threshold=1e9).pairs == ()


def test_a_wrong_answer_equal_to_another_wrong_answer_matches_it():
    manifest = _class([10.0, 20.0, 40.0, 80.0])
    records = _answers("33.3", "33.3", "40", "80")
    records[1] = Answered("s1", "ex", "v", Status.WRONG, "33.3")
    found = detect(manifest, records, threshold=1e9)
    assert {m.against for p in found.pairs for m in p.matches} == {"answer"}


def test_a_vector_matches_only_when_every_component_lies_within_its_tolerance():
    manifest = _class([(1.0, 2.0), (3.0, 4.0), (5.0, 9.0)], kind="vector")
    hit = detect(manifest, _answers("[3, 4]", "[3, 4]", "[5, 9]"), threshold=1e9)
    miss = detect(manifest, _answers("[3, 4.5]", "[3, 4]", "[5, 9]"), threshold=1e9)
    assert [p.students for p in hit.pairs] == [("s0", "s1")] and miss.pairs == ()


def _two_part_class(keys: list[tuple[float, float]], answers: tuple[float, float]
                    ) -> tuple[Manifest, list[Answered]]:
    """A two-part exercise (parts ``h`` and ``t``, tolerance 1 %): student k has
    ``keys[k]``; s0 hands in ``answers`` (wrong for it), every other student its keys."""
    parts = tuple(PartEntry(name, name, "numeric", "m", 1.0, rtol=0.01) for name in "ht")
    students = tuple(StudentEntry(f"s{k}", "", "", (VariantEntry(
        "ex", k, {}, {"h": h, "t": t}),)) for k, (h, t) in enumerate(keys))
    manifest = Manifest(Generator("test", ""), ExamEntry("t", "T", "2026-01-01", "", 1.0),
                        (ExerciseEntry("ex", "Ex", "", 1.0, {}, "", "", parts),), students)
    records = [Answered(f"s{k}", "ex", name, Status.WRONG if k == 0 else Status.CORRECT,
                        f"{(answers if k == 0 else key)[i]:g}")
               for k, key in enumerate(keys) for i, name in enumerate("ht")]
    return manifest, records


def test_a_part_whose_keys_agree_whenever_another_part_s_do_adds_only_that_agreement():
    # t = 2 h for every student, and s1, s2 (and s3, s4) hold the same variant. s0 hands
    # in s1's keys (20, 40). Each part: of the others (s2..s5) only s2's key lies within
    # 10 tolerances, c = 1, p = (1 + 1) / ((6 - 1) * 10) = 0.04. Of the 30 ordered pairs of
    # students, 4 agree on h (s1-s2, s3-s4, both ways), the same 4 on t: pi_t = 4/30 and
    # q(t | h) = (4 + 1) / (4 + 30/4) = 10/23. P = 0.04 * 10/23 and E = 15 P = 6/23
    # (0.26: not listed), where the product of the parts, 15 * 0.04**2 = 0.024, would be.
    keys = [(10.0, 20.0), (20.0, 40.0), (20.0, 40.0), (50.0, 100.0), (50.0, 100.0),
            (80.0, 160.0)]
    manifest, records = _two_part_class(keys, (20.0, 40.0))
    assert detect(manifest, records).pairs == ()
    found = {p.students: p for p in detect(manifest, records, threshold=1.0).pairs}
    pair = found[("s0", "s1")]
    assert [m.chance for m in pair.matches] == [pytest.approx(0.04)] * 2
    assert pair.expected == pytest.approx(6 / 23)


def test_parts_whose_keys_agree_no_more_often_together_than_apart_multiply():
    # 25 students: student k has h = 10 * 1.5**(k // 5) and t = 10 * 1.5**(k % 5), so
    # pairs agree on h within a row of five, on t within a column, never on both: of the
    # 600 ordered pairs 100 agree on h, 100 on t, 0 on both, and q(t | h) = (0 + 1) /
    # (100 + 600/100) = 1/106. s0 hands in s6's keys (15, 15): on each part 4 other keys
    # lie within 10 tolerances, p = (4 + 1) / (24 * 10) = 1/48 > 1/106, so the parts
    # multiply: P = 1/48**2 and E = 300 / 2304.
    keys = [(10 * 1.5 ** (k // 5), 10 * 1.5 ** (k % 5)) for k in range(25)]
    manifest, records = _two_part_class(keys, (15.0, 15.0))
    found = {p.students: p for p in detect(manifest, records, threshold=1.0).pairs}
    pair = found[("s0", "s6")]
    assert [m.chance for m in pair.matches] == [pytest.approx(1 / 48)] * 2
    assert pair.expected == pytest.approx(300 / 48 ** 2)


def test_an_honest_student_who_misreads_a_parameter_is_paired_with_nobody(measured):
    # A misread value carried through every part gives a neighbouring variant's keys; in
    # the class of seed 1 a misreader's answers lie within tolerance of a classmate's
    # keys on two parts or more of one exercise (checked here, so that the test cannot
    # pass for want of such a student), and no pair of theirs with an honest student is
    # listed.
    synthetic, findings, _ = measured
    by_key = {(r.student_id, r.exercise_id, r.part): r for r in synthetic.records}
    keys = {(s.student_id, v.exercise): v.answers for s in synthetic.manifest.students
            for v in s.variants}
    entries = {(d.id, e.name): e for d in synthetic.manifest.exercises for e in d.parts
               if compared(e)}

    def on_keys(student: str, other: str) -> int:
        return max(sum(1 for (e, part), entry in entries.items() if e == exercise
                       and by_key[(student, e, part)].wrong
                       and is_near(entry, answer_value(entry, by_key[(student, e, part)].answer),
                                   key_value(entry, keys[(other, e)][part])))
                   for exercise in {e for e, _ in entries})

    students = [s.student_id for s in synthetic.manifest.students]
    assert any(on_keys(m, t) >= 2 for m in synthetic.misreaders for t in students if t != m)
    assert not [p.students for p in findings.copies.pairs
                if set(p.students) & set(synthetic.misreaders)
                and not set(p.students) & synthetic.copying]


def test_copies_csv_has_one_inert_row_per_matching_part_with_both_keys_and_answers():
    manifest = _class([10.0, -20.0, 21.0, 40.0, 50.0])
    found = detect(manifest, _answers("-20 m/s", "-20", "21", "40", "50"), threshold=1.0)
    text = copies_csv(found)
    assert "'-20 m/s" in text  # a cell starting with "-" and not a plain number is escaped
    rows = restored_rows(csv.reader(io.StringIO(text)))
    assert tuple(rows[0]) == COPIES_HEADER and len(rows) == 2
    row = dict(zip(rows[0], rows[1]))
    assert (row["answer"], row["own_key"], row["other_key"], row["matches"]) == (
        "-20 m/s", "10", "-20", "key of s1")


# -- the perturbations, by hand -----------------------------------------------------------

def _g10_class(count: int = 4):
    """projectile-range with ``count`` students who all used g = 10 for x_max."""
    bank = exercises()
    projectile = bank["projectile-range"]
    synthetic = synthetic_class(count + 2, seed=5, groups=0, cluster_size=(0, 0), noise=0.0)
    records = []
    for student in synthetic.manifest.students:
        params = student.variant("projectile-range").params
        v0, alpha = params["v0"], math.radians(params["alpha"])
        # the range with g = 10, v0^2 sin(2 alpha) / g (eq. 1.80)
        wrong = v0 ** 2 * math.sin(2 * alpha) / 10.0
        status = Status.WRONG if len(records) < count else Status.CORRECT
        records.append(Answered(student.student_id, "projectile-range", "x_max", status,
                                f"{wrong:.6g}"))
    return synthetic.manifest, {"projectile-range": projectile}, records


def test_discovery_names_g_equal_10_from_answers_worked_out_by_hand():
    manifest, bank, records = _g10_class()
    (proposal,) = discover(manifest, bank, records)
    assert (proposal.part, proposal.name, proposal.support) == ("x_max", "g = 10", 4)
    assert proposal.variants == 4 and proposal.family == "g = 10 or 9.8"


def test_the_proposed_misconception_pasted_into_an_exercise_gives_the_hand_value():
    manifest, bank, records = _g10_class()
    (proposal,) = discover(manifest, bank, records)
    projectile = bank["projectile-range"]
    namespace = {"Misconception": Misconception, "ParamValues": ParamValues, "math": math,
                 "solve": projectile.solve, "evaluate_expression": evaluate_expression}
    # the snippet is dynagrade's own text (never a student's), run as an exercise file would
    misconception = eval(proposal.snippet.split("\n#")[0].rstrip(","), namespace)
    p = projectile.si({"v0": 20.0, "alpha": 30.0, "g": 9.81})
    assert misconception.name == "g = 10"
    assert misconception.wrong_value(p) == pytest.approx(400 * math.sin(math.radians(60)) / 10)


def test_too_few_students_make_no_proposal():
    manifest, bank, records = _g10_class(count=2)
    assert discover(manifest, bank, records) == []


def test_the_formula_route_drops_a_term_and_removes_a_square_as_worked_out_by_hand():
    cart = exercises()["two-cart-collision"]
    by_name = {p.name: p for p in space(cart, cart.part("dT"))}
    p = ParamValues({"m1": 2.0, "m2": 3.0, "v1": 4.0, "v2": -1.0, "e": 0.5})
    # dT = m1 m2 (1 - e^2)(v1 - v2)^2 / (2 (m1 + m2)); here m1 m2/(2(m1+m2)) = 0.6
    assert by_name["square of v1 - v2 missing"].value(p) == pytest.approx(0.6 * 0.75 * 5)
    assert by_name["term -v2 of v1 - v2 dropped"].value(p) == pytest.approx(0.6 * 0.75 * 16)
    assert by_name["term 1 of 1 - e^2 dropped"].value(p) == pytest.approx(-0.6 * 0.25 * 25)
    assert by_name["m1 and m2 swapped"].value(p) == pytest.approx(0.6 * 0.75 * 25)


def test_the_solver_route_takes_an_angle_in_degrees_as_radians_and_swaps_sin_and_cos():
    projectile = exercises()["projectile-range"]
    by_name = {p.name: p for p in space(projectile, projectile.part("h_max"))}
    p = projectile.si({"v0": 10.0, "alpha": 30.0, "g": 9.81})
    # h = v0^2 sin^2(alpha) / (2 g), eq. (1.82)
    assert by_name["alpha in degrees taken as radians"].value(p) == pytest.approx(
        100 * math.sin(30.0) ** 2 / (2 * 9.81))
    assert by_name["sin and cos of alpha swapped"].value(p) == pytest.approx(
        100 * math.cos(math.radians(30)) ** 2 / (2 * 9.81))
    assert by_name["g = 9.8"].value(p) == pytest.approx(100 * 0.25 / 19.6)


def test_a_perturbation_outside_its_domain_gives_no_value():
    projectile = exercises()["projectile-range"]
    by_name = {p.name: p for p in space(projectile, projectile.part("x_max"))}
    p = projectile.si({"v0": 10.0, "alpha": 30.0, "g": 9.81})
    negative = ParamValues({**p, "alpha": -p.alpha})  # a negative range: no real root
    assert by_name["square root of the result (a missing square)"].value(negative) is None


# -- outputs ------------------------------------------------------------------------------

def test_answers_csv_reads_back_the_records_it_was_written_from(tmp_path):
    records = [Answered("s1", "ex", "v", Status.WRONG, "=1+1", "sign", "2026-01-01T10:00:00"),
               Answered("s2", "ex", "v", Status.NOT_ANSWERED, None)]
    (tmp_path / "answers.csv").write_text(answered_csv(records), encoding="utf-8")
    assert read_answered(tmp_path / "answers.csv") == records


def test_dynagrade_discover_prints_the_proposal_and_the_misconception_to_paste(tmp_path):
    manifest, _, records = _g10_class()
    dump(manifest, tmp_path / "manifest.json")
    (tmp_path / "graded").mkdir()
    (tmp_path / "graded" / "answers.csv").write_text(answered_csv(records), encoding="utf-8")
    from dynagrade.cli import main

    result = CliRunner().invoke(main, ["discover", str(tmp_path / "manifest.json"),
                                       str(tmp_path / "graded")])
    assert result.exit_code == 0, result.output
    assert "projectile-range, part x_max: g = 10 explains 4 of 4" in result.output
    assert 'Misconception("g = 10",' in result.output
    assert "no grade changes" in result.output


def test_dynagrade_discover_without_answers_csv_says_what_to_do(tmp_path):
    manifest, _, _ = _g10_class()
    dump(manifest, tmp_path / "manifest.json")
    from dynagrade.cli import main

    result = CliRunner().invoke(main, ["discover", str(tmp_path / "manifest.json"),
                                       str(tmp_path)])
    assert result.exit_code == 1 and "answers.csv is missing" in result.output


def test_the_report_shows_both_sections_and_says_the_list_never_changes_a_grade(measured):
    synthetic, findings, _ = measured
    outcome = ClassOutcome("Synthetic", [], [], [], findings=findings)
    html = report_html(synthetic.manifest.exam, outcome)
    assert "<h2>Mistakes nobody declared</h2>" in html
    assert "<h2>Answers that match another student&#39;s numbers</h2>" in html or \
        "<h2>Answers that match another student's numbers</h2>" in html
    assert "never changes a grade" in html
    first = findings.copies.pairs[0]
    assert " and ".join(first.students) in html
    digit_match = next(m for p in findings.copies.pairs for m in p.matches if m.every_digit)
    assert f"{digit_match.against} of {digit_match.other}, to every digit" in html
    assert 'Misconception(&#34;g = 10&#34;' in html or 'Misconception("g = 10"' in html


def test_the_findings_notes_speak_german_in_a_german_context():
    with language("de"):
        lines = proposal_lines([])
    assert lines[0].startswith("Kein Fehler") and "Keine Note" in lines[-1]


def test_close_to_is_the_grader_s_tolerance_rule():
    from dynagrade.classgrade.answer_values import close_to

    entry = PartEntry("v", "v", "numeric", None, 1.0, rtol=0.01)
    near = close_to(entry, 10.1, np.array([[10.0], [9.9], [10.3]]))
    assert near.tolist() == [True, False, False]  # 10.1 - 9.9 = 0.2 > 0.099
