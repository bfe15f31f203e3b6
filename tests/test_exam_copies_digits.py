"""Copy detection to every digit an answer shows (dynagrade.classgrade.shown_digits,
.coinciding_keys, and their use in .copies; issue 32).

Every figure is worked out by hand in the comment above its assertion."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dynagrade.classgrade.answered import Answered
from dynagrade.classgrade.coinciding_keys import changes, identical_key_share, related_variants
from dynagrade.classgrade.copies import Match, chained_chance, copies_csv, detect
from dynagrade.classgrade.part_dependence import PartDependence
from dynagrade.classgrade.shown_digits import last_digit_halfwidth
from dynagrade.exam.manifest import (ExamEntry, ExerciseEntry, Generator, Manifest, PartEntry,
                                     StudentEntry, VariantEntry)
from dynagrade.exercise.results import Status

SPEED = PartEntry("v", "speed", "numeric", "m/s", 1.0, rtol=0.01)


# -- the digits an answer shows -----------------------------------------------------------

@pytest.mark.parametrize("text, halfwidth", [
    ("12.3468", 0.00005),        # six digits: half a unit of 0.0001
    ("12.3", 0.05),
    ("-12.3", 0.05),             # the sign does not change the width
    ("12,3", 0.05),              # a decimal comma, as the grader reads it
    ("1200", 50.0),              # the trailing zeros of a whole number are not digits
    ("1200.", 0.5),              # with a point they are
    ("1.5e3", 50.0),
    ("0.0040", 0.00005),
    ("0.000", 0.0005),           # a zero with its decimals pins the value too
    ("12.39 m/s", 0.005),
    ("45 km/h", 0.5 / 3.6),      # 1 km/h is 1/3.6 m/s
    ("3.2 pi", 0.05 * math.pi),  # a factor after the number scales its last digit
])
def test_the_halfwidth_is_half_a_unit_of_the_last_digit_shown_in_the_part_s_unit(
        text, halfwidth):
    from dynagrade.classgrade.answer_values import answer_value

    value = answer_value(SPEED, text)
    assert last_digit_halfwidth(SPEED, text, value) == pytest.approx(halfwidth, rel=1e-9)


@pytest.mark.parametrize("text", ["", "pi", "0", "[1, 2]"])
def test_an_answer_that_is_not_one_number_with_a_last_digit_shows_no_digits(text):
    from dynagrade.classgrade.answer_values import answer_value

    assert last_digit_halfwidth(SPEED, text, answer_value(SPEED, text)) is None


# -- related variants and identical keys --------------------------------------------------

def test_one_changed_number_or_two_swapped_are_one_change():
    mine = {"m1": 2.0, "m2": 3.0, "v": 5.0}
    assert changes(mine, mine) == 0
    assert changes(mine, {"m1": 2.0, "m2": 3.0, "v": 6.0}) == 1
    assert changes(mine, {"m1": 3.0, "m2": 2.0, "v": 5.0}) == 1    # m1 and m2 swapped
    assert changes(mine, {"m1": 3.0, "m2": 2.0, "v": 6.0}) == 2
    assert changes(mine, {"m1": 4.0, "m2": 7.0, "v": 6.0}) == 3
    # the same number under another name is no swap: m2 = 2.0 and m1 = 5.0 are two changes
    assert changes(mine, {"m1": 5.0, "m2": 2.0, "v": 5.0}) == 2
    assert related_variants(mine, {"m1": 2.0, "m2": 3.0, "v": 6.0})
    assert not related_variants(mine, {"m1": 3.0, "m2": 2.0, "v": 6.0})


def _manifest(variants: list[tuple[dict, dict]], parts=(SPEED,)) -> Manifest:
    """One exercise ``ex``: student k holds the parameters and keys ``variants[k]``."""
    students = tuple(StudentEntry(f"s{k}", "", "", (VariantEntry("ex", k, params, keys),))
                     for k, (params, keys) in enumerate(variants))
    return Manifest(Generator("test", ""), ExamEntry("t", "T", "2026-01-01", "", 1.0),
                    (ExerciseEntry("ex", "Ex", "", 1.0, {}, "", "", tuple(parts)),), students)


def test_the_identical_key_share_counts_pairs_of_different_variants_smoothed_by_one():
    # s0 and s3 hold one variant (a = 1); s1 (a = 2) has the same key, 10, as they do;
    # s2 (a = 3) has 20. Of the 12 ordered pairs, 2 hold the same variant (s0-s3 both
    # ways), so M = 10; the different variants with the same key are s0-s1, s1-s3, both
    # ways: m = 4, and the share is (4 + 1) / (10 + 1).
    manifest = _manifest([({"a": 1.0}, {"v": 10.0}), ({"a": 2.0}, {"v": 10.0}),
                          ({"a": 3.0}, {"v": 20.0}), ({"a": 1.0}, {"v": 10.0})])
    (exercise,) = manifest.exercises
    assert identical_key_share(manifest, exercise) == {"v": pytest.approx(5 / 11)}


# -- the chance of an agreement to every digit, by hand -----------------------------------

def _far_class(size: int, key: float, params=lambda k: {"x": float(k), "y": k + 0.5}) -> Manifest:
    """``size`` students with different variants: s0's key is 5, s1's is ``key``, the
    others' 100 + k, all far (beyond 10 tolerances) from ``key``."""
    keys = [5.0, key] + [100.0 + k for k in range(2, size)]
    return _manifest([(params(k), {"v": v}) for k, v in enumerate(keys)])


