"""Kinetics and work-energy (Sections 1.2.1, 1.2.2): the simulator against energy
balances, forces against their definitions, Examples 1.10-1.14 against hand work."""
import numpy as np
import pytest
from hypothesis import assume, given, settings, strategies as st

from dynagrade.mechanics import energy, particle
from dynagrade.mechanics import kinematics as kin


@settings(max_examples=20, deadline=None)
@given(m=st.floats(0.1, 5.0), k=st.floats(1.0, 100.0), g=st.floats(1.0, 15.0),
       r0=st.tuples(st.floats(-2, 2), st.floats(-2, 2)), v0=st.tuples(st.floats(-5, 5), st.floats(-5, 5)))
def test_energy_is_conserved_by_the_simulator_for_gravity_and_a_spring(m, k, g, r0, v0):
    gvec = np.array([0.0, -g])
    anchor = np.array([0.3, 1.0])

    def force(t, r, v):
        return particle.weight(m, gvec) + particle.spring_force(k, r, anchor)

    def total(r, v):
        return (energy.particle_kinetic_energy(m, v) + energy.gravity_potential(m, r, gvec)
                + energy.spring_potential(k, r[..., 0], anchor[0])
                + energy.spring_potential(k, r[..., 1], anchor[1]))

    period = 2 * np.pi * np.sqrt(m / k)
    traj = particle.simulate(m, r0, v0, force, 3 * period)
    E = total(traj.r, traj.v)
    scale = np.max(np.abs(E)) + m * g * 1.0 + k
    assert np.max(np.abs(E - E[0])) < 1e-7 * scale


@settings(max_examples=20, deadline=None)
@given(m=st.floats(0.1, 5.0), mu=st.floats(0.05, 1.0), v0=st.floats(0.5, 10.0),
       k=st.floats(0.0, 2.0), g=st.floats(5.0, 15.0))
def test_energy_decreases_by_exactly_the_friction_and_drag_work(m, mu, v0, k, g):
    # sliding on a floor with Coulomb friction and linear drag until it stops (v = 0 event);
    # the lost kinetic energy equals minus the work of the non-conservative forces (eq. 1.87),
    # friction work -mu m g * distance (eq. 1.89) plus drag work -integral k v^2 dt
    N = particle.floor_normal_force(m, g)

    def force(t, r, v):
        moving = np.array([1.0])          # sliding in +e1 until the stop event
        return particle.kinetic_friction(N, moving, mu) + particle.linear_drag_force(v, k)

    def stops(t, r, v):
        return v[0]

    stops.terminal = True
    stops.direction = -1
    traj = particle.simulate(m, [0.0], [v0], force, 10 * v0 / (mu * g), events=(stops,))
    t_stop = traj.event_times[0][0]
    distance = traj.event_states[0][0][0]
    ts = np.linspace(0.0, t_stop, 2001)
    _, vs = traj.at(ts)
    drag_work = -k * np.trapezoid(vs[:, 0] ** 2, ts)
    W = energy.friction_work_on_floor(mu, m, g, distance) + drag_work
    assert energy.particle_kinetic_energy(m, v0) + W == pytest.approx(0.0, abs=1e-5 * energy.particle_kinetic_energy(m, v0))
    if k == 0.0:
        assert distance == pytest.approx(energy.sliding_stopping_distance(v0, mu, g), rel=1e-8)
        assert t_stop == pytest.approx(particle.sliding_stop_time(v0, mu, g), rel=1e-8)


@settings(max_examples=20, deadline=None)
@given(m=st.floats(0.1, 5.0), g=st.floats(1.0, 15.0), a=st.floats(0.2, 3.0), b=st.floats(0.2, 3.0),
       tilt=st.floats(0, np.pi))
