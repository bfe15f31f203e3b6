"""The plain-text tables of `grade FILE` and `dynagrade list`."""

from dynagrade.render.text_table import text_table


def test_columns_are_as_wide_as_their_widest_cell_when_the_table_fits():
    table = text_table(("part", "verdict"), [("x_max", "correct"), ("h", "not answered")],
                       title="T", caption="total 1 / 2", width=80)
    assert table.splitlines() == [
        "T", "",
        "part   verdict",
        "-----  ------------",
        "x_max  correct",
        "h      not answered",
        "", "total 1 / 2"]


def test_a_long_cell_is_wrapped_at_spaces_to_fit_the_width():
    feedback = "Not correct: 12.5 m is not within the tolerance (1 %)."
    table = text_table(("part", "feedback"), [("x_max", feedback)], width=30)
    lines = table.splitlines()
    assert max(len(line) for line in lines) <= 30
    # the feedback column is 30 - 5 - 2 = 23 wide: the words wrap, none is broken
    assert lines[2:] == ["x_max  Not correct: 12.5 m is",
                         "       not within the",
                         "       tolerance (1 %)."]


def test_whole_words_are_kept_while_another_column_can_narrow():
    ident = "release-under-gravity"
    table = text_table(("id", "title"), [(ident, "Release under gravity: position")],
                       width=40)
    assert all(len(line) <= 40 for line in table.splitlines())
    assert ident in table.splitlines()[2]


def test_words_are_broken_only_when_whole_words_cannot_fit():
    table = text_table(("id",), [("a" * 30,)], width=20)
    assert table.splitlines()[2:] == ["a" * 20, "a" * 10]


def test_a_column_whose_header_and_cells_are_all_empty_is_drawn_without_failing():
    # list --by-section's last column is empty once every section has enough exercises
    lines = text_table(("section", ""), [("1.1.1", ""), ("1.1.2", "")], width=40).splitlines()
    assert [line.rstrip() for line in lines] == ["section", "-------", "1.1.1", "1.1.2"]
