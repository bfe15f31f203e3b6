"""Which roster student a launching user is, by the claim the platform's registration
names (``user_claim``):

- ``email``: the id_token's ``email`` is the roster row's email (letter case aside);
- ``sub``: the platform's own user id (``sub``) is the roster row's student id;
- ``sourcedid``: the LIS person sourcedid (Moodle sends the user's "ID number" there)
  is the roster row's student id.

A user whom the claim does not find (or whose token lacks it) is on no roster row.
"""

from __future__ import annotations

from typing import Mapping

from . import claims


def claimed_value(found: dict, user_claim: str) -> str:
    """The value of ``user_claim`` in the id_token's claims (``""``: absent)."""
    if user_claim == "email":
        value = found.get("email")
    elif user_claim == "sub":
        value = found.get("sub")
    else:
        lis = found.get(claims.LIS)
        value = lis.get("person_sourcedid") if isinstance(lis, dict) else None
    return value.strip() if isinstance(value, str) else ""


def roster_student(students: Mapping[str, object], found: dict, user_claim: str) -> str | None:
    """The id of the roster student the launch's ``user_claim`` names, or None."""
    value = claimed_value(found, user_claim)
    if not value:
        return None
    if user_claim == "email":
        wanted = value.casefold()
        return next((sid for sid, s in students.items()
                     if str(getattr(s, "email", "")).strip().casefold() == wanted), None)
    return value if value in students else None
