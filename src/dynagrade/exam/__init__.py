"""What an exam is: its specification (``exam.toml``), roster, delivery policy, points and
their rounding, secret, and the manifest that records every student's variants.

Generating an exam is :mod:`dynagrade.generation`, grading a class
:mod:`dynagrade.classgrade`; both read and write the records defined here, and so do
the renderers (:mod:`dynagrade.render`) and the server (:mod:`dynagrade.serve`). The
file formats are described in ``docs/exams.md``.
"""

from .spec import ExamSpec, ExamSpecError, Student, read_exam_spec, read_roster

__all__ = ["ExamSpec", "ExamSpecError", "Student", "read_exam_spec", "read_roster"]
