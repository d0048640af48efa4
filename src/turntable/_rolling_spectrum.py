"""The rolling model's linear system and its eigenvalues in closed form (`turntable.rolling`).

(R4) of docs/theory.md as the real 4x4 matrix on (x, y, vx, vy), and its eigenvalues
lambda_g, lambda_c from the roots p + i q of S, without cancellation.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from turntable import _validate


def system_matrix(delta: float, k: float) -> NDArray[np.float64]:
    r"""Return the 4x4 matrix of the rolling model on (x, y, vx, vy).

    Parameters
    ----------
    delta : float
        Dimensionless rolling-resistance coefficient
        :math:`\delta_\text{dim} / (m R^2 \Omega) > 0`.
    k : float
        Inertia ratio :math:`I / (m R^2) > 0`.

    Returns
    -------
    numpy.ndarray
        M of d(x, y, vx, vy)/dt = M (x, y, vx, vy), shape (4, 4).

    Notes
    -----
    Equation (R4) of :doc:`/theory` in real form:

    .. math::

        M = \begin{pmatrix} 0 & I_2 \\ \frac{\delta J}{k + 1} & \frac{k J - \delta I_2}{k + 1}
            \end{pmatrix}, \qquad J = \begin{pmatrix} 0 & -1 \\ 1 & 0 \end{pmatrix};

    :math:`\omega = r + J v` follows from the constraint.

    Examples
    --------
    Its eigenvalues are `eigenvalues`:

    >>> import numpy as np
    >>> from turntable import rolling
    >>> lam = np.linalg.eigvals(rolling.system_matrix(0.1, 0.4))
    >>> closed_form = rolling.eigenvalues(0.1, 0.4)
    >>> bool(np.allclose(np.sort_complex(lam), np.sort_complex(closed_form)))
    True
    """
    delta = _validate.positive_scalar("delta", delta)
    k = _validate.positive_scalar("k", k)
    i2 = np.eye(2)
    j = np.array([[0.0, -1.0], [1.0, 0.0]])
    return np.block(
        [[np.zeros((2, 2)), i2], [delta * j / (k + 1.0), (k * j - delta * i2) / (k + 1.0)]]
    )


class RollingSpectrum(NamedTuple):
    r"""Real and imaginary parts of the two roots of the rolling model.

    Attributes
    ----------
    sigma_g, nu_g : numpy.ndarray
        Growth rate (> 0) and rate of turning of the spiral,
        :math:`\lambda_g = \sigma_g + i\nu_g`.
    sigma_c, nu_c : numpy.ndarray
        Decay rate (< 0) and rate of turning of the spiral's centre,
        :math:`\lambda_c = \sigma_c + i\nu_c`.

    Examples
    --------
    The spiral grows and its centre decays:

    >>> from turntable import rolling
    >>> s = rolling.spectrum(0.1, 0.4)
    >>> bool(s.sigma_g > 0), bool(s.sigma_c < 0)
    (True, True)
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


def spectrum(delta: ArrayLike, k: ArrayLike) -> RollingSpectrum:
    r"""Return :math:`\sigma_g`, :math:`\nu_g`, :math:`\sigma_c`, :math:`\nu_c` of the rolling
    model.

    Parameters
    ----------
    delta, k : float or array_like
        Rolling-resistance coefficient and inertia ratio, finite and > 0;
        broadcast against each other.

    Returns
    -------
    RollingSpectrum

    See Also
    --------
    turntable.spectrum : The rates of the slipping ball.

    Notes
    -----
    The closed forms of :doc:`/theory` (roots of
    :math:`(k+1) \lambda^2 + (\delta - i k) \lambda - i \delta`), each a quotient of
    positive numbers, accurate to a few units in the last place.

    Examples
    --------
    >>> from turntable import rolling
    >>> s = rolling.spectrum(0.1, 0.4)
    >>> print(f"sigma_g = {s.sigma_g:.6f}, nu_g = {s.nu_g:.6f}, sigma_c = {s.sigma_c:.6f}")
    sigma_g = 0.114305, nu_g = 0.346912, sigma_c = -0.185734
    """
    delta = _validate.positive("delta", delta)
    k = _validate.positive("k", k)
    delta, k = np.broadcast_arrays(delta, k)
    return _spectrum_rolling(delta, k)


