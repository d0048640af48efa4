r"""Exact solution of :math:`\dot z = L z` (2.7)-(2.8) and its no-slip limit (3.3).

The six real equations (1.7) are three complex ones: with r = x + i y,
v = vx + i vy, w = wx + i wy (J acts as multiplication by i),

    r' = v,   v' = mu0 (i r - v - i w),   w' = (mu0 / k)(r + i v - w).

The quantity c = v - i k w is conserved (angular momentum about the contact
point), so w = r_c - i v / k with the spiral centre r_c = i c / k, and the
offset rho = r - r_c obeys the scalar equation

    rho'' + 2 mu rho' - i mu0 rho = 0,   roots lambda_+ = alpha1 + i beta,
                                                lambda_- = alpha2 - i beta.

Its solution is written with the divided difference
D(t) = (e^{lambda_+ t} - e^{lambda_- t}) / (lambda_+ - lambda_-), evaluated as
-e^{lambda_+ t} expm1(-(lambda_+ - lambda_-) t) / (lambda_+ - lambda_-):

    rho(t) = rho0 (E(t) - lambda_+ D(t)) + v0 D(t)
    v(t)   = v0 (E(t) + lambda_- D(t)) + i mu0 rho0 D(t),   E = e^{lambda_+ t}.

Since lambda_+ + lambda_- = -2 mu is real, E X = e^{lambda_- t} - e^{lambda_+ t}
(X = expm1(-(lambda_+ - lambda_-) t)) equals
e^{alpha1 t} (expm1(a) cos(beta t) - i sin(beta t) (2 + expm1(a))) with
a = (alpha2 - alpha1) t, so `solve` needs only the real functions exp, expm1,
cos and sin.  Nothing here overflows (Re lambda_- < 0, and times at which
e^{alpha1 t} would overflow are refused, see `max_time`), nothing cancels as
the roots merge (mu0 -> 0) or separate (mu0 -> infinity).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from turntable import _validate
from turntable._conserved import _complex_state, _real_state, conserved, spiral_centre
from turntable._no_slip import no_slip_state, nonholonomic, slip_velocity
from turntable.spectrum import _spectrum, spectrum

__all__ = [
    "ModalTerms",
    "conserved",
    "max_time",
    "modal_terms",
    "no_slip_state",
    "nonholonomic",
    "slip_velocity",
    "solve",
    "spiral_centre",
]


class _Coefficients(NamedTuple):
    rc: complex
    rho0: complex
    v0: complex
    lp: complex
    lm: complex
    k: float
    mu0: float


def _coefficients(z0: ArrayLike, mu0: float, k: float) -> _Coefficients:
    z0 = _validate.state("z0", z0)
    mu0 = _validate.positive_scalar("mu0", mu0)
    k = _validate.positive_scalar("k", k)
    r0, v0, w0 = _complex_state(z0)
    rc = w0 + 1j * v0 / k
    s = _spectrum(np.float64(mu0), np.float64(k))
    lp = complex(s.alpha1, s.beta)
    lm = complex(s.alpha2, -s.beta)
    return _Coefficients(rc, r0 - rc, v0, lp, lm, k, mu0)


def solve(z0: ArrayLike, t: ArrayLike, mu0: float, k: float) -> NDArray[np.float64]:
    r"""Return the exact solution :math:`z(t)` of :math:`\dot z = L z` with :math:`z(0) = z_0`.

    Parameters
    ----------
    z0 : array_like
        Initial state (x, y, vx, vy, wx, wy).
    t : array_like
        1-D array of non-negative times (in units of :math:`1/\Omega`), in any order.
    mu0, k : float
        Friction coefficient and inertia ratio, finite and > 0.

    Returns
    -------
    numpy.ndarray
        Shape (len(t), 6).

    Raises
    ------
    ValueError
        For a bad argument, or a time beyond ``max_time(mu0, k, z0)``, where
        the growing part :math:`e^{\alpha_1 t}` of the solution overflows a double; the
        message names that largest time.

    See Also
    --------
    turntable.modal_terms : The same solution in its fixed, growing and decaying parts.
    turntable.nonholonomic : Its limit without slipping.
    turntable.rolling.solve : The rolling ball of the comparison model.

    Notes
    -----
    Equation (2.7), :math:`z(t) = z_0 + z_+(t) + z_-(t)`, evaluated in the
    cancellation-free form given in the module docstring.  The error is
    about :math:`10^{-15}` relative to the size of the state for :math:`\mu_0` in
    :math:`[10^{-3}, 10^3]` (see ``benchmarks/``).

    Examples
    --------
    Started at the origin with velocity (1, 0) and no spin, the ball's centre spirals out
    about (0, 2.5), its distance growing like :math:`e^{\alpha_1 t}`, :math:`\alpha_1 = 0.0226`:

    >>> import numpy as np
    >>> from turntable import solve, spiral_centre
    >>> z0 = [0, 0, 1, 0, 0, 0]
    >>> z = solve(z0, np.linspace(0.0, 20.0, 3), mu0=1.0, k=0.4)
    >>> np.hypot(*(z[:, :2] - spiral_centre(z0, 0.4)).T).round(3)
    array([2.5  , 3.132, 3.926])
    """
    t = _validate.times("t", t)
    c = _coefficients(z0, mu0, k)
    d = c.lp - c.lm
    # With D = -E X / d, X = expm1(-d t) and E = e^{lambda_+ t}:
    #   rho = rho0 E + q E X,   v = v0 E + qv E X   (q, qv: `_coefficient_matrix`),
    #   E X = e^{lambda_- t} - e^{lambda_+ t}
    #       = G (expm1(a) cos(beta t) - i sin(beta t) (2 + expm1(a))),
    # with G = e^{alpha1 t} and a = (alpha2 - alpha1) t <= 0: no cancellation,
    # no overflow (times where G times the coefficients would overflow are
    # refused; the decaying mode may underflow to 0), real functions only.
    coef = _coefficient_matrix(c)
    _validate.times_within("t", t, _time_limit(c, coef), _limit_reason(c))
    out = np.empty((t.size, 6))
    # Work in blocks so that the temporaries stay small (cache-resident and
    # reused by the allocator); only the result is a large fresh array.
    basis = np.empty((5, min(t.size, _BLOCK)))
    basis[0] = 1.0
    for start in range(0, t.size, _BLOCK):
        tb = t[start : start + _BLOCK]
        b = basis[:, : tb.size]
        bt = c.lp.imag * tb
        with np.errstate(under="ignore"):
            em1 = np.expm1(-d.real * tb)
        growth = np.exp(c.lp.real * tb)
        np.multiply(growth, np.cos(bt), out=b[1])  # Re E
        np.multiply(growth, np.sin(bt), out=b[2])  # Im E
        np.multiply(b[1], em1, out=b[3])  # Re E X
        em1 += 2.0
        np.multiply(b[2], em1, out=b[4])  # -Im E X
        np.matmul(b.T, coef, out=out[start : start + tb.size])
    return out


#: Number of time points evaluated at once by `solve`.
_BLOCK = 2048


def _time_limit(c: _Coefficients, coef: NDArray[np.float64]) -> float:
    """Largest t at which `solve` (coefficients ``coef``) stays a finite double.

    On the basis (1, Re E, Im E, Re E X, -Im E X) the last four functions are
    bounded by G, G, G and 2 G with G = e^{alpha1 t}, so every component of
    z(t) is at most G times ``scale`` below, and the growth factor G itself
    must be finite.
    """
    scale = np.abs(coef[0]) + np.abs(coef[1:]).T @ np.array([1.0, 1.0, 1.0, 2.0])
    return float(_validate.growth_limit(c.lp.real, float(np.max(scale))))


def _modal_time_limit(c: _Coefficients) -> float:
    """Largest t at which `modal_terms` stays a finite double.

    Each component of the growing mode is at most |A| e^{alpha1 t} max(1, |lambda_+| / k)
    times 1 + |lambda_+| (position, velocity and spin together).
    """
    size = abs((c.v0 - c.lm * c.rho0) / (c.lp - c.lm)) * (1.0 + abs(c.lp)) * max(1.0, 1.0 / c.k)
    return float(_validate.growth_limit(c.lp.real, size + abs(c.rc)))


def _limit_reason(c: _Coefficients) -> str:
    return (
        f"for mu0={c.mu0:g}, k={c.k:g}, e^(alpha1 t) times the size of the solution "
        "overflows a double beyond it"
    )


def max_time(mu0: ArrayLike, k: ArrayLike, z0: ArrayLike | None = None) -> NDArray[np.float64]:
    r"""Return the largest time :math:`t` at which the solution is representable in doubles.

    Parameters
    ----------
    mu0, k : float or array_like
        Friction coefficient and inertia ratio, finite and > 0; broadcast
        against each other.  Single numbers if ``z0`` is given.
    z0 : array_like, optional
        Initial state (x, y, vx, vy, wx, wy).  Without it, the bound is
        where the growth factor :math:`e^{\alpha_1 t}` itself overflows.

    Returns
    -------
    numpy.ndarray
        :math:`\ln(\mathrm{DBL\_MAX}) / \alpha_1 \approx 709.78 / \alpha_1`, of the broadcast
        shape; with ``z0``, the (slightly smaller) largest t that both `solve`
        and `modal_terms` accept for that initial state, as a 0-d array.
        Each of them raises ValueError for later times (`modal_terms`, whose
        terms are bounded one by one, up to 2 % earlier than `solve`).

    Notes
    -----
    Equation (2.7): the growing part of the solution is proportional to
    :math:`e^{\alpha_1 t}`, :math:`\alpha_1` of (2.5)-(2.6), and a double holds at most
    :math:`\mathrm{DBL\_MAX} = 1.8 \times 10^{308} = e^{709.78}`.

    Examples
    --------
    >>> from turntable import max_time, solve
    >>> z0 = [0, 0, 1, 0, 0, 0]
    >>> t_max = max_time(1.0, 0.4, z0)
    >>> print(f"{t_max:.0f}")
    31320
    >>> bool(abs(solve(z0, [t_max], 1.0, 0.4)).max() < float("inf"))
    True
    """
    if z0 is None:
        s = spectrum(mu0, k)
        return _validate.growth_limit(s.alpha1)
    c = _coefficients(z0, mu0, k)
    return np.asarray(min(_time_limit(c, _coefficient_matrix(c)), _modal_time_limit(c)))


def _coefficient_matrix(c: _Coefficients) -> NDArray[np.float64]:
    """`_solution_matrix` of the solution with coefficients ``c`` (see `solve`)."""
    d = c.lp - c.lm
    q = -(c.v0 - c.lp * c.rho0) / d
    qv = -(c.lm * c.v0 + 1j * c.mu0 * c.rho0) / d
    return _solution_matrix(c.rc, c.rho0, q, c.v0, qv, c.k)


def _solution_matrix(
    rc: complex, p: complex, q: complex, pv: complex, qv: complex, k: float
) -> NDArray[np.float64]:
    """Coefficients of z(t) on the basis (1, Re E, Im E, Re E X, -Im E X).

    rho = p E + q E X and v = pv E + qv E X in real form; r = r_c + rho,
    w = r_c - i v / k.
    """

    def real_form(a: complex, b: complex) -> NDArray[np.float64]:
        # (a E + b E X) -> rows give (Re, Im) on the basis without the constant
        return np.array([[a.real, a.imag], [-a.imag, a.real], [b.real, b.imag], [b.imag, -b.real]])

    rho, v = real_form(p, q), real_form(pv, qv)
    m = np.zeros((5, 6))
    m[0] = [rc.real, rc.imag, 0.0, 0.0, rc.real, rc.imag]
    m[1:, 0:2] = rho
    m[1:, 2:4] = v
    m[1:, 4] = v[:, 1] / k
    m[1:, 5] = -v[:, 0] / k
    return m


class ModalTerms(NamedTuple):
    """The three parts of the solution (2.7), each of shape (len(t), 6).

    Examples
    --------
    The three parts add up to the solution:

    >>> import numpy as np
    >>> from turntable import modal_terms, solve
    >>> z0, t = [1.0, 1.0, 0.0, 0.0, 0.0, 1.0], np.linspace(0.0, 10.0, 5)
    >>> terms = modal_terms(z0, t, 1.0, 0.4)
    >>> bool(np.allclose(terms.centre + terms.plus + terms.minus, solve(z0, t, 1.0, 0.4)))
    True
    """

    centre: NDArray[np.float64]
    plus: NDArray[np.float64]
    minus: NDArray[np.float64]


def modal_terms(z0: ArrayLike, t: ArrayLike, mu0: float, k: float) -> ModalTerms:
    r"""Split the solution into its fixed, growing and decaying parts.

    Parameters
    ----------
    z0 : array_like
        Initial state (x, y, vx, vy, wx, wy).
    t : array_like
        1-D array of non-negative times.
    mu0, k : float
        Friction coefficient and inertia ratio, finite and > 0.

    Returns
    -------
    ModalTerms
        ``(centre, plus, minus)``: the projection of z0 on ker L (constant),
        the part on the modes :math:`\alpha_1 \pm i\beta` and the part on the modes
        :math:`\alpha_2 \pm i\beta`.  They sum to `solve` (up to rounding relative to
        the size of the terms, which grow like :math:`\mu_0^{-1/2}` as :math:`\mu_0 \to 0`).

    See Also
    --------
    turntable.solve : Their sum.

    Notes
    -----
    Equation (2.7).  With :math:`\rho_0 = r(0) - r_c`, :math:`v_0 = v(0)` and
    :math:`\lambda_\pm = \alpha_1 + i\beta, \alpha_2 - i\beta`,
    :math:`\rho(t) = A e^{\lambda_+ t} + B e^{\lambda_- t}`,
    :math:`A = (v_0 - \lambda_- \rho_0) / (\lambda_+ - \lambda_-)`,
    :math:`B = (\lambda_+ \rho_0 - v_0) / (\lambda_+ - \lambda_-)`,
    and each mode carries :math:`v = \lambda\rho`, :math:`\omega = -i \lambda\rho / k`.

    Examples
    --------
    The three parts add up to the solution:

    >>> from turntable import modal_terms, solve
    >>> z0, t = [0, 0, 1, 0, 0, 0], [0.0, 1.0, 10.0]
    >>> parts = modal_terms(z0, t, 1.0, 0.4)
    >>> z = solve(z0, t, 1.0, 0.4)
    >>> bool(abs(parts.centre + parts.plus + parts.minus - z).max() < 1e-14)
    True
    """
    t = _validate.times("t", t)
    c = _coefficients(z0, mu0, k)
    d = c.lp - c.lm
    _validate.times_within("t", t, _modal_time_limit(c), _limit_reason(c))
    centre = _real_state(np.full(t.shape, c.rc), np.zeros(t.shape), np.full(t.shape, c.rc))
    # The decaying mode underflows to 0 for large mu0 t: harmless.
    with np.errstate(under="ignore"):
        amp_p = (c.v0 - c.lm * c.rho0) / d * np.exp(c.lp * t)
        amp_m = (c.lp * c.rho0 - c.v0) / d * np.exp(c.lm * t)
        plus = _real_state(amp_p, c.lp * amp_p, -1j * c.lp * amp_p / c.k)
        minus = _real_state(amp_m, c.lm * amp_m, -1j * c.lm * amp_m / c.k)
    return ModalTerms(centre, plus, minus)
