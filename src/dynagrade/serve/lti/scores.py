"""The score a platform should hold for a launched student now (AGS 2.0, "Score
publish service"), by the exam's feedback policy:

- while the student may not see their points (feedback waits for the close, and their
  close has not come), nothing;
- while nothing of theirs counts, nothing (the gradebook calls them absent, which is
  not 0 points: the staff decide);
- before their close: ``scoreGiven`` their total as the gradebook holds it (rounded,
  points set by hand included), ``activityProgress`` ``Submitted``;
- from their close on: the same total, ``Completed``.

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
    if total is None or not rules.shows_verdicts(now):
        return None
    closed = rules.closed(now)
    return {"userId": sub, "scoreGiven": float(total), "scoreMaximum": float(max_total),
            "activityProgress": "Completed" if closed else "Submitted",
            "gradingProgress": "FullyGraded",
            "timestamp": now.astimezone(dt.timezone.utc).isoformat(timespec="milliseconds")}
