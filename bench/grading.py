"""Benchmark of the grader: throughput, symbolic verdict latency, a naive CAS baseline,
the slowest verdict of a fuzzing corpus, the cold-process time of grading one filled-in
exercise file, that of `dynagrade list` (which must not run the bank's exercise files),
each with dynagrade's bytecode cached and compiled from source, and that of collecting
the test suite.

    PYTHONPATH=src python bench/grading.py            # 2000 answers, CI-sized
    PYTHONPATH=src python bench/grading.py --size 10000 --naive 60
    PYTHONPATH=src python bench/grading.py --collect     # only `pytest --collect-only`

The naive baseline is `sympy.simplify(parse_expr(a) - parse_expr(b)) == 0` on the
bench's own generated strings (never a student's), timed on a subsample.
"""

from __future__ import annotations

import argparse
import json
import os
import random
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "src"))

from dynagrade.grading.compare import compare_lines, compare_record  # noqa: E402

PROJ = {"v0": {"min": 1, "max": 50, "unit": "m/s"}, "alpha": {"min": 0.1, "max": 1.4, "unit": "rad"},
        "g": {"min": 9, "max": 10, "unit": "m/s^2"}}
OSC = {"k": {"min": 1, "max": 100, "unit": "N/m"}, "m": {"min": 0.1, "max": 10, "unit": "kg"}}
KIN = {"m": {"min": 0.1, "max": 10, "unit": "kg"}, "v": {"min": 1, "max": 10, "unit": "m/s"},
       "g": {"min": 9, "max": 10, "unit": "m/s^2"}, "h": {"min": 0.1, "max": 10, "unit": "m"}}

# (variables, reference, answers in our syntax, the same answers in sympy's Python syntax)
SYMBOLIC = [
    (PROJ, "v0^2*sin(2*alpha)/g", [
        ("2 v0^2 sin(alpha) cos(alpha)/g", "2*v0**2*sin(alpha)*cos(alpha)/g"),
        ("v0² sin(2α)/g", "v0**2*sin(2*alpha)/g"),
        ("v0^2*sin(alpha)/g", "v0**2*sin(alpha)/g"),
        ("v0^2*cos(2*alpha)/g", "v0**2*cos(2*alpha)/g"),
        ("v0^2*sin(2*alpha)/g*1.001", "v0**2*sin(2*alpha)/g*1.001"),
        ("(v0^2/g)*sin(2*alpha)", "(v0**2/g)*sin(2*alpha)"),
    ]),
    (PROJ, "v0*sin(alpha)/g", [
        ("v0 sin(alpha)/g", "v0*sin(alpha)/g"),
        ("2 v0 sin(alpha)/g", "2*v0*sin(alpha)/g"),
        ("v0*cos(alpha)/g", "v0*cos(alpha)/g"),
        ("v0*sin(alpha)*g^-1", "v0*sin(alpha)*g**-1"),
    ]),
    (OSC, "sqrt(k/m)", [
        ("sqrt(k)/sqrt(m)", "sqrt(k)/sqrt(m)"),
        ("(k/m)^0.5", "(k/m)**0.5"),
        ("2*pi*sqrt(k/m)", "2*pi*sqrt(k/m)"),
        ("sqrt(m/k)", "sqrt(m/k)"),
    ]),
    (KIN, "m*v^2/2 + m*g*h", [
        ("0.5 m v^2 + m g h", "0.5*m*v**2 + m*g*h"),
        ("m (v^2/2 + g h)", "m*(v**2/2 + g*h)"),
        ("m v^2 + m g h", "m*v**2 + m*g*h"),
        ("mv^2/2 + mgh", "m*v**2/2 + m*g*h"),
    ]),
]

NUMERIC_UNITS = [("m/s", [("{v}", 1), ("{k} km/h", 3.6), ("{c} cm/s", 100)]),
                 ("N", [("{v}", 1), ("{k} mN", 1000), ("{v} kg*m/s^2", 1)]),
                 ("rad", [("{v}", 1), ("{d} deg", 180 / 3.141592653589793)]),
                 ("m", [("{v}", 1), ("{k} mm", 1000)])]


