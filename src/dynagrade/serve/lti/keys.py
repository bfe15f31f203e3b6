"""The tool's own RSA key pair, its rotation, and its public JWKS (``GET /lti/jwks``).

The keys live in the database (``lti_keys``), not in a file: every worker process and
every command reaches the same keys wherever the database is (SQLite file of mode 600,
or PostgreSQL), and a backup of the database is a backup of the keys. The newest
unretired key signs (client assertions, deep-linking responses); every unretired key is
published, so a platform that cached the old JWKS still checks what the old key signed.
Rotation therefore takes two steps: :func:`rotate` adds a key that signs from then on,
and, once the platforms have fetched the JWKS again (a day is plenty), :func:`retire`
withdraws the old ones.
"""

from __future__ import annotations

import json
import secrets

import jwt
import sqlalchemy as sa
from cryptography.hazmat.primitives import serialization
from cryptography.hazmat.primitives.asymmetric import rsa

from . import store

KEY_BITS = 2048


def _new_pem() -> str:
    key = rsa.generate_private_key(public_exponent=65537, key_size=KEY_BITS)
    return key.private_bytes(serialization.Encoding.PEM, serialization.PrivateFormat.PKCS8,
                             serialization.NoEncryption()).decode("ascii")


def rotate(engine: sa.Engine) -> str:
    """A new key pair that signs from now on (the older ones stay published); its kid."""
    kid = secrets.token_hex(8)
    store.add_key(engine, kid, _new_pem())
    return kid


def signing_key(engine: sa.Engine) -> store.StoredKey:
    """The key that signs: the newest unretired one, made on first use."""
    live = store.live_keys(engine)
    if not live:
        rotate(engine)
        live = store.live_keys(engine)
    return live[-1]


def retire(engine: sa.Engine) -> list[str]:
    """Withdraw every key but the one that signs; the kids withdrawn."""
    current = signing_key(engine).kid
    old = [key.kid for key in store.live_keys(engine) if key.kid != current]
    store.retire_keys(engine, old)
    return old


def public_jwk(stored: store.StoredKey) -> dict:
    """The public half of ``stored`` as a JWK (RFC 7517), with its kid and use."""
    private = serialization.load_pem_private_key(stored.private_pem.encode(), None)
    if not isinstance(private, rsa.RSAPrivateKey):  # only this module stores keys
        raise TypeError(f"tool key {stored.kid} is not an RSA key")
    jwk = json.loads(jwt.algorithms.RSAAlgorithm.to_jwk(private.public_key()))
    return {**jwk, "kid": stored.kid, "alg": "RS256", "use": "sig"}


def jwks(engine: sa.Engine) -> dict:
    """The tool's public key set: every unretired key."""
    signing_key(engine)  # a tool that was never asked for a key has one now
    return {"keys": [public_jwk(key) for key in store.live_keys(engine)]}


def sign(engine: sa.Engine, claims: dict) -> str:
    """``claims`` as a JWT signed RS256 by the signing key (its kid in the header)."""
    key = signing_key(engine)
    return jwt.encode(claims, key.private_pem, algorithm="RS256",
                      headers={"kid": key.kid, "typ": "JWT"})
