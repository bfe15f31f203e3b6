"""Previews and submits wait in separate lanes of the grading pool (issue 28, item 1): a
class typing fills the previews' lane, and a submit is still graded, before the previews
that waited; previews are the ones refused (503) when the pool is busy."""

from __future__ import annotations

import asyncio

import pytest

from serve_support import exam_dir  # noqa: F401


def test_previews_filling_the_pool_never_make_a_submit_fail(exam_dir):
    from dynagrade.exam.manifest import load
    from dynagrade.serve.grading_pool import Busy, GradingPool

    manifest = exam_dir / "manifest.json"
    student = load(manifest).students[0]
    variant = student.variant("projectile-range")
    right = {name: repr(value) for name, value in variant.answers.items()
             if isinstance(value, float)}
    # previews may wait long here: a loaded machine must not shed them by time
    pool = GradingPool(str(manifest), workers=1, queue=8, preview_queue=8, preview_wait=120)
    try:
        pool.warm_up()

        async def class_typing():
            finished: list[str] = []

            async def preview(number: int):
                try:
                    await pool.read(student.student_id, "projectile-range", "x_max",
                                    f"{number} m", None)
                    finished.append("preview")
                except Busy:
                    finished.append("refused preview")

            async def submit():
                graded = await pool.grade(student.student_id, "projectile-range", right, None)
                finished.append("submit")
                return graded

            previews = [asyncio.create_task(preview(n)) for n in range(40)]
            await asyncio.sleep(0)  # the previews are in their lane before the submits
            submits = await asyncio.gather(*(submit() for _ in range(3)))
            await asyncio.gather(*previews)
            return finished, submits

        finished, submits = asyncio.run(class_typing())
    finally:
        pool.close()
    # 40 previews on one process: one runs, 8 wait, the other 31 are refused at once;
    # the three submits wait too, in their own lane, and none is refused
    assert finished.count("refused preview") == 31
    assert finished.count("preview") == 9
    assert [len(graded) for graded in submits] == [len(right)] * 3
    assert all(part.readable for graded in submits for part in graded)
    # a process that comes free takes a submit first: after the preview that was running,
    # the three submits, then the eight previews that waited
    done = [what for what in finished if what != "refused preview"]
    assert done == ["preview", "submit", "submit", "submit"] + ["preview"] * 8


def test_a_preview_that_waits_too_long_is_refused_and_frees_its_place():
    from dynagrade.serve.grading_pool import PREVIEW, SUBMIT, Busy, Lanes

    async def scenario():
        lanes = Lanes(1, {SUBMIT: 4, PREVIEW: 1})
        await lanes.enter(SUBMIT)  # the one process is busy
        with pytest.raises(Busy):
            await lanes.enter(PREVIEW, seconds=0.05)
        assert len(lanes.waiting[PREVIEW]) == 0  # its place is free again
        waiting = asyncio.create_task(lanes.enter(PREVIEW, seconds=5))
        await asyncio.sleep(0)
        with pytest.raises(Busy):  # the lane of one is full: refused at once
            await lanes.enter(PREVIEW, seconds=5)
        lanes.leave()
        await waiting  # the freed process went to the preview that waited
        assert lanes.free == 0
        lanes.leave()
        assert lanes.free == 1

    asyncio.run(scenario())
