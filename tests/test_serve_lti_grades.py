"""LTI Assignment and Grade Services against the test platform: a launched student's
counted score goes to the exam's line item (made by the tool, or the one the launch
named) once per change; an exam whose feedback waits for the close sends nothing before
it and the score at it; a refused score is tried again after 10 s, then 20 s; the queue
survives a restart; the staff page lists what was sent and the platform's answer."""

from __future__ import annotations

import datetime as dt
from types import SimpleNamespace

import pytest

from lti_support import launch_as, platform, tool  # noqa: F401
from serve_support import Clock, database, exam_copy, exam_dir, postgres_url  # noqa: F401
from serve_support import reference_answers

UTC = dt.timezone.utc
EXAM_POINTS = 10.0  # serve_support.EXAM_TOML: 6 + 4
RANGE_POINTS = 6.0  # projectile-range


@pytest.fixture(autouse=True)
def fresh_platform(platform):
    """Each test starts with a platform that holds no line item nor score."""
    platform.line_items.clear()
    platform.scores.clear()
    platform.score_requests.clear()
    platform.fail_scores, platform.lineitem = 0, None
    yield platform


def launched_submit(client, platform, user: str, student: str, exercise: str) -> None:
    """``user`` launches and answers every part of ``exercise`` rightly (the API, with
    the session's handle and cookie)."""
    answer = launch_as(client, platform, user)
    assert answer.status_code == 303, answer.text
    handle = answer.headers["location"].split("/")[2]
    server = client.app.state.server
    right = reference_answers(SimpleNamespace(variant=server.data.entry), student, exercise)
    stored = client.post("/api/v1/answers", headers={"Authorization": f"Bearer {handle}"},
                         json={"exercise": exercise, "answers": right})
    assert stored.status_code == 200, stored.text


def sync(client, at: dt.datetime | None = None) -> None:
    from dynagrade.serve.lti import grade_sync

    server = client.app.state.server
    now = at or server.clock()
    grade_sync.queue_changes(server, now)
    grade_sync.send_due(server, now)


def test_a_counted_score_goes_to_the_line_item_the_tool_made(exam_dir, tmp_path, database,
                                                             platform):
    manifest = exam_copy(exam_dir, tmp_path / "hw", mode="homework", feedback="immediate")
    with tool(manifest, database, platform) as client:
        launched_submit(client, platform, "u-ada", "s1", "projectile-range")
        sync(client)
        sync(client)  # nothing changed: nothing sent again
        (item,) = platform.line_items.values()
        assert item["scoreMaximum"] == EXAM_POINTS and item["label"] == "Serve test"
        assert item["resourceLinkId"] == "link-1"
        assert item["resourceId"] == client.app.state.server.data.exam_id
        ((line_item, score),) = platform.scores
        assert line_item == item["id"]
        assert score["userId"] == "u-ada"
        assert (score["scoreGiven"], score["scoreMaximum"]) == (RANGE_POINTS, EXAM_POINTS)
        assert (score["activityProgress"], score["gradingProgress"]) == \
            ("Submitted", "FullyGraded")
        assert dt.datetime.fromisoformat(score["timestamp"]).tzinfo is not None


def test_a_launch_naming_a_line_item_binds_the_exam_to_it(exam_dir, tmp_path, platform):
    manifest = exam_copy(exam_dir, tmp_path / "hw", mode="homework", feedback="immediate")
    named = f"{platform.url}/lineitems/7"
    platform.line_items[named] = {"id": named, "scoreMaximum": 10, "label": "Exam"}
    platform.lineitem = named
    with tool(manifest, None, platform) as client:
        launched_submit(client, platform, "u-bo", "s2", "sliding-up-a-slope")
        sync(client)
        assert list(platform.line_items) == [named]  # none made
        ((line_item, score),) = platform.scores
        assert line_item == named and score["userId"] == "u-bo"
        assert score["scoreGiven"] == 4.0


