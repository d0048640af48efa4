"""The rolling model's linear system and its eigenvalues in closed form (`turntable.rolling`).

(R4) of docs/theory.md as the real 4x4 matrix on (x, y, vx, vy), and its eigenvalues
lambda_g, lambda_c from the roots p + i q of S, without cancellation.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

from turntable import _validate


def system_matrix(delta: float, k: float) -> NDArray[np.float64]:
    """Return the 4x4 matrix of the rolling model on (x, y, vx, vy).

    Parameters
    ----------
    delta : float
        Dimensionless rolling-resistance coefficient delta_dim / (m R^2 Omega) > 0.
    k : float
        Inertia ratio I / (m R^2) > 0.

    Returns
    -------
    numpy.ndarray
        M of d(x, y, vx, vy)/dt = M (x, y, vx, vy), shape (4, 4).

    Notes
    -----
    Equation (R4) of the module docstring in real form::

        M = [[0, I], [delta J / (k + 1), (k J - delta I) / (k + 1)]]

    with J = [[0, -1], [1, 0]]; w = r + J v follows from the constraint.
    """
    delta = _validate.positive_scalar("delta", delta)
    k = _validate.positive_scalar("k", k)
    i2 = np.eye(2)
    j = np.array([[0.0, -1.0], [1.0, 0.0]])
    return np.block(
        [[np.zeros((2, 2)), i2], [delta * j / (k + 1.0), (k * j - delta * i2) / (k + 1.0)]]
    )


class RollingSpectrum(NamedTuple):
    """Real and imaginary parts of the two roots of the rolling model.

    Attributes
    ----------
    sigma_g, nu_g : numpy.ndarray
        Growth rate (> 0) and rate of turning of the spiral, lambda_g = sigma_g + i nu_g.
    sigma_c, nu_c : numpy.ndarray
        Decay rate (< 0) and rate of turning of the spiral's centre,
        lambda_c = sigma_c + i nu_c.
    """

    sigma_g: NDArray[np.float64]
    nu_g: NDArray[np.float64]
    sigma_c: NDArray[np.float64]
    nu_c: NDArray[np.float64]


def _spectrum_rolling(delta: NDArray[np.float64], k: NDArray[np.float64]) -> RollingSpectrum:
    """`spectrum` on validated, broadcast arguments (scaled so nothing overflows)."""
    c = np.maximum(delta, k)
    d, kh = delta / c, k / c
    re_s = (d - kh) * (d + kh)
    im_s = 2.0 * d * (kh + 2.0 / c)
    abs_s = np.hypot(re_s, im_s)
    big = delta > k
    with np.errstate(divide="ignore", invalid="ignore"):
        p_big = np.sqrt((abs_s + re_s) / 2.0)
        q_small = np.sqrt((abs_s - re_s) / 2.0)
        ph = np.where(big, p_big, im_s / (2.0 * q_small))
        qh = np.where(big, im_s / (2.0 * p_big), q_small)
    a = abs_s + d * d + kh * kh
    p, q = ph * c, qh * c
    sigma_g = 4.0 * d * qh / (a * (k + 2.0 + q))
    nu_g = (k + q) / (2.0 * (k + 1.0))
    sigma_c = -(delta + p) / (2.0 * (k + 1.0))
    nu_c = -4.0 * d * d / (a * (q + k))
    return RollingSpectrum(sigma_g, nu_g, sigma_c, nu_c)
