"""What an exam's variants say about its exercises: warnings for the instructor.

Two things are worth a look before the exam is handed out, one line per exercise or part:

- an exercise whose variants were **redrawn** more than
  :data:`~dynagrade.exercise.redraws.REDRAW_WARNING` of the time: the class's parameters
  are skewed into the region where nothing coincides with the key (usually a declared
  misconception that equals the key in part of the parameter space; limit it with
  ``applies=``);
- a part whose reference answer (a number, a vector or a choice) is **the same for the
  whole class**: one student's answer is everybody's. Formula parts are left out (their
  reference is one formula by design), and so are classes of fewer than
  :data:`MIN_CLASS` students, where a shared choice is likely by chance.

The warnings are read from the manifest alone, so they can be recomputed from any exam's
``manifest.json``.
"""

from __future__ import annotations

from collections import Counter

from ..exercise.parts import PART_KINDS
from ..exercise.redraws import REDRAW_WARNING, percent
from ..exam.manifest import Manifest

#: the smallest class for which "the same answer for everyone" is worth a warning
MIN_CLASS = 5


def skew_warnings(manifest: Manifest) -> list[str]:
    """The warnings of the module docstring, in exam order."""
    warnings = []
    for exercise in manifest.exercises:
        variants = [v for s in manifest.students for v in s.variants
                    if v.exercise == exercise.id]
        warnings += _redraw_warning(exercise.id, variants)
        if len(variants) < MIN_CLASS:
            continue
        for part in exercise.parts:
            if not PART_KINDS[part.kind].answer_varies:
                continue
            answers = {_comparable(v.answers.get(part.name)) for v in variants}
            if len(answers) == 1:
                warnings.append(
                    f"{exercise.id}, part {part.name}: every one of the {len(variants)} "
                    f"students has the same answer ({_shown(variants[0].answers.get(part.name))})"
                    "; one student's answer is everybody's")
    return warnings


def _redraw_warning(exercise_id: str, variants) -> list[str]:
    redraws = [r for v in variants for r in v.redraws]
    drawn = len(variants) + len(redraws)
    if not drawn or len(redraws) / drawn <= REDRAW_WARNING:
        return []
    reasons = Counter(problem for r in redraws for problem in set(r.problems))
    reason, _ = reasons.most_common(1)[0]
    return [f"{exercise_id}: {len(redraws)} of {drawn} draws ({percent(len(redraws) / drawn)}) "
            f"were redrawn because they could not discriminate, most often: {reason}; the "
            f"class's parameters are skewed (limit a misconception to its regime with "
            f"applies=, docs/authoring.md)"]


def _comparable(answer):
    """An answer as a set member: vectors and several options as tuples, numbers to 12
    significant digits (so that rounding noise does not make equal answers differ)."""
    if isinstance(answer, (list, tuple)):
        return tuple(_comparable(a) for a in answer)
    return float(f"{answer:.12g}") if isinstance(answer, float) else answer


def _shown(answer) -> str:
    if isinstance(answer, (list, tuple)):
        return ", ".join(map(str, answer))
    return f"{answer:g}" if isinstance(answer, float) else str(answer)
