"""Every route of `dynagrade serve` says who may call it, and refuses everyone else; the
OpenAPI document describes every response body.

The routes are enumerated from the app itself, so a route added without a caller
dependency, or with a JSON body the document does not describe, fails here.
"""

from __future__ import annotations

import csv
import io
import re

import pytest

from serve_support import exam_copy, exam_dir, reference_answers, serve  # noqa: F401

#: the routes anyone may call (LTI's: the platform's signed id_token, the state and its
#: cookie decide, tests/test_serve_lti.py)
PUBLIC = {("GET", "/healthz"), ("GET", "/static/{name}"), ("GET", "/lti/login"),
          ("POST", "/lti/login"), ("POST", "/lti/launch"), ("GET", "/lti/jwks")}
OTHER_ROLE = {"student": "staff", "staff": "student"}
#: what a route's path parameters are filled with (a student of the roster, who has
#: answered by the time a staff route asks: the student routes come first)
@pytest.fixture(scope="module")
def served(exam_dir, tmp_path_factory):
    """A practice exam (every route, including "new variant", is open) with tokens."""
    manifest = exam_copy(exam_dir, tmp_path_factory.mktemp("routes") / "exam",
                         mode="practice", feedback="immediate")
    with serve(manifest) as running:
        yield running


def _all_routes(app) -> list[tuple[str, object]]:
    """(path, route) of every route of the app, the routers' prefixes applied."""
    try:  # FastAPI 0.16x keeps an included router whole in app.routes
        from fastapi.routing import iter_route_contexts
    except ImportError:  # earlier ones copy its routes into app.routes
        return [(route.path, route) for route in app.routes]
    return [(context.path, context.original_route)
            for context in iter_route_contexts(app.routes)]


def _routes(app) -> list[tuple[str, object]]:
    """(path, route) of the app's routes that are FastAPI routes (with dependencies)."""
    from fastapi.routing import APIRoute

    found = [(path, route) for path, route in _all_routes(app) if isinstance(route, APIRoute)]
    assert found, "no routes found"
    return found


def _callers(dependant) -> set[tuple[str, str]]:
    """(role, where the token is) of every caller dependency below ``dependant``."""
    from dynagrade.serve.deps import CALLERS

    found = set()
    for sub in dependant.dependencies:
        if sub.call in CALLERS:
            found.add(CALLERS[sub.call])
        found |= _callers(sub)
    return found


def _guarded(app):
    """Every route but the public ones, with the one (role, token place) it admits."""
    out = []
    for path, route in _routes(app):
        (method,) = route.methods
        callers = _callers(route.dependant)
        if (method, path) in PUBLIC:
            assert not callers, path
            continue
        assert len(callers) == 1, f"{method} {path} names {callers or 'no caller'}"
        out.append((method, path, *callers.pop()))
    return out


def test_every_route_is_a_router_route_that_names_its_caller(served):
    from fastapi.routing import APIRoute

    app = served.app
    # FastAPI's own route: the API description (no browsable page, docs/serve.md)
    documentation = {app.openapi_url}
    assert app.openapi_url == "/api/openapi.json" and app.docs_url is None
    for path, route in _all_routes(app):  # nothing bypasses the routers' dependencies
        assert isinstance(route, APIRoute) or path in documentation, path
    guarded = _guarded(app)
    # each router has routes, and they admit the caller of their audience
    admitted = {(path.split("/")[1], role, place) for _, path, role, place in guarded}
    assert admitted == {("s", "student", "path"), ("i", "staff", "path"),
                        ("api", "student", "bearer"), ("api", "staff", "bearer")}
    assert len(guarded) >= 12


def _request(served, method: str, path: str, token: str | None, place: str):
    """``method path`` with ``token`` where the route takes it, and a body it accepts."""
    headers = {}
    if place == "path":
        path = path.replace("{token}", token or "")
    elif token is not None:
        headers["Authorization"] = f"Bearer {token}"
    values = _path_values(served)
    for name, value in values.items():
        path = path.replace("{" + name + "}", value)
    kwargs: dict = {"headers": headers, "follow_redirects": False}
    body = next((body for start, body in _JSON_BODIES.items() if path.startswith(start)),
                None)
    if body is not None:
        kwargs["json"] = body
    elif method == "POST":  # a page's form, with the CSRF field of the page it came from
        from dynagrade.serve import limits

        # an answer of its own: the page submits only what changed since the last counted
        # answer, and the API's submit (``_JSON_BODIES``) may have come first
        kwargs["data"] = {"exercise": "projectile-range", "answer.x_max": "2 m",
                          "link": values["link_id"],
                          "students": "s3", "student": "s3", "extra_minutes": "5",
                          "part": "x_max", "points": "0",
                          "csrf": limits.csrf_field(served.server.secret, token or "")}
    return served.client.request(method, path, **kwargs)


