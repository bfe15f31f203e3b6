"""The hand-written verdict table tests/fixtures/grading.jsonl, one case per line.

Each line is a `dynagrade compare` record plus the verdict worked out by hand:
`want` (correct or not), optional `score` (default 1 when right, 0 when wrong),
`mis` (the misconception the feedback must name) and `error` (the answer is unreadable).
Symbolic cases name a variable set from PRESETS instead of spelling out domains.
"""

import json
from pathlib import Path

import pytest

from dynagrade.grading import grade
from dynagrade.grading.dispatch import accepts
from dynagrade.grading.compare import build, compare_record

FIXTURES = Path(__file__).parent / "fixtures" / "grading.jsonl"

PRESETS = {
    "proj": {"v0": {"min": 1, "max": 50, "unit": "m/s"}, "alpha": {"min": 0.1, "max": 1.4, "unit": "rad"},
             "g": {"min": 9, "max": 10, "unit": "m/s^2"}},
    "osc": {"k": {"min": 1, "max": 100, "unit": "N/m"}, "m": {"min": 0.1, "max": 10, "unit": "kg"}},
    "kin": {"m": {"min": 0.1, "max": 10, "unit": "kg"}, "v": {"min": 1, "max": 10, "unit": "m/s"},
            "g": {"min": 9, "max": 10, "unit": "m/s^2"}, "h": {"min": 0.1, "max": 10, "unit": "m"}},
    "plain": {"x": {"min": 0.5, "max": 2}, "y": {"min": 0.5, "max": 2}},
    "restit": {"e": {"min": 0.1, "max": 0.9, "unit": "1"}, "v": {"min": 1, "max": 10, "unit": "m/s"}},
}


def _cases():
    cases = []
    for line in FIXTURES.read_text(encoding="utf-8").splitlines():
        if line.strip():
            case = json.loads(line)
            cases.append(pytest.param(case, id=case["why"]))
    return cases


CASES = _cases()


def _record(case: dict) -> dict:
    record = {k: v for k, v in case.items() if k not in ("why", "want", "score", "mis", "error")}
    record["id"] = case["why"]
    if isinstance(record.get("variables"), str):
        record["variables"] = PRESETS[record["variables"]]
    return record


def test_the_table_is_large_and_reasons_are_unique():
    reasons = [c.values[0]["why"] for c in CASES]
    assert len(reasons) >= 300
    assert len(set(reasons)) == len(reasons)


@pytest.mark.parametrize("case", CASES)
def test_verdict_matches_the_hand_worked_table(case):
    spec, expected, answer = build(_record(case))
    verdict = grade(spec, expected, answer)
    assert verdict.correct is case["want"], verdict
    want_score = case.get("score", 1.0 if case["want"] else 0.0)
    assert verdict.score == pytest.approx(want_score), verdict
    if "mis" in case:
        assert verdict.misconception == case["mis"], verdict
    if case.get("error"):
        assert verdict.error, verdict
    else:
        assert verdict.error is None, verdict
    assert verdict.feedback


@pytest.mark.parametrize("case", CASES[::7])
def test_compare_gives_the_same_verdict_as_grade(case):
    out = compare_record(_record(case))
    assert out["id"] == case["why"]
    assert out["correct"] is case["want"]
    assert out["score"] == pytest.approx(case.get("score", 1.0 if case["want"] else 0.0))


@pytest.mark.parametrize("case", CASES)
def test_accepts_decides_as_the_hand_worked_table(case):
    """``accepts``, which skips the feedback where a kind can, is right exactly where the
    table's verdict is."""
    spec, expected, answer = build(_record(case))
    assert accepts(spec, expected, answer) is case["want"]
