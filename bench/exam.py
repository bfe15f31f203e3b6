"""Benchmark: generate an exam for a synthetic class, then grade sample submissions.

Usage::

    PYTHONPATH=src python bench/exam.py                              # 20 students x 3
    PYTHONPATH=src python bench/exam.py --students 500 --exercises 6 --jobs 2

Prints the wall time of each stage (choosing the variants; the students' folders, while
a worker compiles the key's PDF; the Moodle export and printing PDFs) and, for the
students' work, the CPU seconds the workers spent choosing and checking variants,
drawing figures, writing sheets, compiling PDFs and on the rest, and the CPU seconds of
``key.pdf``, ``moodle.xml`` and the combined PDFs, each in the process that wrote it; and
the CPU time of this process and its workers (user + system) next to each total, and the
load average before and after generating. The exercises are the first K of those in
``examples/exam.toml`` (three of them draw figures), then of the rest of chapters 1-2 of
the bank, each worth 10 points; the submissions
are those of ``examples/make_submissions.py`` (correct, half-correct, empty, corrupt,
duplicate, CSV, strangers) for every student, cycling through the kinds.
"""

from __future__ import annotations

import argparse
import importlib.util
import os
import shutil
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def _make_submissions_module():
    spec = importlib.util.spec_from_file_location("make_submissions",
                                                  ROOT / "examples" / "make_submissions.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def cpu_seconds() -> float:
    """User + system CPU time of this process and of its finished child processes."""
    times = os.times()
    return times.user + times.system + times.children_user + times.children_system


def load_average() -> str:
    """The machine's load averages over 1, 5 and 15 minutes, as ``uptime`` prints them: a
    time measured on a machine busy with other work is quoted with them."""
    return "load average " + ", ".join(f"{value:.2f}" for value in os.getloadavg())


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--students", type=int, default=20)
    parser.add_argument("--exercises", type=int, default=3)
    parser.add_argument("--jobs", type=int, default=None)
    parser.add_argument("--no-pdf", action="store_true")
    parser.add_argument("--keep", help="Write into this folder and keep it.")
    args = parser.parse_args(argv)

    from dynagrade.classgrade.grade import grade_class
    from dynagrade.generation.generate import generate_exam
    from dynagrade.exercise.loader import open_bank

    import tomllib

    bank = open_bank()
    with open(ROOT / "examples" / "exam.toml", "rb") as handle:
        preferred = [item["id"] for item in tomllib.load(handle)["exercise"]]
    others = [e.id for e in bank.all() if e.chapter in (1, 2) and e.id not in preferred]
    exercises = [bank.get(i) for i in (preferred + others)[:args.exercises]]
    if len(exercises) < args.exercises:
        print(f"only {len(exercises)} exercises in chapters 1-2 of the bank", file=sys.stderr)
    folder = Path(args.keep) if args.keep else Path(tempfile.mkdtemp(prefix="dynagrade-bench-"))
    if folder.exists() and args.keep:
        shutil.rmtree(folder)
    folder.mkdir(parents=True, exist_ok=True)
    try:
        exam = folder / "exam.toml"
        exam.write_text('id = "bench"\ntitle = "Benchmark exam"\ndate = 2025-01-01\n'
                        + "".join(f'\n[[exercise]]\nid = "{e.id}"\npoints = 10\n'
                                  for e in exercises), encoding="utf-8")
        roster = folder / "roster.csv"
        roster.write_text("student_id,name\n" + "".join(
            f"b{i:05d},Student {i}\n" for i in range(args.students)), encoding="utf-8")
        out = folder / "out"
        print(f"{args.students} students x {len(exercises)} exercises "
              f"({', '.join(e.id for e in exercises)}), {os.cpu_count()} cores, "
              f"jobs={args.jobs or 'default'}, {load_average()}")

        started, cpu = time.perf_counter(), cpu_seconds()
        report = generate_exam(exam, roster, out, bank=bank, jobs=args.jobs,
                               pdf=not args.no_pdf)
        generation, cpu = time.perf_counter() - started, cpu_seconds() - cpu
        for stage, seconds in report.timings.items():
            print(f"  generation / {stage:<42} {seconds:7.2f} s")
        print(f"generation{' (no PDFs)' if args.no_pdf else ' including all PDFs'}: "
              f"{generation:.2f} s, CPU {cpu:.2f} s ({report.redraws} redraws), "
              f"{load_average()}")

        make = _make_submissions_module()
        make.PLAN = tuple((kind, args.students) for kind, _ in make.PLAN)
        students = [f"b{i:05d}" for i in range(args.students)]
        kinds = ["correct", "half", "empty", "corrupt", "duplicate", "csv"]
        make.plan = lambda ids: {s: kinds[i % len(kinds)] for i, s in enumerate(students)}
        make.main(str(out))

        started, cpu = time.perf_counter(), cpu_seconds()
        outcome = grade_class(out / "manifest.json", [out / "submissions"], out / "grading",
                              bank=bank, jobs=args.jobs)
        grading, cpu = time.perf_counter() - started, cpu_seconds() - cpu
        for stage, seconds in outcome.timings.items():
            print(f"  grading / {stage:<31} {seconds:7.2f} s")
        print(f"class grading: {grading:.2f} s, CPU {cpu:.2f} s ({len(outcome.rows)} students, "
              f"{len(outcome.problems)} problems reported)")
    finally:
        if not args.keep:
            shutil.rmtree(folder, ignore_errors=True)


if __name__ == "__main__":
    main()
