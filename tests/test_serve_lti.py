"""LTI 1.3 launches against the test platform (tests/lti_platform.py, on localhost):
a learner's launch opens their page by the session cookie alone, an instructor's the
staff page; forged tokens are refused, one test each (wrong key, wrong audience,
replayed nonce, expired, wrong deployment, wrong issuer, missing nonce); a user not on
the roster gets a page that says so; launched pages alone may be framed, by the
platform alone; the tool's keys rotate with the old one still published; on SQLite and
PostgreSQL."""

from __future__ import annotations

import time

import pytest

from lti_platform import CLIENT_ID, rsa_pem
from lti_support import TOOL, begin, launch_as, platform, post_launch, tool  # noqa: F401
from serve_support import database, exam_copy, exam_dir, postgres_url  # noqa: F401


@pytest.fixture(scope="module")
def manifest(exam_dir, tmp_path_factory):
    return exam_copy(exam_dir, tmp_path_factory.mktemp("lti") / "exam", mode="homework",
                     feedback="immediate")


def refused(answer) -> None:
    """The launch was refused with a page and started no session."""
    assert answer.status_code == 401, answer.text
    assert "could not be verified" in answer.text
    assert "dynagrade_lti=" not in answer.headers.get("set-cookie", "")


# -- launches that work -------------------------------------------------------------------


def test_a_learner_s_launch_opens_their_page_by_the_session_cookie(manifest, database,
                                                                   platform):
    with tool(manifest, database, platform) as client:
        answer = launch_as(client, platform, "u-ada")
        assert answer.status_code == 303, answer.text
        page_path = answer.headers["location"]
        assert page_path.startswith("/s/lti-")
        cookie = next(c for c in answer.headers.get_list("set-cookie")
                      if c.startswith("dynagrade_lti="))
        flags = {part.strip().lower() for part in cookie.split(";")[1:]}
        assert {"secure", "httponly", "samesite=none"} <= flags
        page = client.get(page_path)
        assert page.status_code == 200
        assert "Ada One" in page.text  # s1 of the roster, found by her email
        # the API takes the handle as its bearer token, with the cookie
        handle = page_path.split("/")[2]
        drafts = client.put("/api/v1/drafts", headers={"Authorization": f"Bearer {handle}"},
                            json={"exercise": "projectile-range", "answers": {"x_max": "1 m"}})
        assert drafts.status_code == 200, drafts.text
        # the handle without the cookie opens nothing; nor does the cookie with another
        session = client.cookies.get("dynagrade_lti")
        client.cookies.delete("dynagrade_lti")
        assert client.get(page_path).status_code == 401
        client.cookies.set("dynagrade_lti", session)
        assert client.get("/s/lti-" + "0" * 40).status_code == 401


def test_a_secret_link_keeps_working_beside_launches(manifest, platform):
    from dynagrade.serve import db

    with tool(manifest, None, platform) as client:
        server = client.app.state.server
        token = db.issue_tokens(server.engine, server.data.exam_id, ["s3"], rotate=True)["s3"]
        assert launch_as(client, platform, "u-bo").status_code == 303
        page = client.get(f"/s/{token}")
        assert page.status_code == 200 and "Cy Three" in page.text


def test_an_email_is_matched_whatever_its_letter_case(manifest, platform):
    with tool(manifest, None, platform) as client:
        answer = launch_as(client, platform, "u-bo")  # BO@example.org; roster bo@...
        assert answer.status_code == 303
        assert "Bo Two" in client.get(answer.headers["location"]).text


def test_the_lis_sourcedid_finds_the_student_by_id_number(manifest, platform):
    with tool(manifest, None, platform, user_claim="sourcedid") as client:
        answer = launch_as(client, platform, "u-bo", email="elsewhere@example.org")
        assert answer.status_code == 303
        assert "Bo Two" in client.get(answer.headers["location"]).text


