"""The exam's line item (its column in the platform's gradebook), bound or created.

A launch whose AGS claim names a ``lineitem`` binds the exam to it (:mod:`.launch`).
Without one, but with the ``lineitems`` URL and the line-item scope, the tool looks for
its own line item among the resource link's (``resourceId`` the exam's id) and creates
it when there is none: ``scoreMaximum`` the exam's points, ``label`` its title. Either
way the exam has one line item per platform, kept in ``lti_line_items``.
"""

from __future__ import annotations

import json

import sqlalchemy as sa

from . import access, claims, grades_store, http
from .store import Platform


def line_item_url(engine: sa.Engine, platform: Platform, member: grades_store.Member,
                  title: str, max_points: float) -> tuple[str | None, http.Answer | None]:
    """The exam's line item on ``platform`` (found, bound or made now), or None and the
    platform's answer that kept it from being made."""
    bound = grades_store.line_item(engine, member.exam_id, platform.id)
    if bound is not None:
        return bound, None
    if member.lineitem_url:
        grades_store.bind_line_item(engine, member.exam_id, platform.id, member.lineitem_url)
        return member.lineitem_url, None
    if not member.lineitems_url or claims.AGS_LINEITEM_SCOPE not in member.scopes:
        return None, None
    token = access.access_token(engine, platform, (claims.AGS_LINEITEM_SCOPE,))
    auth = {"Authorization": f"Bearer {token}"}
    query = {"resource_link_id": member.resource_link_id} if member.resource_link_id else {}
    listed = http.request("GET", http.with_query(member.lineitems_url, query),
                          {**auth, "Accept": claims.LINEITEMS_MEDIA})
    if listed.ok:
        try:
            items = listed.json()
        except ValueError:
            items = []
        mine = [i for i in items if isinstance(i, dict) and i.get("resourceId") ==
                member.exam_id and isinstance(i.get("id"), str)] \
            if isinstance(items, list) else []
        if mine:
            grades_store.bind_line_item(engine, member.exam_id, platform.id, mine[0]["id"])
            return mine[0]["id"], None
    item = {"scoreMaximum": max_points, "label": title, "resourceId": member.exam_id,
            "tag": "dynagrade"}
    if member.resource_link_id:
        item["resourceLinkId"] = member.resource_link_id
    made = http.request("POST", member.lineitems_url,
                        {**auth, "Content-Type": claims.LINEITEM_MEDIA,
                         "Accept": claims.LINEITEM_MEDIA}, json.dumps(item).encode())
    try:
        url = made.json().get("id") if made.ok else None
    except (ValueError, AttributeError):
        url = None
    if not isinstance(url, str) or not url:
        return None, made
    grades_store.bind_line_item(engine, member.exam_id, platform.id, url)
    return url, None


def scores_url(line_item: str) -> str:
    """The scores endpoint of a line item: ``/scores`` after its path, its query kept."""
    path, mark, query = line_item.partition("?")
    return f"{path.rstrip('/')}/scores{mark}{query}"
