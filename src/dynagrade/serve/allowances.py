"""Exceptions to the policy for one student, and the rules in force for one student.

An exception (an :class:`Allowance`, granted by the staff to one student or a list of
them) changes the policy for those students only:

- ``opens`` and ``closes``: their own opening and close, each *replacing* the policy's
  (unset: the policy's holds), as Moodle's user overrides do. A close after the policy's
  is an extension; an opening and a close both after the policy's close is a reopen
  window (the student answers within it, and only then).
- ``extra_minutes``: on a timed exam (the policy's ``time_limit``), minutes added to the
  student's time.
- ``extra_attempts``: attempts added to the policy's ``attempts``, by scope:
  :data:`EVERY_PART` (``"*"``), an exercise (``"<exercise>"``) or one part of it
  (``"<exercise>/<part>"``). The most specific scope naming a part decides (they are not
  added up): ``{"*": 1, "ex": 3}`` gives every part of ``ex`` 3 more and every other part
  1 more. With ``attempts = 0`` (no limit) there is nothing to add.

:class:`Rules` is the policy as it holds for one student at a moment: their opening,
close, timed deadline and the attempts of each part. Every decision made for a student
(a submit, a draft, a preview, the page, the worked solutions) asks :func:`rules_for`;
what concerns the whole class (the gradebook, the staff page) keeps the policy.

Granting (:func:`grant`) sets the listed students' exceptions to the one given, is
checked as exam.toml's policy is (times with their offset, the close after the opening,
whole numbers within bounds, the exam's exercise and part names, roster students), is
idempotent (granting what a student has already changes and records nothing) and records
one audit log entry per student changed (action ``"exception"``, subject the student id,
before and after as JSON); :func:`clear` removes a student's exceptions.
:func:`granted` lists them (the staff pages show them).
"""

from __future__ import annotations

import datetime as dt
import json
import re
from dataclasses import dataclass, field
from typing import Mapping, NoReturn

import sqlalchemy as sa

from ..errors import DynagradeError
from ..exam.policy import MAX_ATTEMPTS, MAX_MINUTES, Policy, read_moment, whole_number
from ..i18n import _, ngettext
from . import db, moments

#: the scope of extra attempts that covers every part of the exam
EVERY_PART = "*"
#: the fields of an exception, as a form or the API names them
FIELDS = ("opens", "closes", "extra_minutes", "extra_attempts")


class AllowanceError(DynagradeError, ValueError):
    """An exception the rules refuse; the message says what is wrong."""


@dataclass(frozen=True)
class Allowance:
    """One student's exceptions to the policy (see the module); ``updated_at`` and
    ``updated_by`` say who granted them last and do not count in comparisons."""

    opens: dt.datetime | None = None
    closes: dt.datetime | None = None
    extra_minutes: int = 0
    extra_attempts: Mapping[str, int] = field(default_factory=dict)
    updated_at: dt.datetime | None = field(default=None, compare=False)
    updated_by: str | None = field(default=None, compare=False)

    @property
    def empty(self) -> bool:
        return self.opens is None and self.closes is None and not self.extra_minutes \
            and not self.extra_attempts

    def extra_for(self, exercise_id: str, part: str) -> int:
        """The extra attempts of one part: those of the most specific scope naming it."""
        for scope in (f"{exercise_id}/{part}", exercise_id, EVERY_PART):
            if scope in self.extra_attempts:
                return self.extra_attempts[scope]
        return 0

    def to_json(self) -> dict:
        """As the audit log and the API keep it."""
        return {"opens": _iso(self.opens), "closes": _iso(self.closes),
                "extra_minutes": self.extra_minutes,
                "extra_attempts": dict(sorted(self.extra_attempts.items()))}

    @classmethod
    def from_row(cls, row: db.AllowanceRow) -> Allowance:
        return cls(db.utc(row.opens), db.utc(row.closes), int(row.extra_minutes),
                   {str(k): int(v) for k, v in json.loads(row.extra_attempts or "{}").items()},
                   db.utc(row.updated_at), row.updated_by)

    def columns(self) -> dict:
        """The values of the database's row."""
        return {"opens": _utc(self.opens), "closes": _utc(self.closes),
                "extra_minutes": self.extra_minutes,
                "extra_attempts": json.dumps(dict(sorted(self.extra_attempts.items())))}


