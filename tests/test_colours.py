"""Figure colours as ``#rrggbb``: every form a figure may name, worked out by hand, and
the same answer whether the colour comes as text (kept after its first use, since every
line, label and arrow of every student's figure names one) or as a tuple."""

from __future__ import annotations

import pytest

from dynagrade.errors import DefinitionError
from dynagrade.exercise.colours import to_hex


@pytest.mark.parametrize("colour, expected", [
    ("C3", "#d62728"),        # the fourth colour of matplotlib's tab10 cycle
    ("0.1", "#1a1a1a"),       # 0.1 x 255 = 25.5, rounded to the even 26 = 0x1a
    ("#abc", "#aabbcc"),      # each digit of the short form doubled
    (" White ", "#ffffff"),   # spaces and case do not matter
    ("k", "#000000"),
])
def test_a_colour_named_as_text_gives_its_hex_every_time_it_is_asked_for(colour, expected):
    assert [to_hex(colour) for _ in range(3)] == [expected] * 3


def test_a_colour_given_as_fractions_gives_the_hex_of_the_same_colour_named_as_text():
    assert to_hex((0.1, 0.1, 0.1)) == to_hex("0.1") == "#1a1a1a"
    assert to_hex((0.5, 0.0, 1.0)) == "#8000ff"  # 127.5 rounds to the even 128 = 0x80


def test_a_name_that_is_no_colour_is_refused_each_time_not_only_the_first():
    for _ in range(2):
        with pytest.raises(DefinitionError, match="'C11'"):
            to_hex("C11")
