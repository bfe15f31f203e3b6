"""The score a platform should hold for a launched student now (AGS 2.0, "Score
publish service"), by the exam's feedback policy:

- while the student may not see their points (feedback waits for the close, and their
  close has not come), nothing;
- before their close, with points that count: ``scoreGiven`` their total as the
  gradebook holds it (rounded, points set by hand included), ``activityProgress``
  ``Submitted``;
- from their close on: their total (0 when nothing counts), ``Completed``.

``gradingProgress`` is ``FullyGraded`` (every counted answer is graded when stored),
``scoreMaximum`` the exam's points, ``userId`` the student's ``sub`` on the platform,
``timestamp`` the moment the score was computed (ISO 8601 with its offset).
"""

from __future__ import annotations

import datetime as dt

from ..allowances import Rules


def score_body(sub: str, total: float | None, max_total: float, rules: Rules,
               now: dt.datetime) -> dict | None:
    """The score's JSON body, or None when there is nothing the student may see."""
    if not rules.shows_verdicts(now):
        return None
    closed = rules.closed(now)
    if total is None and not closed:
        return None
    return {"userId": sub, "scoreGiven": float(total or 0.0), "scoreMaximum": float(max_total),
            "activityProgress": "Completed" if closed else "Submitted",
            "gradingProgress": "FullyGraded",
            "timestamp": now.astimezone(dt.timezone.utc).isoformat(timespec="milliseconds")}
