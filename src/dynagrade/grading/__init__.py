"""Grading: a safe expression parser and the comparison of answers with references."""
