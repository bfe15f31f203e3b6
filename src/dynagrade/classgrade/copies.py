"""Copied-answer detection: wrong answers that are right for someone else.

Every student has their own numbers, so a wrong answer equal, within the part's
tolerance, to a classmate's reference answer (or to the classmate's own wrong answer)
is a coincidence whose chance can be measured on the class. For every wrong numeric or
vector answer ``a`` of student *s* and every other student *t*:

- *s*'s answer **matches** *t* on the part when ``a`` lies within the part's tolerance
  of *t*'s key (or of *t*'s wrong answer);
- when *t*'s key lies within :data:`NEAR_KEYS` tolerances of *s*'s own, a small slip
  looks like a copy: the match counts only if ``a`` agrees with *t*'s number to every
  digit (below);
- an answer that a mistake on the student's *own* numbers explains (a misconception or
  slip the grader named, follow-through, or a proposal of :mod:`.discover`) is an honest
  mistake first and is no evidence.

**Chance of a match.** The probability that a random other student's key falls within
the tolerance window around ``a`` is estimated from the spread of the class's keys: with
``N`` the students on the roster with a variant of the exercise (those absent too: their
keys are drawn alike) and ``c`` the number of their keys, *s*'s and *t*'s left out,
within :data:`WIDE` times the tolerance of ``a``,

    p = (c + 1) / ((N - 1) · WIDE)

(the density of keys around ``a``, smoothed by one key). A match on another student's
answer takes the larger of that and the same estimate over the class's wrong answers.

**To every digit.** A copier hands in the digits they see. When ``a`` agrees with
*t*'s number to every digit it shows (``|a − x| ≤ h``, ``h`` half a unit of its last
digit, :mod:`.shown_digits`), the coincidence is narrower than the tolerance ``τ``:

    p_d = max(p · h / τ,  ι,  h / (NEAR_KEYS · τ) for near keys,  k / (N − 2) for a wrong
              answer that k ≥ COMMON others hand in too)

with ``ι`` the share of the class's pairs of different variants whose keys of the part
are the same number, smoothed by one pair (:mod:`.coinciding_keys`: the range of a
projectile is the same at α and 90° − α; with the smoothing one number alone never
makes a pair stand out). It does not apply when *t*'s numbers are *s*'s own with one
changed or two swapped (an honest student who misreads one number hands in that
variant's keys to every digit), nor, for *t*'s wrong answer that a mistake on *t*'s own
numbers explains, when two changes lead from one to the other.

**Pair score.** The parts of one pair (both directions; per part the smallest chance)
combine into one chance ``P``. Different exercises are drawn independently, so their
chances multiply. The parts of one exercise come from the same parameters, so a match
on one makes a match on another more likely (:mod:`.part_dependence`): they are chained,
each part's factor the larger of its own chance and ``q(part | a part taken before)``
measured on the class's keys,

    P = Π over exercises of  p_1 · max(p_2, q(2 | 1)) · max(p_3, q(3 | 1), q(3 | 2)) ···

the parts that agree to every digit first, the smallest factor first (the most specific
evidence), then the others, the largest factor first (a part that follows from another,
like a flight time from a peak height, adds nearly nothing; parts whose keys agree no
more often together than apart multiply), and

    E = n (n - 1) / 2 · P

is the number of pairs a class of ``n`` students who handed something in would show with
coincidences this unlikely (a Bonferroni bound over the class's pairs). With fewer than
:data:`~.stats.MIN_STUDENTS` keys the spread rests on few numbers, and the report says
so: the list is then a hint. A pair is listed when ``E ≤`` :data:`THRESHOLD`
(one class in twenty would show one such pair by chance); the report shows ``−log10 E``
as its score (1.3 at the threshold, 3 for one class in a thousand). Listed pairs that
share a student form clusters (a source and several copiers). A classmate who holds the
source's very variant is matched as strongly as the source: each match names them, and
a conversation tells them apart. The list is evidence for a conversation: it **never
changes a grade**.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import AbstractSet, Any, Iterable, Mapping

import numpy as np

from ..exam.csvcells import csv_text
from ..i18n import N_
from ..exam.manifest import Manifest, PartEntry
from ..exercise.numbers import answer_text
from .answer_values import Value, answer_value, as_rows, close_to, compared, key_value
from .answered import Answered
from .coinciding_keys import changes, identical_key_share
from .part_dependence import PartDependence, part_dependence
from .shown_digits import DigitAgreement
from .stats import MIN_STUDENTS

#: keys closer than this many tolerances make a part evidence only to every digit
NEAR_KEYS = 3.0
#: the window, in tolerances, in which the density of keys is counted
WIDE = 10.0
#: a pair is listed when a class of its size would show at most this many such pairs by chance
THRESHOLD = 0.05
KEY, ANSWER = "key", "answer"
#: what the report and ``dynagrade discover`` say of the list
NEVER_A_GRADE = N_("This list never changes a grade: each pair is evidence to look at, and "
                   "a conversation with the students decides.")


@dataclass(frozen=True)
class Match:
    """One part on which ``student``'s wrong answer matches ``other``'s key or answer."""

    exercise_id: str
    part: str
    unit: str | None
    student: str
    other: str
    #: :data:`KEY` or :data:`ANSWER`: what of ``other``'s it matches
    against: str
    answer: str
    student_key: Value
    other_key: Value
    other_answer: str
    #: the chance estimate ``p`` of the module's docstring
    chance: float
    student_time: str = ""
    other_time: str = ""
    #: whether the answer agrees with what it matches to every digit it shows
    #: (:mod:`.shown_digits`), which narrows the chance
    every_digit: bool = False
    #: the other students who hold ``other``'s very variant: the answer matches their
    #: keys too, and cannot tell which of them it came from
    same_variant: tuple[str, ...] = ()


@dataclass(frozen=True)
class CopiedPair:
    """Two students whose answers match beyond chance, with the evidence."""

    students: tuple[str, ...]
    matches: tuple[Match, ...]
    #: pairs a class of this size would show by chance (``E``)
    expected: float

    @property
    def score(self) -> float:
        """``−log10 E``: 2 means one class in a hundred would show such a pair by chance."""
        return -math.log10(max(self.expected, 1e-300))


@dataclass(frozen=True)
class Copies:
    """The pairs and clusters found, and the number of students compared."""

    pairs: tuple[CopiedPair, ...] = ()
    clusters: tuple[tuple[str, ...], ...] = ()
    #: the students who handed something in
    students: int = 0
    threshold: float = THRESHOLD
    #: the numeric and vector parts compared
    parts: int = 0
    #: the students on the roster, whose keys give the spread
    roster: int = 0

    @property
    def few_keys(self) -> bool:
        """Whether the spread of keys rests on fewer than :data:`~.stats.MIN_STUDENTS`."""
        return self.roster < MIN_STUDENTS


def detect(manifest: Manifest, records: Iterable[Answered],
           explained: AbstractSet[tuple[str, str, str]] = frozenset(),
           threshold: float = THRESHOLD) -> Copies:
    """The pairs of students whose wrong answers match each other's keys or answers
    beyond chance; ``explained`` holds ``(student_id, exercise_id, part)`` of answers a
    mistake on the student's own numbers explains (no evidence)."""
    by_part = {(r.student_id, r.exercise_id, r.part): r for r in records}
    present = sorted({r.student_id for r in by_part.values()})
    n = len(present)
    best: dict[tuple[str, ...], dict[tuple[str, str], Match]] = {}
    parts = 0
    for described in manifest.exercises:
        identical = identical_key_share(manifest, described)
        for entry in described.parts:
            if not compared(entry):
                continue
            parts += 1
            for match in _part_matches(manifest, described.id, entry, by_part, explained,
                                       identical.get(entry.name, 0.0)):
                pair = tuple(sorted((match.student, match.other)))
                kept = best.setdefault(pair, {})
                where = (match.exercise_id, match.part)
                if where not in kept or match.chance < kept[where].chance:
                    kept[where] = match
    pairs = []
    chained = {e for kept in best.values() if len(kept) > 1 for e, _ in kept}
    dependence = {d.id: part_dependence(manifest, d) for d in manifest.exercises
                  if d.id in chained}
    for pair, matches in best.items():
        expected = n * (n - 1) / 2 * joint_chance(matches.values(), dependence)
        if expected <= threshold:
            pairs.append(CopiedPair(pair, tuple(matches.values()), expected))
    pairs.sort(key=lambda p: (p.expected, p.students))
    return Copies(tuple(pairs), clusters(pairs), n, threshold, parts, len(manifest.students))


