"""The HTML of the student page and the staff page (templates in ``templates/``)."""

from __future__ import annotations

import datetime as dt
import uuid
from collections import Counter
from pathlib import Path

import jinja2
from markupsafe import Markup

from ..exam.solution_policy import solution_visible
from . import db, gradebook, limits
from ..i18n import _, ngettext
from .exam_data import MAX_ANSWER_CHARS, ExamData
from .practice import practice_seed
from .state import Server
from .submit import Refused

_TEMPLATES = jinja2.Environment(
    loader=jinja2.FileSystemLoader(Path(__file__).resolve().parent / "templates"),
    autoescape=True, trim_blocks=True, lstrip_blocks=True)
#: a template's fixed strings are ``{{ _("...") }}``, in the language of the request
_TEMPLATES.globals.update(_=_, ngettext=ngettext)


def render(template: str, **values) -> str:
    """``templates/<template>`` rendered with ``values`` (error pages, :mod:`.errors`)."""
    return _TEMPLATES.get_template(template).render(**values)


def student_html(server: Server, token: str, student_id: str, practice: str | None,
                 now: dt.datetime, base: str, error: str | None = None) -> str:
    """A student's page: their variant of every exercise, answer boxes, their attempts
    and what the policy shows; ``practice`` (``"<exercise>:<signed draw>"``) shows a
    practice draw of one exercise instead of the student's own variant."""
    from ..render.markup import markdown_to_html

    data = server.data
    verdicts = data.policy.shows_verdicts(now)
    stored = db.student_answers(server.engine, data.exam_id, student_id)
    practice_of, _, practice_value = (practice or "").partition(":")
    exercises = []
    for exercise_id in data.exercise_ids:
        meta = data.exercises_meta[exercise_id]
        seed = None
        if practice_of == exercise_id:
            try:
                seed = practice_seed(server.secret, student_id, exercise_id, practice_value)
            except Refused:
                seed = None
        mine = [a for a in stored if a.exercise_id == exercise_id and
                (a.counted if seed is None else a.seed == seed and not a.counted)]
        last = {a.part: a.raw for a in mine}
        solution = (_solution(data, student_id, exercise_id, mine, now)
                    if seed is None else None)
        exercises.append({
            "id": exercise_id, "title": meta.title, "points": meta.points,
            "statement": Markup(data.statement_html(student_id, exercise_id, seed)),
            "figure": Markup(data.figure_svg(student_id, exercise_id) or "")
            if seed is None else "",
            "parts": data.parts(exercise_id), "key": uuid.uuid4().hex, "last": last,
            "practice": practice_value if seed is not None else None,
            "history": [{"attempt": a.attempt, "counted": a.counted,
                         "time": a.created_at.strftime("%Y-%m-%d %H:%M:%S"),
                         "part": a.part, "raw": a.raw, "message": a.message,
                         "status": a.status, "correct": a.correct,
                         "score": round(a.score, 3), "max_score": round(a.max_score, 3),
                         "feedback": a.feedback} for a in reversed(mine)],
            "solution": Markup(solution) if solution else None})
    is_open = data.policy.is_open(now)
    closed_text = ("The exam is not open yet." if data.policy.opens and now < data.policy.opens
                   else "The exam is closed; answers are no longer accepted.")
    return _TEMPLATES.get_template("student.html").render(
        title=data.title, student=data.students[student_id], token=token, base=base,
        language=data.manifest.exam.language,
        csrf=limits.csrf_field(server.secret, token), exercises=exercises, verdicts=verdicts,
        mode=data.policy.mode, policy_text=policy_text(data.policy, now), is_open=is_open,
        closed_text=closed_text, error=error, max_chars=MAX_ANSWER_CHARS,
        instructions=Markup(markdown_to_html(data.instructions)) if data.instructions else "",
        submit_label="Save answers" if not verdicts else "Submit")


def staff_tables(server: Server) -> dict:
    """What the staff page shows and its script refreshes: counts, the gradebook and the
    progress, each table as ``{"columns": [...], "rows": [[cell text, ...], ...]}``."""
    data = server.data
    stored = db.all_answers(server.engine, data.exam_id)
    columns, rows = gradebook.staff_table(data, stored)
    book = [["—" if row[c] is None else str(row[c]) for c in columns] for row in rows]
    progress = [[p["student_id"], p["name"],
                 *(str(p["attempts"].get(e, "")) for e in data.exercise_ids),
                 p["last"].strftime("%Y-%m-%d %H:%M:%S") if p["last"] else ""]
                for p in gradebook.progress(data, stored)]
    counts = db.counts(server.engine, data.exam_id)
    text = ", ".join([
        ngettext("{n} submission", "{n} submissions", counts["submissions"]).format(
            n=counts["submissions"]),
        ngettext("{n} answer stored", "{n} answers stored", counts["answers"]).format(
            n=counts["answers"])])
    return {"submissions": counts["submissions"], "answers": counts["answers"],
            "counts_text": text,
            "gradebook": {"columns": columns, "rows": book},
            "progress": {"columns": [_("student"), _("name"), *data.exercise_ids,
                                     _("last submit (UTC)")], "rows": progress}}


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


def policy_text(policy, now: dt.datetime) -> str:
    """The exam's policy in one line, as the pages show it."""
    words = [policy.mode]
    if policy.closes:
        words.append(f"closes {policy.closes.isoformat()}")
    if policy.attempts:
        words.append(f"{policy.attempts} attempts per part")
    if policy.penalty:
        words.append(f"{round(100 * policy.penalty)} % less per extra attempt")
    words.append("verdicts shown" if policy.shows_verdicts(now) else
                 "answers are checked for readability only; verdicts after the close")
    return " · ".join(words)


def _solution(data: ExamData, student_id: str, exercise_id: str, mine: list,
              now: dt.datetime) -> str | None:
    """The worked solution of the student's variant as HTML, once the policy lets them
    see it: after the close, or after the last attempt of every part (``mine``: the
    student's counted answers to the exercise)."""
    policy = data.policy
    closed = policy.closes is not None and now >= policy.closes
    used = Counter(a.part for a in mine)
    out_of_attempts = bool(policy.attempts) and all(
        used[part.name] >= policy.attempts for part in data.manifest_parts[exercise_id])
    if not solution_visible(policy.solutions, closed, policy.shows_verdicts(now),
                            out_of_attempts):
        return None
    return data.solution_html(student_id, exercise_id)
