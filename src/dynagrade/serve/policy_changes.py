"""Changing an exam's policy while it is served, without generating it again.

The policy in force is the manifest's (what ``dynagrade exam`` wrote from exam.toml),
overridden by the newest change the staff recorded in the database's audit log (action
``"policy"``, ``after``: the whole policy). A change comes from the staff page's form or
from ``dynagrade policy``; both go through :func:`change_policy`, which validates the
result exactly as exam.toml's policy is validated
(:func:`dynagrade.exam.policy.read_policy`: an exam cannot show feedback immediately,
times need their offset, closes after opens, ...) and records who, when, before and after.

Every worker process reads the policy in force through its :class:`PolicySource`, which
asks the database at most every :data:`FRESH_SECONDS`, so a change made anywhere holds
everywhere within that time.
"""

from __future__ import annotations

import threading
import time
from typing import Callable, Mapping

import sqlalchemy as sa

from ..exam.policy import Policy, PolicyError, read_policy
from ..i18n import N_, _
from . import db

#: the keys a change may set (the mode is the exam's nature, not a setting)
CHANGEABLE = ("opens", "closes", "attempts", "penalty", "feedback", "counts", "solutions",
              "time_limit")
#: the settings and their values as the staff page names them (the form posts the values
#: exam.toml writes)
WORDS = (N_("opens"), N_("closes"), N_("attempts"), N_("penalty"), N_("feedback"),
         N_("counts"), N_("solutions"), N_("immediate"), N_("after-close"), N_("best"),
         N_("last"), N_("with-feedback"), N_("after-last-attempt"), N_("never"),
         N_("time_limit"))

#: how long a worker trusts the policy it read (seconds)
FRESH_SECONDS = 2.0


class PolicySource:
    """The policy in force for one worker: the manifest's, or the latest change,
    re-read from the database when older than ``fresh`` seconds."""

    def __init__(self, engine: sa.Engine, exam_id: str, manifest_policy: Policy,
                 fresh: float = FRESH_SECONDS, clock: Callable[[], float] = time.monotonic):
        self.engine, self.exam_id, self.manifest_policy = engine, exam_id, manifest_policy
        self.fresh, self.clock = fresh, clock
        self._policy = manifest_policy
        self._read_at: float | None = None
        self._lock = threading.Lock()

    def forget(self) -> None:
        """Read the database at the next call (after a change made in this worker)."""
        with self._lock:
            self._read_at = None

    def __call__(self) -> Policy:
        with self._lock:
            stamp = self.clock()
            if self._read_at is None or stamp - self._read_at >= self.fresh:
                try:
                    self._policy = in_force(self.engine, self.exam_id, self.manifest_policy)
                except sa.exc.SQLAlchemyError:  # keep the last one read; the request that
                    pass                        # needs the database will say it is down
                self._read_at = stamp
            return self._policy


def in_force(engine: sa.Engine, exam_id: str, manifest_policy: Policy) -> Policy:
    """The policy in force now, read from the database."""
    latest = db.latest_change(engine, exam_id, db.POLICY_CHANGE)
    return manifest_policy if latest is None or latest.after is None \
        else Policy.from_json(latest.after)


def validated(current: Policy, changes: Mapping[str, object]) -> Policy:
    """``current`` with ``changes`` applied, validated as exam.toml's policy is.

    Values may be given as text (a form, the command line): ``""`` clears ``opens`` or
    ``closes``; numbers are read as numbers. Raises :class:`PolicyError`."""
    unknown = sorted(set(changes) - set(CHANGEABLE))
    if unknown:
        raise PolicyError(_("cannot change {keys}; a change may set {allowed}").format(
            keys=", ".join(unknown), allowed=", ".join(CHANGEABLE)))
    merged: dict[str, object] = {key: value for key, value in current.to_json().items()
                                 if value is not None}
    for key, value in changes.items():
        value = _typed(key, value)
        if value is None:
            merged.pop(key, None)
        else:
            merged[key] = value
    return read_policy(merged, _("the policy change"), lambda key: "")


def _typed(key: str, value: object) -> object:
    """A value given as text, as exam.toml would hold it (left as text when it is not a
    number, for :func:`read_policy` to refuse with its own message)."""
    if not isinstance(value, str):
        return value
    text = value.strip()
    if key in ("opens", "closes"):
        return text or None
    if key in ("attempts", "time_limit") and text.isdigit():
        return int(text)
    if key == "penalty":
        try:
            return float(text)
        except ValueError:
            return text
    return text


def change_policy(engine: sa.Engine, exam_id: str, manifest_policy: Policy, actor: str,
                  changes: Mapping[str, object]) -> tuple[Policy, Policy]:
    """Apply and record ``changes`` by ``actor``: (before, after). A change that changes
    nothing is not recorded."""
    before = in_force(engine, exam_id, manifest_policy)
    after = validated(before, changes)
    if after != before:
        db.record_change(engine, exam_id, actor, db.POLICY_CHANGE, "policy",
                         before.to_json(), after.to_json())
    return before, after


def describe_change(before: Policy, after: Policy) -> list[str]:
    """The keys that differ, as ``key: old → new`` lines."""
    old, new = before.to_json(), after.to_json()
    return [f"{key}: {_shown(old[key])} → {_shown(new[key])}"
            for key in CHANGEABLE if old[key] != new[key]]


def _shown(value: object) -> str:
    return _("none") if value is None else str(value)
