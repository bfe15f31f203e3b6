"""Accessibility of the outputs (WCAG 2.1 AA, issue 18): axe-core in Chromium finds no
violation of the A/AA rules on a sheet, a class report and a feedback page, and the checks
axe cannot make hold: every SVG is a named image whose description states what it shows,
ids are unique, the pages declare the exam's language and a viewport, nothing scrolls
sideways at phone width, colours reach their contrast, bold vectors are bold characters,
and the PDF is tagged, in the exam's language, with alternative text on its figures.

axe-core comes from npm (``npm install --prefix .cache/axe axe-core``, done by .ci/run);
without it, or without Chromium or Playwright, the axe tests are skipped with the reason.
"""

from __future__ import annotations

import importlib.util
import json
import os
import re
import shutil
import subprocess
import unicodedata
import zlib
from collections import Counter
from html.parser import HTMLParser
from pathlib import Path

import pytest

from dynagrade.classgrade.grade import grade_class
from dynagrade.generation.generate import generate_exam
from dynagrade.render.figures import figure_svg
from dynagrade.render.mathtex import to_mathml
from dynagrade.classgrade.gradebook import GradebookRow, RowStatus
from dynagrade.classgrade.report import class_summary, score_bins

ROOT = Path(__file__).resolve().parent.parent
TEMPLATES = ROOT / "src" / "dynagrade" / "templates"
CHROMIUM = Path("/usr/bin/chromium")
AXE_JS = Path(os.environ.get("DYNAGRADE_AXE_JS",
                             ROOT / ".cache" / "axe" / "node_modules" / "axe-core" / "axe.min.js"))
CHROMIUM_ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                 "--no-first-run", "--disable-background-networking",
                 "--disable-component-update", "--disable-sync"]
WCAG_TAGS = ["wcag2a", "wcag2aa", "wcag21a", "wcag21aa"]

# a figure, an exercise without one (and with bold vectors), a figure: the figures are
# numbered 1 and 2
EXAM = """\
id = "a11y-exam"
title = "Dynamik: Zwischenprüfung"
date = 2025-04-14
language = "de"
instructions = "Alle Teile beantworten."

[[exercise]]
id = "car-in-a-looping"
points = 8

[[exercise]]
id = "release-under-gravity"
points = 4

[[exercise]]
id = "projectile-range"
points = 6
"""
SUBMISSIONS = (("correct", 1), ("half", 1), ("empty", 1), ("corrupt", 1), ("duplicate", 1))
STUDENTS = [f"s-{i}" for i in range(6)]  # the last one is absent