def _wrong(student: str, text: str, exercise: str = "ex", part: str = "v") -> Answered:
    return Answered(student, exercise, part, Status.WRONG, text)


def _handed_in(manifest: Manifest, *wrong: Answered) -> list[Answered]:
    """The ``wrong`` answers, and every other student's part answered right."""
    given = {(r.student_id, r.exercise_id, r.part) for r in wrong}
    return [*wrong, *(Answered(s.student_id, v.exercise, name, Status.CORRECT, f"{key:g}")
                      for s in manifest.students for v in s.variants
                      for name, key in v.answers.items()
                      if (s.student_id, v.exercise, name) not in given)]


def test_an_answer_that_shows_a_key_s_digits_has_the_tolerance_chance_narrowed_by_them():
    # 200 students, every variant different and no two keys equal. s0 answers 20.1, s1's
    # key to every digit shown: h = 0.05, the tolerance tau = 1 % of 20.1 = 0.201. No other
    # key lies within 10 tolerances: p = 1 / (199 * 10); narrowed, p * h / tau =
    # 0.05 / (1990 * 0.201) = 1.2500e-4, above iota = 1 / (200 * 199 + 1).
    manifest = _far_class(200, 20.1)
    (pair,) = detect(manifest, _handed_in(manifest, _wrong("s0", "20.1")), threshold=1e9).pairs
    (match,) = pair.matches
    assert match.every_digit
    assert match.chance == pytest.approx(0.05 / (1990 * 0.201))
    # "20.05" lies within the tolerance of 20.1 but not within its last digit: plain p
    (pair,) = detect(manifest, _handed_in(manifest, _wrong("s0", "20.05")), threshold=1e9).pairs
    assert not pair.matches[0].every_digit
    assert pair.matches[0].chance == pytest.approx(1 / 1990)


def test_one_number_alone_never_makes_a_pair_stand_out():
    # six digits narrow p far below iota = 1 / (n (n - 1) + 1), so the chance is iota and
    # E = n (n - 1) / 2 * iota = 19900 / 39801, about one half: not listed
    manifest = _far_class(200, 20.1234)
    (pair,) = detect(manifest, _handed_in(manifest, _wrong("s0", "20.1234")), threshold=1e9).pairs
    assert pair.matches[0].chance == pytest.approx(1 / 39801)
    assert pair.expected == pytest.approx(19900 / 39801)
    assert detect(manifest, _handed_in(manifest, _wrong("s0", "20.1234"))).pairs == ()


@settings(max_examples=40, deadline=None)
@given(size=st.integers(3, 60), key=st.floats(1.0, 99.0), digits=st.integers(2, 8))
def test_a_pair_that_agrees_on_one_number_is_never_listed(size, key, digits):
    manifest = _far_class(size, key)
    text = f"{key:.{digits}g}"
    assert detect(manifest, _handed_in(manifest, _wrong("s0", text))).pairs == ()


def test_a_classmate_whose_numbers_are_the_student_s_own_with_one_misread_gains_nothing():
    # s1's parameters differ from s0's in y alone: s0 may have misread y and worked out
    # s1's key right, to every digit; the match keeps the tolerance's chance 1 / 1990
    manifest = _far_class(200, 20.1234, params=lambda k: {"x": 1.0 if k < 2 else float(k),
                                                          "y": float(k)})
    (pair,) = detect(manifest, _handed_in(manifest, _wrong("s0", "20.1234")), threshold=1e9).pairs
    assert not pair.matches[0].every_digit
    assert pair.matches[0].chance == pytest.approx(1 / 1990)


def test_a_near_key_counts_only_to_every_digit_and_at_least_as_a_slip_in_its_window():
    # s0's key 20 and s1's 20.3 lie within 3 tolerances (0.609) of each other. "20.31" is
    # within the tolerance of 20.3 but not within its last digit (0.005): no evidence.
    # "20.3" agrees to every digit: h = 0.05, tau = 0.203, and the chance is at least
    # h / (3 tau) = 0.05 / 0.609 = 0.0821, the chance that a slip anywhere within three
    # tolerances lands there.
    keys = [20.0, 20.3] + [100.0 + k for k in range(2, 50)]
    manifest = _manifest([({"x": float(k), "y": k + 0.5}, {"v": v}) for k, v in enumerate(keys)])
    assert detect(manifest, _handed_in(manifest, _wrong("s0", "20.31")), threshold=1e9).pairs == ()
    (pair,) = detect(manifest, _handed_in(manifest, _wrong("s0", "20.3")), threshold=1e9).pairs
    assert pair.matches[0].every_digit
    assert pair.matches[0].chance == pytest.approx(0.05 / (3 * 0.203))


