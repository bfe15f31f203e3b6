"""The audit log as the staff read it: a table on ``/i/{token}/audit``, ``audit.csv``,
and JSON (``GET /api/v1/audit``).

Every change the staff make is one entry (:func:`dynagrade.serve.db.record_change`):
when, who (the staff link's name, or the user of a command), the action, what it
concerns, and the JSON value before and after. The table says what changed in words
(:func:`change_text`); the CSV keeps the JSON as it is stored, with the time in the
course's zone and its offset.
"""

from __future__ import annotations

import datetime as dt
import json

from ..i18n import N_, _
from ..exam.csvcells import csv_text
from . import db

#: the columns of ``audit.csv``
AUDIT_COLUMNS = ("id", "at", "actor", "action", "subject", "before", "after")
#: the actions the staff pages record, as the audit page names them
ACTION_WORDS = (N_("policy"), N_("exception"), N_("override"), N_("regrade"),
                N_("staff-link"))
#: keys that say whom or what a change concerns, shown even when they did not change
_NAMING_KEYS = ("name",)
#: the newest entries the audit page shows (the CSV holds every one)
PAGE_ENTRIES = 500


def local_time(moment: dt.datetime, zone: dt.tzinfo) -> str:
    """An entry's time in the course's zone, ISO 8601 with its offset, to the second."""
    return db.utc(moment).astimezone(zone).isoformat(timespec="seconds")


def audit_csv(entries: list[db.AuditEntry], zone: dt.tzinfo) -> str:
    """The entries, oldest first, as ``audit.csv``."""
    return csv_text([AUDIT_COLUMNS, *(
        [entry.id, local_time(entry.at, zone), entry.actor, entry.action, entry.subject,
         _json(entry.before), _json(entry.after)]
        for entry in sorted(entries, key=lambda e: e.id))])


def change_text(entry: db.AuditEntry) -> str:
    """What an entry changed, in words: ``key: old → new`` for each key that differs
    (after the name of what it concerns, where the value has one), or what was made or
    removed."""
    before, after = entry.before, entry.after
    if before is None and after is None:
        return ""
    if before is None:
        return _("made: {value}").format(value=_pairs(after))
    if after is None:
        return _("removed: {value}").format(value=_pairs(before))
    if not isinstance(before, dict) or not isinstance(after, dict):
        return f"{_json(before)} → {_json(after)}"
    keys = [k for k in {**before, **after} if before.get(k) != after.get(k)]
    named = [f"{k}: {_shown(after[k])}" for k in _NAMING_KEYS
             if k not in keys and after.get(k) not in (None, "")]
    return "; ".join(named + [f"{k}: {_shown(before.get(k))} → {_shown(after.get(k))}"
                              for k in keys])


def _pairs(value) -> str:
    if isinstance(value, dict):
        return "; ".join(f"{k}: {_shown(v)}" for k, v in value.items() if v not in (None, "", {}))
    return _json(value)


def _shown(value) -> str:
    if value is None or value == "":
        return "—"
    return value if isinstance(value, str) else _json(value)


def _json(value) -> str:
    return "" if value is None else json.dumps(value, sort_keys=True, ensure_ascii=False)
