"""Misconception discovery: mistakes nobody declared, found in a class's wrong answers.

Per numeric or vector part, the *unexplained* wrong answers (wrong or partly right,
readable, and named by no misconception or slip of the grader) are held against every
perturbation of the reference in the bounded space of :mod:`.perturbations`, each
evaluated at the student's own parameters. A perturbation *explains* an answer when the
answer lies within the part's tolerance of the perturbed value and the perturbed value
itself does not (in that variant the mistake would give the right answer).

Proposals are chosen greedily: the perturbation that explains the most answers is
proposed when it explains at least :data:`MIN_SUPPORT` students on at least
:data:`MIN_VARIANTS` different variants and more than :data:`CHANCE_FACTOR` times the
number it would explain by chance; its students are set aside and the search repeats.
*By chance* is measured on the class itself: each student's answer held against the
perturbed values of every *other* student's variant (the numbers a mistake unrelated to
the student's own would hit), averaged. Perturbations that explain exactly the same
students are listed beside the proposal as its alternatives: the answers cannot tell
them apart.

Each proposal carries a ready-to-paste ``Misconception(...)`` for the exercise file. The
search only proposes: it changes no grade, and nothing a student typed is ever run.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Iterable, Mapping

from ..i18n import N_, _
from ..exam.manifest import ExerciseEntry, Manifest, PartEntry
from ..exercise.model import Exercise
from ..exercise.params import ParamValues, to_si_values
from .answer_values import Value, answer_value, as_rows, close_to, compared, is_near, key_value
from .answered import Answered
from .perturbations import Perturbation, Rerun, solver_reruns, space

#: the fewest students a proposal must explain
MIN_SUPPORT = 3
#: the fewest different variants (parameter sets) among them
MIN_VARIANTS = 2
#: a proposal explains more than this many times what the same perturbation explains by chance
CHANCE_FACTOR = 3.0
#: the example students a proposal shows
EXAMPLES = 3
#: what the report and ``dynagrade discover`` say of the proposals
PROPOSALS_ONLY = N_("These are proposals: no grade changes until a misconception is declared "
                    "in the exercise file and the class is graded again.")


@dataclass(frozen=True)
class Example:
    """One student a proposal explains: their answer, what the mistake gives in their
    variant and their reference (part's unit)."""

    student_id: str
    answer: str
    predicted: Value
    key: Value


@dataclass(frozen=True)
class Proposal:
    """A mistake that explains a cluster of one part's unexplained wrong answers."""

    exercise_id: str
    part: str
    label: str
    unit: str | None
    name: str
    family: str
    students: tuple[str, ...]
    variants: int
    #: the part's unexplained wrong answers with a readable value
    unexplained: int
    #: the number this perturbation explains by chance (see the module's docstring)
    by_chance: float
    alternatives: tuple[str, ...]
    examples: tuple[Example, ...]
    snippet: str

    @property
    def support(self) -> int:
        return len(self.students)


@dataclass(frozen=True)
class _Wrong:
    student_id: str
    answer: str
    value: Value
    key: Value
    params: ParamValues
    variant: tuple


def discover(manifest: Manifest, exercises: Mapping[str, Exercise],
             records: Iterable[Answered]) -> list[Proposal]:
    """The proposals for every numeric and vector part of the exam, in exam order."""
    by_part: dict[tuple[str, str, str], Answered] = {
        (r.student_id, r.exercise_id, r.part): r for r in records}
    proposals = []
    for described in manifest.exercises:
        exercise = exercises.get(described.id)
        if exercise is None:
            continue
        # one ParamValues per student and one set of reruns for all the exercise's parts:
        # each perturbed solve then runs once per student, whichever part asks
        params: dict[str, ParamValues] = {}
        reruns = solver_reruns(exercise)
        for entry in described.parts:
            if compared(entry):
                wrong = _unexplained(manifest, described, entry, exercise, by_part, params)
                proposals += _propose(described, entry, exercise, wrong, reruns)
    return proposals


def explained_students(proposals: Iterable[Proposal]) -> set[tuple[str, str, str]]:
    """``(student_id, exercise_id, part)`` of every answer a proposal explains."""
    return {(s, p.exercise_id, p.part) for p in proposals for s in p.students}


def _unexplained(manifest: Manifest, described: ExerciseEntry, entry: PartEntry,
                 exercise: Exercise, by_part: Mapping[tuple[str, str, str], Answered],
                 params_of: dict[str, ParamValues]) -> list[_Wrong]:
    wrong = []
    for student in manifest.students:
        record = by_part.get((student.student_id, described.id, entry.name))
        variant = student.variant(described.id)
        if record is None or variant is None or not record.unexplained_wrong:
            continue
        value = answer_value(entry, record.answer)
        key = key_value(entry, variant.answers.get(entry.name))
        if value is None or key is None:
            continue
        params = {p.name: float(variant.params[p.name]) for p in exercise.params}
        si = params_of.setdefault(student.student_id, to_si_values(exercise.params, params))
        wrong.append(_Wrong(student.student_id, record.answer or "", value, key, si,
                            tuple(sorted(params.items()))))
    return wrong


def _predictions(perturbation: Perturbation, exercise: Exercise, entry: PartEntry,
                 wrong: list[_Wrong]) -> list[Value | None]:
    """The perturbed answer in each student's variant, in the part's unit."""
    part = exercise.part(entry.name)
    out: list[Value | None] = []
    for item in wrong:
        raw = perturbation.value(item.params)
        try:
            value = None if raw is None else part.in_part_unit(raw)
        except (TypeError, ValueError):
            value = None
        out.append(value if value is not None and _finite(value) else None)
    return out


def _finite(value: Any) -> bool:
    values = value if isinstance(value, tuple) else (value,)
    return all(isinstance(v, float) and math.isfinite(v) for v in values)


def _explains(entry: PartEntry, wrong: list[_Wrong], predicted: list[Value | None]
              ) -> frozenset[int]:
    return frozenset(i for i, (item, value) in enumerate(zip(wrong, predicted))
                     if value is not None and is_near(entry, item.value, value)
                     and not is_near(entry, value, item.key))


def _by_chance(entry: PartEntry, wrong: list[_Wrong], predicted: list[Value | None]) -> float:
    """How many answers the perturbation explains when each is held against the
    perturbed values of the other students' variants, averaged over those variants."""
    usable = [(i, v) for i, v in enumerate(predicted) if v is not None]
    if len(usable) < 2:
        return 0.0
    targets = as_rows([v for _, v in usable])
    hits = 0
    for position, (i, _value) in enumerate(usable):
        near = close_to(entry, wrong[i].value, targets)
        near[position] = False
        hits += int(near.sum())
    return hits / (len(usable) - 1)


def _propose(described: ExerciseEntry, entry: PartEntry, exercise: Exercise,
             wrong: list[_Wrong], reruns: list[Rerun]) -> list[Proposal]:
    if len(wrong) < MIN_SUPPORT:
        return []
    tried = []
    for perturbation in space(exercise, exercise.part(entry.name), reruns):
        predicted = _predictions(perturbation, exercise, entry, wrong)
        explained = _explains(entry, wrong, predicted)
        if len(explained) >= MIN_SUPPORT:
            tried.append((perturbation, predicted, explained,
                          _by_chance(entry, wrong, predicted)))
    proposals: list[Proposal] = []
    left = set(range(len(wrong)))
    while True:
        ranked = [(len(explained & left), -index, index) for index, (_p, _v, explained, _c)
                  in enumerate(tried)]
        if not ranked:
            break
        count, _, best = max(ranked)
        perturbation, predicted, explained, chance = tried[best]
        cluster = explained & left
        variants = {wrong[i].variant for i in cluster}
        if count < MIN_SUPPORT or len(variants) < MIN_VARIANTS or count <= CHANCE_FACTOR * chance:
            tried.pop(best)
            continue
        alternatives = tuple(p.name for i, (p, _v, e, _c) in enumerate(tried)
                             if i != best and e & left == cluster)
        chosen = sorted(cluster, key=lambda i: wrong[i].student_id)
        proposals.append(Proposal(
            described.id, entry.name, entry.label, entry.unit, perturbation.name,
            perturbation.family, tuple(wrong[i].student_id for i in chosen), len(variants),
            len(wrong), chance, alternatives,
            tuple(Example(wrong[i].student_id, wrong[i].answer, value, wrong[i].key)
                  for i in chosen[:EXAMPLES] if (value := predicted[i]) is not None),
            snippet(perturbation)))
        left -= cluster
        tried = [t for t in tried if t[0].name not in alternatives and t[0] is not perturbation]
    return proposals


def snippet(perturbation: Perturbation) -> str:
    """The ``Misconception(...)`` to paste into the part's ``misconceptions``, with the
    imports it needs as a comment."""
    feedback = f"Your answer is what you get with {perturbation.name}: check that step."
    lines = [f"Misconception({_quoted(perturbation.name)},",
             f"              lambda p: {perturbation.code},",
             f"              {_quoted(feedback)}),"]
    if perturbation.imports:
        lines.append("# needs: " + "; ".join(sorted(set(perturbation.imports))))
    return "\n".join(lines)


def _quoted(text: str) -> str:
    """``text`` as a double-quoted Python string."""
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def proposal_lines(proposals: Iterable[Proposal]) -> list[str]:
    """The proposals as ``dynagrade discover`` prints them: per proposal its part, its
    support, its examples and the ``Misconception(...)`` to paste."""
    from ..exercise.numbers import answer_text

    lines = []
    for p in proposals:
        lines.append(_("{exercise}, part {part}: {name} explains {count} of {unexplained} "
                       "unexplained wrong answers on {variants} variants ({chance} by chance)"
                       ).format(exercise=p.exercise_id, part=p.part, name=p.name,
                                count=p.support, unexplained=p.unexplained,
                                variants=p.variants, chance=f"{p.by_chance:.2g}"))
        if p.alternatives:
            lines.append("  " + _("the answers cannot tell it from: {names}").format(
                names="; ".join(p.alternatives)))
        for e in p.examples:
            lines.append("  " + _("{student}: answered {answer}, the mistake gives {predicted}, "
                                  "the key is {key}").format(
                student=e.student_id, answer=e.answer, predicted=answer_text(e.predicted, 6),
                key=answer_text(e.key, 6)))
        lines += ["  " + line for line in p.snippet.splitlines()]
        lines.append("")
    if not lines:
        lines.append(_("No mistake of the set explains a cluster of unexplained answers."))
    return lines + [_(PROPOSALS_ONLY)]
