"""Kinematics of Section 1.1 against independent routes: solve_ivp for the a(v), a(x)
problems, sympy differentiation for polar and circular motion, hand-worked values."""
import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from dynagrade.mechanics import kinematics as kin
from deferred import deferred

sp = deferred("sympy")
solve_ivp = deferred("scipy.integrate", "solve_ivp")


def test_trajectory_from_time_dependent_acceleration_by_quadrature_matches_hand_integration():
    # a(t) = 3 t^2 - 2: v = v0 + t^3 - 2t, x = x0 + v0 t + t^4/4 - t^2 (eqs. 1.9, 1.10)
    a = lambda t: 3 * t**2 - 2
    t, x0, v0 = 1.7, 0.4, -1.2
    assert kin.velocity_from_acceleration(a, t, v0) == pytest.approx(v0 + t**3 - 2 * t, rel=1e-12)
    assert kin.position_from_acceleration(a, t, x0, v0) == pytest.approx(
        x0 + v0 * t + t**4 / 4 - t**2, rel=1e-12)
    # started at t0 = 0.5 instead: v(t) = v0 + (t^3 - 2t) - (t0^3 - 2 t0)
    assert kin.velocity_from_acceleration(a, t, v0, t0=0.5) == pytest.approx(
        v0 + (t**3 - 2 * t) - (0.125 - 1.0), rel=1e-12)


@settings(max_examples=20, deadline=None)
@given(t=st.floats(0.0, 5.0), g=st.floats(1.0, 20.0),
       r0=st.lists(st.floats(-10, 10), min_size=3, max_size=3),
       v0=st.lists(st.floats(-20, 20), min_size=3, max_size=3))
def test_release_under_gravity_matches_quadrature_of_each_component(t, g, r0, v0):
    gvec = np.array([0.0, -g, 0.0])
    r = kin.release_position(t, r0, v0, gvec)
    v = kin.release_velocity(t, v0, gvec)
    for i in range(3):
        ai = lambda tau, i=i: gvec[i]
        assert v[i] == pytest.approx(kin.velocity_from_acceleration(ai, t, v0[i]), abs=1e-9)
        assert r[i] == pytest.approx(kin.position_from_acceleration(ai, t, r0[i], v0[i]), abs=1e-9)
    assert v[0] == v0[0] and v[2] == v0[2]          # only the x2 component changes (Ex. 1.1)


def _integrate_1d(accel, v0, t_end, events=()):
    return solve_ivp(lambda t, y: [y[1], accel(y[0], y[1])], (0.0, t_end), [0.0, v0],
                     events=events or None, rtol=1e-10, atol=1e-12, dense_output=True)


@settings(max_examples=20, deadline=None)
@given(v0=st.floats(0.5, 30.0), k=st.floats(0.05, 3.0), frac=st.floats(0.05, 0.95))
def test_linear_drag_closed_forms_match_integration(v0, k, frac):
    v_target = frac * v0

    def reached(t, y):
        return y[1] - v_target

    reached.terminal = True
    sol = _integrate_1d(lambda x, v: -k * v, v0, 100.0 / k, (reached,))
    assert sol.status == 1
    t_hit, x_hit = sol.t_events[0][0], sol.y_events[0][0][0]
    assert kin.linear_drag_time_to_speed(v0, v_target, k) == pytest.approx(t_hit, rel=1e-7)
    assert kin.linear_drag_distance_to_speed(v0, v_target, k) == pytest.approx(x_hit, rel=1e-7)
    t = 0.5 * t_hit
    x_num, v_num = sol.sol(t)
    assert kin.linear_drag_velocity(t, v0, k) == pytest.approx(v_num, rel=1e-7)
    assert kin.linear_drag_position(t, v0, k) == pytest.approx(x_num, rel=1e-7)
    assert kin.linear_drag_coasting_distance(v0, k) > x_hit


@settings(max_examples=20, deadline=None)
@given(v0=st.floats(0.5, 30.0), k=st.floats(0.01, 1.0), frac=st.floats(0.05, 0.95))
def test_quadratic_drag_closed_forms_match_integration(v0, k, frac):
    v_target = frac * v0

    def reached(t, y):
        return y[1] - v_target

    reached.terminal = True
    # by hand, 1/v - 1/v0 = k t: the target speed is reached at (1/v - 1/v0)/k
    t_reach = (1.0 / v_target - 1.0 / v0) / k
    sol = _integrate_1d(lambda x, v: -k * v * abs(v), v0, 1.5 * t_reach, (reached,))
    assert sol.status == 1
    t_hit, x_hit = sol.t_events[0][0], sol.y_events[0][0][0]
    assert kin.quadratic_drag_velocity(t_hit, v0, k) == pytest.approx(v_target, rel=1e-7)
    assert kin.quadratic_drag_position(t_hit, v0, k) == pytest.approx(x_hit, rel=1e-7)
    assert kin.quadratic_drag_distance_to_speed(v0, v_target, k) == pytest.approx(x_hit, rel=1e-7)


