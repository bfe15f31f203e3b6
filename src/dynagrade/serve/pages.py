"""The HTML of the student page and the staff page (templates in ``templates/``)."""

from __future__ import annotations

import datetime as dt
import uuid
from collections import Counter
from dataclasses import dataclass, field, replace
from pathlib import Path

import jinja2
from markupsafe import Markup

from ..exam.solution_policy import solution_visible
from ..exercise.results import ExerciseResult
from . import allowances, db, drafts, gradebook, limits, moments, regrade, standing
from .allowances import Rules
from ..grading.choice import shown_option
from ..i18n import N_, _, ngettext
from .exam_data import MAX_ANSWER_CHARS, ExamData
from .practice import practice_seed
from .state import Server
from .submit import Refused

_TEMPLATES = jinja2.Environment(
    loader=jinja2.FileSystemLoader(Path(__file__).resolve().parent / "templates"),
    autoescape=True, trim_blocks=True, lstrip_blocks=True)
#: a template's fixed strings are ``{{ _("...") }}``, in the language of the request
_TEMPLATES.globals.update(_=_, ngettext=ngettext, shown_option=shown_option)


@dataclass(frozen=True)
class Typed:
    """The submit a page answers: its exercise, the texts the student typed, the reason
    beside each part that was refused or could not be read, and whether anything was
    saved."""

    exercise_id: str | None = None
    texts: dict[str, str] = field(default_factory=dict)
    reasons: dict[str, str] = field(default_factory=dict)
    saved: bool = False

    @classmethod
    def done(cls, exercise_id: str | None) -> Typed | None:
        """The page after a stored submit of ``exercise_id`` (None: no submit)."""
        return cls(exercise_id, saved=True) if exercise_id else None

    def with_reasons(self, reasons: dict[str, str], saved: bool = False) -> Typed:
        return replace(self, reasons=dict(reasons), saved=saved)


def render(template: str, **values) -> str:
    """``templates/<template>`` rendered with ``values`` (error pages, :mod:`.errors`)."""
    return _TEMPLATES.get_template(template).render(**values)


def student_html(server: Server, token: str, student_id: str, practice: str | None,
                 now: dt.datetime, base: str, error: str | None = None,
                 typed: Typed | None = None) -> str:
    """A student's page: their variant of every exercise, answer boxes, where they stand
    and what the policy shows; ``practice`` (``"<exercise>:<signed draw>"``) shows a
    practice draw of one exercise instead of the student's own variant; ``typed``: the
    submit this page answers (its texts shown again, with the reasons beside the parts).
    Before the exam opens (for this student: :mod:`.allowances`), only the title, the
    policy and the opening time; on a timed exam, until the student presses Start, the
    policy and the Start button."""
    from ..render.markup import markdown_to_html

    data, policy = server.data, server.data.policy
    rules = allowances.rules_for(server.engine, data.exam_id, policy, student_id)
    verdicts = rules.shows_verdicts(now)
    zone = moments.exam_zone(policy)
    before = rules.before_opens(now)
    waiting = rules.waiting_to_start(now)
    exercises = []
    counted: dict = {}
    if not before and not waiting:
        stored = db.student_answers(server.engine, data.exam_id, student_id)
        shown = drafts.shown_texts(stored, db.student_drafts(server.engine, data.exam_id,
                                                             student_id))
        counted = standing.results(data, stored, student_id, db.stored_overrides(
            server.engine, data.exam_id, student_id))
        exercises = [_exercise(server, rules, student_id, exercise_id, practice, stored,
                               shown, counted.get(exercise_id), typed, now, zone)
                     for exercise_id in data.exercise_ids]
    is_open = rules.is_open(now)
    deadline = rules.deadline
    return _TEMPLATES.get_template("student.html").render(
        title=data.title, student=data.students[student_id], token=token, base=base,
        language=data.manifest.exam.language, before=before,
        csrf=limits.csrf_field(server.secret, token), exercises=exercises, verdicts=verdicts,
        mode=policy.mode, policy=_policy_lines(rules, now), is_open=is_open,
        opens=moments.moment(rules.opens, zone) if rules.opens else None,
        closes=moments.moment(rules.closes, zone) if rules.closes else None,
        closed=rules.closed(now), extended=_close_word(rules), waiting=waiting,
        timed=rules.timed, time_over=rules.time_over(now),
        deadline=moments.moment(deadline, zone) if deadline else None,
        time_ends=moments.moment(rules.time_ends, zone) if rules.time_ends else None,
        error=error, status=_status(data, typed, error, exercises), max_chars=MAX_ANSWER_CHARS,
        total=standing.total(data, counted) if verdicts and counted else None,
        max_total=sum(float(m.points) for m in data.exercises_meta.values()),
        instructions=Markup(markdown_to_html(data.instructions))
        if data.instructions and not before and not waiting else "",
        regraded=[] if before else regrade.notices(server, student_id, now),
        submit_label=_("Save answers") if not verdicts else _("Submit"))


