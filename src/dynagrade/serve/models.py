"""The JSON bodies of the API, requests and responses, as pydantic models.

They are what ``/api/openapi.json`` describes. The routes build the responses from what
the server's own modules compute (:func:`dynagrade.serve.submit.submit`,
:meth:`ExamData.preview <dynagrade.serve.exam_data.ExamData.preview>`,
:func:`dynagrade.serve.gradebook.outcome`); a field that is absent from that result
stays absent from the JSON (the routes answer with ``response_model_exclude_unset``), so
verdicts appear only where the exam's policy shows them.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Literal

from pydantic import BaseModel, Field, field_validator

from ..i18n import _
from .exam_data import MAX_ANSWER_CHARS

if TYPE_CHECKING:
    from ..classgrade.gradebook import GradebookRow as Row


# -- requests -----------------------------------------------------------------------------


def _lone_surrogate(value: Any) -> str | None:
    """The first lone surrogate in ``value`` (a text, or a mapping or list of texts), which
    JSON can escape (``"\\ud800"``) but no UTF-8 text holds, or None."""
    if isinstance(value, str):
        return next((c for c in value if "\ud800" <= c <= "\udfff"), None)
    if isinstance(value, dict):
        value = [*value.keys(), *value.values()]
    if isinstance(value, list):
        return next((found for item in value if (found := _lone_surrogate(item))), None)
    return None


class TextBody(BaseModel):
    """A request body of texts that the server stores, grades and shows again: each must
    be text UTF-8 can hold, else the request is refused (422) naming the field."""

    @field_validator("*")
    @classmethod
    def _characters_only(cls, value: Any) -> Any:
        found = _lone_surrogate(value)
        if found is not None:
            raise ValueError(_("holds {code}, half of a UTF-16 pair and not a character; "
                               "send the text as UTF-8").format(code=f"U+{ord(found):04X}"))
        return value


class AnswersBody(TextBody):
    """``POST /api/v1/answers``: one exercise's answers, part name → text."""

    exercise: str = Field(max_length=200)
    answers: dict[str, str]


class DraftsBody(TextBody):
    """``PUT /api/v1/drafts``: what the student typed into one exercise's boxes, part
    name → text (an empty text: the box was cleared). Never graded, never counted."""

    exercise: str = Field(max_length=200)
    answers: dict[str, str]


class PreviewBody(TextBody):
    """``POST /api/v1/preview``: how one answer reads."""

    exercise: str = Field(max_length=200)
    part: str = Field(max_length=200)
    answer: str = Field(max_length=MAX_ANSWER_CHARS)
    practice: str | None = Field(default=None, max_length=200,
                                 description="a practice draw's signed value, from the page")


# -- responses ----------------------------------------------------------------------------


class Problem(BaseModel):
    """Every refusal: what is wrong, for the student or the client's author."""

    detail: str


def problem(description: str) -> dict[str, Any]:
    """How the OpenAPI document describes a refusal: ``{"detail": ...}`` as JSON, whatever
    the route answers when it does not refuse (a page, a CSV file)."""
    return {"description": description,
            "content": {"application/json": {"schema": Problem.model_json_schema()}}}


class PartVerdict(BaseModel):
    """One submitted part: how it read and, where the policy shows verdicts, the verdict.

    A part that cannot be read (``readable`` false) was not graded, not stored and spent
    no attempt; ``message`` says why."""

    name: str
    readable: bool = Field(description="false: not graded, not stored, no attempt spent")
    message: str = Field(description="how the answer reads, or why it cannot be read")
    correct: bool | None = Field(default=None, description="only where verdicts are shown")
    score: float | None = Field(default=None, description="points earned, penalty applied; "
                                                          "only where verdicts are shown")
    feedback: str | None = Field(default=None, description="only where verdicts are shown")


class SubmitResponse(BaseModel):
    """``POST /api/v1/answers``: the stored submit, as the policy lets the student see it."""

    exercise: str
    attempt: int = Field(description="the student's submits of this exercise, numbered")
    idempotency_key: str
    parts: list[PartVerdict]
    score: float | None = Field(default=None, description="of the parts in this submit, "
                                                          "only where verdicts are shown")
    max_score: float | None = Field(default=None, description="only where verdicts are shown")
    replayed: bool | None = Field(default=None, description="true when the key was stored "
                                                            "already (nothing stored again)")


class DraftsResponse(BaseModel):
    """``PUT /api/v1/drafts``: the parts whose drafts were saved."""

    exercise: str
    saved: list[str]


