"""A complete LTI 1.3 platform for the tests, on localhost in a thread of the test
session: its own RSA key and JWKS, OIDC login initiation (``/launch`` sends the browser
to the tool), the authorization endpoint (``/auth``: checks the tool's request, mints
the id_token, posts it back with a self-submitting form), an OAuth2 client-credentials
token endpoint (``/token``: the tool's client_assertion verified with the tool's JWKS),
AGS (line items, scores) and NRPS (memberships, two a page) endpoints, and the return
URL of deep linking (``/deep-link-return``: the tool's signed answer verified), which
record what the tool sent.

Written from the specifications (LTI 1.3 Core, Security Framework, AGS 2.0, NRPS 2.0),
as a platform would behave, not from the tool's code.
"""

from __future__ import annotations

import html
import json
import secrets
import threading
import time
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Callable
from urllib.parse import urlencode

from deferred import deferred

if TYPE_CHECKING:
    from starlette.requests import Request

# imported when the platform starts, not when the suite is collected (test_collection)
httpx = deferred("httpx")
jwt = deferred("jwt")
uvicorn = deferred("uvicorn")
serialization = deferred("cryptography.hazmat.primitives.serialization")
rsa = deferred("cryptography.hazmat.primitives.asymmetric.rsa")
Starlette = deferred("starlette.applications", "Starlette")
HTMLResponse = deferred("starlette.responses", "HTMLResponse")
JSONResponse = deferred("starlette.responses", "JSONResponse")
RedirectResponse = deferred("starlette.responses", "RedirectResponse")
Response = deferred("starlette.responses", "Response")
Route = deferred("starlette.routing", "Route")

from serve_support import free_port

LTI = "https://purl.imsglobal.org/spec/lti/claim/"
AGS = "https://purl.imsglobal.org/spec/lti-ags/"
SCORE_SCOPE = AGS + "scope/score"
LINEITEM_SCOPE = AGS + "scope/lineitem"
NRPS = "https://purl.imsglobal.org/spec/lti-nrps/"
MEMBERS_SCOPE = NRPS + "scope/contextmembership.readonly"
LEARNER = "http://purl.imsglobal.org/vocab/lis/v2/membership#Learner"
INSTRUCTOR = "http://purl.imsglobal.org/vocab/lis/v2/membership#Instructor"
CLIENT_ID = "dynagrade-test-client"
DEPLOYMENT_ID = "deployment-1"


def rsa_pem() -> str:
    key = rsa.generate_private_key(public_exponent=65537, key_size=2048)
    return key.private_bytes(serialization.Encoding.PEM, serialization.PrivateFormat.PKCS8,
                             serialization.NoEncryption()).decode()


def public_jwk(pem: str, kid: str) -> dict:
    private = serialization.load_pem_private_key(pem.encode(), None)
    jwk = json.loads(jwt.algorithms.RSAAlgorithm.to_jwk(private.public_key()))
    return {**jwk, "kid": kid, "alg": "RS256", "use": "sig"}


@dataclass
class User:
    """A platform user: their id (``sub``), name, email, ID number and roles."""

    sub: str
    name: str
    email: str
    sourcedid: str
    roles: list[str]


