"""Delivery policies in exam.toml (exam/policy.py): defaults per mode, located errors,
and what the policy means at a moment (open, verdicts shown, attempt penalty)."""

from __future__ import annotations

import datetime as dt
import json

import pytest

from dynagrade.exam.policy import Policy
from dynagrade.exam.spec import ExamSpecError, read_exam_spec

HEAD = 'id = "p-test"\ntitle = "P"\ndate = 2025-04-14\n'
TAIL = '\n[[exercise]]\nid = "projectile-range"\npoints = 6\n'
ZURICH = dt.timezone(dt.timedelta(hours=2))


def _spec(tmp_path, lines: str):
    path = tmp_path / "exam.toml"
    path.write_text(HEAD + lines + TAIL, encoding="utf-8")
    return read_exam_spec(path)


def test_defaults_follow_the_mode(tmp_path):
    exam = _spec(tmp_path, "").policy
    assert (exam.mode, exam.feedback, exam.counts, exam.attempts, exam.penalty) == \
        ("exam", "after-close", "last", 0, 0.0)
    homework = _spec(tmp_path, 'mode = "homework"\n').policy
    assert (homework.feedback, homework.counts) == ("immediate", "best")


def test_times_and_limits_are_read(tmp_path):
    policy = _spec(tmp_path, 'mode = "homework"\nopens = 2025-04-14T08:00:00+02:00\n'
                             'closes = "2025-04-21T23:59:00+02:00"\nattempts = 3\n'
                             'penalty = 0.1\nfeedback = "after-close"\n').policy
    assert policy.opens == dt.datetime(2025, 4, 14, 8, 0, tzinfo=ZURICH)
    assert policy.closes == dt.datetime(2025, 4, 21, 23, 59, tzinfo=ZURICH)
    assert (policy.attempts, policy.penalty, policy.feedback) == (3, 0.1, "after-close")
    # 06:00 UTC is 08:00 in Zurich: open from that moment on, closed at the close
    assert not policy.is_open(dt.datetime(2025, 4, 14, 5, 59, tzinfo=dt.timezone.utc))
    assert policy.is_open(dt.datetime(2025, 4, 14, 6, 0, tzinfo=dt.timezone.utc))
    assert not policy.is_open(policy.closes)
    assert not policy.shows_verdicts(policy.closes - dt.timedelta(seconds=1))
    assert policy.shows_verdicts(policy.closes)
    # attempt k earns 1 - 0.1 (k - 1) of the points, never less than nothing
    assert [round(policy.attempt_factor(k), 10) for k in (1, 2, 3)] == [1.0, 0.9, 0.8]
    assert Policy(penalty=0.5).attempt_factor(5) == 0.0


def test_the_manifest_carries_the_policy(tmp_path):
    policy = _spec(tmp_path, 'mode = "practice"\ncloses = 2025-05-01T12:00:00Z\n').policy
    stored = json.loads(json.dumps(policy.to_json()))
    assert Policy.from_json(stored) == policy
    assert Policy.from_json(None) == Policy()


@pytest.mark.parametrize("lines, line, field, words", [
    ('mode = "quiz"\n', 4, "mode", "exam, homework, practice"),
    ('feedback = "immediate"\n', 4, "feedback", "homework"),
    ('mode = "homework"\nfeedback = "soon"\n', 5, "feedback", "immediate"),
    ('attempts = -1\n', 4, "attempts", "whole number"),
    ('attempts = 2.5\n', 4, "attempts", "whole number"),
    ('penalty = 1.5\n', 4, "penalty", "between 0 and 1"),
    ('closes = 2025-04-21T23:59:00\n', 4, "closes", "time zone"),
    ('closes = "next friday"\n', 4, "closes", "not a date-time"),
    ('opens = 2025-04-21T10:00:00Z\ncloses = 2025-04-21T09:00:00Z\n', 5, "closes",
     "not after opens"),
    ('counts = "worst"\n', 4, "counts", "best, last"),
])
def test_bad_policies_are_refused_with_file_line_and_field(tmp_path, lines, line, field,
                                                           words):
    with pytest.raises(ExamSpecError) as error:
        _spec(tmp_path, lines)
    message = str(error.value)
    assert f"exam.toml, line {line}, field '{field}'" in message and words in message


def test_dynagrade_exam_writes_the_policy_into_the_manifest(tmp_path):
    from dynagrade.generation.generate import generate_exam
    from dynagrade.exam.manifest import load

    (tmp_path / "roster.csv").write_text("student_id,name\ns1,Ada\n", encoding="utf-8")
    plain = tmp_path / "plain.toml"
    plain.write_text(HEAD + TAIL, encoding="utf-8")
    generate_exam(plain, tmp_path / "roster.csv", tmp_path / "a", pdf=False, jobs=1)
    assert load(tmp_path / "a" / "manifest.json").exam.policy is None  # as before: defaults
    homework = tmp_path / "homework.toml"
    homework.write_text(HEAD + 'mode = "homework"\nattempts = 3\n'
                        'closes = 2025-05-01T12:00:00Z\n' + TAIL, encoding="utf-8")
    generate_exam(homework, tmp_path / "roster.csv", tmp_path / "b", pdf=False, jobs=1)
    stored = Policy.from_json(load(tmp_path / "b" / "manifest.json").exam.policy)
    assert stored == Policy(mode="homework", attempts=3, feedback="immediate", counts="best",
                            closes=dt.datetime(2025, 5, 1, 12, tzinfo=dt.timezone.utc))