class PreviewResponse(BaseModel):
    """``POST /api/v1/preview``: how an answer reads; never right or wrong."""

    readable: bool
    message: str
    formula: str | None = Field(description="a readable formula typeset as MathML")


class GradebookRow(BaseModel):
    """One roster student's row of the gradebook (the columns of ``grades.csv``)."""

    student_id: str
    name: str
    email: str
    exercises: dict[str, float | None] = Field(
        description="points per exercise id (null: absent, no grade)")
    total: float | None
    max_total: float
    percent: float | None
    status: Literal["graded", "incomplete", "absent", "rejected"]


class Gradebook(BaseModel):
    """``GET /api/v1/gradebook``: every roster student's row, in roster order."""

    exercise_ids: list[str]
    rows: list[GradebookRow]

    @classmethod
    def from_rows(cls, exercise_ids: list[str], rows: list[Row]) -> "Gradebook":
        """The model of class grading's gradebook rows (:func:`dynagrade.serve.gradebook.
        outcome`), the exercise cells apart from the fixed columns as the rows keep them."""
        return cls(exercise_ids=list(exercise_ids), rows=[
            GradebookRow(student_id=row.student_id, name=row.name, email=row.email,
                         exercises=dict(row.cells), total=row.total,
                         max_total=row.max_total, percent=row.percent,
                         status=row.status.value) for row in rows])


class Table(BaseModel):
    """A table as a page shows it: column headings and rows of cell texts."""

    columns: list[str]
    rows: list[list[str]]


class StaffTables(BaseModel):
    """``GET /i/{token}/tables``: what the staff page's script refreshes."""

    submissions: int
    answers: int
    counts_text: str = Field(description="the counts as the page words them")
    gradebook: Table
    progress: Table


# -- staff links --------------------------------------------------------------------------


class StaffLinkInfo(BaseModel):
    """A staff link as lists show it (never its token)."""

    id: str = Field(description="the start of the token's hash; names the link")
    name: str | None
    created_at: str = Field(description="ISO 8601")
    revoked_at: str | None = Field(description="ISO 8601; null: the link works")

    @classmethod
    def of(cls, link: Any) -> "StaffLinkInfo":
        """The model of a :class:`dynagrade.serve.db.StaffLinkRecord`."""
        from .db import iso

        return cls(id=link.id, name=link.label, created_at=iso(link.created_at),
                   revoked_at=iso(link.revoked_at))


class StaffLinks(BaseModel):
    """``GET /api/v1/staff-links``: every staff link, oldest first."""

    links: list[StaffLinkInfo]


class NewStaffLinkBody(BaseModel):
    """``POST /api/v1/staff-links``: the new link's name (shown in the audit log)."""

    name: str | None = Field(default=None, max_length=200)


class NewStaffLink(BaseModel):
    """A staff link just made: its token and address are shown only this once."""

    id: str
    name: str | None
    token: str
    url: str


class AuditEntryModel(BaseModel):
    """One change the staff made: when, who, what, and the value before and after."""

    id: int
    at: str = Field(description="ISO 8601, UTC")
    actor: str
    action: str = Field(description="policy, exception, override, regrade, staff-link")
    subject: str = Field(description="what the change concerns (a student, a part, ...)")
    before: Any = Field(description="the JSON value before (null: made by this change)")
    after: Any = Field(description="the JSON value after (null: removed by this change)")

    @classmethod
    def of(cls, entry: Any) -> "AuditEntryModel":
        """The model of a :class:`dynagrade.serve.db.AuditEntry`."""
        from .db import iso

        return cls(id=entry.id, at=iso(entry.at),
                   actor=entry.actor, action=entry.action, subject=entry.subject,
                   before=entry.before, after=entry.after)


class AuditLog(BaseModel):
    """``GET /api/v1/audit``: the recorded changes, newest first."""

    entries: list[AuditEntryModel]


# -- exceptions to the policy per student, and timed exams --------------------------------


class ExceptionBody(BaseModel):
    """``PUT /api/v1/exceptions``: set the exceptions of one or several students (each
    gets exactly these; what they had before is replaced)."""

    students: list[str] = Field(max_length=5000, description="roster student ids")
    opens: str | None = Field(default=None, max_length=64,
                              description="their own opening, with its offset")
    closes: str | None = Field(default=None, max_length=64,
                               description="their own close, with its offset (a later one "
                                           "extends; opens and closes after the class's "
                                           "close: a reopen window)")
    extra_minutes: int = Field(default=0, description="added to a timed exam's time_limit")
    extra_attempts: dict[str, int] = Field(
        default_factory=dict, description="scope -> attempts added to the policy's: `*` "
        "every part, `<exercise>`, or `<exercise>/<part>`; the most specific scope wins")