def _close_word(rules: Rules) -> str | None:
    """How the page marks a close an exception gave the student (None: the class's)."""
    mine, class_close = rules.closes, rules.policy.closes
    if mine == class_close:
        return None
    later = mine is None or (class_close is not None and mine > class_close)
    return _("extended") if later else _("set for you")


#: the verdicts' words, as the history shows them
_STATUS_WORDS = {"correct": N_("correct"), "follow-through": N_("follow-through"),
                 "partial": N_("partial"), "wrong": N_("wrong"),
                 "not answered": N_("not answered"), "error": N_("error")}


def _exercise(server: Server, rules: Rules, student_id: str, exercise_id: str,
              practice: str | None, stored: list[db.StoredAnswer],
              shown: dict[tuple[str, str], str], result: ExerciseResult | None,
              typed: Typed | None, now: dt.datetime, zone: dt.tzinfo) -> dict:
    """One exercise's section of the page: its statement, its parts (each with the text
    its box shows, the attempts left by the student's rules, the reason it was refused)
    and its history."""
    data = server.data
    meta = data.exercises_meta[exercise_id]
    practice_of, _sep, practice_value = (practice or "").partition(":")
    seed = None
    if practice_of == exercise_id:
        try:
            seed = practice_seed(server.secret, student_id, exercise_id, practice_value)
        except Refused:
            seed = None
    mine = [a for a in stored if a.exercise_id == exercise_id and
            (a.counted if seed is None else a.seed == seed and not a.counted)]
    used = standing.attempts_used(stored, exercise_id)
    here = typed if typed is not None and typed.exercise_id == exercise_id else Typed()
    parts = []
    for info in data.parts(exercise_id):
        if seed is None:
            text = shown.get((exercise_id, info.name), "")
        else:
            text = next((a.raw for a in reversed(mine) if a.part == info.name), "")
        if info.name in here.reasons or (here.texts and not here.saved):
            text = here.texts.get(info.name, text)  # what was typed, not yet saved
        allowed = rules.attempts(exercise_id, info.name)
        left = max(0, allowed - used[info.name]) if allowed and seed is None else None
        verdict = result.part(info.name) if result is not None and seed is None else None
        reason = here.reasons.get(info.name)
        parts.append({
            "info": info, "text": text, "left": left, "exhausted": left == 0,
            "reading": _reading(data, student_id, exercise_id, info, text, seed)
            if not reason else None,
            "chosen": {c.strip() for c in text.split(",")} if info.options else set(),
            "reason": reason, "verdict": verdict,
            "staff_note": verdict.override_note(data.rounding) if verdict else "",
            "history": [{"attempt": a.attempt, "counted": a.counted,
                         "time": moments.moment(a.created_at, zone), "raw": a.raw,
                         "message": a.message, "status": _(_STATUS_WORDS.get(a.status, a.status)), "correct": a.correct,
                         "score": round(a.score, 3), "max_score": round(a.max_score, 3),
                         "feedback": a.feedback} for a in mine if a.part == info.name]})
    solution = _solution(data, rules, student_id, exercise_id, mine, now) \
        if seed is None else None
    return {
        "id": exercise_id, "title": meta.title, "points": meta.points,
        "statement": Markup(data.statement_html(student_id, exercise_id, seed)),
        "figure": Markup(data.figure_svg(student_id, exercise_id) or "")
        if seed is None else "",
        "parts": parts, "key": uuid.uuid4().hex,
        "practice": practice_value if seed is not None else None,
        "result": result if seed is None else None,
        "answered": any(p["history"] for p in parts),
        "locked": not rules.is_open(now) and seed is None,
        "solution": Markup(solution) if solution else None}