def test_work_of_gravity_around_a_closed_path_is_zero_and_friction_work_is_negative(m, g, a, b, tilt):
    # an ellipse in the vertical plane, traversed once with unit angular rate
    rot = np.array([[np.cos(tilt), -np.sin(tilt)], [np.sin(tilt), np.cos(tilt)]])
    path = lambda s: rot @ np.array([a * np.cos(s), b * np.sin(s)])
    vel = lambda s: rot @ np.array([-a * np.sin(s), b * np.cos(s)])
    gravity = lambda r, v: particle.weight(m, [0.0, -g])
    assert energy.work_along_path(gravity, path, vel, 0.0, 2 * np.pi) == pytest.approx(0.0, abs=1e-9 * m * g * (a + b))
    mu, N = 0.3, 2.0
    friction = lambda r, v: particle.kinetic_friction(N, v, mu)
    W_friction = energy.work_along_path(friction, path, vel, 0.0, 2 * np.pi)
    # |R| = mu N along the whole perimeter: W = -mu N * perimeter (perimeter by quadrature)
    from scipy.integrate import quad
    perimeter = quad(lambda s: np.linalg.norm(vel(s)), 0, 2 * np.pi, epsabs=1e-12)[0]
    assert W_friction < 0
    assert W_friction == pytest.approx(-mu * N * perimeter, rel=1e-8)
    # half way round: gravity's work is the potential difference (eq. 1.99)
    W_half = energy.work_along_path(gravity, path, vel, 0.0, np.pi)
    V = lambda r: energy.gravity_potential(m, r, [0.0, -g])
    assert W_half == pytest.approx(energy.work_from_potential(V(path(0.0)), V(path(np.pi))),
                                   abs=1e-9 * m * g * (a + b))


def test_curl_test_tells_conservative_from_non_conservative_fields():
    rng = np.random.default_rng(0)
    points = rng.uniform(-1, 1, size=(5, 3))
    gravity = lambda r: particle.weight(2.0, [0, 0, -9.81])
    spring = lambda r: -4.0 * (r - np.array([0.1, 0.2, 0.3]))
    central = lambda r: -r / np.linalg.norm(r) ** 3
    swirl = lambda r: np.array([-r[1], r[0], 0.0])          # curl = (0, 0, 2)
    assert energy.is_conservative(gravity, points, scale=20)
    assert energy.is_conservative(spring, points, scale=4)
    assert energy.is_conservative(central, points + 2.0, scale=1)
    assert not energy.is_conservative(swirl, points, scale=1)
    assert np.allclose(energy.curl(swirl, points[0]), [0, 0, 2], atol=1e-8)


@settings(max_examples=20, deadline=None)
@given(m=st.floats(0.1, 5.0), v1=st.floats(0.0, 10.0), W=st.floats(-50.0, 50.0))
def test_speed_after_work_satisfies_the_work_energy_balance(m, v1, W):
    v2 = energy.speed_after_work(m, v1, W)
    if energy.particle_kinetic_energy(m, v1) + W < 0:
        assert np.isnan(v2)
    else:
        assert energy.particle_kinetic_energy(m, v2) - energy.particle_kinetic_energy(m, v1) == pytest.approx(W, abs=1e-9 * (1 + abs(W)))


@settings(max_examples=20, deadline=None)
@given(m=st.floats(0.05, 2.0), k=st.floats(10.0, 1000.0), dx=st.floats(0.01, 0.3), g=st.floats(5.0, 15.0))
def test_spring_launch_height_matches_simulated_launch(m, k, dx, g):
    # Example 1.12 variation, eq. (1.108), height counted from the compressed start.
    # Phase 1: spring and gravity until the spring is back at its natural length (x = 0);
    # phase 2: free flight until the apex.
    assume(k * dx**2 / 2 > m * g * dx * 1.01)          # the spring can lift it off at all

    def pushed(t, r, v):
        return np.array([particle.spring_force(k, r[0], 0.0) - m * g])

    def released(t, r, v):
        return r[0]

    released.terminal = True
    released.direction = 1
    one = particle.simulate(m, [-dx], [0.0], pushed, 10 * np.sqrt(m / k), events=(released,))
    r1, v1 = one.event_states[0][0]
    assert v1 > 0

    def apex(t, r, v):
        return v[0]

    apex.terminal = True
    apex.direction = -1
    two = particle.simulate(m, [r1], [v1], lambda t, r, v: particle.weight(m, [-g]),
                            10 * v1 / g, events=(apex,))
    h = two.event_states[0][0][0]
    assert energy.spring_launch_height(k, dx, m, g) == pytest.approx(h + dx, rel=1e-7)