def _part_matches(manifest: Manifest, exercise_id: str, entry: PartEntry,
                  by_part: Mapping[tuple[str, str, str], Answered],
                  explained: AbstractSet[tuple[str, str, str]],
                  identical: float) -> list[Match]:
    """Every match of one part, with its chance (``identical``: ``ι`` of the module's
    docstring, :func:`.coinciding_keys.identical_key_share`)."""
    ids, keys, records, params = [], [], [], []
    for student in manifest.students:
        variant = student.variant(exercise_id)
        key = key_value(entry, variant.answers.get(entry.name)) if variant else None
        if variant is not None and key is not None:
            ids.append(student.student_id)
            keys.append(key)
            records.append(by_part.get((student.student_id, exercise_id, entry.name)))
            params.append(variant.params)
    if len(ids) < 2:
        return []
    holders: dict[str, list[str]] = {}
    for student_id, numbers in zip(ids, params):
        holders.setdefault(_signature(numbers), []).append(student_id)
    key_rows = as_rows(keys)
    values: list[Value | None] = [answer_value(entry, r.answer) if r and r.wrong else None
                                  for r in records]
    wrong = [i for i, v in enumerate(values) if v is not None]
    answer_rows = as_rows([v for v in values if v is not None]) if wrong else np.zeros((0, 1))
    found = []
    for i in wrong:
        record, value = records[i], values[i]
        assert record is not None and value is not None  # a wrong answer has both
        if (ids[i], exercise_id, entry.name) in explained or record.misconception:
            continue
        on_key = close_to(entry, value, key_rows)
        on_answer = np.zeros(len(ids), dtype=bool)
        wide_answers = np.zeros(len(ids), dtype=bool)
        if len(wrong) > 1:
            on_answer[wrong] = close_to(entry, value, answer_rows)
            wide_answers[wrong] = close_to(entry, value, answer_rows, WIDE)
        on_answer &= ~on_key
        on_key[i] = on_answer[i] = False
        near_keys = close_to(entry, keys[i], key_rows, NEAR_KEYS)
        wide_keys = close_to(entry, value, key_rows, WIDE)
        digits = DigitAgreement.of(entry, record.answer, value, key_rows, answer_rows, wrong)
        for j in np.flatnonzero(on_key | on_answer):
            other = records[j]
            with_key = bool(on_key[j])
            # a wrong answer that a mistake on the other's own numbers explains is worked
            # out from numbers one change from theirs
            worked_out = not with_key and other is not None and (
                bool(other.misconception) or (ids[j], exercise_id, entry.name) in explained)
            every_digit = digits is not None and digits.agrees(int(j), with_key) and \
                changes(params[i], params[j]) > (2 if worked_out else 1)
            if near_keys[j] and not every_digit:
                continue
            others = np.ones(len(ids), dtype=bool)
            others[i] = others[j] = False
            chance = (int((wide_keys & others).sum()) + 1) / ((len(ids) - 1) * WIDE)
            if not with_key:
                spread = (int((wide_answers & others).sum()) + 1) / (max(len(wrong) - 1, 1) * WIDE)
                chance = max(chance, spread)
            if every_digit:
                assert digits is not None
                chance = digits.narrowed(chance, others, with_key, identical,
                                         NEAR_KEYS if near_keys[j] else None)
            found.append(Match(exercise_id, entry.name, entry.unit, ids[i], ids[j],
                               KEY if with_key else ANSWER, record.answer or "",
                               keys[i], keys[j], (other.answer or "") if other else "",
                               min(chance, 1.0), record.time, other.time if other else "",
                               every_digit,
                               tuple(h for h in holders[_signature(params[j])]
                                     if h not in (ids[i], ids[j]))))
    return found


