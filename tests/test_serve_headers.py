"""Every answer of the server carries the security headers; pages run only the server's
own scripts and styles; HEAD is answered wherever GET is; a streamed body over the limit
is a 413 (issue 26, item 5; docs/serve.md, "Deployment").

Each route of every router is asked with the token of its audience, as in
tests/test_serve_routes.py, so that a route added later is held to the same headers.
"""

from __future__ import annotations

from html.parser import HTMLParser

import pytest

from test_serve_routes import PUBLIC, _guarded, _request, served  # noqa: F401
from serve_support import exam_dir  # noqa: F401


@pytest.fixture(autouse=True)
def unlimited(served):
    """Every route asked twice over is more than one token's burst: no rate limit here."""
    from dynagrade.serve import limits

    served.server.limiter = limits.RateLimiter(burst=10_000)


def _policy(answer) -> dict[str, list[str]]:
    """The answer's Content-Security-Policy as {directive: sources}."""
    policy = {}
    for directive in answer.headers["content-security-policy"].split(";"):
        name, *sources = directive.split()
        policy[name] = sources
    return policy


def _get_routes(served) -> list[tuple[str, str | None, str]]:
    """(path, token, place) of every GET route, public ones without a token."""
    token_of = {"student": served.tokens["s3"], "staff": served.staff}
    routes = [(path, token_of[role], place)
              for method, path, role, place in _guarded(served.app) if method == "GET"]
    # (LTI's login initiation answers a platform's parameters only: tests/test_serve_lti.py)
    routes += [(path.replace("{name}", "base.css"), None, "public")
               for method, path in PUBLIC if method == "GET" and path != "/lti/login"]
    assert len(routes) >= 10
    return routes


def test_every_answer_is_kept_out_of_caches_referrers_frames_and_sniffing(served):
    for path, token, place in _get_routes(served):
        answer = _request(served, "GET", path, token, place)
        assert answer.status_code == 200, path
        assert answer.headers["x-content-type-options"] == "nosniff", path
        assert answer.headers["referrer-policy"] == "no-referrer", path  # tokens in URLs
        assert answer.headers["x-frame-options"] == "DENY", path
        assert _policy(answer)["frame-ancestors"] == ["'none'"], path
        assert _policy(answer)["base-uri"] == ["'none'"], path
        expected_cache = "no-cache" if path.startswith("/static/") else "no-store"
        assert answer.headers["cache-control"] == expected_cache, path
    refused = served.client.get("/s/not-a-token", headers={"Accept": "text/html"})
    assert refused.status_code == 401 and refused.headers["cache-control"] == "no-store"
    assert _policy(refused)["script-src"] == ["'self'"]


def test_pages_may_run_only_the_servers_own_scripts_and_styles(served):
    """Every page's policy names the server alone for scripts, styles, fetches and form
    posts, and allows nothing inline and nothing evaluated; the class report, a saved
    document with its own inline styles, may run no script at all."""
    for path, token, place in _get_routes(served):
        answer = _request(served, "GET", path, token, place)
        policy = _policy(answer)
        assert policy["default-src"] == ["'none'"], path
        everything = " ".join(" ".join(sources) for sources in policy.values())
        assert "unsafe-eval" not in everything and "*" not in everything, path
        assert "script-src" not in policy or policy["script-src"] == ["'self'"], path
        if path.endswith("/report.html"):
            assert "script-src" not in policy  # default-src 'none': no script
            assert policy["style-src"] == ["'unsafe-inline'"]
        else:
            assert policy["script-src"] == ["'self'"] and policy["style-src"] == ["'self'"]
            assert policy["connect-src"] == ["'self'"] and policy["form-action"] == ["'self'"]


class _Inline(HTMLParser):
    """What of a page its policy would refuse or load: inline scripts and styles, style
    and event attributes, and the addresses of scripts and stylesheets."""

    def __init__(self):
        super().__init__()
        self.inline: list[str] = []
        self.loaded: list[str] = []
        self.svgs = 0

    def handle_starttag(self, tag, attrs):
        attributes = dict(attrs)
        self.svgs += tag == "svg"
        if tag == "script":
            if not attributes.get("src"):
                self.inline.append("<script> without src")
            else:
                self.loaded.append(attributes["src"])
        if tag == "style":
            self.inline.append("<style>")
        if tag == "link" and attributes.get("rel") == "stylesheet":
            self.loaded.append(attributes["href"])
        self.inline += [f"<{tag} {name}=>" for name in attributes
                        if name == "style" or name.startswith("on")]


