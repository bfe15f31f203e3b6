"""Grading of choice parts: one option, or a set of options with partial credit.

Labels are matched ignoring case and spaces. A multiple-choice answer lists labels
separated by commas, semicolons or spaces (``a, c``). Partial credit for multiple
choice: ``max(0, (right picks - wrong picks) / number of right options)``; only the
exact set is correct.
"""

from __future__ import annotations

import re

from .errors import SpecError
from .verdict import Verdict, unreadable


def _key(label: str) -> str:
    return re.sub(r"\s+", "", str(label)).casefold()


def _expected(spec, expected) -> set[str]:
    labels = (expected,) if isinstance(expected, str) else tuple(expected)
    keys = {_key(o) for o in spec.options}
    chosen = {_key(x) for x in labels}
    if not chosen or not chosen <= keys:
        raise SpecError(f"the reference {expected!r} is not among the options {spec.options!r}")
    if not spec.multiple and len(chosen) != 1:
        raise SpecError("a single-choice part needs exactly one right option")
    return chosen


def _split(spec, answer: str) -> list[str] | str:
    keys = {_key(o): o for o in spec.options}
    text = answer.strip().strip("{}[]()")
    if not text:
        return "the answer is empty: choose " + ("one or more options" if spec.multiple else "an option")
    if _key(text) in keys:
        return [_key(text)]
    picks = []
    for chunk in re.split(r"[,;]|\band\b", text):
        chunk = chunk.strip()
        if not chunk:
            continue
        if _key(chunk) in keys:
            picks.append(_key(chunk))
            continue
        words = chunk.split()
        if len(words) > 1 and all(_key(w) in keys for w in words):
            picks.extend(_key(w) for w in words)
            continue
        shown = chunk if len(chunk) <= 30 else chunk[:30] + "…"
        return f"unknown option '{shown}'; the options are: {', '.join(spec.options)}"
    if not picks:
        return "the answer is empty: choose an option"
    return picks


def grade_choice(spec, expected, answer: str) -> Verdict:
    right = _expected(spec, expected)
    picks = _split(spec, answer)
    if isinstance(picks, str):
        return unreadable(picks)
    chosen = set(picks)
    reveal = ""
    if spec.reveal:
        labels = [o for o in spec.options if _key(o) in right]
        reveal = " The right option" + ("s are " if len(labels) > 1 else " is ") + ", ".join(labels) + "."
    if not spec.multiple:
        if len(chosen) > 1:
            return Verdict(False, 0.0, "Choose only one option." + reveal)
        if chosen == right:
            return Verdict(True, 1.0, "Correct.")
        return Verdict(False, 0.0, "Not correct." + reveal)
    if chosen == right:
        return Verdict(True, 1.0, "Correct.")
    hits = len(chosen & right)
    wrong = len(chosen - right)
    score = max(0.0, (hits - wrong) / len(right))
    text = f"Not correct: {hits} of your {len(chosen)} choices are right"
    missing = len(right - chosen)
    if missing:
        text += f", and {missing} right option{'s are' if missing > 1 else ' is'} missing"
    return Verdict(False, score, text + "." + reveal)
