"""Regrading the stored answers after an exercise file or the manifest's key was fixed.

A regrade has three steps (docs/serve.md, "Regrade after fixing a key or a tolerance"):

1. **Preview** (:func:`preview`): every counted answer is graded again against the
   manifest and the exercise files *as they are on disk now*, in processes spawned for
   it that load :class:`~dynagrade.serve.exam_data.ExamData` afresh (the worker's own
   copy holds the files as they were when it started). Each answer is graded as its
   submit graded it: the parts of one submission together, then the penalty of the
   policy in force at the submit's time for the part's attempt number. The answers whose
   status, points or misconception would change are the plan, kept with their old and
   new verdicts and the digests of the files used (``source``). Practice draws are not
   regraded: they never count, and each was graded against a draw of its own, not the
   manifest's key.
2. **Apply** (:func:`apply`): in one transaction, each answer of the plan must still hold
   its old verdict, the old verdict is copied to ``verdict_history``, the new one
   replaces it, the plan is marked applied and the audit log records it. Applying again
   does nothing. Every server process then loads the exam again (:mod:`.reload`), so new
   submits are graded as the plan was.
3. or **Discard** (:func:`discard`).

Students whose verdicts changed see a notice on their page (:func:`notices`) where the
policy shows them verdicts.
"""

from __future__ import annotations

import dataclasses
import datetime as dt
import hashlib
import multiprocessing
import os
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

from ..exam.policy import Policy
from ..i18n import _
from . import db, gradebook, moments
from .db import StoredAnswer
from .exam_data import ExamData
from .state import Server
from .submit import Refused
from .verdicts import SubmittedPart

#: one job of the spawned process: the submission's answers (part -> text) and whose
Job = tuple[str, str, dict[str, str]]


# -- recomputing, in a fresh process -------------------------------------------------------


def _digest(path: str | Path) -> str:
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()


def source_of(data: ExamData) -> dict:
    """The files ``data`` was loaded from (the manifest, each exercise's file), each with
    its path and SHA-256 as it is on disk now."""
    return {"manifest": {"path": str(data.path.resolve()), "digest": _digest(data.path)},
            "exercise_files": {i: {"path": str(e.file), "digest": _digest(e.file)}
                          for i, e in data.exercises.items()}}


def _source_now(source: dict) -> dict | None:
    """The digests of the files a ``source`` names, as they are on disk now (None: one
    cannot be read)."""
    try:
        return _digests(source)
    except OSError:
        return None


def _digests(source: dict) -> dict:
    return {"manifest": {"path": source["manifest"]["path"],
                         "digest": _digest(source["manifest"]["path"])},
            "exercise_files": {i: {"path": f["path"], "digest": _digest(f["path"])}
                          for i, f in source["exercise_files"].items()}}


def _recompute(manifest: str, folders: tuple[str, ...], jobs: list[Job]
               ) -> tuple[dict, list[list[SubmittedPart]]]:
    """In a spawned process: the exam loaded from disk, each job graded as a submit
    grades it (before the penalty); with the digests of the files used. A verdict depends
    on the variant's numbers and the texts alone (not on the student or the seed), so
    students who share both are graded once."""
    from ..exercise.loader import open_bank
    from ..i18n import language

    digest = _digest(manifest)
    data = ExamData(manifest, open_bank(folders))
    source = source_of(data)
    if source["manifest"]["digest"] != digest:  # replaced while loading: load it again
        return _recompute(manifest, folders, jobs)
    graded: dict[tuple, list[SubmittedPart]] = {}
    out = []
    with language(data.manifest.exam.language):
        for student_id, exercise_id, texts in jobs:
            entry = data.entry(student_id, exercise_id)
            same = (exercise_id, repr(sorted(entry.params.items())),
                    repr(sorted(entry.answers.items())), tuple(sorted(texts.items())))
            if same not in graded:
                graded[same] = data.grade(student_id, exercise_id, texts, check=False)
            out.append(graded[same])
    return source, out


