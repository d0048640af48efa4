r"""Asymptotic regimes of the model: small friction (Fig. 2) and the no-slip limit (Section 3).

All quantities are dimensionless: length :math:`R`, time :math:`1/\Omega`, mass :math:`m`.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from turntable import _validate
from turntable.solution import nonholonomic, solve
from turntable.spectrum import Expansion


def small_friction_expansion(mu0: ArrayLike, k: ArrayLike) -> Expansion:
    r"""Return the leading small-:math:`\mu_0` behaviour of :math:`\alpha_1`, :math:`\alpha_2` and
    :math:`\beta`.

    Parameters
    ----------
    mu0, k : float or array_like
        Friction coefficient and inertia ratio, finite and > 0.

    Returns
    -------
    Expansion
        :math:`\alpha_1 = \sqrt{\mu_0/2} - \mu`, :math:`\alpha_2 = -\sqrt{\mu_0/2} - \mu` and
        :math:`\beta = \sqrt{\mu_0/2}`, with :math:`\mu = \mu_0 (k + 1) / (2 k)` of (2.2).

    See Also
    --------
    turntable.spectrum : The exact rates.

    Notes
    -----
    From (2.5) with :math:`\varepsilon = 4 k^2 / (\mu_0 (k+1)^2) \to \infty` as
    :math:`\mu_0 \to 0`:

    .. math::

        a = \sqrt{\varepsilon/2}\, \left(1 + \tfrac{1}{2\varepsilon} + O(\varepsilon^{-2})\right),
        \quad
        b = \sqrt{\varepsilon/2}\, \left(1 - \tfrac{1}{2\varepsilon} + O(\varepsilon^{-2})\right),
        \quad
        \mu \sqrt{\varepsilon/2} = \sqrt{\mu_0/2},

    so each returned value has an error :math:`O(\mu_0^{3/2})`.  To leading order all three
    rates are :math:`\sqrt{\mu_0/2}` in size.

    Examples
    --------
    Against the exact roots at :math:`\mu_0 = 10^{-3}`:

    >>> from turntable import small_friction_expansion, spectrum
    >>> approx, exact = small_friction_expansion(1e-3, 0.4), spectrum(1e-3, 0.4)
    >>> print(f"{approx.beta:.5f} {exact.beta:.5f}")
    0.02236 0.02233
    """
    mu0 = _validate.positive("mu0", mu0)
    k = _validate.positive("k", k)
    mu0, k = np.broadcast_arrays(mu0, k)
    root = np.sqrt(mu0 / 2.0)
    mu = mu0 * (k + 1.0) / (2.0 * k)
    return Expansion(root - mu, -root - mu, root + 0.0 * k)


def nonholonomic_period(k: ArrayLike) -> NDArray[np.float64]:
    r"""Return the period :math:`2\pi (k + 1) / k` of the no-slip motion of the centre.

    Parameters
    ----------
    k : float or array_like
        Inertia ratio, finite and > 0.

    Returns
    -------
    numpy.ndarray
        :math:`2\pi (k + 1) / k`, of the shape of ``k``.

    Notes
    -----
    Equation (3.3): without slip the centre circles about :math:`(x_0, y_0)` of (2.8)
    at the constant rate :math:`k / (k + 1)` (2/7 of the plane's rate for :math:`k = 2/5`).

    Examples
    --------
    >>> from turntable import nonholonomic_period
    >>> print(f"{nonholonomic_period(0.4):.6f}")
    21.991149
    """
    k = _validate.positive("k", k)
    return 2.0 * np.pi * (k + 1.0) / k


def limit_error(z0: ArrayLike, t: ArrayLike, mu0: ArrayLike, k: float) -> NDArray[np.float64]:
    r"""Return the largest distance between the slipping and the no-slip centre.

    Parameters
    ----------
    z0 : array_like
        Initial state (x, y, vx, vy, wx, wy), on or off the no-slip constraint.
    t : array_like
        1-D array of non-negative times on which the distance is sampled.
    mu0 : float or array_like
        Friction coefficient(s), finite and > 0.
    k : float
        Inertia ratio, finite and > 0.

    Returns
    -------
    numpy.ndarray
        Same shape as ``mu0``: :math:`\max_t |r(t; \mu_0) - r_{nh}(t)|`, with r the
        centre from `solve` and :math:`r_{nh}` the centre from `nonholonomic`.

    See Also
    --------
    turntable.limit_error_fit : Its power law in the friction.
    turntable.nonholonomic : The limit.

    Notes
    -----
    Section 3, (3.3): on a fixed interval the solution tends to the no-slip one
    started from `no_slip_state` (z0); the position error is :math:`O(1/\mu_0)`.

    Examples
    --------
    The error falls like :math:`1/\mu_0`:

    >>> import numpy as np
    >>> from turntable import limit_error
    >>> t = np.linspace(0.0, 5.0, 51)
    >>> limit_error([0, 0, 1, 0, 0, 0], t, [100.0, 1000.0], 0.4).round(5)
    array([0.00303, 0.0003 ])
    """
    t = _validate.times("t", t)
    mu0 = _validate.positive("mu0", mu0)
    k = _validate.positive_scalar("k", k)
    r_nh = nonholonomic(z0, t, k)[:, :2]
    err = [np.max(np.hypot(*(solve(z0, t, m, k)[:, :2] - r_nh).T)) for m in mu0.ravel()]
    return np.reshape(err, mu0.shape)


#: Samples of [0, t_end] at which `limit_error_fit` takes the largest position error.
LIMIT_FIT_TIMES = 1001


class LimitErrorFit(NamedTuple):
    r"""The largest position error of the no-slip limit and its power law in :math:`\mu_0`.

    Attributes
    ----------
    mu0 : numpy.ndarray
        The friction coefficients, increasing.
    error : numpy.ndarray
        `limit_error` on :math:`[0, t_\mathrm{end}]` at each :math:`\mu_0`.
    order : float
        :math:`p` of the least-squares line :math:`\ln e = \ln c + p \ln \mu_0` (:math:`e` the
        error).
    prefactor : float
        :math:`c` of that line.

    Examples
    --------
    >>> from turntable import limit_error_fit
    >>> result = limit_error_fit([1, 1, 0, 0, 0, 1], 20.0, [10.0, 30.0, 100.0], 0.4)
    >>> print(f"order {result.order:.2f}, prefactor {result.prefactor:.2f}")
    order -1.01, prefactor 0.49
    """

    mu0: NDArray[np.float64]
    error: NDArray[np.float64]
    order: float
    prefactor: float


def limit_error_fit(z0: ArrayLike, t_end: float, mu0: ArrayLike, k: float) -> LimitErrorFit:
    r"""Return the largest position error on :math:`[0, t_\mathrm{end}]` at each :math:`\mu_0` and
    its fitted order.

    Parameters
    ----------
    z0 : array_like
        Initial state (x, y, vx, vy, wx, wy), on or off the no-slip constraint.
    t_end : float
        End of the fixed interval [0, t_end], finite and > 0.
    mu0 : array_like
        At least two different friction coefficients, finite and > 0.
    k : float
        Inertia ratio, finite and > 0.

    Returns
    -------
    LimitErrorFit

    See Also
    --------
    turntable.limit_error : The error at one friction.

    Notes
    -----
    :math:`e(\mu_0) = \max_{0 \le t \le t_{end}} |r(t; \mu_0) - r_{nh}(t)|` (`limit_error`,
    on ``LIMIT_FIT_TIMES`` equally spaced times), and the least-squares fit
    :math:`\ln e = \ln c + p \ln \mu_0` over the given :math:`\mu_0`.  Section 3:
    :math:`p \to -1` (positions converge uniformly on a fixed interval at rate
    :math:`O(1/\mu_0)`).  The one fit of the order that
    the claim ``limit.convergence`` reports for the paper's ball and Fig. 6(b) draws.

    Examples
    --------
    >>> from turntable import limit_error_fit
    >>> fit = limit_error_fit([0, 0, 1, 0, 0, 0], 5.0, [100.0, 1000.0], 0.4)
    >>> print(f"order {fit.order:.3f}, prefactor {fit.prefactor:.3f}")
    order -1.000, prefactor 0.303
    """
    z0 = _validate.state("z0", z0)
    t_end = _validate.positive_scalar("t_end", t_end)
    mu0 = np.sort(_validate.positive("mu0", mu0).ravel())
    k = _validate.positive_scalar("k", k)
    if np.unique(mu0).size < 2:
        raise ValueError(f"mu0 must hold at least two different values; got {mu0.tolist()}")
    t = np.linspace(0.0, t_end, LIMIT_FIT_TIMES)
    error = limit_error(z0, t, mu0, k)
    order, log_c = np.polyfit(np.log(mu0), np.log(error), 1)
    return LimitErrorFit(mu0, error, float(order), float(np.exp(log_c)))