def _reading(data: ExamData, student_id: str, exercise_id: str, info, text: str,
             seed: int | None) -> dict | None:
    """How the text a box shows reads, as the preview under it says it (the page carries
    it, so that its script asks for no preview on load): ``{"readable", "message",
    "formula"}`` with the formula as MathML markup; ``None`` for an empty box or a choice
    (whose ticks need no reading)."""
    if info.options or not text.strip():
        return None
    read = data.reading(student_id, exercise_id, info.name, text, seed)
    return {**read, "formula": Markup(read["formula"]) if read["formula"] else None}


def _status(data: ExamData, typed: Typed | None, error: str | None,
            exercises: list[dict]) -> dict | None:
    """The summary a submit ends on (the page moves the focus to it): what was saved,
    what could not be read, or why nothing was."""
    if typed is None or typed.exercise_id not in data.exercises_meta:
        return {"alert": True, "text": error} if error else None
    title = data.exercises_meta[typed.exercise_id].title
    if error:
        return {"alert": True, "text": error, "exercise": typed.exercise_id}
    if typed.reasons:
        return {"alert": True, "exercise": typed.exercise_id, "text": ngettext(
            "Answers to “{title}” saved, but {n} answer could not be read: it was not "
            "saved and cost no attempt. Correct it and submit again.",
            "Answers to “{title}” saved, but {n} answers could not be read: they were not "
            "saved and cost no attempt. Correct them and submit again.",
            len(typed.reasons)).format(title=title, n=len(typed.reasons))}
    return {"alert": False, "exercise": typed.exercise_id,
            "text": _("Your answers to “{title}” were saved.").format(title=title)}


def _policy_lines(rules: Rules, now: dt.datetime) -> list[str]:
    """The exam's rules as the student page lists them (with the student's own
    exceptions), each a sentence."""
    policy, allowance = rules.policy, rules.allowance
    lines = [{"exam": _("Exam"), "homework": _("Homework"),
              "practice": _("Practice")}.get(policy.mode, policy.mode)]
    if rules.timed:
        lines.append(ngettext("Time limit: {n} minute from when you press “Start”",
                              "Time limit: {n} minutes from when you press “Start”",
                              rules.minutes).format(n=rules.minutes))
        if allowance and allowance.extra_minutes:
            lines.append(ngettext("({n} extra minute granted to you included)",
                                  "({n} extra minutes granted to you included)",
                                  allowance.extra_minutes).format(n=allowance.extra_minutes))
    if policy.attempts:
        lines.append(ngettext("{n} attempt per part", "{n} attempts per part",
                              policy.attempts).format(n=policy.attempts))
        if allowance and allowance.extra_attempts:
            lines.append(_("You were granted extra attempts: each part shows the attempts "
                           "it has left"))
    else:
        lines.append(_("Attempts per part: no limit"))
    if policy.penalty:
        lines.append(_("each further attempt of a part earns {percent} % fewer points")
                     .format(percent=round(100 * policy.penalty)))
    lines.append(_("What counts: the best attempt of each part") if policy.counts == "best"
                 else _("What counts: the last saved answer of each part"))
    lines.append(_("Verdicts and points are shown after each submit")
                 if rules.shows_verdicts(now) else
                 _("Answers are checked for readability only; verdicts and points appear "
                   "after the close"))
    lines.append(_("An answer that cannot be read is not saved and costs no attempt"))
    return lines