@settings(max_examples=20, deadline=None)
@given(frac=st.floats(0.1, 0.95), g=st.floats(5.0, 15.0), R=st.floats(1e5, 1e7))
def test_rocket_with_height_dependent_gravity_peaks_where_integration_stops(frac, g, R):
    v0 = frac * kin.escape_speed(g, R)

    def peak(t, y):
        return y[1]

    peak.terminal = True
    t_scale = v0 / g
    # the climb lasts about 27 v0/g at 95 % of the escape speed: 100 v0/g is past every peak
    sol = _integrate_1d(lambda x, v: -kin.gravity_at_height(x, g, R), v0, 100.0 * t_scale, (peak,))
    assert sol.status == 1
    h = sol.y_events[0][0][0]
    assert kin.rocket_peak_height(v0, g, R) == pytest.approx(h, rel=1e-6)
    # the general route of eq. (1.17): speed from quadrature of a(x)
    x_mid = 0.5 * h
    assert kin.speed_from_acceleration_field(lambda x: -kin.gravity_at_height(x, g, R), 0.0, x_mid,
                                             v0) == pytest.approx(float(kin.rocket_speed_at_height(
                                                 x_mid, v0, g, R)), rel=1e-8)
    # and the time to the peak from eq. (1.16) with v(x)
    t_peak = kin.time_from_velocity_field(lambda x: kin.rocket_speed_at_height(x, v0, g, R),
                                          0.0, 0.999999 * h)
    assert t_peak == pytest.approx(sol.t_events[0][0], rel=2e-3)


def test_constant_gravity_is_recovered_near_the_ground():
    # R -> infinity: peak height v0^2/(2g) of Example 1.9 with alpha = 90 deg
    assert kin.rocket_peak_height(10.0, 9.81, 1e12) == pytest.approx(100 / (2 * 9.81), rel=1e-9)
    assert kin.rocket_peak_height(kin.escape_speed(9.81, 6.4e6), 9.81, 6.4e6) == np.inf


def test_degrees_of_freedom_of_example_1_4():
    assert kin.degrees_of_freedom(3) == 3           # (a) free in 3D
    assert kin.degrees_of_freedom(2) == 2           # (b) free in 2D
    assert kin.degrees_of_freedom(3, 1) == 2        # (c) on a plane in 3D
    assert kin.degrees_of_freedom(2, 1) == 1        # (d) on a rigid link in 2D
    with pytest.raises(ValueError):
        kin.degrees_of_freedom(2, 3)


@pytest.fixture(scope="module")
def t_sym():
    """The time symbol of the sympy differentiations below."""
    return sp.symbols("t")


@settings(max_examples=20, deadline=None)
@given(c=st.lists(st.floats(-2, 2), min_size=6, max_size=6), t=st.floats(0.0, 2.0))
def test_polar_components_equal_projections_of_the_differentiated_cartesian_position(c, t, t_sym):
    # r(t), phi(t) quadratic polynomials; differentiate x = r cos phi, y = r sin phi with sympy
    r_expr = 2.5 + c[0] * t_sym + 0.5 * c[1] * t_sym**2
    phi_expr = c[2] + c[3] * t_sym + c[4] * t_sym**2
    pos = sp.Matrix([r_expr * sp.cos(phi_expr), r_expr * sp.sin(phi_expr)])
    vel = pos.diff(t_sym)
    acc = vel.diff(t_sym)
    val = lambda e: float(e.subs(t_sym, t))
    r, rd, rdd = (val(r_expr.diff(t_sym, n)) for n in range(3))
    phi, phd, phdd = (val(phi_expr.diff(t_sym, n)) for n in range(3))
    e_r, e_phi = kin.polar_basis(phi)
    v_c = np.array([val(x) for x in vel])
    a_c = np.array([val(x) for x in acc])
    assert np.allclose(kin.polar_velocity(r, rd, phd), (v_c @ e_r, v_c @ e_phi), atol=1e-10)
    assert np.allclose(kin.polar_acceleration(r, rd, rdd, phd, phdd), (a_c @ e_r, a_c @ e_phi),
                       atol=1e-9)
    assert np.allclose(kin.polar_to_cartesian(*kin.polar_velocity(r, rd, phd), phi), v_c, atol=1e-10)


