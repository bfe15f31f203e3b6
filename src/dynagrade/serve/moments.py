"""Times as the pages show them: in the course's zone (that of the exam's ``closes`` or
``opens``), naming the zone, and as ISO 8601 for the browser to show in the reader's
own zone."""

from __future__ import annotations

import datetime as dt
from dataclasses import dataclass

from . import db


@dataclass(frozen=True)
class Moment:
    """A time as the page shows it: ISO 8601 for the browser to show in the reader's own
    zone, and a text in the exam's zone (naming it) for a page without JavaScript."""

    iso: str
    text: str


def exam_zone(policy) -> dt.tzinfo:
    """The course's zone (:attr:`Policy.zone <dynagrade.exam.policy.Policy.zone>`)."""
    return policy.zone


def moment(value: dt.datetime, zone: dt.tzinfo, seconds: bool = False) -> Moment:
    """``value`` (SQLite's naive times are UTC) in ``zone``, to the minute (to the
    second with ``seconds``: the staff's pages, where "I submitted at 10:02" is checked)."""
    aware = db.utc(value)
    local = aware.astimezone(zone)
    shown = "%Y-%m-%d %H:%M:%S" if seconds else "%Y-%m-%d %H:%M"
    return Moment(aware.isoformat(timespec="seconds"),
                  f"{local.strftime(shown)} {local.tzname() or 'UTC'}")