def eigenvalues(delta: ArrayLike, k: ArrayLike) -> NDArray[np.complex128]:
    r"""Return the four eigenvalues of the real linear system `system_matrix`.

    Parameters
    ----------
    delta, k : float or array_like
        Rolling-resistance coefficient and inertia ratio, finite and > 0;
        broadcast against each other.

    Returns
    -------
    numpy.ndarray
        Complex, shape ``broadcast(delta, k).shape + (4,)``:
        :math:`(\lambda_g, \bar\lambda_g, \lambda_c, \bar\lambda_c)`.

    Notes
    -----
    See `spectrum` and :doc:`/theory`.

    Examples
    --------
    The growing pair first, then the centre's decaying pair:

    >>> from turntable import rolling
    >>> rolling.eigenvalues(0.1, 0.4).round(6)
    array([ 0.114305+0.346912j,  0.114305-0.346912j, -0.185734-0.061198j,
           -0.185734+0.061198j])
    """
    s = spectrum(delta, k)
    out = np.empty((*s.sigma_g.shape, 4), dtype=complex)
    out[..., 0] = s.sigma_g + 1j * s.nu_g
    out[..., 1] = s.sigma_g - 1j * s.nu_g
    out[..., 2] = s.sigma_c + 1j * s.nu_c
    out[..., 3] = s.sigma_c - 1j * s.nu_c
    return out


def growth_rate(delta: ArrayLike, k: ArrayLike) -> NDArray[np.float64]:
    r"""Return :math:`\sigma_g`, the growth rate per unit time of the spiral's radius.

    Parameters
    ----------
    delta, k : float or array_like
        Rolling-resistance coefficient and inertia ratio, finite and > 0.

    Returns
    -------
    numpy.ndarray
        :math:`\sigma_g`, of the broadcast shape.

    Notes
    -----
    :math:`\sigma_g = 4 \delta q / (A (k + 2 + q))` (:doc:`/theory`);
    :math:`\delta / (k (k + 1))` for small :math:`\delta`, about :math:`1 / \delta` for
    large :math:`\delta`.

    Examples
    --------
    About :math:`\delta / (k (k + 1))` for small :math:`\delta`:

    >>> from turntable import rolling
    >>> rolling.growth_rate([1e-4, 0.1], 0.4).round(6)
    array([0.000179, 0.114305])
    """
    return spectrum(delta, k).sigma_g


def log_growth_per_turn(delta: ArrayLike, k: ArrayLike) -> NDArray[np.float64]:
    r"""Return :math:`2\pi\sigma_g/\nu_g`, the logarithm of the spiral's growth per turn.

    Parameters
    ----------
    delta, k : float or array_like
        Rolling-resistance coefficient and inertia ratio, finite and > 0.

    Returns
    -------
    numpy.ndarray
        :math:`2\pi \sigma_g / \nu_g`, of the broadcast shape.

    Notes
    -----
    About :math:`2\pi \delta / k^2` for small :math:`\delta` and :math:`2\pi / \delta` for
    large :math:`\delta`.

    Examples
    --------

    >>> from turntable import rolling
    >>> print(rolling.log_growth_per_turn([1e-4, 1e4], 0.4))
    [0.003927 0.0006283]
    """
    s = spectrum(delta, k)
    return 2.0 * np.pi * s.sigma_g / s.nu_g


def centre_decay_rate(delta: ArrayLike, k: ArrayLike) -> NDArray[np.float64]:
    r"""Return :math:`|\sigma_c|`, the rate at which the spiral's centre approaches the axis.

    Parameters
    ----------
    delta, k : float or array_like
        Rolling-resistance coefficient and inertia ratio, finite and > 0.

    Returns
    -------
    numpy.ndarray
        :math:`|\sigma_c|`, of the broadcast shape.

    Notes
    -----
    :math:`|\sigma_c| = (\delta + p) / (2 (k + 1))`, between :math:`\delta / (2 (k + 1))`
    and :math:`\delta / k`; it is the decay rate of the non-growing part of the motion.

    Examples
    --------

    >>> from turntable import rolling
    >>> print(f"{rolling.centre_decay_rate(0.1, 0.4):.6f}")
    0.185734
    """
    return -spectrum(delta, k).sigma_c