@pytest.fixture(scope="module")
def outputs(tmp_path_factory, bank):
    """A German exam generated with PDFs, graded for a small class with every kind of
    submission (right, half right, empty, corrupt, handed in twice, absent)."""
    folder = tmp_path_factory.mktemp("a11y")
    (folder / "exam.toml").write_text(EXAM, encoding="utf-8")
    (folder / "roster.csv").write_text(
        "student_id,name\n" + "".join(f"{s},Student {s}\n" for s in STUDENTS), encoding="utf-8")
    out = folder / "out"
    generate_exam(folder / "exam.toml", folder / "roster.csv", out, bank=bank, jobs=1)
    spec = importlib.util.spec_from_file_location(
        "make_submissions_for_a11y", ROOT / "examples" / "make_submissions.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    module.PLAN = SUBMISSIONS
    module.main(str(out))
    grade_class(out / "manifest.json", [out / "submissions"], out / "grading", bank=bank,
                jobs=1)
    manifest = json.loads((out / "manifest.json").read_text(encoding="utf-8"))
    return {"out": out, "manifest": manifest,
            "sheet": out / "students" / "s-0" / "sheet.html",
            "report": out / "grading" / "report.html",
            "feedback": out / "grading" / "feedback" / "s-1.html",
            "empty feedback": out / "grading" / "feedback" / "s-2.html"}


PAGES = ["sheet", "report", "feedback"]


# -- axe-core in Chromium -----------------------------------------------------------------


@pytest.fixture(scope="module")
def browser():
    if not CHROMIUM.exists():
        pytest.skip("headless Chromium missing: install the apt package chromium")
    if not AXE_JS.exists():
        pytest.skip(f"axe-core missing at {AXE_JS}: run `npm install --prefix .cache/axe "
                    "axe-core` (.ci/run does) or set DYNAGRADE_AXE_JS")
    playwright = pytest.importorskip("playwright.sync_api",
                                     reason="Playwright for Python missing: pip install "
                                            "playwright (its browsers are not needed)")
    with playwright.sync_playwright() as driver:
        chromium = driver.chromium.launch(executable_path=str(CHROMIUM), args=CHROMIUM_ARGS)
        yield chromium
        chromium.close()


def _open(browser, path: Path, width: int = 1280):
    page = browser.new_page(viewport={"width": width, "height": 900})
    page.goto(path.as_uri())
    return page


def _axe(browser, path: Path) -> dict:
    page = _open(browser, path)
    page.add_script_tag(content=AXE_JS.read_text(encoding="utf-8"))
    result = page.evaluate("tags => axe.run(document, {runOnly: {type: 'tag', values: tags}})",
                           WCAG_TAGS)
    page.close()
    return result


def test_axe_reports_the_faults_it_is_there_to_find(browser, tmp_path):
    """The set-up works: a page without a language, with an unnamed image and an unnamed
    SVG image, fails the rules that check exactly these."""
    page = tmp_path / "bad.html"
    page.write_text('<!DOCTYPE html><html><head><meta charset="utf-8"><title>t</title>'
                    '</head><body><main><img src="x.png"><svg role="img" width="10" '
                    'height="10"></svg></main></body></html>', encoding="utf-8")
    found = {v["id"] for v in _axe(browser, page)["violations"]}
    assert {"html-has-lang", "image-alt", "svg-img-alt"} <= found


@pytest.mark.parametrize("kind", PAGES)
def test_axe_finds_no_wcag_21_a_or_aa_violation(outputs, browser, kind):
    result = _axe(browser, outputs[kind])
    assert result["passes"], "axe ran no rule at all"
    violations = [(v["id"], v["help"], [n["target"] for n in v["nodes"]][:3])
                  for v in result["violations"]]
    assert violations == []


@pytest.mark.parametrize("kind", PAGES)
def test_at_phone_width_a_page_does_not_scroll_sideways(outputs, browser, kind):
    """WCAG 1.4.10: at 320 CSS pixels (a phone, or 1280 px at 400 % zoom) only a table's
    own box may scroll, never the page."""
    page = _open(browser, outputs[kind], width=320)
    overflow = page.evaluate("document.documentElement.scrollWidth - window.innerWidth")
    page.close()
    assert overflow <= 0


# -- the language follows the spec ----------------------------------------------------------


def test_the_language_is_read_from_the_spec_english_by_default(tmp_path):
    from dynagrade.exam.spec import ExamSpecError, read_exam_spec

    exam = tmp_path / "exam.toml"
    exam.write_text(EXAM, encoding="utf-8")
    assert read_exam_spec(exam).language == "de"
    exam.write_text(EXAM.replace('language = "de"\n', ""), encoding="utf-8")
    assert read_exam_spec(exam).language == "en"
    exam.write_text(EXAM.replace('"de"', '"Deutsch"'), encoding="utf-8")
    with pytest.raises(ExamSpecError, match=r"line 4, field 'language': 'Deutsch' is not a "
                                            r"language tag"):
        read_exam_spec(exam)


def test_the_manifest_keeps_the_language_and_reads_older_manifests_as_english(outputs):
    from dynagrade.exam.manifest import from_dict, to_dict

    data = outputs["manifest"]
    assert data["exam"]["language"] == "de"
    assert from_dict(data).exam.language == "de"
    older = json.loads(json.dumps(data))
    del older["exam"]["language"]
    assert from_dict(older).exam.language == "en"
    assert "language" not in to_dict(from_dict(older))["exam"]


def test_an_english_sheet_says_en_and_a_swiss_german_pdf_de_ch():
    from dynagrade.render.sheets import StudentSheet, sheet_html, typst_preamble

    exam = {"id": "e", "title": "T", "date": "2025-04-14", "instructions": ""}
    assert '<html lang="en">' in sheet_html(StudentSheet(exam, "s", "S", ()))
    preamble = typst_preamble({**exam, "language": "de-CH"})
    assert 'lang: "de", region: "CH"' in preamble


# -- what axe cannot see ------------------------------------------------------------------


class _Elements(HTMLParser):
    """Every start tag of a page with its attributes, and the text inside tags by name."""

    def __init__(self, text: str):
        super().__init__(convert_charrefs=True)
        self.tags: list[tuple[str, dict]] = []
        self.text: dict[str, list[str]] = {}
        self._open: list[str] = []
        self.feed(text)

    def handle_starttag(self, tag, attrs):
        self.tags.append((tag, dict(attrs)))
        self._open.append(tag)
        for name in ("title", "desc", "figcaption", "caption"):
            if tag == name:
                self.text.setdefault(name, []).append("")

    def handle_endtag(self, tag):
        if tag in self._open:
            while self._open.pop() != tag:
                pass

    def handle_data(self, data):
        for name in ("title", "desc", "figcaption", "caption"):
            if name in self._open:
                self.text[name][-1] += data

    def all(self, tag):
        return [attrs for name, attrs in self.tags if name == tag]


def _page(outputs, kind) -> tuple[str, _Elements]:
    text = outputs[kind].read_text(encoding="utf-8")
    return text, _Elements(text)


def _svgs(text: str) -> list[str]:
    return re.findall(r"<svg\b.*?</svg>", text, re.S)


@pytest.mark.parametrize("kind", PAGES)
def test_every_page_declares_the_exam_language_a_viewport_and_its_main_part(outputs, kind):
    _, page = _page(outputs, kind)
    assert page.all("html")[0]["lang"] == "de"
    viewports = [m for m in page.all("meta") if m.get("name") == "viewport"]
    assert len(viewports) == 1 and "width=device-width" in viewports[0]["content"]
    assert len(page.all("main")) == 1


@pytest.mark.parametrize("kind", PAGES)
def test_ids_are_unique_in_every_page(outputs, kind):
    _, page = _page(outputs, kind)
    ids = Counter(attrs["id"] for _, attrs in page.tags if "id" in attrs)
    assert [name for name, count in ids.items() if count > 1] == []
    for _, attrs in page.tags:
        for reference in ("aria-labelledby", "aria-describedby"):
            for name in attrs.get(reference, "").split():
                assert name in ids, (reference, name)


@pytest.mark.parametrize("kind", ["sheet", "report"])
def test_every_svg_is_an_image_with_a_title_and_a_description(outputs, kind):
    text, _ = _page(outputs, kind)
    svgs = _svgs(text)
    assert len(svgs) == 2
    for svg in svgs:
        opening = re.match(r"<svg\b[^>]*>", svg).group(0)
        assert 'role="img"' in opening
        # the title and the description come first, and they have words
        children = re.match(r"<svg\b[^>]*>\s*<title\b[^>]*>([^<]+)</title>\s*"
                            r"<desc\b[^>]*>([^<]+)</desc>", svg)
        assert children and len(children.group(1).split()) >= 2 \
            and len(children.group(2).split()) >= 5


def test_every_table_has_a_caption_and_its_rows_a_header(outputs):
    for kind in PAGES:
        text, page = _page(outputs, kind)
        tables = text.count("<table")
        assert tables and text.count("<caption") == tables, kind
        assert text.count('<th scope="row"') >= tables, kind
        # each table sits in a focusable box of its own that scrolls when it is too wide
        assert len(re.findall(r'<div class="table-scroll" role="region" tabindex="0" '
                              r'aria-labelledby="[^"]+">\s*<table', text)) == tables, kind


def test_the_sheet_numbers_its_figures_without_gaps(outputs):
    _, page = _page(outputs, "sheet")
    captions = [c.split(":")[0] for c in page.text["figcaption"]]
    assert captions == ["Figure 1", "Figure 2"]  # exercises 1 and 3 have a figure


def test_a_figure_description_names_every_value_and_direction_it_shows(outputs):
    """The looping of student s-0: the values come from the manifest, the directions from
    Example 1.13's set-up (the car enters at the bottom moving right and goes round
    counter-clockwise; φ is measured from the bottom)."""
    text, page = _page(outputs, "sheet")
    params = outputs["manifest"]["students"][0]["variants"][0]["params"]
    description = page.text["desc"][0]
    for shown in (f"R = {params['R']:g} m", f"φ = {params['phi']:g}°",
                  f"v₀ = {params['v0']:g} m/s"):
        assert shown in description
    for words in ("counter-clockwise", "measured from the direction pointing down",
                  "pointing to the right", "lowest point A"):
        assert words in description
    # the statement gives the same values
    statement = re.search(r'<section class="exercise" id="car-in-a-looping".*?</section>',
                          text, re.S).group(0)
    assert f"{params['R']:g} m" in statement and f"{params['v0']:g} m/s" in statement


def _drawn_labels(svg: str) -> list[str]:
    """The text a figure draws, read from its SVG ``<text>`` elements (an independent
    route to the labels: the SVG itself)."""
    import xml.etree.ElementTree as ET

    labels = []
    for element in ET.fromstring(svg.encode()).iter():
        if element.tag.rsplit("}", 1)[-1] == "text":
            words = " ".join("".join(element.itertext()).split())
            if words:
                labels.append(words)
    return labels


def test_every_figure_of_the_bank_describes_every_label_it_draws(bank):
    seen = 0
    for exercise in bank.all():
        if exercise.figure is None:
            continue
        for seed in (0, 1):
            svg = figure_svg(exercise, exercise.variant(seed))
            description = re.search(r"<desc\b[^>]*>(.*?)</desc>", svg, re.S).group(1)
            labels = _drawn_labels(svg)
            assert labels, exercise.id
            for label in labels:
                assert label.replace("&", "&amp;") in description, (exercise.id, label)
            seen += 1
    assert seen >= 20


def test_unanswered_parts_say_so_in_words_not_only_with_a_dash(outputs):
    text, _ = _page(outputs, "empty feedback")
    assert "— (no answer)" in text
    assert not re.search(r"<td>\s*—\s*</td>", text)
    report, _ = _page(outputs, "report")
    assert not re.search(r"<td[^>]*>\s*—\s*</td>", report)


# -- contrast -----------------------------------------------------------------------------


def _luminance(colour: str) -> float:
    """Relative luminance of an sRGB colour ``#rrggbb`` or ``#rgb`` (WCAG 2.1 definition)."""
    colour = colour.lstrip("#")
    if len(colour) == 3:
        colour = "".join(c * 2 for c in colour)
    channels = []
    for i in (0, 2, 4):
        c = int(colour[i:i + 2], 16) / 255
        channels.append(c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4)
    return 0.2126 * channels[0] + 0.7152 * channels[1] + 0.0722 * channels[2]


def contrast(first: str, second: str = "#ffffff") -> float:
    high, low = sorted((_luminance(first), _luminance(second)), reverse=True)
    return (high + 0.05) / (low + 0.05)


def test_the_contrast_formula_gives_the_known_ratios():
    assert contrast("#000000") == pytest.approx(21.0)
    assert contrast("#ffffff") == pytest.approx(1.0)
    assert contrast("#767676") == pytest.approx(4.54, abs=0.01)  # the grey known to pass AA
    assert contrast("#ff7f0e") == pytest.approx(2.53, abs=0.01)  # the old orange bars


def test_every_text_colour_of_the_pages_has_at_least_4_5_to_1_on_white(outputs):
    styles = (TEMPLATES / "page_style.css").read_text(encoding="utf-8")
    for kind in PAGES:
        styles += "".join(re.findall(r"<style>(.*?)</style>", outputs[kind].read_text(
            encoding="utf-8"), re.S))
    colours = set(re.findall(r"(?<![-\w])color:\s*(#[0-9a-fA-F]{3,6})\b", styles))
    assert len(colours) >= 5
    for colour in colours:
        assert contrast(colour) >= 4.5, colour
    for border in re.findall(r"border[-\w]*:[^;]*?(#[0-9a-fA-F]{3,6})", styles):
        assert contrast(border) >= 3.0, border


def _svg_colours(svg: str):
    """``(fill, stroke, is_text)`` of every painted element of an SVG (presentation
    attributes or a style attribute): a figure's labels are ``<text>`` elements, a
    matplotlib chart's glyphs ``<use>`` elements inside a styled text group."""
    for match in re.finditer(r'<(\w+)\b([^>]*)>', svg):
        attributes = dict(re.findall(r'([\w-]+)="([^"]*)"', match.group(2)))
        style = {name: attributes[name] for name in ("fill", "stroke") if name in attributes}
        written = attributes.get("style", "")  # matplotlib's charts style their elements
        style.update((k.strip(), v.strip()) for k, v in
                     (part.split(":", 1) for part in written.split(";") if ":" in part))
        if not style:
            continue
        following = svg[match.end():match.end() + 400]
        is_text = match.group(1) == "text" or (match.group(1) == "g"
                                               and following.lstrip().startswith("<use"))
        yield style.get("fill"), style.get("stroke"), is_text


def _colour(value):
    return value if value and re.fullmatch(r"#[0-9a-fA-F]{6}", value) else None


def test_every_graphic_reaches_3_to_1_and_every_label_4_5_to_1_against_white(outputs, bank):
    """Lines and unoutlined shapes at least 3:1 (WCAG 1.4.11), drawn text at least 4.5:1
    (1.4.3); a light fill counts when its own outline reaches 3:1; white is the page."""
    svgs = _svgs(outputs["report"].read_text(encoding="utf-8"))
    svgs += [figure_svg(e, e.variant(0)) for e in bank.all() if e.figure is not None]
    checked = 0
    for svg in svgs:
        for fill, stroke, is_text in _svg_colours(svg):
            fill, stroke = _colour(fill), _colour(stroke)
            if is_text:
                if fill and fill != "#ffffff":  # white labels sit on a block, see below
                    assert contrast(fill) >= 4.5, ("text", fill)
                    checked += 1
                continue
            if stroke and stroke != "#ffffff":
                assert contrast(stroke) >= 3.0, ("line", stroke)
                checked += 1
            if fill and fill != "#ffffff" and not (stroke and contrast(stroke) >= 3.0):
                assert contrast(fill) >= 3.0, ("shape", fill)
                checked += 1
    assert checked > 100


def test_a_block_label_takes_the_colour_that_reads_on_the_block():
    """White on the ballistic pendulum's brown (#a0724a) is 4.2:1, too little for text;
    the label turns dark there, and stays white on the default blue."""
    from dynagrade.exercise.figure import block, new_drawing

    figure, axes = new_drawing()
    block(axes, (0, 0), 1, 1, "M", color="#a0724a")
    block(axes, (2, 0), 1, 1, "m")
    brown, blue = (text.get_color() for text in axes.texts)
    from matplotlib.colors import to_hex

    assert contrast(to_hex(brown), "#a0724a") >= 4.5
    assert contrast(to_hex(blue), "#1f77b4") >= 4.5 and to_hex(blue) == "#ffffff"


# -- math and the report's numbers --------------------------------------------------------


def test_bold_vectors_are_bold_characters_not_css():
    mathml = to_mathml(r"\mathbf{r} = r\,\mathbf{e}_1 + \boldsymbol{\omega}")
    assert "style=" not in mathml and "alttext" not in mathml
    bold = re.findall(r'<mi mathvariant="bold">(.)</mi>', mathml)
    assert [unicodedata.name(c) for c in bold] == [
        "MATHEMATICAL BOLD SMALL R", "MATHEMATICAL BOLD SMALL E",
        "MATHEMATICAL BOLD SMALL OMEGA"]
    assert "<mi>r</mi>" in mathml  # the scalar r stays a plain letter


def test_the_sheet_writes_the_bold_vectors_of_its_statement_as_bold_characters(outputs):
    text, _ = _page(outputs, "sheet")
    section = re.search(r'<section class="exercise" id="release-under-gravity".*?</section>',
                        text, re.S).group(0)
    bold = re.findall(r'<mi mathvariant="bold">([^<]+)</mi>', section)
    assert bold and all(unicodedata.name(c).startswith("MATHEMATICAL BOLD")
                        for c in "".join(bold))
    assert "font-weight" not in section


def test_the_median_of_an_even_count_is_the_mean_of_the_two_middle_values():
    rows = [GradebookRow(f"s{i}", "", "", {"e": p / 10}, p / 10, 10.0, RowStatus.GRADED)
            for i, p in enumerate((100.0, 70.0, 100.0, 85.0))]
    rows.append(GradebookRow("s9", "", "", {"e": None}, None, 10.0, RowStatus.ABSENT))
    summary = class_summary(rows)
    assert summary["median"] == "92.5"  # (85 + 100) / 2, not the upper middle 100
    assert summary["mean"] == "88.75"
    assert (summary["present"], summary["absent"]) == (4, 1)


def test_the_histogram_data_counts_every_student_once_and_100_in_the_top_band():
    bins = dict(score_bins([0.0, 9.99, 10.0, 55.0, 90.0, 100.0]))
    counts = list(bins.values())
    assert counts == [2, 1, 0, 0, 0, 1, 0, 0, 0, 2] and sum(counts) == 6


def test_the_report_states_its_histogram_as_data(outputs):
    text, page = _page(outputs, "report")
    rows = outputs["out"] / "grading" / "grades.csv"
    import csv

    present = [float(r["percent"]) for r in csv.DictReader(rows.open(encoding="utf-8"))
               if r["status"] != "absent"]
    histogram = page.text["desc"][0]
    assert f"scores of {len(present)} students" in histogram
    for low in range(0, 100, 10):
        count = sum(1 for p in present if low <= p < low + 10 or (low == 90 and p == 100))
        assert f"{low}–{low + 10} %" in histogram
        assert re.search(rf"{low}–{low + 10} %[^:]*: {count}\b", histogram), low


# -- PDF ----------------------------------------------------------------------------------


def _pdf_objects(path: Path) -> bytes:
    """The PDF's bytes with every Flate stream inflated (object streams included)."""
    data = path.read_bytes()
    parts = [data]
    for match in re.finditer(rb"stream\r?\n(.*?)endstream", data, re.S):
        try:
            parts.append(zlib.decompress(match.group(1)))
        except zlib.error:
            continue
    return b"\n".join(parts)


def _pdf_text_string(raw: bytes) -> str:
    if raw.startswith(b"<"):
        data = bytes.fromhex(raw[1:-1].decode())
        return data[2:].decode("utf-16-be") if data.startswith(b"\xfe\xff") else data.decode()
    return raw[1:-1].decode("latin-1")


@pytest.mark.skipif(shutil.which("pdfinfo") is None,
                    reason="pdfinfo missing: install the apt package poppler-utils")
def test_the_pdf_is_tagged_in_the_exam_language_with_alternative_text_on_figures(outputs):
    path = outputs["out"] / "students" / "s-0" / "sheet.pdf"
    info = subprocess.run(["pdfinfo", str(path)], capture_output=True, text=True,
                          timeout=60).stdout
    assert re.search(r"^Tagged:\s+yes$", info, re.M)
    assert re.search(r"^Title:\s+Dynamik: Zwischenprüfung$", info, re.M)
    objects = _pdf_objects(path)
    catalog = re.search(rb"/Type\s*/Catalog.*?>>", objects, re.S).group(0)
    assert re.search(rb"/Lang\s*\(de\)", catalog)
    assert b"/StructTreeRoot" in catalog
    figures = re.findall(rb"/S\s*/Figure\b[^>]*?/Alt\s*(<[0-9A-Fa-f]+>|\((?:\\.|[^)])*\))",
                         objects)
    alternatives = [_pdf_text_string(raw) for raw in figures]
    assert len(alternatives) == 2
    params = outputs["manifest"]["students"][0]["variants"][0]["params"]
    looping = next(a for a in alternatives if a.startswith("Car in a looping"))
    assert f"R = {params['R']:g} m" in looping and "counter-clockwise" in looping


def test_the_pdf_declares_pdf_ua_1_which_typst_checked(outputs):
    objects = _pdf_objects(outputs["out"] / "students" / "s-0" / "sheet.pdf")
    assert re.search(rb"<pdfuaid:part>1</pdfuaid:part>|pdfuaid:part=\"1\"", objects)


def test_every_exercise_of_the_bank_makes_a_pdf_ua_1_sheet(bank):
    """typst refuses a PDF/UA-1 document with an image or an equation without alternative
    text; every statement and figure of the bank passes, so no exam can fail on it."""
    from dynagrade.render.pdf import ACCESSIBLE, compile_pdf
    from dynagrade.render.sheets import (SheetExercise, StudentSheet, sheet_typst_body,
                                         typst_preamble)

    exam = {"id": "bank", "title": "Every exercise", "date": "2025-04-14",
            "instructions": "Use $\\mathbf{r}$.", "language": "en"}
    exercises = []
    for number, exercise in enumerate(bank.all(), 1):
        variant = exercise.variant(0)
        exercises.append(SheetExercise(number, exercise.id, exercise.title, exercise.source,
                                       1.0, variant.statement, (), f"{exercise.id}.py",
                                       figure_svg(exercise, variant)))
    sheet = StudentSheet(exam, "x-1", "Every Exercise", tuple(exercises))
    pdf = compile_pdf(typst_preamble(exam) + sheet_typst_body(sheet), standards=ACCESSIBLE)
    assert pdf.startswith(b"%PDF")


def test_a_vector_verdict_says_right_or_wrong_beside_its_marks():
    """"✓" and "✗" alone are read as "check mark" and "ballot x"; the words come along."""
    from dynagrade.grading import VectorSpec, grade

    verdict = grade(VectorSpec(2, unit="m/s"), (1.2, -3.4), "(1.2, 5) m/s")
    assert not verdict.correct and verdict.score == 0.5
    assert "(1: ✓ right, 2: ✗ wrong)" in verdict.feedback


def test_the_served_student_page_declares_the_language_and_keeps_figure_ids_unique(
        outputs, tmp_path):
    """`dynagrade serve` shows every exercise of a student on one page: both figures
    inlined, their ids apart, the page in the exam's language."""
    pytest.importorskip("fastapi", reason="the server's dependencies are not installed")
    from serve_support import serve

    copy = tmp_path / "exam"
    shutil.copytree(outputs["out"], copy, ignore=shutil.ignore_patterns("grading"))
    with serve(copy / "manifest.json") as served:
        text = served.client.get(f"/s/{served.tokens['s-0']}").text
    page = _Elements(text)
    assert page.all("html")[0]["lang"] == "de"
    assert len([s for s in _svgs(text) if 'role="img"' in s]) == 2
    ids = Counter(attrs["id"] for _, attrs in page.tags if "id" in attrs)
    assert [name for name, count in ids.items() if count > 1] == []
