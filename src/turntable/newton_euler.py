"""The full three-dimensional Newton-Euler equations (1.3)-(1.6).

This is the independent cross-check of the reduction to dz/dt = L z: it
integrates r, v, w as 3-vectors with the spin wz and gravity g free, builds
the friction force from the slip velocity with cross products, and obtains
the normal reaction from the contact condition.  It does not use L.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from turntable import _validate

GAMMA = np.array([0.0, 0.0, 1.0])


@dataclass(frozen=True)
class NewtonEulerResult:
    """Trajectory of the full 3-D equations.

    Attributes
    ----------
    t : numpy.ndarray
        Times, shape (n,).
    r, v, w : numpy.ndarray
        Centre position, centre velocity and angular velocity, shape (n, 3).
    normal : numpy.ndarray
        Normal reaction N (its component along gamma), shape (n,).

    Examples
    --------
    >>> from turntable import newton_euler
    >>> result = newton_euler([1.0, 1.0, 0.0, 0.0, 0.0, 1.0], [0.0, 1.0], 1.0, 0.4)
    >>> result.r.shape, result.normal.shape
    ((2, 3), (2,))
    """

    t: NDArray[np.float64]
    r: NDArray[np.float64]
    v: NDArray[np.float64]
    w: NDArray[np.float64]
    normal: NDArray[np.float64]

    @property
    def z(self) -> NDArray[np.float64]:
        """The planar state (x, y, vx, vy, wx, wy), shape (n, 6)."""
        return np.column_stack([self.r[:, :2], self.v[:, :2], self.w[:, :2]])


def _slip(r: NDArray, v: NDArray, w: NDArray) -> NDArray:
    """u = v + gamma x w - Omega x r with Omega = gamma (dimensionless)."""
    return v + np.cross(GAMMA, w) - np.cross(GAMMA, r)


def newton_euler(
    z0: ArrayLike,
    t: ArrayLike,
    mu0: float,
    k: float,
    *,
    wz0: float = 0.0,
    g: float = 9.81,
    method: str = "LSODA",
    rtol: float = 1e-12,
    atol: float = 1e-12,
) -> NewtonEulerResult:
    r"""Integrate the full 3-D Newton-Euler equations of the ball.

    Parameters
    ----------
    z0 : array_like
        Initial planar state (x, y, vx, vy, wx, wy); the centre starts at
        height 1 (one radius above the plane) with vz = 0.
    t : array_like
        Increasing 1-D array of non-negative output times; integration starts at 0.
    mu0, k : float
        Friction coefficient and inertia ratio, finite and > 0.
    wz0 : float, optional
        Initial spin about the vertical (free: it must not affect the motion).
    g : float, optional
        Dimensionless gravity :math:`g / (R \Omega^2)` (free: it must not affect the
        planar motion).
    method, rtol, atol : optional
        Passed to `scipy.integrate.solve_ivp`.

    Returns
    -------
    NewtonEulerResult

    See Also
    --------
    turntable.solve : The closed form of the reduced equations.

    Notes
    -----
    Equations (1.3)-(1.4) in the units of (1.6):

    .. math::

        u = v + \gamma \times \omega - \gamma \times r, \quad
        \dot r = v, \quad \dot v = -\mu_0 u + \mathbf{g} + \mathbf{N}, \quad
        \dot\omega = \frac{\mu_0}{k}\, \gamma \times u,

    with :math:`\mathbf{g} = -g\gamma` and :math:`\mathbf{N} = N\gamma` the reaction that
    keeps the ball on the plane: :math:`\ddot z = 0` gives :math:`N = g + \mu_0\, u \cdot \gamma`.

    Examples
    --------
    The full 3-D equations agree with the closed form of the planar motion:

    >>> import numpy as np
    >>> from turntable import newton_euler, solve
    >>> z0, t = [0, 0, 1, 0, 0, 0], np.linspace(0.0, 2.0, 5)
    >>> result = newton_euler(z0, t, 1.0, 0.4)
    >>> bool(np.abs(result.z - solve(z0, t, 1.0, 0.4)).max() < 1e-9)
    True
    """
    z0 = _validate.state("z0", z0)
    t = _validate.times("t", t, increasing=True)
    if t.size == 0:
        raise ValueError("t must be a non-empty 1-D array of times >= 0")
    mu0 = _validate.positive_scalar("mu0", mu0)
    k = _validate.positive_scalar("k", k)
    wz0 = _validate.finite_scalar("wz0", wz0)
    g = _validate.finite_scalar("g", g)

    def normal_force(r: NDArray, v: NDArray, w: NDArray) -> float:
        return g + mu0 * float(_slip(r, v, w) @ GAMMA)

    def rhs(_t: float, y: NDArray) -> NDArray:
        r, v, w = y[0:3], y[3:6], y[6:9]
        u = _slip(r, v, w)
        friction = -mu0 * u
        dv = friction - g * GAMMA + normal_force(r, v, w) * GAMMA
        dw = (mu0 / k) * np.cross(GAMMA, u)
        return np.concatenate([v, dv, dw])

    # Imported here: scipy.integrate takes ~0.4 s to import and nothing else needs it.
    from scipy.integrate import solve_ivp

    y0 = np.array([z0[0], z0[1], 1.0, z0[2], z0[3], 0.0, z0[4], z0[5], wz0])
    sol = solve_ivp(
        rhs,
        (0.0, max(float(t[-1]), 1e-300)),
        y0,
        method=method,
        t_eval=t,
        rtol=rtol,
        atol=atol,
    )
    if not sol.success:
        raise RuntimeError(f"solve_ivp failed: {sol.message}")
    y = sol.y.T
    r, v, w = y[:, 0:3], y[:, 3:6], y[:, 6:9]
    normal = g + mu0 * (_slip(r, v, w) @ GAMMA)
    return NewtonEulerResult(sol.t, r, v, w, normal)
