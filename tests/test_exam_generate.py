"""Generating an exam: reproducible files, PDFs holding each student's numbers, a valid
Moodle export with the right tolerances, and variants that cannot discriminate replaced."""

from __future__ import annotations

import base64
import hashlib
import json
import math
import os
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from dynagrade.generation.generate import generate_exam
from dynagrade.exam.manifest import VariantEntry
from dynagrade.exercise.loader import open_bank
from dynagrade.exercise.numbers import format_number
from dynagrade.exercise.seeds import exam_seed, variant_token
from dynagrade.render.figures import figure_svg
from dynagrade.render.moodle import variant_idnumber
from moodle_reader import read_fields

ROOT = Path(__file__).resolve().parent.parent
SECRET = "0123456789abcdef" * 4  # fixed, so that two runs can be compared
ROSTER = "student_id,name\nq-001,Emmy Noether\nq-002,Leonhard Euler\nq-003,Sophie Germain\n"


@pytest.fixture(scope="module")
def exam(tmp_path_factory, bank, exam_toml):
    folder = tmp_path_factory.mktemp("exam")
    roster = folder / "roster.csv"
    roster.write_text(ROSTER, encoding="utf-8")
    exam = folder / "exam.toml"
    exam.write_text(exam_toml, encoding="utf-8")
    out = folder / "out"
    secret_file = folder / "exam.secret"
    secret_file.write_text(SECRET + "\n", encoding="ascii")
    generate_exam(exam, roster, out, bank=bank, jobs=1, secret=SECRET)
    manifest = json.loads((out / "manifest.json").read_text(encoding="utf-8"))
    return {"folder": folder, "roster": roster, "exam": exam, "out": out, "manifest": manifest,
            "secret_file": secret_file}


def _files(folder: Path) -> dict[str, bytes]:
    return {str(p.relative_to(folder)): p.read_bytes()
            for p in sorted(folder.rglob("*")) if p.is_file()}


def test_a_second_run_writes_byte_identical_files(exam):
    """Run again in a fresh process with two workers and the same secret: every file, PDFs
    included, matches."""
    second = exam["folder"] / "again"
    environment = {**os.environ, "PYTHONPATH": str(ROOT / "src")}
    subprocess.run([sys.executable, "-m", "dynagrade.cli", "exam", str(exam["exam"]), "--roster",
                    str(exam["roster"]), "-o", str(second), "--jobs", "2",
                    "--secret-file", str(exam["secret_file"])],
                   check=True, capture_output=True, env=environment, timeout=120)
    first, again = _files(exam["out"]), _files(second)
    assert sorted(first) == sorted(again)
    different = [name for name in first if first[name] != again[name]]
    assert different == []
    assert "manifest.json" in first and "sheets.pdf" in first


def test_the_manifest_stores_each_students_seed_parameters_and_answers(exam, bank):
    manifest = exam["manifest"]
    spec_points = {"projectile-range": 6, "sliding-up-a-slope": 6, "car-in-a-looping": 8}
    for described in manifest["exercises"]:
        exercise = bank.get(described["id"])
        assert described["sha256"] == hashlib.sha256(Path(exercise.path).read_bytes()).hexdigest()
        assert math.isclose(sum(p["points"] for p in described["parts"]),
                            spec_points[exercise.id], rel_tol=1e-9)
    for student in manifest["students"]:
        for entry in student["variants"]:
            exercise = bank.get(entry["exercise"])
            if not entry["redraws"]:
                assert entry["seed"] == exam_seed(SECRET, manifest["exam"]["id"],
                                                  student["student_id"], exercise.id)
            rebuilt = exercise.variant_from_params(entry["seed"], entry["params"])
            for name, value in rebuilt.answers.items():
                stored = entry["answers"][name]
                if isinstance(value, float):
                    assert stored == value
                else:
                    assert stored == (list(value) if isinstance(value, tuple) else value)
    looping = [v for s in manifest["students"] for v in s["variants"]
               if v["exercise"] == "car-in-a-looping"]
    assert all(v["params"]["g"] == 9.81 for v in looping)