def staff_tables(server: Server) -> dict:
    """What the staff page shows and its script refreshes: counts, the gradebook and the
    progress, each table as ``{"columns": [...], "rows": [[cell text, ...], ...]}``."""
    data = server.data
    stored = db.all_answers(server.engine, data.exam_id)
    columns, rows = gradebook.staff_table(data, stored,
                                          db.stored_overrides(server.engine, data.exam_id))
    book = [["—" if row[c] is None else str(row[c]) for c in columns] for row in rows]
    zone = moments.exam_zone(data.policy)
    progress = [[p["student_id"], p["name"],
                 *(str(p["attempts"].get(e, "")) for e in data.exercise_ids),
                 moments.moment(p["last"], zone, seconds=True).text if p["last"] else ""]
                for p in gradebook.progress(data, stored)]
    counts = db.counts(server.engine, data.exam_id)
    text = ", ".join([
        ngettext("{n} submission", "{n} submissions", counts["submissions"]).format(
            n=counts["submissions"]),
        ngettext("{n} answer stored", "{n} answers stored", counts["answers"]).format(
            n=counts["answers"])])
    return {"submissions": counts["submissions"], "answers": counts["answers"],
            "counts_text": text,
            "gradebook": {"columns": [_(c) if c in gradebook.COLUMN_WORDS else c
                                      for c in columns], "rows": book},
            "progress": {"columns": [_("student"), _("name"), *data.exercise_ids,
                                     _("last submit ({zone})").format(
                                         zone=_zone_name(zone))], "rows": progress}}


def _zone_name(zone: dt.tzinfo) -> str:
    """A zone as the staff read it: its name (Europe/Zurich), else its abbreviation."""
    return str(getattr(zone, "key", None) or zone.tzname(None) or "UTC")


#: how often the staff page's script asks for fresh tables (seconds)
STAFF_POLL_SECONDS = 30


def staff_html(server: Server, token: str, now: dt.datetime, base: str,
               error: str | None = None, typed: dict[str, str] | None = None) -> str:
    """The staff page: counts, gradebook and progress (refreshed by its script, which can
    be paused), the downloads, the policy form and the recorded changes. ``error`` and
    ``typed``: a refused policy change, shown with what was typed."""
    from .policy_changes import CHANGEABLE

    data = server.data
    policy = data.policy
    current = {k: ("" if v is None else str(v)) for k, v in policy.to_json().items()}
    return _TEMPLATES.get_template("staff.html").render(
        title=data.title, token=token, base=base, language=data.manifest.exam.language,
        tables=staff_tables(server), poll=STAFF_POLL_SECONDS,
        policy_text=policy_text(policy, now), mode=policy.mode, keys=CHANGEABLE,
        values={**current, **(typed or {})}, error=error,
        csrf=limits.csrf_field(server.secret, token),
        changes=db.changes(server.engine, data.exam_id, db.POLICY_CHANGE, limit=20))


#: the policy's modes as the pages name them
_MODE_WORDS = (N_("exam"), N_("homework"), N_("practice"))


def policy_text(policy, now: dt.datetime) -> str:
    """The exam's policy in one line, as the pages show it."""
    words = [_(policy.mode)]
    if policy.closes:
        words.append(_("closes {time}").format(time=policy.closes.isoformat()))
    if policy.attempts:
        words.append(_("{n} attempts per part").format(n=policy.attempts))
    if policy.time_limit:
        words.append(_("{n} minutes from each student's start").format(n=policy.time_limit))
    if policy.penalty:
        words.append(_("{percent} % less per extra attempt").format(
            percent=round(100 * policy.penalty)))
    words.append(_("verdicts shown") if policy.shows_verdicts(now) else
                 _("answers are checked for readability only; verdicts after the close"))
    return " · ".join(words)


def _solution(data: ExamData, rules: Rules, student_id: str, exercise_id: str, mine: list,
              now: dt.datetime) -> str | None:
    """The worked solution of the student's variant as HTML, once the policy lets them
    see it: after their close, or after the last attempt of every part (their extra ones
    included; ``mine``: the student's counted answers to the exercise)."""
    used = Counter(a.part for a in mine)
    out_of_attempts = bool(rules.policy.attempts) and all(
        used[part.name] >= rules.attempts(exercise_id, part.name)
        for part in data.manifest_parts[exercise_id])
    if not solution_visible(rules.policy.solutions, rules.closed(now),
                            rules.shows_verdicts(now), out_of_attempts):
        return None
    return data.solution_html(student_id, exercise_id)
