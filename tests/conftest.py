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
