"""The rolling coefficient delta matched to a slipping mu0: equal power, equal decay.

The powers dissipated by the two frictions, the delta at which rolling along the slipping
path dissipates the slipping power (`equal_power_delta`, with the ball's own spin:
`own_spin_power_delta`), and the delta of equal decay of the non-growing part
(`equal_decay_delta`).  Public through `turntable.rolling`.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from turntable import _validate
from turntable._rolling_spectrum import _spectrum_rolling
from turntable.solution import slip_velocity
from turntable.spectrum import _spectrum


def power_rolling(z: ArrayLike, delta: float) -> NDArray[np.float64]:
    r"""Return the power dissipated by the rolling-resistance torque, :math:`\delta |w_h|^2`.

    Parameters
    ----------
    z : array_like
        State(s) with last axis (x, y, vx, vy, wx, wy).
    delta : float
        Rolling-resistance coefficient, > 0.

    Returns
    -------
    numpy.ndarray
        The power, of shape ``z.shape[:-1]``.

    Notes
    -----
    (R3): :math:`-M \cdot \omega = \delta (\omega_x^2 + \omega_y^2)`, in units
    :math:`m R^2 \Omega^3`.

    Examples
    --------
    >>> from turntable import rolling
    >>> rolling.power_rolling([[0, 0, 1, 0, 0, 1], [0, 0, 1, 0, 2, 0]], 0.1)
    array([0.1, 0.4])
    """
    z = _validate.states("z", z)
    delta = _validate.positive_scalar("delta", delta)
    return delta * (z[..., 4] ** 2 + z[..., 5] ** 2)


def power_slipping(z: ArrayLike, mu0: float) -> NDArray[np.float64]:
    r"""Return the power dissipated by viscous slipping friction, :math:`\mu_0 |u|^2`.

    Parameters
    ----------
    z : array_like
        State(s) with last axis (x, y, vx, vy, wx, wy).
    mu0 : float
        Friction coefficient, > 0.

    Returns
    -------
    numpy.ndarray
        The power, of shape ``z.shape[:-1]``.

    Notes
    -----
    Section 1 of the paper: :math:`F = -\mu_0 u` at the contact point, which slides
    with :math:`u` relative to the plane; in units :math:`m R^2 \Omega^3`.

    Examples
    --------
    A slip of speed 2 at :math:`\mu_0 = 0.5`:

    >>> from turntable import rolling
    >>> print(rolling.power_slipping([0, 0, 2, 0, 0, 0], 0.5))
    2.0
    """
    z = _validate.states("z", z)
    mu0 = _validate.positive_scalar("mu0", mu0)
    u = slip_velocity(z)
    return mu0 * (u[..., 0] ** 2 + u[..., 1] ** 2)


def _slipping_mode(mu0: ArrayLike, k: ArrayLike) -> tuple[NDArray[np.float64], ...]:
    """Validated mu0, k and, of lambda_+ = alpha1 + i beta, the parts that enter the powers.

    Returns mu0, k, alpha1, beta and y = (k + 1) beta - k, broadcast.  alpha1 = beta b /
    (a + 1) (as (a - 1) / b = b / (a + 1)); y = -2 k (h - 1) / (s (2 + s)) with
    s = sqrt(2 (h + 1)), h - 1 = eps (eps / (h + 1)), h = sqrt(1 + eps^2): no step
    cancels, overflows or underflows for any mu0 at which `turntable.spectrum` is finite.
    """
    mu0 = _validate.positive("mu0", mu0)
    k = _validate.positive("k", k)
    mu0, k = np.broadcast_arrays(mu0, k)
    with np.errstate(over="ignore"):  # alpha1 of _spectrum (not used) overflows below 1e-206
        sp = _spectrum(mu0, k)
    h = np.hypot(1.0, sp.eps)
    s = np.sqrt(2.0 * (h + 1.0))
    alpha1 = sp.beta * (sp.b / (sp.a + 1.0))
    y = -2.0 * k * (sp.eps * (sp.eps / (h + 1.0))) / (s * (2.0 + s))
    return mu0, k, alpha1, sp.beta, y


def equal_power_delta(mu0: ArrayLike, k: ArrayLike) -> NDArray[np.float64]:
    r"""Return :math:`\delta` at which rolling along the slipping path dissipates the slipping
    power.

    Parameters
    ----------
    mu0, k : float or array_like
        Slipping friction coefficient and inertia ratio, > 0.

    Returns
    -------
    numpy.ndarray
        :math:`\delta_P = \mu_0 |(k + 1) \lambda_+ - i k|^2 / (k^2 |1 + i \lambda_+|^2)`.

    Notes
    -----
    The equal-power comparison, equal mean dissipated power on the same motion: the same path
    of the centre, each mechanism with its own kinematics.  The path is the
    slipping model's spiral about the turntable's axis, its growing mode
    :math:`r = \rho e^{\lambda_+ t}` (:math:`\lambda_+ = \alpha_1 + i\beta` of (2.5)).

    - Slipping: the mode has :math:`c = v - i k \omega = 0`, so :math:`v = \lambda_+ r` and
      :math:`\omega = -i \lambda_+ r / k`; the contact point slides with
      :math:`u = v + i \omega - i r = ((k + 1) \lambda_+ - i k) r / k` and friction
      dissipates :math:`\mu_0 |u|^2`.
    - Rolling along the same path: the no-slip constraint (R1) fixes the spin,
      :math:`\omega = r + i v = (1 + i \lambda_+) r`, and the torque (R3) dissipates
      :math:`\delta |\omega|^2`.

    Both powers are :math:`|r|^2 = |\rho|^2 e^{2 \alpha_1 t}` times a constant, so they
    are equal at every instant, hence on average, for

    .. math::

        \delta_P = \frac{\mu_0 |(k + 1) \lambda_+ - i k|^2}{k^2 |1 + i \lambda_+|^2}.

    Evaluated as
    :math:`\left(\sqrt{\mu_0}\, |(k + 1) \alpha_1 + i y| / (k |(1 - \beta) + i \alpha_1|)\right)^2`
    with :math:`y = (k + 1) \beta - k` written without cancellation;
    :math:`1 - \beta > 1 / (k + 1)` does not cancel either (:math:`\beta < k / (k + 1)`).
    Limits: :math:`\delta_P / \mu_0 \to 1` as :math:`\mu_0 \to 0`
    (:math:`\lambda_+ \sim \sqrt{i \mu_0}`, so :math:`u \sim -i r` and :math:`\omega \sim r`:
    at small :math:`\mu_0` the ball slides with the plane's speed under it and would roll
    with unit spin); :math:`\delta_P \sim k^4 / (\mu_0 (k + 1)^2)` as
    :math:`\mu_0 \to \infty`, where the slipping motion becomes the no-slip one and both
    spins agree.  `own_spin_power_delta`
    is the alternative that charges the torque on the slipping ball's own spin.

    Examples
    --------
    >>> from turntable import rolling
    >>> print(f"{rolling.equal_power_delta(1.0, 0.4):.6f}")
    0.012428
    """
    mu0, k, alpha1, beta, y = _slipping_mode(mu0, k)
    num = np.hypot((k + 1.0) * alpha1, y)
    den = k * np.hypot(1.0 - beta, alpha1)
    return (np.sqrt(mu0) * num / den) ** 2


def own_spin_power_delta(mu0: ArrayLike, k: ArrayLike) -> NDArray[np.float64]:
    r"""Return :math:`\delta` that matches the slipping power with the torque on the slipping spin.

    Parameters
    ----------
    mu0, k : float or array_like
        Slipping friction coefficient and inertia ratio, > 0.

    Returns
    -------
    numpy.ndarray
        :math:`\delta_S = \mu_0 |(k + 1) \lambda_+ - i k|^2 / |\lambda_+|^2`.

    Notes
    -----
    NOT the equal-power comparison: the alternative reading it replaces, kept so that the
    difference can be shown.  On the slipping spiral about the axis it charges the
    rolling-resistance power :math:`\delta |\omega|^2` on the slipping ball's own spin
    :math:`\omega = -i \lambda_+ r / k`, which a ball rolling along that path cannot have
    (its spin is :math:`\omega = r + i v`).  :math:`\mu_0 |u|^2 = \delta_S |\omega|^2` at
    every instant; :math:`\delta_S \to k^2` as :math:`\mu_0 \to 0` (the slipping spin
    vanishes like :math:`\sqrt{\mu_0}` while the slip does not),
    :math:`\delta_S \sim k^4 / (\mu_0 (k + 1)^2)` as :math:`\mu_0 \to \infty` (as
    `equal_power_delta`).  Same evaluation as `equal_power_delta`, with
    :math:`|\lambda_+| = \beta |1 + i \alpha_1 / \beta|`.

    Examples
    --------
    >>> from turntable import rolling
    >>> print(f"{rolling.own_spin_power_delta(1.0, 0.4):.6f}")
    0.012812
    """
    mu0, k, alpha1, beta, y = _slipping_mode(mu0, k)
    num = np.hypot((k + 1.0) * alpha1, y)
    return (np.sqrt(mu0) * num / (beta * np.hypot(1.0, alpha1 / beta))) ** 2


def equal_decay_delta(mu0: ArrayLike, k: ArrayLike) -> NDArray[np.float64]:
    r"""Return :math:`\delta` at which the rolling centre decays at the slipping :math:`|\alpha_2|`.

    Parameters
    ----------
    mu0, k : float or array_like
        Slipping friction coefficient and inertia ratio, > 0.

    Returns
    -------
    numpy.ndarray
        The unique :math:`\delta` with :math:`|\sigma_c(\delta, k)| = |\alpha_2(\mu_0, k)|`.

    Notes
    -----
    The equal-decay comparison: equal decay rates of the non-growing parts (:math:`z_-` of (2.7)
    and the moving centre).  :math:`|\sigma_c| = (\delta + p) / (2 (k + 1))` increases
    strictly with :math:`\delta` and lies between :math:`\delta / (2 (k + 1))` and
    :math:`\delta / k`, so the root lies in :math:`[k |\alpha_2|, 2 (k + 1) |\alpha_2|]`.
    The lower end is the root's limit for small :math:`\mu_0` (where
    :math:`|\sigma_c| = \delta / k\, (1 - O(\delta))`), so in doubles it can be the root
    itself: Brent's method brackets it in :math:`[k |\alpha_2| / 2, 4 (k + 1) |\alpha_2|]`,
    where the function changes sign by at least a half at either end, and finds it to a
    relative :math:`10^{-15}`.  Large :math:`\mu_0`: :math:`\delta \sim \mu_0 (k+1)^2 / k`;
    small :math:`\mu_0`: :math:`\delta \sim k |\alpha_2| \sim k \sqrt{\mu_0 / 2}`.

    Examples
    --------
    The rolling centre then decays at the slipping :math:`|\alpha_2|`:

    >>> from turntable import rolling, spectrum
    >>> delta = rolling.equal_decay_delta(1.0, 0.4)
    >>> rate, alpha2 = rolling.centre_decay_rate(delta, 0.4), spectrum(1.0, 0.4).alpha2
    >>> print(f"{delta:.6f} {rate:.6f} {-alpha2:.6f}")
    4.698148 3.522587 3.522587
    """
    from scipy.optimize import brentq

    mu0 = _validate.positive("mu0", mu0)
    k = _validate.positive("k", k)
    mu0, k = np.broadcast_arrays(mu0, k)
    with np.errstate(over="ignore"):  # alpha1 of _spectrum (not used) overflows below 1e-206
        target = -_spectrum(mu0, k).alpha2
    out = np.empty(mu0.shape)
    for idx in np.ndindex(mu0.shape):
        kk, a2 = np.float64(k[idx]), float(target[idx])

        def f(dl: float, kk: np.float64 = kk, a2: float = a2) -> float:
            return float(-_spectrum_rolling(np.float64(dl), kk).sigma_c) / a2 - 1.0

        lo, hi = 0.5 * float(kk) * a2, 4.0 * (float(kk) + 1.0) * a2
        out[idx] = brentq(f, lo, hi, xtol=1e-300, rtol=1e-15)
    return out
