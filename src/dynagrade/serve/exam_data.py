"""The exam the server delivers: the one place that reads the manifest.

:class:`ExamData` holds what ``dynagrade exam`` wrote (students, their variants with the
stored reference answers, part points, the policy) and the bank's exercises that grade
them. It renders a student's statement (HTML with MathML; the figure ``dynagrade exam``
drew), reads answers (:mod:`dynagrade.grading.readability`) and grades them exactly as
class grading does (:func:`dynagrade.classgrade.grade.grade_student`), so a regrade of the
server's submissions with ``dynagrade grade`` gives the same points.
"""

from __future__ import annotations

from ..i18n import _
import secrets
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import Callable

from ..errors import UnknownExercise
from ..classgrade.grade import grade_student, stored_variant
from ..exam.manifest import ManifestError, PartEntry, StudentEntry, VariantEntry, load
from ..exam.points import Rounding
from ..exam.policy import Policy
from ..classgrade.submissions import Submission
from ..exercise.loader import Bank, open_bank
from ..exercise.model import ConstraintError, Exercise
from ..exercise.results import GradedPart, Status
from ..grading.readability import readability
from .verdicts import SubmittedPart

#: Longest answer text accepted for one part (longer answers are refused, not graded).
MAX_ANSWER_CHARS = 2000

#: The most statements (or worked solutions) a server process keeps rendered: enough for
#: every variant of a class of 3,000 students with 6 exercises, a bound on the memory of
#: a larger one (a statement is a few kB of HTML).
MAX_CACHED_VARIANTS = 20_000
#: The most readings of answers shown on pages a process keeps (a reading is a sentence,
#: a formula's MathML at most a few kB).
MAX_CACHED_READINGS = 50_000


def cache_size(students: int, exercises: int) -> int:
    """Entries of a per-variant cache: one per student and exercise, so that no page of a
    class evicts another's (a fixed 4,096 was smaller than 700 students x 6 exercises),
    within :data:`MAX_CACHED_VARIANTS`."""
    return max(64, min(MAX_CACHED_VARIANTS, students * exercises))


@dataclass(frozen=True)
class PartInfo:
    """One answer part as the student page shows it."""

    name: str
    label: str
    kind: str
    unit: str  # as printed ("m/s²")
    points: float
    hint: str
    #: the options of a choice part (empty: a free-text answer)
    options: tuple[str, ...] = ()
    #: whether several options may be chosen (checkboxes rather than radio buttons)
    multiple: bool = False


