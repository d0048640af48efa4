"""Orientation of the ball: integrating its rotation from the angular velocity.

The reduced system (1.7) gives the horizontal components (wx, wy) of the ball's angular
velocity; the vertical spin wz is constant (Section 1) and drops out of (1.7), but it turns
the ball all the same. The attitude Q(t) (a rotation matrix taking body-fixed vectors to the
fixed frame Oxyz) obeys dQ/dt = [w]x Q, with w = (wx, wy, wz) in the fixed frame.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from turntable import _validate


def rotation_matrix(phi: ArrayLike) -> NDArray[np.float64]:
    """Return the rotation matrices exp([phi]x) for rotation vectors phi.

    Parameters
    ----------
    phi : array_like
        Rotation vector(s), last axis of length 3: the axis phi/|phi| and the angle |phi|.

    Returns
    -------
    numpy.ndarray
        Shape ``phi.shape[:-1] + (3, 3)``, orthogonal with determinant 1.

    See Also
    --------
    scipy.spatial.transform.Rotation.from_rotvec : The rotations, whose matrices these are.

    Notes
    -----
    Rodrigues' formula, exp([phi]x) = I + sin(a)/a [phi]x + (1 - cos a)/a^2 [phi]x^2 with
    a = |phi|, as `scipy.spatial.transform.Rotation` evaluates it (accurate for small a).
    """
    from scipy.spatial.transform import Rotation

    phi = np.asarray(phi, dtype=float)
    if phi.shape[-1:] != (3,) or not np.all(np.isfinite(phi)):
        raise ValueError(f"phi must be finite with last axis of length 3, got shape {phi.shape}")
    flat = phi.reshape(-1, 3)
    if not flat.size:
        return np.empty((*phi.shape[:-1], 3, 3))
    return Rotation.from_rotvec(flat).as_matrix().reshape(*phi.shape[:-1], 3, 3)


def integrate_orientation(
    t: ArrayLike, omega: ArrayLike, q0: ArrayLike | None = None
) -> NDArray[np.float64]:
    """Integrate dQ/dt = [w(t)]x Q from angular velocities sampled at the times t.

    Parameters
    ----------
    t : array_like
        Increasing times, shape (n,).
    omega : array_like
        Angular velocity w = (wx, wy, wz) in the fixed frame at each time, shape (n, 3).
    q0 : array_like, optional
        Initial attitude (3, 3), a rotation matrix; default the identity.

    Returns
    -------
    numpy.ndarray
        Q at every time, shape (n, 3, 3): Q[i] @ b is the fixed-frame direction of the
        body-fixed vector b.

    Notes
    -----
    Lie midpoint rule: Q_{i+1} = exp(h [w_mid]x) Q_i with h = t_{i+1} - t_i and
    w_mid = (w_i + w_{i+1}) / 2. Each step is an exact rotation, so Q stays orthogonal to
    rounding; the global error is O(h^2) (exact when w is constant in direction).
    """
    t = np.asarray(t, dtype=float)
    omega = np.asarray(omega, dtype=float)
    if t.ndim != 1 or t.size < 1 or not np.all(np.isfinite(t)):
        raise ValueError(f"t must be a non-empty 1-D array of finite times, got shape {t.shape}")
    if np.any(np.diff(t) <= 0):
        raise ValueError("t must be strictly increasing")
    if omega.shape != (t.size, 3) or not np.all(np.isfinite(omega)):
        raise ValueError(
            f"omega must be finite with shape (len(t), 3) = ({t.size}, 3), got {omega.shape}"
        )
    q = np.eye(3) if q0 is None else np.asarray(q0, dtype=float)
    if q.shape != (3, 3) or not np.allclose(q.T @ q, np.eye(3), atol=1e-9):
        raise ValueError("q0 must be a 3x3 rotation matrix")
    steps = rotation_matrix(np.diff(t)[:, None] * 0.5 * (omega[1:] + omega[:-1]))
    out = np.empty((t.size, 3, 3))
    out[0] = q
    for i, step in enumerate(steps):
        q = step @ q
        out[i + 1] = q
    return out


def ball_angular_velocity(z: ArrayLike, wz: float) -> NDArray[np.float64]:
    """Return the full angular velocity (wx, wy, wz) of states z and a vertical spin wz.

    Parameters
    ----------
    z : array_like
        States (x, y, vx, vy, wx, wy), shape (n, 6) (e.g. from `solve` or `nonholonomic`).
    wz : float
        The vertical spin, constant in the model (Section 1).

    Returns
    -------
    numpy.ndarray
        Shape (n, 3).

    Notes
    -----
    Section 1: the vertical component of I dw/dt = mu0 R gamma x u vanishes, so wz keeps its
    initial value; (wx, wy) are the last two components of the state of (1.7).
    """
    z = _validate.states("z", z)
    wz = float(wz)
    if not np.isfinite(wz):
        raise ValueError(f"wz must be finite, got {wz}")
    z = np.atleast_2d(z)
    return np.column_stack([z[:, 4], z[:, 5], np.full(len(z), wz)])
