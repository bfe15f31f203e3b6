"""The root of every error dynagrade raises, and the errors shared by several layers.

Every exception class of the package derives from :class:`DynagradeError`, so a caller
(the command line, the server) catches the root once and shows its message: the message
alone says what is wrong and where. Subclasses also derive from the builtin exception
they resemble, so code that expects the builtin keeps working: an unknown exercise is a
:class:`LookupError`, a bad definition a :class:`ValueError`.

This module is a leaf: it imports nothing of dynagrade, so every layer (the grader
included) may import it. Errors that belong to one layer live in that layer's modules
and derive from the root here.

One class stays outside the root on purpose: ``grading.timing.OutOfTime`` is a
control-flow signal (a time limit interrupting a computation), derived from
:class:`BaseException` like :class:`KeyboardInterrupt` so that no ``except Exception``
between the limit and its handler can swallow it. It never reaches a user.
"""

from __future__ import annotations


class DynagradeError(Exception):
    """Something dynagrade cannot do with what it was given; ``str()`` says what and where."""


class DefinitionError(DynagradeError, ValueError):
    """An exercise definition that contradicts itself: a bad id, a duplicate name, a
    reference to a part that does not exist (or comes later), a solver that leaves a part
    without an answer."""


class UnknownExercise(DynagradeError, LookupError):
    """No exercise with the requested id on the search path; the message suggests
    close ids."""


class UnknownParameter(DynagradeError, LookupError):
    """An exercise has no parameter of the requested name; the message lists those it has."""


class UnknownPart(DynagradeError, LookupError):
    """An exercise has no answer part of the requested name; the message lists those it has."""


class UnitError(DynagradeError, ValueError):
    """A value that cannot be converted to the unit asked for (different dimensions)."""