def test_every_student_gets_sheets_fill_in_files_and_figures(exam, bank):
    out = exam["out"]
    for student in exam["manifest"]["students"]:
        folder = out / "students" / student["student_id"]
        for name in ("sheet.pdf", "sheet.html", "sheet.md"):
            assert (folder / name).stat().st_size > 0
        markdown = (folder / "sheet.md").read_text(encoding="utf-8")
        html = (folder / "sheet.html").read_text(encoding="utf-8")
        for entry in student["variants"]:
            fill_in = (folder / f"{entry['exercise']}.py").read_text(encoding="utf-8")
            # an exam's fill-in file carries the variant's token, never its seed or secret
            token = variant_token(SECRET, exam["manifest"]["exam"]["id"],
                                  student["student_id"], entry["exercise"], entry["seed"])
            assert f"VARIANT = {token!r}" in fill_in and "SEED" not in fill_in
            assert str(entry["seed"]) not in fill_in and SECRET not in fill_in
            assert f"STUDENT = {student['student_id']!r}" in fill_in
            # the figure is beside the fill-in file, named in its header and linked
            # from the sheet: the same drawing the exam's sheets show
            figure = f"{entry['exercise']}.svg"
            assert f"]({figure})" in markdown
            assert f"Figure: {figure}, in the folder of this file." in fill_in
            svg = (folder / figure).read_text(encoding="utf-8")
            assert svg.lstrip().startswith("<?xml") and "<svg" in svg
            exercise = bank.get(entry["exercise"])
            assert svg == figure_svg(exercise, exercise.variant_from_params(
                entry["seed"], entry["params"]))
        assert html.count("<svg") == 3 and "<math" in html
        assert "<script" not in html and "http://cdn" not in html and "https://" not in html


def _pdf_text(path: Path) -> str:
    return subprocess.run(["pdftotext", "-layout", str(path), "-"], check=True,
                          capture_output=True, text=True, timeout=60).stdout


@pytest.mark.skipif(shutil.which("pdftotext") is None,
                    reason="pdftotext missing: install the apt package poppler-utils")
def test_every_pdf_opens_and_shows_the_students_own_numbers(exam, bank):
    out = exam["out"]
    combined = _pdf_text(out / "sheets.pdf")
    key = _pdf_text(out / "key.pdf")
    for student in exam["manifest"]["students"]:
        text = _pdf_text(out / "students" / student["student_id"] / "sheet.pdf")
        assert student["name"] in text and student["name"] in combined
        for entry in student["variants"]:
            exercise = bank.get(entry["exercise"])
            for parameter in exercise.params:
                shown = format_number(entry["params"][parameter.name])
                assert re.search(rf"(?<![\d.]){re.escape(shown)}(?![\d])", text), \
                    (student["student_id"], parameter.name, shown)
            first_numeric = next(p for p in exercise.parts if p.kind == "numeric")
            assert format_number(entry["answers"][first_numeric.name]) in key
    assert combined.count("Exercise 1:") == len(exam["manifest"]["students"])


def _page_texts(pdf: Path) -> list[str]:
    from dynagrade.render.pdf import page_count

    return [subprocess.run(["pdftotext", "-layout", "-f", str(n), "-l", str(n), str(pdf), "-"],
                           check=True, capture_output=True, text=True, timeout=60).stdout
            for n in range(1, page_count(pdf.read_bytes()) + 1)]


def _header(page: str) -> str:
    return " ".join(page.strip().splitlines()[0].split())


@pytest.mark.skipif(shutil.which("pdftotext") is None,
                    reason="pdftotext missing: install the apt package poppler-utils")
def test_every_page_of_a_sheet_names_its_student_in_the_header_the_first_too(exam):
    title = exam["manifest"]["exam"]["title"]
    for student in exam["manifest"]["students"]:
        pages = _page_texts(exam["out"] / "students" / student["student_id"] / "sheet.pdf")
        assert len(pages) >= 2
        for page in pages:
            assert _header(page) == f"{title} {student['name']} ({student['student_id']})"


@pytest.mark.skipif(shutil.which("pdftotext") is None,
                    reason="pdftotext missing: install the apt package poppler-utils")
