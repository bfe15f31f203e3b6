"""Statement math without TeX or a network: TeX subset to MathML (laid out by a browser)
and to typst (compiled to PDF), and the Markdown around it."""

from __future__ import annotations

import html
import json
import re
import shutil
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from dynagrade.render.pdf import compile_pdf
from dynagrade.render.markup import markdown_to_html, markdown_to_typst, math_warnings
from dynagrade.render.mathtex import to_mathml, to_typst, unknown_commands

SUBSET = [
    r"v_0", r"x_{1,\max}", r"\alpha = 30", r"\varphi", r"g = 9.81\,\mathrm{m/s^2}",
    r"\frac{v_0^2}{2 g}\sin(2\alpha)", r"\sqrt{5 g R}", r"\sqrt[3]{x}", r"\dot{x}_1 + \ddot{y}",
    r"\vec{F} = m \vec{a}", r"\mu < \tan\alpha", r"\left( a + b \right)^2",
    r"\text{if } x \ge 0", r"\mathbf{r}_{AB} \cdot \mathbf{e}", r"\Delta E = -\mu m g \cos\alpha\,\Delta x",
    r"\omega^2 = \frac{k}{m}", r"T' \approx 2\pi", r"\{a\} \quad b",
]


def _strip(element):
    return element.tag.split("}")[-1]


@pytest.mark.parametrize("tex", SUBSET)
def test_every_expression_of_the_subset_becomes_well_formed_mathml(tex):
    root = ET.fromstring(to_mathml(tex))
    # no alttext: the TeX source is not a spoken form (issue 18)
    assert root.tag == "math" and root.get("alttext") is None
    assert unknown_commands(tex) == ()
    for element in root.iter():
        tag = _strip(element)
        if tag in ("mfrac", "mroot", "mover"):
            assert len(element) == 2, tex
        if tag == "msubsup":
            assert len(element) == 3, tex


def test_scripts_fractions_and_fonts_have_the_meaning_of_the_tex():
    sub = ET.fromstring(to_mathml(r"x_{1,\max}"))[0]
    assert sub.tag == "msub" and sub[0].text == "x"
    assert [(_strip(e), e.text) for e in sub[1]] == [("mn", "1"), ("mo", ","), ("mi", "max")]
    frac = ET.fromstring(to_mathml(r"\frac{v_0^2}{2 g}"))[0]
    assert frac.tag == "mfrac" and frac[0].tag == "msubsup"
    assert [e.text for e in frac[0]] == ["v", "0", "2"]
    unit = ET.fromstring(to_mathml(r"\mathrm{m/s^2}"))[0]
    assert unit[0].get("mathvariant") == "normal" and unit[0].text == "m"
    assert ET.fromstring(to_mathml(r"\varphi"))[0].text == "φ"
    assert ET.fromstring(to_mathml(r"\phi"))[0].text == "ϕ"
    assert ET.fromstring(to_mathml(r"\sin"))[0].text == "sin"


def test_an_unknown_command_is_shown_as_text_and_reported():
    assert unknown_commands(r"a \foo b") == (r"\foo",)
    assert "<mtext>\\foo</mtext>" in to_mathml(r"a \foo b")
    assert math_warnings("see $\\bar{x}$ and $\\weird$") == ["\\weird"]


def test_markdown_paragraphs_lists_and_math_become_html():
    text = "A ball of mass $m$ = 2 kg, **heavy**.\nIt flies.\n\n1. How far?\n2. How *high*?\n"
    page = markdown_to_html(text)
    assert page.startswith("<p>A ball of mass <math")
    assert "<strong>heavy</strong>" in page and "It flies." in page
    assert re.search(r"<ol><li>How far\?</li><li>How <em>high</em>\?</li></ol>", page)
    assert "$" not in page
    assert markdown_to_html("costs \\$5 & <b>") == "<p>costs $5 &amp; &lt;b&gt;</p>"