def test_an_instructor_s_launch_opens_the_staff_page(manifest, platform):
    with tool(manifest, None, platform) as client:
        answer = launch_as(client, platform, "u-prof")
        assert answer.status_code == 303
        assert answer.headers["location"].startswith("/i/lti-")
        assert client.get(answer.headers["location"]).status_code == 200


def test_a_learner_not_on_the_roster_gets_a_page_saying_so(manifest, platform):
    with tool(manifest, None, platform) as client:
        answer = launch_as(client, platform, "u-zed")
        assert answer.status_code == 403
        assert "not on this exam&#39;s roster" in answer.text  # escaped as HTML
        assert "zed@example.org" in answer.text
        assert "dynagrade_lti=" not in answer.headers.get("set-cookie", "")


def test_a_launch_without_a_role_of_the_course_is_refused(manifest, platform):
    with tool(manifest, None, platform) as client:
        guest = "http://purl.imsglobal.org/vocab/lis/v2/membership#Mentor"
        answer = launch_as(client, platform, "u-ada", **{
            "https://purl.imsglobal.org/spec/lti/claim/roles": [guest]})
        assert answer.status_code == 403 and "gives no access" in answer.text


# -- forged or stale tokens, one test each ------------------------------------------------


def test_a_token_signed_by_another_key_is_refused(manifest, platform):
    with tool(manifest, None, platform) as client:
        state, nonce = begin(client, platform, "u-ada")
        claims = platform.claims(platform.users["u-ada"], nonce)
        refused(post_launch(client, platform.sign(claims, key=rsa_pem()), state))


def test_a_token_for_another_audience_is_refused(manifest, platform):
    with tool(manifest, None, platform) as client:
        refused(launch_as(client, platform, "u-ada", aud="another-tool"))


def test_a_replayed_nonce_is_refused(manifest, platform):
    with tool(manifest, None, platform) as client:
        state, nonce = begin(client, platform, "u-ada")
        token = platform.sign(platform.claims(platform.users["u-ada"], nonce))
        assert post_launch(client, token, state).status_code == 303
        # the same id_token again: with its own state (used up), then with a fresh one
        assert post_launch(client, token, state).status_code == 401
        fresh, _ = begin(client, platform, "u-ada")
        refused(post_launch(client, token, fresh))


def test_an_expired_token_is_refused(manifest, platform):
    with tool(manifest, None, platform) as client:
        now = int(time.time())
        refused(launch_as(client, platform, "u-ada", iat=now - 900, exp=now - 300))


def test_a_token_of_another_deployment_is_refused(manifest, platform):
    with tool(manifest, None, platform) as client:
        refused(launch_as(client, platform, "u-ada", **{
            "https://purl.imsglobal.org/spec/lti/claim/deployment_id": "deployment-2"}))


def test_a_token_of_another_issuer_is_refused(manifest, platform):
    with tool(manifest, None, platform) as client:
        refused(launch_as(client, platform, "u-ada", iss="https://elsewhere.example"))


def test_a_token_without_a_nonce_is_refused(manifest, platform):
    with tool(manifest, None, platform) as client:
        refused(launch_as(client, platform, "u-ada", nonce=None))


def test_a_launch_without_the_state_cookie_is_refused(manifest, platform):
    with tool(manifest, None, platform) as client:
        state, nonce = begin(client, platform, "u-ada")
        client.cookies.clear()
        token = platform.sign(platform.claims(platform.users["u-ada"], nonce))
        answer = post_launch(client, token, state)
        assert answer.status_code == 401 and "another browser window" in answer.text


def test_a_login_from_an_unregistered_platform_is_refused(manifest, platform):
    with tool(manifest, None, platform) as client:
        answer = client.get("/lti/login", params={
            "iss": "https://unknown.example", "login_hint": "u-ada",
            "target_link_uri": f"{TOOL}/lti/launch"}, follow_redirects=False)
        assert answer.status_code == 400 and "not registered" in answer.text


