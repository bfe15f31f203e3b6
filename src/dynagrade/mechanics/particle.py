"""Kinetics of a single particle, Section 1.2.1: linear momentum, the forces of the
chapter-1 examples, and a numerical integrator of the linear momentum balance (1.61).
SI units; vectors as numpy arrays of 2 or 3 components.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Literal, Sequence

import numpy as np

from dynagrade.mechanics._common import ArrayLike, Field, Quantity

if TYPE_CHECKING:
    from scipy.integrate import OdeSolution


def particle_linear_momentum(m: Quantity, v: ArrayLike) -> Quantity:
    """Linear momentum P = m v, eq. (1.59)."""
    return m * np.asarray(v, dtype=float)


def acceleration(m: Quantity, *forces: Quantity) -> Quantity:
    """Acceleration from the linear momentum balance at constant mass, sum F = m a, eq. (1.63)."""
    return np.sum([np.asarray(f, dtype=float) for f in forces], axis=0) / m


def resultant_force(m: Quantity, a: ArrayLike) -> Quantity:
    """Resultant force that gives a particle of constant mass m the acceleration a,
    sum F = m a, eq. (1.63)."""
    return m * np.asarray(a, dtype=float)


def weight(m: Quantity, g: ArrayLike) -> Quantity:
    """Weight m g for the gravity vector g (e.g. (0, -9.81)), eq. (1.96)."""
    return m * np.asarray(g, dtype=float)


def spring_force(k: Quantity, x: ArrayLike, x0: Quantity) -> Quantity:
    """Force of a linear spring along its axis, -k (x - x0), eq. (1.97)."""
    return -k * (np.asarray(x, dtype=float) - x0)


def kinetic_friction(N: ArrayLike, v: ArrayLike, mu: Quantity) -> Quantity:
    """Coulomb sliding friction R = -mu |N| v/|v|, eq. (1.74)/(1.103); zero when v = 0."""
    v = np.asarray(v, dtype=float)
    speed = np.linalg.norm(v, axis=-1, keepdims=True)
    with np.errstate(invalid="ignore", divide="ignore"):
        direction = np.where(speed > 0.0, v / np.where(speed > 0, speed, 1.0), 0.0)
    return -mu * np.abs(np.asarray(N, dtype=float))[..., None] * direction


def linear_drag_force(v: ArrayLike, k: Quantity) -> Quantity:
    """Viscous (Stokes) drag F_d = -k v, eq. (1.104)."""
    return -k * np.asarray(v, dtype=float)


def quadratic_drag_force(v: ArrayLike, c: Quantity) -> Quantity:
    """Rayleigh drag F_d = -c |v| v (footnote 2 of Example 1.2)."""
    v = np.asarray(v, dtype=float)
    return -c * np.linalg.norm(v, axis=-1, keepdims=True) * v


def floor_normal_force(m: Quantity, g: Quantity) -> Quantity:
    """Normal force on a particle sliding on a horizontal floor, N = m g, eq. (1.70)."""
    return m * g


def floor_normal_force_under_pull(m: Quantity, g: Quantity, F: Quantity,
                                  theta: Quantity) -> Quantity:
    """Normal force on a particle kept on a horizontal floor while a force F pulls it at the
    angle theta above the floor: no acceleration normal to the floor, so
    N = m g - F sin(theta) (the e2 component of the balance, eqs. (1.68)-(1.69), with the
    pull added; N = m g of eq. (1.70) for theta = 0). Negative N means the particle lifts off."""
    return floor_normal_force(m, g) - F * np.sin(theta)


def string_tension(m: Quantity, l: Quantity, omega: Quantity) -> Quantity:
    """Magnitude of the string force on a particle circling at radius l with constant
    angular velocity omega (no gravity), |S| = m l omega^2, eq. (1.84)."""
    return m * l * omega**2


def sliding_stop_time(v0: Quantity, mu: Quantity, g: Quantity) -> Quantity:
    """Time for Coulomb friction to stop a particle sliding on a horizontal floor,
    v0/(mu g), eq. (1.73) with alpha = 0 integrated as in Example 1.1 (the slope's time to
    rest with a level slope)."""
    return v0 / (g * mu)


@dataclass(frozen=True)
class Trajectory:
    """Result of :func:`simulate`: times t (n,), positions r (n, d), velocities v (n, d),
    event times (a tuple of arrays, one per event) and the dense solution ``at(t)``."""

    t: np.ndarray
    r: np.ndarray
    v: np.ndarray
    event_times: tuple
    event_states: tuple
    solution: OdeSolution

    def at(self, t):
        """Position and velocity at time(s) t from the dense output."""
        y = self.solution(t)
        d = y.shape[0] // 2
        return y[:d].T, y[d:].T


def simulate(m: Quantity, r0: ArrayLike, v0: ArrayLike, force: Field, t_end: float,
             events: Sequence[Field] = (), rtol: float = 1e-9, atol: float = 1e-12,
             method: Literal["RK23", "RK45", "DOP853", "Radau", "BDF", "LSODA"] = "DOP853",
             max_step: float = np.inf) -> Trajectory:
    """Integrate the linear momentum balance m r'' = F(t, r, v) (eq. 1.61 at constant mass)
    from r(0) = r0, v(0) = v0 up to t_end with scipy's solve_ivp.

    ``force(t, r, v)`` returns the resultant force vector.  ``events`` are callables
    ``event(t, r, v)`` with optional ``terminal``/``direction`` attributes as in solve_ivp.
    The default DOP853 with rtol 1e-9 and atol 1e-12 keeps the energy drift of short runs
    near 1e-10 of the total."""
    from scipy.integrate import solve_ivp
    r0 = np.asarray(r0, dtype=float)
    d = r0.size

    def rhs(t, y):
        return np.concatenate([y[d:], np.asarray(force(t, y[:d], y[d:]), dtype=float) / m])

    wrapped = [_StateEvent(event, d) for event in events]
    y0 = np.concatenate([r0, np.asarray(v0, dtype=float)])
    sol = solve_ivp(rhs, (0.0, t_end), y0, method=method, events=wrapped or None,
                    rtol=rtol, atol=atol, dense_output=True, max_step=max_step)
    if sol.status < 0:
        raise RuntimeError(f"integration failed: {sol.message}")
    if sol.sol is None:  # dense_output=True always gives one
        raise RuntimeError("the integration returned no dense solution")
    # solve_ivp gives the events' lists when it was given events, None otherwise
    event_times = tuple(sol.t_events or ())
    event_states = tuple(sol.y_events or ())
    return Trajectory(t=sol.t, r=sol.y[:d].T, v=sol.y[d:].T, event_times=event_times,
                      event_states=event_states, solution=sol.sol)


class _StateEvent:
    """An event ``event(t, r, v)`` of :func:`simulate` as solve_ivp calls it, on the
    state y = (r, v), with the event's ``terminal`` and ``direction``."""

    def __init__(self, event: Field, d: int) -> None:
        self.event = event
        self.d = d
        self.terminal = getattr(event, "terminal", False)
        self.direction = getattr(event, "direction", 0)

    def __call__(self, t: float, y: np.ndarray) -> float:
        return float(self.event(t, y[:self.d], y[self.d:]))
