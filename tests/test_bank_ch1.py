"""The new bank exercises of issue 31 for Sections 1.1.2-1.1.4, 1.2.4 and 2.1, each at one
variant worked by hand, and the core relations they added, each against a second route
(numerical integration or differentiation, a limit)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from dynagrade.exercise import open_bank
from dynagrade.mechanics import kinematics, systems


#: the variants worked by hand below, in the parameters' declared units
HAND = {
    "boat-hauled-to-quay": {"h": 3.0, "u": 0.4, "x": 4.0},
    "puck-on-tilted-plane": {"alpha": 30, "beta": 60, "x1": 1.0, "x2": -1.0, "v1": 2.0, "v2": 1.0},
    "radar-tracking-level-flight": {"h": 1000, "v": 100, "phi": 30},
    "telescoping-arm": {"r0": 0.5, "b": 0.2, "eps": 1.0, "t": 2.0},
    "helical-slide": {"R": 2.0, "H": 6.0, "v": 4.0, "at": 3.0},
    "ball-rolling-off-table": {"h": 1.0, "u": 2.0, "e": 0.6, "g": 9.81},
    "planet-moon-barycentre": {"q": 0.05, "R": 4000, "d": 60000, "w": 1.05},
    "linked-pucks": {"mA": 1.0, "mB": 3.0, "L": 0.5, "theta": 60, "aA": 1.0, "bA": 0.0, "uB": 0.0},
}


@pytest.fixture(scope="module")
def bank():
    return open_bank()


def _answers(bank, exercise_id, params):
    """The key of the variant with the given parameters (in their declared units), in SI."""
    exercise = bank.get(exercise_id)
    return exercise.solve(exercise.si(exercise.variant(0, params).params))


# --- Section 1.1.2: the boat hauled by a winch ----------------------------------------------

def _haul(h, u, x0, until):
    """x(t) of the hauled boat, integrated from x' = -u sqrt(x^2 + h^2)/x (the rope's
    length shrinking at u), with a dense output."""
    from scipy.integrate import solve_ivp   # here: collecting the suite imports no scipy
    return solve_ivp(lambda t, y: [-u * math.hypot(y[0], h) / y[0]], (0.0, until), [x0],
                     dense_output=True, rtol=1e-10, atol=1e-12)


def test_the_hauled_speed_and_acceleration_are_the_integrated_motions_derivatives():
    h, u, x0 = 2.0, 0.7, 5.0
    motion = _haul(h, u, x0, 1.0)
    x = lambda t: float(motion.sol(t)[0])  # noqa: E731
    dt = 1e-3
    speed = (x(0.5 - dt) - x(0.5 + dt)) / (2 * dt)
    acceleration = (x(0.5 + dt) - 2 * x(0.5) + x(0.5 - dt)) / dt**2
    assert kinematics.hauled_speed(x(0.5), h, u) == pytest.approx(speed, rel=1e-5)
    assert kinematics.hauled_acceleration(x(0.5), h, u) == pytest.approx(-acceleration, rel=1e-4)


def test_the_hauling_time_is_when_the_integrated_boat_reaches_the_distance():
    h, u, x0, x1 = 2.0, 0.7, 5.0, 1.5
    t = kinematics.hauling_time(x0, x1, h, u)
    assert float(_haul(h, u, x0, t).sol(t)[0]) == pytest.approx(x1, rel=1e-7)


def test_a_hauled_body_far_away_moves_as_fast_as_the_rope_and_does_not_accelerate():
    assert kinematics.hauled_speed(1e6, 1.0, 0.8) == pytest.approx(0.8)
    assert kinematics.hauled_acceleration(1e6, 1.0, 0.8) == pytest.approx(0.0, abs=1e-12)


def test_boat_hauled_to_quay_at_a_variant_worked_by_hand(bank):
    # h = 3 m, u = 0.4 m/s, x = 4 m: the rope is l = sqrt(16 + 9) = 5 m long
    # v = u l / x = 0.4 * 5 / 4 = 0.5 m/s
    # a = u^2 h^2 / x^3 = 0.16 * 9 / 64 = 0.0225 m/s^2
    # at x/2 = 2 m the rope is sqrt(4 + 9) = 3.605551 m: t = (5 - 3.605551)/0.4 = 3.486122 s
    key = _answers(bank, "boat-hauled-to-quay", HAND["boat-hauled-to-quay"])
    assert key["v"] == pytest.approx(0.5, rel=1e-9)
    assert key["a"] == pytest.approx(0.0225, rel=1e-9)
    assert key["t_half"] == pytest.approx(3.486122, rel=1e-6)


# --- Section 1.1.2: the puck on a tilted plane ----------------------------------------------

def test_a_point_of_the_tilted_plane_has_the_height_its_uphill_distance_times_sin_alpha():
    # the plane spanned by uphill u = (cos a cos b, cos a sin b, sin a) and level
    # l = (-sin b, cos b, 0): the point 1.5 u - 0.7 l lies in it at the height 1.5 sin a
    alpha, beta = math.radians(25.0), math.radians(-40.0)
    u = np.array([math.cos(alpha) * math.cos(beta), math.cos(alpha) * math.sin(beta), math.sin(alpha)])
    level = np.array([-math.sin(beta), math.cos(beta), 0.0])
    point = 1.5 * u - 0.7 * level
    n = kinematics.inclined_plane_normal(alpha, beta)
    assert np.linalg.norm(n) == pytest.approx(1.0)
    assert float(n @ u) == pytest.approx(0.0, abs=1e-15) and float(n @ level) == pytest.approx(0.0, abs=1e-15)
    assert kinematics.vertical_component_in_plane(n, point[:2]) == pytest.approx(1.5 * math.sin(alpha))


def test_puck_on_tilted_plane_at_a_variant_worked_by_hand(bank):
    # alpha = 30 deg (tan = 0.577350), beta = 60 deg (cos = 0.5, sin = 0.866025)
    # x3 = tan(a) (x1 cos b + x2 sin b) = 0.577350 * (0.5 - 0.866025) = -0.211325 m
    # v3 = tan(a) (v1 cos b + v2 sin b) = 0.577350 * (1.0 + 0.866025) = 1.077350 m/s
    # |v| = sqrt(2^2 + 1^2 + 1.077350^2) = sqrt(6.160684) = 2.482072 m/s
    key = _answers(bank, "puck-on-tilted-plane", HAND["puck-on-tilted-plane"])
    assert key["x3"] == pytest.approx(-0.211325, rel=1e-5)
    assert key["v3"] == pytest.approx(1.077350, rel=1e-6)
    assert key["speed"] == pytest.approx(2.482072, rel=1e-6)


# --- Section 1.1.3: the radar tracking an aircraft ------------------------------------------

def _polar_readings(t):
    """r(t) and phi(t) of the accelerating Cartesian path x = (2 + t + cos 2t, 1 + t^2)."""
    x1, x2 = 2.0 + t + math.cos(2 * t), 1.0 + t**2
    return math.hypot(x1, x2), math.atan2(x2, x1)


def test_the_polar_rates_are_the_differenced_polar_readings_of_a_cartesian_path():
    t, dt = 0.7, 1e-4
    # v = (1 - 2 sin 2t, 2 t), a = (-4 cos 2t, 2) at t = 0.7
    v = (1 - 2 * math.sin(1.4), 1.4)
    a = (-4 * math.cos(1.4), 2.0)
    r, phi = _polar_readings(t)
    before, after = _polar_readings(t - dt), _polar_readings(t + dt)
    rdot, phidot = kinematics.polar_coordinate_rates(r, phi, v)
    assert rdot == pytest.approx((after[0] - before[0]) / (2 * dt), rel=1e-6)
    assert phidot == pytest.approx((after[1] - before[1]) / (2 * dt), rel=1e-6)
    rddot, phiddot = kinematics.polar_coordinate_accelerations(r, phi, rdot, phidot, a)
    assert rddot == pytest.approx((after[0] - 2 * r + before[0]) / dt**2, rel=1e-4)
    assert phiddot == pytest.approx((after[1] - 2 * phi + before[1]) / dt**2, rel=1e-4)


def test_radar_tracking_level_flight_at_a_variant_worked_by_hand(bank):
    # h = 1000 m, v = 100 m/s, phi = 30 deg: r = h / sin(phi) = 2000 m
    # rdot = -v cos(phi) = -86.602540 m/s;  phidot = v sin(phi) / r = 50/2000 = 0.025 rad/s
    # a = 0: rddot = r phidot^2 = 2000 * 0.025^2 = 1.25 m/s^2
    #        phiddot = -2 rdot phidot / r = 2 * 86.602540 * 0.025 / 2000 = 0.00216506 rad/s^2
    key = _answers(bank, "radar-tracking-level-flight", HAND["radar-tracking-level-flight"])
    assert key["r"] == pytest.approx(2000.0, rel=1e-9)
    assert key["rdot"] == pytest.approx(-86.602540, rel=1e-7)
    assert key["phidot"] == pytest.approx(0.025, rel=1e-9)
    assert key["rddot"] == pytest.approx(1.25, rel=1e-9)
    assert key["phiddot"] == pytest.approx(0.00216506, rel=1e-5)


# --- Section 1.1.3: the telescoping arm (core relations of eqs. (1.31), (1.33) exist) -------

def test_telescoping_arm_at_a_variant_worked_by_hand(bank):
    # r0 = 0.5 m, r'' = 0.2 m/s^2, phi'' = 1 rad/s^2, t = 2 s, both from rest:
    # r' = 0.4 m/s, r = 0.5 + 0.2 * 4 / 2 = 0.9 m, phi' = 2 rad/s
    # v = (r', r phi') = (0.4, 1.8) m/s
    # a_r = r'' - r phi'^2 = 0.2 - 0.9 * 4 = -3.4 m/s^2
    # a_phi = 2 r' phi' + r phi'' = 1.6 + 0.9 = 2.5 m/s^2;  |a| = sqrt(11.56 + 6.25) = 4.220190
    key = _answers(bank, "telescoping-arm", HAND["telescoping-arm"])
    assert key["v"] == pytest.approx((0.4, 1.8), rel=1e-9)
    assert key["a"] == pytest.approx((-3.4, 2.5), rel=1e-9)
    assert key["a_abs"] == pytest.approx(4.220190, rel=1e-6)


# --- Section 1.1.4: the helical slide --------------------------------------------------------

def test_the_helix_relations_agree_with_the_curvature_of_its_differenced_path():
    # r(phi) = (R cos phi, R sin phi, c phi) run at phi' = 1: v and a by central differences,
    # then rho = |v|^3 / |v x a| (eq. (1.51)) and the speed |v| = phi' sqrt(R^2 + c^2)
    R, H, dt = 2.0, 5.0, 1e-4
    c = H / (2 * math.pi)
    path = lambda t: np.array([R * math.cos(t), R * math.sin(t), c * t])  # noqa: E731
    v = (path(0.3 + dt) - path(0.3 - dt)) / (2 * dt)
    a = (path(0.3 + dt) - 2 * path(0.3) + path(0.3 - dt)) / dt**2
    rho = np.linalg.norm(v)**3 / np.linalg.norm(np.cross(v, a))
    assert kinematics.helix_radius_of_curvature(R, H) == pytest.approx(rho, rel=1e-6)
    assert kinematics.helix_angular_rate(R, H, np.linalg.norm(v)) == pytest.approx(1.0, rel=1e-7)
    assert kinematics.helix_radius_of_curvature(R, 0.0) == R          # a flat circle


def test_helical_slide_at_a_variant_worked_by_hand(bank):
    # R = 2 m, H = 6 m:
    # c = 6 / (2 pi) = 0.954930 m, c^2 = 0.911891, R^2 + c^2 = 4.911891
    # rho = 4.911891 / 2 = 2.455945 m
    # v = 4 m/s: a_n = 16 / 2.455945 = 6.514803 m/s^2
    # s'' = 3 m/s^2: |a| = sqrt(9 + 42.442658) = 7.172354 m/s^2
    # phi' = 4 / sqrt(4.911891) = 4 / 2.216279 = 1.804827 rad/s
    key = _answers(bank, "helical-slide", HAND["helical-slide"])
    assert key["rho"] == pytest.approx(2.455945, rel=1e-6)
    assert key["a_n"] == pytest.approx(6.514803, rel=1e-6)
    assert key["a_abs"] == pytest.approx(7.172354, rel=1e-6)
    assert key["phidot"] == pytest.approx(1.804827, rel=1e-6)


# --- Section 1.2.4: the ball rolling off a table (keys from existing impact relations) -------

def test_ball_rolling_off_table_at_a_variant_worked_by_hand(bank):
    # h = 1 m, u = 2 m/s, e = 0.6, g = 9.81 m/s^2
    # fall time sqrt(2/9.81) = 0.451524 s, so x1 = 2 * 0.451524 = 0.903047 m
    # vertical speed at the floor sqrt(19.62) = 4.429447 m/s, after it 0.6 * that = 2.657668 m/s
    # beta = atan(2.657668 / 2) = 53.0371 deg;  h1 = 0.36 * 1 = 0.36 m
    # the bounce lasts 2 * 2.657668 / 9.81 = 0.541828 s: d12 = 2 * 0.541828 = 1.083657 m
    key = _answers(bank, "ball-rolling-off-table", HAND["ball-rolling-off-table"])
    assert key["x1"] == pytest.approx(0.903047, rel=1e-6)
    assert math.degrees(key["beta"]) == pytest.approx(53.0371, rel=1e-6)
    assert key["h1"] == pytest.approx(0.36, rel=1e-9)
    assert key["d12"] == pytest.approx(1.083657, rel=1e-6)


# --- Section 2.1: planet and moon (keys from existing relative-coordinate relations) --------

def test_planet_moon_barycentre_at_a_variant_worked_by_hand(bank):
    # q = 0.05, d = 60000 km, w = 1.05 km/s, R = 4000 km: M = 1.05 planet masses
    # |r1 - rC| = q d / (1 + q) = 0.05 * 60000 / 1.05 = 2857.142857 km < R: inside
    # planet relative to C: q w / (1 + q) = 0.05 * 1050 / 1.05 = 50 m/s
    # moon relative to C: w / (1 + q) = 1050 / 1.05 = 1000 m/s
    key = _answers(bank, "planet-moon-barycentre", HAND["planet-moon-barycentre"])
    assert key["x_C"] == pytest.approx(2857142.857, rel=1e-9)
    assert key["inside"] == "inside"
    assert key["v_planet"] == pytest.approx(50.0, rel=1e-9)
    assert key["v_moon"] == pytest.approx(1000.0, rel=1e-9)


def test_a_heavier_moon_farther_out_pulls_the_centre_of_mass_outside_the_planet(bank):
    # q = 0.1, d = 110000 km: q d / (1 + q) = 11000 / 1.1 = 10000 km > R = 5000 km
    key = _answers(bank, "planet-moon-barycentre", {"q": 0.1, "R": 5000, "d": 110000, "w": 1.0})
    assert key["x_C"] == pytest.approx(1.0e7, rel=1e-9)
    assert key["inside"] == "outside"


# --- Section 2.1: two pucks joined by a rigid rod --------------------------------------------

def test_the_rigid_link_relations_recover_a_turning_rods_differenced_motion():
    # A moves at vA, the rod (length L) turns at omega from theta: rB(t) = vA t +
    # L (cos(theta + omega t), sin(theta + omega t)); vB by a central difference
    vA, L, theta, omega, dt = np.array([0.4, -0.3]), 0.8, math.radians(35.0), -1.7, 1e-6
    rB = lambda t: vA * t + L * np.array([math.cos(theta + omega * t), math.sin(theta + omega * t)])  # noqa: E731
    vB = (rB(dt) - rB(-dt)) / (2 * dt)
    assert systems.rigid_link_second_velocity(theta, vA, vB[0]) == pytest.approx(vB[1], rel=1e-8)
    assert systems.rigid_link_angular_velocity(theta, L, vA, vB) == pytest.approx(omega, rel=1e-8)


def test_linked_pucks_at_a_variant_worked_by_hand(bank):
    # mA = 1 kg, mB = 3 kg, L = 0.5 m, theta = 60 deg (cot = 0.577350), vA = (1, 0), x_B' = 0
    # y_B' = y_A' - (x_B' - x_A') cot(theta) = 0 + 1 * 0.577350 = 0.577350 m/s
    # v_C = (1 * (1, 0) + 3 * (0, 0.577350)) / 4 = (0.25, 0.433013) m/s
    # omega = (cos(theta) (y_B' - y_A') - sin(theta) (x_B' - x_A')) / L
    #       = (0.5 * 0.577350 + 0.866025) / 0.5 = 2.309401 rad/s
    # |vB - vA| = sqrt(1 + 0.333333) = 1.154701 m/s, B's share mA/M = 1/4: 0.288675 m/s
    key = _answers(bank, "linked-pucks", HAND["linked-pucks"])
    assert key["yB"] == pytest.approx(0.577350, rel=1e-6)
    assert key["v_C"] == pytest.approx((0.25, 0.433013), rel=1e-6)
    assert key["omega"] == pytest.approx(2.309401, rel=1e-6)
    assert key["rel_B"] == pytest.approx(0.288675, rel=1e-6)


# --- the misconceptions, at the hand-worked variants above ------------------------------------


@pytest.mark.parametrize("exercise_id, part, answer, misconception", [
    # the boat taken as fast as the rope: u = 0.4 m/s
    ("boat-hauled-to-quay", "v", "0.4", "boat as fast as the rope"),
    # the camera's horizontal speed sqrt(2^2 + 1^2) = 2.236068 m/s
    ("puck-on-tilted-plane", "speed", "2.236068", "the camera's speed"),
    # v sin(phi) / h = 100 * 0.5 / 1000 = 0.05 rad/s instead of / r
    ("radar-tracking-level-flight", "phidot", "0.05", "whole speed over r"),
    # a_r without -r phi'^2: (0.2, 2.5)
    ("telescoping-arm", "a", "[0.2, 2.5]", "centripetal term missing"),
    # rho = R = 2 m
    ("helical-slide", "rho", "2", "the helix's radius"),
    # e h = 0.6 m instead of e^2 h
    ("ball-rolling-off-table", "h1", "0.6", "e applied to the height"),
    # the midpoint d/2 = 30000 km
    ("planet-moon-barycentre", "x_C", "30000", "the midpoint"),
    # the plain mean ((1 + 0)/2, (0 + 0.577350)/2) = (0.5, 0.288675) m/s
    ("linked-pucks", "v_C", "[0.5, 0.288675]", "plain mean of the velocities"),
])
def test_a_named_mistake_worked_by_hand_gets_its_feedback(bank, exercise_id, part, answer, misconception):
    from dynagrade.exercise.scoring import grade_variant

    exercise = bank.get(exercise_id)
    variant = exercise.variant(0, HAND[exercise_id])
    (result,) = [r for r in grade_variant(exercise, variant, {part: answer}).parts if r.name == part]
    assert not result.correct and result.misconception == misconception