def test_circular_motion_of_example_1_3_matches_sympy(t_sym):
    R = 1.3
    phi_expr = 0.4 * t_sym**2 + 0.2 * t_sym
    pos = sp.Matrix([R * sp.cos(phi_expr), R * sp.sin(phi_expr)])
    t = 1.1
    phi, phd, phdd = (float(phi_expr.diff(t_sym, n).subs(t_sym, t)) for n in range(3))
    assert np.allclose(kin.circular_position(R, phi), [float(x.subs(t_sym, t)) for x in pos])
    assert np.allclose(kin.circular_velocity(R, phi, phd),
                       [float(x.subs(t_sym, t)) for x in pos.diff(t_sym)])
    assert np.allclose(kin.circular_acceleration(R, phi, phd, phdd),
                       [float(x.subs(t_sym, t)) for x in pos.diff(t_sym, 2)])
    assert np.linalg.norm(kin.circular_velocity(R, phi, phd)) == pytest.approx(R * phd)  # (1.19)


@settings(max_examples=25, deadline=None)
@given(c=st.floats(-3, 3).filter(lambda c: abs(c) > 0.05), x1=st.floats(-3, 3),
       speed=st.floats(0.5, 5.0))
def test_parabola_curvature_equals_the_parametric_curvature_of_a_particle_on_it(c, x1, speed):
    # travel x1(t) = x1 + speed t along x2 = c x1^2: v = speed (1, 2 c x1), a = speed^2 (0, 2c)
    v = speed * np.array([1.0, 2 * c * x1])
    a = speed**2 * np.array([0.0, 2 * c])
    rho = kin.parabola_radius_of_curvature(c, x1)
    assert kin.radius_of_curvature(v, a) == pytest.approx(rho, rel=1e-10)
    assert kin.normal_acceleration(v, a) == pytest.approx(np.dot(v, v) / rho, rel=1e-10)
    # tangential + normal parts rebuild a (eq. 1.51)
    rebuilt = (kin.tangential_acceleration(v, a) * kin.unit_tangent(v)
               + kin.normal_acceleration(v, a) * kin.principal_normal(v, a))
    assert np.allclose(rebuilt, a, atol=1e-10 * np.linalg.norm(a))
    # at the vertex rho = 1/(2|c|)
    assert kin.parabola_radius_of_curvature(c, 0.0) == pytest.approx(1 / (2 * abs(c)))


def test_space_curve_frame_of_a_helix():
    # helix r = (R cos w t, R sin w t, h t): curvature radius (R^2 w^2 + h^2)/(R w^2)
    R, w, h, t = 2.0, 1.5, 0.7, 0.3
    v = np.array([-R * w * np.sin(w * t), R * w * np.cos(w * t), h])
    a = np.array([-R * w**2 * np.cos(w * t), -R * w**2 * np.sin(w * t), 0.0])
    pa = kin.path_acceleration(v, a)
    assert pa.rho == pytest.approx((R**2 * w**2 + h**2) / (R * w**2))
    assert pa.tangential == pytest.approx(0.0, abs=1e-12)
    assert pa.normal == pytest.approx(R * w**2)
    e_b = kin.binormal(v, a)
    assert np.allclose(np.cross(kin.unit_tangent(v), kin.principal_normal(v, a)), e_b)
    assert abs(np.dot(a, e_b)) < 1e-12                    # no binormal acceleration (after 1.52)


def test_circular_motion_in_the_space_curve_frame_of_example_1_6():
    # e_t = e_phi and e_n = -e_r on a circle (eq. 1.54)
    R, phi, phd, phdd = 1.5, 0.8, 2.0, 0.5
    v = kin.circular_velocity(R, phi, phd)
    a = kin.circular_acceleration(R, phi, phd, phdd)
    e_r, e_phi = kin.polar_basis(phi)
    assert np.allclose(kin.unit_tangent(v), e_phi)
    assert np.allclose(kin.principal_normal(v, a), -e_r)
    assert kin.tangential_acceleration(v, a) == pytest.approx(R * phdd)
    assert kin.normal_acceleration(v, a) == pytest.approx(R * phd**2)
    assert kin.radius_of_curvature(v, a) == pytest.approx(R)
    assert kin.path_centripetal_acceleration(R * phd, R) == pytest.approx(R * phd**2)
    assert kin.radius_of_curvature_of_graph(0.3, 0.0) == np.inf      # straight line


