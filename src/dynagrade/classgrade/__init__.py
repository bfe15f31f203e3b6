"""Grading a class against an exam's manifest: collecting the submissions (folders,
response CSVs, a platform's bulk download), grading them, the staff's overrides, the
gradebooks a platform imports, item statistics, feedback and the report.

Usage::

    from dynagrade.classgrade import grade_class
    grade_class("out/manifest.json", ["out/submissions/"], "out/grading/")

The command line is ``dynagrade grade --manifest``.
"""

__all__ = ["grade_class"]


def grade_class(*args, **kwargs):
    """See :func:`dynagrade.classgrade.grade.grade_class`."""
    from .grade import grade_class as run

    return run(*args, **kwargs)
