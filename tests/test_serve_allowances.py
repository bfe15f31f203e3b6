"""Exceptions to the policy per student (serve/allowances.py, routes/exceptions.py):
the rules worked out by hand, then the API and the staff page on SQLite and on a real
PostgreSQL: an extension lets one student (and only them) submit after the class's close,
extra attempts hold only where granted, granting is idempotent and recorded, refusals
name what is wrong."""

from __future__ import annotations

import datetime as dt

import pytest

from dynagrade.exam.policy import Policy
from serve_support import (Clock, database, exam_copy, exam_dir, postgres_url,  # noqa: F401
                           reference_answers, serve)

UTC = dt.timezone.utc
ZURICH = dt.timezone(dt.timedelta(hours=2))
OPENS = dt.datetime(2025, 4, 14, 8, 0, tzinfo=UTC)
CLOSES = dt.datetime(2025, 4, 14, 10, 0, tzinfo=UTC)
LATER = dt.datetime(2025, 4, 14, 12, 0, tzinfo=UTC)


def at(hour: int, minute: int = 0) -> dt.datetime:
    return dt.datetime(2025, 4, 14, hour, minute, tzinfo=UTC)


# -- the rules, by hand --------------------------------------------------------------------


def test_an_extension_opens_the_exam_for_that_student_only():
    from dynagrade.serve.allowances import Allowance, Rules  # the server's libraries load lazily

    policy = Policy(mode="homework", opens=OPENS, closes=CLOSES, feedback="after-close")
    extended = Rules(policy, Allowance(closes=LATER))
    plain = Rules(policy)
    assert extended.is_open(at(11)) and not plain.is_open(at(11))
    assert extended.refusal(at(11)) is None
    assert "closed at 2025-04-14T10:00:00+00:00" in plain.refusal(at(11))
    assert not extended.is_open(at(12))  # their close is the end for them
    assert extended.extended and not plain.extended
    # verdicts and solutions follow their close: the class sees them at 10:00, they at 12:00
    assert plain.shows_verdicts(at(10)) and not extended.shows_verdicts(at(11))
    assert extended.shows_verdicts(at(12))


def test_a_reopen_window_replaces_the_times():
    from dynagrade.serve.allowances import Allowance, Rules  # the server's libraries load lazily

    policy = Policy(opens=OPENS, closes=CLOSES)
    window = Rules(policy, Allowance(opens=at(14), closes=at(15)))
    assert [window.is_open(at(h)) for h in (9, 13, 14, 15)] == [False, False, True, False]
    assert "opens at 2025-04-14T14:00:00+00:00" in window.refusal(at(9))


def test_the_most_specific_scope_of_extra_attempts_wins():
    from dynagrade.serve.allowances import Allowance, Rules  # the server's libraries load lazily

    policy = Policy(mode="homework", attempts=2)
    rules = Rules(policy, Allowance(extra_attempts={"*": 1, "ex": 3, "ex/p": 5}))
    # one part: 2 + 5; the other parts of ex: 2 + 3; every other part: 2 + 1
    assert (rules.attempts("ex", "p"), rules.attempts("ex", "q"),
            rules.attempts("other", "r")) == (7, 5, 3)
    assert Rules(policy).attempts("ex", "p") == 2
    # no limit: nothing to add
    assert Rules(Policy(), Allowance(extra_attempts={"*": 4})).attempts("ex", "p") == 0


def test_a_timed_deadline_is_the_start_plus_the_time_unless_the_close_comes_first():
    from dynagrade.serve.allowances import Allowance, Rules  # the server's libraries load lazily

    policy = Policy(opens=OPENS, closes=LATER, time_limit=30)
    started = at(10)
    mine = Rules(policy, Allowance(extra_minutes=15), started)
    assert mine.minutes == 45 and mine.deadline == at(10, 45)
    assert mine.is_open(at(10, 44)) and not mine.is_open(at(10, 45))
    assert "your time ran out at 2025-04-14 10:45 UTC" in mine.refusal(at(10, 50))
    assert Rules(policy, None, started).deadline == at(10, 30)
    late = Rules(policy, Allowance(extra_minutes=15), at(11, 30))  # 11:30 + 45 > 12:00
    assert late.deadline == LATER
    waiting = Rules(policy)
    assert waiting.waiting_to_start(at(9)) and not waiting.is_open(at(9))
    assert "Start" in waiting.refusal(at(9))
    assert not waiting.waiting_to_start(at(12))  # closed: nothing to start
    assert Rules(Policy(closes=LATER), Allowance(extra_minutes=15)).deadline == LATER


