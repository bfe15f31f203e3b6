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
from ..i18n import N_, _, ngettext
from .exam_data import MAX_ANSWER_CHARS, ExamData
from .practice import practice_seed
from .state import Server
from .submit import Refused

_TEMPLATES = jinja2.Environment(
    loader=jinja2.FileSystemLoader(Path(__file__).resolve().parent / "templates"),
    autoescape=True, trim_blocks=True, lstrip_blocks=True)
#: a template's fixed strings are ``{{ _("...") }}``, in the language of the request
_TEMPLATES.globals.update(_=_, ngettext=ngettext)


def student_html(server: Server, token: str, student_id: str, practice: str | None,
                 now: dt.datetime, base: str, error: str | None = None) -> str:
    """A student's page: their variant of every exercise, answer boxes, their attempts
    and what the policy shows; ``practice`` (``"<exercise>:<signed draw>"``) shows a
    practice draw of one exercise instead of the student's own variant."""
    from ..render.markup import markdown_to_html

    data = server.data
    verdicts = data.policy.shows_verdicts(now)
    stored = db.student_answers(server.engine, data.exam_id, student_id)
    practice_of, _colon, practice_value = (practice or "").partition(":")
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
                         "status": _(a.status), "correct": a.correct,
                         "score": round(a.score, 3), "max_score": round(a.max_score, 3),
                         "feedback": a.feedback} for a in reversed(mine)],
            "solution": Markup(solution) if solution else None})
    is_open = data.policy.is_open(now)
    closed_text = (_("The exam is not open yet.") if data.policy.opens and now < data.policy.opens
                   else _("The exam is closed; answers are no longer accepted."))
    return _TEMPLATES.get_template("student.html").render(
        title=data.title, student=data.students[student_id], token=token, base=base,
        language=data.manifest.exam.language,
        csrf=limits.csrf_field(server.secret, token), exercises=exercises, verdicts=verdicts,
        mode=data.policy.mode, policy_text=policy_text(data.policy, now), is_open=is_open,
        closed_text=closed_text, error=error, max_chars=MAX_ANSWER_CHARS,
        instructions=Markup(markdown_to_html(data.instructions)) if data.instructions else "",
        submit_label=_("Save answers") if not verdicts else _("Submit"))


def staff_html(server: Server, token: str, now: dt.datetime, base: str) -> str:
    """The staff page: gradebook, progress and the downloads."""
    data = server.data
    stored = db.all_answers(server.engine, data.exam_id)
    columns, rows = gradebook.staff_table(data, stored)
    return _TEMPLATES.get_template("staff.html").render(
        title=data.title, token=token, base=base, rows=rows, columns=columns,
        language=data.manifest.exam.language,
        progress=gradebook.progress(data, stored), exercise_ids=data.exercise_ids,
        counts=db.counts(server.engine, data.exam_id), refresh=60,
        policy_text=policy_text(data.policy, now))


#: the policy's modes as the pages name them
_MODE_WORDS = (N_("exam"), N_("homework"), N_("practice"))


def policy_text(policy, now: dt.datetime) -> str:
    """The exam's policy in one line, as the pages show it."""
    words = [_(policy.mode)]
    if policy.closes:
        words.append(_("closes {time}").format(time=policy.closes.isoformat()))
    if policy.attempts:
        words.append(_("{n} attempts per part").format(n=policy.attempts))
    if policy.penalty:
        words.append(_("{percent} % less per extra attempt").format(
            percent=round(100 * policy.penalty)))
    words.append(_("verdicts shown") if policy.shows_verdicts(now) else
                 _("answers are checked for readability only; verdicts after the close"))
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