@dataclass(frozen=True)
class Rules:
    """The policy as it holds for one student: the policy in force, their exceptions
    (None: none) and when they started a timed exam (None: not yet)."""

    policy: Policy
    allowance: Allowance | None = None
    started_at: dt.datetime | None = None

    @property
    def opens(self) -> dt.datetime | None:
        """Their opening: the exception's, else the policy's."""
        mine = self.allowance.opens if self.allowance else None
        return mine or self.policy.opens

    @property
    def closes(self) -> dt.datetime | None:
        """Their close: the exception's, else the policy's."""
        mine = self.allowance.closes if self.allowance else None
        return mine or self.policy.closes

    @property
    def extended(self) -> bool:
        """Whether an exception gives them another opening or close than the class's."""
        return (self.opens, self.closes) != (self.policy.opens, self.policy.closes)

    @property
    def timed(self) -> bool:
        return self.policy.time_limit > 0

    @property
    def minutes(self) -> int:
        """Their time on a timed exam, extra minutes included (0: untimed)."""
        extra = self.allowance.extra_minutes if self.allowance else 0
        return self.policy.time_limit + extra if self.timed else 0

    @property
    def time_ends(self) -> dt.datetime | None:
        """When their time runs out (None: untimed, or not started)."""
        if not self.timed or self.started_at is None:
            return None
        return self.started_at + dt.timedelta(minutes=self.minutes)

    @property
    def deadline(self) -> dt.datetime | None:
        """The moment they can no longer answer: their close, or the end of their time
        when that comes first (None: never)."""
        ends = [m for m in (self.closes, self.time_ends) if m is not None]
        return min(ends) if ends else None

    def before_opens(self, now: dt.datetime) -> bool:
        return self.opens is not None and now < self.opens

    def closed(self, now: dt.datetime) -> bool:
        """Whether their close has come (verdicts and solutions follow it)."""
        return self.closes is not None and now >= self.closes

    def time_over(self, now: dt.datetime) -> bool:
        ends = self.time_ends
        return ends is not None and now >= ends

    def waiting_to_start(self, now: dt.datetime) -> bool:
        """Whether they may press Start now: a timed exam, open, not started yet."""
        return self.timed and self.started_at is None and not self.before_opens(now) \
            and not self.closed(now)

    def is_open(self, now: dt.datetime) -> bool:
        """Whether their answers are accepted at ``now``."""
        return self.refusal(now) is None

    def refusal(self, now: dt.datetime, zone: dt.tzinfo | None = None) -> str | None:
        """Why their answers are not accepted at ``now`` (None: they are)."""
        if self.before_opens(now):
            assert self.opens is not None
            return _("the exam opens at {time}").format(time=self.opens.isoformat())
        if self.closed(now):
            assert self.closes is not None
            return _("the exam closed at {time}; answers are no longer accepted").format(
                time=self.closes.isoformat())
        if self.timed and self.started_at is None:
            return _("this exam is timed: press “Start” on your page first; your time "
                     "runs from then")
        ends = self.time_ends
        if ends is not None and now >= ends:
            return _("your time ran out at {time}; answers are no longer accepted").format(
                time=shown_time(ends, zone or self.policy.zone))
        return None

    def shows_verdicts(self, now: dt.datetime) -> bool:
        """Whether they see right/wrong and points: at once, or from their close on."""
        return self.policy.feedback == "immediate" or self.closed(now)

    def attempts(self, exercise_id: str, part: str) -> int:
        """The attempts one part allows them (0: no limit)."""
        if not self.policy.attempts:
            return 0
        extra = self.allowance.extra_for(exercise_id, part) if self.allowance else 0
        return self.policy.attempts + extra


def rules_for(engine: sa.Engine, exam_id: str, policy: Policy, student_id: str) -> Rules:
    """The rules in force for ``student_id`` under ``policy`` (the one in force)."""
    return rules_from(policy, *db.student_terms(engine, exam_id, student_id))


def rules_from(policy: Policy, row: db.AllowanceRow | None,
               started: dt.datetime | None) -> Rules:
    """The rules under ``policy`` for a student whose exceptions are ``row`` (or none) and
    who started a timed exam at ``started`` (or not), as :func:`db.student_terms` reads
    them."""
    return Rules(policy, Allowance.from_row(row) if row else None, db.utc(started))


def granted(engine: sa.Engine, exam_id: str,
            student_ids: list[str] | None = None) -> dict[str, Allowance]:
    """Every student's exceptions (of ``student_ids``, if given), by student id."""
    return {row.student_id: Allowance.from_row(row)
            for row in db.allowance_rows(engine, exam_id, student_ids)}


# -- granting and removing ------------------------------------------------------------------


def student_list(text: str) -> list[str]:
    """The student ids in ``text``: separated by spaces, commas, semicolons or new
    lines, each once, in the order given."""
    return list(dict.fromkeys(word for word in re.split(r"[\s,;]+", text) if word))


def check_students(students: object, roster: Mapping[str, object]) -> list[str]:
    """``students`` (a list of ids) checked against the roster: every unknown id is
    named in the refusal."""
    if not isinstance(students, list) or not all(isinstance(s, str) for s in students):
        raise AllowanceError(_("give the students as a list of student ids"))
    ids = list(dict.fromkeys(s.strip() for s in students if s.strip()))
    if not ids:
        raise AllowanceError(_("name at least one student"))
    unknown = [s for s in ids if s not in roster]
    if unknown:
        raise AllowanceError(_("not on the roster: {ids}").format(ids=", ".join(unknown)))
    return ids


