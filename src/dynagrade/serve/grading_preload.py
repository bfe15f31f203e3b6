"""Imported once by the grading pool's fork server (:mod:`.grading_pool`): the grader's
libraries and pint's unit registry, loaded before any grading process is forked from it,
so that each process starts with them in place (a second or two less per process, and
their pages shared between the processes until written)."""

from ..grading import prepare

prepare()
