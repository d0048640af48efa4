"""The parameter vector of a fit: its layout, the model's columns of the Jacobian, standard errors.

The parameters are the state at the first frame, the logarithm of the coefficient and,
optionally, s = ln(Omega / Omega_given) and the axis (`turntable.fit`).  Standard errors
treat the other parameters as nuisance parameters: se(ln c) = s / |(I - P) j_c|, j_c the
column of ln c and P the projection on the other columns (`_stderr_of`); for residuals
correlated from frame to frame, the Newey-West estimate from the same projection
(`_hac_stderr_of`), and that for noise with a slowly drifting part (`slow_noise`,
`_slow_stderr_of`).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

from turntable.fit.models import N_STATE, _axis_free, _check_model, _full_state, _solve

#: A slow part of the errors (`slow_noise`) is one this many times its spread for white noise.
DRIFT_Z = 3.0
#: Relative step in :math:`\ln c` of the central difference for the coefficient's column of
#: :math:`J`.
LOG_STEP = 1e-5


class _Layout(NamedTuple):
    """Where each parameter sits in the vector theta of a fit.

    theta = (state (n_state), ln c, [s = ln(Omega / Omega_given)], [a_x, a_y]), the axis
    offset a in units of R.
    """

    model: str
    fit_omega: bool
    fit_axis: bool

    @property
    def n_state(self) -> int:
        return N_STATE[self.model]

    @property
    def i_c(self) -> int:
        return self.n_state

    @property
    def i_s(self) -> int:
        return self.n_state + 1

    @property
    def i_axis(self) -> int:
        return self.n_state + 1 + int(self.fit_omega)

    @property
    def size(self) -> int:
        return self.n_state + 1 + int(self.fit_omega) + 2 * int(self.fit_axis)


def _layout(model: str, fit_omega: bool, fit_axis: bool) -> _Layout:
    return _Layout(_check_model(model), bool(fit_omega), _axis_free(model, fit_axis))


def _unpack(
    lay: _Layout, theta: NDArray[np.float64]
) -> tuple[NDArray[np.float64], float, float, NDArray[np.float64]]:
    """(full state, ln c, s, axis offset) of a parameter vector (s = 0, offset 0 if fixed)."""
    s = float(theta[lay.i_s]) if lay.fit_omega else 0.0
    a = theta[lay.i_axis : lay.i_axis + 2] if lay.fit_axis else np.zeros(2)
    return _full_state(lay.model, theta[: lay.n_state]), float(theta[lay.i_c]), s, a


def _columns(
    lay: _Layout, c: float, s: float, z0: NDArray[np.float64], tau: NDArray[np.float64], k: float
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Dimensionless derivatives of the positions (2n rows): (others, ln c column).

    The solution is linear in the initial state, so the column of the j-th state parameter
    is the solution from the j-th unit vector; the column of ln c is a central difference;
    that of s = ln Omega is tau v(tau) (the positions at tau e^s, differentiated in s); those
    of the axis are 1 in its coordinate.  "Others" holds, in the order of theta, every
    column but that of ln c.
    """
    tau_s = tau * math.exp(s)
    ns = lay.n_state
    cols = np.empty((2 * tau.size, lay.size - 1))
    for j in range(ns):
        e = np.zeros(ns)
        e[j] = 1.0
        cols[:, j] = _solve(lay.model, _full_state(lay.model, e), tau_s, c, k)[:, :2].ravel()
    up = _solve(lay.model, z0, tau_s, c * math.exp(LOG_STEP), k)[:, :2]
    down = _solve(lay.model, z0, tau_s, c * math.exp(-LOG_STEP), k)[:, :2]
    j_c = ((up - down) / (2.0 * LOG_STEP)).ravel()
    i = ns
    if lay.fit_omega:
        z = _solve(lay.model, z0, tau_s, c, k)
        cols[:, i] = (tau_s[:, None] * z[:, 2:4]).ravel()
        i += 1
    if lay.fit_axis:
        cols[:, i : i + 2] = np.tile(np.eye(2), (tau.size, 1))
    return cols, j_c


def _full_jacobian(others: NDArray[np.float64], j_c: NDArray[np.float64], lay: _Layout):
    """The Jacobian in the order of theta: ``others`` with the column of ln c inserted."""
    return np.insert(others, lay.i_c, j_c, axis=1)


def _own_part(jac: NDArray[np.float64], i: int) -> NDArray[np.float64]:
    """(I - P) j_i: the part of column i that no other column explains."""
    j_i = jac[:, i]
    rest = np.delete(jac, i, axis=1)
    coef, *_ = np.linalg.lstsq(rest, j_i, rcond=None)
    return j_i - rest @ coef


def _stderr_of(jac: NDArray[np.float64], i: int, sigma: float) -> float:
    """se of parameter i with every other column a nuisance: sigma / |(I - P) j_i|."""
    norm = float(np.linalg.norm(_own_part(jac, i)))
    return sigma / norm if norm > 0 else math.inf