def read_allowance(fields: Mapping[str, object], policy: Policy,
                   parts: Mapping[str, tuple[str, ...]]) -> Allowance:
    """The exception in ``fields`` (``opens``, ``closes``: date-times with their offset or
    ISO text, empty for none; ``extra_minutes``: a whole number; ``extra_attempts``:
    scope -> whole number, 0 for none), checked; ``parts``: each exercise's part names.
    Raises :class:`AllowanceError`."""
    def fail(key: str, message: str) -> NoReturn:
        raise AllowanceError(_("{field}: {message}").format(field=key, message=message))

    def moment(key: str) -> dt.datetime | None:
        value = fields.get(key)
        if isinstance(value, str) and not value.strip():
            return None
        return read_moment(value, lambda message: fail(key, message))

    opens, closes = moment("opens"), moment("closes")
    first, last = opens or policy.opens, closes or policy.closes
    if first and last and last <= first:
        fail("closes", _("{closes} is not after the opening {opens}").format(
            closes=last.isoformat(), opens=first.isoformat()))
    minutes = _number(fields.get("extra_minutes", 0))
    if not whole_number(minutes, 0, MAX_MINUTES):
        fail("extra_minutes", _("{value!r}; give a whole number of minutes from 0 to "
                                "{most}").format(value=minutes, most=MAX_MINUTES))
    given = fields.get("extra_attempts") or {}
    if not isinstance(given, Mapping):
        fail("extra_attempts", _("give the extra attempts as scope -> number"))
    scopes = {EVERY_PART, *parts, *(f"{e}/{p}" for e, names in parts.items() for p in names)}
    extra: dict[str, int] = {}
    for scope, value in given.items():
        if scope not in scopes:
            fail("extra_attempts", _("no exercise or part {scope!r} in this exam; give * "
                                     "(every part), an exercise or exercise/part").format(
                scope=scope))
        number = _number(value)
        if not whole_number(number, 0, MAX_ATTEMPTS):
            fail("extra_attempts", _("{scope}: {value!r}; give a whole number of attempts "
                                     "from 0 to {most}").format(scope=scope, value=value,
                                                               most=MAX_ATTEMPTS))
        if number:
            extra[str(scope)] = number
    allowance = Allowance(opens, closes, minutes, extra)
    if allowance.empty:
        raise AllowanceError(_("nothing to grant: give a close, an opening, extra minutes "
                               "or extra attempts (to take exceptions away, remove them)"))
    return allowance


def grant(engine: sa.Engine, exam_id: str, actor: str, student_ids: list[str],
          allowance: Allowance) -> dict[str, Allowance]:
    """Set the exceptions of ``student_ids`` (checked) to ``allowance``; those who had
    it already are left alone (nothing recorded). The exceptions now in force for them."""
    current = granted(engine, exam_id, student_ids)
    writes = [db.AllowanceWrite(student, allowance.columns(),
                                _json(current.get(student)), allowance.to_json())
              for student in student_ids if current.get(student) != allowance]
    db.write_allowances(engine, exam_id, actor, writes)
    return granted(engine, exam_id, student_ids)


def clear(engine: sa.Engine, exam_id: str, actor: str, student_id: str) -> Allowance | None:
    """Remove a student's exceptions (the policy holds for them again); the ones
    removed (None: there were none, and nothing is recorded)."""
    current = granted(engine, exam_id, [student_id]).get(student_id)
    if current is not None:
        db.write_allowances(engine, exam_id, actor, [
            db.AllowanceWrite(student_id, None, current.to_json(), None)])
    return current


# -- how an exception reads ----------------------------------------------------------------


def describe(allowance: Allowance, zone: dt.tzinfo) -> list[str]:
    """An exception as the pages list it, one phrase per thing granted."""
    words = []
    if allowance.opens:
        words.append(_("opens {time}").format(time=shown_time(allowance.opens, zone)))
    if allowance.closes:
        words.append(_("closes {time}").format(time=shown_time(allowance.closes, zone)))
    if allowance.extra_minutes:
        words.append(ngettext("{n} extra minute", "{n} extra minutes", allowance.extra_minutes
                              ).format(n=allowance.extra_minutes))
    for scope, number in sorted(allowance.extra_attempts.items()):
        where = _("every part") if scope == EVERY_PART else scope
        words.append(ngettext("{n} extra attempt on {scope}", "{n} extra attempts on {scope}",
                              number).format(n=number, scope=where))
    return words


def shown_time(moment: dt.datetime, zone: dt.tzinfo) -> str:
    """A time in the course's zone, to the minute, naming the zone."""
    return moments.moment(moment, zone).text


def _number(value: object) -> object:
    """A number given as text (a form), as a number; anything else as it is."""
    if isinstance(value, str):
        text = value.strip()
        if not text:
            return 0
        return int(text) if re.fullmatch(r"\d+", text) else text
    return value


def _json(allowance: Allowance | None) -> dict | None:
    return None if allowance is None else allowance.to_json()


def _iso(moment: dt.datetime | None) -> str | None:
    return moment.isoformat() if moment else None


def _utc(moment: dt.datetime | None) -> dt.datetime | None:
    """In UTC, as the database keeps times (SQLite drops the offset)."""
    return None if moment is None else moment.astimezone(dt.timezone.utc)
