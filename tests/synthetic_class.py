"""A synthetic class with a known truth, for measuring copy detection and misconception
discovery (tests/test_exam_findings.py, bench/detect.py).

Two exercises of the bank (projectile-range: three numbers; two-cart-collision: three
numbers, whose energy part has a reference formula) are drawn for every student, as an
exam would. Every student then answers, and the real grader grades the answers:

- **honest** students answer right, except that each number is, with probability
  ``noise``, a wrong value of their own (their key times a random factor between 0.3 and
  3, or a digit slip) or left empty;
- **planted** students are honest students who, on one part, make one mistake of the
  discovery space (:data:`PLANTED`) at their own parameters; it is declared nowhere;
- **copiers** hand in a classmate's answers (the classmate is the *source*): every number
  of the exam, or of one exercise; a group has one source and one or two copiers;
- **misreaders** are honest students who misread one parameter of one exercise (one or
  two steps of its grid off) and work every number of it out right from the misread
  value: their wrong answers are the keys of a neighbouring variant, which a classmate
  may hold. Mistakes that carry through every part are common; without them the class
  would only have honest mistakes that are independent from part to part, and could not
  show a chance model that counts parts worked out from the same numbers as independent
  coincidences (:mod:`dynagrade.classgrade.part_dependence`). They are drawn with their
  own random numbers, so the rest of the class is the same with or without them.

The truth comes along: the groups of copiers with their source, and per planted cluster
its part, its mistake's name (as :mod:`dynagrade.classgrade.perturbations` names it) and
its students.
"""

from __future__ import annotations

import random
from dataclasses import dataclass, field
from pathlib import Path

from dynagrade.classgrade.answered import Answered, from_results
from dynagrade.classgrade.perturbations import space
from dynagrade.exam.manifest import (ExamEntry, ExerciseEntry, Generator, Manifest,
                                     StudentEntry, VariantEntry)
from dynagrade.exercise.loader import load_file
from dynagrade.exercise.model import Exercise
from dynagrade.exercise.numbers import answer_text
from dynagrade.exercise.params import Uniform
from dynagrade.exercise.scoring import grade_variant
from dynagrade.generation.generate import exercise_parts

BANK = Path(__file__).resolve().parents[1] / "exercises"
FILES = ("ch1_particles/projectile.py", "ch2_systems/two_cart_collision.py")
#: the undeclared mistakes planted: (exercise, part, the perturbation's name)
PLANTED = (
    ("projectile-range", "x_max", "g = 10"),
    ("projectile-range", "h_max", "sin and cos of alpha swapped"),
    ("projectile-range", "t_flight", "alpha in degrees taken as radians"),
    ("two-cart-collision", "v1_after", "m1 and m2 swapped"),
    ("two-cart-collision", "v2_after", "sign of v2 flipped"),
    ("two-cart-collision", "dT", "square of v1 - v2 missing"),
)


@dataclass
class Cluster:
    """A planted mistake: where, which, and who made it."""

    exercise_id: str
    part: str
    name: str
    students: list[str] = field(default_factory=list)


@dataclass
class SyntheticClass:
    manifest: Manifest
    exercises: dict[str, Exercise]
    records: list[Answered]
    #: each group of copiers with their source (source first)
    groups: list[tuple[str, ...]]
    #: per group, whether its copiers copied the whole exam (else one exercise)
    whole: list[bool]
    clusters: list[Cluster]
    #: each student's graded results by exercise, in roster order
    results: list[dict]
    #: the honest students who misread a parameter of one exercise
    misreaders: list[str] = field(default_factory=list)

    @property
    def copying(self) -> set[str]:
        return {s for group in self.groups for s in group}


def exercises() -> dict[str, Exercise]:
    loaded = [load_file(BANK / name, templates=False) for name in FILES]
    return {e.id: e for e in loaded}