def test_the_whole_subset_compiles_with_typst_and_keeps_its_text():
    body = "\n\n".join(f"Case {i}: ${to_typst(tex)}$" for i, tex in enumerate(SUBSET))
    body += "\n\n" + markdown_to_typst("Costs \\$5 #hash *bold* _x_ [link] <tag> @ref\n\n"
                                       "1. first\n2. second")
    pdf = compile_pdf('#set document(date: datetime(year: 2025, month: 1, day: 1))\n' + body)
    assert pdf.startswith(b"%PDF")
    if shutil.which("pdftotext"):
        text = subprocess.run(["pdftotext", "-", "-"], input=pdf, capture_output=True,
                              check=True).stdout.decode()
        assert f"Case {len(SUBSET) - 1}" in text
        assert "Costs $5 #hash" in text and "[link] <tag> @ref" in text


CHECK = """
<script>
(function () {
  const bad = [];
  const maths = [...document.querySelectorAll('math')];
  for (const m of maths) {
    if (!(m instanceof MathMLElement) || m.getBoundingClientRect().width <= 0) bad.push('math');
  }
  for (const s of document.querySelectorAll('msub, msubsup')) {
    const base = s.children[0].getBoundingClientRect(), sub = s.children[1].getBoundingClientRect();
    if (!(sub.bottom > base.bottom + 0.5 && sub.left >= base.right - 1)) bad.push('msub');
  }
  for (const s of document.querySelectorAll('msup')) {
    const base = s.children[0].getBoundingClientRect(), sup = s.children[1].getBoundingClientRect();
    if (!(sup.top < base.top - 0.5)) bad.push('msup');
  }
  for (const f of document.querySelectorAll('mfrac')) {
    const n = f.children[0].getBoundingClientRect(), d = f.children[1].getBoundingClientRect();
    if (!(n.bottom <= d.top + 0.5)) bad.push('mfrac');
  }
  const svgs = [...document.querySelectorAll('svg')].filter(s => s.getBoundingClientRect().width > 0);
  document.body.setAttribute('data-math-check', JSON.stringify(
    {maths: maths.length, svgs: svgs.length, bad: bad}));
})();
</script>
"""


def _laid_out(page: Path, tmp_path: Path) -> dict:
    checked = tmp_path / ("checked-" + page.name)
    checked.write_text(page.read_text(encoding="utf-8").replace("</body>", CHECK + "</body>"),
                       encoding="utf-8")
    command = ["/usr/bin/chromium", "--headless", "--no-sandbox", "--disable-gpu",
               "--disable-quic", "--no-first-run", "--disable-background-networking",
               "--disable-component-update", "--disable-sync",
               f"--user-data-dir={tmp_path / 'profile'}", "--dump-dom", checked.as_uri()]
    dom = subprocess.run(command, capture_output=True, text=True, timeout=120).stdout
    found = re.search(r'data-math-check="([^"]*)"', dom)
    assert found, dom[-2000:]
    return json.loads(html.unescape(found.group(1)))


chromium = pytest.mark.skipif(not Path("/usr/bin/chromium").exists(),
                              reason="headless Chromium missing: install the apt package "
                                     "chromium to check that MathML is laid out")


@chromium
def test_a_generated_html_sheet_lays_out_its_math_and_figures_in_chromium(tmp_path):
    from dynagrade.generation.generate import generate_exam
    from dynagrade.exercise.loader import open_bank

    roster = tmp_path / "roster.csv"
    roster.write_text("student_id,name\nh-1,Henri Poincaré\n", encoding="utf-8")
    exam = tmp_path / "exam.toml"
    exam.write_text('id = "t"\ntitle = "T"\ndate = 2025-01-01\n' + "".join(
        f'[[exercise]]\nid = "{e}"\npoints = 5\n'
        for e in ("projectile-range", "sliding-up-a-slope", "car-in-a-looping")),
        encoding="utf-8")
    generate_exam(exam, roster, tmp_path / "out", bank=open_bank(), jobs=1, pdf=False)
    result = _laid_out(tmp_path / "out" / "students" / "h-1" / "sheet.html", tmp_path)
    assert result["maths"] >= 10 and result["svgs"] == 3
    assert result["bad"] == []


@chromium
def test_the_whole_subset_is_laid_out_as_math_in_chromium(tmp_path):
    page = tmp_path / "subset.html"
    page.write_text('<!DOCTYPE html><html><head><meta charset="utf-8"></head><body>'
                    + "".join(f"<p>{to_mathml(tex)}</p>" for tex in SUBSET)
                    + "</body></html>", encoding="utf-8")
    result = _laid_out(page, tmp_path)
    assert result["maths"] == len(SUBSET)
    assert result["bad"] == []