@settings(max_examples=20, deadline=None)
@given(v0=st.floats(0.0, 20.0), a=st.floats(0.5, 10.0), t=st.floats(0.1, 5.0))
def test_constant_acceleration_speed_and_distance_match_integration_of_x_double_dot(v0, a, t):
    # x'' = a from x(0) = 0, x'(0) = v0 integrated numerically (eqs. 1.9, 1.10)
    sol = solve_ivp(lambda _, y: [y[1], a], (0.0, t), [0.0, v0], rtol=1e-11, atol=1e-12)
    assert kin.distance_at_constant_acceleration(t, v0, a) == pytest.approx(sol.y[0, -1], rel=1e-8)
    assert kin.speed_at_constant_acceleration(t, v0, a) == pytest.approx(sol.y[1, -1], rel=1e-8)


@settings(max_examples=20, deadline=None)
@given(s=st.floats(0.1, 50.0), a=st.floats(0.2, 20.0))
def test_time_from_rest_is_when_a_started_particle_reaches_the_distance(s, a):
    t = kin.time_from_rest_over_distance(s, a)
    # a solve_ivp event at x = s, and the identity v^2 = 2 a s at that instant
    hit = lambda _, y: y[0] - s
    hit.terminal = True
    sol = solve_ivp(lambda _, y: [y[1], a], (0.0, 10 * t), [0.0, 0.0], events=hit,
                    rtol=1e-11, atol=1e-12)
    assert t == pytest.approx(sol.t_events[0][0], rel=1e-8)
    assert (a * t) ** 2 == pytest.approx(2 * a * s, rel=1e-12)


def test_half_life_halves_an_exponential_decay():
    # exp(-k t_half) = 1/2 for k = 0.37 1/s by hand: t_half = 0.6931472/0.37 = 1.8733708 s
    k = 0.37
    t_half = kin.half_life(k)
    assert np.exp(-k * t_half) == pytest.approx(0.5, rel=1e-14)
    assert t_half == pytest.approx(1.8733708, rel=1e-7)
    assert kin.linear_drag_velocity(2 * t_half, 8.0, k) == pytest.approx(2.0, rel=1e-12)


def test_circular_speed_is_radius_times_angular_rate_by_hand():
    # r = 2.2 m, phi' = 1.65 rad/s: v = 3.63 m/s, also when turning clockwise (eq. 1.19)
    assert kin.circular_speed(2.2, 1.65) == pytest.approx(3.63, rel=1e-12)
    assert kin.circular_speed(2.2, -1.65) == pytest.approx(3.63, rel=1e-12)


def test_circular_speed_equals_length_of_differentiated_position():
    t = sp.Symbol("t")
    r, phi = 1.3, 0.7 * t**2 - 0.4 * t
    x = sp.Matrix([r * sp.cos(phi), r * sp.sin(phi)])
    for t_val in (0.1, 0.9, 2.0):
        speed = float(x.diff(t).subs(t, t_val).norm())
        phidot = float(phi.diff(t).subs(t, t_val))
        assert kin.circular_speed(r, phidot) == pytest.approx(speed, rel=1e-12)


def test_angle_from_arc_length_of_a_quarter_circle_is_a_right_angle():
    R = 50.0
    assert kin.angle_from_arc_length(np.pi * R / 2, R) == pytest.approx(np.pi / 2, rel=1e-12)


def test_acceleration_magnitude_matches_the_cartesian_acceleration_on_a_circle():
    # a_t = r phi'', a_n = r phi'^2 (eq. 1.54) against |a| of the Cartesian vector (1.20)
    r, phi, phidot, phiddot = 2.2, 0.41, 1.65, 3.3
    cartesian = np.linalg.norm(kin.circular_acceleration(r, phi, phidot, phiddot))
    assert kin.acceleration_magnitude(r * phiddot, r * phidot**2) == pytest.approx(cartesian,
                                                                                    rel=1e-12)
    assert kin.acceleration_magnitude(3.0, 4.0) == pytest.approx(5.0, rel=1e-12)


def test_the_radius_of_curvature_is_infinite_on_a_straight_stretch_and_undefined_at_rest_without_a_warning():
    import warnings

    from dynagrade.mechanics.kinematics import radius_of_curvature

    with warnings.catch_warnings():
        warnings.simplefilter("error")  # verify turns a constraint's warning into noise
        assert radius_of_curvature([2.0, 0.0], [3.0, 0.0]) == np.inf  # a parallel to v
        assert np.isnan(radius_of_curvature([0.0, 0.0], [1.0, 0.0]))  # at rest
