#!/bin/sh
# Generate the example exam, write sample submissions, grade them.
#   sh examples/run.sh            (from the repository root; writes out/)
set -e
cd "$(dirname "$0")/.."
export PYTHONPATH="src${PYTHONPATH:+:$PYTHONPATH}"
python -m dynagrade.cli exam examples/exam.toml --roster examples/roster.csv -o out/
python examples/make_submissions.py out/
python -m dynagrade.cli grade --manifest out/manifest.json out/submissions/ -o out/grading/