@pytest.mark.parametrize("value, words", [("-1", "whole number"), ('"x"', "whole number"),
                                          ("2.5", "whole number"), ("20000", "at most")])
def test_a_bad_time_limit_in_exam_toml_is_refused_naming_the_key(tmp_path, value, words):
    from dynagrade.exam.spec import ExamSpecError, read_exam_spec

    path = tmp_path / "exam.toml"
    path.write_text(f'id = "t"\ntitle = "T"\ndate = 2025-04-14\ntime_limit = {value}\n'
                    '[[exercise]]\nid = "projectile-range"\npoints = 6\n', encoding="utf-8")
    with pytest.raises(ExamSpecError) as error:
        read_exam_spec(path)
    assert "line 4, field 'time_limit'" in str(error.value) and words in str(error.value)


def test_the_time_limit_is_read_kept_and_changeable(tmp_path):
    from dynagrade.exam.policy import PolicyError
    from dynagrade.exam.spec import read_exam_spec
    from dynagrade.serve.policy_changes import validated

    path = tmp_path / "exam.toml"
    path.write_text('id = "t"\ntitle = "T"\ndate = 2025-04-14\ntime_limit = 90\n'
                    '[[exercise]]\nid = "projectile-range"\npoints = 6\n', encoding="utf-8")
    policy = read_exam_spec(path).policy
    assert policy.time_limit == 90 and Policy.from_json(policy.to_json()) == policy
    old = {k: v for k, v in Policy().to_json().items() if k != "time_limit"}
    assert Policy.from_json(old).time_limit == 0  # a manifest written before the key
    assert validated(policy, {"time_limit": "30"}).time_limit == 30
    with pytest.raises(PolicyError, match="'time_limit'"):
        validated(policy, {"time_limit": "soon"})


# -- the API and the pages, on both databases ----------------------------------------------


def _bearer(token: str) -> dict:
    return {"Authorization": f"Bearer {token}"}


def _put(served, **body):
    return served.client.put("/api/v1/exceptions", json=body, headers=_bearer(served.staff))


def _audit(served) -> list:
    from dynagrade.serve import db

    return db.changes(served.server.engine, served.server.data.exam_id, "exception")


def test_an_extension_lets_one_student_submit_after_the_close(exam_dir, tmp_path, database):
    manifest = exam_copy(exam_dir, tmp_path / "exam", mode="homework", feedback="immediate",
                         opens=OPENS, closes=CLOSES)
    clock = Clock(at(9))
    with serve(manifest, database, clock) as served:
        answers = {k: v for k, v in reference_answers(served, "s1", "projectile-range").items()}
        granted = _put(served, students=["s1"], closes="2025-04-14T14:00:00+02:00")
        assert granted.status_code == 200, granted.text
        (record,) = granted.json()["exceptions"]
        assert (record["student_id"], record["name"]) == ("s1", "Ada One")
        assert dt.datetime.fromisoformat(record["closes"]) == LATER  # 14:00+02 = 12:00Z
        clock.now = at(11)
        assert served.submit("s1", "projectile-range", answers).status_code == 200
        refused = served.submit("s2", "projectile-range",
                                reference_answers(served, "s2", "projectile-range"))
        assert refused.status_code == 403
        assert "closed at 2025-04-14T10:00:00+00:00" in refused.json()["detail"]
        # the same for drafts, and the pages: theirs shows their close, the other's is closed
        drafts = {"exercise": "projectile-range", "answers": {"x_max": "1 m"}}
        assert served.client.put("/api/v1/drafts", json=drafts,
                                 headers=_bearer(served.tokens["s1"])).status_code == 200
        assert served.client.put("/api/v1/drafts", json=drafts,
                                 headers=_bearer(served.tokens["s2"])).status_code == 403
        mine = served.client.get(f"/s/{served.tokens['s1']}").text
        other = served.client.get(f"/s/{served.tokens['s2']}").text
        assert "Your close:" in mine and "(extended)" in mine
        assert "2025-04-14T12:00:00+00:00" in mine
        closed = '<p class="notice">The exam is closed'
        assert closed not in mine and "<button type=\"submit\">Submit" in mine
        assert "Your close:" not in other and "extended" not in other
        assert closed in other and "<button type=\"submit\">Submit" not in other
        clock.now = at(12)
        assert served.submit("s1", "projectile-range", answers).status_code == 403


