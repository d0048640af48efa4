r"""The comparison model: a ball rolling without slipping, with rolling resistance.

The paper (Sec. 2, after Fig. 4) compares its slipping ball with a ball that
rolls WITHOUT slipping on the turntable and feels a moment of resistance to
rolling proportional to its angular velocity (ref. [2] of the paper).  This
module is that second system, in the paper's dimensionless units (length :math:`R`,
time :math:`1/\Omega`, mass :math:`m`), with :math:`z = (x, y, v_x, v_y, w_x, w_y)` as
elsewhere.

The derivation (the model (R1)-(R3), the linear equations (R4), the eigenvalues in closed
form and the moving centre of the spiral) is in docs/theory.md.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from turntable import _validate
from turntable._rolling_match import (
    equal_decay_delta,
    equal_power_delta,
    own_spin_power_delta,
    power_rolling,
    power_slipping,
)
from turntable._rolling_solution import (
    SLIP_TOLERANCE,
    RollingModes,
    _modes,
    modal_terms,
    solve,
    spiral_centre,
    state_on_constraint,
)
from turntable._rolling_spectrum import (
    RollingSpectrum,
    centre_decay_rate,
    eigenvalues,
    growth_rate,
    log_growth_per_turn,
    spectrum,
    system_matrix,
)
from turntable.solution import slip_velocity

__all__ = [
    "COMPARISONS",
    "GAMMA",
    "SLIP_TOLERANCE",
    "TORQUES",
    "RollingModes",
    "RollingNewtonEuler",
    "RollingSpectrum",
    "centre_decay_rate",
    "eigenvalues",
    "equal_decay_delta",
    "equal_power_delta",
    "growth_per_turn_ratio",
    "growth_rate",
    "log_growth_per_turn",
    "matched_delta",
    "modal_terms",
    "newton_euler",
    "own_spin_power_delta",
    "power_rolling",
    "power_slipping",
    "slip_velocity",
    "solve",
    "spectrum",
    "spiral_centre",
    "state_on_constraint",
    "system_matrix",
]

GAMMA = np.array([0.0, 0.0, 1.0])


#: The torque variants of `newton_euler`: which components of w the torque acts on.
TORQUES = ("horizontal", "full", "relative")


#: The comparisons of the two mechanisms: equal coefficients (:math:`\delta = \mu_0`), equal
#: dissipated power on the same path of the centre (each ball with its own spin), equal decay
#: rate of the non-growing part.
COMPARISONS = ("equal_coefficient", "equal_power", "equal_decay")


def matched_delta(mu0: ArrayLike, k: ArrayLike, comparison: str) -> NDArray[np.float64]:
    r"""Return the rolling coefficient :math:`\delta` that corresponds to :math:`\mu_0` under a
    comparison.

    Parameters
    ----------
    mu0, k : float or array_like
        Slipping friction coefficient and inertia ratio, > 0.
    comparison : {"equal_coefficient", "equal_power", "equal_decay"}
        :math:`\delta = \mu_0`; `equal_power_delta`; `equal_decay_delta`.

    Returns
    -------
    numpy.ndarray
        :math:`\delta`, of the broadcast shape of ``mu0`` and ``k``.

    Examples
    --------
    >>> from turntable import rolling
    >>> for comparison in rolling.COMPARISONS:
    ...     print(comparison, rolling.matched_delta([0.1, 1.0], 0.4, comparison).round(4))
    equal_coefficient [0.1 1. ]
    equal_power [0.0296 0.0124]
    equal_decay [0.3348 4.6981]
    """
    if comparison not in COMPARISONS:
        raise ValueError(f"comparison must be one of {COMPARISONS}; got {comparison!r}")
    if comparison == "equal_power":
        return equal_power_delta(mu0, k)
    if comparison == "equal_decay":
        return equal_decay_delta(mu0, k)
    mu0 = _validate.positive("mu0", mu0)
    k = _validate.positive("k", k)
    return np.broadcast_arrays(mu0, k)[0].astype(float)


def growth_per_turn_ratio(mu0: ArrayLike, k: ArrayLike, comparison: str) -> NDArray[np.float64]:
    r"""Return the slipping spiral's log growth per turn over the rolling one's.

    Parameters
    ----------
    mu0, k : float or array_like
        Slipping friction coefficient and inertia ratio, finite and > 0.
    comparison : {"equal_coefficient", "equal_power", "equal_decay"}
        How the rolling coefficient is matched to :math:`\mu_0` (`COMPARISONS`,
        `matched_delta`).

    Returns
    -------
    numpy.ndarray
        The ratio, of the broadcast shape of ``mu0`` and ``k``.

    Notes
    -----
    :math:`(2\pi \alpha_1 / \beta)(\mu_0) / (2\pi \sigma_g / \nu_g)(\delta)`,
    :math:`\delta` from ``matched_delta(mu0, k, comparison)``.  Limits for large
    :math:`\mu_0`: :math:`k^2 / (k + 1)^2` (equal coefficients), 1 (equal power),
    :math:`k` (equal decay).

    Examples
    --------
    Above 1 where the slipping spiral untwists faster per turn:

    >>> from turntable import rolling
    >>> for comparison in rolling.COMPARISONS:
    ...     ratio = rolling.growth_per_turn_ratio([0.1, 1.0], 0.4, comparison)
    ...     print(comparison, ratio.round(3))
    equal_coefficient [1.342 0.211]
    equal_power [2.721 1.06 ]
    equal_decay [1.056 0.443]
    """
    from turntable.spectrum import log_growth_per_turn as slipping_growth

    delta = matched_delta(mu0, k, comparison)
    return slipping_growth(mu0, k) / log_growth_per_turn(delta, k)


class RollingNewtonEuler(NamedTuple):
    """Trajectory of the constrained 3-D equations: t (n,), r, v, w (n, 3), force F (n, 3).

    Examples
    --------
    >>> from turntable import rolling
    >>> z0 = rolling.state_on_constraint([0, 0, 1, 0])
    >>> result = rolling.newton_euler(z0, [0.0, 1.0], 0.1, 0.4)
    >>> result.r.shape, result.force.shape
    ((2, 3), (2, 3))
    """

    t: NDArray[np.float64]
    r: NDArray[np.float64]
    v: NDArray[np.float64]
    w: NDArray[np.float64]
    force: NDArray[np.float64]

    @property
    def z(self) -> NDArray[np.float64]:
        """The planar state (x, y, vx, vy, wx, wy), shape (n, 6)."""
        return np.column_stack([self.r[:, :2], self.v[:, :2], self.w[:, :2]])


def newton_euler(
    z0: ArrayLike,
    t: ArrayLike,
    delta: float,
    k: float,
    *,
    torque: str = "horizontal",
    wz0: float = 0.0,
    g: float = 9.81,
    rtol: float = 1e-12,
    atol: float = 1e-13,
) -> RollingNewtonEuler:
    r"""Integrate the constrained 3-D Newton-Euler equations of the rolling ball.

    Parameters
    ----------
    z0 : array_like
        Initial planar state on the no-slip constraint; the centre starts at
        height 1 with vz = 0.
    t : array_like
        Increasing 1-D array of non-negative output times.
    delta, k : float
        Rolling-resistance coefficient and inertia ratio, > 0.
    torque : {"horizontal", "full", "relative"}
        :math:`M = -\delta \omega_h`, :math:`M = -\delta \omega`, or
        :math:`M = -\delta (\omega - \gamma)` (relative to the plane).
    wz0 : float
        Initial vertical spin, finite.
    g : float
        Dimensionless gravity :math:`g / (R \Omega^2)`, finite and > 0 (the normal
        force is m g: the ball is pressed onto the plane).
    rtol, atol : float
        Tolerances of `scipy.integrate.solve_ivp` (DOP853), finite and > 0.

    Returns
    -------
    RollingNewtonEuler

    See Also
    --------
    turntable.rolling.solve : The closed form.

    Notes
    -----
    (R1)-(R3) with the reaction F as Lagrange multiplier: at each instant F
    solves the 3x3 linear system obtained by differentiating (R1),
    dv/dt + gamma x dw/dt - gamma x v = 0, with dv/dt = F - g gamma and
    k dw/dt = -gamma x F + M.  Nothing of the reduction (R4) is used.

    Examples
    --------
    The constrained 3-D equations agree with the closed form:

    >>> import numpy as np
    >>> from turntable import rolling
    >>> z0, t = rolling.state_on_constraint([0, 0, 1, 0]), np.linspace(0.0, 2.0, 5)
    >>> result = rolling.newton_euler(z0, t, 0.1, 0.4)
    >>> bool(abs(result.z - rolling.solve(z0, t, 0.1, 0.4)).max() < 1e-9)
    True
    """
    if torque not in TORQUES:
        raise ValueError(f"torque must be one of {TORQUES}; got {torque!r}")
    z0 = _validate.state("z0", z0)
    m = _modes(z0, delta, k)  # validates delta, k and the constraint
    delta, k = m.delta, m.k
    t = _validate.times("t", t, increasing=True)
    if t.size == 0:
        raise ValueError("t must be a non-empty 1-D array of times >= 0")
    wz0 = _validate.finite_scalar("wz0", wz0)
    g = _validate.positive_scalar("g", g)
    rtol = _validate.positive_scalar("rtol", rtol)
    atol = _validate.positive_scalar("atol", atol)
    gvec = g * GAMMA

    def cross_g(a: NDArray) -> NDArray:
        return np.cross(GAMMA, a)

    # d/dt (R1) = A F + b: A F = F + gamma x (-gamma x F) / k
    amat = np.column_stack([e + cross_g(-cross_g(e)) / k for e in np.eye(3)])

    def moment(w: NDArray) -> NDArray:
        if torque == "horizontal":
            return -delta * np.array([w[0], w[1], 0.0])
        if torque == "full":
            return -delta * w
        return -delta * (w - GAMMA)

    def force(v: NDArray, w: NDArray) -> NDArray:
        rhs = gvec + cross_g(v) - cross_g(moment(w)) / k
        return np.linalg.solve(amat, rhs)

    def rhs(_t: float, y: NDArray) -> NDArray:
        v, w = y[3:6], y[6:9]
        f = force(v, w)
        return np.concatenate([v, f - gvec, (-cross_g(f) + moment(w)) / k])

    from scipy.integrate import solve_ivp

    y0 = np.array([z0[0], z0[1], 1.0, z0[2], z0[3], 0.0, z0[4], z0[5], wz0])
    sol = solve_ivp(
        rhs, (0.0, max(float(t[-1]), 1e-300)), y0, method="DOP853", t_eval=t, rtol=rtol, atol=atol
    )
    if not sol.success:
        raise RuntimeError(f"solve_ivp failed: {sol.message}")
    y = sol.y.T
    forces = np.array([force(row[3:6], row[6:9]) for row in y])
    return RollingNewtonEuler(sol.t, y[:, 0:3], y[:, 3:6], y[:, 6:9], forces)