def test_an_exam_sends_nothing_before_its_close_and_the_score_at_it(exam_dir, tmp_path,
                                                                    platform):
    closes = dt.datetime(2025, 4, 14, 12, 0, tzinfo=UTC)
    manifest = exam_copy(exam_dir, tmp_path / "exam", mode="exam", feedback="after-close",
                         opens=dt.datetime(2025, 4, 14, 9, 0, tzinfo=UTC), closes=closes)
    clock = Clock(dt.datetime(2025, 4, 14, 10, 0, tzinfo=UTC))
    with tool(manifest, None, platform, clock=clock) as client:
        launched_submit(client, platform, "u-ada", "s1", "projectile-range")
        sync(client)
        assert platform.scores == [] and platform.score_requests == []
        clock.now = closes + dt.timedelta(minutes=1)
        sync(client)
        ((_, score),) = platform.scores
        assert score["scoreGiven"] == RANGE_POINTS
        assert score["activityProgress"] == "Completed"


def test_a_refused_score_is_tried_again_after_10_then_20_seconds(exam_dir, tmp_path,
                                                                  platform):
    manifest = exam_copy(exam_dir, tmp_path / "hw", mode="homework", feedback="immediate")
    platform.fail_scores = 2
    with tool(manifest, None, platform, clock=Clock()) as client:
        launched_submit(client, platform, "u-ada", "s1", "projectile-range")
        start = client.app.state.server.clock()
        for seconds, tries in ((0, 1), (9, 1), (10, 2), (29, 2), (30, 3), (100, 3)):
            sync(client, start + dt.timedelta(seconds=seconds))
            assert len(platform.score_requests) == tries, seconds
        assert [status for status, _ in platform.score_requests] == [503, 503, 200]
        assert len(platform.scores) == 1
        staff = _staff_page(client)
        assert "204" in staff and "sent" in staff


def test_queued_scores_survive_a_restart(exam_dir, tmp_path, platform):
    manifest = exam_copy(exam_dir, tmp_path / "hw", mode="homework", feedback="immediate")
    platform.fail_scores = 1
    clock = Clock()
    with tool(manifest, None, platform, clock=clock) as client:
        launched_submit(client, platform, "u-ada", "s1", "projectile-range")
        sync(client)
        assert platform.scores == []
        assert "503" in _staff_page(client)  # the platform's refusal, as answered
    clock.now += dt.timedelta(minutes=5)
    with tool(manifest, None, platform, clock=clock) as client:  # a new process, say
        from dynagrade.serve.lti import grade_sync

        grade_sync.send_due(client.app.state.server, clock.now)
        ((_, score),) = platform.scores
        assert score["scoreGiven"] == RANGE_POINTS


def _staff_page(client) -> str:
    from dynagrade.serve import db

    server = client.app.state.server
    token = db.issue_staff_token(server.engine, server.data.exam_id)
    page = client.get(f"/i/{token}/lti")
    assert page.status_code == 200
    return page.text


def test_the_sync_task_computes_the_gradebook_again_only_when_a_score_may_have_changed(
        exam_dir, tmp_path, platform, monkeypatch):
    # computing every launched student's score reads every answer of the exam: a class
    # of a thousand cannot pay that every 5 s in every process
    from dynagrade.serve import gradebook
    from dynagrade.serve.lti import grade_sync

    computed = []
    outcome = gradebook.outcome
    monkeypatch.setattr(gradebook, "outcome",
                        lambda *a, **k: computed.append(1) or outcome(*a, **k))
    manifest = exam_copy(exam_dir, tmp_path / "hw", mode="homework", feedback="immediate")
    with tool(manifest, None, platform) as client:
        server = client.app.state.server
        gate = grade_sync.RecomputeGate()
        launched_submit(client, platform, "u-ada", "s1", "projectile-range")
        grade_sync.sync_once(server, gate)
        assert len(computed) == 1 and len(platform.scores) == 1
        grade_sync.sync_once(server, gate)  # nothing changed: not computed again
        assert len(computed) == 1
        launched_submit(client, platform, "u-ada", "s1", "sliding-up-a-slope")
        grade_sync.sync_once(server, gate)  # a new submission: computed, and sent
        assert len(computed) == 2 and len(platform.scores) == 2
        later = server.clock() + dt.timedelta(seconds=grade_sync.RECOMPUTE_SECONDS)
        assert gate.due(server, later)  # a close may have passed: computed again
