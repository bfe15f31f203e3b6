"""The HTML of the staff's regrade page (``/i/{token}/regrade``, template
``templates/regrade.html``): the "Preview regrade" form, the open plan as a table of
the verdicts it changes (old → new, and the student's total old → new) with "Apply" and
"Discard", what an applied plan changed, and the earlier regrades."""

from __future__ import annotations

import datetime as dt

from ..i18n import N_, _, ngettext
from . import db, limits, moments, pages, regrade
from .state import Server

#: a regrade's states as the page names them
STATE_WORDS = {"previewed": N_("previewed"), "applied": N_("applied"),
               "discarded": N_("discarded")}


def _when(value: dt.datetime | None, zone: dt.tzinfo) -> str:
    """A time in the course's zone, to the second, naming the zone ("" for none)."""
    return "" if value is None else moments.moment(value, zone, seconds=True).text


def _plan_rows(server: Server, plan: dict) -> list[dict]:
    """The plan's changes as the table shows them (cell texts)."""
    data = server.data
    text = data.rounding.text
    titles = {e: m.title for e, m in data.exercises_meta.items()}
    rows = []
    for change in plan["changes"]:
        totals = plan["grades"].get(change["student_id"], {}).get("total", [None, None])
        old, new = change["old"], change["new"]
        rows.append({
            "student": f"{change['student_id']} {change['name']}".strip(),
            "exercise": titles.get(change["exercise_id"], change["exercise_id"]),
            "part": change["label"], "attempt": change["attempt"], "raw": change["raw"],
            "old": f"{_(old['status'])}, {text(old['score'])}",
            "new": f"{_(new['status'])}, {text(new['score'])}",
            "counts": _("yes") if change["counts"] else _("no"),
            "total": "—" if totals[0] == totals[1] else
            f"{_total(text, totals[0])} → {_total(text, totals[1])}"})
    return rows


def _total(text, value: float | None) -> str:
    return "—" if value is None else text(value)


def _result(server: Server, applied: int | None) -> str | None:
    """What the plan just applied changed, in a sentence or two."""
    if applied is None:
        return None
    found = db.find_regrade(server.engine, server.data.exam_id, applied)
    if found is None or found.state != "applied":
        return None
    changes = found.plan["changes"]
    totals = sum(1 for t in found.plan["grades"].values() if t["total"][0] != t["total"][1])
    sentence = " ".join([
        ngettext("Regrade {id} applied: {n} verdict changed.",
                 "Regrade {id} applied: {n} verdicts changed.", len(changes)).format(
            id=found.id, n=len(changes)),
        ngettext("The total of {n} student changed.", "The totals of {n} students changed.",
                 totals).format(n=totals),
        _("The old verdicts are kept in the verdict history; every server grades new "
          "submits by the files regraded against within seconds.")])
    since = regrade.answers_since(server, found)
    if since:
        sentence += " " + ngettext(
            "{n} answer was submitted between the preview and the reload of every server and "
            "may have been graded by the files of before: preview again to regrade it if "
            "needed.",
            "{n} answers were submitted between the preview and the reload of every server "
            "and may have been graded by the files of before: preview again to regrade "
            "those that need it.", since).format(n=since)
    return sentence


def regrade_html(server: Server, token: str, now: dt.datetime, base: str,
                 error: str | None = None, applied: int | None = None) -> str:
    """The regrade page; ``error``: why the last form was refused; ``applied``: the plan
    just applied."""
    data = server.data
    zone = moments.exam_zone(data.policy)
    history = db.list_regrades(server.engine, data.exam_id)
    plan = next((r for r in history if r.state == "previewed"), None)
    return pages.render(
        "regrade.html", title=data.title, token=token, base=base,
        language=data.manifest.exam.language, csrf=limits.csrf_field(server.secret, token),
        error=error, result=_result(server, applied),
        plan=None if plan is None else {
            "id": plan.id, "actor": plan.actor, "when": _when(plan.created_at, zone),
            "answers": plan.plan["answers"], "rows": _plan_rows(server, plan.plan)},
        history=[{"id": r.id, "when": _when(r.created_at, zone), "actor": r.actor,
                  "state": _(STATE_WORDS.get(r.state, r.state)),
                  "applied": _when(r.applied_at, zone), "changes": len(r.plan["changes"])}
                 for r in history])
