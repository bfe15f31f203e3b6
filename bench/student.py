"""Benchmark of one student's work in an exam generation, without PDFs: the CPU
milliseconds per student of each stage (choosing and checking variants, figures,
sheets, the rest: fill-in files) and, with ``--profile``, where they go.

    PYTHONPATH=src python bench/student.py                    # the example exam, 40 students
    PYTHONPATH=src python bench/student.py --students 100 --repeat 5
    PYTHONPATH=src python bench/student.py --profile 30       # cProfile, the top 30 by own time

The exam is ``examples/exam.toml`` (six exercises, five with a figure) for a roster of
synthetic students, generated in one process with a fixed secret. The first student is
run once before timing, so that imports and compiled templates are not counted; each
repetition opens a new run (empty caches) and the fastest is reported, as the least
disturbed by other work on the machine.
"""

from __future__ import annotations

import argparse
import cProfile
import pstats
import shutil
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "src"))

from dynagrade.generation.generate import open_run  # noqa: E402
from dynagrade.generation.student import STAGES, student_job  # noqa: E402
from dynagrade.exercise.loader import open_bank  # noqa: E402

SECRET = "bench-" + "0" * 40


def students_cpu(folder: Path, roster: Path, bank, profiler=None) -> tuple[float, dict, int]:
    """A new run's CPU seconds for every student but the first, by stage, and the
    number of students timed."""
    run, students = open_run(ROOT / "examples" / "exam.toml", roster, folder / "out", bank,
                             False, [], SECRET)
    student_job(run, students[0])
    stages = dict.fromkeys(STAGES, 0.0)
    started = time.process_time()
    if profiler is not None:
        profiler.enable()
    for student in students[1:]:
        for stage, seconds in student_job(run, student).timings.items():
            stages[stage] += seconds
    if profiler is not None:
        profiler.disable()
    shutil.rmtree(run.out_dir, ignore_errors=True)
    return time.process_time() - started, stages, len(students) - 1


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--students", type=int, default=40)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--profile", type=int, metavar="N",
                        help="Profile one repetition and print the top N functions.")
    args = parser.parse_args(argv)
    bank = open_bank()
    folder = Path(tempfile.mkdtemp(prefix="dynagrade-bench-student-"))
    try:
        roster = folder / "roster.csv"
        roster.write_text("student_id,name\n" + "".join(
            f"b{i:05d},Student {i}\n" for i in range(args.students + 1)), encoding="utf-8")
        if args.profile:
            profiler = cProfile.Profile()
            students_cpu(folder, roster, bank, profiler)
            pstats.Stats(profiler).sort_stats("tottime").print_stats(args.profile)
            return
        total, stages, count = min((students_cpu(folder, roster, bank)
                                    for _ in range(args.repeat)), key=lambda run: run[0])
        print(f"{count} students (examples/exam.toml, no PDFs), fastest of {args.repeat}: "
              f"{1000 * total / count:.2f} ms CPU per student")
        for stage in STAGES:
            if stage != "PDFs":
                print(f"  {stage:<10} {1000 * stages[stage] / count:6.2f} ms")
    finally:
        shutil.rmtree(folder, ignore_errors=True)


if __name__ == "__main__":
    main()
