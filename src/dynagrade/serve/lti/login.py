"""OIDC third-party login initiation (LTI 1.3 Core 4.1, Security Framework 5.1.1).

The platform sends the browser here with ``iss``, ``login_hint``, ``target_link_uri``
(and ``client_id``, ``lti_message_hint``, ``lti_deployment_id``); the tool answers with
a redirect to the platform's authorization URL, carrying a fresh ``state`` and
``nonce``. Both are stored (the state as its sha256) for :data:`LOGIN_SECONDS` and used
once; the state is also set as a cookie, so that the id_token posted back is accepted
only in the browser that began the login.
"""

from __future__ import annotations

import datetime as dt
import secrets
from dataclasses import dataclass
from urllib.parse import urlencode, urlsplit

import sqlalchemy as sa

from ...i18n import _
from . import store
from .refusals import LaunchRefused

#: how long a login may take from initiation to the id_token posted back (seconds)
LOGIN_SECONDS = 600
#: the cookie that binds the state to the browser that began the login
STATE_COOKIE = "dynagrade_lti_state"


@dataclass(frozen=True)
class Login:
    """Where to send the browser, and the state to set as its cookie."""

    redirect: str
    state: str


def initiate(engine: sa.Engine, params: dict[str, str], launch_url: str,
             now: dt.datetime) -> Login:
    """The redirect to the platform's authorization URL for a login initiation's
    ``params``; :class:`LaunchRefused` (400) for an unknown platform or a target that is
    not this tool."""
    issuer, hint = params.get("iss", ""), params.get("login_hint", "")
    platform = store.find_platform(engine, issuer, params.get("client_id") or None) \
        if issuer else None
    if platform is None:
        raise LaunchRefused(_("this course platform is not registered with the exam "
                              "server; ask the course staff"), 400)
    target = params.get("target_link_uri", "")
    if not hint or urlsplit(target).netloc != urlsplit(launch_url).netloc:
        raise LaunchRefused(_("the sign-in request is incomplete or names another tool"),
                            400)
    state, nonce = secrets.token_urlsafe(32), secrets.token_urlsafe(24)
    store.add_login(engine, state, nonce, platform.id,
                    now + dt.timedelta(seconds=LOGIN_SECONDS))
    query = {"scope": "openid", "response_type": "id_token", "response_mode": "form_post",
             "prompt": "none", "client_id": platform.client_id, "redirect_uri": launch_url,
             "login_hint": hint, "state": state, "nonce": nonce}
    if params.get("lti_message_hint"):
        query["lti_message_hint"] = params["lti_message_hint"]
    separator = "&" if "?" in platform.auth_login_url else "?"
    return Login(f"{platform.auth_login_url}{separator}{urlencode(query)}", state)
