"""The id_token's claims (LTI 1.3 Core, section 5) and what their roles mean here.

A launch's roles are IRIs of the LIS vocabulary (``http://purl.imsglobal.org/vocab/lis/
v2/membership#Instructor``) or, as the specification still allows, their short names
(``Instructor``, a role in the course). The course's instructors and teaching
assistants are staff, and so are administrators (of the course, the institution or the
system); the course's learners are students; anyone else is neither and is refused.
An institution role other than administrator says nothing about this course: a learner
who teaches elsewhere (``institution/person#Instructor``) is a student here.
"""

from __future__ import annotations

LTI = "https://purl.imsglobal.org/spec/lti/claim/"
MESSAGE_TYPE = LTI + "message_type"
VERSION = LTI + "version"
DEPLOYMENT_ID = LTI + "deployment_id"
TARGET_LINK_URI = LTI + "target_link_uri"
RESOURCE_LINK = LTI + "resource_link"
ROLES = LTI + "roles"
CONTEXT = LTI + "context"
LIS = LTI + "lis"
CUSTOM = LTI + "custom"

RESOURCE_LINK_REQUEST = "LtiResourceLinkRequest"
DEEP_LINKING_REQUEST = "LtiDeepLinkingRequest"
DEEP_LINKING_RESPONSE = "LtiDeepLinkingResponse"
#: the messages a launch may carry
LAUNCH_MESSAGES = (RESOURCE_LINK_REQUEST, DEEP_LINKING_REQUEST)
LTI_VERSION = "1.3.0"

LIS_ROLES = "http://purl.imsglobal.org/vocab/lis/v2/"
#: the course's roles (context roles) that make their holder staff, by their last word
STAFF_ROLES = frozenset({"Instructor", "TeachingAssistant", "Administrator"})
STUDENT_ROLES = frozenset({"Learner"})

STAFF, STUDENT = "staff", "student"


def role_name(role: str) -> str:
    """The last word of a role: ``...membership/Instructor#TeachingAssistant`` ->
    ``TeachingAssistant``, ``Learner`` -> ``Learner``."""
    return role.rsplit("#", 1)[-1].rsplit("/", 1)[-1]


def in_course(role: str) -> bool:
    """Whether ``role`` is a role in the course (a membership role, or a short name)."""
    return role.startswith(LIS_ROLES + "membership") or ("/" not in role and ":" not in role)


def role_of(roles: object) -> str | None:
    """``"staff"``, ``"student"`` or None (no role this tool admits) for a launch's
    roles claim; staff when the holder is both."""
    held = [r for r in roles if isinstance(r, str)] if isinstance(roles, list) else []
    course = {role_name(r) for r in held if in_course(r)}
    anywhere = {role_name(r) for r in held}
    if course & STAFF_ROLES or "Administrator" in anywhere:
        return STAFF
    if course & STUDENT_ROLES:
        return STUDENT
    return None


# -- Assignment and Grade Services (AGS 2.0) ----------------------------------------------

AGS_ENDPOINT = "https://purl.imsglobal.org/spec/lti-ags/claim/endpoint"
AGS_LINEITEM_SCOPE = "https://purl.imsglobal.org/spec/lti-ags/scope/lineitem"
AGS_RESULT_SCOPE = "https://purl.imsglobal.org/spec/lti-ags/scope/result.readonly"
AGS_SCORE_SCOPE = "https://purl.imsglobal.org/spec/lti-ags/scope/score"
LINEITEM_MEDIA = "application/vnd.ims.lis.v2.lineitem+json"
LINEITEMS_MEDIA = "application/vnd.ims.lis.v2.lineitemcontainer+json"
SCORE_MEDIA = "application/vnd.ims.lis.v1.score+json"

# -- Names and Role Provisioning Services (NRPS 2.0) --------------------------------------

NRPS_CLAIM = "https://purl.imsglobal.org/spec/lti-nrps/claim/namesroleservice"
NRPS_SCOPE = "https://purl.imsglobal.org/spec/lti-nrps/scope/contextmembership.readonly"
MEMBERSHIPS_MEDIA = "application/vnd.ims.lti-nrps.v2.membershipcontainer+json"

# -- Deep Linking 2.0 ---------------------------------------------------------------------

DL = "https://purl.imsglobal.org/spec/lti-dl/claim/"
DL_SETTINGS = DL + "deep_linking_settings"
DL_CONTENT_ITEMS = DL + "content_items"
DL_DATA = DL + "data"