def newey_west_lags(n: int) -> int:
    """Lags of the Newey-West estimate for a series of n terms: 1.3 sqrt(n), rounded up,
    at most n - 1 (Lazarus, Lewis, Stock and Watson 2018, J. Bus. Econ. Stat. 36, 541:
    longer than the bandwidths that minimise the error of the variance, which leave
    intervals too short)."""
    return max(min(math.ceil(1.3 * math.sqrt(n)), n - 1), 0)


def _hac_stderr_of(jac: NDArray[np.float64], i: int, residuals: NDArray, lags: int) -> float:
    """se of parameter i for noise correlated from frame to frame (Newey-West).

    The estimate of parameter i is q . y, q = (I - P) j_i / |(I - P) j_i|^2; its variance
    is estimated from the scores g_t = q_t . r_t of the frames (both coordinates) as
    sum_t g_t^2 + 2 sum_{l <= lags} (1 - l / (lags + 1)) sum_t g_t g_{t+l}, times N / (N - p).
    """
    q = _own_part(jac, i)
    norm2 = float(q @ q)
    if not norm2 > 0:
        return math.inf
    g = (q * residuals).reshape(-1, 2).sum(axis=1) / norm2
    var = float(g @ g)
    for lag in range(1, lags + 1):
        var += 2.0 * (1.0 - lag / (lags + 1)) * float(g[lag:] @ g[:-lag])
    n_obs, p = jac.shape
    return math.sqrt(max(var, 0.0) * n_obs / (n_obs - p))


def _kernel_times(v: NDArray[np.float64], a: float) -> NDArray[np.float64]:
    """K v for the symmetric Toeplitz K_ij = a^|i - j| along axis 0 (by FFT, in scipy)."""
    from scipy.linalg import matmul_toeplitz

    column = a ** np.arange(v.shape[0])
    return matmul_toeplitz(column, v.reshape(v.shape[0], -1)).reshape(v.shape)


def slow_noise(jac: NDArray[np.float64], residuals: NDArray[np.float64]) -> tuple[float, ...]:
    """Return (white, slow, a): the errors of a fit as white noise of variance ``white``
    plus a part of variance ``slow`` that drifts, slow a^|i - j| between frames i and j,
    such as a tracker's errors of the ball's outline, which change with where it is.

    The sums over both coordinates of the residuals' products l frames apart, l = 0 to
    n / 4, are fitted by their expectations, white s_l(M) + slow s_l(M K M) (M = I - H,
    H the projection on the columns of ``jac``, which absorbs part of the drift), for 16
    correlation lengths -1 / ln a from 1 frame to n; the variances by non-negative least
    squares.  A slow part less than `DRIFT_Z` times its spread for white noise (each sum
    of 2 n products, of variance 2 n white^2) is none.  ``jac`` has a row per coordinate,
    frame by frame; ``residuals`` shape (n, 2).
    """
    from scipy.optimize import nnls

    n = residuals.shape[0]
    lags = max(n // 4, 1)
    size = 1 << (n + lags).bit_length()
    q = np.linalg.qr(jac)[0].reshape(n, 2, -1)
    fq = np.fft.rfft(q, size, axis=0)

    def lag_sums(product: NDArray[np.complex128]) -> NDArray[np.float64]:
        return np.fft.irfft(product, size)[: lags + 1]

    fr = np.fft.rfft(residuals, size, axis=0)
    seen = lag_sums(np.sum(np.abs(fr) ** 2, axis=1))
    white = -lag_sums(np.sum(np.abs(fq) ** 2, axis=(1, 2)))
    white[0] += 2.0 * n
    steps = np.arange(lags + 1)
    best = (math.inf, 0.0, 0.0, 0.0)
    for length in np.geomspace(1.0, n, 16):
        a = math.exp(-1.0 / length)
        kq = _kernel_times(q, a)
        qkq = np.einsum("icj,ick->jk", q, kq)
        cross = np.sum(np.conj(fq) * np.fft.rfft(kq, size, axis=0), axis=(1, 2))
        projected = np.sum(np.conj(fq) * (fq @ qkq), axis=(1, 2))
        slow = 2.0 * (n - steps) * a**steps - lag_sums(cross + np.conj(cross) - projected)
        (w, s), loss = nnls(np.column_stack([white, slow]), seen)
        if loss < best[0]:
            best = (loss, w, s, a, s * np.linalg.norm(slow[1:]) / (math.sqrt(2.0 * n) * w))
    _, w, s, a, z = best
    return (w, s, a) if z > DRIFT_Z else (w, 0.0, a)


def _slow_stderr_of(jac: NDArray[np.float64], i: int, noise: tuple[float, ...]) -> float:
    """se of parameter i for the noise of `slow_noise`: sqrt(q^T (white I + slow K) q), the
    estimate q . y as in `_hac_stderr_of`, K_ij = a^|i - j| in each coordinate."""
    white, slow, a = noise
    q = _own_part(jac, i)
    norm2 = float(q @ q)
    if not norm2 > 0:
        return math.inf
    q = (q / norm2).reshape(-1, 2)
    var = white * float(np.sum(q * q)) + slow * float(np.sum(q * _kernel_times(q, a)))
    return math.sqrt(max(var, 0.0))