def synthetic_class(students: int = 200, seed: int = 1, groups: int = 10,
                    cluster_size: tuple[int, int] = (5, 9), noise: float = 0.15,
                    misreads: int = 10, digits: int = 6) -> SyntheticClass:
    """A class of ``students`` with ``groups`` copying groups, one planted cluster of
    ``cluster_size`` students per entry of :data:`PLANTED` and ``misreads`` misreaders;
    the numbers students work out are typed to ``digits`` significant digits (their own
    wrong values to four)."""
    rng = random.Random(seed)
    bank = exercises()
    ids = [f"s{k:03d}" for k in range(students)]
    variants = {sid: {e.id: e.variant(seed * 100_000 + k * 10 + i, with_statement=False)
                      for i, e in enumerate(bank.values())} for k, sid in enumerate(ids)}
    answers = {sid: {e: _honest(rng, bank[e], variants[sid][e], noise, digits) for e in bank}
               for sid in ids}
    free = ids[:]
    rng.shuffle(free)
    clusters = []
    for exercise_id, part, name in PLANTED:
        cluster = Cluster(exercise_id, part, name)
        perturbation = next(p for p in space(bank[exercise_id], bank[exercise_id].part(part))
                            if p.name == name)
        for sid in [free.pop() for _ in range(rng.randint(*cluster_size))]:
            variant = variants[sid][exercise_id]
            wrong = perturbation.value(bank[exercise_id].si(variant.params))
            if wrong is None:
                continue
            shown = bank[exercise_id].part(part).in_part_unit(wrong)
            answers[sid][exercise_id][part] = answer_text(shown, digits)
            cluster.students.append(sid)
        clusters.append(cluster)
    copying, whole_exam = [], []
    for g in range(groups):
        source, *copiers = [free.pop() for _ in range(2 if g % 3 else 3)]
        whole = g % 2 == 0
        copied = list(bank) if whole else [rng.choice(list(bank))]
        for copier in copiers:
            for exercise_id in copied:
                answers[copier][exercise_id] = dict(answers[source][exercise_id])
        copying.append((source, *copiers))
        whole_exam.append(whole)
    misreaders = _misread(random.Random(f"misread {seed}"), bank, variants, answers, free,
                          misreads, digits)
    manifest = _manifest(bank, ids, variants)
    results = {sid: {e: grade_variant(bank[e], variants[sid][e], answers[sid][e])
                     for e in bank} for sid in ids}
    return SyntheticClass(manifest, bank, from_results(results), copying, whole_exam,
                          clusters, [results[sid] for sid in ids], misreaders)


def _honest(rng: random.Random, exercise: Exercise, variant, noise: float,
            digits: int) -> dict:
    """An honest student's answers: right, with an own mistake now and then."""
    out: dict[str, str | None] = {}
    for part in exercise.parts:
        if part.kind != "numeric":
            out[part.name] = None
            continue
        key = variant.answers[part.name]
        draw = rng.random()
        if draw < noise / 3:
            out[part.name] = None
        elif draw < noise:
            out[part.name] = answer_text(key * rng.uniform(0.3, 3.0), 4)
        else:
            out[part.name] = answer_text(key, digits)
    return out


def _misread(rng: random.Random, bank: dict[str, Exercise], variants, answers, free: list[str],
             count: int, digits: int) -> list[str]:
    """``count`` of the ``free`` students misread one drawn parameter of one exercise by
    one or two steps of its grid and answer every number of it from the misread value."""
    chosen = rng.sample(free, min(count, len(free)))
    for sid in chosen:
        exercise = bank[rng.choice(sorted(bank))]
        drawn = [p for p in exercise.params if isinstance(p, Uniform) and p.step]
        param = rng.choice(drawn)
        values = dict(variants[sid][exercise.id].params)
        shifted = values[param.name] + rng.choice((-2, -1, 1, 2)) * (param.step or 0.0)
        values[param.name] = min(max(shifted, param.low), param.high)
        misread = exercise.solve_in_part_units(values)
        answers[sid][exercise.id] = {
            part.name: answer_text(misread[part.name], digits) if part.kind == "numeric" else None
            for part in exercise.parts}
    return chosen