def _signature(params: Mapping[str, Any]) -> str:
    """The same text for two variants with the same parameters."""
    return repr(sorted(params.items()))


def joint_chance(matches: Iterable[Match], dependence: Mapping[str, PartDependence]) -> float:
    """``P`` of the module's docstring: the chained chance of each exercise's matching
    parts (:func:`chained_chance`), the exercises multiplied."""
    by_exercise: dict[str, list[Match]] = {}
    for match in matches:
        by_exercise.setdefault(match.exercise_id, []).append(match)
    return math.prod(chained_chance(found, dependence.get(exercise_id, PartDependence()))
                     for exercise_id, found in by_exercise.items())


def chained_chance(matches: Iterable[Match], counts: PartDependence) -> float:
    """The chance of one exercise's matching parts together: chained, each part's factor
    the larger of its own chance and ``q`` given a part taken before. The parts that
    agree to every digit are taken first, the smallest factor first: each is the most
    specific evidence; then the others, the largest factor first (which keeps the
    estimate on the side of chance)."""
    left, taken = list(matches), list[Match]()
    while left:
        digits = [m for m in left if m.every_digit]
        if digits:
            match = min(digits, key=lambda m: _factor(m, taken, counts))
        else:
            match = max(left, key=lambda m: _factor(m, taken, counts))
        left.remove(match)
        taken.append(match)
    return _chain(taken, counts)