class StudentException(BaseModel):
    """One student's exceptions, as granted."""

    student_id: str
    name: str
    opens: str | None
    closes: str | None
    extra_minutes: int
    extra_attempts: dict[str, int]
    granted_by: str | None
    granted_at: str | None = Field(description="ISO 8601, UTC")


class Exceptions(BaseModel):
    """``GET``/``PUT /api/v1/exceptions``: the exceptions in force (of the students named,
    for a PUT), by student id."""

    exceptions: list[StudentException]


class Removed(BaseModel):
    """``DELETE /api/v1/exceptions/{student_id}``: what was removed (null: nothing was
    granted; nothing changed)."""

    student_id: str
    removed: StudentException | None


class StartResponse(BaseModel):
    """``POST /api/v1/start``: when the student's time started and when it ends."""

    timed: bool = Field(description="false: the exam has no time limit (nothing started)")
    started_at: str | None = Field(description="ISO 8601; the first start counts")
    minutes: int = Field(description="their time, extra minutes included (0: untimed)")
    deadline: str | None = Field(description="the earlier of their close and the end of "
                                             "their time (null: never)")


# -- regrades -----------------------------------------------------------------------------


class Verdict(BaseModel):
    """A stored verdict on one answer (points in the exam's scale, penalty applied)."""

    status: str
    correct: bool
    score: float
    feedback: str
    misconception: str | None


class RegradeChange(BaseModel):
    """One answer whose verdict the regrade changes: whose, which part, the text, and the
    verdict before and after."""

    answer_id: int
    student_id: str
    name: str
    exercise_id: str
    part: str
    label: str
    attempt: int = Field(description="the student's submit of the exercise it came with")
    raw: str = Field(description="the answer as the student typed it")
    old: Verdict
    new: Verdict
    counts: bool = Field(description="whether it is the part's counted answer before or "
                                     "after the regrade")


class StudentChange(BaseModel):
    """An affected student's points, old and new: per exercise (null: not handed in) and
    in total, as the gradebook computes them."""

    cells: dict[str, list[float | None]] = Field(description="per exercise id")
    total: list[float | None]


class RegradePlan(BaseModel):
    """``/api/v1/regrades``: a regrade, its state and its plan."""

    id: int
    state: Literal["previewed", "applied", "discarded"]
    created_at: str = Field(description="when it was previewed (ISO 8601, UTC)")
    actor: str = Field(description="who previewed it")
    applied_at: str | None
    answers: int = Field(description="the counted answers graded again")
    changes: list[RegradeChange]
    grades: dict[str, StudentChange] = Field(
        description="by student id: the affected students' points per exercise and "
                    "total, [old, new]")
    source: dict[str, Any] = Field(description="the manifest and exercise files the "
                                               "verdicts were recomputed against: paths "
                                               "and SHA-256 digests (`manifest`, "
                                               "`exercise_files`)")
    done: bool | None = Field(default=None, description="apply or discard: whether this "
                                                        "call changed the state (false: "
                                                        "it was done already)")
    answers_since: int | None = Field(default=None, description="counted answers stored "
                                      "after the preview, graded with the key of then "
                                      "(preview again to regrade them)")

    @classmethod
    def of(cls, regrade: Any, **extra: Any) -> "RegradePlan":
        """The model of a stored :class:`dynagrade.serve.db.Regrade`."""
        from .db import iso

        plan = regrade.plan
        return cls(id=regrade.id, state=regrade.state, created_at=iso(regrade.created_at),
                   actor=regrade.actor, applied_at=iso(regrade.applied_at),
                   answers=plan["answers"], changes=plan["changes"],
                   grades=plan["grades"], source=regrade.source, **extra)


# -- points by hand and a student's record ------------------------------------------------


class OverrideBody(BaseModel):
    """``PUT /api/v1/overrides``: the points of one part of one student, set by hand."""

    student: str = Field(max_length=200)
    exercise: str = Field(max_length=200)
    part: str = Field(max_length=200)
    points: float = Field(description="0 to the part's points, a multiple of the exam's "
                                      "rounding")
    comment: str = Field(default="", max_length=2000,
                         description="shown to the student with the points")