def _manifest(bank: dict[str, Exercise], ids: list[str], variants) -> Manifest:
    described = tuple(ExerciseEntry(e.id, e.title, e.source, 4.0, {}, e.file, "",
                                    exercise_parts(e, 4.0)) for e in bank.values())
    students = tuple(StudentEntry(sid, sid, "", tuple(
        VariantEntry(e, v.seed, dict(v.params), dict(v.answers))
        for e, v in variants[sid].items())) for sid in ids)
    return Manifest(Generator("synthetic", ""),
                    ExamEntry("synthetic", "Synthetic class", "2026-01-01", "", 8.0),
                    described, students)


@dataclass(frozen=True)
class Measured:
    """Precision and recall of both features on one synthetic class."""

    copy_pairs: int
    copy_pairs_found: int
    #: listed pairs of two honest students (no copying group holds either)
    false_pairs: int
    #: listed pairs of a copier and a student whose variant is a near twin of the source's
    twin_pairs: int
    #: copied wrong answers, and those found, of copiers of the whole exam / of one exercise
    copied_answers: tuple[int, int]
    copied_answers_found: tuple[int, int]
    clusters: int
    clusters_recovered: int

    @property
    def pair_recall(self) -> float:
        return self.copy_pairs_found / self.copy_pairs if self.copy_pairs else 1.0

    def answer_recall(self, whole: bool = True) -> float:
        """The share of copied answers found (of copiers of the whole exam, or of one
        exercise)."""
        k = 0 if whole else 1
        total = self.copied_answers[k]
        return self.copied_answers_found[k] / total if total else 1.0

    @property
    def recovery(self) -> float:
        return self.clusters_recovered / self.clusters if self.clusters else 1.0


def measure(synthetic: SyntheticClass, findings, min_cluster: int = 5) -> Measured:
    """Compare ``findings`` (:class:`dynagrade.classgrade.findings.Findings`) with the
    truth: a listed pair is right when both students are of one copying group; a copied
    answer (a copier's wrong answer that equals the source's) is found when a listed pair
    of its group holds its part; a planted cluster (``min_cluster`` or more students whose
    answer the grader left unexplained) is recovered when a proposal for its part names
    its mistake (or lists it among the alternatives the answers cannot tell apart) and
    explains most of its students."""
    group_of = {s: k for k, group in enumerate(synthetic.groups) for s in group}
    truth = {tuple(sorted((g[0], c))) for g in synthetic.groups for c in g[1:]}
    listed = {p.students: p for p in findings.copies.pairs}
    false = sum(1 for a, b in listed if a not in group_of and b not in group_of)
    twins = sum(1 for a, b in listed if group_of.get(a, -1) != group_of.get(b, -2)) - false
    by_key = {(r.student_id, r.exercise_id, r.part): r for r in synthetic.records}
    copied, found = [0, 0], [0, 0]
    for group, whole in zip(synthetic.groups, synthetic.whole):
        source, k = group[0], 0 if whole else 1
        for copier in group[1:]:
            pair = listed.get(tuple(sorted((source, copier))))  # type: ignore[arg-type]
            parts = {(m.exercise_id, m.part) for m in pair.matches} if pair else set()
            for (sid, e, part), record in by_key.items():
                if sid == copier and record.wrong and not record.misconception and \
                        record.answer == by_key[(source, e, part)].answer:
                    copied[k] += 1
                    found[k] += (e, part) in parts
    recovered = counted = 0
    for cluster in synthetic.clusters:
        unexplained = [s for s in cluster.students
                       if by_key[(s, cluster.exercise_id, cluster.part)].unexplained_wrong]
        if len(unexplained) < min_cluster:
            continue
        counted += 1
        recovered += any(
            p.exercise_id == cluster.exercise_id and p.part == cluster.part
            and (p.name == cluster.name or cluster.name in p.alternatives)
            and 2 * len(set(p.students) & set(unexplained)) > len(unexplained)
            for p in findings.proposals)
    return Measured(len(truth), sum(1 for p in truth if p in listed), false, twins,
                    (copied[0], copied[1]), (found[0], found[1]),
                    counted, recovered)
