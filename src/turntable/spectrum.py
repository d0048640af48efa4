r"""The linear system (1.7) and its spectrum (2.1)-(2.6), (2.9)-(2.10), (3.2).

All quantities are dimensionless: length :math:`R`, time :math:`1/\Omega`, mass :math:`m`,
so that ``mu0`` stands for :math:`\mu_0 / (m \Omega)` and ``k`` for :math:`I / (m R^2)`.

The closed forms are rewritten so that no step subtracts nearly equal
numbers.  With ``h = sqrt(1 + eps^2)``, ``a = sqrt((h + 1) / 2)`` and the
identity ``mu * eps = 2 k / (k + 1)``,

    alpha1 = k eps / ((k + 1) (h + 1) (a + 1))
    alpha2 = -mu (a + 1)
    beta   = 2 k / ((k + 1) sqrt(2 (h + 1)))

each of which is a product or quotient of positive numbers, so each is
accurate to a few units in the last place for every mu0 > 0 and k > 0.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from turntable import _validate

#: The golden ratio; :math:`\alpha_1` peaks where :math:`a = (1 + \sqrt 5) / 2` (see
#: `alpha1_peak`).
GOLDEN = (1.0 + np.sqrt(5.0)) / 2.0

_I2 = np.eye(2)
_J = np.array([[0.0, -1.0], [1.0, 0.0]])


def system_matrix(mu0: float, k: float) -> NDArray[np.float64]:
    r"""Return the 6x6 matrix :math:`L` of the linear system :math:`\dot z = L z`.

    Parameters
    ----------
    mu0 : float
        Dimensionless viscous friction coefficient, :math:`\mu_0 / (m \Omega) > 0`.
    k : float
        Inertia ratio :math:`I / (m R^2) > 0` (2/5 for a homogeneous ball).

    Returns
    -------
    numpy.ndarray
        The matrix L, shape (6, 6), acting on z = (x, y, vx, vy, wx, wy).

    See Also
    --------
    turntable.eigenvalues : Its nonzero eigenvalues.

    Notes
    -----
    Equation (1.7) of the paper:

    .. math::

        L = \begin{pmatrix} 0 & I_2 & 0 \\ \mu_0 J & -\mu_0 I_2 & -\mu_0 J \\
            \tfrac{\mu_0}{k} I_2 & \tfrac{\mu_0}{k} J & -\tfrac{\mu_0}{k} I_2 \end{pmatrix},
        \qquad J = \begin{pmatrix} 0 & -1 \\ 1 & 0 \end{pmatrix},

    with :math:`I_2` the 2x2 identity.

    Examples
    --------
    Its nonzero eigenvalues are `eigenvalues`; its kernel, the equilibria, is two-dimensional:

    >>> import numpy as np
    >>> from turntable import system_matrix
    >>> L = system_matrix(1.0, 0.4)
    >>> L.shape, int(np.linalg.matrix_rank(L))
    ((6, 6), 4)
    """
    mu0 = _validate.positive_scalar("mu0", mu0)
    k = _validate.positive_scalar("k", k)
    z = np.zeros((2, 2))
    return np.block(
        [
            [z, _I2, z],
            [mu0 * _J, -mu0 * _I2, -mu0 * _J],
            [(mu0 / k) * _I2, (mu0 / k) * _J, -(mu0 / k) * _I2],
        ]
    )


class Spectrum(NamedTuple):
    r"""Real and imaginary parts of the nonzero eigenvalues of L.

    Attributes
    ----------
    alpha1 : numpy.ndarray
        Growth rate of the modes :math:`\lambda_{1,2} = \alpha_1 \pm i\beta` (> 0).
    alpha2 : numpy.ndarray
        Decay rate of the modes :math:`\lambda_{3,4} = \alpha_2 \pm i\beta` (< 0).
    beta : numpy.ndarray
        Common angular frequency of all four modes.
    mu : numpy.ndarray
        :math:`\mu = \mu_0 (k + 1) / (2 k)` of (2.2).
    eps : numpy.ndarray
        :math:`\varepsilon = 4 k^2 / (\mu_0 (k + 1)^2)` of (2.2).
    a : numpy.ndarray
        :math:`a = \sqrt{(\sqrt{1 + \varepsilon^2} + 1) / 2}` of (2.5).
    b : numpy.ndarray
        :math:`b = \sqrt{(\sqrt{1 + \varepsilon^2} - 1) / 2}` of (2.5).

    Examples
    --------
    >>> from turntable import spectrum
    >>> s = spectrum(1.0, 0.4)
    >>> print(f"alpha1 {float(s.alpha1):.4f}, alpha2 {float(s.alpha2):.4f}, "
    ...       f"beta {float(s.beta):.4f}")
    alpha1 0.0226, alpha2 -3.5226, beta 0.2821
    """

    alpha1: NDArray[np.float64]
    alpha2: NDArray[np.float64]
    beta: NDArray[np.float64]
    mu: NDArray[np.float64]
    eps: NDArray[np.float64]
    a: NDArray[np.float64]
    b: NDArray[np.float64]


def _spectrum(mu0: NDArray[np.float64], k: NDArray[np.float64]) -> Spectrum:
    """`spectrum` on arguments that are already validated."""
    kk = k / (k + 1.0)
    mu = mu0 / (2.0 * kk)
    eps = 4.0 * kk * kk / mu0
    h = np.hypot(1.0, eps)
    a = np.sqrt((h + 1.0) / 2.0)
    b = eps / np.sqrt(2.0 * (h + 1.0))
    alpha1 = kk * eps / ((h + 1.0) * (a + 1.0))
    alpha2 = -mu * (a + 1.0)
    beta = 2.0 * kk / np.sqrt(2.0 * (h + 1.0))
    return Spectrum(alpha1, alpha2, beta, mu, eps, a, b)


def spectrum(mu0: ArrayLike, k: ArrayLike) -> Spectrum:
    r"""Return :math:`\alpha_1`, :math:`\alpha_2`, :math:`\beta` and the auxiliary :math:`\mu`,
    :math:`\varepsilon`, :math:`a`, :math:`b`.

    Parameters
    ----------
    mu0, k : float or array_like
        Friction coefficient and inertia ratio, finite and > 0; broadcast
        against each other.

    Returns
    -------
    Spectrum
        Named tuple of arrays of the broadcast shape.

    See Also
    --------
    turntable.eigenvalues : The same rates as complex eigenvalues.
    turntable.small_friction_expansion : Its leading terms at small friction.
    turntable.large_friction_expansion : Its leading terms at large friction.

    Notes
    -----
    Equations (2.2) and (2.5):

    .. math::

        \mu = \frac{\mu_0 (k + 1)}{2 k}, \quad
        \varepsilon = \frac{4 k^2}{\mu_0 (k + 1)^2}, \quad
        \alpha_1 = \mu (a - 1), \quad \alpha_2 = -\mu (a + 1), \quad \beta = \mu b,

    evaluated in the cancellation-free form given in the module docstring.

    Examples
    --------
    >>> from turntable import spectrum
    >>> s = spectrum(1.0, 0.4)
    >>> print(f"alpha1 = {s.alpha1:.6f}, alpha2 = {s.alpha2:.6f}, beta = {s.beta:.6f}")
    alpha1 = 0.022587, alpha2 = -3.522587, beta = 0.282074
    """
    mu0 = _validate.positive("mu0", mu0)
    k = _validate.positive("k", k)
    mu0, k = np.broadcast_arrays(mu0, k)
    return _spectrum(mu0, k)


def eigenvalues(mu0: ArrayLike, k: ArrayLike) -> NDArray[np.complex128]:
    r"""Return the four nonzero eigenvalues of :math:`L`.

    Parameters
    ----------
    mu0, k : float or array_like
        Friction coefficient and inertia ratio, finite and > 0; broadcast
        against each other.

    Returns
    -------
    numpy.ndarray
        Complex array of shape ``broadcast(mu0, k).shape + (4,)`` whose last
        axis is :math:`(\alpha_1 + i\beta, \alpha_1 - i\beta, \alpha_2 + i\beta,
        \alpha_2 - i\beta)`.

    See Also
    --------
    turntable.spectrum : The same rates as real numbers.
    turntable.system_matrix : The matrix whose eigenvalues they are.

    Notes
    -----
    Equation (2.4): :math:`\lambda_{1,2} = \mu (-1 + \sqrt{1 \pm i\varepsilon})` and
    :math:`\lambda_{3,4} = \mu (-1 - \sqrt{1 \pm i\varepsilon})`; each real and imaginary part
    has a relative error of a few units in the last place for all
    :math:`\mu_0, k > 0` (see ``benchmarks/``).

    Examples
    --------
    Two pairs :math:`\alpha_1 \pm i\beta` and :math:`\alpha_2 \pm i\beta`, with
    :math:`\alpha_1 + \alpha_2 = -\mu_0 (k + 1) / k` to rounding:

    >>> from turntable import eigenvalues
    >>> lam = eigenvalues(1.0, 0.4)
    >>> lam.round(4)
    array([ 0.0226+0.2821j,  0.0226-0.2821j, -3.5226+0.2821j, -3.5226-0.2821j])
    >>> bool(abs(lam[0].real + lam[2].real + 3.5) < 1e-12)
    True
    """
    s = spectrum(mu0, k)
    out = np.empty((*s.alpha1.shape, 4), dtype=complex)
    out[..., 0] = s.alpha1 + 1j * s.beta
    out[..., 1] = s.alpha1 - 1j * s.beta
    out[..., 2] = s.alpha2 + 1j * s.beta
    out[..., 3] = s.alpha2 - 1j * s.beta
    return out


def log_damping_ratio(mu0: ArrayLike, k: ArrayLike) -> NDArray[np.float64]:
    r"""Return :math:`\ln N`, the logarithm of the decay of :math:`z_-` over one period.

    Parameters
    ----------
    mu0, k : float or array_like
        Friction coefficient and inertia ratio, finite and > 0.

    Returns
    -------
    numpy.ndarray
        :math:`\ln N = 2\pi |\alpha_2| / \beta`, of the broadcast shape.

    Notes
    -----
    Equations (2.9)-(2.10): over one period :math:`T = 2\pi / \beta` the decaying
    term falls by :math:`N = e^{|\alpha_2| T}`.  Since
    :math:`|\alpha_2| / \beta = (a + 1) / b = \sqrt{(a + 1) / (a - 1)} > 1`,
    :math:`\ln N > 2\pi` for all :math:`\mu_0` and k, tending to :math:`2\pi` as
    :math:`\mu_0 \to 0`.  N itself overflows a double near :math:`\mu_0 = 5`, so only
    its logarithm is returned.

    Examples
    --------
    Above the bound :math:`2\pi` for every :math:`\mu_0` (here :math:`k = 2/5`):

    >>> import numpy as np
    >>> from turntable import log_damping_ratio
    >>> log_damping_ratio([1e-3, 1.0], 0.4).round(2)
    array([ 6.79, 78.47])
    >>> bool(np.all(log_damping_ratio(np.geomspace(1e-6, 1e6, 49), 0.4) > 2 * np.pi))
    True
    """
    s = spectrum(mu0, k)
    return 2.0 * np.pi * (s.a + 1.0) / s.b


def log_growth_per_turn(mu0: ArrayLike, k: ArrayLike) -> NDArray[np.float64]:
    r"""Return :math:`2\pi\alpha_1/\beta`, the log growth of the spiral per turn.

    Parameters
    ----------
    mu0, k : float or array_like
        Friction coefficient and inertia ratio, finite and > 0.

    Returns
    -------
    numpy.ndarray
        :math:`2\pi\alpha_1 / \beta`, of the broadcast shape.

    Notes
    -----
    :math:`\alpha_1 / \beta = (a - 1) / b = \sqrt{(a - 1) / (a + 1)} = \beta / |\alpha_2|`,
    which decreases monotonically from 1 (:math:`\mu_0 \to 0`) to 0
    (:math:`\mu_0 \to \infty`).

    Examples
    --------
    The spiral grows by less per turn as friction grows:

    >>> from turntable import log_growth_per_turn
    >>> log_growth_per_turn([0.1, 1.0, 10.0], 0.4).round(4)
    array([2.7..., 0.5031, 0.05...])
    """
    s = spectrum(mu0, k)
    return 2.0 * np.pi * s.b / (s.a + 1.0)


class Peak(NamedTuple):
    r"""Location and height of the maximum of :math:`\alpha_1` over :math:`\mu_0`.

    Examples
    --------
    The largest growth rate at :math:`k = 0.4` (Figure 2):

    >>> from turntable import alpha1_peak
    >>> peak = alpha1_peak(0.4)
    >>> print(f"alpha1 = {float(peak.alpha1):.4f} at mu0 = {float(peak.mu0):.4f}")
    alpha1 = 0.0858 at mu0 = 0.0793
    """

    mu0: NDArray[np.float64]
    alpha1: NDArray[np.float64]
    eps: float


def alpha1_peak(k: ArrayLike) -> Peak:
    r"""Return the friction :math:`\mu_0` at which :math:`\alpha_1` is largest, and :math:`\alpha_1`
    there.

    Parameters
    ----------
    k : float or array_like
        Inertia ratio, finite and > 0.

    Returns
    -------
    Peak
        :math:`\mu_0 = 2 k^2 / ((k + 1)^2 \varphi^{3/2})` and
        :math:`\alpha_1 = k / (k + 1)\, \varphi^{-5/2}`, with :math:`\varphi` the golden
        ratio, and the universal :math:`\varepsilon = 2 \varphi^{3/2}` at the peak.

    See Also
    --------
    turntable.spectrum : The rates at any friction.

    Notes
    -----
    In terms of a of (2.5),
    :math:`\alpha_1 = \frac{k}{k + 1} \sqrt{(a - 1)/(a + 1)} / a`,
    whose logarithmic derivative vanishes where :math:`a^2 - a - 1 = 0`, i.e.
    :math:`a = \varphi`.  For :math:`k = 2/5` the peak is at :math:`\mu_0 = 0.0793`.

    Examples
    --------
    >>> import numpy as np
    >>> from turntable import alpha1_peak, spectrum
    >>> peak = alpha1_peak(0.4)
    >>> print(f"mu0 = {peak.mu0:.4f}, alpha1 = {peak.alpha1:.4f}")
    mu0 = 0.0793, alpha1 = 0.0858
    >>> bool(spectrum(np.array([0.9, 1.1]) * peak.mu0, 0.4).alpha1.max() < peak.alpha1)
    True
    """
    k = _validate.positive("k", k)
    kk = k / (k + 1.0)
    eps_star = 2.0 * GOLDEN**1.5
    return Peak(4.0 * kk * kk / eps_star, kk * GOLDEN**-2.5, float(eps_star))


class Expansion(NamedTuple):
    r"""Large-:math:`\mu_0` expansion (3.2) of :math:`\alpha_1`, :math:`\alpha_2` and :math:`\beta`,
    to :math:`O(1/\mu_0)`.

    Examples
    --------
    Close to the exact rates at a large friction:

    >>> from turntable import large_friction_expansion, spectrum
    >>> approx, exact = large_friction_expansion(100.0, 0.4), spectrum(100.0, 0.4)
    >>> print(f"alpha1 {float(approx.alpha1):.4e} (exact {float(exact.alpha1):.4e})")
    alpha1 2.3324e-04 (exact 2.3324e-04)
    """

    alpha1: NDArray[np.float64]
    alpha2: NDArray[np.float64]
    beta: NDArray[np.float64]


def large_friction_expansion(mu0: ArrayLike, k: ArrayLike) -> Expansion:
    r"""Return the leading terms of (3.2) for the real and imaginary parts.

    Parameters
    ----------
    mu0, k : float or array_like
        Friction coefficient and inertia ratio, finite and > 0.

    Returns
    -------
    Expansion
        :math:`\alpha_1 = k^3 / (\mu_0 (k+1)^3)`,
        :math:`\alpha_2 = -\mu_0 (k+1) / k - k^3 / (\mu_0 (k+1)^3)`,
        :math:`\beta = k / (k+1)`.

    See Also
    --------
    turntable.spectrum : The exact rates.

    Notes
    -----
    Equation (3.2):

    .. math::

        \lambda_{1,2} &= \pm i \frac{k}{k+1} + \frac{k^3}{\mu_0 (k+1)^3} + O(\mu_0^{-2}),\\
        \lambda_{3,4} &= -\mu_0 \frac{k+1}{k} \mp i \frac{k}{k+1}
            - \frac{k^3}{\mu_0 (k+1)^3} + O(\mu_0^{-2}).

    The remainders are :math:`O(\mu_0^{-2})` for :math:`\beta`
    (:math:`-2 k^5 / (\mu_0^2 (k+1)^5)`) and :math:`O(\mu_0^{-3})` for :math:`\alpha_1`
    and :math:`\alpha_2`.

    Examples
    --------
    Against the exact roots at :math:`\mu_0 = 100` (:math:`\alpha_1` close to
    :math:`k^3 / (\mu_0 (k + 1)^3)`, :math:`\beta` to :math:`k / (k + 1)`):

    >>> from turntable import large_friction_expansion, spectrum
    >>> approx, exact = large_friction_expansion(100.0, 0.4), spectrum(100.0, 0.4)
    >>> print(f"{approx.alpha1:.6e} {exact.alpha1:.6e}")
    2.332362e-04 2.332...e-04
    >>> print(f"{approx.beta:.6f} {exact.beta:.6f}")
    0.285714 0.2857...
    """
    mu0 = _validate.positive("mu0", mu0)
    k = _validate.positive("k", k)
    mu0, k = np.broadcast_arrays(mu0, k)
    kk = k / (k + 1.0)
    corr = kk**3 / mu0
    return Expansion(corr, -mu0 / kk - corr, kk + 0.0 * mu0)
