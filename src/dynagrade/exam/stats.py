"""Item analysis of a graded class: how hard each part was and how well it separated
strong from weak students, and which wrong answers were common.

- difficulty: the mean score fraction of a part (1 = everyone right);
- point-biserial discrimination: the correlation between a part's score fraction and the
  student's total without that part (the corrected item-total correlation; ``None`` when
  either does not vary);
- upper-lower index: mean fraction in the best 27 % of students (by total) minus the mean
  in the weakest 27 %.
"""

from __future__ import annotations

import math
from collections import Counter
from dataclasses import dataclass, field

from .manifest import PartEntry

GROUP_FRACTION = 0.27


@dataclass
class PartStats:
    """Item statistics of one part of one exercise."""

    exercise_id: str
    part: str
    label: str
    points: float
    answered: int = 0
    difficulty: float | None = None
    point_biserial: float | None = None
    upper_lower: float | None = None
    wrong_answers: list[tuple[str, int, str]] = field(default_factory=list)
    misconceptions: list[tuple[str, int]] = field(default_factory=list)


def correlation(xs: list[float], ys: list[float]) -> float | None:
    """Pearson's correlation of ``xs`` and ``ys``; ``None`` when either is constant."""
    n = len(xs)
    if n < 2:
        return None
    mean_x, mean_y = sum(xs) / n, sum(ys) / n
    sxx = sum((x - mean_x) ** 2 for x in xs)
    syy = sum((y - mean_y) ** 2 for y in ys)
    if sxx <= 1e-15 or syy <= 1e-15:
        return None
    sxy = sum((x - mean_x) * (y - mean_y) for x, y in zip(xs, ys))
    return sxy / math.sqrt(sxx * syy)


def upper_lower_index(fractions: list[float], totals: list[float]) -> float | None:
    """Mean of ``fractions`` among the top 27 % by ``totals`` minus among the bottom 27 %
    (ties broken by position, so the result is reproducible)."""
    n = len(fractions)
    size = math.ceil(GROUP_FRACTION * n)
    if n < 2 or size < 1:
        return None
    order = sorted(range(n), key=lambda i: (totals[i], i))
    lower, upper = order[:size], order[-size:]
    return (sum(fractions[i] for i in upper) - sum(fractions[i] for i in lower)) / size


def part_statistics(exercise_parts: list[tuple[str, PartEntry]], graded: list[dict],
                    top: int = 5) -> list[PartStats]:
    """Statistics for each ``(exercise_id, part)``; ``graded`` holds per student
    ``{"total": float, "parts": {(exercise_id, part): {...}}}`` with each part's
    ``fraction``, ``answer``, ``status`` and ``misconception`` (students who did not
    submit an exercise have no entry for its parts)."""
    stats = []
    for exercise_id, part in exercise_parts:
        key = (exercise_id, part.name)
        entries = [(g["parts"][key], g["total"]) for g in graded if key in g["parts"]]
        item = PartStats(exercise_id, part.name, part.label, part.points,
                         answered=len(entries))
        if entries:
            fractions = [e["fraction"] for e, _ in entries]
            rest = [total - e["fraction"] * part.points for e, total in entries]
            totals = [total for _, total in entries]
            item.difficulty = sum(fractions) / len(fractions)
            item.point_biserial = correlation(fractions, rest)
            item.upper_lower = upper_lower_index(fractions, totals)
            wrong = Counter()
            matched: dict[str, Counter] = {}
            named = Counter()
            for entry, _ in entries:
                if entry["status"] in ("wrong", "partial") and entry["answer"]:
                    text = " ".join(entry["answer"].split())
                    wrong[text] += 1
                    matched.setdefault(text, Counter())[entry["misconception"] or ""] += 1
                    if entry["misconception"]:
                        named[entry["misconception"]] += 1
            item.wrong_answers = [(text, count, matched[text].most_common(1)[0][0])
                                  for text, count in sorted(wrong.items(),
                                                            key=lambda kv: (-kv[1], kv[0]))[:top]]
            item.misconceptions = sorted(named.items(), key=lambda kv: (-kv[1], kv[0]))
        stats.append(item)
    return stats