#: a body each JSON route accepts, by the start of its path
_JSON_BODIES = {
    "/api/v1/answers": {"exercise": "projectile-range", "answers": {"x_max": "1 m"}},
    "/api/v1/drafts": {"exercise": "projectile-range", "answers": {"x_max": "1 m"}},
    "/api/v1/preview": {"exercise": "projectile-range", "part": "x_max", "answer": "1 m"},
    "/api/v1/staff-links": {"name": "a TA"},
    "/api/v1/exceptions": {"students": ["s3"], "extra_minutes": 5},
    "/api/v1/overrides": {"student": "s3", "exercise": "projectile-range", "part": "x_max",
                          "points": 0},
    "/api/v1/policy": {"attempts": 0},
}


def _path_values(served) -> dict[str, str]:
    """A value for each parameter of a route's path (but the token) that the route
    answers: a platform layout, another staff link (made afresh: it may be revoked), a
    student, a previewed regrade (made afresh: it may be applied)."""
    from dynagrade.serve import db

    data = served.server.data
    other = db.issue_staff_token(served.server.engine, data.exam_id, "another")
    return {"layout": "moodle", "link_id": db.link_id(other), "student_id": "s3",
            "exercise": "projectile-range", "part": "x_max",
            "regrade_id": str(_fresh_plan(served))}


def _fresh_plan(served) -> int:
    """A previewed regrade that changes no verdict, of the files the server loaded."""
    from dynagrade.serve import db, regrade

    data = served.server.data
    return db.store_regrade(served.server.engine, data.exam_id, "test",
                            regrade.source_of(data), {"answers": 0, "changes": [],
                                                      "grades": {}, "last_answer_id": 0})


def _submissions(served) -> int:
    from dynagrade.serve import db

    return db.counts(served.server.engine, served.server.data.exam_id)["submissions"]


def test_every_route_refuses_a_missing_unknown_or_wrong_token(served):
    token_of = {"student": served.tokens["s2"], "staff": served.staff}
    stored = _submissions(served)
    for method, path, role, place in _guarded(served.app):
        where = f"{method} {path}"
        unknown = _request(served, method, path, "not-a-token-of-this-exam", place)
        assert unknown.status_code == 401, where
        assert unknown.json() == {"detail": "unknown link"}, where
        missing = _request(served, method, path, None, place)
        # without a token a page's path is no page at all
        assert missing.status_code == (401 if place == "bearer" else 404), where
        wrong = _request(served, method, path, token_of[OTHER_ROLE[role]], place)
        assert wrong.status_code == 403, where
        assert wrong.json() == {"detail": "not a link for this page"}, where
    assert _submissions(served) == stored  # nothing refused was stored


def test_every_route_answers_its_own_caller(served):
    """The requests above are refused for their token alone: with the right one, the
    same request is answered."""
    token_of = {"student": served.tokens["s3"], "staff": served.staff}
    for method, path, role, place in _guarded(served.app):
        answered = _request(served, method, path, token_of[role], place)
        assert answered.status_code in (200, 201, 303), (method, path, answered.text[:300])


