"""Generating an exam: every student's variants, sheets, fill-in files, PDFs, answer keys
and LMS export, and the Moodle question pool.

Usage::

    from dynagrade.generation import generate_exam
    generate_exam("exam.toml", "roster.csv", "out/")

The command line is ``dynagrade exam`` and ``dynagrade moodle``.
"""

__all__ = ["generate_exam"]


def generate_exam(*args, **kwargs):
    """See :func:`dynagrade.generation.generate.generate_exam`."""
    from .generate import generate_exam as run

    return run(*args, **kwargs)