def _chain(order: Iterable[Match], counts: PartDependence) -> float:
    """The product of the factors of ``order``, each given the parts before it."""
    total, taken = 1.0, list[Match]()
    for match in order:
        total *= _factor(match, taken, counts)
        taken.append(match)
    return total


def _factor(match: Match, taken: list[Match], counts: PartDependence) -> float:
    """A part's factor: the larger of its own chance and ``q`` given a part taken before."""
    return min(max([match.chance, *(counts.conditional(match.part, t.part) for t in taken)]),
               1.0)


def clusters(pairs: Iterable[CopiedPair]) -> tuple[tuple[str, ...], ...]:
    """The groups of students that listed pairs connect, largest first."""
    parent: dict[str, str] = {}

    def root(x: str) -> str:
        while parent.setdefault(x, x) != x:
            x = parent[x]
        return x

    for pair in pairs:
        a, b = (root(s) for s in pair.students)
        if a != b:
            parent[max(a, b)] = min(a, b)
    groups: dict[str, list[str]] = {}
    for student in parent:
        groups.setdefault(root(student), []).append(student)
    return tuple(sorted((tuple(sorted(g)) for g in groups.values()),
                        key=lambda g: (-len(g), g)))


COPIES_HEADER = ("cluster", "student_a", "student_b", "pairs_expected_by_chance", "score",
                 "exercise_id", "part", "answer_of", "matches", "answer", "own_key",
                 "other_key", "other_answer", "chance", "time_answer", "time_other",
                 "every_digit", "same_variant_as_other")


def copies_csv(found: Copies) -> str:
    """``copies.csv``: one row per matching part of every listed pair, with the evidence
    (both keys, both answers, the chance and the times when known)."""
    cluster_of = {s: k for k, group in enumerate(found.clusters, 1) for s in group}
    rows: list[tuple] = [COPIES_HEADER]
    for pair in found.pairs:
        for m in pair.matches:
            rows.append((cluster_of.get(pair.students[0], ""), *pair.students,
                         f"{pair.expected:.3g}", f"{pair.score:.1f}", m.exercise_id, m.part,
                         m.student, f"{m.against} of {m.other}", m.answer,
                         answer_text(m.student_key), answer_text(m.other_key), m.other_answer,
                         f"{m.chance:.3g}", m.student_time, m.other_time,
                         "yes" if m.every_digit else "no", " ".join(m.same_variant)))
    return csv_text(rows)
