"""Variety: no answer that the whole class shares, no two answers that can be swapped.

A randomized exercise is worth its randomness only when the numbers it asks for differ
between students and between its own parts. ``dynagrade verify`` applies two rules, on the
reference answers it has already computed (nothing is solved again):

- **one answer for (almost) everybody** (:func:`one_answer_problems`): over the variants
  verify draws, a part fails when one answer scores in more than :data:`ONE_ANSWER_SHARE`
  of them — a choice whose right option is (almost) always the same, a number or vector
  that stays within its own tolerance of one value. The grader's own tolerance decides
  what "one value" is (:meth:`Part.one_answer <dynagrade.exercise.parts.Part.one_answer>`),
  so a key that varies by less than 1 % counts as constant. The rule is judged over
  :data:`MIN_VARIANTS` variants or more (fewer say too little about a share); formula
  parts are left out (their answer is one formula by design), and so is a part that
  declares ``constant_answer="why"``: the reason the answer is the physics being taught.
- **two answers that coincide** (:func:`coincidences`): in one variant, the number one
  numeric part asks for, typed into another numeric part, scores there, so a student who
  swapped the two formulas would score both and the variant cannot discriminate. It is a
  problem of the variant (:func:`dynagrade.exercise.verify.variant_problems`), which an
  exam redraws and ``verify`` reports with the seed. Two parts of one dimension (both pure
  numbers included) are compared in SI, within the tolerance of the part the number is
  typed into (a speed in m/s and one in km/h; two moments of inertia). Two parts of
  different dimensions are compared as the bare numbers a student types, each in its
  part's unit, and only where they agree to :data:`SAME_NUMBER_RTOL` (where the part
  reads bare numbers at all): 0.254842 m of a stopping distance against 0.254842 s of a
  stopping time, where the parameters make the ratio of the two formulas exactly 1
  (v₀ = 2 m/s in d = v₀ t/2). Unrelated quantities of different dimensions agree within
  1 % by chance in a few of 200 variants (a force in kN and a height in km); that says
  nothing about a swap a student would make, so the rule leaves it alone.
"""

from __future__ import annotations

from typing import Any, Mapping, Sequence

from .model import Exercise
from .redraws import percent

#: one answer scoring in more than this share of the variants is the class's answer
ONE_ANSWER_SHARE = 0.9
#: the fewest variants over which :func:`one_answer_problems` judges a share
MIN_VARIANTS = 50
#: how closely two numbers of different dimensions must agree to count as the same number
SAME_NUMBER_RTOL = 1e-6
#: the seeds a failure of :func:`one_answer_problems` names where the answer differs
_SHOWN_SEEDS = 5


def one_answer_problems(exercise: Exercise, seeds: Sequence[int],
                        answers: Sequence[Mapping[str, Any]]) -> list[str]:
    """A line for each part of ``exercise`` whose answer, over the variants of ``seeds``
    (whose reference answers, in the parts' units, are ``answers``), is one answer in more
    than :data:`ONE_ANSWER_SHARE` of them; none with fewer than :data:`MIN_VARIANTS`."""
    if len(answers) < MIN_VARIANTS:
        return []
    problems = []
    for part in exercise.parts:
        if not part.answer_varies or part.constant_answer:
            continue
        references = [a[part.name] for a in answers]
        answer, count = part.one_answer(references)
        if count <= ONE_ANSWER_SHARE * len(references):
            continue
        other = [seed for seed, r in zip(seeds, references) if not part.scores(answer, r)]
        where = (f"; it differs only at seeds {_seeds(other)}" if other
                 else "; it never differs")
        problems.append(
            f"part {part.name}: the answer {part.shown_answer(answer)} scores in {count} of "
            f"{len(references)} variants ({percent(count / len(references))}){where}: "
            f"vary the parameters so the class's answers differ, or give the part "
            f"constant_answer=\"why\" where one answer is the physics taught")
    return problems


def coincidences(exercise: Exercise, answers: Mapping[str, Any]) -> list[str]:
    """A line for each pair of numeric parts whose answers in one variant (``answers``, in
    the parts' units) can be swapped and score: the part, both numbers with their units."""
    numbers = [(part, answers[part.name]) for part in exercise.parts
               if isinstance(part.key_number(answers[part.name]), float)]
    problems = []
    for i, (first, a) in enumerate(numbers):
        for second, b in numbers[i + 1:]:
            if _scores_for(second, a, first.unit, b) or _scores_for(first, b, second.unit, a):
                problems.append(
                    f"parts {first.name} and {second.name} coincide: "
                    f"{first.name} = {first.shown_answer(a)} and "
                    f"{second.name} = {second.shown_answer(b)}, so swapping their formulas "
                    f"scores both")
    return problems


def _scores_for(part, value: float, unit: str | None, expected: float) -> bool:
    """Whether ``value``, worked out in ``unit`` for another part, scores in ``part``
    whose reference is ``expected`` (the module docstring's two comparisons)."""
    typed = part.typed_as(value, unit)
    if typed is not None:
        return part.scores(typed, expected)
    bare = part.typed_bare(value)
    return bare is not None and abs(bare - expected) <= SAME_NUMBER_RTOL * max(
        abs(bare), abs(expected))


def _seeds(seeds: Sequence[int]) -> str:
    shown = ", ".join(map(str, seeds[:_SHOWN_SEEDS]))
    return shown + (f" and {len(seeds) - _SHOWN_SEEDS} more" if len(seeds) > _SHOWN_SEEDS
                    else "")