def test_sheets_laid_out_in_one_document_name_each_pages_own_student(tmp_path):
    from dynagrade.render.pdf import compile_pdf
    from dynagrade.render.sheets import StudentSheet, sheet_typst_body, typst_preamble

    exam = {"id": "e", "title": "Midterm", "date": "2025-01-01", "instructions": ""}
    owners = [("a-1", "Ada Lovelace"), ("b-2", "Emmy Noether"), ("c-3", "Sophie Germain")]
    bodies = [sheet_typst_body(StudentSheet(exam, sid, name, ())) for sid, name in owners]
    pdf = tmp_path / "all.pdf"
    pdf.write_bytes(compile_pdf(typst_preamble(exam) + "\n#pagebreak(weak: true)\n".join(bodies)))
    assert [_header(page) for page in _page_texts(pdf)] == [
        f"Midterm {name} ({sid})" for sid, name in owners]


def _by_idnumber(manifest: dict) -> dict:
    """Every variant of a manifest under the idnumber the Moodle export gives it."""
    return {variant_idnumber(VariantEntry(v["exercise"], v["seed"], v["params"], {})): v
            for s in manifest["students"] for v in s["variants"]}


def test_the_moodle_export_has_one_question_per_variant_with_its_tolerance(exam, bank):
    tree = ET.parse(exam["out"] / "moodle.xml")
    questions = tree.getroot().findall("question")
    categories = [q for q in questions if q.get("type") == "category"]
    assert [c.findtext("category/text").rsplit("/", 1)[1] for c in categories] == \
        [e["id"] for e in exam["manifest"]["exercises"]]
    variants = _by_idnumber(exam["manifest"])
    graded = [q for q in questions if q.get("type") != "category"]
    assert len(graded) == len(variants)
    for question in graded:
        assert question.findtext("penalty") == "0"
        variant = variants[question.findtext("idnumber")]
        exercise = bank.get(variant["exercise"])
        numeric = [p for p in exercise.parts if p.kind == "numeric"]
        fields = read_fields(question.findtext("questiontext/text"))
        assert question.get("type") == "cloze" and len(fields) == len(numeric)
        for part, found in zip(numeric, fields):
            expected = variant["answers"][part.name]
            right = found.answers[0]
            assert found.kind == "NUMERICAL" and right.fraction == 1.0
            assert math.isclose(right.value, expected, rel_tol=1e-9)  # 10 figures written
            assert math.isclose(right.tolerance, part.rtol * abs(expected), rel_tol=1e-9)


def test_the_moodle_export_embeds_the_figure_each_student_got(exam, bank):
    """Every question of a variant whose exercise draws a figure embeds exactly that
    figure, drawn afresh here from the manifest's parameters (not read from wherever the
    generator keeps its copy), and the count is held against the variants: an export
    that lost its figures (it looked in a folder the figures no longer go to) embeds
    none, and must fail here."""
    root = ET.parse(exam["out"] / "moodle.xml").getroot()
    variants = _by_idnumber(exam["manifest"])
    questions = [q for q in root.findall("question") if q.get("type") != "category"]
    drawing = {idnumber for idnumber, v in variants.items()
               if bank.get(v["exercise"]).figure is not None}
    embedded = 0
    for question in questions:
        variant = variants[question.findtext("idnumber")]
        exercise = bank.get(variant["exercise"])
        files = question.findall("questiontext/file")
        if exercise.figure is None:
            assert files == []
            continue
        assert len(files) == 1, variant["exercise"]
        drawn = figure_svg(exercise, exercise.variant_from_params(variant["seed"],
                                                                  variant["params"]))
        assert base64.b64decode(files[0].text).decode("utf-8") == drawn
        assert f'src="@@PLUGINFILE@@/{files[0].get("name")}"' in \
            question.findtext("questiontext/text")
        embedded += 1
    assert len(drawing) > 0  # the test exam has exercises with figures
    assert embedded == len(drawing)


