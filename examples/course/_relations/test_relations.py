"""The conical pendulum's relations against Newton's law on the circle, by hand."""

import numpy as np
import pytest

from . import conical_pendulum_angular_velocity, conical_pendulum_tension


def test_by_hand():
    # L = 1 m, theta = 60 deg, m = 2 kg: omega = sqrt(9.81/0.5) = 4.42945 rad/s, S = 39.24 N
    assert conical_pendulum_angular_velocity(1.0, np.pi / 3, 9.81) == pytest.approx(4.42945, abs=1e-5)
    assert conical_pendulum_tension(2.0, np.pi / 3, 9.81) == pytest.approx(39.24)


@pytest.mark.parametrize("L, theta", [(0.5, 0.3), (1.2, 0.9), (2.0, 1.3)])
def test_the_string_pulls_the_mass_round_its_circle(L, theta):
    m, g = 1.5, 9.81
    omega = conical_pendulum_angular_velocity(L, theta, g)
    S = conical_pendulum_tension(m, theta, g)
    assert S * np.sin(theta) == pytest.approx(m * omega**2 * L * np.sin(theta))
    assert S * np.cos(theta) == pytest.approx(m * g)
