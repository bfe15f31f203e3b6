"""Can this answer be graded? The check an exam may show before its key is released.

``readability(spec, text)`` reads an answer the way grading would — a number with a unit
of the right dimension, a vector with the right number of components, a formula in the
declared names only, one of the options — and says how it was read ("reads as 45 km/h =
12.5 m/s"). It never sees the reference answer, so it cannot reveal whether the answer
is right: exam mode shows this message, homework shows the verdict too.

Never raises because of ``text``. Each kind reads its own answers (the ``read`` of its
:class:`~dynagrade.grading.kinds.GradingKind`, in the kind's module).
"""

from __future__ import annotations

from ..i18n import _
from dataclasses import dataclass

from .errors import AnswerError


@dataclass(frozen=True)
class Readability:
    """Whether an answer can be graded, and how it was read (or why not)."""

    readable: bool
    message: str


def readability(spec, text: str) -> Readability:
    """How ``text`` reads as an answer to a part with ``spec`` (a grading spec)."""
    if not isinstance(text, str) or not text.strip():
        return Readability(False, _("no answer yet"))
    from .kinds import kind_of

    from .decorations import mode_for, noted_reading, strip

    kind = kind_of(spec)
    if kind is None:
        return Readability(False, _("this kind of answer cannot be checked here"))
    stripped = strip(text, mode_for(spec))
    try:
        found = kind.function("read")(spec, stripped.text)
    except AnswerError as error:
        found = Readability(False, str(error))
    except (RecursionError, MemoryError):
        found = Readability(False, _("the answer cannot be read (too large or too deeply nested)"))
    except Exception:  # a reader's own failure on odd input: still an answer, not a crash
        found = Readability(False, _("the answer cannot be read; write a number, a unit and "
                                     "operators only"))
    return noted_reading(found, stripped, spec)