@dataclass
class Platform:
    """The platform's state; ``url`` once it runs, ``tool`` the tool's base URL."""

    tool: str = ""
    url: str = ""
    key: str = field(default_factory=rsa_pem)
    kid: str = "platform-key-1"
    users: dict[str, User] = field(default_factory=dict)
    #: every id_token the platform posted to the tool
    issued: list[str] = field(default_factory=list)
    #: the line items, by their URL (their id), as the tool made them or the test did
    line_items: dict[str, dict] = field(default_factory=dict)
    #: every score the platform accepted: (line item URL, body)
    scores: list[tuple[str, dict]] = field(default_factory=list)
    #: every score request, accepted or not: (status answered, body)
    score_requests: list[tuple[int, dict]] = field(default_factory=list)
    #: how many score posts to refuse (503) before accepting
    fail_scores: int = 0
    #: the line item launches name (None: none, the tool makes its own)
    lineitem: str | None = None
    #: the tool's public keys (None: fetched from the tool's /lti/jwks)
    tool_jwks: Callable[[], dict] | None = None
    #: the access tokens given, with their scopes
    tokens: dict[str, set[str]] = field(default_factory=dict)
    #: the claims of every deep-linking answer the tool posted back (verified)
    placed: list[dict] = field(default_factory=list)

    @property
    def issuer(self) -> str:
        return self.url

    def claims(self, user: User, nonce: str, **changes) -> dict:
        """The claims of a resource-link launch of ``user`` (``changes`` replace any)."""
        now = int(time.time())
        found = {
            "iss": self.issuer, "aud": CLIENT_ID, "sub": user.sub, "exp": now + 300,
            "iat": now, "nonce": nonce, "name": user.name, "email": user.email,
            LTI + "message_type": "LtiResourceLinkRequest", LTI + "version": "1.3.0",
            LTI + "deployment_id": DEPLOYMENT_ID,
            LTI + "target_link_uri": f"{self.tool}/lti/launch",
            LTI + "resource_link": {"id": "link-1", "title": "Exam"},
            LTI + "roles": user.roles,
            LTI + "context": {"id": "course-1", "label": "DYN", "title": "Dynamics"},
            LTI + "lis": {"person_sourcedid": user.sourcedid},
            AGS + "claim/endpoint": {
                "scope": [LINEITEM_SCOPE, SCORE_SCOPE, AGS + "scope/result.readonly"],
                "lineitems": f"{self.url}/lineitems",
                **({"lineitem": self.lineitem} if self.lineitem else {})},
            NRPS + "claim/namesroleservice": {
                "context_memberships_url": f"{self.url}/memberships",
                "service_versions": ["2.0"]},
        }
        found.update(changes)
        return {k: v for k, v in found.items() if v is not None}

    def sign(self, claims: dict, key: str | None = None, kid: str | None = None) -> str:
        return jwt.encode(claims, key or self.key, algorithm="RS256",
                          headers={"kid": kid or self.kid})

    def deep_linking_claims(self, user: User, nonce: str) -> dict:
        """The claims of a deep-linking request of ``user`` (the activity chooser)."""
        found = self.claims(user, nonce)
        del found[LTI + "resource_link"]
        found[LTI + "message_type"] = "LtiDeepLinkingRequest"
        found["https://purl.imsglobal.org/spec/lti-dl/claim/deep_linking_settings"] = {
            "deep_link_return_url": f"{self.url}/deep-link-return",
            "accept_types": ["ltiResourceLink"], "accept_multiple": False,
            "accept_presentation_document_targets": ["iframe", "window"],
            "data": "platform-data-42"}
        return found

    def login_initiation(self, user: str, hint: str = "link-1") -> str:
        """The URL a platform sends the browser to when ``user`` opens the activity
        (``hint`` ``deep-link``: when they add one from the activity chooser)."""
        return f"{self.tool}/lti/login?" + urlencode({
            "iss": self.issuer, "login_hint": user, "target_link_uri": f"{self.tool}/lti/launch",
            "client_id": CLIENT_ID, "lti_deployment_id": DEPLOYMENT_ID,
            "lti_message_hint": hint})

    # -- the endpoints --------------------------------------------------------------------

    async def launch(self, request: Request) -> Response:
        hint = "deep-link" if request.query_params.get("deep") else "link-1"
        return RedirectResponse(self.login_initiation(request.query_params["user"], hint), 302)

    async def course(self, request: Request) -> Response:
        """The course page: the activity in an iframe, as an LMS shows it embedded."""
        user = html.escape(request.query_params["user"])
        return HTMLResponse(f'<!doctype html><html lang="en"><head><title>Course</title>'
                            f'</head><body><main><h1>Dynamics</h1><iframe title="Exam" '
                            f'src="/launch?user={user}" width="1000" height="700"></iframe>'
                            f'</main></body></html>')

    async def jwks(self, request: Request) -> Response:
        return JSONResponse({"keys": [public_jwk(self.key, self.kid)]})

    async def auth(self, request: Request) -> Response:
        """The authorization request (OIDC implicit flow, LTI's profile of it)."""
        q = request.query_params
        expected = {"scope": "openid", "response_type": "id_token",
                    "response_mode": "form_post", "prompt": "none", "client_id": CLIENT_ID,
                    "redirect_uri": f"{self.tool}/lti/launch"}
        wrong = {k: q.get(k) for k, v in expected.items() if q.get(k) != v}
        user = self.users.get(q.get("login_hint", ""))
        if wrong or user is None or not q.get("state") or not q.get("nonce"):
            return JSONResponse({"error": "invalid_request", "wrong": wrong}, 400)
        claims = self.deep_linking_claims(user, q["nonce"]) \
            if q.get("lti_message_hint") == "deep-link" else self.claims(user, q["nonce"])
        token = self.sign(claims)
        self.issued.append(token)
        return HTMLResponse(
            f'<!doctype html><html lang="en"><head><title>Platform</title></head><body>'
            f'<form id="post" method="post" action="{html.escape(q["redirect_uri"])}">'
            f'<input type="hidden" name="id_token" value="{html.escape(token)}">'
            f'<input type="hidden" name="state" value="{html.escape(q["state"])}">'
            f'</form><script>document.getElementById("post").submit()</script>'
            f'</body></html>')

    async def token(self, request: Request) -> Response:
        """OAuth 2.0 client credentials, the client's proof a JWT it signed (RFC 7523)."""
        form = await request.form()
        if form.get("grant_type") != "client_credentials" or form.get(
                "client_assertion_type") != "urn:ietf:params:oauth:client-assertion-type:jwt-bearer":
            return JSONResponse({"error": "unsupported_grant_type"}, 400)
        assertion = str(form.get("client_assertion", ""))
        try:
            found = jwt.decode(assertion, self.tool_key(assertion), algorithms=["RS256"],
                               audience=f"{self.url}/token", issuer=CLIENT_ID,
                               options={"require": ["exp", "iat", "jti", "sub"]})
        except (jwt.PyJWTError, KeyError, StopIteration):
            return JSONResponse({"error": "invalid_client"}, 401)
        if found["sub"] != CLIENT_ID:
            return JSONResponse({"error": "invalid_client"}, 401)
        scopes = set(str(form.get("scope", "")).split())
        if not scopes <= {LINEITEM_SCOPE, SCORE_SCOPE, MEMBERS_SCOPE}:
            return JSONResponse({"error": "invalid_scope"}, 400)
        token = secrets.token_urlsafe(16)
        self.tokens[token] = scopes
        return JSONResponse({"access_token": token, "token_type": "Bearer",
                             "expires_in": 3600, "scope": " ".join(sorted(scopes))})

    def tool_key(self, token: str):
        """The tool's public key that signed ``token`` (KeyError: none of its keys)."""
        keys = self.tool_jwks() if self.tool_jwks else \
            httpx.get(f"{self.tool}/lti/jwks", timeout=10).json()
        kid = jwt.get_unverified_header(token)["kid"]
        return jwt.PyJWK(next(k for k in keys["keys"] if k["kid"] == kid)).key

    async def deep_link_return(self, request: Request) -> Response:
        """The tool's deep-linking answer: a JWT it signed, audience this platform."""
        token = str((await request.form()).get("JWT", ""))
        try:
            found = jwt.decode(token, self.tool_key(token), algorithms=["RS256"],
                               audience=self.issuer, issuer=CLIENT_ID,
                               options={"require": ["exp", "iat", "nonce"]})
        except (jwt.PyJWTError, KeyError, StopIteration):
            return HTMLResponse("<p>refused</p>", 400)
        self.placed.append(found)
        titles = ", ".join(html.escape(i.get("title", "")) for i in found.get(
            "https://purl.imsglobal.org/spec/lti-dl/claim/content_items", []))
        return HTMLResponse(f'<!doctype html><html lang="en"><head><title>Placed</title>'
                            f'</head><body><main><h1>Placed: {titles}</h1></main></body></html>')

    def _granted(self, request: Request, scope: str) -> bool:
        given = request.headers.get("authorization", "").removeprefix("Bearer ")
        return scope in self.tokens.get(given, set())

    async def line_items_endpoint(self, request: Request) -> Response:
        if not self._granted(request, LINEITEM_SCOPE):
            return JSONResponse({"error": "unauthorized"}, 401)
        if request.method == "GET":
            link = request.query_params.get("resource_link_id")
            return JSONResponse([i for i in self.line_items.values()
                                 if link is None or i.get("resourceLinkId") == link],
                                media_type="application/vnd.ims.lis.v2.lineitemcontainer+json")
        item = await request.json()
        item["id"] = f"{self.url}/lineitems/{len(self.line_items) + 1}"
        self.line_items[item["id"]] = item
        return JSONResponse(item, 201, media_type="application/vnd.ims.lis.v2.lineitem+json")

    async def score_endpoint(self, request: Request) -> Response:
        line_item = f"{self.url}/lineitems/{request.path_params['n']}"
        if not self._granted(request, SCORE_SCOPE):
            return JSONResponse({"error": "unauthorized"}, 401)
        if request.headers.get("content-type") != "application/vnd.ims.lis.v1.score+json" \
                or line_item not in self.line_items:
            return JSONResponse({"error": "bad request"}, 400)
        body = await request.json()
        if self.fail_scores > 0:
            self.fail_scores -= 1
            self.score_requests.append((503, body))
            return JSONResponse({"error": "busy, try later"}, 503)
        self.score_requests.append((200, body))
        self.scores.append((line_item, body))
        return Response(status_code=204)

    async def memberships(self, request: Request) -> Response:
        """The course's members, two a page (``Link: <…>; rel="next"``)."""
        if not self._granted(request, MEMBERS_SCOPE):
            return JSONResponse({"error": "unauthorized"}, 401)
        page = int(request.query_params.get("page", "0"))
        users = list(self.users.values())
        members = [{"user_id": u.sub, "name": u.name, "email": u.email,
                    "lis_person_sourcedid": u.sourcedid, "roles": u.roles, "status": "Active"}
                   for u in users[2 * page:2 * page + 2]]
        headers = {"Link": f'<{self.url}/memberships?page={page + 1}>; rel="next"'} \
            if 2 * page + 2 < len(users) else {}
        return JSONResponse({"id": f"{self.url}/memberships",
                             "context": {"id": "course-1", "label": "DYN"},
                             "members": members}, headers=headers,
                            media_type="application/vnd.ims.lti-nrps.v2.membershipcontainer+json")

    def app(self) -> Starlette:
        return Starlette(routes=[
            Route("/launch", self.launch), Route("/course", self.course),
            Route("/jwks", self.jwks), Route("/auth", self.auth),
            Route("/token", self.token, methods=["POST"]),
            Route("/lineitems", self.line_items_endpoint, methods=["GET", "POST"]),
            Route("/lineitems/{n}/scores", self.score_endpoint, methods=["POST"]),
            Route("/memberships", self.memberships),
            Route("/deep-link-return", self.deep_link_return, methods=["POST"])])


