"""Particles of variable mass: rockets (mass loss) and mass accretion (Section 2.3.2).

Balance of linear momentum of a body that gains or loses mass at rate m_dot with the
gained/lost mass moving at velocity w:  m dv/dt = F + m_dot (w - v).  For a rocket the
exhaust leaves at relative speed u backwards, so the thrust is u |m_dot|.
"""
from __future__ import annotations

import numpy as np

from dynagrade.mechanics._common import Quantity
from dynagrade.mechanics.impact import impact_speed_after_fall


def mass_at_time(t: Quantity, initial_mass: Quantity, mass_rate: Quantity) -> Quantity:
    """Mass of a body that gains mass at the constant rate m_dot (negative for a loss),
    m(t) = m0 + m_dot t (Section 2.3.2)."""
    return initial_mass + mass_rate * t


def thrust(exhaust_speed: Quantity, mass_flow_rate: Quantity) -> Quantity:
    """Thrust of a rocket, F = u q with exhaust speed u relative to the rocket and the
    burned mass per time q = -dm/dt > 0 (Section 2.3.2)."""
    return exhaust_speed * mass_flow_rate


def rocket_speed_gain(exhaust_speed: Quantity, initial_mass: Quantity,
                      final_mass: Quantity) -> Quantity:
    """Speed gained by a rocket without external forces, Delta v = u ln(m0 / m)
    (rocket equation, Section 2.3.2)."""
    return exhaust_speed * np.log(initial_mass / final_mass)


def vertical_rocket_speed(t: Quantity, v0: Quantity, exhaust_speed: Quantity,
                          initial_mass: Quantity, mass_flow_rate: Quantity,
                          g: Quantity) -> Quantity:
    """Upward speed of a rocket launched vertically in uniform gravity with a constant
    burn rate q: v(t) = v0 + u ln(m0 / (m0 - q t)) - g t, valid while fuel is left
    (Section 2.3.2)."""
    mass = mass_at_time(t, initial_mass, -mass_flow_rate)
    return v0 + rocket_speed_gain(exhaust_speed, initial_mass, mass) - g * t


def vertical_rocket_height(t: Quantity, v0: Quantity, exhaust_speed: Quantity,
                           initial_mass: Quantity, mass_flow_rate: Quantity,
                           g: Quantity) -> Quantity:
    """Height of a vertically launched rocket with constant burn rate q, from integrating
    v(t): h(t) = v0 t + u [t - (m/q) ln(m0/m)] - 1/2 g t^2 with m = m0 - q t
    (Section 2.3.2)."""
    mass = mass_at_time(t, initial_mass, -mass_flow_rate)
    log_term = (mass / mass_flow_rate) * np.log(initial_mass / mass)
    return v0 * t + exhaust_speed * (t - log_term) - 0.5 * g * t**2


def burn_time(fuel_mass: Quantity, mass_flow_rate: Quantity) -> Quantity:
    """Duration of the burn, t_b = m_fuel / q at constant burn rate (Section 2.3.2)."""
    return fuel_mass / mass_flow_rate


def speed_after_accretion(initial_mass: Quantity, v0: Quantity, m: Quantity) -> Quantity:
    """Speed of a body that collects mass arriving with no velocity component along its
    motion and no external force in that direction (cart collecting load falling
    vertically): m v = m0 v0, so v = m0 v0 / m (Section 2.3.2)."""
    return initial_mass * v0 / m


def force_to_keep_speed_while_accreting(mass_rate: Quantity,
                                        relative_speed: Quantity) -> Quantity:
    """Force needed to keep a body at constant speed while it collects mass at rate
    m_dot that arrives with relative speed v - w: F = m_dot (v - w) (Section 2.3.2)."""
    return mass_rate * relative_speed


def chain_on_scale_force(rhoA: Quantity, fallen_length: Quantity, g: Quantity) -> Quantity:
    """Reading of a scale onto which a chain falls freely from rest (hanging vertically
    and released) with mass per length rhoA: the weight of the piled part rhoA g x plus
    the momentum flux of the arriving links rhoA v^2 = 2 rhoA g x, in total
    F = 3 rhoA g x (Section 2.3.2)."""
    speed = impact_speed_after_fall(fallen_length, g)
    momentum_flux = force_to_keep_speed_while_accreting(rhoA * speed, speed)
    return rhoA * g * fallen_length + momentum_flux
