"""turntable.orientation against scipy's rotations and a tight ODE solution of dQ/dt = [w]x Q."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.spatial.transform import Rotation

from turntable import nonholonomic, solve
from turntable.orientation import ball_angular_velocity, integrate_orientation, rotation_matrix

Z0 = np.array([1.0, 1.0, 0.0, 0.0, 0.0, 1.0])


@pytest.mark.parametrize(
    "phi",
    [[0.0, 0.0, 0.0], [1e-6, -2e-6, 3e-7], [0.3, -1.2, 0.5], [0.0, 0.0, 3.0], [-2.0, 1.0, 4.0]],
    ids=["zero", "tiny", "generic", "vertical", "large"],
)
def test_rotation_matrix_turns_about_phi_by_its_length(phi: list[float]) -> None:
    """exp([phi]x) keeps phi and turns a vector u perpendicular to it counterclockwise about
    phi by |phi|: cos |phi| u + sin |phi| (phi / |phi|) x u."""
    phi = np.array(phi)
    q = rotation_matrix(phi)
    angle = np.linalg.norm(phi)
    axis = phi / angle if angle else np.array([0.0, 0.0, 1.0])
    u = np.cross(axis, [1.0, 0.0, 0.0] if abs(axis[0]) < 0.9 else [0.0, 1.0, 0.0])
    u /= np.linalg.norm(u)
    assert np.allclose(q @ phi, phi, rtol=0, atol=1e-14)
    turned = np.cos(angle) * u + np.sin(angle) * np.cross(axis, u)
    assert np.allclose(q @ u, turned, rtol=0, atol=1e-14)
    assert np.allclose(q.T @ q, np.eye(3), rtol=0, atol=1e-14)


@pytest.mark.parametrize("shape", [(0,), (5,), (2, 4)])
def test_rotation_matrix_of_an_array_of_vectors(shape: tuple[int, ...]) -> None:
    phi = np.random.default_rng(2).normal(size=(*shape, 3))
    q = rotation_matrix(phi)
    assert q.shape == (*shape, 3, 3)
    for index in np.ndindex(*shape):
        assert np.allclose(q[index], rotation_matrix(phi[index]), rtol=0, atol=0)


def test_constant_spin_is_exact() -> None:
    w = np.array([0.4, -0.7, 1.3])
    t = np.linspace(0.0, 5.0, 11)
    q = integrate_orientation(t, np.tile(w, (t.size, 1)))
    expected = Rotation.from_rotvec(t[:, None] * w).as_matrix()
    assert np.allclose(q, expected, rtol=0, atol=1e-13)


def test_vertical_spin_turns_the_ball_about_the_vertical() -> None:
    t = np.linspace(0.0, 2.0, 5)
    q = integrate_orientation(t, ball_angular_velocity(np.zeros((t.size, 6)), wz=1.5))
    for ti, qi in zip(t, q, strict=True):
        c, s = np.cos(1.5 * ti), np.sin(1.5 * ti)
        assert np.allclose(qi, [[c, -s, 0], [s, c, 0], [0, 0, 1]], atol=1e-14)


def _reference(t_end: float, omega) -> np.ndarray:
    """Q(t_end) from solve_ivp of dQ/dt = [w(t)]x Q at rtol 1e-12 (independent of the package)."""

    def rhs(t: float, y: np.ndarray) -> np.ndarray:
        wx, wy, wz = omega(t)
        k = np.array([[0.0, -wz, wy], [wz, 0.0, -wx], [-wy, wx, 0.0]])
        return (k @ y.reshape(3, 3)).ravel()

    sol = solve_ivp(rhs, (0.0, t_end), np.eye(3).ravel(), method="DOP853", rtol=1e-12, atol=1e-13)
    return sol.y[:, -1].reshape(3, 3)


@pytest.mark.parametrize(
    ("model", "wz"),
    [("slipping mu0=0.3", 0.0), ("slipping mu0=0.3", 0.8), ("no-slip", 0.8)],
    ids=["slip", "slip-spin", "noslip-spin"],
)
def test_second_order_convergence_to_the_ode(model: str, wz: float) -> None:
    k, t_end = 0.4, 6.0

    def states(t: np.ndarray) -> np.ndarray:
        return solve(Z0, t, 0.3, k) if model.startswith("slipping") else nonholonomic(Z0, t, k)

    def omega(t: float) -> np.ndarray:
        return ball_angular_velocity(states(np.array([t])), wz)[0]

    ref = _reference(t_end, omega)
    errors = []
    for n in (200, 400, 800):
        t = np.linspace(0.0, t_end, n + 1)
        q = integrate_orientation(t, ball_angular_velocity(states(t), wz))
        assert np.allclose(q[-1].T @ q[-1], np.eye(3), atol=1e-12)
        errors.append(np.max(np.abs(q[-1] - ref)))
    assert errors[-1] < 1e-4
    orders = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert np.all((orders > 1.8) & (orders < 2.2)), orders


def test_the_spin_changes_the_orientation() -> None:
    t = np.linspace(0.0, 3.0, 301)
    z = solve(Z0, t, 0.3, 0.4)
    without = integrate_orientation(t, ball_angular_velocity(z, 0.0))[-1]
    with_spin = integrate_orientation(t, ball_angular_velocity(z, 1.0))[-1]
    assert np.max(np.abs(without - with_spin)) > 0.1


@pytest.mark.parametrize(
    ("t", "omega", "q0", "match"),
    [
        ([0.0, 1.0, 1.0], np.zeros((3, 3)), None, "increasing"),
        ([0.0, 1.0], np.zeros((3, 3)), None, "omega"),
        ([0.0, 1.0], [[0, 0, 0], [0, np.nan, 0]], None, "omega"),
        ([0.0, 1.0], np.zeros((2, 3)), 2 * np.eye(3), "rotation"),
    ],
    ids=["repeated-time", "shape", "nan", "not-rotation"],
)
def test_bad_input(t, omega, q0, match: str) -> None:
    with pytest.raises(ValueError, match=match):
        integrate_orientation(t, omega, q0)
