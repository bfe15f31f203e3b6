"""The tool's side of the LTI tests: the app under a TestClient over HTTPS (its cookies
are Secure) with the test platform registered, and a launch driven step by step."""

from __future__ import annotations

from contextlib import contextmanager
from urllib.parse import parse_qs, urlsplit

import pytest

from lti_platform import CLIENT_ID, DEPLOYMENT_ID, Platform, start, stop, with_users

TOOL = "https://testserver"


@pytest.fixture(scope="module")
def platform():
    """The test platform, running, its users the test roster's (and two more)."""
    running = start(with_users(Platform(tool=TOOL)))
    yield running.platform
    stop(running)


@contextmanager
def tool(manifest, db_url, platform: Platform, user_claim: str = "email", clock=None):
    """The tool (a TestClient over HTTPS: the cookies are Secure) with ``platform``
    registered; the platform reads the tool's keys in process (it cannot reach a
    TestClient's address)."""
    from fastapi.testclient import TestClient

    from dynagrade.serve.app import create_app
    from dynagrade.serve.lti import keys, store

    app = create_app(manifest, db_url, grading_workers=1, clock=clock)
    engine = app.state.server.engine
    platform.tool_jwks = lambda: keys.jwks(engine)
    store.register(engine, platform.issuer, CLIENT_ID, [DEPLOYMENT_ID],
                   f"{platform.url}/auth", f"{platform.url}/token", f"{platform.url}/jwks",
                   user_claim)
    with TestClient(app, base_url=TOOL) as client:
        yield client


def begin(client, platform: Platform, user: str) -> tuple[str, str]:
    """A login initiation of ``user``: the state and nonce the tool sent to the
    platform's authorization URL (the state cookie is now in the client)."""
    answer = client.get(platform.login_initiation(user), follow_redirects=False)
    assert answer.status_code == 303, answer.text
    location = answer.headers["location"]
    assert location.startswith(f"{platform.url}/auth?")
    query = {k: v[0] for k, v in parse_qs(urlsplit(location).query).items()}
    assert query["redirect_uri"] == f"{TOOL}/lti/launch"
    assert query["client_id"] == CLIENT_ID and query["login_hint"] == user
    return query["state"], query["nonce"]


def post_launch(client, token: str, state: str):
    return client.post("/lti/launch", data={"id_token": token, "state": state},
                       follow_redirects=False)


def launch_as(client, platform: Platform, user: str, **changes):
    """A launch of ``user`` whose id_token carries ``changes`` to the platform's claims
    (a change to None leaves the claim out)."""
    state, nonce = begin(client, platform, user)
    claims = {**platform.claims(platform.users[user], nonce), **changes}
    token = platform.sign({k: v for k, v in claims.items() if v is not None})
    return post_launch(client, token, state)