#: processes a preview grades in (each loads the exam; more than the cores gain nothing)
PREVIEW_PROCESSES = max(1, min(4, os.cpu_count() or 1))


def _in_fresh_processes(server: Server, jobs: list[Job]
                        ) -> tuple[dict, list[list[SubmittedPart]]]:
    """:func:`_recompute` of ``jobs`` in :data:`PREVIEW_PROCESSES` spawned processes (the
    jobs of one exercise kept together, so that students sharing a variant's numbers are
    mostly graded once); the verdicts in the jobs' order. :class:`Refused` (409) when the files changed meanwhile."""
    settings = server.settings
    order = sorted(range(len(jobs)), key=lambda i: jobs[i][:2][::-1])
    count = min(PREVIEW_PROCESSES, max(1, len(jobs) // 200))
    chunks = [order[k * len(order) // count:(k + 1) * len(order) // count]
              for k in range(count)]
    context = multiprocessing.get_context("spawn")
    with ProcessPoolExecutor(count, mp_context=context) as pool:
        futures = [pool.submit(_recompute, str(settings.manifest), tuple(settings.folders),
                               [jobs[i] for i in chunk]) for chunk in chunks]
        results = [future.result() for future in futures]
    sources = [source for source, _graded in results]
    if any(source != sources[0] for source in sources):
        raise Refused(409, _("the manifest or an exercise file changed during the preview; "
                             "preview again"))
    verdicts: list[list[SubmittedPart]] = [[] for _job in jobs]
    for chunk, (_source, graded) in zip(chunks, results):
        for index, parts in zip(chunk, graded):
            verdicts[index] = parts
    return sources[0], verdicts


# -- the policy at each submit -----------------------------------------------------------


def _policy_history(server: Server) -> list[tuple[dt.datetime, Policy]]:
    """The policy in force from each moment on, oldest first (the manifest's from the
    start; each recorded change from its time)."""
    data = server.data
    history = [(dt.datetime.min.replace(tzinfo=dt.timezone.utc), data.manifest_policy)]
    for entry in reversed(db.changes(server.engine, data.exam_id, db.POLICY_CHANGE)):
        if entry.after is not None:
            history.append((db.utc(entry.at), Policy.from_json(entry.after)))
    return history


def _policy_at(history: list[tuple[dt.datetime, Policy]], moment: dt.datetime) -> Policy:
    return [policy for since, policy in history if since <= db.utc(moment)][-1]


# -- preview -------------------------------------------------------------------------------


def _verdict(answer: StoredAnswer) -> dict:
    return {"status": answer.status, "correct": bool(answer.correct),
            "score": float(answer.score), "feedback": answer.feedback,
            "misconception": answer.misconception}


def _regraded(answer: StoredAnswer, part: SubmittedPart) -> StoredAnswer:
    row = part.row()
    return dataclasses.replace(answer, **{c: row[c] for c in db.VERDICT})


def _differs(old: dict, new: dict) -> bool:
    return (old["status"] != new["status"] or abs(old["score"] - new["score"]) > 1e-9
            or old["misconception"] != new["misconception"])


def preview(server: Server, actor: str) -> db.Regrade:
    """Grade every counted answer again against the files on disk and keep the plan of
    the verdicts that would change (see the module docstring)."""
    started = time.perf_counter()
    data = server.data
    stored = db.counted_answers_by_id(server.engine, data.exam_id)
    submissions: dict[int, list[tuple[int, StoredAnswer]]] = {}
    for answer_id, answer in stored:
        submissions.setdefault(answer.submission_id, []).append((answer_id, answer))
    groups = list(submissions.values())
    jobs = [(rows[0][1].student_id, rows[0][1].exercise_id,
             {answer.part: answer.raw for _id, answer in rows}) for rows in groups]
    try:
        source, graded = _in_fresh_processes(server, jobs)
    except Refused:
        raise
    except Exception as error:  # the files on disk cannot be loaded or graded
        raise Refused(422, _("the exam cannot be regraded as its files are now: "
                             "{error}").format(error=error)) from None
    history = _policy_history(server)
    tries: dict[tuple[str, str, str], int] = {}
    new_stored: dict[int, StoredAnswer] = {}
    for rows, parts in zip(groups, graded):
        by_name = {part.name: part for part in parts}
        policy = _policy_at(history, rows[0][1].created_at)
        for answer_id, answer in rows:
            key = (answer.student_id, answer.exercise_id, answer.part)
            tries[key] = tries.get(key, 0) + 1
            factor = policy.attempt_factor(tries[key])
            new_stored[answer_id] = _regraded(answer, by_name[answer.part].penalised(
                factor, tries[key]))
    plan = _plan(data, stored, new_stored, db.stored_overrides(server.engine, data.exam_id))
    plan["seconds"] = round(time.perf_counter() - started, 2)
    regrade_id = db.store_regrade(server.engine, data.exam_id, actor, source, plan)
    found = db.find_regrade(server.engine, data.exam_id, regrade_id)
    assert found is not None
    return found


def _plan(data: ExamData, stored: list[tuple[int, StoredAnswer]],
          new_stored: dict[int, StoredAnswer], overrides: list[db.StoredOverride]) -> dict:
    """The changed verdicts, old and new, and what they change in the gradebook (where
    the staff set a part's points by hand, those stay)."""
    old_list = [answer for _id, answer in stored]
    new_list = [new_stored[answer_id] for answer_id, _a in stored]
    old_counted = _counted_ids(data, stored, old_list)
    new_counted = _counted_ids(data, stored, new_list)
    changes = []
    for answer_id, answer in stored:
        old, new = _verdict(answer), _verdict(new_stored[answer_id])
        if not _differs(old, new):
            continue
        parts = {p.name: p for p in data.manifest_parts[answer.exercise_id]}
        changes.append({
            "answer_id": answer_id, "student_id": answer.student_id,
            "name": data.students[answer.student_id].name
            if answer.student_id in data.students else "",
            "exercise_id": answer.exercise_id, "part": answer.part,
            "label": parts[answer.part].label if answer.part in parts else answer.part,
            "attempt": answer.attempt, "raw": answer.raw, "old": old, "new": new,
            "counts": answer_id in old_counted or answer_id in new_counted})
    affected: set[str] = {str(c["student_id"]) for c in changes}
    before, after = (_grades(data, answers, affected, overrides)
                     for answers in (old_list, new_list))
    grades = {s: {"cells": {e: [before[s]["cells"][e], after[s]["cells"][e]]
                                  for e in data.exercise_ids},
                    "total": [before[s]["total"], after[s]["total"]]}
                for s in sorted(affected) if s in before}
    return {"answers": len(stored), "changes": changes, "grades": grades,
            "last_answer_id": max((i for i, _a in stored), default=0)}


def _counted_ids(data: ExamData, stored: list[tuple[int, StoredAnswer]],
                 answers: list[StoredAnswer]) -> set[int]:
    """The ids of the answers that count (the gradebook's choice among ``answers``)."""
    ids = {id(answer): answer_id for (answer_id, _a), answer in zip(stored, answers)}
    return {ids[id(answer)] for answer in gradebook.counted_answers(data, answers).values()}


def _grades(data: ExamData, answers: list[StoredAnswer], students: set[str],
            overrides: list[db.StoredOverride]) -> dict:
    """Each of ``students``' points per exercise and total, as the gradebook has them."""
    if not students:
        return {}
    rows = gradebook.outcome(data, answers, overrides).rows
    return {row.student_id: {"cells": dict(row.cells), "total": row.total}
            for row in rows if row.student_id in students}


# -- apply and discard ---------------------------------------------------------------------


def find(server: Server, regrade_id: int) -> db.Regrade:
    """The exam's regrade ``regrade_id``; :class:`Refused` (404) when there is none."""
    found = db.find_regrade(server.engine, server.data.exam_id, regrade_id)
    if found is None:
        raise Refused(404, _("no regrade {id} in this exam").format(id=regrade_id))
    return found


def apply(server: Server, regrade_id: int, actor: str) -> tuple[db.Regrade, bool]:
    """Apply a previewed plan (see the module docstring): (the regrade, whether this call
    applied it). :class:`Refused`: 404 for an unknown plan, 409 when it was discarded,
    the files changed since the preview or an answer no longer holds its old verdict."""
    found = find(server, regrade_id)
    if found.state == "discarded":
        raise Refused(409, _("this regrade was discarded; preview again"))
    if found.state == "previewed" and _source_now(found.source) != found.source:
        raise Refused(409, _("the manifest or an exercise file changed since the "
                             "preview; preview again"))
    changes = found.plan["changes"]
    totals = found.plan["grades"]
    before = {"state": "previewed", "answers": len(changes),
              "totals": {s: t["total"][0] for s, t in totals.items()}}
    after = {"state": "applied", "answers": len(changes),
             "totals": {s: t["total"][1] for s, t in totals.items()}}
    try:
        done = db.apply_regrade(server.engine, server.data.exam_id, regrade_id, actor,
                                changes, before, after)
    except db.RegradeConflict as error:
        raise Refused(409, _("answers changed since the preview; preview again")
                      if error.why == "answers changed" else
                      _("this regrade was discarded; preview again")) from None
    return find(server, regrade_id), done


def discard(server: Server, regrade_id: int, actor: str) -> tuple[db.Regrade, bool]:
    """Discard a previewed plan: (the regrade, whether this call discarded it);
    :class:`Refused` 404 for an unknown plan, 409 for an applied one."""
    find(server, regrade_id)
    try:
        done = db.discard_regrade(server.engine, server.data.exam_id, regrade_id, actor)
    except db.RegradeConflict:
        raise Refused(409, _("this regrade was applied; it cannot be discarded")) from None
    return find(server, regrade_id), done


#: how long after an apply every server process grades by the new files at the latest
#: (seconds): :data:`.reload.FRESH_SECONDS` and the time a load takes, generously
RELOADED_WITHIN = 15.0


def answers_since(server: Server, regrade: db.Regrade) -> int:
    """How many counted answers were stored after the plan was previewed and before
    every server process had loaded the files it was applied with: they may have been
    graded by the files of before (a new preview regrades those that need it)."""
    until = None
    if regrade.applied_at is not None:
        until = regrade.applied_at + dt.timedelta(seconds=RELOADED_WITHIN)
    return db.counted_answers_after(server.engine, server.data.exam_id,
                                    int(regrade.plan.get("last_answer_id", 0)), until)


# -- what the student is told --------------------------------------------------------------


def notices(server: Server, student_id: str, now: dt.datetime) -> list[str]:
    """One line per verdict of the student's that an applied regrade changed: "Regraded
    on <date>: <exercise> <part>: <old> → <new> points"; none where the policy does not
    show verdicts at ``now`` (an exam before its close)."""
    data = server.data
    policy = data.policy
    if not policy.shows_verdicts(now):
        return []
    zone = moments.exam_zone(policy)
    lines = []
    for changed in db.replaced_verdicts(server.engine, data.exam_id, student_id):
        meta = data.exercises_meta.get(changed.exercise_id)
        parts = {p.name: p.label for p in data.manifest_parts.get(changed.exercise_id, ())}
        when = db.utc(changed.applied_at).astimezone(zone)
        lines.append(_("Regraded on {date}: {exercise} {part} (attempt {attempt}): {old} → "
                       "{new} points").format(
            date=f"{when:%Y-%m-%d}", exercise=meta.title if meta else changed.exercise_id,
            part=parts.get(changed.part, changed.part), attempt=changed.attempt,
            old=data.rounding.text(changed.before),
            new=data.rounding.text(changed.after)))
    return lines
