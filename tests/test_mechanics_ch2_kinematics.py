"""Kinematics of systems of particles (Section 2.1): the centre of mass, its velocity and
the coordinates relative to it, held against hand values and a second route."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from dynagrade.mechanics import systems

MASSES = [2.0, 1.0, 0.5]
POSITIONS = [[1.0, 0.5], [-1.0, 1.0], [0.5, -1.5]]
VELOCITIES = [[0.5, -1.0], [1.5, 0.5], [-1.0, 2.0]]


def test_centre_of_mass_velocity_by_hand():
    # M = 3.5 kg; sum m u = 1 + 1.5 - 0.5 = 2, sum m w = -2 + 0.5 + 1 = -0.5
    assert systems.centre_of_mass_velocity(MASSES, VELOCITIES) == pytest.approx(
        [2.0 / 3.5, -0.5 / 3.5])


def test_positions_relative_to_centre_of_mass_by_hand():
    # r_C = (1.25, 1.25)/3.5; rho_i = r_i - r_C
    rho = systems.positions_relative_to_centre_of_mass(MASSES, POSITIONS)
    c = 1.25 / 3.5
    assert rho == pytest.approx(np.array([[1.0 - c, 0.5 - c], [-1.0 - c, 1.0 - c],
                                          [0.5 - c, -1.5 - c]]))


def test_centre_of_mass_velocity_is_the_rate_of_the_centre_of_mass():
    # second route: particles on curved paths r_i(t); v_C against the central difference
    # of r_C(t)
    masses = np.array([0.7, 1.9, 3.2, 0.4])
    phase = np.array([0.0, 1.0, 2.5, 4.0])

    def paths(t):
        return np.column_stack([np.cos(2 * t + phase) + t**2, np.sin(t - phase) * (1 + t)])

    def rates(t):
        return np.column_stack([-2 * np.sin(2 * t + phase) + 2 * t,
                                np.cos(t - phase) * (1 + t) + np.sin(t - phase)])

    t, h = 0.8, 1e-5
    numerical = (systems.centre_of_mass(masses, paths(t + h))
                 - systems.centre_of_mass(masses, paths(t - h))) / (2 * h)
    assert systems.centre_of_mass_velocity(masses, rates(t)) == pytest.approx(numerical,
                                                                               rel=1e-8)


@settings(max_examples=60, deadline=None)
@given(masses=arrays(float, 4, elements=st.floats(0.1, 10.0)),
       positions=arrays(float, (4, 3), elements=st.floats(-10.0, 10.0)))
def test_mass_weighted_relative_positions_sum_to_zero(masses, positions):
    """The mass-weighted sum of the positions relative to the centre of mass is zero, and
    adding r_C back gives each position."""
    rho = systems.positions_relative_to_centre_of_mass(masses, positions)
    assert (masses[:, None] * rho).sum(axis=0) == pytest.approx(np.zeros(3), abs=1e-9)
    r_c = systems.centre_of_mass(masses, positions)
    assert rho + r_c == pytest.approx(positions, abs=1e-9)
