"""Exercise figures are drawn to scale with the variant's own numbers, and their SVG is
the same bytes on every run."""

from __future__ import annotations

import dataclasses
import math

import pytest

from dynagrade.exercise.figure import Circle, Polygon
from dynagrade.render.figures import figure_svg, inline_svg


@pytest.mark.parametrize("seed", [0, 7, 31])
def test_the_throw_is_drawn_to_scale(bank, seed):
    exercise = bank.get("projectile-range")
    p = exercise.si(exercise.variant(seed).params)
    axes = exercise.figure(p).axes[0]
    path = next(line for line in axes.get_lines() if line.get_linestyle() == "--")
    x, y = path.get_data()
    # hand formulas: range v0^2 sin(2a)/g, peak height (v0 sin a)^2/(2g)
    assert math.isclose(x[-1], p.v0**2 * math.sin(2 * p.alpha) / p.g, rel_tol=1e-9)
    assert math.isclose(max(y), (p.v0 * math.sin(p.alpha))**2 / (2 * p.g), rel_tol=1e-3)
    assert axes.get_aspect() == 1.0
    texts = " ".join(t.get_text() for t in axes.texts)
    assert f"{math.degrees(p.alpha):g}°" in texts and f"{p.v0:g} m/s" in texts


@pytest.mark.parametrize("seed", [0, 5])
def test_the_slope_is_drawn_at_the_variants_angle(bank, seed):
    exercise = bank.get("sliding-up-a-slope")
    p = exercise.si(exercise.variant(seed).params)
    axes = exercise.figure(p).axes[0]
    triangle = next(patch for patch in axes.patches if isinstance(patch, Polygon)
                    and len(patch.get_xy()) == 4)  # closed: first point repeated
    (x0, y0), (x1, _), (x2, y2) = triangle.get_xy()[:3]
    assert math.isclose(math.atan2(y2 - y0, x2 - x0), p.alpha, rel_tol=1e-9)
    assert math.isclose(x1, x2) and axes.get_aspect() == 1.0


@pytest.mark.parametrize("seed", [0, 9])
def test_the_looping_is_drawn_with_its_radius_and_the_car_at_phi(bank, seed):
    exercise = bank.get("car-in-a-looping")
    p = exercise.si(exercise.variant(seed).params)
    axes = exercise.figure(p).axes[0]
    circle = next(patch for patch in axes.patches if isinstance(patch, Circle))
    assert math.isclose(circle.get_radius(), p.R) and circle.center == (0.0, p.R)
    car = next(line for line in axes.get_lines() if line.get_marker() == "s")
    x, y = car.get_data()
    # the car has travelled phi around the circle from the bottom point A = (0, 0)
    assert math.isclose(math.hypot(x[0], y[0] - p.R), p.R, rel_tol=1e-9)
    assert math.isclose(math.atan2(x[0], p.R - y[0]) % (2 * math.pi), p.phi, rel_tol=1e-9)


def test_figures_render_to_the_same_svg_bytes_each_time(bank):
    for exercise_id in ("projectile-range", "sliding-up-a-slope", "car-in-a-looping"):
        exercise = bank.get(exercise_id)
        variant = exercise.variant(3)
        first, second = figure_svg(exercise, variant), figure_svg(exercise, variant)
        assert first == second
        assert "<dc:date" not in first and "Date" not in first
        assert inline_svg(first).startswith("<svg")


def test_an_exercise_without_a_figure_has_no_svg(bank):
    exercise = dataclasses.replace(bank.get("projectile-range"), figure=None)
    assert figure_svg(exercise, exercise.variant(0)) is None