def test_a_login_by_post_is_answered_as_by_get(manifest, platform):
    with tool(manifest, None, platform) as client:
        answer = client.post("/lti/login", data={
            "iss": platform.issuer, "login_hint": "u-ada", "client_id": CLIENT_ID,
            "target_link_uri": f"{TOOL}/lti/launch"}, follow_redirects=False)
        assert answer.status_code == 303
        assert answer.headers["location"].startswith(f"{platform.url}/auth?")


# -- framing ------------------------------------------------------------------------------


def test_only_launched_pages_may_be_framed_and_only_by_the_platform(manifest, platform):
    with tool(manifest, None, platform) as client:
        page = client.get(launch_as(client, platform, "u-ada").headers["location"])
        policy = page.headers["content-security-policy"]
        assert f"frame-ancestors {platform.url}" in policy
        assert "x-frame-options" not in page.headers
        elsewhere = client.get("/healthz")
        assert "frame-ancestors 'none'" in elsewhere.headers["content-security-policy"]
        assert elsewhere.headers["x-frame-options"] == "DENY"


# -- the tool's keys ----------------------------------------------------------------------


def test_a_rotated_key_signs_while_the_old_one_stays_published_until_retired(manifest,
                                                                              platform):
    import jwt

    from dynagrade.serve.lti import keys

    with tool(manifest, None, platform) as client:
        engine = client.app.state.server.engine
        first = {k["kid"] for k in client.get("/lti/jwks").json()["keys"]}
        assert len(first) == 1
        new = keys.rotate(engine)
        published = {k["kid"]: k for k in client.get("/lti/jwks").json()["keys"]}
        assert set(published) == first | {new}
        signed = keys.sign(engine, {"iss": "tool", "aud": "x"})
        assert jwt.get_unverified_header(signed)["kid"] == new
        public = jwt.PyJWK(published[new]).key
        assert jwt.decode(signed, public, algorithms=["RS256"], audience="x")["iss"] == "tool"
        assert keys.retire(engine) == sorted(first)
        assert [k["kid"] for k in client.get("/lti/jwks").json()["keys"]] == [new]


def test_roles_map_to_staff_and_students():
    from dynagrade.serve.lti.claims import role_of

    lis = "http://purl.imsglobal.org/vocab/lis/v2/"
    assert role_of([lis + "membership#Learner"]) == "student"
    assert role_of([lis + "membership#Instructor"]) == "staff"
    assert role_of([lis + "membership/Instructor#TeachingAssistant"]) == "staff"
    assert role_of([lis + "institution/person#Administrator"]) == "staff"
    assert role_of(["Learner", lis + "membership#Instructor"]) == "staff"
    assert role_of(["Learner"]) == "student"
    assert role_of([lis + "membership#Mentor"]) is None
    assert role_of("Learner") is None  # not a list: no roles at all
    # teaching elsewhere makes no one staff here; administering the system does
    assert role_of([lis + "institution/person#Instructor",
                    lis + "membership#Learner"]) == "student"
    assert role_of([lis + "institution/person#Instructor"]) is None
    assert role_of([lis + "system/person#Administrator"]) == "staff"


def test_a_canvas_registration_lets_the_school_s_canvas_frame_launched_pages(tmp_path):
    from dynagrade.serve import db
    from dynagrade.serve.lti import store
    from dynagrade.serve.lti.framing import PlatformOrigins

    engine = db.connect(f"sqlite:///{tmp_path / 'framing.sqlite3'}")
    store.register(engine, "https://canvas.instructure.com", "1000", ["d1"],
                   "https://sso.canvaslms.com/api/lti/authorize_redirect",
                   "https://school.instructure.com/login/oauth2/token",
                   "https://sso.canvaslms.com/api/lti/security/jwks", "email")
    assert PlatformOrigins(engine)() == ("https://canvas.instructure.com",
                                         "https://school.instructure.com",
                                         "https://sso.canvaslms.com")
