"""Practice draws travel signed: ``"<seed>.<signature>"`` in the page and its forms.

In practice mode a student may ask for a fresh variant of an exercise. The server keeps
no record of the draw: the seed goes to the page with a signature under the server's
secret, bound to the student and the exercise, so a student can neither pick a seed nor
reuse another student's draw.
"""

from __future__ import annotations

from ..i18n import _
from . import limits
from .submit import Refused


def practice_value(secret: str, student_id: str, exercise_id: str, seed: int) -> str:
    """The signed value of a practice draw ``seed`` for this student and exercise."""
    return f"{seed}.{limits.sign(secret, _signed_text(student_id, exercise_id, seed))}"


def practice_seed(secret: str, student_id: str, exercise_id: str,
                  value: str | None) -> int | None:
    """The seed of a signed practice draw (``None`` without one); :class:`Refused` (422)
    when the value is not a draw of this student and exercise."""
    if not value:
        return None
    seed, _dot, signature = value.partition(".")
    if not seed.isdigit() or not limits.signed_ok(
            secret, _signed_text(student_id, exercise_id, seed), signature):
        raise Refused(422, _("not a practice variant of this page"))
    return int(seed)


def _signed_text(student_id: str, exercise_id: str, seed) -> str:
    return f"{student_id}:{exercise_id}:{seed}"
