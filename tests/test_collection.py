"""Collecting the suite imports none of the heavy libraries: the tests that need sympy,
scipy, matplotlib, mpmath or SQLAlchemy import them when they run (tests/deferred.py),
so that `pytest --collect-only` and `pytest -k one_test` do not pay for them; nor does
it import what only some commands use (typst for PDFs, pint's units, rich's terminal
output, the web server's framework)."""

import json
import subprocess
import sys
from pathlib import Path

import pytest

TESTS = Path(__file__).resolve().parent
HEAVY = ("sympy", "scipy", "matplotlib", "mpmath", "sqlalchemy", "alembic", "typst", "pint",
         "rich", "fastapi", "starlette", "httpx")

COLLECT_AND_LIST_MODULES = """
import json, sys, pytest
code = pytest.main(["--collect-only", "-q", "-p", "no:cacheprovider", sys.argv[1]])
print(json.dumps({"exit": int(code), "modules": sorted(sys.modules)}))
"""


@pytest.mark.slow
def test_collecting_the_suite_imports_no_heavy_library():
    done = subprocess.run([sys.executable, "-c", COLLECT_AND_LIST_MODULES, str(TESTS)],
                          capture_output=True, text=True, cwd=TESTS.parent, timeout=300)
    report = json.loads(done.stdout.strip().splitlines()[-1])
    assert report["exit"] == 0, done.stdout[-2000:]
    imported = {name.partition(".")[0] for name in report["modules"]}
    assert sorted(imported.intersection(HEAVY)) == []