class ExamData:
    """An exam manifest with its exercises, ready to show and grade."""

    def __init__(self, manifest_path: str | Path, bank: Bank | None = None):
        self.path = Path(manifest_path)
        self.manifest = load(self.path)
        exam = self.manifest.exam
        self.exam_id: str = exam.id
        self.title: str = exam.title
        self.instructions: str = exam.instructions
        #: the policy ``dynagrade exam`` wrote; :attr:`policy` is the one in force
        self.manifest_policy = Policy.from_json(exam.policy)
        #: where the policy in force comes from (the server's :mod:`.policy_changes`);
        #: ``None``: the manifest's
        self.policy_source: Callable[[], Policy] | None = None
        #: how the exam rounds points, as class grading rounds them
        self.rounding = Rounding(exam.rounding)
        self.exercises_meta = {e.id: e for e in self.manifest.exercises}
        self.exercise_ids = self.manifest.exercise_ids
        self.manifest_parts: dict[str, tuple[PartEntry, ...]] = {
            e.id: e.parts for e in self.manifest.exercises}
        self.students: dict[str, StudentEntry] = {s.student_id: s
                                                  for s in self.manifest.students}
        bank = bank or open_bank()
        self.exercises: dict[str, Exercise] = {}
        for exercise_id in self.exercise_ids:
            try:
                self.exercises[exercise_id] = bank.get(exercise_id)
            except UnknownExercise as error:
                raise ManifestError(f"{self.path}: {error} (needed to serve this "
                                    "exam; point --exercises at its folder)") from None
        variants = cache_size(len(self.students), len(self.exercise_ids))
        self._statement = lru_cache(maxsize=variants)(self._render_statement)
        self._solution = lru_cache(maxsize=variants)(self._render_solution)
        self._reading = lru_cache(maxsize=min(MAX_CACHED_READINGS, 8 * variants))(self.preview)
        #: (student, exercise) whose figure is known to be absent: a page render tries
        #: no file for them again (the folder is written before the server starts)
        self._no_figure: set[tuple[str, str]] = set()

    @property
    def policy(self) -> Policy:
        """The policy in force: the manifest's, overridden by the staff's latest change."""
        return self.policy_source() if self.policy_source is not None \
            else self.manifest_policy

    # -- what the pages show --------------------------------------------------------------

    def parts(self, exercise_id: str) -> list[PartInfo]:
        from ..exercise.units import pretty_unit

        exercise = self.exercises[exercise_id]
        return [PartInfo(p.name, p.label, p.kind, pretty_unit(p.unit) if p.unit else "",
                         float(p.points), exercise.part(p.name).input_hint(),
                         exercise.part(p.name).input_options(), bool(p.multiple))
                for p in self.manifest_parts[exercise_id]]

    def entry(self, student_id: str, exercise_id: str,
              seed: int | None = None) -> VariantEntry:
        """The student's variant as the manifest stores it, or a practice draw ``seed``."""
        if seed is None:
            entry = self.students[student_id].variant(exercise_id)
            if entry is None:
                raise ManifestError(f"{self.path}: {student_id} has no variant of "
                                    f"{exercise_id!r}")
            return entry
        return _practice_entry(self, exercise_id, seed)

    def statement_html(self, student_id: str, exercise_id: str,
                       seed: int | None = None) -> str:
        entry = self.entry(student_id, exercise_id, seed)
        return self._statement(exercise_id, entry.seed, tuple(sorted(entry.params.items())))

    def _render_statement(self, exercise_id: str, seed: int, params: tuple) -> str:
        from ..render.markup import markdown_to_html

        variant = self.exercises[exercise_id].variant_from_params(seed, dict(params))
        return markdown_to_html(variant.statement, heading_offset=2)

    def solution_html(self, student_id: str, exercise_id: str) -> str | None:
        """The worked solution of the student's variant as HTML (MathML), from the
        variant the manifest stores; ``None`` when the exercise has none."""
        return self._solution(exercise_id, student_id)

    def _render_solution(self, exercise_id: str, student_id: str) -> str | None:
        from ..exercise.solution import render_solution
        from ..render.markup import markdown_to_html

        exercise = self.exercises[exercise_id]
        solution = render_solution(exercise, stored_variant(
            exercise, self.entry(student_id, exercise_id)))
        return None if solution is None else markdown_to_html(solution, heading_offset=3)

    def figure_svg(self, student_id: str, exercise_id: str) -> str | None:
        """The figure ``dynagrade exam`` drew for the student's variant, inline; ``None``
        when there is none (remembered: the next page looks for no file)."""
        from ..render.figures import inline_svg

        if (student_id, exercise_id) in self._no_figure:
            return None
        folder = self.path.parent / "students" / student_id
        # beside the fill-in file; exams generated before kept figures in figures/
        for path in (folder / f"{exercise_id}.svg", folder / "figures" / f"{exercise_id}.svg"):
            try:
                return inline_svg(path.read_text(encoding="utf-8"), f"figure-{exercise_id}-")
            except (OSError, UnicodeDecodeError):
                continue
        self._no_figure.add((student_id, exercise_id))
        return None

    # -- reading and grading --------------------------------------------------------------

    def read(self, student_id: str, exercise_id: str, part: str, text: str,
             seed: int | None = None) -> tuple[bool, str]:
        """How ``text`` reads as an answer to ``part`` (never reveals correctness)."""
        if len(text) > MAX_ANSWER_CHARS:
            return False, _("the answer is longer than {limit} characters").format(
                limit=MAX_ANSWER_CHARS)
        exercise = self.exercises[exercise_id]
        entry = self.entry(student_id, exercise_id, seed)
        spec = exercise.part(part).spec(exercise.si(entry.params))
        found = readability(spec, text)
        return found.readable, found.message

    def preview(self, student_id: str, exercise_id: str, part: str, text: str,
                seed: int | None = None) -> dict:
        """How ``text`` reads (:meth:`read`) and, for a formula, the formula typeset as
        MathML (``formula``: None otherwise)."""
        from .formula import formula_mathml

        readable, message = self.read(student_id, exercise_id, part, text, seed)
        asked = self.exercises[exercise_id].part(part)
        variables = asked.variable_names()
        shown = None
        if readable and variables:  # a formula: typeset it as it was read
            shown = formula_mathml(text, variables, asked.spellings())
        return {"readable": readable, "message": message, "formula": shown}

    def reading(self, student_id: str, exercise_id: str, part: str, text: str,
                seed: int | None = None) -> dict:
        """:meth:`preview` of an answer a page shows in its box (a counted answer or a
        draft), kept: a page shows the same texts again at every load. About 0.2 ms of
        CPU the first time, read here rather than stored with the answer: drafts, saved
        at every pause in typing, far outnumber page loads."""
        return self._reading(student_id, exercise_id, part, text, seed)

    def grade(self, student_id: str, exercise_id: str, answers: dict[str, str],
              seed: int | None = None, check: bool = True) -> list[SubmittedPart]:
        """Each submitted part read and, when readable, graded, with points in the exam's
        scale. ``check=False`` (a regrade of stored answers, which were read when they
        were stored) skips the reading: every answer is graded, as ``dynagrade grade``
        grades it.

        An answer the grader cannot read is not graded: its part comes back unreadable
        with the reason (:meth:`SubmittedPart.unread`), and the server stores none of it.
        A part whose grading fails (a fault of the grader, not of the student) gets the
        status "error", 0 points and a message; the other parts are graded as usual.
        """
        read = {name: self.read(student_id, exercise_id, name, text, seed) if check
                else (True, "") for name, text in answers.items()}
        readable = {name: text for name, text in answers.items() if read[name][0]}
        graded = self._grade_each(student_id, exercise_id, readable, seed) if readable else {}
        out = []
        for part in self.manifest_parts[exercise_id]:
            name = part.name
            if name not in answers:
                continue
            ok, message = read[name]
            out.append(SubmittedPart(answers[name], True, message, graded[name]) if ok else
                       SubmittedPart.unread(part, answers[name], message))
        return out

    def _grade_each(self, student_id: str, exercise_id: str, answers: dict[str, str],
                    seed: int | None) -> dict[str, GradedPart]:
        """The verdict on each answer; one that the grader fails on costs one part."""
        try:
            return self._grade_parts(student_id, exercise_id, answers, seed)
        except Exception:  # grade part by part so that one failure costs one part
            graded = {}
            for name, text in answers.items():
                try:
                    graded.update(self._grade_parts(student_id, exercise_id,
                                                    {name: text}, seed))
                except Exception as error:
                    graded[name] = _failed(self.manifest_parts[exercise_id], name, text,
                                           error)
            return graded

    def _grade_parts(self, student_id: str, exercise_id: str, answers: dict[str, str],
                     seed: int | None) -> dict[str, GradedPart]:
        entry = self.entry(student_id, exercise_id, seed)
        student = StudentEntry(student_id, "", "", (entry,))
        submission = Submission("server", student_id, exercise_id, dict(answers))
        graded = grade_student(student, {exercise_id: self.manifest_parts[exercise_id]},
                               {exercise_id: self.exercises[exercise_id]},
                               {exercise_id: submission})[exercise_id]
        if graded is None:  # cannot be: the submission is there
            raise ManifestError(f"{self.path}: {exercise_id!r} was not graded")
        return {part.name: part for part in graded.parts if part.name in answers}

    def new_practice_seed(self, exercise_id: str) -> int:
        """A fresh seed whose draw meets the exercise's constraints."""
        for _draw in range(20):
            seed = secrets.randbits(48)
            try:
                _practice_entry(self, exercise_id, seed)
            except ConstraintError:
                continue
            return seed
        raise ConstraintError(f"no practice variant of {exercise_id!r} could be drawn")


def _failed(parts: tuple[PartEntry, ...], name: str, text: str,
            error: Exception) -> GradedPart:
    part = next(p for p in parts if p.name == name)
    return GradedPart(name, part.label, Status.ERROR, 0.0, float(part.points), text,
                      _("this answer could not be graded ({error}); the staff will look at "
                        "it").format(error=type(error).__name__), unit=part.unit)


@lru_cache(maxsize=1024)
def _practice_entry(data: ExamData, exercise_id: str, seed: int) -> VariantEntry:
    exercise = data.exercises[exercise_id]
    variant = exercise.variant(seed, dict(data.exercises_meta[exercise_id].set))
    return VariantEntry(exercise_id, seed, variant.params, dict(variant.answers))

