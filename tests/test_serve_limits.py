"""The guards' memory and the access log (issue 26, item 4): the rate limiter keeps a
table of fixed size however many tokens arrive, keyed by the client's address and a
digest of the token; a token far longer than ours is refused before it is looked up or
remembered; the access log never holds a link's token."""

from __future__ import annotations

import logging

from serve_support import exam_copy, exam_dir, serve  # noqa: F401


def test_the_limiter_table_stays_bounded_whatever_the_tokens():
    from dynagrade.serve.limits import RateLimiter, limiter_key

    limiter = RateLimiter(rate=0.0, burst=2, size=50)
    for n in range(1_000):
        assert limiter.allow(limiter_key("10.0.0.1", f"{n}" + "x" * 100_000))
    assert len(limiter) == 50
    key = limiter_key("10.0.0.1", "ours")
    assert len(key) < 40  # a digest, not the token
    assert limiter.allow(key) and limiter.allow(key) and not limiter.allow(key)
    # the same token from another address has its own bucket
    assert limiter.allow(limiter_key("10.0.0.2", "ours"))


def test_the_longest_idle_bucket_is_forgotten_first():
    from dynagrade.serve.limits import RateLimiter

    limiter = RateLimiter(rate=0.0, burst=1, size=2)
    assert limiter.allow("a") and limiter.allow("b")
    assert not limiter.allow("a")  # spent; now the newest
    assert limiter.allow("c")      # forgets b, the longest idle
    assert limiter.allow("b")      # a fresh bucket
    assert not limiter.allow("c")


def test_an_overlong_token_is_refused_and_nothing_is_kept(exam_dir, tmp_path):
    manifest = exam_copy(exam_dir, tmp_path / "exam")
    with serve(manifest) as served:
        before = len(served.server.limiter)
        for n in range(300):
            answer = served.client.get(f"/api/v1/gradebook", headers={
                "Authorization": f"Bearer {n}{'t' * 100_000}"})
            assert answer.status_code == 401
        assert len(served.server.limiter) == before
        ours = served.client.get("/api/v1/gradebook",
                                 headers={"Authorization": f"Bearer {served.staff}"})
        assert ours.status_code == 200


def test_the_access_log_shows_no_token(exam_dir, tmp_path, caplog):
    from dynagrade.serve import db
    from dynagrade.serve.limits import TokenlessAccessLog

    token = "Zm9vYmFyLXNlY3JldC10b2tlbi12YWx1ZS0xMjM0NTY3ODkw"
    record = logging.LogRecord("uvicorn.access", logging.INFO, __file__, 1,
                               '%s - "%s %s HTTP/%s" %d',
                               ("127.0.0.1:5000", "GET", f"/i/{token}/grades.csv?x=1", "1.1",
                                200), None)
    assert TokenlessAccessLog().filter(record)
    line = record.getMessage()
    assert token not in line
    assert f"/i/{db.link_id(token)}…/grades.csv?x=1" in line
    manifest = exam_copy(exam_dir, tmp_path / "exam")
    with serve(manifest):  # building the app installs the filter on uvicorn's log
        assert any(isinstance(f, TokenlessAccessLog)
                   for f in logging.getLogger("uvicorn.access").filters)
