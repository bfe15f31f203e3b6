"""Exams: every student's variants, sheets, answer keys and LMS export, and grading a
class from the exam's manifest.

Usage::

    from dynagrade.exam import generate_exam, grade_class
    generate_exam("exam.toml", "roster.csv", "out/")
    grade_class("out/manifest.json", ["out/submissions/"], "out/grading/")

The command line is ``dynagrade exam`` and ``dynagrade grade --manifest``; the file
formats are described in ``docs/exams.md``.
"""

from .spec import ExamSpec, ExamSpecError, Student, read_exam_spec, read_roster

__all__ = ["ExamSpec", "ExamSpecError", "Student", "read_exam_spec", "read_roster",
           "generate_exam", "grade_class"]


def generate_exam(*args, **kwargs):
    """See :func:`dynagrade.exam.generate.generate_exam`."""
    from .generate import generate_exam as run

    return run(*args, **kwargs)


def grade_class(*args, **kwargs):
    """See :func:`dynagrade.exam.classgrade.grade_class`."""
    from .classgrade import grade_class as run

    return run(*args, **kwargs)
