"""Undecodable input is a 422 naming what is wrong, never a 500 (issue 26, item 3).

JSON may spell a lone surrogate (``"\\ud800"``), which is valid JSON but not a character:
no UTF-8 text (the database, a response) can hold it. Bytes that are not UTF-8 are not
JSON at all. Both are refused before anything is graded or stored.
"""

from __future__ import annotations

import pytest

from serve_support import exam_copy, exam_dir, serve  # noqa: F401

EXERCISE = "projectile-range"


@pytest.fixture(scope="module")
def served(exam_dir, tmp_path_factory):
    manifest = exam_copy(exam_dir, tmp_path_factory.mktemp("undecodable") / "exam",
                         mode="practice")
    with serve(manifest) as running:
        yield running


def _send(served, method: str, path: str, body: bytes):
    return served.client.request(method, path, content=body, headers={
        "Authorization": f"Bearer {served.tokens['s1']}", "Content-Type": "application/json"})


SURROGATE_BODIES = [
    ("POST", "/api/v1/answers", b'{"exercise": "%s", "answers": {"x_max": "1\\ud800 m"}}'),
    ("POST", "/api/v1/answers", b'{"exercise": "%s", "answers": {"\\udfff": "1 m"}}'),
    ("POST", "/api/v1/preview", b'{"exercise": "%s", "part": "x_max", "answer": "\\ud83d"}'),
    ("POST", "/api/v1/preview", b'{"exercise": "%s\\ud800", "part": "x_max", "answer": "1"}'),
    ("PUT", "/api/v1/drafts", b'{"exercise": "%s", "answers": {"x_max": "\\udc00"}}'),
]


@pytest.mark.parametrize("method, path, body", SURROGATE_BODIES)
def test_a_lone_surrogate_is_refused_with_a_message(served, method, path, body):
    response = _send(served, method, path, body.replace(b"%s", EXERCISE.encode()))
    assert response.status_code == 422, response.text
    detail = response.json()["detail"]
    assert len(detail) == 1 and detail[0]["loc"][0] == "body" and detail[0]["msg"]
    # pydantic refuses the text itself where the field has a length limit; else ours does
    assert "not a character" in detail[0]["msg"] or "unicode" in detail[0]["msg"]


@pytest.mark.parametrize("method, path", [("POST", "/api/v1/answers"),
                                          ("POST", "/api/v1/preview"),
                                          ("PUT", "/api/v1/drafts")])
def test_bytes_that_are_not_utf8_are_refused_with_a_message(served, method, path):
    body = b'{"exercise": "' + EXERCISE.encode() + b'", "answers": {"x_max": "\xff\xfe"}}'
    response = _send(served, method, path, body)
    assert response.status_code == 422, response.text
    assert "not UTF-8" in response.json()["detail"]


@pytest.mark.parametrize("body", [b"Infinity", b"-Infinity", b"NaN",
                                  b'{"exercise": "projectile-range", "answers": NaN}'])
@pytest.mark.parametrize("method, path", [("POST", "/api/v1/answers"),
                                          ("POST", "/api/v1/preview"),
                                          ("PUT", "/api/v1/drafts")])
def test_a_number_json_cannot_hold_is_refused_and_quoted_as_text(served, method, path,
                                                                 body):
    """Python's JSON reads ``Infinity`` and ``NaN``; the refusal quotes the input it
    refused, and must still be JSON (the server's fuzzing found this 500)."""
    response = _send(served, method, path, body)
    assert response.status_code == 422, response.text
    assert response.json()["detail"]
    assert any(f'"{word}"' in response.text for word in ("inf", "-inf", "nan"))


def test_nothing_refused_was_stored(served):
    _send(served, "POST", "/api/v1/answers",
          b'{"exercise": "%s", "answers": {"x_max": "\\ud800"}}' % EXERCISE.encode())
    page = served.client.get(f"/s/{served.tokens['s1']}").text
    assert "\\ud800" not in page and "\ufffd" not in page


def test_a_surrogate_escape_in_a_form_post_is_no_500(served):
    """The student page's form (urlencoded, no JavaScript): the bytes of a surrogate are
    not UTF-8; the page answers (a refusal or the answer read with U+FFFD), never 500."""
    response = served.client.post(f"/s/{served.tokens['s1']}/submit", content=(
        f"exercise={EXERCISE}&answer.x_max=%ED%A0%80").encode(),
        headers={"Content-Type": "application/x-www-form-urlencoded", "Accept": "text/html"},
        follow_redirects=False)
    assert response.status_code < 500, response.text