def test_extra_attempts_hold_only_on_the_exercise_granted(exam_dir, tmp_path, database):
    manifest = exam_copy(exam_dir, tmp_path / "exam", mode="homework", feedback="immediate",
                         attempts=2)
    with serve(manifest, database, Clock()) as served:
        assert _put(served, students=["s1"],
                    extra_attempts={"projectile-range": 1}).status_code == 200
        granted = reference_answers(served, "s1", "projectile-range")
        other = reference_answers(served, "s1", "sliding-up-a-slope")
        for _ in range(3):  # 2 + 1 on projectile-range's parts
            assert served.submit("s1", "projectile-range", granted).status_code == 200
        fourth = served.submit("s1", "projectile-range", granted)
        assert fourth.status_code == 403 and "each part allows 3" in fourth.json()["detail"]
        for _ in range(2):
            assert served.submit("s1", "sliding-up-a-slope", other).status_code == 200
        third = served.submit("s1", "sliding-up-a-slope", other)
        assert third.status_code == 403 and "each part allows 2" in third.json()["detail"]
        s2 = reference_answers(served, "s2", "projectile-range")
        assert [served.submit("s2", "projectile-range", s2).status_code
                for _ in range(3)] == [200, 200, 403]
        page = served.client.get(f"/s/{served.tokens['s1']}").text
        assert "You were granted extra attempts" in page


def test_granting_is_idempotent_recorded_and_removable(exam_dir, tmp_path, database):
    manifest = exam_copy(exam_dir, tmp_path / "exam", mode="homework", feedback="immediate",
                         closes=CLOSES, attempts=2)
    with serve(manifest, database, Clock()) as served:
        body = {"students": ["s1", "s2"], "closes": "2025-04-14T12:00:00Z",
                "extra_attempts": {"*": 1}}
        assert _put(served, **body).status_code == 200
        assert len(_audit(served)) == 2  # one entry per student
        again = _put(served, **body)
        assert again.status_code == 200 and len(_audit(served)) == 2  # nothing new
        assert {r["student_id"] for r in again.json()["exceptions"]} == {"s1", "s2"}
        entry = next(e for e in _audit(served) if e.subject == "s1")
        assert entry.before is None and entry.after["extra_attempts"] == {"*": 1}
        assert dt.datetime.fromisoformat(entry.after["closes"]) == LATER
        assert entry.actor.startswith("staff link ")
        # a change of one student replaces theirs (one more entry, before and after)
        assert _put(served, students=["s1"], extra_minutes=10).status_code == 200
        changed = _audit(served)[0]
        assert (changed.subject, changed.before["extra_attempts"], changed.after) == (
            "s1", {"*": 1}, {"opens": None, "closes": None, "extra_minutes": 10,
                             "extra_attempts": {}})
        listed = served.staff_get("/api/v1/exceptions").json()["exceptions"]
        assert [(r["student_id"], r["extra_minutes"]) for r in listed] == [("s1", 10),
                                                                            ("s2", 0)]
        removed = served.client.delete("/api/v1/exceptions/s2", headers=_bearer(served.staff))
        assert removed.status_code == 200 and removed.json()["removed"]["student_id"] == "s2"
        assert len(_audit(served)) == 4 and _audit(served)[0].after is None
        twice = served.client.delete("/api/v1/exceptions/s2", headers=_bearer(served.staff))
        assert twice.json() == {"student_id": "s2", "removed": None}
        assert len(_audit(served)) == 4
        assert [r["student_id"] for r in served.staff_get("/api/v1/exceptions")
                .json()["exceptions"]] == ["s1"]


