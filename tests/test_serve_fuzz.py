"""The server's submit, preview and drafts bodies, fuzzed: no body gives a 500 (issue 26,
item 3). Random unicode (lone surrogates included, which JSON escapes), long texts and
JSON of every odd type where a text belongs; each answer is 2xx or a 4xx refusal with a
``detail``.
"""

from __future__ import annotations

import json

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from serve_support import exam_copy, exam_dir, serve  # noqa: F401

EXERCISE = "projectile-range"

_TEXT = st.one_of(
    st.text(st.characters(codec=None, exclude_categories=()), max_size=40),
    st.text(st.sampled_from("0123456789.,-+*/^()e xmsg\ud800\udfff"), max_size=60),
    st.text(max_size=3000),  # over the 2000 characters an answer may have
    st.sampled_from([EXERCISE, "x_max", "h_max", "6666666666-.0", "1e999", ""]))
_ODD = st.one_of(st.none(), st.booleans(), st.integers(), st.floats(allow_nan=False),
                 st.lists(st.integers(), max_size=3), st.dictionaries(st.text(max_size=3),
                                                                       st.integers(), max_size=2))
_VALUE = st.one_of(_TEXT, _TEXT, _ODD)
_ANSWERS = st.one_of(st.dictionaries(_TEXT, _VALUE, max_size=3), _ODD)
_BODIES = st.one_of(
    st.fixed_dictionaries({"exercise": _VALUE, "answers": _ANSWERS}),
    st.fixed_dictionaries({"exercise": _VALUE, "part": _VALUE, "answer": _VALUE},
                          optional={"practice": _VALUE}),
    _ODD)
_ROUTES = st.sampled_from([("POST", "/api/v1/answers"), ("POST", "/api/v1/preview"),
                           ("PUT", "/api/v1/drafts")])


@pytest.fixture(scope="module")
def served(exam_dir, tmp_path_factory):
    manifest = exam_copy(exam_dir, tmp_path_factory.mktemp("fuzz") / "exam", mode="practice")
    with serve(manifest) as running:
        yield running


@settings(max_examples=60, deadline=None, suppress_health_check=[
    HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(route=_ROUTES, body=_BODIES)
def test_no_body_gives_a_500(served, route, body):
    method, path = route
    # ensure_ascii: JSON's own escapes, so a lone surrogate reaches the server as "\ud800"
    content = json.dumps(body, ensure_ascii=True).encode("ascii")
    response = served.client.request(method, path, content=content, headers={
        "Authorization": f"Bearer {served.tokens['s1']}", "Content-Type": "application/json"})
    assert response.status_code < 500, (body, response.text)
    if response.status_code >= 400:
        assert response.json()["detail"]