def synthetic_class(size: int, seed: int = 7) -> list[dict]:
    """A mixed class: about 40 % plain numbers, 30 % numbers with units, 30 % formulas."""
    rng = random.Random(seed)
    records = []
    for i in range(size):
        roll = rng.random()
        if roll < 0.4:
            e = rng.uniform(-100, 100)
            answer = rng.choice([f"{e:.4g}", f"{e * 1.05:.4g}", f"{-e:.3g}", f"{e:.2e}", "abc", f"{e:.5g}".replace(".", ",")])
            records.append({"id": f"n{i}", "kind": "numeric", "expected": e, "answer": answer})
        elif roll < 0.7:
            unit, forms = rng.choice(NUMERIC_UNITS)
            e = rng.uniform(0.1, 50)
            form, factor = rng.choice(forms)
            wrong = rng.random() < 0.3
            value = e * factor * (1.07 if wrong else 1.0)
            answer = form.format(v=f"{value:.4g}", k=f"{value:.4g}", c=f"{value:.4g}", d=f"{value:.4g}")
            records.append({"id": f"u{i}", "kind": "numeric", "expected": e, "unit": unit, "answer": answer})
        else:
            variables, reference, answers = rng.choice(SYMBOLIC)
            answer = rng.choice(answers)[0]
            records.append({"id": f"s{i}", "kind": "symbolic", "expected": reference,
                            "variables": variables, "answer": answer})
    return records


def percentile(values: list[float], q: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(round(q * (len(ordered) - 1))))]


def run_fixtures() -> None:
    sys.path.insert(0, str(ROOT / "tests"))
    from test_grading_fixtures import FIXTURES, _record

    records = [_record(json.loads(line)) for line in FIXTURES.read_text(encoding="utf-8").splitlines() if line.strip()]
    start = time.perf_counter()
    outputs = list(compare_lines(json.dumps(r) for r in records))
    elapsed = time.perf_counter() - start
    print(f"fixtures: {len(outputs)} cases in {elapsed * 1000:.0f} ms ({len(outputs) / elapsed:,.0f} answers/s)")


def run_class(size: int) -> list[float]:
    records = synthetic_class(size)
    lines = [json.dumps(r) for r in records]
    start = time.perf_counter()
    outputs = list(compare_lines(lines))
    elapsed = time.perf_counter() - start
    assert len(outputs) == size
    print(f"class: {size} answers in {elapsed:.2f} s = {size / elapsed:,.0f} answers/s")
    symbolic_times = []
    for record in records:
        if record["kind"] == "symbolic":
            t0 = time.perf_counter()
            compare_record(record)
            symbolic_times.append(time.perf_counter() - t0)
    print(f"symbolic verdicts: n={len(symbolic_times)}, median {statistics.median(symbolic_times) * 1e3:.3f} ms, "
          f"p99 {percentile(symbolic_times, 0.99) * 1e3:.3f} ms, max {max(symbolic_times) * 1e3:.1f} ms")
    return symbolic_times


def fuzzing_corpus(seed: int = 11) -> list[tuple[object, object, str]]:
    """(spec, reference, answer) triples: the hostile answers of the parser tests and
    generated unit powers, unit-only answers, extreme exponents and long flat sums,
    each against every kind of part."""
    sys.path.insert(0, str(ROOT / "tests"))
    from test_grading_parser import HOSTILE, SPECS

    rng = random.Random(seed)
    units = ["m", "km", "deg", "rad", "rev", "lbf", "rpm", "blargs", "Hz", "ft", "bar"]
    generated = []
    for _ in range(150):
        unit, other = rng.choice(units), rng.choice(units)
        generated += [f"{rng.uniform(0, 1e3):.4g} {unit}^{rng.randint(-400, 400)}",
                      f"{unit}^{other}", f"{unit} {other}^-{rng.randint(1, 9)}",
                      f"{rng.uniform(0, 10):.3g}e{rng.choice('-−+')}{rng.randint(0, 5000)}",
                      "+".join(["x"] * rng.randint(100, 450)),
                      f"1-cos(x)+x^{rng.randint(-50, 50)}"]
    return [(spec, expected, answer) for answer in HOSTILE + generated for spec, expected in SPECS]


def run_fuzzing() -> None:
    """Slowest verdict of the fuzzing corpus in a fresh process after ``prepare()``:
    on the first pass (``ever``: caches empty) and on a second pass (``warm``)."""
    code = ("import sys, time, json\n"
            f"sys.path.insert(0, {str(ROOT / 'bench')!r})\n"
            "from grading import fuzzing_corpus\n"
            "from dynagrade.grading import grade, prepare\n"
            "corpus = fuzzing_corpus()\n"
            "def slowest():\n"
            "    worst = (0.0, '')\n"
            "    for spec, expected, answer in corpus:\n"
            "        t0 = time.perf_counter(); grade(spec, expected, answer)\n"
            "        worst = max(worst, (time.perf_counter() - t0, answer[:30]))\n"
            "    return worst\n"
            "prepare(); ever = slowest(); warm = slowest()\n"
            "print(json.dumps([len(corpus), ever, warm]))\n")
    env = dict(os.environ, PYTHONPATH=str(ROOT / "src"))
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env)
    if done.returncode != 0:
        print(f"fuzzing corpus: failed ({(done.stderr.strip().splitlines() or ['no output'])[-1]})")
        return
    count, (ever, ever_answer), (warm, warm_answer) = json.loads(done.stdout)
    print(f"fuzzing corpus: {count} verdicts; slowest warm {warm * 1e3:.0f} ms ({warm_answer!r}), "
          f"slowest ever {ever * 1e3:.0f} ms ({ever_answer!r}); targets 200 ms warm, 1000 ms ever")


