"""Our course's own relations: the conical pendulum (a mass on a string of length L
circling at the angle theta from the vertical, Section 1.2.1). Each is tested against an
independent route in test_relations.py beside this file."""

import numpy as np


def conical_pendulum_angular_velocity(L, theta, g):
    """omega = sqrt(g / (L cos theta)), from the radial and vertical momentum balance."""
    return np.sqrt(g / (L * np.cos(theta)))


def conical_pendulum_tension(m, theta, g):
    """S = m g / cos(theta): the string carries the weight with its vertical component."""
    return m * g / np.cos(theta)
