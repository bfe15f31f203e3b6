"""Answer keys for hand checking: key.csv and key.pdf show each variant's given values
(the parameters its statement prints, with their units) next to its answers."""

from __future__ import annotations

import csv
import io
import json
import shutil
import subprocess

import pytest

from dynagrade.generation.generate import generate_exam

EXAM = """\
id = "key-exam"
title = "Keys"
date = 2025-04-14

[[exercise]]
id = "projectile-range"
points = 6

[[exercise]]
id = "car-in-a-looping"
points = 8
"""


@pytest.fixture(scope="module")
def exam(tmp_path_factory, bank):
    folder = tmp_path_factory.mktemp("keys")
    (folder / "exam.toml").write_text(EXAM, encoding="utf-8")
    (folder / "roster.csv").write_text("student_id,name\nk1,Emmy Noether\nk2,Leonhard Euler\n",
                                       encoding="utf-8")
    generate_exam(folder / "exam.toml", folder / "roster.csv", folder / "out", bank=bank,
                  jobs=1, pdf=shutil.which("pdftotext") is not None)
    manifest = json.loads((folder / "out" / "manifest.json").read_text(encoding="utf-8"))
    return {"out": folder / "out", "manifest": manifest}


def expected_given(exercise_id: str, params: dict) -> str:
    """The given values written out by hand from the exercises' parameters: projectile-range
    prints v0 (m/s), alpha (deg) and g (m/s²); car-in-a-looping m (kg), R (m), v0 (m/s),
    phi (deg) and g (m/s²)."""
    units = {"projectile-range": [("v0", " m/s"), ("alpha", "°"), ("g", " m/s²")],
             "car-in-a-looping": [("m", " kg"), ("R", " m"), ("v0", " m/s"), ("phi", "°"),
                                  ("g", " m/s²")]}[exercise_id]
    return "; ".join(f"{name} = {params[name]:g}{unit}" for name, unit in units)


def test_key_csv_gives_every_variants_given_values_beside_its_answers(exam):
    rows = list(csv.DictReader(io.StringIO((exam["out"] / "key.csv").read_text(
        encoding="utf-8"))))
    assert list(rows[0]) == ["student_id", "name", "exercise_id", "seed", "given", "part",
                             "answer", "unit", "points"]
    variants = {(s["student_id"], v["exercise"]): v for s in exam["manifest"]["students"]
                for v in s["variants"]}
    assert len(rows) == 2 * (4 + 6)
    for row in rows:
        variant = variants[(row["student_id"], row["exercise_id"])]
        assert row["given"] == expected_given(row["exercise_id"], variant["params"])
        assert int(row["seed"]) == variant["seed"]


@pytest.mark.skipif(shutil.which("pdftotext") is None,
                    reason="pdftotext missing: install the apt package poppler-utils")
def test_key_pdf_shows_the_given_values_of_every_variant(exam):
    text = subprocess.run(["pdftotext", str(exam["out"] / "key.pdf"), "-"], check=True,
                          capture_output=True, text=True, timeout=60).stdout
    flat = " ".join(text.split())
    for student in exam["manifest"]["students"]:
        for variant in student["variants"]:
            for given in expected_given(variant["exercise"], variant["params"]).split("; "):
                assert given in flat, (student["student_id"], given)