def run_naive(count: int, ours: list[float]) -> None:
    import sympy
    from sympy.parsing.sympy_parser import parse_expr, standard_transformations

    pairs = [(ref.replace("^", "**"), py) for _, ref, answers in SYMBOLIC for _, py in answers]
    rng = random.Random(3)
    sample = [rng.choice(pairs) for _ in range(count)]
    times = []
    for reference, answer in sample:
        t0 = time.perf_counter()
        # The bench's own strings, never a student's: the naive approach in question.
        sympy.simplify(parse_expr(answer, transformations=standard_transformations)
                       - parse_expr(reference, transformations=standard_transformations)) == 0
        times.append(time.perf_counter() - t0)
    naive = statistics.median(times)
    mine = statistics.median(ours)
    print(f"naive sympy.simplify baseline: n={count}, median {naive * 1e3:.1f} ms, "
          f"p99 {percentile(times, 0.99) * 1e3:.1f} ms -> ours is {naive / mine:,.0f}x faster (median)")


def bytecode_cases(folder: Path) -> list[tuple[str, dict]]:
    """The two ways a command starts cold, as (name, environment): with dynagrade's
    bytecode cached (src/ as it is, PYTHONDONTWRITEBYTECODE unset, so the untimed first
    run writes what is missing) and compiled from source (a copy of src/ without
    __pycache__ in ``folder``, run with PYTHONDONTWRITEBYTECODE set, as a fresh clone
    starts under that setting; the installed libraries keep their bytecode in both)."""
    copy = folder / "from-source"
    shutil.copytree(ROOT / "src", copy / "src",
                    ignore=shutil.ignore_patterns("__pycache__", "*.egg-info"))
    (copy / "exercises").symlink_to(ROOT / "exercises")  # the bank beside src/, as here
    cached = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    return [("bytecode cached", dict(cached, PYTHONPATH=str(ROOT / "src"))),
            ("compiled from source", dict(os.environ, PYTHONPATH=str(copy / "src"),
                                          PYTHONDONTWRITEBYTECODE="1"))]


def run_cold(cases: list[tuple[str, dict]]) -> None:
    env = dict(os.environ, PYTHONPATH=str(ROOT / "src"))
    out = subprocess.run([sys.executable, "-X", "importtime", "-c", "import dynagrade.grading"],
                         capture_output=True, text=True, env=env)
    lines = [l for l in out.stderr.splitlines() if l.rstrip().endswith("dynagrade.grading")]
    if lines:
        cumulative = int(lines[-1].split("|")[1])
        print(f"import dynagrade.grading: {cumulative / 1000:.0f} ms cumulative (python -X importtime)")
    with tempfile.TemporaryDirectory() as folder:
        sheet = Path(folder) / "x.py"
        made = subprocess.run([sys.executable, "-m", "dynagrade.cli", "sheet", "projectile-range",
                               "--student", "s1", "-o", str(sheet)], capture_output=True, text=True, env=env)
        if made.returncode != 0 or not sheet.exists():
            print("cold `grade FILE`: skipped (could not make a sheet: "
                  f"{(made.stderr or made.stdout).strip().splitlines()[-1:] or 'no output'})")
            return
        lines = sheet.read_text(encoding="utf-8").splitlines()
        for k, line in enumerate(lines):
            if line.endswith(" = None") and line.split(" = ")[0].isidentifier():
                comment = lines[k - 1] if k else ""
                value = '"v0^2*sin(2*alpha)/g"' if "formula" in comment else '"12.5"'
                lines[k] = line.replace("None", value)
        sheet.write_text("\n".join(lines) + "\n", encoding="utf-8")
        command = [sys.executable, "-c", "import sys; from dynagrade.cli import grade_main; grade_main()", str(sheet)]
        for case, case_env in cases:
            print(f"cold `grade FILE` (answered sheet, {case}" + cold_runs(command, case_env)
                  + "; target 0.25 s")


