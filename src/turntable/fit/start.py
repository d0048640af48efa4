"""Start values of a fit, from the data alone.

For a fixed coefficient both models are linear in their amplitudes: in complex form
(r = x + i y)

    slipping:  r(tau) = r_c + A e^{lambda_+ tau} + B e^{lambda_- tau}   (2.7)
    rolling:   r(tau) = A_g e^{lambda_g tau} + A_c e^{lambda_c tau}  (+ a, axis free)

(lambda_+- = alpha1 + i beta, alpha2 - i beta of (2.5)-(2.6); lambda_g, lambda_c of
`turntable.rolling`), so on a log grid of the coefficient the amplitudes are a linear least
squares problem (variable projection).  The best grid point, refined by a bounded scalar
search, gives the coefficient and, from the amplitudes, the initial state (Omega starts
from the given value).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from turntable import rolling
from turntable.fit.models import BOUNDS, _axis_free
from turntable.spectrum import spectrum

#: Points per decade of the start-value grid over the coefficient.
GRID_PER_DECADE = 8
#: Frames used by the search for start values: every stride-th frame, so that about
#: START_FRAMES remain, unless that would leave frames more than START_STEP apart in
#: :math:`\Omega t` (about 20 per turn of the turntable).
START_FRAMES = 400
START_STEP = 0.3


def _rates(model: str, c: NDArray[np.float64], k: float) -> NDArray[np.complex128]:
    """The two rates of each coefficient c, shape c.shape + (2,): growing, then the other."""
    if model == "slipping":
        s = spectrum(c, k)
        return np.stack([s.alpha1 + 1j * s.beta, s.alpha2 - 1j * s.beta], axis=-1)
    return rolling.eigenvalues(c, k)[..., [0, 2]]


def _basis(
    model: str,
    c: NDArray[np.float64],
    tau: NDArray[np.float64],
    k: float,
    constant: bool = False,
) -> tuple[NDArray[np.complex128], NDArray[np.complex128], NDArray[np.float64]]:
    """Columns of the amplitudes for each coefficient c: shape c.shape + (n, m).

    Each exponential e^{lambda tau} is scaled to at most 1 on the film: it is written
    e^{lambda (tau - ref)} with ref the last time for the growing one, 0 otherwise, so
    that nothing overflows.  A constant column comes first for the slipping model (the
    spiral centre) and, if ``constant``, for the rolling one (the axis offset).  Returns
    the columns, the rates and the refs.
    """
    rates = _rates(model, c, k)
    refs = np.where(rates.real > 0, tau[-1], 0.0)
    with np.errstate(under="ignore"):
        cols = np.exp(rates[..., None, :] * (tau[:, None] - refs[..., None, :]))
    if model == "slipping" or constant:
        cols = np.concatenate([np.ones((*cols.shape[:-1], 1), dtype=complex), cols], axis=-1)
    return cols, rates, refs


def _residual_sums(
    model: str,
    c: NDArray[np.float64],
    tau: NDArray[np.float64],
    r: NDArray[np.complex128],
    k: float,
    constant: bool = False,
) -> NDArray[np.float64]:
    """Residual sum of squares of the best amplitudes, for each coefficient of c.

    The residual is r minus its projection Q Q^H r on the columns (Householder QR of
    each stack, stable also where the columns nearly coincide).
    """
    cols, _, _ = _basis(model, c, tau, k, constant)
    q, _ = np.linalg.qr(cols)
    coef = np.conj(np.swapaxes(q, -1, -2)) @ r
    res = r - (q @ coef[..., None])[..., 0]
    return np.sum(np.abs(res) ** 2, axis=-1)


def _initial_state(
    model: str,
    c: float,
    tau: NDArray[np.float64],
    r: NDArray[np.complex128],
    k: float,
    constant: bool = False,
) -> NDArray[np.float64]:
    """Initial state of the best amplitudes for coefficient c (module docstring).

    For the rolling model with ``constant``, the axis offset (a_x, a_y) follows the state.
    """
    cols, rates, refs = _basis(model, np.float64(c), tau, k, constant)
    a, *_ = np.linalg.lstsq(cols, r, rcond=None)
    with np.errstate(under="ignore"):
        amp = a[-2:] * np.exp(-rates * refs)
    r0, v0 = amp.sum(), rates @ amp
    if model == "slipping":
        r0 += a[0]
        w0 = a[0] - 1j * v0 / k
        return np.array([r0.real, r0.imag, v0.real, v0.imag, w0.real, w0.imag])
    state = [r0.real, r0.imag, v0.real, v0.imag]
    return np.array(state + ([a[0].real, a[0].imag] if constant else []))


def start_values(
    model: str,
    tau: NDArray[np.float64],
    xy: NDArray[np.float64],
    k: float,
    fit_axis: bool = False,
) -> tuple[float, NDArray[np.float64]]:
    r"""Return a start (coefficient, state parameters) found from the data alone.

    Parameters
    ----------
    model : {"slipping", "rolling_resistance"}
    tau : numpy.ndarray
        Dimensionless times :math:`\Omega (t - t_0)`, from 0, increasing.
    xy : numpy.ndarray
        Dimensionless positions (position - axis) / R, shape (n, 2).
    k : float
        Inertia ratio.
    fit_axis : bool
        For the rolling model: the axis is free too (a constant term in the amplitudes).

    Returns
    -------
    coefficient : float
    state : numpy.ndarray
        The initial state (6 numbers, or (x, y, vx, vy) for the rolling model), followed
        by the axis offset (a_x, a_y) in units of R for the rolling model with ``fit_axis``.

    Notes
    -----
    Variable projection (module docstring): the residual of the best amplitudes on a
    grid of `GRID_PER_DECADE` points per decade over `BOUNDS`, then a bounded search
    (Brent) in :math:`\ln c` between the neighbours of the best grid point; on a subset of the
    frames (`START_FRAMES`, ``START_STEP``), which is plenty for a start.

    Examples
    --------
    From a noiseless rolling path:

    >>> import numpy as np
    >>> from turntable import fit, rolling
    >>> tau = np.linspace(0.0, 20.0, 200)
    >>> z = rolling.solve(rolling.state_on_constraint([10, 0, 0, 0]), tau, 0.02, 0.4)
    >>> coefficient, state = fit.start_values("rolling_resistance", tau, z[:, :2], 0.4)
    >>> print(f"{coefficient:.3f}")
    0.020
    """
    from scipy.optimize import minimize_scalar

    constant = _axis_free(model, fit_axis)
    lo, hi = (math.log(b) for b in BOUNDS[model])
    grid = np.linspace(lo, hi, round((hi - lo) / math.log(10.0) * GRID_PER_DECADE) + 1)
    # Every stride-th frame, so that at most START_FRAMES remain, but never more than
    # START_STEP apart in tau (both models turn at a rate below 1, so no aliasing).
    step = float(np.median(np.diff(tau))) if tau.size > 1 else 1.0
    stride = max(1, min(math.ceil(tau.size / START_FRAMES), math.floor(START_STEP / step)))
    keep = np.unique(np.append(np.arange(0, tau.size, stride), tau.size - 1))
    tau, r = tau[keep], xy[keep, 0] + 1j * xy[keep, 1]
    rss = _residual_sums(model, np.exp(grid), tau, r, k, constant)
    i = int(np.argmin(rss))
    a, b = grid[max(i - 1, 0)], grid[min(i + 1, grid.size - 1)]
    res = minimize_scalar(
        lambda g: float(_residual_sums(model, np.exp(np.float64(g)), tau, r, k, constant)),
        bounds=(a, b),
        method="bounded",
        options={"xatol": 1e-6},
    )
    g = float(res.x) if res.fun <= rss[i] else float(grid[i])
    c = math.exp(g)
    return c, _initial_state(model, c, tau, r, k, constant)
