"""The grader's half of every part kind, each registered once.

A part kind is one object on each side of the layers (docs/design.md, "Part kinds"):
here, below the exercise model, a :class:`GradingKind` names its spec class and the
functions that grade, accept, read and build it; above, the exercise model's part class
(:mod:`dynagrade.exercise.parts`) names its grading kind, its Moodle form and its
wording. Like scipy's ``integrate._ivp`` ``METHODS`` (one ``OdeSolver`` subclass per
method) or a PrairieLearn element folder, the kind is the unit: :func:`register` refuses
a kind that lacks a piece, so the registry's type is its completeness check, and nothing
else keeps a table keyed by kind.

The functions are named, not imported (``"vector:grade_vector"``: a module of
:mod:`dynagrade.grading` and a function in it) and imported on first use, so grading a
number never loads the symbolic machinery; :meth:`GradingKind.function` finds one, and a
test finds every one of every kind. By convention a kind's functions live in its own
module (:mod:`.numeric`, :mod:`.vector`, :mod:`.symbolic`, :mod:`.choice`).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, fields
from functools import cache
from importlib import import_module
from typing import Callable

from ..errors import DefinitionError
from .spec import ChoiceSpec, NumericSpec, SymbolicSpec, VectorSpec

#: a function of a grading module, as a kind names it
_FUNCTION = re.compile(r"[a-z_][a-z0-9_]*:[a-z_][a-z0-9_]*")


@dataclass(frozen=True)
class GradingKind:
    """What the grader knows of a part kind; every piece is required (``accepts`` may
    be None, said explicitly: :func:`dynagrade.grading.accepts` then asks ``grade``).

    - ``name``: the kind's name (a part's ``kind``, a compare record's ``kind``);
    - ``spec``: its spec class (:mod:`.spec`); a subclass of it grades as it does;
    - ``grade(spec, expected, answer) -> Verdict``: the verdict (:func:`.dispatch.grade`);
    - ``accepts(spec, expected, answer) -> bool``: the same decision without feedback;
    - ``read(spec, text) -> Readability``: how an answer reads, without the reference
      (:func:`.readability.readability`);
    - ``build(record, common) -> (spec, expected)``: a ``dynagrade compare`` record's
      spec and reference (:mod:`.compare`, :mod:`.records`).
    """

    name: str
    spec: type
    grade: str
    accepts: str | None
    read: str
    build: str

    def __post_init__(self) -> None:
        if not isinstance(self.name, str) or not re.fullmatch(r"[a-z][a-z0-9_]*", self.name):
            raise DefinitionError(f"a part kind's name must be a lower-case word, "
                                  f"got {self.name!r}")
        if not isinstance(self.spec, type):
            raise DefinitionError(f"part kind {self.name!r}: spec must be a class, "
                                  f"got {self.spec!r}")
        for piece in ("grade", "accepts", "read", "build"):
            value = getattr(self, piece)
            if value is None and piece == "accepts":
                continue
            if not isinstance(value, str) or not _FUNCTION.fullmatch(value):
                raise DefinitionError(
                    f"part kind {self.name!r} has no {piece} function: name one as "
                    f"'module:function' (a module of dynagrade.grading), got {value!r}")

    def function(self, piece: str) -> Callable:
        """The function named for ``piece`` (``"grade"``, ``"accepts"``, ``"read"``,
        ``"build"``), imported on first use."""
        return _named(getattr(self, piece))


@cache
def _named(where: str) -> Callable:
    """The function ``module:function`` of dynagrade.grading (looked up once: every
    answer read or graded asks for one)."""
    module, name = where.split(":")
    return getattr(import_module(f".{module}", __package__), name)


#: the pieces of a kind, in order (a test finds each)
PIECES = tuple(f.name for f in fields(GradingKind))[2:]


def register(*kinds: GradingKind) -> dict[str, GradingKind]:
    """The registry of ``kinds`` by name; DefinitionError for anything that is not a
    complete :class:`GradingKind`, or a name or spec class registered twice."""
    registry: dict[str, GradingKind] = {}
    for kind in kinds:
        if not isinstance(kind, GradingKind):
            raise DefinitionError(f"not a part kind: {kind!r}")
        clash = next((k for k in registry.values()
                      if k.name == kind.name or k.spec is kind.spec), None)
        if clash is not None:
            raise DefinitionError(f"part kind {kind.name!r} clashes with {clash.name!r}: "
                                  "each kind has its own name and spec class")
        registry[kind.name] = kind
    return registry


#: every part kind the grader knows, by name: one line per kind
GRADING_KINDS: dict[str, GradingKind] = register(
    GradingKind("numeric", NumericSpec, "numeric:grade_numeric", "numeric:accepts_numeric",
                "numeric:read_numeric", "numeric:build_numeric"),
    GradingKind("symbolic", SymbolicSpec, "symbolic:grade_symbolic", None,
                "symbolic:read_symbolic", "symbolic:build_symbolic"),
    GradingKind("vector", VectorSpec, "vector:grade_vector", "vector:accepts_vector",
                "vector:read_vector", "vector:build_vector"),
    GradingKind("choice", ChoiceSpec, "choice:grade_choice", None,
                "choice:read_choice", "choice:build_choice"),
)

_BY_SPEC = {kind.spec: kind for kind in GRADING_KINDS.values()}


def kind_of(spec) -> GradingKind | None:
    """The kind ``spec`` belongs to (a subclass of a kind's spec class belongs to it),
    or None."""
    return next((_BY_SPEC[c] for c in type(spec).__mro__ if c in _BY_SPEC), None)
