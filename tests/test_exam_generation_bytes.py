"""Making exam generation faster must not change one byte of what it writes.

A small exam (the exam tests' three exercises for 6 students, with figures, PDFs and
worked solutions) is generated along two routes, one process (``jobs=1``) and two
workers (``jobs=2``), each in a fresh process, and every file's SHA-256 is compared with
``tests/fixtures/exam_bytes.json``. That list was written by the generation code as it
was BEFORE issue 28's speed work (commit 85b9dbd, checked out apart), with::

    PYTHONPATH=<checkout of 85b9dbd>/src python tests/test_exam_generation_bytes.py --write

so it is a third route that does not share the code under test: it is never to be
regenerated to make this test pass, only when an output is meant to change (and then the
commit says why). It was written again, the same way, by the code of 5f950a7 (the merge
that brought this test to main) when that merge's exercises had changed the manifest's
file hashes and the worked solutions (projectile-range's checks and closing sanity line),
and again for the manifest alone when issue 31 added constraints to sliding-up-a-slope and
car-in-a-looping (their files' hashes; every other file kept its bytes). PDFs and the manifest hold the versions of typst and numpy, so the list
records those; with other versions installed the comparison with the list is skipped
(the two routes are still compared with each other).
"""

from __future__ import annotations

import hashlib
import json
import os
import subprocess
import sys
from importlib.metadata import version
from pathlib import Path

import pytest

from conftest import EXAM_TOML
from dynagrade.exercise.loader import open_bank
from dynagrade.generation.generate import generate_exam

ROOT = Path(__file__).resolve().parent.parent
HASHES = ROOT / "tests" / "fixtures" / "exam_bytes.json"
SECRET = "fedcba9876543210" * 4
#: six students; one name needs escaping in Markdown, HTML and typst
ROSTER = ("student_id,name\n" + "s-001,Emmy Noether\ns-002,Leonhard Euler\n"
          "s-003,Sophie Germain\ns-004,\"Ada <Lovelace> & *Byron*\"\ns-005,Émilie du Châtelet\n"
          "s-006,Joseph-Louis Lagrange\n")


def environment() -> dict[str, str]:
    """The versions that the bytes of PDFs and the manifest depend on."""
    return {name: version(name) for name in ("typst", "numpy")}


def generate(folder: Path, jobs: int) -> dict[str, str]:
    """The SHA-256 of every file of the exam generated in ``folder`` with ``jobs``."""
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "exam.toml").write_text(EXAM_TOML, encoding="utf-8")
    (folder / "roster.csv").write_text(ROSTER, encoding="utf-8")
    out = folder / "out"
    generate_exam(folder / "exam.toml", folder / "roster.csv", out, bank=open_bank(),
                  jobs=jobs, secret=SECRET, solutions=True)
    return {str(path.relative_to(out)): hashlib.sha256(path.read_bytes()).hexdigest()
            for path in sorted(out.rglob("*")) if path.is_file()}


def generate_elsewhere(folder: Path, jobs: int) -> dict[str, str]:
    """:func:`generate` in a fresh process: worker processes are forked, and a fork of a
    process whose typst already started threads can hang."""
    done = subprocess.run([sys.executable, __file__, "--hashes", str(folder), str(jobs)],
                          capture_output=True, text=True, check=True,
                          env={**os.environ, "PYTHONPATH": str(ROOT / "src")})
    return json.loads(done.stdout)


@pytest.fixture(scope="module")
def routes(tmp_path_factory) -> dict[int, dict[str, str]]:
    folder = tmp_path_factory.mktemp("bytes")
    return {jobs: generate_elsewhere(folder / f"jobs-{jobs}", jobs) for jobs in (1, 2)}


def test_one_process_and_two_workers_write_the_same_bytes(routes):
    assert len(routes[1]) == 6 * 12 + 6  # per student: 3 x (.py, .svg), sheet x3, solution x3
    assert routes[1] == routes[2]


def test_every_file_has_the_bytes_the_code_before_the_speed_work_wrote(routes):
    recorded = json.loads(HASHES.read_text(encoding="utf-8"))
    if recorded["environment"] != environment():
        pytest.skip(f"the list was written with {recorded['environment']}, "
                    f"this is {environment()}")
    assert sorted(routes[2]) == sorted(recorded["files"])
    changed = [name for name, digest in recorded["files"].items() if routes[2][name] != digest]
    assert changed == []


if __name__ == "__main__" and sys.argv[1:2] == ["--hashes"]:  # one route, for the test
    print(json.dumps(generate(Path(sys.argv[2]), int(sys.argv[3]))))
elif __name__ == "__main__" and sys.argv[1:] == ["--write"]:
    import tempfile

    with tempfile.TemporaryDirectory() as temporary:
        files = generate(Path(temporary), jobs=1)
    HASHES.write_text(json.dumps({"environment": environment(), "files": files}, indent=1,
                                 sort_keys=True) + "\n", encoding="utf-8")
    print(f"wrote {len(files)} hashes to {HASHES}")
