"""Seeds: a variant is fully determined by (exercise id, seed).

A student's seed is a stable hash of who they are and what they are given, so that the
same student always gets the same numbers, on any machine and in any Python version.
"""

from __future__ import annotations

import hashlib


def stable_seed(*keys: str) -> int:
    """A 32-bit seed from the SHA-256 of ``keys`` joined by NUL bytes."""
    digest = hashlib.sha256("\0".join(keys).encode("utf-8")).digest()
    return int.from_bytes(digest[:4], "big")


def student_seed(exercise_id: str, student_id: str) -> int:
    """The seed of a student's own variant of an exercise."""
    return stable_seed("student", exercise_id, student_id)


def exam_seed(exam_id: str, student_id: str, exercise_id: str) -> int:
    """The seed of a student's variant of an exercise in an exam."""
    return stable_seed("exam", exam_id, student_id, exercise_id)
