"""Seeds: a variant is fully determined by (exercise id, seed).

Practice variants (``dynagrade sheet``, ``show --student``) are seeded by a public hash of
the student and exercise: anybody may regenerate them, and that is the point.

Exam variants are seeded by a keyed hash (HMAC-SHA-256) with the exam's **secret**, which
only the instructor's manifest holds: without it nobody can tell which seed a student got,
so nobody can regenerate their parameters or key. A student's fill-in file carries an
opaque **variant token** instead of the seed: another HMAC with the secret, of the exam,
student, exercise and seed. It identifies the variant to the staff (who hold the secret)
and authenticates it: a token cannot be made up or moved to another student.
"""

from __future__ import annotations

import hashlib
import hmac

SECRET_BYTES = 32
TOKEN_CHARACTERS = 24
_TOKEN_ALPHABET = "0123456789abcdefghjkmnpqrstvwxyz"  # Crockford's base 32, lower case


def stable_seed(*keys: str) -> int:
    """A 32-bit seed from the SHA-256 of ``keys`` joined by NUL bytes."""
    digest = hashlib.sha256("\0".join(keys).encode("utf-8")).digest()
    return int.from_bytes(digest[:4], "big")


def student_seed(exercise_id: str, student_id: str) -> int:
    """The seed of a student's own (public, practice) variant of an exercise."""
    return stable_seed("student", exercise_id, student_id)


def new_secret() -> str:
    """A fresh exam secret: 32 random bytes as hex."""
    import secrets  # here: only a new exam needs it, and it imports random and base64

    return secrets.token_hex(SECRET_BYTES)


def _keyed(secret: str, *keys: str) -> bytes:
    return hmac.new(secret.encode("utf-8"), "\0".join(keys).encode("utf-8"),
                    hashlib.sha256).digest()


def exam_seed(secret: str, exam_id: str, student_id: str, exercise_id: str,
              attempt: int = 0) -> int:
    """The seed of a student's ``attempt``-th draw of an exercise in an exam (0: the
    first; later ones replace draws that cannot discriminate)."""
    keys: tuple[str, ...] = ("exam", exam_id, student_id, exercise_id)
    if attempt:
        keys += ("redraw", str(attempt))
    return int.from_bytes(_keyed(secret, *keys)[:4], "big")


def variant_token(secret: str, exam_id: str, student_id: str, exercise_id: str,
                  seed: int) -> str:
    """The opaque token of a student's variant, printed in their fill-in file."""
    digest = int.from_bytes(_keyed(secret, "token", exam_id, student_id, exercise_id,
                                   str(seed))[:15], "big")
    return "".join(_TOKEN_ALPHABET[(digest >> (5 * i)) & 31]
                   for i in reversed(range(TOKEN_CHARACTERS)))


def token_matches(token: str, expected: str) -> bool:
    """Whether a file's ``token`` is ``expected`` (compared in constant time)."""
    return hmac.compare_digest(token.encode("utf-8"), expected.encode("utf-8"))
