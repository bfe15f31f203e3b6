"""Grading of choice parts: one option, or a set of options with partial credit.

Labels are matched ignoring case and spaces, and may be written ``b``, ``(b)``,
``b)``, ``[b]``, ``{b}`` or ``b.``; an option may also be named by its aliases (the
number or letter the statement gives it: ``spec.aliases``). A multiple-choice answer lists labels separated by
commas, semicolons, spaces or "and" (``a, c``, ``(a) (c)``, ``a) and c)``), in any
mix of these forms. An option labelled with a word of the interface (``yes``, ``no``,
``true``, ``false``: :data:`CHOICE_WORDS`) may also be written in the active language
(``ja``, ``nein`` in a German exam); English exams accept the English words only. Answers longer than :data:`lexer.MAX_LENGTH` are refused before
any other work. Partial credit for multiple
choice: ``max(0, (right picks - wrong picks) / number of right options)``; only the
exact set is correct.

The module is the kind's grading half (:mod:`.kinds`): besides grading it reads an answer
without the reference (``read_choice``) and builds the spec of a ``dynagrade compare`` record
(``build_choice``).
"""

from __future__ import annotations

from ..i18n import N_, _, ngettext
import re

from .errors import SpecError
from .lexer import MAX_LENGTH
from .verdict import Verdict, unreadable
from . import records
from .readability import Readability
from .records import Common
from .spec import ChoiceSpec


#: What may separate the labels of several options.
_SEPARATORS = re.compile(r"[,;]|\band\b")
#: Option labels that are words of the interface: in another language, the word's
#: translation names the same option too (docs/grading.md, "Choice words").
CHOICE_WORDS = (N_("yes"), N_("no"), N_("true"), N_("false"))
#: Brackets around labels in a run of labels (``(a)(c)``, ``a) c)``) separate them.
_BRACKETS_AS_SPACES = str.maketrans("()[]{}", "      ")


def _key(label: str) -> str:
    return re.sub(r"\s+", "", str(label)).casefold()


def _keys(spec) -> dict[str, str]:
    """Every way to name an option (its label, its aliases), as keys -> the option's key."""
    keys = {_key(o): _key(o) for o in spec.options}
    for alias, option in spec.aliases:
        keys.setdefault(_key(alias), _key(option))
    for word in CHOICE_WORDS:  # ``ja`` for ``yes`` in German; nothing new in English
        if _key(word) in keys and keys[_key(word)] == _key(word):
            keys.setdefault(_key(_(word)), _key(word))
    return keys


def shown_option(label: str) -> str:
    """An option's label as the interface shows it: a choice word in the active language
    (``ja`` for ``yes`` in German), any other label as the author wrote it."""
    return _(label) if label in CHOICE_WORDS else label


def _expected(spec, expected) -> set[str]:
    labels = (expected,) if isinstance(expected, str) else tuple(expected)
    keys = {_key(o) for o in spec.options}
    chosen = {_key(x) for x in labels}
    if not chosen or not chosen <= keys:
        raise SpecError(f"the reference {expected!r} is not among the options {spec.options!r}")
    if not spec.multiple and len(chosen) != 1:
        raise SpecError("a single-choice part needs exactly one right option")
    return chosen


def _label(word: str, keys: dict) -> str | None:
    """The option a written label names: ``b``, ``(b)``, ``b)``, ``[b]``, ``{b}`` or ``b.``."""
    for form in (word, word.strip("()[]{}"), word.rstrip(".").strip("()[]{}")):
        if form and _key(form) in keys:
            return keys[_key(form)]
    return None


def _split(spec, answer: str) -> list[str] | str:
    if len(answer) > MAX_LENGTH:
        return _("the answer is too long ({length} characters; at most {limit})").format(
            length=len(answer), limit=MAX_LENGTH)
    keys = _keys(spec)
    text = answer.strip()
    if not text.strip("()[]{}").strip():
        return (_("the answer is empty: choose one or more options") if spec.multiple
                else _("the answer is empty: choose an option"))
    whole = _label(text, keys)
    if whole is not None:
        return [whole]
    picks = []
    for chunk in _SEPARATORS.split(text):
        chunk = chunk.strip()
        if not chunk:
            continue
        label = _label(chunk, keys)
        if label is not None:
            picks.append(label)
            continue
        words = chunk.translate(_BRACKETS_AS_SPACES).split()
        labels = [_label(w, keys) for w in words]
        if len(words) > 1 and all(labels):
            picks.extend(label for label in labels if label)
            continue
        shown = chunk if len(chunk) <= 30 else chunk[:30] + "…"
        options = ", ".join(shown_option(o) for o in spec.options)
        if spec.aliases:
            return _("unknown option '{given}'; the options are: {options} (or {aliases})").format(
                given=shown, options=options, aliases=", ".join(a for a, _o in spec.aliases))
        return _("unknown option '{given}'; the options are: {options}").format(
            given=shown, options=options)
    if not picks:
        return _("the answer is empty: choose an option")
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
        reveal = " " + ngettext("The right option is {options}.", "The right options are {options}.",
                                len(labels)).format(options=", ".join(shown_option(o) for o in labels))
    if not spec.multiple:
        if len(chosen) > 1:
            return Verdict(False, 0.0, _("Choose only one option.") + reveal)
        if chosen == right:
            return Verdict(True, 1.0, _("Correct."))
        return Verdict(False, 0.0, _("Not correct.") + reveal)
    if chosen == right:
        return Verdict(True, 1.0, _("Correct."))
    hits = len(chosen & right)
    wrong = len(chosen - right)
    score = max(0.0, (hits - wrong) / len(right))
    text = _("Not correct: {hits} of your {chosen} choices are right").format(
        hits=hits, chosen=len(chosen))
    missing = len(right - chosen)
    if missing:
        text += ngettext(", and {missing} right option is missing",
                         ", and {missing} right options are missing", missing).format(missing=missing)
    return Verdict(False, score, text + "." + reveal)


def read_choice(spec: ChoiceSpec, text: str) -> Readability:
    """How ``text`` reads as an answer to ``spec`` (:func:`.readability.readability`)."""
    picks = _split(spec, text)
    if isinstance(picks, str):
        return Readability(False, picks)
    if not spec.multiple and len(set(picks)) > 1:
        return Readability(False, _("choose only one option"))
    chosen = [o for o in spec.options if any(o.replace(" ", "").casefold() == p for p in picks)]
    return Readability(True, _("reads as {answer}").format(
        answer=", ".join(shown_option(o) for o in chosen)))


def build_choice(record: dict, common: Common):
    """A choice record's spec and reference (``dynagrade compare``, :mod:`.compare`)."""
    choices = record.get("choices")
    if not isinstance(choices, list) or not choices or not all(isinstance(c, str) for c in choices):
        raise records.RecordError("field 'choices' must be a non-empty list of strings")
    expected = record["expected"]
    if isinstance(expected, list):
        expected = tuple(expected)
    if not (isinstance(expected, str) or (isinstance(expected, tuple) and all(isinstance(x, str) for x in expected))):
        raise records.RecordError("field 'expected' of a choice must be a label or a list of labels")
    aliases = record.get("aliases") or {}
    if not isinstance(aliases, dict) or not all(isinstance(v, str) for v in aliases.values()):
        raise records.RecordError("field 'aliases' must be an object of labels")
    spec = ChoiceSpec(tuple(choices), multiple=records.flag(record, "multiple") or isinstance(expected, tuple),
                      reveal=common.reveal, aliases=tuple(aliases.items()))
    return spec, expected