@pytest.mark.parametrize("body, words", [
    ({"students": ["s1", "nobody", "s2", "ghost"], "extra_minutes": 5},
     "not on the roster: nobody, ghost"),
    ({"students": [], "extra_minutes": 5}, "name at least one student"),
    ({"students": ["s1"], "closes": "2025-04-14T12:00:00"}, "closes: "),
    ({"students": ["s1"], "closes": "friday"}, "not a date-time"),
    ({"students": ["s1"], "closes": "2025-04-14T07:00:00Z"}, "is not after the opening"),
    ({"students": ["s1"], "extra_minutes": -5}, "extra_minutes"),
    ({"students": ["s1"], "extra_attempts": {"no-such-exercise": 1}}, "no-such-exercise"),
    ({"students": ["s1"], "extra_attempts": {"projectile-range/nope": 1}},
     "projectile-range/nope"),
    ({"students": ["s1"], "extra_attempts": {"*": 5000}}, "from 0 to 1000"),
    ({"students": ["s1"]}, "nothing to grant"),
])
def test_refusals_name_what_is_wrong_and_change_nothing(exam_dir, tmp_path, body, words):
    manifest = exam_copy(exam_dir, tmp_path / "exam", mode="homework", feedback="immediate",
                         opens=OPENS, closes=CLOSES, attempts=2)
    with serve(manifest, None, Clock()) as served:
        refused = _put(served, **body)
        assert refused.status_code == 422
        assert words in refused.json()["detail"]
        assert _audit(served) == []
        assert served.staff_get("/api/v1/exceptions").json() == {"exceptions": []}
        unknown = served.client.delete("/api/v1/exceptions/ghost",
                                       headers=_bearer(served.staff))
        assert unknown.status_code == 422 and "ghost" in unknown.json()["detail"]
        student = served.client.put("/api/v1/exceptions", json=body,
                                    headers=_bearer(served.tokens["s1"]))
        assert student.status_code == 403


def test_the_staff_page_grants_lists_refuses_and_removes(exam_dir, tmp_path, database):
    from dynagrade.serve import limits

    manifest = exam_copy(exam_dir, tmp_path / "exam", mode="homework", feedback="immediate",
                         opens=OPENS, closes=CLOSES, attempts=2)
    with serve(manifest, database, Clock()) as served:
        page = f"/i/{served.staff}/exceptions"
        csrf = limits.csrf_field(served.server.secret, served.staff)
        empty = served.client.get(page)
        assert empty.status_code == 200 and "None yet" in empty.text
        filled = served.client.get(f"{page}?students=s1,s3").text
        assert ">s1\ns3</textarea>" in filled
        refused = served.client.post(page, data={
            "csrf": csrf, "students": "s1, zed\nqux", "closes": "2025-04-14T13:00:00"})
        assert refused.status_code == 422
        assert "not on the roster: zed, qux" in refused.text
        assert ">s1, zed\nqux</textarea>" in refused.text  # what was typed, kept
        assert 'value="2025-04-14T13:00:00"' in refused.text
        done = served.client.post(page, data={
            "csrf": csrf, "students": "s1 s3", "closes": "2025-04-14T14:00:00+02:00",
            "attempts.projectile-range": "1", "attempts.*": ""}, follow_redirects=False)
        assert done.status_code == 303 and done.headers["location"].endswith("#granted")
        listed = served.client.get(page).text
        # in the course's zone (that of its close: UTC here), to the second when granted
        assert "closes 2025-04-14 12:00 UTC" in listed
        assert "1 extra attempt on projectile-range" in listed
        assert listed.count("Remove the exceptions of") == 2 and "Cy Three" in listed
        one = served.client.get(f"{page}?students=s1").text  # their exception, to change
        assert 'name="attempts.projectile-range" inputmode="numeric" value="1"' in one
        gone = served.client.post(f"{page}/remove", data={"csrf": csrf, "student": "s3"},
                                  follow_redirects=False)
        assert gone.status_code == 303
        assert "Cy Three" not in served.client.get(page).text
        stale = served.client.post(f"{page}/remove", data={"csrf": "x", "student": "s1"})
        assert stale.status_code == 403
        assert [e.subject for e in _audit(served)] == ["s3", "s3", "s1"]
