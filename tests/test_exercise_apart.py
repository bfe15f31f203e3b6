"""answers_apart: a variant's answers of different meaning print numbers far enough apart."""

from dynagrade.exercise.apart import answers_apart


def test_answers_that_print_the_same_number_in_their_units_are_not_apart():
    # 80 MPa and 80 us: 8e7 and 8e-5 in SI, but both print 80
    assert not answers_apart({"sigma": 80e6, "t": 80e-6}, {"sigma": 1e6, "t": 1e-6})


def test_answers_equal_in_si_are_not_apart_even_in_different_units():
    # 0.2548 s and 0.2548 m, the second asked in mm (254.8): equal in SI
    assert not answers_apart({"t": 0.2548, "x": 0.2548}, {"t": 1.0, "x": 1e-3})


def test_answers_eleven_percent_apart_in_si_and_in_their_units_are_apart():
    # 1.11 against 1.0 in SI; 1110 mm against 1.0 s in the parts' units
    assert answers_apart({"x": 1.11, "t": 1.0}, {"x": 1e-3, "t": 1.0})


def test_nine_percent_is_too_close_for_the_default_ten_percent_but_not_for_five():
    assert not answers_apart({"a": 1.09, "b": 1.0}, {"a": 1.0, "b": 1.0})
    assert answers_apart({"a": 1.09, "b": 1.0}, {"a": 1.0, "b": 1.0}, ratio=1.05)
