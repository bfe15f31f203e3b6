"""Item analysis of a graded class: how hard each part was and how well it separated
strong from weak students, and which wrong answers were common.

- difficulty: the mean score fraction of a part (1 = everyone right);
- point-biserial discrimination: the correlation between a part's score fraction and the
  student's total without that part (the corrected item-total correlation; ``None`` when
  either does not vary);
- upper-lower index: mean fraction in the best 27 % of students (by total) minus the mean
  in the weakest 27 %.

Each of these rests on the students who answered the part; with fewer than
:data:`MIN_STUDENTS` a single student moves it a lot, and the report says so.

Wrong answers are grouped by what explains them, as the grader's verdict named it (a
slip the grader tries on every part: sign, factor 2, power of ten, unit, degrees for
radians ...; or one of the exercise's declared misconceptions; or follow-through from an
earlier wrong answer), never by raw value: two students' variants have different numbers,
so equal numbers do not mean equal mistakes. What no explanation covers is counted as the
part's *unexplained* wrong answers.
"""

from __future__ import annotations

import math
from collections import Counter
from dataclasses import dataclass, field
from typing import Mapping

from ..exam.manifest import PartEntry
from ..exercise.results import GradedPart, Status

GROUP_FRACTION = 0.27
#: below this many students a statistic is a hint, not a measurement (a common rule of
#: thumb for item analysis; one student more or less can change it by a tenth or more)
MIN_STUDENTS = 30
FOLLOW_THROUGH = "follow-through from an earlier wrong answer"
#: kinds of explanation, as the report names them
DECLARED, SLIP, FOLLOWED = "the exercise's misconception", "slip", "follow-through"


@dataclass(frozen=True)
class Explanation:
    """Wrong answers to one part that one mistake explains: its name as the grader gave
    it, its kind (:data:`DECLARED`, :data:`SLIP` or :data:`FOLLOWED`) and how many."""

    name: str
    kind: str
    students: int


@dataclass(frozen=True)
class StudentParts:
    """One student's graded parts by ``(exercise_id, part)`` (only the exercises they
    handed in) and their total."""

    total: float
    parts: Mapping[tuple[str, str], GradedPart]


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
    wrong: int = 0
    explained: list[Explanation] = field(default_factory=list)
    unexplained: int = 0

    @property
    def few_students(self) -> bool:
        """Whether the statistics rest on fewer than :data:`MIN_STUDENTS` students."""
        return self.answered < MIN_STUDENTS

    @property
    def unexplained_share(self) -> float | None:
        """The share of the part's wrong answers that nothing explains (None: none wrong)."""
        return self.unexplained / self.wrong if self.wrong else None


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


def part_statistics(exercise_parts: list[tuple[str, PartEntry]], graded: list[StudentParts],
                    top: int = 5,
                    declared: dict[tuple[str, str], set[str]] | None = None) -> list[PartStats]:
    """Statistics for each ``(exercise_id, part)`` over the students in ``graded`` who
    handed its exercise in. ``declared`` names each part's declared misconceptions, to
    tell them from the grader's generic slips."""
    declared = declared or {}
    stats = []
    for exercise_id, part in exercise_parts:
        key = (exercise_id, part.name)
        entries = [(g.parts[key], g.total) for g in graded if key in g.parts]
        item = PartStats(exercise_id, part.name, part.label, part.points,
                         answered=len(entries))
        if entries:
            fractions = [e.fraction for e, _ in entries]
            rest = [total - e.fraction * part.points for e, total in entries]
            totals = [total for _, total in entries]
            item.difficulty = sum(fractions) / len(fractions)
            item.point_biserial = correlation(fractions, rest)
            item.upper_lower = upper_lower_index(fractions, totals)
            wrong: Counter[str] = Counter()
            matched: dict[str, Counter[str]] = {}
            named: Counter[str] = Counter()
            for entry, _ in entries:
                if entry.status in (Status.WRONG, Status.PARTIAL) and entry.answer:
                    text = " ".join(entry.answer.split())
                    wrong[text] += 1
                    matched.setdefault(text, Counter())[entry.misconception or ""] += 1
                    if entry.misconception:
                        named[entry.misconception] += 1
            item.wrong_answers = [(text, count, matched[text].most_common(1)[0][0])
                                  for text, count in sorted(wrong.items(),
                                                            key=lambda kv: (-kv[1], kv[0]))[:top]]
            item.misconceptions = sorted(named.items(), key=lambda kv: (-kv[1], kv[0]))
            _explain(item, [entry for entry, _ in entries], declared.get(key, set()))
        stats.append(item)
    return stats


def _explain(item: PartStats, entries: list[GradedPart], declared: set[str]) -> None:
    """Group the part's wrong answers by the mistake the grader named for each."""
    groups: Counter = Counter()
    for entry in entries:
        if not entry.status.answered_wrong or not (entry.answer or "").strip():
            continue
        item.wrong += 1
        if entry.status is Status.FOLLOW_THROUGH:
            groups[(FOLLOW_THROUGH, FOLLOWED)] += 1
        elif entry.misconception:
            name = entry.misconception
            groups[(name, DECLARED if name in declared else SLIP)] += 1
        else:
            item.unexplained += 1
    item.explained = [Explanation(name, kind, count) for (name, kind), count
                      in sorted(groups.items(), key=lambda kv: (-kv[1], kv[0]))]


def declared_names(exercises) -> dict[tuple[str, str], set[str]]:
    """Per ``(exercise_id, part)`` the names of the misconceptions its exercise declares
    (``exercises`` maps ids to :class:`~dynagrade.exercise.model.Exercise`)."""
    return {(exercise_id, part.name): {m.name for m in part.misconceptions}
            for exercise_id, exercise in exercises.items() for part in exercise.parts}