class OverrideEntry(BaseModel):
    """Points set by hand on one part, and by whom and when."""

    student: str
    exercise: str
    part: str
    points: float
    comment: str
    author: str = Field(description="the staff link's name")
    at: str = Field(description="ISO 8601")


class OverrideChange(BaseModel):
    """``PUT`` and ``DELETE /api/v1/overrides…``: whether anything changed (false: the
    same again, nothing recorded)."""

    changed: bool


class Overrides(BaseModel):
    """``GET /api/v1/overrides``: every part whose points were set by hand."""

    overrides: list[OverrideEntry]


class AttemptRecord(BaseModel):
    """One stored answer of a part."""

    attempt: int
    practice: bool = Field(description="a practice draw's answer: never counts")
    answer: str = Field(description="as typed")
    read_as: str = Field(description="how the grader read it")
    readable: bool
    status: str
    score: float = Field(description="the grader's points, penalty applied, unrounded")
    max_score: float
    feedback: str
    at: str = Field(description="ISO 8601")
    counts: bool = Field(description="the attempt the gradebook counts for the part")


class DraftRecord(BaseModel):
    """What the student typed into a part and did not submit (never counted)."""

    text: str
    saved_at: str


class OverrideRecord(BaseModel):
    """Points set by hand on a part."""

    points: float
    comment: str
    author: str
    at: str


class PartRecord(BaseModel):
    """One part of a student's record."""

    part: str
    label: str
    points: float
    attempts: list[AttemptRecord]
    counted_attempt: int | None = Field(description="null: no attempt counts")
    status: str | None = Field(description="the counted verdict")
    auto_score: float | None = Field(description="the grader's points, rounded")
    score: float | None = Field(description="the points that count (set by hand, or else "
                                            "the grader's)")
    override: OverrideRecord | None
    draft: DraftRecord | None


class ExerciseRecord(BaseModel):
    """One exercise of a student's record."""

    exercise: str
    title: str
    handed_in: bool
    score: float | None
    max_score: float
    parts: list[PartRecord]


class StudentTerms(BaseModel):
    """The policy as it holds for one student (times in the course's zone, as text)."""

    exceptions: list[str] = Field(description="one phrase per exception granted")
    granted_by: str | None
    granted_at: str | None
    closes: str | None = Field(description="their close")
    extended: bool = Field(description="whether an exception sets their opening or close")
    timed: bool
    minutes: int = Field(description="their time on a timed exam, extra minutes included")
    started_at: str | None
    time_ends: str | None


class RegradedVerdict(BaseModel):
    """A verdict of the student's that an applied regrade changed."""

    at: str
    exercise: str
    part: str
    attempt: int
    before: float
    after: float


class StudentRecord(BaseModel):
    """``GET /api/v1/students/{student_id}``: every attempt, the counted one, drafts,
    points set by hand, the exceptions granted and the verdicts regrades changed."""

    student_id: str
    name: str
    email: str
    counts: Literal["best", "last"]
    total: float | None
    exercises: list[ExerciseRecord]
    terms: StudentTerms
    regrades: list[RegradedVerdict]


# -- the policy ------------------------------------------------------------------------------


class PolicyBody(BaseModel):
    """``PUT /api/v1/policy``: the settings to change, as exam.toml writes them (times
    with their offset, ``""`` for no time); the mode is the exam's and cannot change."""

    model_config = {"extra": "forbid"}

    opens: str | None = Field(default=None, max_length=64)
    closes: str | None = Field(default=None, max_length=64)
    attempts: int | None = None
    penalty: float | None = None
    feedback: str | None = Field(default=None, max_length=32)
    counts: str | None = Field(default=None, max_length=32)
    solutions: str | None = Field(default=None, max_length=32)
    time_limit: int | None = None


class PolicyInForce(BaseModel):
    """``GET``/``PUT /api/v1/policy``: the policy in force (exam.toml's keys)."""

    policy: dict[str, Any] = Field(description="mode, opens, closes, attempts, penalty, "
                                               "feedback, counts, solutions, time_limit")
    changed: bool | None = Field(default=None, description="PUT: whether this call changed "
                                                           "the policy")


# -- LTI ----------------------------------------------------------------------------------


class KeySet(BaseModel):
    """``GET /lti/jwks``: the tool's public keys (a JWK Set, RFC 7517), which platforms
    check the tool's signatures with."""

    keys: list[dict[str, str]] = Field(description="RSA public keys: kty, n, e, kid, alg, use")