def test_a_wrong_number_two_others_hand_in_too_is_a_common_mistake():
    # s0 hands in 33.3, which s1 handed in too (wrong for s1). With one more student
    # (s2) handing it in, that is what a group of copiers shows: of the 3 wrong answers,
    # 1 other lies within 10 tolerances, the spread is (1 + 1) / ((3 - 1) * 10) = 0.1
    # (above the keys' 1 / 490), narrowed by h / tau = 0.05 / 0.333. With two more (s2,
    # s3) it is a common mistake: the chance is at least 2 / (N - 2) = 2/48 (above the
    # narrowed (2 + 1) / ((4 - 1) * 10) * 0.05 / 0.333 = 0.015).
    manifest = _far_class(50, 20.0)

    def chance(handing_in: int) -> float:
        records = [_wrong(f"s{k}", "33.3") for k in range(2 + handing_in)]
        found = detect(manifest, _handed_in(manifest, *records), threshold=1e9)
        pair = next(p for p in found.pairs if p.students == ("s0", "s1"))
        match = next(m for m in pair.matches if m.student == "s0")
        assert match.against == "answer" and match.every_digit
        return match.chance

    assert chance(1) == pytest.approx(0.1 * 0.05 / 0.333)
    assert chance(2) == pytest.approx(2 / 48)


def test_a_match_names_the_classmates_who_hold_the_other_s_very_variant():
    # s1 and s7 hold the same variant (same parameters and key); s0's answer is their key
    variants = [({"x": float(k), "y": k + 0.5}, {"v": 100.0 + k}) for k in range(10)]
    variants[0] = ({"x": 0.0, "y": 0.5}, {"v": 5.0})
    variants[1] = variants[7] = ({"x": 1.0, "y": 7.5}, {"v": 20.1234})
    manifest = _manifest(variants)
    found = detect(manifest, _handed_in(manifest, _wrong("s0", "20.1234")), threshold=1e9)
    by_pair = {p.students: p.matches[0] for p in found.pairs}
    assert by_pair[("s0", "s1")].same_variant == ("s7",)
    assert by_pair[("s0", "s7")].same_variant == ("s1",)
    rows = copies_csv(found).splitlines()
    assert rows[0].endswith(",every_digit,same_variant_as_other")
    assert any(row.endswith(",yes,s7") for row in rows[1:])


# -- chaining the parts of one exercise ----------------------------------------------------

def _match(part: str, chance: float, every_digit: bool) -> Match:
    return Match("ex", part, "m", "s0", "s1", "key", "1", 1.0, 2.0, "", chance,
                 every_digit=every_digit)


def test_a_part_that_agrees_to_every_digit_is_chained_first():
    # 1000 ordered pairs: 10 agree on a, 100 on b, 3 on both. q(b | a) = (3 + 1) / (10 +
    # 1000/100) = 0.2 and q(a | b) = (3 + 1) / (100 + 1000/10) = 0.02. Part a agrees to
    # every digit (1e-6), b within its tolerance (0.01): a first, P = 1e-6 * max(0.01,
    # 0.2) = 2e-7. (Taking the larger factor first would give 0.01 * max(1e-6, 0.02).)
    counts = PartDependence(1000, {"a": 10, "b": 100}, {("a", "b"): 3, ("b", "a"): 3})
    assert counts.conditional("b", "a") == pytest.approx(0.2)
    assert counts.conditional("a", "b") == pytest.approx(0.02)
    found = [_match("b", 0.01, False), _match("a", 1e-6, True)]
    assert chained_chance(found, counts) == pytest.approx(2e-7)
    # without the digits, the larger factor first, as before
    found = [_match("b", 0.01, False), _match("a", 1e-3, False)]
    assert chained_chance(found, counts) == pytest.approx(0.01 * 0.02)


def test_two_parts_of_different_exercises_that_agree_to_every_digit_list_a_pair():
    # two exercises, each a single part; 200 students with different variants. s0 hands
    # in s1's keys of both to six digits: each part's chance is iota = 1 / 39801 (above
    # p * h / tau), the exercises multiply, and E = 19900 / 39801**2 = 1.26e-5: listed.
    parts = {e: PartEntry("v", "speed", "numeric", "m/s", 1.0, rtol=0.01) for e in "AB"}
    keys = {"A": [5.0, 20.1234] + [100.0 + k for k in range(2, 200)],
            "B": [7.0, 31.4159] + [300.0 + k for k in range(2, 200)]}
    students = tuple(StudentEntry(f"s{k}", "", "", tuple(
        VariantEntry(e, k, {"x": float(k), "y": k + 0.5}, {"v": keys[e][k]}) for e in "AB"))
        for k in range(200))
    manifest = Manifest(Generator("test", ""), ExamEntry("t", "T", "2026-01-01", "", 1.0),
                        tuple(ExerciseEntry(e, e, "", 1.0, {}, "", "", (parts[e],))
                              for e in "AB"), students)
    records = [_wrong("s0", "20.1234", "A"), _wrong("s0", "31.4159", "B")]
    (pair,) = detect(manifest, _handed_in(manifest, *records)).pairs
    assert pair.students == ("s0", "s1")
    assert pair.expected == pytest.approx(19900 / 39801 ** 2)