def test_every_page_loads_its_scripts_and_styles_from_the_server_and_nothing_inline(served):
    pages, loaded, svgs = 0, set(), 0
    for path, token, place in _get_routes(served):
        answer = _request(served, "GET", path, token, place)
        if not answer.headers["content-type"].startswith("text/html") or \
                path.endswith("/report.html"):
            continue
        found = _Inline()
        found.feed(answer.text)
        assert found.inline == [], (path, found.inline)
        assert "/static/base.css" in found.loaded, path
        loaded |= set(found.loaded)
        svgs += found.svgs
        pages += 1
    assert pages >= 7 and svgs >= 1  # the student page's figure is an inline SVG
    assert {"/static/student.js", "/static/staff.js"} <= loaded
    for address in loaded:
        asset = served.client.get(address)
        assert asset.status_code == 200, address
        kind = "text/css" if address.endswith(".css") else "text/javascript"
        assert asset.headers["content-type"].startswith(kind), address
        assert asset.headers["x-content-type-options"] == "nosniff"


def test_a_static_file_is_revalidated_by_its_etag_and_nothing_else_is_served(served):
    first = served.client.get("/static/student.js")
    again = served.client.get("/static/student.js",
                              headers={"If-None-Match": first.headers["etag"]})
    assert again.status_code == 304 and again.content == b""
    stale = served.client.get("/static/student.js", headers={"If-None-Match": '"old"'})
    assert stale.status_code == 200 and stale.content == first.content
    for name in ("nothing.js", "..%2Fapp.py", "..%2F..%2Fserve%2Fapp.py", "%2Fetc%2Fpasswd",
                 "__init__.py"):
        assert served.client.get(f"/static/{name}").status_code == 404, name


def test_head_is_answered_wherever_get_is_with_the_same_headers_and_no_body(served):
    sizes = 0
    for path, token, place in _get_routes(served):
        got = _request(served, "GET", path, token, place)
        head = _request(served, "HEAD", path, token, place)
        assert head.status_code == got.status_code == 200, path
        assert head.content == b"", path
        assert head.headers["content-type"] == got.headers["content-type"], path
        again = _request(served, "GET", path, token, place)
        if len(again.content) == len(got.content):  # not a page that lists new links
            assert head.headers["content-length"] == str(len(got.content)), path
            sizes += 1
    assert sizes >= 8
    posted_only = served.client.head("/api/v1/answers",
                                     headers={"Authorization": f"Bearer {served.tokens['s3']}"})
    assert posted_only.status_code == 405 and "POST" in posted_only.headers["allow"]


def test_a_streamed_body_over_the_limit_is_refused_with_413_and_one_under_it_is_read(served):
    from dynagrade.serve.limits import MAX_BODY_BYTES

    bearer = {"Authorization": f"Bearer {served.tokens['s3']}",
              "Content-Type": "application/json"}

    def chunks(body: bytes, size: int = 4096):
        for start in range(0, len(body), size):
            yield body[start:start + size]

    too_long = b'{"exercise": "projectile-range", "part": "x_max", "answer": "' + \
        b"1" * MAX_BODY_BYTES + b'"}'
    refused = served.client.post("/api/v1/preview", content=chunks(too_long), headers=bearer)
    assert refused.status_code == 413
    assert refused.json() == {"detail": "the request is too large"}
    fine = b'{"exercise": "projectile-range", "part": "x_max", "answer": "45 km"}'
    read = served.client.post("/api/v1/preview", content=chunks(fine, 7), headers=bearer)
    assert read.status_code == 200 and read.json()["readable"] is True
    form = served.client.post(f"/s/{served.tokens['s3']}", content=chunks(b"answer=" + b"x" *
                              (MAX_BODY_BYTES + 1)),
                              headers={"Content-Type": "application/x-www-form-urlencoded"})
    assert form.status_code == 413


def test_the_api_is_described_in_json_and_has_no_page_that_loads_scripts_from_elsewhere(served):
    assert served.client.get("/api/docs").status_code == 404
    description = served.client.get("/api/openapi.json")
    assert description.status_code == 200 and "/api/v1/answers" in description.json()["paths"]