def cold_runs(command: list[str], env: dict, runs: int = 5) -> str:
    """``command`` run ``runs`` times in fresh processes, after one untimed run: ", status):
    the median wall time (and the fastest) and the median CPU time (user + system of the
    process)"."""
    fresh_process_times(command, env, 1)
    walls, cpus, code = fresh_process_times(command, env, runs)
    status = "ok" if code == 0 else f"exit {code}"
    return (f", {status}): median of {runs} {statistics.median(walls):.2f} s "
            f"(min {min(walls):.2f} s), CPU {statistics.median(cpus):.2f} s")


def fresh_process_times(command: list[str], env: dict, runs: int) -> tuple[list[float], list[float], int]:
    """Wall and CPU (user + system) seconds of ``runs`` runs of ``command`` in fresh
    processes, and the last exit status. On a loaded machine CPU time is the steadier."""
    walls, cpus = [], []
    for _ in range(runs):
        t0 = time.perf_counter()
        process = subprocess.Popen(command, cwd=ROOT, env=env, stdout=subprocess.DEVNULL,
                                   stderr=subprocess.DEVNULL)
        _, status, usage = os.wait4(process.pid, 0)
        walls.append(time.perf_counter() - t0)
        cpus.append(usage.ru_utime + usage.ru_stime)
    return walls, cpus, os.waitstatus_to_exitcode(status)


def run_cold_list(cases: list[tuple[str, dict]], runs: int = 5) -> None:
    """The time of `dynagrade list` in fresh processes: the median of ``runs``."""
    command = [sys.executable, "-m", "dynagrade.cli", "list"]
    for case, env in cases:
        print(f"cold `dynagrade list` ({case}" + cold_runs(command, env, runs)
              + "; target 0.5 s")


def run_collect(runs: int = 3) -> None:
    """Collecting the test suite (`pytest --collect-only`, target 1.5 s), median of ``runs``,
    in the two cases a developer meets. Cached: the project's bytecode and pytest's
    rewritten asserts are in __pycache__ (one run writes them first). Nothing cached, as
    in a fresh clone or with PYTHONDONTWRITEBYTECODE set and no __pycache__: pytest
    rewrites every test module's asserts and Python compiles every module anew; this case
    runs on a copy of the project without its __pycache__ folders, with
    PYTHONDONTWRITEBYTECODE set, so that this checkout's caches stay as they are."""
    import shutil

    pytest_collect = [sys.executable, "-m", "pytest", "--collect-only", "-q", "-p", "no:cacheprovider"]
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    fresh_process_times(pytest_collect, dict(env, PYTHONPATH=str(ROOT / "src")), 1)
    cases = [("rewritten asserts cached", pytest_collect, dict(env, PYTHONPATH=str(ROOT / "src")))]
    with tempfile.TemporaryDirectory(prefix="dynagrade-collect-") as scratch:
        copy = Path(scratch) / "project"
        caches = shutil.ignore_patterns("__pycache__", ".git", ".hypothesis", ".pytest_cache",
                                        ".venv", "*.egg-info")
        shutil.copytree(ROOT, copy, ignore=lambda folder, names: caches(folder, names) | (
            {"out"} & set(names) if Path(folder) == ROOT else set()))  # examples/run.sh's output
        in_copy = ["--rootdir", str(copy), "-c", str(copy / "pyproject.toml"), str(copy / "tests")]
        cases.append(("nothing cached", pytest_collect + in_copy,
                      dict(env, PYTHONPATH=str(copy / "src"), PYTHONDONTWRITEBYTECODE="1")))
        for case, command, case_env in cases:
            walls, cpus, code = fresh_process_times(command, case_env, runs)
            status = "ok" if code == 0 else f"exit {code}"
            print(f"pytest --collect-only ({status}, {case}): {statistics.median(walls):.2f} s wall, "
                  f"{statistics.median(cpus):.2f} s CPU (median of {runs})")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, default=2000, help="answers in the synthetic class")
    parser.add_argument("--naive", type=int, default=30, help="symbolic cases for the naive baseline")
    parser.add_argument("--no-cold", action="store_true", help="skip the cold-process timings")
    parser.add_argument("--collect", action="store_true", help="only time collecting the test suite")
    args = parser.parse_args()
    if args.collect:
        run_collect()
        return
    run_fixtures()
    ours = run_class(args.size)
    run_naive(args.naive, ours)
    run_fuzzing()
    if not args.no_cold:
        with tempfile.TemporaryDirectory() as folder:
            cases = bytecode_cases(Path(folder))
            run_cold(cases)
            run_cold_list(cases)
        run_collect()


if __name__ == "__main__":
    main()