@dataclass
class Running:
    platform: Platform
    server: uvicorn.Server
    thread: threading.Thread


def start(platform: Platform) -> Running:
    """``platform`` served on a free loopback port in a thread (until :func:`stop`)."""
    port = free_port()
    platform.url = f"http://127.0.0.1:{port}"
    server = uvicorn.Server(uvicorn.Config(platform.app(), host="127.0.0.1", port=port,
                                           log_level="warning", lifespan="off"))
    thread = threading.Thread(target=server.run, daemon=True)
    thread.start()
    for _ in range(200):
        if server.started:
            break
        time.sleep(0.02)
    return Running(platform, server, thread)


def stop(running: Running) -> None:
    running.server.should_exit = True
    running.thread.join(timeout=10)


def with_users(platform: Platform) -> Platform:
    """The test roster as platform users (serve_support.ROSTER: s1, s2 with their
    emails), a stranger who is on no roster, and an instructor."""
    for user in (User("u-ada", "Ada One", "ada@example.org", "s1", [LEARNER]),
                 User("u-bo", "Bo Two", "BO@example.org", "s2", [LEARNER]),
                 User("u-zed", "Zed Stranger", "zed@example.org", "s9", [LEARNER]),
                 User("u-prof", "Pat Professor", "pat@example.org", "", [INSTRUCTOR])):
        platform.users[user.sub] = user
    return platform


def new_state() -> str:
    return secrets.token_urlsafe(8)
