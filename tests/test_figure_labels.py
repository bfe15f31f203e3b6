"""Figure labels are SVG text: the TeX subset labels are written in becomes Unicode with
sub- and superscripts as shifted ``<tspan>`` elements, and every label of every figure
of the bank, at several seeds, renders as the text it says."""

from __future__ import annotations

import xml.etree.ElementTree as ET

import pytest

from dynagrade.errors import DefinitionError
from dynagrade.render.figures import figure_svg
from dynagrade.render.svg_text import label_runs, plain_label, svg_tspans

from bank_ids import figured_ids

SVG = "{http://www.w3.org/2000/svg}"
_FIGURED = figured_ids()


@pytest.mark.parametrize("label, runs", [
    (r"$\theta$ = 30°", [("θ = 30°", 0)]),
    (r"$v_0$ = 3 m/s", [("v", 0), ("0", -1), (" = 3 m/s", 0)]),
    (r"$\omega_{n}$", [("ω", 0), ("n", -1)]),
    (r"$\dot x$", [("x\u0307", 0)]),
    (r"$\ddot{\varphi}$", [("φ\u0308", 0)]),
    (r"$x^2 + F_{far}$", [("x", 0), ("2", 1), ("+F", 0), ("far", -1)]),
    (r"$\Delta x$ = 5 cm", [("Δx = 5 cm", 0)]),
    (r"$v_{\mathrm{top}}$", [("v", 0), ("top", -1)]),
    ("m₁ = 4 kg", [("m₁ = 4 kg", 0)]),
])
def test_the_tex_subset_becomes_unicode_runs(label, runs):
    assert label_runs(label) == runs


def test_scripts_are_tspans_that_return_to_the_baseline():
    tspans = svg_tspans(label_runs(r"$v_0$ = 3"), 10.0)
    assert tspans == 'v<tspan dy="2.2" font-size="7">0</tspan><tspan dy="-2.2"> = 3</tspan>'


@pytest.mark.parametrize("label", [r"$\frac{a}{b}$", "$v_0", r"$v_{0$"])
def test_a_label_outside_the_subset_is_an_error_naming_it(label):
    with pytest.raises(DefinitionError, match="figure label"):
        label_runs(label)


@pytest.mark.parametrize("exercise_id", _FIGURED)
def test_every_label_of_the_bank_renders_as_the_text_it_says(bank, exercise_id):
    exercise = bank.get(exercise_id)
    for seed in (0, 1, 2, 3):
        variant = exercise.variant(seed)
        drawing = exercise.figure(exercise.si(variant.params))
        said = [plain_label(label.get_text()) for label in drawing.axes[0].texts]
        root = ET.fromstring(figure_svg(exercise, variant).encode())
        shown = ["".join(text.itertext()) for text in root.iter(f"{SVG}text")]
        assert shown == [text for text in said if text] and shown, seed