REDRAW_EXERCISE = '''
"""Squaring a number, whose value 1 cannot tell the square from the number itself."""
from dynagrade.exercise import Choice, Exercise, Misconception, Numeric


def solve(p):
    return {"y": p.x ** 2}


EXERCISE = Exercise(
    id="square-of-x", title="Square", source="Section 1.1",
    params=(Choice("x", (1.0, 2.0, 3.0), unit="m"),),
    statement="What is the square of $x$ = {{ x }}?",
    solve=solve,
    parts=(Numeric("y", "square", unit="m^2", points=1,
                   misconceptions=(Misconception("not squared", lambda p: p.x, "Square it."),)),),
)
'''


def test_a_variant_that_cannot_discriminate_is_replaced_and_the_manifest_says_why(tmp_path):
    bank_folder = tmp_path / "bank"
    bank_folder.mkdir()
    (bank_folder / "square.py").write_text(REDRAW_EXERCISE, encoding="utf-8")
    exam = tmp_path / "exam.toml"
    exam.write_text('id = "q"\ntitle = "Q"\ndate = 2025-01-01\n[[exercise]]\n'
                    'id = "square-of-x"\npoints = 2\n', encoding="utf-8")
    roster = tmp_path / "roster.csv"
    roster.write_text("student_id,name\n" + "".join(f"t{i},T {i}\n" for i in range(12)),
                      encoding="utf-8")
    bank = open_bank([bank_folder])
    # a fixed secret: with a fresh one, none of the 12 students drew x = 1 in one run of
    # 130 ((2/3)**12), and the test then had no redraw to look at
    report = generate_exam(exam, roster, tmp_path / "out", bank=bank, jobs=1, pdf=False,
                           secret="7a" * 32)
    manifest = json.loads((tmp_path / "out" / "manifest.json").read_text(encoding="utf-8"))
    exercise = bank.get("square-of-x")
    entries = [s["variants"][0] for s in manifest["students"]]
    assert all(e["params"]["x"] != 1.0 for e in entries)
    redraws = [r for e in entries for r in e["redraws"]]
    assert redraws and report.redraws == len(redraws)
    for redraw in redraws:
        assert exercise.variant(redraw["seed"]).params["x"] == 1.0
        assert any("not squared" in problem for problem in redraw["problems"])


def test_vector_and_choice_parts_become_cloze_fields_with_their_answers(tmp_path, bank):
    exam = tmp_path / "exam.toml"
    exam.write_text('id = "m"\ntitle = "M & <Co>"\ndate = 2025-01-01\n'
                    '[[exercise]]\nid = "release-under-gravity"\npoints = 4\n'
                    '[[exercise]]\nid = "block-sliding-down-incline"\npoints = 4\n',
                    encoding="utf-8")
    roster = tmp_path / "roster.csv"
    roster.write_text("student_id,name\nm1,A\nm2,B\n", encoding="utf-8")
    generate_exam(exam, roster, tmp_path / "out", bank=bank, jobs=1, pdf=False)
    manifest = json.loads((tmp_path / "out" / "manifest.json").read_text(encoding="utf-8"))
    root = ET.parse(tmp_path / "out" / "moodle.xml").getroot()
    assert root.find("question/category/text").text == "$course$/top/M & <Co>/release-under-gravity"
    questions = {q.findtext("idnumber"): q.findtext("questiontext/text")
                 for q in root.findall("question") if q.get("type") == "cloze"}
    assert len(questions) == 4
    variants = _by_idnumber(manifest)
    for idnumber, text in questions.items():
        variant = variants[idnumber]
        exercise = bank.get(variant["exercise"])
        fields = iter(read_fields(text))
        for part in exercise.parts:
            value = variant["answers"][part.name]
            if part.kind == "vector":
                for component in value:
                    right = next(fields).answers[0]
                    assert math.isclose(right.value, component, rel_tol=1e-9)
                    assert math.isclose(right.tolerance, part.rtol * abs(component),
                                        rel_tol=1e-9)
            elif part.kind == "choice":
                found = next(fields)
                assert found.kind == "MULTICHOICE"
                assert [(a.answer_text, a.fraction == 1.0) for a in found.answers] == \
                    [(o, o == value) for o in part.options]
            elif part.kind == "numeric":
                assert math.isclose(next(fields).answers[0].value, value, rel_tol=1e-9)
