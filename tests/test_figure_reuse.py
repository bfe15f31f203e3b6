"""A drawing is made once per process and emptied after each figure is saved: the
figures it gives are byte for byte those of a new drawing, and a drawing that grew more
than a drawing has is never handed out again."""

from __future__ import annotations

import pytest

from dynagrade.exercise import figure as drawings
from dynagrade.exercise import open_bank
from dynagrade.render.figures import figure_svg
from deferred import deferred

matplotlib = deferred("matplotlib")


@pytest.fixture(autouse=True, scope="module")
def agg_backend():
    """Figures are drawn without a display (chosen when the tests run, so that collecting
    this module does not import matplotlib)."""
    matplotlib.use("Agg")


@pytest.fixture
def no_spare():
    drawings._SPARE.clear()
    yield
    drawings._SPARE.clear()


def _fresh_svg(exercise, variant) -> str:
    drawings._SPARE.clear()
    return figure_svg(exercise, variant)


def test_every_bank_figure_drawn_on_a_reused_drawing_has_the_bytes_of_a_new_one(no_spare):
    bank = open_bank()
    variants = [(e, e.variant(seed)) for seed in (0, 1) for e in bank.all()
                if e.figure is not None]
    fresh = [_fresh_svg(e, v) for e, v in variants]
    # drawn in the reverse order, each on the drawing the previous figure left behind
    drawings._SPARE.clear()
    reused = [figure_svg(e, v) for e, v in reversed(variants)][::-1]
    differing = [e.id for (e, _), a, b in zip(variants, fresh, reused) if a != b]
    assert differing == []


def test_a_saved_drawing_is_handed_out_again_emptied(no_spare):
    figure, axes = drawings.new_drawing(4.0, 2.0)
    drawings.arrow(axes, (0, 0), (1, 1), "$v$")
    axes.set_xlim(-3, 3)
    drawings.recycle(figure)
    again, same_axes = drawings.new_drawing(6.0, 1.5)
    assert again is figure and same_axes is axes
    assert (len(axes.lines), len(axes.patches), len(axes.texts)) == (0, 0, 0)
    assert drawings.figure_notes(again) == {"author": [], "drawn": []}
    assert tuple(again.get_size_inches()) == (6.0, 1.5)
    assert axes.get_autoscalex_on() and axes.get_autoscaley_on()


def test_a_drawing_given_a_second_axes_is_not_reused(no_spare):
    figure, axes = drawings.new_drawing()
    figure.add_axes((0.5, 0.5, 0.4, 0.4))
    drawings.recycle(figure)
    assert drawings.new_drawing()[0] is not figure


def test_a_figure_not_made_as_a_drawing_is_not_reused(no_spare):
    from matplotlib.figure import Figure

    figure = Figure()
    figure.add_axes((0, 0, 1, 1))
    drawings.recycle(figure)
    assert drawings.new_drawing()[0] is not figure


def test_the_crop_is_the_box_matplotlibs_own_tight_crop_gives(no_spare):
    """A label far right of the axes stays in the picture: the box measured in one pass
    is the one matplotlib's two-pass ``bbox_inches="tight"`` writes into the SVG."""
    import io
    import re

    from dynagrade.render.figures import PAD_INCHES, SVG_SETTINGS, tight_box

    figure, axes = drawings.new_drawing(4.0, 2.0)
    drawings.ground(axes, 0.0, 1.0)
    axes.text(1.6, 0.5, "$F_{far}$ a label past the axes", ha="left")
    axes.set_xlim(0.0, 1.0)
    axes.set_ylim(-0.1, 1.0)
    buffer = io.StringIO()
    with matplotlib.rc_context(SVG_SETTINGS):
        figure.savefig(buffer, format="svg", bbox_inches="tight", pad_inches=PAD_INCHES)
        box = tight_box(figure, PAD_INCHES)
    width, height = (float(re.search(rf'{name}="([\d.]+)pt"', buffer.getvalue()).group(1))
                     for name in ("width", "height"))
    assert box.width * 72 == pytest.approx(width, abs=1e-5)
    assert box.height * 72 == pytest.approx(height, abs=1e-5)
    assert box.width > 4.0  # the label reaches past the figure's own width


def test_margins_and_aspect_an_author_changed_do_not_reach_the_next_figure(no_spare):
    figure, axes = drawings.new_drawing()
    fresh = (axes.margins(), axes.get_adjustable(), axes.get_anchor(), axes.get_aspect())
    axes.margins(0.0, 0.3)
    axes.set_aspect(2.0, adjustable="datalim", anchor="NE")
    drawings.recycle(figure)
    again, axes = drawings.new_drawing()
    assert again is figure
    assert (axes.margins(), axes.get_adjustable(), axes.get_anchor(),
            axes.get_aspect()) == fresh
