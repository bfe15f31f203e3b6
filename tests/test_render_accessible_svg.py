"""Ids that stay unique in a page and the labels a figure's description repeats: the
scans that find them, against hand-worked cases and against the regular expressions
with a leading ``\\b`` that define them."""

from __future__ import annotations

import re

from hypothesis import given, settings
from hypothesis import strategies as st

from dynagrade.render.accessible_svg import _names_word, prefixed_ids


def test_every_id_and_every_reference_to_one_gets_the_prefix():
    svg = ('<svg aria-labelledby="t x" aria-describedby="d"><title id="t">T</title>'
           '<desc id="d">D</desc><clipPath id="c"/><g clip-path="url(#c)"/>'
           '<use href="#c"/><use href="#elsewhere"/></svg>')
    assert prefixed_ids(svg, "f2-") == (
        '<svg aria-labelledby="f2-t x" aria-describedby="f2-d"><title id="f2-t">T</title>'
        '<desc id="f2-d">D</desc><clipPath id="f2-c"/><g clip-path="url(#f2-c)"/>'
        '<use href="#f2-c"/><use href="#elsewhere"/></svg>')


def test_an_attribute_that_only_ends_in_id_is_not_an_id():
    """``grid="a"`` and ``xaria-labelledby`` end in what an id or an aria attribute
    starts with, after a letter: neither names an id. The search goes on right after
    the refused ``id="``, not after its value, so the ``id="r"`` that starts inside that
    value (after a space) is found."""
    assert prefixed_ids('<g grid="a"/><g id="b"/>', "p-") == '<g grid="a"/><g id="p-b"/>'
    assert prefixed_ids('<g xaria-labelledby="b"/><g id="b"/>', "p-") == \
        '<g xaria-labelledby="b"/><g id="p-b"/>'
    assert prefixed_ids('<g xid="q id="r"/>', "p-") == '<g xid="q id="p-r"/>'
    assert prefixed_ids('<g data-id="b"/><use href="#b"/>', "p-") == \
        '<g data-id="p-b"/><use href="#p-b"/>'
    assert prefixed_ids('<g grid="q"/>', "p-") == '<g grid="q"/>'
    assert prefixed_ids('<g id="b"/>', "") == '<g id="b"/>'


def _prefixed_by_regex(svg: str, prefix: str) -> str:
    """The definition: the same renaming with a leading ``\\b`` in each pattern."""
    if not prefix:
        return svg
    ids = set(re.findall(r'\bid="([^"]+)"', svg))
    if not ids:
        return svg
    svg = re.sub(r'(\bid="|href="#|url\(#)([^")]+)',
                 lambda m: m.group(1) + prefix + m.group(2) if m.group(2) in ids
                 else m.group(0), svg)
    return re.sub(r'(\baria-(?:labelledby|describedby)=)"([^"]*)"',
                  lambda m: m.group(1) + '"' + " ".join(prefix + n if n in ids else n
                                                        for n in m.group(2).split()) + '"',
                  svg)


_FRAGMENTS = st.sampled_from(['id="', 'href="#', 'url(#', 'aria-labelledby="',
                              'aria-describedby="', '"', ")", " ", "a", "b", "x", "_", "é",
                              "-", "<g ", "/>", "=", "#", "1"])


@settings(max_examples=400, deadline=None)
@given(st.lists(_FRAGMENTS, max_size=30).map("".join), st.sampled_from(["", "p-"]))
def test_ids_are_renamed_exactly_where_the_regular_expressions_rename_them(svg, prefix):
    assert prefixed_ids(svg, prefix) == _prefixed_by_regex(svg, prefix)


def test_a_label_is_named_only_as_a_whole_word():
    drawn = "v₀ = 12 m/s along e_1; the angle α = 30°"
    assert _names_word(drawn, "v₀ = 12 m/s")
    assert _names_word(drawn, "α = 30°")
    assert not _names_word(drawn, "e")        # only inside e_1
    assert not _names_word(drawn, "2 m/s")    # after the 1 of 12
    assert not _names_word(drawn, "α = 3")    # before the 0 of 30
    assert not _names_word(drawn, "β")


@settings(max_examples=400, deadline=None)
@given(st.lists(st.sampled_from(["a", "b", " ", "_", "1", "°", "=", "é", "."]),
                max_size=20).map("".join),
       st.lists(st.sampled_from(["a", "b", " ", "_", "1", "°", "="]), min_size=1,
                max_size=3).map("".join))
def test_a_label_is_named_where_the_regular_expression_finds_it(text, word):
    expected = re.search(rf"(?<!\w){re.escape(word)}(?!\w)", text) is not None
    assert _names_word(text, word) is expected
