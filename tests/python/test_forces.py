"""Each force's energy, gradient and Hessians against finite differences, through the module."""

import numpy as np
import pytest
import scipy.sparse

import fosssim
from conftest import FORCES_SCENE

STEP = 1e-6


def central_difference(function, x, step=STEP):
    """d function / dx by central differences, one column per coordinate of x."""
    columns = []
    for k in range(x.size):
        e = np.zeros_like(x)
        e[k] = step
        columns.append((np.asarray(function(x + e)) - np.asarray(function(x - e))) / (2 * step))
    return np.array(columns).T


@pytest.fixture
def scene():
    return fosssim.load_scene_text(FORCES_SCENE, "forces.xml")


@pytest.fixture
def point(scene):
    return np.array(scene.initial_q), np.array(scene.initial_v)


def test_the_scene_has_every_force(scene):
    labels = " ".join(f.label for f in scene.forces)
    for name in ("spring", "gravitational", "vortex", "drag", "gravity", "constant"):
        assert name in labels
    assert len(scene.forces) == 7


def test_gradient_is_the_derivative_of_energy(scene, point):
    q, v = point
    checked = 0
    for force in scene.forces:
        if not force.conservative:
            continue
        numeric = central_difference(lambda x: np.array([force.energy(x, v)]), q)[0]
        np.testing.assert_allclose(force.gradient(q, v), numeric, rtol=1e-6, atol=1e-7,
                                   err_msg=force.label)
        checked += 1
    assert checked >= 4


def test_hessian_x_is_the_derivative_of_the_gradient(scene, point):
    q, v = point
    for force in scene.forces:
        hessian = force.hessian_x(q, v)
        assert scipy.sparse.issparse(hessian) and hessian.shape == (6, 6)
        numeric = central_difference(lambda x: force.gradient(x, v), q)
        np.testing.assert_allclose(hessian.toarray(), numeric, rtol=1e-6, atol=1e-6,
                                   err_msg=force.label)


def test_hessian_v_is_the_velocity_derivative_of_the_gradient(scene, point):
    q, v = point
    nonzero = 0
    for force in scene.forces:
        hessian = force.hessian_v(q, v)
        numeric = central_difference(lambda x: force.gradient(q, x), v)
        np.testing.assert_allclose(hessian.toarray(), numeric, rtol=1e-6, atol=1e-6,
                                   err_msg=force.label)
        nonzero += hessian.count_nonzero() > 0
    assert nonzero >= 2  # the damped spring and the drag


def test_the_scene_sums_its_forces(scene, point):
    q, v = point
    forces = scene.forces
    np.testing.assert_allclose(scene.gradient(q, v), sum(f.gradient(q, v) for f in forces),
                               rtol=1e-14, atol=1e-14)
    np.testing.assert_array_equal(scene.force(q, v), -scene.gradient(q, v))
    assert scene.potential_energy(q, v) == pytest.approx(sum(f.energy(q, v) for f in forces))
    total = sum(f.hessian_x(q, v) for f in forces).toarray()
    np.testing.assert_allclose(scene.hessian_x(q, v).toarray(), total, rtol=1e-14, atol=1e-13)
    total = sum(f.hessian_v(q, v) for f in forces).toarray()
    np.testing.assert_allclose(scene.hessian_v(q, v).toarray(), total, rtol=1e-14, atol=1e-13)
    assert scene.kinetic_energy(v) == pytest.approx(0.5 * np.dot(scene.mass, v * v))


def test_spring_energy_by_hand(scene):
    # Spring of edge 1 (particles 1, 2): k = 3, l0 = 1.4, U = k/2 (l - l0)^2.
    spring = [f for f in scene.forces if f.label.startswith("spring")][1]
    q = np.array(scene.initial_q)
    length = np.linalg.norm(q[4:6] - q[2:4])
    assert spring.energy(q) == pytest.approx(1.5 * (length - 1.4) ** 2, rel=1e-15)


def test_arrays_of_the_wrong_size_are_refused(scene):
    with pytest.raises(ValueError, match="must hold 6 numbers"):
        scene.gradient(np.zeros(5))
    np.testing.assert_array_equal(scene.gradient(np.zeros((3, 2)) + 1.0),
                                  scene.gradient(np.ones(6)))


def test_definite_hessian_of_a_compressed_spring(scene, point):
    # Spring of edge 1 is compressed (length 1.17 < l0 = 1.4): its exact hessX has a negative
    # eigenvalue (transverse), the definite one has none and keeps the axial stiffness.
    q, v = point
    spring = [f for f in scene.forces if f.label.startswith("spring")][1]
    assert np.linalg.norm(q[4:6] - q[2:4]) < 1.4
    exact = np.linalg.eigvalsh(spring.hessian_x(q, v).toarray())
    definite = np.linalg.eigvalsh(spring.hessian_x(q, v, definite=True).toarray())
    assert exact.min() < -1e-3
    assert definite.min() > -1e-12
    assert definite.max() == pytest.approx(exact.max(), rel=1e-12)
