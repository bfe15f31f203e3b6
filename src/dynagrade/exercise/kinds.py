"""The exercise model's half of every part kind, registered by defining it.

A part kind is its part class (:mod:`.parts`): it declares its name (``kind``), its
grading kind (``grading``: :class:`dynagrade.grading.kinds.GradingKind`, which names the
spec class and the functions that grade, accept, read and build it), its Moodle form
(``moodle``) and the manifest settings it stores, and its methods say everything else
that differs between kinds (the fill-in line, the answer in the key, the near misses).
Defining a class with its own ``kind`` registers it in :data:`PART_KINDS`;
:func:`check_part_kind` refuses, at that moment, a class that lacks a piece or whose
pieces disagree, so no test has to hold tables of kinds together.

The Moodle form is data, not code: the exercise model may not import the renderers
(docs/design.md, "Layers"). A kind says which form it takes (:class:`MoodleForm`) or that
it is not exported and what the staff note calls it (:class:`NotExported`);
:mod:`dynagrade.render.moodle` writes each form, and a test holds that it writes every
member of :class:`MoodleForm`. Whether a lone part becomes a Moodle ``numerical``
question is part of the form (only :attr:`MoodleForm.NUMBER`), never a separate flag that
could be set on a kind whose answer is no single number.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum
from typing import Any, ClassVar, Protocol

from ..errors import DefinitionError
from ..grading.kinds import GRADING_KINDS, GradingKind


class MoodleForm(Enum):
    """How a part goes into a Moodle question (:mod:`dynagrade.render.moodle`)."""

    #: one NUMERICAL field with the part's tolerance; a lone part of its exercise is a
    #: ``numerical`` question instead (the answer is one number in ``unit``)
    NUMBER = "number"
    #: a NUMERICAL field per component (``size`` of them), each with its own tolerance
    COMPONENTS = "components"
    #: a drop-down of the options' text, or check boxes when several are right
    OPTIONS = "options"


@dataclass(frozen=True)
class NotExported:
    """A kind Moodle cannot check: its parts are left out of the question, and the
    category's staff note names each as ``absent`` (``"a formula"``)."""

    absent: str

    def __post_init__(self) -> None:
        if not isinstance(self.absent, str) or not self.absent.strip():
            raise DefinitionError("NotExported needs the words the staff note uses for "
                                  "the part (e.g. 'a formula')")


class PartKind(Protocol):
    """A part as the layers above read its kind from :data:`PART_KINDS` (whose values are
    the part classes): the class attributes :func:`check_part_kind` guarantees.
    :class:`dynagrade.exercise.parts.Part` is one; this module cannot import it, since
    ``parts`` imports this module."""

    manifest_fields: ClassVar[tuple[str, ...]]
    answer_varies: ClassVar[bool]
    moodle: ClassVar[MoodleForm | NotExported | None]
    compares_numbers: ClassVar[bool]

    @classmethod
    def answer_number(cls, entry: Any, text: str) -> float | tuple[float, ...] | None: ...

    @classmethod
    def key_number(cls, key: Any) -> float | tuple[float, ...] | None: ...


#: every part kind by its name (the ``kind`` of a part and of a manifest's part entry)
PART_KINDS: dict[str, type[PartKind]] = {}


def check_part_kind(cls: type) -> None:
    """Refuse a part class that declares a ``kind`` without the other pieces a kind
    needs, or with pieces that disagree: a grading kind registered under the same name,
    a Moodle form, and manifest settings given as attribute names; and a name taken."""
    name = cls.__dict__["kind"]
    where = f"part kind {name!r} ({cls.__name__})"
    grading = cls.__dict__.get("grading")
    if not isinstance(grading, GradingKind):
        raise DefinitionError(f"{where} names no grading kind: set grading = "
                              "dynagrade.grading.kinds.GRADING_KINDS[...] (its spec, grade, "
                              "accepts, read and build)")
    if GRADING_KINDS.get(name) is not grading:
        raise DefinitionError(f"{where}: its grading kind must be the one registered as "
                              f"{name!r} in dynagrade.grading.kinds, not {grading.name!r}")
    moodle = cls.__dict__.get("moodle")
    if not isinstance(moodle, (MoodleForm, NotExported)):
        raise DefinitionError(f"{where} says nothing of Moodle: set moodle to a MoodleForm "
                              f"or NotExported('...'), not {moodle!r}")
    fields = getattr(cls, "manifest_fields", ())
    if not isinstance(fields, tuple) or not all(isinstance(f, str) for f in fields):
        raise DefinitionError(f"{where}: manifest_fields must be a tuple of attribute names")
    if name in PART_KINDS and PART_KINDS[name] is not cls:
        raise DefinitionError(f"{where}: the kind {name!r} is already "
                              f"{PART_KINDS[name].__name__}")


def register_part_kind(cls: type[PartKind]) -> None:
    """Check ``cls`` (:func:`check_part_kind`) and register it under its ``kind``."""
    check_part_kind(cls)
    PART_KINDS[cls.__dict__["kind"]] = cls
