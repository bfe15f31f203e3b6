"""Points by hand on the server: the staff set the points of one part of one student,
with a comment, and remove them again.

An override is checked exactly as a row of the offline overrides file
(:class:`dynagrade.classgrade.overrides.OverrideRules`: the student on the roster, the
exercise and part in the exam, 0 ≤ points ≤ the part's points, a multiple of the exam's
rounding; and :func:`~dynagrade.classgrade.overrides.not_handed_in`: an exercise the
student handed nothing in for has no graded part to replace). It is stored beside the
automatic verdict, never over it (table ``overrides``; :mod:`.db`), and applied where the
server builds its marks (:func:`dynagrade.serve.gradebook.outcome` and
:func:`dynagrade.serve.standing.results`) by class grading's own
:func:`~dynagrade.classgrade.overrides.apply_overrides`: the override wins, the automatic
score stays in the part's record, and the part's feedback ends with the staff's note.
Removing it restores the automatic score.

Each set, change or removal is one entry of the audit log (action ``override``, subject
``student/exercise/part``, before and after ``{"points", "comment"}``); setting the same
points and comment again, or removing what is not there, changes and records nothing.

:func:`overrides_csv` writes the stored overrides as the offline file
(``student_id,exercise,part,points,comment``), so ``dynagrade grade --manifest … --overrides``
on the server's downloads gives the server's ``grades.csv``.
"""

from __future__ import annotations

from typing import Sequence

import sqlalchemy as sa

from ..classgrade.overrides import OVERRIDE_COLUMNS, Override, OverrideRules, not_handed_in
from ..i18n import _
from ..exam.csvcells import csv_text
from . import db
from .exam_data import ExamData
from .submit import Refused

#: the longest comment kept with points set by hand
MAX_COMMENT_CHARS = 2000


def set_points(engine: sa.Engine, data: ExamData, actor: str, student_id: str,
               exercise_id: str, part: str, points: str | float, comment: str = ""
               ) -> bool:
    """Set the points of a student's part by hand (``actor``: who, for the audit log);
    whether anything changed. :class:`~dynagrade.serve.submit.Refused` (422) names what
    is wrong, as the overrides file's check words it."""
    rules = OverrideRules(data.manifest, data.rounding)
    try:
        checked = rules.points(student_id, exercise_id, part, points)
    except ValueError as problem:
        raise Refused(422, str(problem)) from None
    comment = comment.strip()
    if len(comment) > MAX_COMMENT_CHARS:
        raise Refused(422, _("the comment is longer than {n} characters").format(
            n=MAX_COMMENT_CHARS))
    stored = db.student_answers(engine, data.exam_id, student_id)
    if not any(a.counted and a.exercise_id == exercise_id for a in stored):
        raise Refused(422, not_handed_in(student_id, exercise_id))
    return db.put_override(engine, data.exam_id, actor, student_id, exercise_id, part,
                           checked, comment) is not None


def remove_points(engine: sa.Engine, data: ExamData, actor: str, student_id: str,
                  exercise_id: str, part: str) -> bool:
    """Remove the points set by hand on a student's part (the automatic score counts
    again); whether there were any. Refused (422) for a student, exercise or part not in
    the exam."""
    try:
        OverrideRules(data.manifest, data.rounding).part_points(student_id, exercise_id,
                                                                part)
    except ValueError as problem:
        raise Refused(422, str(problem)) from None
    return db.put_override(engine, data.exam_id, actor, student_id, exercise_id, part,
                           None) is not None


def as_class_overrides(stored: Sequence[db.StoredOverride]) -> tuple[Override, ...]:
    """The stored overrides as class grading applies them (with their author and time)."""
    return tuple(Override(number, o.student_id, o.exercise_id, o.part, o.points, o.comment,
                          author=o.author, at=db.iso(o.at))
                 for number, o in enumerate(stored, 1))


def overrides_csv(data: ExamData, stored: Sequence[db.StoredOverride]) -> str:
    """The stored overrides as the offline overrides file, in roster and exam order."""
    order = {(s, e, p.name): n for n, (s, e, p) in enumerate(
        (s, e, p) for s in data.students for e in data.exercise_ids
        for p in data.manifest_parts[e])}
    return csv_text([OVERRIDE_COLUMNS, *(
        [o.student_id, o.exercise_id, o.part, data.rounding.text(o.points), o.comment]
        for o in sorted(stored, key=lambda o: order.get(
            (o.student_id, o.exercise_id, o.part), len(order))))])