def test_the_openapi_document_describes_every_response(served):
    document = served.client.get("/api/openapi.json").json()
    schemas = document["components"]["schemas"]
    operations = {(method.upper(), path): operation
                  for path, item in document["paths"].items()
                  for method, operation in item.items()}
    described = {(method, path) for path, route in _routes(served.app)
                 for method in route.methods}
    assert described and set(operations) == described
    json_bodies = set()
    for (method, path), operation in operations.items():
        statuses = set(operation["responses"])
        assert statuses & {"200", "201", "303"}, (method, path, statuses)
        for status, response in operation["responses"].items():
            for media, content in response.get("content", {}).items():
                schema = content.get("schema")
                assert schema, f"{method} {path} {status} {media}: no schema"
                if media != "application/json":  # a page, a CSV file, plain text
                    assert schema == {"type": "string"}, (method, path, status, media)
                    continue
                name = schema.get("$ref", "").rsplit("/", 1)[-1]
                resolved = schemas.get(name, {}) if name else schema
                assert resolved.get("properties"), (method, path, status)
                if status in ("200", "201"):
                    json_bodies.add((method, path, name))
    assert json_bodies == {("POST", "/api/v1/answers", "SubmitResponse"),
                           ("POST", "/api/v1/preview", "PreviewResponse"),
                           ("PUT", "/api/v1/drafts", "DraftsResponse"),
                           ("GET", "/api/v1/gradebook", "Gradebook"),
                           ("GET", "/i/{token}/tables", "StaffTables"),
                           ("GET", "/api/v1/staff-links", "StaffLinks"),
                           ("POST", "/api/v1/staff-links", "NewStaffLink"),
                           ("DELETE", "/api/v1/staff-links/{link_id}", "StaffLinkInfo"),
                           ("GET", "/api/v1/audit", "AuditLog"),
                           ("POST", "/api/v1/start", "StartResponse"),
                           ("GET", "/api/v1/exceptions", "Exceptions"),
                           ("PUT", "/api/v1/exceptions", "Exceptions"),
                           ("DELETE", "/api/v1/exceptions/{student_id}", "Removed"),
                           ("POST", "/api/v1/regrades", "RegradePlan"),
                           ("GET", "/api/v1/regrades/{regrade_id}", "RegradePlan"),
                           ("POST", "/api/v1/regrades/{regrade_id}/apply", "RegradePlan"),
                           ("POST", "/api/v1/regrades/{regrade_id}/discard", "RegradePlan"),
                           ("PUT", "/api/v1/overrides", "OverrideChange"),
                           ("DELETE", "/api/v1/overrides/{student_id}/{exercise}/{part}",
                            "OverrideChange"),
                           ("GET", "/api/v1/overrides", "Overrides"),
                           ("GET", "/api/v1/students/{student_id}", "StudentRecord"),
                           ("GET", "/api/v1/policy", "PolicyInForce"),
                           ("PUT", "/api/v1/policy", "PolicyInForce"),
                           ("GET", "/lti/jwks", "KeySet")}
    refusal = operations[("POST", "/api/v1/answers")]["responses"]
    for status in ("401", "403", "413", "422", "429", "503"):
        schema = refusal[status]["content"]["application/json"]["schema"]
        assert schema["title"] == "Problem" and schema["required"] == ["detail"], status
    assert "HTTPBearer" in document["components"]["securitySchemes"]


def test_submit_response_shows_verdict_fields_only_with_verdicts(served):
    """The model lists every field; the JSON holds the ones the policy shows."""
    right = reference_answers(served, "s1", "sliding-up-a-slope")
    name = next(iter(right))
    body = served.submit("s1", "sliding-up-a-slope", {name: right[name]},
                         key="routes-0001").json()
    assert set(body) == {"exercise", "attempt", "idempotency_key", "parts", "score",
                         "max_score"}
    assert set(body["parts"][0]) == {"name", "readable", "message", "correct", "score",
                                     "feedback"} and body["parts"][0]["correct"] is True
    again = served.submit("s1", "sliding-up-a-slope", {name: right[name]},
                          key="routes-0001").json()
    assert again == {**body, "replayed": True}


def test_the_json_gradebook_holds_the_rows_of_grades_csv(served):
    right = reference_answers(served, "s1", "projectile-range")
    served.submit("s1", "projectile-range", right)
    book = served.staff_get("/api/v1/gradebook")
    assert book.status_code == 200
    body = book.json()
    assert body["exercise_ids"] == ["projectile-range", "sliding-up-a-slope"]
    table = {row["student_id"]: row for row in csv.DictReader(io.StringIO(
        served.staff_get("/api/v1/grades.csv").text))}
    assert [row["student_id"] for row in body["rows"]] == list(table)
    for row in body["rows"]:
        line = table[row["student_id"]]
        assert (row["name"], row["email"], row["status"]) == (
            line["name"], line["email"], line["status"])
        for exercise, points in row["exercises"].items():
            assert (points is None and line[exercise] == "") or \
                points == pytest.approx(float(line[exercise]))
        assert row["max_total"] == pytest.approx(float(line["max_total"]))
    s1 = next(row for row in body["rows"] if row["student_id"] == "s1")
    assert s1["exercises"]["projectile-range"] == pytest.approx(6.0)
    assert re.fullmatch(r"graded|incomplete", s1["status"])
