"""The platform's id_token checked, as LTI 1.3 Core (5.1.3) and the Security Framework
(5.1.3) require, before anything in it is believed:

1. its signature is RS256 by a key of the platform's JWKS (fetched, cached, and fetched
   again when the token names a kid the cache does not hold);
2. ``iss`` is the platform's issuer, ``aud`` holds the tool's client id, and ``azp``,
   where given (it must be when ``aud`` holds several), is that client id;
3. ``exp`` has not passed and ``iat`` is not in the future (one minute of leeway for
   clocks);
4. ``nonce`` is the one this tool gave the login that the state names;
5. the deployment is one the platform registered, the message a resource-link launch
   or a deep-linking request, the LTI version 1.3.0.

A token failing any of these is refused (:class:`.refusals.LaunchRefused`, 401).
"""

from __future__ import annotations

import threading

import jwt

from ...i18n import _
from . import claims
from .refusals import LaunchRefused
from .store import Platform

LEEWAY_SECONDS = 60
#: how long a platform's JWKS is believed before it is fetched again (seconds)
JWKS_LIFESPAN = 3600

_clients: dict[str, jwt.PyJWKClient] = {}
_clients_lock = threading.Lock()


def platform_keys(jwks_url: str) -> jwt.PyJWKClient:
    """The cached key set of the platform at ``jwks_url`` (one client per URL and
    process; an unknown kid makes it fetch the set again)."""
    with _clients_lock:
        client = _clients.get(jwks_url)
        if client is None:
            client = _clients[jwks_url] = jwt.PyJWKClient(
                jwks_url, cache_keys=True, lifespan=JWKS_LIFESPAN, timeout=10)
        return client


def verified_claims(id_token: str, platform: Platform, nonce: str,
                    messages: tuple[str, ...] = claims.LAUNCH_MESSAGES) -> dict:
    """The claims of ``id_token`` once every check of the module holds."""
    refused = LaunchRefused(_("the sign-in from the course platform could not be "
                              "verified; open the activity from the course again"))
    try:
        key = platform_keys(platform.jwks_url).get_signing_key_from_jwt(id_token)
        found = jwt.decode(id_token, key.key, algorithms=["RS256"],
                           audience=platform.client_id, issuer=platform.issuer,
                           leeway=LEEWAY_SECONDS,
                           options={"require": ["exp", "iat", "iss", "aud", "sub", "nonce"]})
    except (jwt.PyJWTError, jwt.PyJWKClientError) as error:
        raise refused from error
    audience = found["aud"] if isinstance(found["aud"], list) else [found["aud"]]
    if (len(audience) > 1 or "azp" in found) and found.get("azp") != platform.client_id:
        raise refused
    if found["nonce"] != nonce:
        raise refused
    if found.get(claims.DEPLOYMENT_ID) not in platform.deployment_ids:
        raise refused
    if found.get(claims.MESSAGE_TYPE) not in messages \
            or found.get(claims.VERSION) != claims.LTI_VERSION:
        raise refused
    return found
