"""Particle kinematics, Section 1.1 of the notes: Cartesian motion from a known
acceleration (Examples 1.1, 1.2), constrained motion (1.1.2), polar coordinates (1.1.3)
and space curves (1.1.4).  SI units, angles in rad; floats or numpy arrays.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from dynagrade.mechanics._common import ArrayLike, Function, Quantity, spatial_vector


# --- 1.1.1 Cartesian frame: trajectories from a(t), a(v), a(x) ----------------------------

def velocity_from_acceleration(acceleration: Function, t: float, v0: float,
                               t0: float = 0.0) -> float:
    """Velocity at time t from a known 1D acceleration a(t) (a callable), eq. (1.9):
    v(t) = v(t0) + integral_{t0}^{t} a(tau) dtau, by quadrature."""
    from scipy.integrate import quad
    integral, _ = quad(acceleration, t0, t, epsabs=1e-13, epsrel=1e-11, limit=200)
    return v0 + integral


def position_from_acceleration(acceleration: Function, t: float, x0: float, v0: float,
                               t0: float = 0.0) -> float:
    """Position at time t from a known 1D acceleration a(t), eq. (1.10) with (1.9):
    x(t) = x0 + v0 (t - t0) + integral_{t0}^{t} (t - tau) a(tau) dtau (both integrations in one)."""
    from scipy.integrate import quad
    integral, _ = quad(lambda tau: (t - tau) * acceleration(tau), t0, t,
                       epsabs=1e-13, epsrel=1e-11, limit=200)
    return x0 + v0 * (t - t0) + integral


def release_velocity(t: Quantity, v0: ArrayLike, g: ArrayLike) -> Quantity:
    """Velocity vector of a particle released with velocity v0 under gravity g (a vector,
    e.g. (0, -9.81, 0)), eq. (1.11): v(t) = v(0) + g t.  Broadcasts over a column of times."""
    t = np.asarray(t, dtype=float)[..., None]
    return np.asarray(v0, dtype=float) + np.asarray(g, dtype=float) * t


def release_position(t: Quantity, r0: ArrayLike, v0: ArrayLike, g: ArrayLike) -> Quantity:
    """Position vector of a particle released from r0 with velocity v0 under gravity g
    (a vector), eq. (1.12): r(t) = g t^2/2 + v(0) t + r(0)."""
    t = np.asarray(t, dtype=float)[..., None]
    return (np.asarray(r0, dtype=float) + np.asarray(v0, dtype=float) * t
            + 0.5 * np.asarray(g, dtype=float) * t**2)


def speed_at_constant_acceleration(t: Quantity, v0: Quantity, a: Quantity) -> Quantity:
    """Speed (or path velocity s') after a time t under a constant acceleration a (or constant
    tangential acceleration a_t = s''), eq. (1.9) with a = const (cf. eq. 1.11): v = v0 + a t."""
    return v0 + a * t


def distance_at_constant_acceleration(t: Quantity, v0: Quantity, a: Quantity) -> Quantity:
    """Distance (or path length s along a space curve) covered in a time t from the speed v0
    under a constant (tangential) acceleration a, eq. (1.10) with a = const (cf. eq. 1.12):
    s = v0 t + a t^2 / 2."""
    return v0 * t + 0.5 * a * t**2


def time_from_rest_over_distance(s: Quantity, a: Quantity) -> Quantity:
    """Time to cover the distance s from rest under a constant acceleration a > 0, eq. (1.12)
    solved for t: s = a t^2 / 2, so t = sqrt(2 s / a)."""
    return np.sqrt(2.0 * s / a)


def linear_drag_velocity(t: ArrayLike, v0: Quantity, k: Quantity) -> Quantity:
    """Velocity under linear (Stokes) drag a = -k v, eq. (1.14): v(t) = v0 exp(-k t).
    Component-wise for vectors, eq. (1.15)."""
    return v0 * np.exp(-k * np.asarray(t, dtype=float))


def linear_drag_position(t: ArrayLike, v0: Quantity, k: Quantity,
                         x0: Quantity = 0.0) -> Quantity:
    """Position under linear drag, eq. (1.14) integrated once more with eq. (1.10):
    x(t) = x0 + v0 (1 - exp(-k t)) / k."""
    return x0 + v0 * (1.0 - np.exp(-k * np.asarray(t, dtype=float))) / k


def linear_drag_time_to_speed(v0: Quantity, v: Quantity, k: Quantity) -> Quantity:
    """Time for linear drag to slow the particle from v0 to v (same sign), eq. (1.13)/(1.14):
    t = ln(v0/v)/k."""
    return np.log(v0 / v) / k


def linear_drag_distance_to_speed(v0: Quantity, v: Quantity, k: Quantity) -> Quantity:
    """Distance covered while linear drag slows the particle from v0 to v, from
    a(x) = v dv/dx = -k v (eq. 1.17): x = (v0 - v)/k."""
    return (v0 - v) / k


def half_life(decay_rate: Quantity) -> Quantity:
    """Half-life ln(2) / k of a quantity decaying as exp(-k t), eq. (1.14): the time for
    linear drag to halve the speed.

    A decay rate of ln 2 per second halves the speed in one second.

    >>> round(float(half_life(np.log(2.0))), 12)
    1.0
    """
    return linear_drag_time_to_speed(1.0, 0.5, decay_rate)


def linear_drag_coasting_distance(v0: Quantity, k: Quantity) -> Quantity:
    """Total distance until rest under linear drag (t -> infinity), v0/k, limit of eq. (1.14)."""
    return v0 / k


def quadratic_drag_velocity(t: ArrayLike, v0: Quantity, k: Quantity) -> Quantity:
    """Velocity under quadratic (Rayleigh) drag a = -k v^2 (v0 > 0), separation of variables
    as in eq. (1.13), footnote 2: v(t) = v0 / (1 + k v0 t)."""
    return v0 / (1.0 + k * v0 * np.asarray(t, dtype=float))


def quadratic_drag_position(t: ArrayLike, v0: Quantity, k: Quantity,
                            x0: Quantity = 0.0) -> Quantity:
    """Position under quadratic drag a = -k v^2: x(t) = x0 + ln(1 + k v0 t)/k (eq. 1.10)."""
    return x0 + np.log1p(k * v0 * np.asarray(t, dtype=float)) / k


def quadratic_drag_distance_to_speed(v0: Quantity, v: Quantity, k: Quantity) -> Quantity:
    """Distance over which quadratic drag slows the particle from v0 to v, eq. (1.17):
    x = ln(v0/v)/k."""
    return np.log(v0 / v) / k


def time_from_velocity_field(velocity: Function, x0: float, x: float) -> float:
    """Time to travel from x0 to x when the velocity is a known function v(x) of position
    (a callable, no sign change on the way), eq. (1.16): t = integral dx / v(x)."""
    from scipy.integrate import quad
    integral, _ = quad(lambda s: 1.0 / velocity(s), x0, x, epsabs=1e-13, epsrel=1e-11, limit=200)
    return integral


def speed_from_acceleration_field(acceleration: Function, x0: float, x: float,
                                  v0: float) -> float:
    """Speed at position x when the acceleration is a known function a(x) (a callable),
    eq. (1.17): v^2/2 = v0^2/2 + integral_{x0}^{x} a(s) ds.  NaN where x is not reached."""
    from scipy.integrate import quad
    integral, _ = quad(acceleration, x0, x, epsabs=1e-13, epsrel=1e-11, limit=200)
    v_sq = v0**2 + 2.0 * integral
    return float(np.sqrt(v_sq)) if v_sq >= 0.0 else float("nan")


def gravity_at_height(x: ArrayLike, g: Quantity, R: Quantity) -> Quantity:
    """Gravitational acceleration (magnitude) at height x above a planet of radius R with
    surface value g, g(x) = g R^2 / (R + x)^2 (the rocket of Example 1.2, eq. 1.17)."""
    return g * R**2 / (R + np.asarray(x, dtype=float)) ** 2


def rocket_speed_at_height(x: ArrayLike, v0: Quantity, g: Quantity, R: Quantity) -> Quantity:
    """Speed at height x of a body launched vertically with v0 under g(x) = g R^2/(R+x)^2,
    eq. (1.17) integrated: v^2 = v0^2 - 2 g R x / (R + x).  NaN above the peak."""
    x = np.asarray(x, dtype=float)
    v_sq = v0**2 - 2.0 * g * R * x / (R + x)
    with np.errstate(invalid="ignore"):
        return np.where(v_sq >= 0.0, np.sqrt(np.maximum(v_sq, 0.0)), np.nan)


def rocket_peak_height(v0: Quantity, g: Quantity, R: Quantity) -> Quantity:
    """Greatest height reached under g(x) = g R^2/(R+x)^2, where v of eq. (1.17) vanishes:
    h = R v0^2 / (2 g R - v0^2); infinite at or above the escape speed.

    Launched at half the escape speed (v0^2 = g R / 2) it climbs R/3: h = R (gR/2) / (2gR - gR/2).

    >>> round(float(rocket_peak_height(np.sqrt(9.81 * 6.371e6 / 2), 9.81, 6.371e6) / 6.371e6), 12)
    0.333333333333
    """
    denominator = np.asarray(2.0 * g * R - v0**2, dtype=float)
    safe = np.where(denominator > 0.0, denominator, 1.0)
    return np.where(denominator > 0.0, R * v0**2 / safe, np.inf)


def escape_speed(g: Quantity, R: Quantity) -> Quantity:
    """Launch speed above which eq. (1.17) with g(x) = g R^2/(R+x)^2 never gives v = 0:
    sqrt(2 g R).

    The notes' Example 1.2 with the Earth's g = 9.81 m/s^2 and R = 6371 km: about
    11.2 km/s.

    >>> round(float(escape_speed(9.81, 6.371e6)))
    11180
    """
    return np.sqrt(2.0 * g * R)


# --- 1.1.2 constrained motion -------------------------------------------------------------

def degrees_of_freedom(d: Quantity, k: Quantity = 0) -> Quantity:
    """Degrees of freedom of a particle in d dimensions under k kinematic constraints,
    eqs. (1.2) and (1.21): d - k."""
    if not 1 <= d <= 3 or not 0 <= k <= d:
        raise ValueError(f"need 1 <= d <= 3 and 0 <= k <= d, got d={d}, k={k}")
    return d - k


# --- 1.1.3 polar coordinates --------------------------------------------------------------

def polar_basis(phi: ArrayLike) -> tuple[Quantity, Quantity]:
    """Co-rotating unit vectors (e_r, e_phi) in Cartesian components, eq. (1.27)/(1.28)."""
    phi = np.asarray(phi, dtype=float)
    e_r = np.stack([np.cos(phi), np.sin(phi)], axis=-1)
    e_phi = np.stack([-np.sin(phi), np.cos(phi)], axis=-1)
    return e_r, e_phi


def polar_velocity(r: Quantity, rdot: Quantity, phidot: Quantity) -> tuple[Quantity, Quantity]:
    """Polar components (v_r, v_phi) = (r', r phi') of the velocity, eq. (1.31)."""
    return rdot + 0.0 * r, r * phidot


def polar_acceleration(r: Quantity, rdot: Quantity, rddot: Quantity, phidot: Quantity,
                       phiddot: Quantity) -> tuple[Quantity, Quantity]:
    """Polar components (a_r, a_phi) = (r'' - r phi'^2, 2 r' phi' + r phi'') of the
    acceleration, eq. (1.33)."""
    return rddot - r * phidot**2, 2.0 * rdot * phidot + r * phiddot


def polar_to_cartesian(radial: ArrayLike, circumferential: ArrayLike, phi: Quantity) -> Quantity:
    """Cartesian components of the vector radial e_r + circumferential e_phi, eq. (1.29)
    with (1.27); e.g. eq. (1.25) for the velocity."""
    e_r, e_phi = polar_basis(phi)
    return (np.asarray(radial, dtype=float)[..., None] * e_r
            + np.asarray(circumferential, dtype=float)[..., None] * e_phi)


def circular_position(r: Quantity, phi: Quantity) -> Quantity:
    """Position on a circle of radius r about the origin, eq. (1.18)."""
    return polar_to_cartesian(r, 0.0 * np.asarray(phi, dtype=float), phi)


def circular_velocity(r: Quantity, phi: Quantity, phidot: Quantity) -> Quantity:
    """Velocity vector on a circle of constant radius r, eq. (1.19): r phi' e_phi."""
    return polar_to_cartesian(*polar_velocity(r, 0.0, phidot), phi)


def circular_acceleration(r: Quantity, phi: Quantity, phidot: Quantity,
                          phiddot: Quantity) -> Quantity:
    """Acceleration vector on a circle of constant radius r, eq. (1.20):
    -r phi'^2 e_r + r phi'' e_phi."""
    return polar_to_cartesian(*polar_acceleration(r, 0.0, 0.0, phidot, phiddot), phi)


def circular_speed(r: Quantity, phidot: Quantity) -> Quantity:
    """Speed on a circle of constant radius r at angular rate phi', v = r |phi'|,
    eqs. (1.19) and (1.53)."""
    return r * np.abs(phidot)


def angle_from_arc_length(s: Quantity, R: Quantity) -> Quantity:
    """Angle swept on a circle of radius R along the path length s, phi = s/R
    (s = R phi, Example 1.6, eq. (1.53))."""
    return s / R


def path_centripetal_acceleration(v: Quantity, rho: Quantity) -> Quantity:
    """Magnitude of the acceleration towards the centre of curvature, v^2/rho, eqs. (1.37), (1.51)."""
    return v**2 / rho


# --- 1.1.4 space curves -------------------------------------------------------------------

def radius_of_curvature_of_graph(fp: ArrayLike, fpp: ArrayLike) -> Quantity:
    """Radius of curvature of the plane curve x2 = f(x1) from f' and f'', eq. (1.48):
    rho = (1 + f'^2)^(3/2) / |f''| (infinite where f'' = 0)."""
    fpp = np.asarray(fpp, dtype=float)
    with np.errstate(divide="ignore"):
        return (1.0 + np.asarray(fp, dtype=float) ** 2) ** 1.5 / np.abs(fpp)


def parabola_radius_of_curvature(c: Quantity, x1: ArrayLike) -> Quantity:
    """Radius of curvature of the parabola x2 = c x1^2 at x1, eq. (1.49):
    rho = (1 + (2 c x1)^2)^(3/2) / (2 |c|)."""
    return radius_of_curvature_of_graph(2.0 * c * np.asarray(x1, dtype=float), 2.0 * c)


def unit_tangent(v: ArrayLike) -> Quantity:
    """Unit tangent e_t = v/|v| of the trajectory, eq. (1.41)."""
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def tangential_acceleration(v: ArrayLike, a: ArrayLike) -> Quantity:
    """Path acceleration s'' = a . e_t, the e_t component of eq. (1.51)."""
    return np.sum(np.asarray(a, dtype=float) * unit_tangent(v), axis=-1)


def normal_acceleration(v: ArrayLike, a: ArrayLike) -> Quantity:
    """Magnitude of the acceleration normal to the path, v^2/rho = |v x a|/|v|, eq. (1.51)."""
    cross = np.cross(spatial_vector(v), spatial_vector(a))
    return np.linalg.norm(cross, axis=-1) / np.linalg.norm(np.asarray(v, dtype=float), axis=-1)


def principal_normal(v: ArrayLike, a: ArrayLike) -> Quantity:
    """Principal normal e_n, the unit part of a normal to v, pointing to the centre of
    curvature, eqs. (1.44)-(1.50)."""
    a = np.asarray(a, dtype=float)
    e_t = unit_tangent(v)
    a_n = a - np.asarray(tangential_acceleration(v, a))[..., None] * e_t
    return a_n / np.linalg.norm(a_n, axis=-1, keepdims=True)


def binormal(v: ArrayLike, a: ArrayLike) -> Quantity:
    """Binormal e_b = e_t x e_n, eq. (1.52) (3D components)."""
    return np.cross(spatial_vector(unit_tangent(v)), spatial_vector(principal_normal(v, a)))


def radius_of_curvature(v: ArrayLike, a: ArrayLike) -> Quantity:
    """Radius of curvature of the path at a point with velocity v and acceleration a
    (any parametrisation in time), rho = |v|^3 / |v x a|, from eq. (1.51): infinite on a
    straight stretch (v x a = 0), undefined (nan) where the particle is at rest."""
    speed = np.linalg.norm(np.asarray(v, dtype=float), axis=-1)
    with np.errstate(divide="ignore", invalid="ignore"):
        return speed**3 / np.linalg.norm(np.cross(spatial_vector(v), spatial_vector(a)), axis=-1)


def acceleration_magnitude(tangential: Quantity, normal: Quantity) -> Quantity:
    """Magnitude of the acceleration from its space-curve components,
    |a| = sqrt(s''^2 + (v^2/rho)^2), e_t and e_n being orthonormal in eq. (1.51)."""
    return np.hypot(tangential, normal)


@dataclass(frozen=True)
class PathAcceleration:
    """Acceleration in the space-curve frame, eq. (1.51): a = s'' e_t + (v^2/rho) e_n."""

    tangential: Quantity
    normal: Quantity
    rho: Quantity


def path_acceleration(v: ArrayLike, a: ArrayLike) -> PathAcceleration:
    """Split a known (v, a) into the space-curve components of eq. (1.51)."""
    return PathAcceleration(tangential=tangential_acceleration(v, a),
                            normal=normal_acceleration(v, a), rho=radius_of_curvature(v, a))


# --- Bank exercises of issue 31, chapter 1: constrained, polar and space-curve relations ----

def hauled_speed(x: Quantity, h: Quantity, u: Quantity) -> Quantity:
    """Speed of a body on a horizontal surface hauled by a rope that runs to a fixed point
    at the height h above the surface and is pulled in at the constant rate u, when the body
    is at the horizontal distance x from that point: the rope is a kinematic constraint
    (Section 1.1.2, Example 1.4(d)), sqrt(x^2 + h^2) = l(t) with l' = -u, and differentiating
    it once, x x' = l l', gives |x'| = u sqrt(x^2 + h^2) / x."""
    return u * np.hypot(x, h) / x


def hauled_acceleration(x: Quantity, h: Quantity, u: Quantity) -> Quantity:
    """Magnitude of the acceleration of the hauled body of :func:`hauled_speed`: the
    constraint differentiated twice, x x'' + x'^2 = l'^2 = u^2 (l'' = 0), so
    |x''| = u^2 h^2 / x^3, directed toward the point below the rope's end: the body speeds
    up although the rope runs at a constant rate (Section 1.1.2)."""
    return u**2 * h**2 / x**3


def hauling_time(x0: Quantity, x1: Quantity, h: Quantity, u: Quantity) -> Quantity:
    """Time for the rope of :func:`hauled_speed` to bring the body from the horizontal
    distance x0 to x1 < x0: the rope shortens by sqrt(x0^2 + h^2) - sqrt(x1^2 + h^2) at the
    rate u (the constraint of Section 1.1.2 read as l(t) = l(0) - u t)."""
    return (np.hypot(x0, h) - np.hypot(x1, h)) / u


def inclined_plane_normal(alpha: Quantity, beta: Quantity) -> Quantity:
    """Unit normal n of a plane through the origin inclined at alpha to the horizontal
    (e1, e2 horizontal, e3 up), its steepest ascent pointing at the azimuth beta from e1:
    n = (-sin alpha cos beta, -sin alpha sin beta, cos alpha), the n of the constraint
    r . n = 0 of Example 1.4(c)."""
    return np.array([-np.sin(alpha) * np.cos(beta), -np.sin(alpha) * np.sin(beta),
                     np.cos(alpha)])


def vertical_component_in_plane(normal: ArrayLike, horizontal: ArrayLike) -> Quantity:
    """Vertical (e3) component of a vector that lies in the plane r . n = 0 through the
    origin, from its two horizontal components: -(n1 x1 + n2 x2)/n3 (Example 1.4(c), the
    one kinematic constraint of eq. (1.21)). The constraint differentiated in time,
    v . n = 0 and a . n = 0, makes it hold for the velocity and the acceleration too."""
    n = np.asarray(normal, dtype=float)
    x = np.asarray(horizontal, dtype=float)
    return -(n[0] * x[..., 0] + n[1] * x[..., 1]) / n[2]


def polar_coordinate_rates(r: Quantity, phi: Quantity, v: ArrayLike) -> tuple[Quantity, Quantity]:
    """Rates (r', phi') of the polar coordinates of a particle at (r, phi) whose velocity v
    is known in Cartesian components: eq. (1.31) projected on the co-rotating basis (1.27),
    r' = v . e_r and phi' = (v . e_phi) / r (eq. (1.30))."""
    e_r, e_phi = polar_basis(phi)
    v = np.asarray(v, dtype=float)
    return float(v @ e_r), float(v @ e_phi) / r


def polar_coordinate_accelerations(r: Quantity, phi: Quantity, rdot: Quantity, phidot: Quantity,
                                   a: ArrayLike) -> tuple[Quantity, Quantity]:
    """Second rates (r'', phi'') of the polar coordinates of a particle whose acceleration a
    is known in Cartesian components: eq. (1.33) solved for them, r'' = a . e_r + r phi'^2
    and phi'' = (a . e_phi - 2 r' phi') / r (eq. (1.32))."""
    e_r, e_phi = polar_basis(phi)
    a = np.asarray(a, dtype=float)
    return float(a @ e_r) + r * phidot**2, (float(a @ e_phi) - 2 * rdot * phidot) / r


def helix_radius_of_curvature(R: Quantity, H: Quantity) -> Quantity:
    """Radius of curvature of a helix of radius R that rises by H per turn,
    r(phi) = (R cos phi, R sin phi, H phi / (2 pi)): rho = (R^2 + c^2)/R with c = H/(2 pi),
    from rho = |v|^3 / |v x a| of eq. (1.51) (the same at every point; a flat circle,
    H = 0, has rho = R as in Example 1.6)."""
    c = H / (2.0 * np.pi)
    return (R**2 + c**2) / R


def helix_angular_rate(R: Quantity, H: Quantity, v: Quantity) -> Quantity:
    """Rate phi' at which a particle moving at the speed v along the helix of
    :func:`helix_radius_of_curvature` goes round its axis: ds = sqrt(R^2 + c^2) dphi, so
    phi' = v / sqrt(R^2 + c^2) with c = H/(2 pi) (eq. (1.40), v = s')."""
    return v / np.hypot(R, H / (2.0 * np.pi))