@settings(max_examples=20, deadline=None)
@given(m=st.floats(0.05, 2.0), k=st.floats(10.0, 1000.0), dx=st.floats(0.02, 0.5), l0=st.floats(0.05, 0.5))
def test_slingshot_speed_matches_simulated_release(m, k, dx, l0):
    # Example 1.14: spring anchored at (0, l0) above the floor point r2 = (0, 0); the particle
    # slides on the frictionless floor from (-dx, 0).  Speed when it passes x = 0.
    anchor = np.array([0.0, l0])

    def force(t, r, v):
        d = np.array([r[0], 0.0]) - anchor
        length = np.linalg.norm(d)
        return np.array([-k * (length - l0) * d[0] / length])   # floor takes the vertical part

    def passes(t, r, v):
        return r[0]

    passes.terminal = True
    traj = particle.simulate(m, [-dx], [0.0], force, 100 * np.sqrt(m / k) * (1 + dx / l0),
                             events=(passes,))
    v = abs(traj.event_states[0][0][1])
    assert energy.slingshot_speed(k, m, dx, l0) == pytest.approx(v, rel=1e-7)


@settings(max_examples=20, deadline=None)
@given(m=st.floats(0.1, 5.0), l=st.floats(0.2, 3.0), omega=st.floats(0.5, 10.0))
def test_string_force_of_example_1_10_keeps_the_particle_on_its_circle(m, l, omega):
    S = particle.string_tension(m, l, omega)

    def force(t, r, v):
        return -S * r / np.linalg.norm(r)

    period = 2 * np.pi / omega
    traj = particle.simulate(m, [l, 0.0], [0.0, l * omega], force, period)
    radius = np.linalg.norm(traj.r, axis=1)
    assert np.max(np.abs(radius - l)) < 1e-7 * l
    assert traj.r[-1] == pytest.approx([l, 0.0], abs=1e-6 * l)       # back after one period


def test_forces_follow_their_definitions():
    assert np.allclose(particle.weight(2.0, [0, -9.81]), [0, -19.62])
    assert np.allclose(particle.kinetic_friction(10.0, [3.0, 4.0], 0.5), [-3.0, -4.0])
    assert np.allclose(particle.kinetic_friction(-10.0, [0.0, 0.0], 0.5), [0.0, 0.0])
    assert np.allclose(particle.linear_drag_force([1.0, -2.0], 0.5), [-0.5, 1.0])
    assert np.allclose(particle.quadratic_drag_force([3.0, 4.0], 0.1), [-1.5, -2.0])
    assert particle.spring_force(100.0, 0.3, 0.1) == pytest.approx(-20.0)
    assert np.allclose(particle.particle_linear_momentum(2.0, [1.0, 2.0]), [2.0, 4.0])
    assert np.allclose(particle.acceleration(2.0, [1.0, 0.0], [0.0, -19.62]), [0.5, -9.81])
    assert particle.floor_normal_force(3.0, 9.81) == pytest.approx(29.43)         # eq. (1.70)


def test_height_gain_by_energy_equals_the_integrated_peak_of_example_1_12():
    v0, alpha, g = 12.0, 0.9, 9.81
    from dynagrade.mechanics.examples import projectile
    assert energy.height_gain(v0, v0 * np.cos(alpha), g) == pytest.approx(projectile.peak_height(v0, alpha, g))
    assert kin.rocket_peak_height(v0, g, 1e15) == pytest.approx(energy.height_gain(v0, 0.0, g), rel=1e-9)


def test_resultant_force_by_hand_and_back_to_the_acceleration():
    # m = 2 kg, a = (3, -4) m/s^2: F = (6, -8) N, and F/m gives a again (eq. 1.63)
    force = particle.resultant_force(2.0, [3.0, -4.0])
    assert force == pytest.approx([6.0, -8.0])
    assert particle.acceleration(2.0, force) == pytest.approx([3.0, -4.0])


def test_normal_force_under_an_inclined_pull_by_hand():
    # m = 10 kg, g = 9.81, F = 50 N at 30 deg: N = 98.1 - 25 = 73.1 N
    assert particle.floor_normal_force_under_pull(10.0, 9.81, 50.0, np.radians(30)) == \
        pytest.approx(73.1, rel=1e-12)


@settings(max_examples=20, deadline=None)
@given(m=st.floats(0.5, 20.0), g=st.floats(1.0, 15.0), F=st.floats(0.0, 50.0),
       theta=st.floats(-1.2, 1.2))
def test_pulled_block_does_not_accelerate_normal_to_the_floor(m, g, F, theta):
    N = particle.floor_normal_force_under_pull(m, g, F, theta)
    pull = (F * np.cos(theta), F * np.sin(theta))
    a = particle.acceleration(m, pull, particle.weight(m, (0.0, -g)), (0.0, N))
    assert a[1] == pytest.approx(0.0, abs=1e-9)
