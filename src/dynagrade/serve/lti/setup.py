"""The values a platform's registration form asks for, from the tool's public URL.

Moodle ("Site administration → Plugins → Activity modules → External tool → Manage
tools → configure a tool manually") asks for the tool URL, the public keyset URL, the
initiate login URL, the redirection URI(s) and (deep linking) the content selection
URL; Canvas (Developer Keys → LTI key) takes the same values, or all at once as a JSON
configuration (:func:`canvas_json`).
docs/lti.md walks through both forms.
"""

from __future__ import annotations

from dataclasses import dataclass

from . import claims

TITLE = "dynagrade"

#: the services the tool asks for (the LTI Advantage scopes it may be granted): line
#: items and scores (AGS), the course's members (NRPS)
SCOPES: tuple[str, ...] = (claims.AGS_LINEITEM_SCOPE, claims.AGS_SCORE_SCOPE,
                           claims.NRPS_SCOPE)


@dataclass(frozen=True)
class ToolUrls:
    """The tool's addresses under its public base URL."""

    base: str

    @property
    def tool_url(self) -> str:
        return f"{self.base}/lti/launch"

    @property
    def login_url(self) -> str:
        return f"{self.base}/lti/login"

    @property
    def redirect_uris(self) -> tuple[str, ...]:
        return (self.tool_url,)

    @property
    def jwks_url(self) -> str:
        return f"{self.base}/lti/jwks"

    @property
    def deep_linking_url(self) -> str:
        """Where the activity chooser's requests go (the launch URL takes both kinds)."""
        return self.tool_url

    def fields(self) -> list[tuple[str, str]]:
        """(form field, value) in the order Moodle's form asks for them."""
        return [("Tool URL", self.tool_url),
                ("Public key type", "Keyset URL"),
                ("Public keyset URL", self.jwks_url),
                ("Initiate login URL", self.login_url),
                ("Redirection URI(s)", "\n".join(self.redirect_uris)),
                ("Content Selection URL (deep linking)", self.deep_linking_url)]


def canvas_json(urls: ToolUrls, description: str) -> dict:
    """The JSON configuration Canvas's LTI key accepts ("Method: Paste JSON")."""
    return {
        "title": TITLE,
        "description": description,
        "oidc_initiation_url": urls.login_url,
        "target_link_uri": urls.tool_url,
        "public_jwk_url": urls.jwks_url,
        "scopes": list(SCOPES),
        "extensions": [{
            "platform": "canvas.instructure.com",
            "privacy_level": "public",
            "settings": {"placements": [
                {"placement": placement, "message_type": "LtiDeepLinkingRequest",
                 "target_link_uri": urls.deep_linking_url, "text": TITLE}
                for placement in ("link_selection", "assignment_selection")]},
        }],
        "custom_fields": {},
    }
