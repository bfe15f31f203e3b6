"""`dynagrade serve` shows a student the worked solution of their own variant after the
close or after their last attempt, as the exam's ``solutions`` setting says, and never
before."""

from __future__ import annotations

import datetime as dt

from serve_support import Clock, exam_copy, exam_dir, reference_answers, serve  # noqa: F401

from dynagrade.classgrade.grade import stored_variant

UTC = dt.timezone.utc
OPENS = dt.datetime(2025, 4, 14, 8, 0, tzinfo=UTC)
CLOSES = dt.datetime(2025, 4, 14, 12, 0, tzinfo=UTC)
HEADING = "Worked solution</h3>"


def _page(served, student: str) -> str:
    return served.client.get(f"/s/{served.tokens[student]}").text


def _key_answer(served, student: str, exercise_id: str, part: str) -> str:
    """The part's reference answer as the key prints it, for this student's variant."""
    data = served.server.data
    exercise = data.exercises[exercise_id]
    variant = stored_variant(exercise, data.entry(student, exercise_id))
    return exercise.part(part).shown_answer(variant.answers[part])


def test_an_exam_shows_each_student_their_own_solution_after_the_close(exam_dir, tmp_path):
    manifest = exam_copy(exam_dir, tmp_path / "exam", mode="exam", opens=OPENS,
                         closes=CLOSES, solutions="after-close")
    clock = Clock()
    with serve(manifest, None, clock) as served:
        served.submit("s1", "projectile-range", {"x_max": "28.9 m"})
        assert HEADING not in _page(served, "s1")
        clock.now = CLOSES
        for student, other in (("s1", "s2"), ("s2", "s1")):
            page = _page(served, student)
            # projectile-range has a worked solution: the student's own numbers, not the
            # other student's (the two variants differ in their landing distance)
            mine = _key_answer(served, student, "projectile-range", "x_max")
            theirs = _key_answer(served, other, "projectile-range", "x_max")
            assert mine != theirs
            section = page[page.index(HEADING):]
            assert mine in section and theirs not in section
            assert "<math" in section


def test_an_exam_that_says_never_shows_no_solution_even_after_the_close(exam_dir, tmp_path):
    manifest = exam_copy(exam_dir, tmp_path / "exam", mode="exam", opens=OPENS,
                         closes=CLOSES, solutions="never")
    clock = Clock()
    clock.now = CLOSES
    with serve(manifest, None, clock) as served:
        assert HEADING not in _page(served, "s1")


def test_homework_shows_the_solution_once_every_part_has_used_its_attempts(exam_dir,
                                                                           tmp_path):
    manifest = exam_copy(exam_dir, tmp_path / "hw", mode="homework", feedback="immediate",
                         counts="best", attempts=1, solutions="after-last-attempt")
    with serve(manifest, None, Clock()) as served:
        answers = reference_answers(served, "s1", "projectile-range")
        first = dict(list(answers.items())[:2])
        assert served.submit("s1", "projectile-range", first).status_code == 200
        assert HEADING not in _page(served, "s1")  # two parts still have their attempt
        rest = {k: v for k, v in answers.items() if k not in first}
        assert served.submit("s1", "projectile-range", rest).status_code == 200
        page = _page(served, "s1")
        assert page.count(HEADING) == 1  # this exercise only; nothing of the other
        assert _key_answer(served, "s1", "projectile-range", "h_max") in \
            page[page.index(HEADING):]
        assert HEADING not in _page(served, "s2")  # another student: not yet
