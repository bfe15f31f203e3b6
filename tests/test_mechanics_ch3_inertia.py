"""Inertia tensors (Section 3.2.3): against direct quadrature over the body."""
import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from dynagrade.mechanics import inertia
from dynagrade.mechanics.rotations import rotation_matrix
from deferred import deferred

eigh = deferred("scipy.linalg", "eigh")
Rotation = deferred("scipy.spatial.transform", "Rotation")

N_GAUSS = 4   # Gauss-Legendre points: exact for the quadratic integrands here
N_ANGLE = 8   # uniform points in an angle: exact for trigonometric degree < 8


def _gauss(a, b, n=N_GAUSS):
    if a == b:  # a thin body: one point in this direction
        return np.array([a]), np.array([1.0])
    x, w = np.polynomial.legendre.leggauss(n)
    return 0.5 * (b - a) * x + 0.5 * (b + a), 0.5 * (b - a) * w


def _angles():
    return np.arange(N_ANGLE) * 2 * np.pi / N_ANGLE, np.full(N_ANGLE, 2 * np.pi / N_ANGLE)


def _grid(*axes):
    """Tensor-product points and weights of 1D rules."""
    pts = np.meshgrid(*[a[0] for a in axes], indexing="ij")
    wts = np.meshgrid(*[a[1] for a in axes], indexing="ij")
    w = np.ones_like(wts[0])
    for wi in wts:
        w = w * wi
    return [p.ravel() for p in pts], w.ravel()


def points_box(m, a, b, c):
    (x, y, z), w = _grid(_gauss(-a / 2, a / 2), _gauss(-b / 2, b / 2), _gauss(-c / 2, c / 2))
    return np.column_stack([x, y, z]), m * w / w.sum()


def points_cylinder(m, radius, h):
    (r, t, z), w = _grid(_gauss(0, radius), _angles(), _gauss(-h / 2, h / 2))
    w = w * r  # area element r dr dtheta
    return np.column_stack([r * np.cos(t), r * np.sin(t), z]), m * w / w.sum()


def points_sphere(m, radius):
    (rho, u, t), w = _grid(_gauss(0, radius), _gauss(-1, 1), _angles())
    w = w * rho**2
    s = np.sqrt(1 - u**2)
    return np.column_stack([rho * s * np.cos(t), rho * s * np.sin(t), rho * u]), m * w / w.sum()


def points_spherical_shell(m, radius):
    (u, t), w = _grid(_gauss(-1, 1), _angles())
    s = np.sqrt(1 - u**2)
    return radius * np.column_stack([s * np.cos(t), s * np.sin(t), u]), m * w / w.sum()


def points_tube(m, radius, h):
    (t, z), w = _grid(_angles(), _gauss(-h / 2, h / 2))
    return np.column_stack([radius * np.cos(t), radius * np.sin(t), z]), m * w / w.sum()


def points_rod(m, length):
    z, w = _gauss(-length / 2, length / 2)
    return np.column_stack([0 * z, 0 * z, z]), m * w / w.sum()


def direct_inertia(points, weights, about):
    d = points - about
    r2 = np.einsum("w,wi,wi->", weights, d, d)
    return r2 * np.eye(3) - np.einsum("w,wi,wj->ij", weights, d, d)


BODIES = {
    "box": (lambda m, a, b, c: points_box(m, a, b, c),
            lambda m, a, b, c: inertia.inertia_tensor_box(m, a, b, c)),
    "cylinder": (lambda m, a, b, c: points_cylinder(m, a, b),
                 lambda m, a, b, c: inertia.inertia_tensor_cylinder(m, a, b)),
    "disk": (lambda m, a, b, c: points_cylinder(m, a, 0.0),
             lambda m, a, b, c: inertia.inertia_tensor_disk(m, a)),
    "sphere": (lambda m, a, b, c: points_sphere(m, a),
               lambda m, a, b, c: inertia.inertia_tensor_sphere(m, a)),
    "spherical shell": (lambda m, a, b, c: points_spherical_shell(m, a),
                        lambda m, a, b, c: inertia.inertia_tensor_spherical_shell(m, a)),
    "tube": (lambda m, a, b, c: points_tube(m, a, b),
             lambda m, a, b, c: inertia.inertia_tensor_cylindrical_shell(m, a, b)),
    "hoop": (lambda m, a, b, c: points_tube(m, a, 0.0),
             lambda m, a, b, c: inertia.inertia_tensor_hoop(m, a)),
    "rod": (lambda m, a, b, c: points_rod(m, a),
            lambda m, a, b, c: inertia.inertia_tensor_rod(m, a)),
}

size = st.floats(0.05, 3.0)
vec3 = st.lists(st.floats(-2.0, 2.0), min_size=3, max_size=3).map(np.array)


@settings(max_examples=40, deadline=None)
@given(st.sampled_from(sorted(BODIES)), st.floats(0.1, 20.0), size, size, size, vec3, vec3,
       st.floats(-np.pi, np.pi))
