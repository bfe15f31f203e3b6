"""Statements that hold at every draw (issue 31, item 3): the ballistic pendulum's string
is given and longer than the rise, and the slingshot drawn "to scale" draws its spring at
its length."""

from __future__ import annotations

import math

import pytest

from dynagrade.exercise import open_bank

BANK = open_bank()
SEEDS = range(200)


def test_the_ballistic_pendulum_gives_its_strings_length_and_rises_below_it():
    exercise = BANK.get("ballistic-pendulum")
    for seed in SEEDS:
        variant = exercise.variant(seed)
        length = variant.params["L"]
        assert f"strings of length $L$ = {length:g} m" in " ".join(variant.statement.split())
        assert variant.answers["h"] / 100 < length  # h in cm, L in m


def test_the_rise_the_issue_found_is_refused():
    # m = 42 g, M = 0.8 kg, v = 190 m/s: V = 0.042 * 190 / 0.842 = 9.47743 m/s and
    # h = V^2 / (2 g) = 89.8217 / 19.62 = 4.57807 m, longer than any string drawn (3 m)
    exercise = BANK.get("ballistic-pendulum")
    variant = exercise.variant_set(3, {"m": 42, "M": 0.8, "v": 190, "L": 3.0})
    assert variant.answers["h"] == pytest.approx(457.807, abs=1e-3)
    assert variant.warnings == ("the block rises less than the strings' length (h < L)",)


def _spring(drawing, top):
    """The figure's zig-zag line that starts at the fixed point ``top``."""
    (line,) = [line for line in drawing.axes[0].get_lines()
               if len(line.x) > 10 and (line.x[0], line.y[0]) == pytest.approx(top)]
    return line


@pytest.mark.parametrize("seed", range(0, 200, 10))
def test_the_slingshot_spring_is_drawn_at_its_length_on_the_figures_scale(seed):
    # the figure is in cm: the Δx dimension spans dx cm, the l0 dimension l0 cm, so the
    # spring from the fixed point to the particle's centre is sqrt(dx^2 + l0^2) cm long
    # and its vertical extent is l0 (it used to end on the slot's floor, a particle's
    # radius, 0.04 max(l0, dx), short of the centre: up to 27 % of l0 at seeds 0-199)
    exercise = BANK.get("elastic-slingshot")
    variant = exercise.variant(seed)
    l0, dx = variant.params["l0"], variant.params["dx"]  # cm
    assert exercise.figure_to_scale
    line = _spring(exercise.figure(exercise.si(variant.params)), (0.0, l0))
    drawn = math.hypot(line.x[-1] - line.x[0], line.y[-1] - line.y[0])
    assert drawn == pytest.approx(math.hypot(dx, l0), rel=1e-9)
    assert line.y[0] - line.y[-1] == pytest.approx(l0, rel=1e-9)
    assert line.x[-1] - line.x[0] == pytest.approx(dx, rel=1e-9)
