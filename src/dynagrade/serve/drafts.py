"""Drafts: what a student typed and has not submitted, kept so that nothing typed is lost.

The student page saves the text of each box as the student types (debounced, through
``PUT /api/v1/drafts``) and shows it again on every later page: after a reload, after a
submit of another exercise, on another device. A draft is never graded and never
counts, at the close either (docs/serve.md, "Drafts and what counts"): only a submit
counts. A draft newer than the part's last counted answer is what the part's box shows;
an older one was submitted since (or typed before it) and is ignored.
"""

from __future__ import annotations

import datetime as dt

from starlette.concurrency import run_in_threadpool

from . import db
from .exam_data import ExamData
from .submit import check_open, check_texts


def check_drafts(data: ExamData, exercise_id, texts) -> dict[str, str]:
    """The drafts of a well-formed request (an empty text is a draft too: the student
    cleared the box); :class:`Refused` (422) otherwise, as for a submit."""
    check_texts(data, exercise_id, texts)
    return dict(texts)


async def save(state, student_id: str, exercise_id, texts, now: dt.datetime) -> list[str]:
    """Store one exercise's drafts while the exam is open (403 otherwise); the parts
    saved."""
    data: ExamData = state.data
    checked = check_drafts(data, exercise_id, texts)
    check_open(data.policy, now)
    await run_in_threadpool(db.save_drafts, state.engine, data.exam_id, student_id,
                            exercise_id, checked)
    return list(checked)


def shown_texts(stored: list[db.StoredAnswer], drafts: list[db.Draft]
                ) -> dict[tuple[str, str], str]:
    """What each part's box shows, by (exercise, part): the latest counted answer, or a
    draft saved after it."""
    shown: dict[tuple[str, str], str] = {}
    when: dict[tuple[str, str], dt.datetime] = {}
    for answer in stored:  # oldest first
        if answer.counted:
            shown[(answer.exercise_id, answer.part)] = answer.raw
            when[(answer.exercise_id, answer.part)] = answer.created_at
    for draft in drafts:
        key = (draft.exercise_id, draft.part)
        if key not in when or db.aware(draft.saved_at) > db.aware(when[key]):
            shown[key] = draft.text
    return shown
