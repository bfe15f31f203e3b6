"""Shared test settings: a hypothesis profile that keeps the suite fast on two cores."""

import os

from hypothesis import HealthCheck, settings

settings.register_profile("ci", max_examples=50, deadline=None,
                          suppress_health_check=[HealthCheck.too_slow])
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))

import pytest


@pytest.fixture(scope="session")
def bank():
    """The shipped exercise bank."""
    from dynagrade.exercise import open_bank

    return open_bank()


@pytest.fixture(scope="session")
def exam_toml():
    """A three-exercise exam spec shared by the exam tests."""
    return """\
id = "dynamics-test-exam"
title = "Dynamics: test exam"
date = 2025-04-14
instructions = "Answer every part."

[[exercise]]
id = "projectile-range"
points = 6

[[exercise]]
id = "sliding-up-a-slope"
points = 6

[[exercise]]
id = "car-in-a-looping"
points = 8
[exercise.set]
g = 9.81
"""
