"""Type checking that counts: mypy (configured in pyproject.toml, ``[tool.mypy]``) finds
no error in the packages of ``CLEAN``, and no more errors in those of ``RATCHET`` than
the number written beside each, which may only go down (docs/design.md, "Type checking").

A package that is not clean yet joins ``RATCHET`` with its count (``mypy
src/dynagrade/<package>`` gives it), and ``CLEAN`` once the count is 0; mechanics/ is
at 0 already, render/ (most of its errors in moodle.py, which reads the manifest's
optional part settings) at 42.

One mypy run checks every listed file (170 of them), with mypy's cache in the
repository's ``.cache/mypy``. Measured on a two-core machine shared with other work (load
1.1 to 1.4), the module's tests take 20 s cold (no cache: 21 s CPU, most of it reading
numpy's, scipy's and matplotlib's stubs) and 0.5 s warm (nothing changed since the last
run); an edit to one module that leaves what it exports alone brings it to about 0.6 s,
one that changes it to a few seconds.
"""
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
PACKAGE = "src/dynagrade"

#: files and folders (relative to src/dynagrade) with no mypy error at all
CLEAN = ("grading", "config.py", "errors.py", "exercise", "exam", "generation", "classgrade",
         "runs", "serve", "cli.py", "i18n.py")

#: files and folders (relative to src/dynagrade) and the most errors each may have
RATCHET = {"mechanics": 0, "render": 42}

ERROR = re.compile(r"^(?P<path>[^:\n]+\.py):\d+: error: ", re.MULTILINE)
CHECKED = re.compile(r"^(?:Success: no issues found in |Found \d+ errors? in \d+ files? \(checked )"
                     r"(?P<n>\d+) source files?", re.MULTILINE)


def _python_files(target: str) -> list[str]:
    path = ROOT / PACKAGE / target
    files = [path] if path.is_file() else sorted(path.rglob("*.py"))
    return [f.relative_to(ROOT).as_posix() for f in files]


def _owner(path: str) -> str | None:
    """The target of CLEAN or RATCHET a reported file belongs to."""
    for target in (*CLEAN, *RATCHET):
        prefix = f"{PACKAGE}/{target}"
        if path == prefix or path.startswith(prefix + "/"):
            return target
    return None


@pytest.fixture(scope="module")
def mypy_report() -> tuple[dict[str, list[str]], int]:
    """mypy's errors by target, and the number of source files it says it checked."""
    targets = [f"{PACKAGE}/{t}" for t in (*CLEAN, *RATCHET)]
    # A module imported from outside the targets is analysed for its types but its own
    # errors are not reported: each package answers for its own files only.
    done = subprocess.run(
        [sys.executable, "-m", "mypy", "--cache-dir", str(ROOT / ".cache" / "mypy"),
         "--follow-imports=silent", "--no-pretty", "--no-color-output", *targets],
        cwd=ROOT, capture_output=True, text=True, timeout=600)
    assert done.returncode in (0, 1), f"mypy did not run:\n{done.stdout[-3000:]}{done.stderr[-3000:]}"
    summary = CHECKED.search(done.stdout)
    assert summary, f"no summary line in mypy's output:\n{done.stdout[-3000:]}"
    errors: dict[str, list[str]] = {t: [] for t in (*CLEAN, *RATCHET)}
    for match in ERROR.finditer(done.stdout):
        owner = _owner(match["path"])
        assert owner is not None, f"an error outside the checked files: {match.group()}"
        line_end = done.stdout.find("\n", match.start())
        errors[owner].append(done.stdout[match.start():line_end if line_end >= 0 else None])
    return errors, int(summary["n"])


@pytest.mark.slow
def test_mypy_checked_every_file_of_the_listed_packages(mypy_report):
    _, checked = mypy_report
    expected = sum(len(_python_files(t)) for t in (*CLEAN, *RATCHET))
    assert expected > 0
    assert checked == expected


@pytest.mark.slow
@pytest.mark.parametrize("target", CLEAN)
def test_a_clean_package_has_no_type_error(mypy_report, target):
    errors, _ = mypy_report
    assert errors[target] == [], "\n".join(errors[target])


@pytest.mark.slow
@pytest.mark.parametrize("target", sorted(RATCHET))
def test_a_ratcheted_package_has_no_more_type_errors_than_its_limit(mypy_report, target):
    errors, _ = mypy_report
    found = errors[target]
    assert len(found) <= RATCHET[target], (
        f"{len(found)} mypy errors in {PACKAGE}/{target}, at most {RATCHET[target]} allowed:\n"
        + "\n".join(found))