def test_parallel_axis_theorem_and_rotation_hold_against_direct_integration_over_the_body(
        body, m, a, b, c, shift, axis, angle):
    points_of, tensor_of = BODIES[body]
    pts, w = points_of(m, a, b, c)
    if np.linalg.norm(axis) < 1e-3:
        axis = np.array([0.0, 1.0, 0.0])
    rot = rotation_matrix(axis, angle)
    centre = np.array([0.3, -0.2, 0.5])
    placed = pts @ rot.T + centre          # body rotated by R, centre moved to `centre`
    about = centre + shift
    expected = direct_inertia(placed, w, about)
    i_c = inertia.rotated_inertia_tensor(tensor_of(m, a, b, c), rot)
    got = inertia.parallel_axis_inertia_tensor(i_c, m, centre - about)
    scale = m * (a**2 + b**2 + c**2 + shift @ shift)
    assert got == pytest.approx(expected, abs=1e-9 * scale)


def test_box_inertia_by_monte_carlo_with_fixed_seed():
    # independent of the quadrature: 200k uniform samples in the box, corner as reference
    rng = np.random.default_rng(12345)
    m, a, b, c = 2.0, 0.4, 0.3, 0.2
    x = rng.uniform([0, 0, 0], [a, b, c], size=(200_000, 3))
    r2 = np.sum(x * x, axis=1)
    mc = m * (np.mean(r2) * np.eye(3) - x.T @ x / len(x))
    got = inertia.parallel_axis_inertia_tensor(inertia.inertia_tensor_box(m, a, b, c), m,
                                               np.array([a, b, c]) / 2)
    assert got == pytest.approx(mc, rel=0.01, abs=2e-4)


@settings(max_examples=40, deadline=None)
@given(st.sampled_from(sorted(BODIES)), st.floats(0.1, 20.0), size, size, size, vec3)
def test_inertia_tensors_are_symmetric_positive_semidefinite(body, m, a, b, c, shift):
    i_c = BODIES[body][1](m, a, b, c)
    i_p = inertia.parallel_axis_inertia_tensor(i_c, m, shift)
    for t in (i_c, i_p):
        assert t == pytest.approx(t.T)
        eig = eigh(t, eigvals_only=True)
        assert eig.min() >= -1e-12 * eig.max()
        # triangle inequality of principal moments: I1 + I2 >= I3
        assert eig[0] + eig[1] >= eig[2] * (1 - 1e-9)


@settings(max_examples=40, deadline=None)
@given(st.sampled_from(["box", "cylinder", "tube"]), st.floats(0.1, 20.0), size, size, size,
       st.integers(0, 10_000))
def test_solid_body_tensors_are_positive_definite_and_eigenvalues_invariant_under_rotation(
        body, m, a, b, c, seed):
    i_c = BODIES[body][1](m, a, b, c)
    assert eigh(i_c, eigvals_only=True).min() > 0
    rot = Rotation.random(random_state=seed).as_matrix()
    rotated = inertia.rotated_inertia_tensor(i_c, rot)
    assert inertia.principal_axes(rotated).moments == pytest.approx(
        np.sort(np.diag(i_c)), rel=1e-9)


@settings(max_examples=30, deadline=None)
@given(st.floats(0.1, 10.0), size, size, size, st.integers(0, 10_000))
def test_principal_axes_diagonalize_the_tensor(m, a, b, c, seed):
    rot = Rotation.random(random_state=seed).as_matrix()
    tensor = inertia.rotated_inertia_tensor(inertia.inertia_tensor_box(m, a, b, c), rot)
    tensor = inertia.parallel_axis_inertia_tensor(tensor, m, [0.1, 0.2, -0.3])
    pa = inertia.principal_axes(tensor)
    assert np.linalg.det(pa.axes) == pytest.approx(1.0)
    assert pa.axes.T @ tensor @ pa.axes == pytest.approx(np.diag(pa.moments), abs=1e-10 * m)
    for k in range(3):
        assert inertia.moment_of_inertia_about_axis(tensor, pa.axes[:, k]) == pytest.approx(
            pa.moments[k])


def test_standard_moments_by_hand():
    # rod about its end: mL^2/12 + m(L/2)^2 = mL^2/3
    i_end = inertia.parallel_axis_moment(inertia.inertia_tensor_rod(3.0, 2.0)[0, 0], 3.0, 1.0)
    assert i_end == pytest.approx(3.0 * 4.0 / 3.0)
    assert inertia.inertia_tensor_disk(2.0, 0.5)[2, 2] == pytest.approx(0.25)
    assert inertia.inertia_tensor_hoop(2.0, 0.5)[2, 2] == pytest.approx(0.5)
    assert inertia.inertia_tensor_sphere(5.0, 1.0)[0, 0] == pytest.approx(2.0)
    # axis along the cube diagonal: isotropic tensor of a cube gives m a^2/6
    cube = inertia.inertia_tensor_box(6.0, 1.0, 1.0, 1.0)
    assert inertia.moment_of_inertia_about_axis(cube, [1, 1, 1]) == pytest.approx(1.0)
