"""From a filmed ball to its friction: fit both friction models, and design the experiment.

Two mechanisms can make a ball's centre spiral outwards on a turntable:

``slipping``
    the paper's model, viscous friction F = -mu0 u at the contact point
    (`turntable.solve`, coefficient mu0 = mu0_dim / (m Omega));
``rolling_resistance``
    rolling without slipping against a resistance torque -delta w
    (`turntable.rolling.solve`, coefficient delta = delta_dim / (m R^2 Omega)).

`fit_model` fits one of them to a `turntable.film.Film` (tracked positions in the lab frame,
SI units) by nonlinear least squares (`scipy.optimize.least_squares`) on the exact
closed-form solution, in the paper's units: tau = Omega (t - t0), r = (position - axis) / R.
The parameters are the state at the first frame t0 and the logarithm of the coefficient
(which keeps it positive): 6 + 1 for slipping, and 4 + 1 for rolling, whose state is
parametrised on the no-slip constraint by (x, y, vx, vy) (`turntable.rolling.state_on_constraint`).
Optionally also s = ln(Omega / Omega_given) (``fit_omega``: the turntable's rate is not
known exactly) and, for the rolling model, the position a of the axis (``fit_axis``); the
slipping motion does not depend on the axis at all (a shift of the position with the same
shift of the spin is again a solution, the plane of equilibria (2.3)), so there the axis
is neither needed nor identifiable.  With Omega free, tau = Omega_given e^s (t - t0) and
d r / d s = tau v(tau): both models' rates scale with Omega, and the ratio of growth to
turning (alpha1 / beta, or Re / Im of lambda_g) fixes the coefficient alone, so Omega is
identifiable from a film of a turn or more.

Start values come from the data alone.  For a fixed coefficient both models are linear in
their amplitudes: in complex form (r = x + i y)

    slipping:  r(tau) = r_c + A e^{lambda_+ tau} + B e^{lambda_- tau}   (2.7)
    rolling:   r(tau) = A_g e^{lambda_g tau} + A_c e^{lambda_c tau}  (+ a, axis free)

(lambda_+- = alpha1 + i beta, alpha2 - i beta of (2.5)-(2.6); lambda_g, lambda_c of
`turntable.rolling`), so on a log grid of the coefficient the amplitudes are a linear least
squares problem (variable projection).  The best grid point, refined by a bounded scalar
search, gives the coefficient and, from the amplitudes, the initial state (Omega starts
from the given value).

Standard errors come from the Jacobian J at the optimum and the residual variance
s^2 = RSS / (N - p) (N = 2n coordinates, p parameters), with the other parameters as
nuisance parameters: se(ln c) = s / |(I - P) j_c|, j_c the column of ln c and P the
projection on the other columns; se(c) = c se(ln c) (delta method), and the 95 % interval
exp(ln c +- 1.96 se(ln c)), which stays positive and is the honest form when se(ln c) is
not small.  The same formula with the camera's noise instead of s, at the true parameters,
is the Cramer-Rao bound that `predicted_stderr` returns: the Fisher information
J^T J / sigma^2 over the frames, reduced to the coefficient.  It is reached only while
the fit is locally linear, i.e. while the relative error is small (about 0.2, Fig. 8).

A coefficient that ends at an end of `BOUNDS` is not a measurement: the film is then
consistent with every larger (or smaller) value, and `fit_model` gives instead a one-sided
95 % limit from the profile of the residual sum of squares,
RSS_profile(c) - RSS_min = z_0.95^2 s^2 (z_0.95 = 1.645).

The models are compared by the small-sample corrected Akaike criterion
AICc = N ln(RSS / N) + 2 K + 2 K (K + 1) / (N - K - 1), K = p + 1 (Gaussian noise of
unknown variance, the + 1), reported with the difference and the Akaike weights; a
difference below `DECISIVE` is not decisive, and with fewer than `MIN_DOF` coordinates left
(N - K - 1 for the larger model) no model is selected.  Whether a model fits to the noise
level is told by the lag-1 autocorrelation of its residuals (`whiteness`): white noise gives
about 0 with a spread of 1 / sqrt(number of pairs); a wrong Omega, k, axis or sign of y
leaves smooth structure and a large positive value.  `problems` lists in one line each what
a user must know about a fit.  `distinguishability` predicts, for a slipping ball, how far
the best rolling trajectory stays from it and hence the expected AICc difference and the
probability that the slipping model is selected.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import brentq, least_squares, minimize_scalar

from turntable import _validate, rolling
from turntable.film import Camera, Film, Setup, check_setup, frame_times
from turntable.solution import max_time, no_slip_state, solve
from turntable.spectrum import spectrum

#: The two models, in the order they are reported.
MODELS = ("slipping", "rolling_resistance")
#: Name of each model's dimensionless coefficient.
COEFFICIENT = {"slipping": "mu0", "rolling_resistance": "delta"}
#: Number of free components of the initial state.
N_STATE = {"slipping": 6, "rolling_resistance": 4}
#: Range searched for each coefficient (the fit stops at these bounds and says so).
BOUNDS = {"slipping": (1e-6, 1e6), "rolling_resistance": (1e-6, 1e4)}
#: With ``fit_omega``, Omega is searched within this factor of the given value.
OMEGA_FACTOR = 2.0
#: Points per decade of the start-value grid over the coefficient.
GRID_PER_DECADE = 8
#: Frames used by the search for start values: every stride-th frame, so that about
#: START_FRAMES remain, unless that would leave frames more than START_STEP apart in
#: Omega t (about 20 per turn of the turntable).
START_FRAMES = 400
START_STEP = 0.3
#: Relative step in ln c of the central difference for the coefficient's column of J.
LOG_STEP = 1e-5
#: Residual of a trial point whose solution would overflow a double (see `max_time`).
_OVERFLOW_RESIDUAL = 1e100
#: Two-sided 95 % quantile of the normal distribution (the `*_ci95` intervals).
Z95 = 1.959963984540054
#: One-sided 95 % quantile of the normal distribution (the limits at a bound).
Z95_ONE_SIDED = 1.6448536269514722
#: AICc differences of at least this much are decisive (Burnham and Anderson: above 10,
#: essentially no support for the other model).
DECISIVE = 10.0
#: Fewest coordinates left over, N - K - 1 for the model with more parameters, for which
#: a model is selected at all (below it the AICc correction dominates the comparison).
MIN_DOF = 20
#: Residuals count as not white when their lag-1 autocorrelation exceeds this many times
#: its spread 1 / sqrt(pairs) for white noise (false alarm about 3e-5 for white noise).
WHITENESS_Z = 4.0
#: A fit whose rms residual is at most this fraction of the largest distance of the tracked
#: centre from the axis reproduces the positions to rounding: the film carries no noise by
#: which to weigh the fits (a noiseless film, or a ball at rest tracked to whole pixels).
EXACT_FIT = 1e-9
#: Relative standard error (of ln c) above which a fit is not locally linear: its standard
#: error and interval are then only indicative (Fig. 8: fits reach the Cramer-Rao bound
#: below about this, and beyond a few times it their intervals miss the truth in up to half
#: the films); `problems` says so.
LINEAR_RELATIVE_ERROR = 0.2
#: A freed Omega or axis (`consistency`) farther than this many standard errors from the
#: given value means the given one is wrong (false alarm about 6e-5 when it is right).
CONSISTENCY_Z = 4.0
#: Frames farther apart than this in Omega t (rad) cannot follow the ball (it turns at a
#: rate up to Omega): the time unit or the rate is probably wrong.
MAX_FRAME_STEP = 1.0


def _check_model(model: str) -> str:
    if model not in MODELS:
        raise ValueError(f"model must be one of {MODELS}; got {model!r}")
    return model


def _axis_free(model: str, fit_axis: bool) -> bool:
    """Whether the axis is a parameter: only the rolling model depends on it."""
    return bool(fit_axis) and model == "rolling_resistance"


def n_parameters(model: str, fit_omega: bool = False, fit_axis: bool = False) -> int:
    """Return the number p of fitted parameters of ``model``.

    The initial state (6 for slipping, 4 for rolling), ln c, and with ``fit_omega`` ln Omega,
    with ``fit_axis`` the axis (x, y) of the rolling model (the slipping model does not
    depend on the axis).
    """
    return N_STATE[_check_model(model)] + 1 + int(bool(fit_omega)) + 2 * _axis_free(model, fit_axis)


def min_frames(fit_omega: bool = False, fit_axis: bool = False) -> int:
    """Return the fewest frames n for which `fit_film` selects a model.

    Each frame gives N = 2 n coordinates; AICc needs N - K - 1 >= `MIN_DOF` with
    K = p + 1 for the model with the most parameters p (`n_parameters`).
    """
    p = max(n_parameters(m, fit_omega, fit_axis) for m in MODELS)
    return math.ceil((MIN_DOF + p + 2) / 2)


def _full_state(model: str, p: NDArray[np.float64]) -> NDArray[np.float64]:
    """The state (x, y, vx, vy, wx, wy) of the fit parameters ``p`` (rolling: on the constraint)."""
    return p if model == "slipping" else rolling.state_on_constraint(p)


def _state_parameters(model: str, state0: NDArray[np.float64]) -> NDArray[np.float64]:
    return state0.copy() if model == "slipping" else state0[:4].copy()


def _solve(model: str, z0: NDArray[np.float64], tau: NDArray[np.float64], c: float, k: float):
    if model == "slipping":
        return solve(z0, tau, c, k)
    return rolling.solve(z0, tau, c, k)


def positions(
    model: str,
    coefficient: float,
    state0: ArrayLike,
    t: ArrayLike,
    setup: Setup,
    t0: float = 0.0,
) -> NDArray[np.float64]:
    """Return the positions (x, y) in m of the ball's centre at times ``t``, s.

    Parameters
    ----------
    model : {"slipping", "rolling_resistance"}
        Which mechanism.
    coefficient : float
        mu0 or delta, dimensionless, > 0.
    state0 : array_like
        Dimensionless state (x, y, vx, vy, wx, wy) at time ``t0`` (units of the paper:
        length R, time 1/Omega, relative to the axis); on the no-slip constraint for the
        rolling model.
    t : array_like
        Times in s, >= t0.
    setup : Setup
        Ball and turntable.
    t0 : float
        Time of ``state0``, s.

    Returns
    -------
    numpy.ndarray
        Shape (len(t), 2): axis + R r(Omega (t - t0)) with r from `turntable.solve` or
        `turntable.rolling.solve`.
    """
    _check_model(model)
    setup = check_setup(setup)
    t = np.asarray(_validate._as_float_array("t", t, "a 1-D array of times"), dtype=float)
    t0 = _validate.finite_scalar("t0", t0)
    if t.ndim != 1 or not np.all(np.isfinite(t)) or np.any(t < t0):
        raise ValueError(f"t must be a 1-D array of finite times >= t0 = {t0:g} s")
    z0 = _validate.state("state0", state0)
    z = _solve(model, z0, setup.omega * (t - t0), coefficient, setup.k)
    return setup.radius * z[:, :2] + np.asarray(setup.axis)


# --------------------------------------------------------------------------- parameters
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


def _stderr_of(jac: NDArray[np.float64], i: int, sigma: float) -> float:
    """se of parameter i with every other column a nuisance: sigma / |(I - P) j_i|."""
    j_i = jac[:, i]
    rest = np.delete(jac, i, axis=1)
    coef, *_ = np.linalg.lstsq(rest, j_i, rcond=None)
    norm = float(np.linalg.norm(j_i - rest @ coef))
    return sigma / norm if norm > 0 else math.inf


# --------------------------------------------------------------------------- start values
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
    """Return a start (coefficient, state parameters) found from the data alone.

    Parameters
    ----------
    model : {"slipping", "rolling_resistance"}
    tau : numpy.ndarray
        Dimensionless times Omega (t - t0), from 0, increasing.
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
    (Brent) in ln c between the neighbours of the best grid point; on a subset of the
    frames (`START_FRAMES`, `START_STEP`), which is plenty for a start.
    """
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


# --------------------------------------------------------------------------- fitting
class ModelFit(NamedTuple):
    """The fit of one model to a film.

    Attributes
    ----------
    model : str
        "slipping" or "rolling_resistance".
    coefficient, stderr : float
        The dimensionless coefficient (mu0 or delta) and its standard error.  At a bound
        (``bound`` not None) the coefficient is where the search stopped, not a measurement.
    log_stderr : float
        Standard error of ln coefficient (the relative standard error).
    state0 : numpy.ndarray
        Dimensionless state (x, y, vx, vy, wx, wy) at the first frame t0 (relative to
        ``axis``, velocities in units of R ``omega``).
    t0 : float
        Time of the first frame, s.
    rss : float
        Residual sum of squares, m^2.
    rms_residual : float
        sqrt(RSS / N), m: the rms residual per coordinate (N = 2n coordinates).
    aic : float
        N ln(RSS / N) + 2 K, K = p + 1.
    aicc : float
        AIC + 2 K (K + 1) / (N - K - 1); inf if N <= K + 1.
    n_parameters, n_observations : int
        p and N.
    converged : bool
        Whether `scipy.optimize.least_squares` met a convergence criterion.
    at_bound : bool
        Whether the coefficient ended at an end of `BOUNDS`.
    residuals : numpy.ndarray
        Data minus fit, m, shape (n, 2).
    bound : str or None
        "upper" or "lower": the end of `BOUNDS` the coefficient ran into; None inside.
    limit : float
        At a bound, the one-sided 95 % limit (lower limit at the upper bound, upper limit
        at the lower one, `_limit`); nan otherwise.
    omega, omega_stderr : float
        Omega (rad/s) of the fit: the given one, or the fitted one with its standard error
        (nan when given).
    omega_at_bound : bool
        With ``fit_omega``: Omega ran into its search range (factor `OMEGA_FACTOR`).
    axis, axis_stderr : tuple of float
        Position of the axis (m): the given one, or the fitted one (rolling model with
        ``fit_axis``) with its standard errors (nan when given).
    autocorrelation, autocorrelation_sd : float
        Lag-1 autocorrelation of the residuals and its spread for white noise (`whiteness`).
    orbital_rate : float
        Angular rate of the growing mode (beta, or Im lambda_g) in units of Omega: the ball
        turns about its spiral centre orbital_rate Omega T / (2 pi) times in a film of
        length T.
    exact : bool
        Whether the fit reproduces the positions to rounding (`EXACT_FIT`): then there is no
        noise, the residuals count as white, and AICc cannot weigh it against another
        exact fit.
    """

    model: str
    coefficient: float
    stderr: float
    log_stderr: float
    state0: NDArray[np.float64]
    t0: float
    rss: float
    rms_residual: float
    aic: float
    n_parameters: int
    n_observations: int
    converged: bool
    at_bound: bool
    residuals: NDArray[np.float64]
    aicc: float = math.inf
    bound: str | None = None
    limit: float = math.nan
    omega: float = math.nan
    omega_stderr: float = math.nan
    omega_at_bound: bool = False
    axis: tuple[float, float] = (0.0, 0.0)
    axis_stderr: tuple[float, float] = (math.nan, math.nan)
    autocorrelation: float = math.nan
    autocorrelation_sd: float = math.nan
    orbital_rate: float = math.nan
    exact: bool = False

    @property
    def ci95(self) -> tuple[float, float]:
        """95 % interval exp(ln c -+ 1.96 se(ln c)) of the coefficient (not at a bound)."""
        lo = math.exp(math.log(self.coefficient) - Z95 * self.log_stderr)
        hi = math.exp(min(math.log(self.coefficient) + Z95 * self.log_stderr, 709.0))
        return lo, hi

    @property
    def whiteness_z(self) -> float:
        """Lag-1 autocorrelation in units of its spread for white noise."""
        return self.autocorrelation / self.autocorrelation_sd

    @property
    def white(self) -> bool:
        """Whether the residuals pass as white noise: |autocorrelation| < `WHITENESS_Z` sd
        (or the fit is exact to rounding, and there is no noise to test)."""
        return self.exact or not abs(self.whiteness_z) > WHITENESS_Z


def _dimensionless(film: Film, setup: Setup) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    t = _validate.times("t", np.asarray(film.t) - film.t[0], increasing=True)
    xy = np.column_stack([film.x, film.y]) - np.asarray(setup.axis)
    if not np.all(np.isfinite(xy)) or xy.shape != (t.size, 2):
        raise ValueError("film.x and film.y must be finite and as long as film.t")
    return setup.omega * t, xy / setup.radius


def aic(rss: float, n_observations: int, n_params: int) -> float:
    """Return Akaike's criterion N ln(RSS / N) + 2 (p + 1) of a Gaussian least-squares fit.

    The + 1 counts the noise variance, estimated as RSS / N.  An exact fit (RSS = 0,
    only for noiseless data) counts as RSS = the smallest positive double.
    """
    rss = max(float(rss), float(np.finfo(float).tiny))
    return n_observations * math.log(rss / n_observations) + 2.0 * (n_params + 1)


def aicc(rss: float, n_observations: int, n_params: int) -> float:
    """Return the small-sample corrected criterion AICc = AIC + 2 K (K + 1) / (N - K - 1).

    Parameters
    ----------
    rss : float
        Residual sum of squares.
    n_observations : int
        N, the number of coordinates (2 per frame).
    n_params : int
        p, the fitted parameters; K = p + 1 counts the noise variance.

    Returns
    -------
    float
        `aic` plus the correction (Hurvich and Tsai 1989), exact for a linear Gaussian
        model; inf when N <= K + 1, where it is undefined.
    """
    k = n_params + 1
    if n_observations - k - 1 <= 0:
        return math.inf
    return aic(rss, n_observations, n_params) + 2.0 * k * (k + 1) / (n_observations - k - 1)


def whiteness(residuals: ArrayLike) -> tuple[float, float]:
    """Return the lag-1 autocorrelation of residuals and its spread for white noise.

    Parameters
    ----------
    residuals : array_like
        Shape (n, 2): data minus fit of each coordinate at each frame, in frame order.

    Returns
    -------
    rho : float
        sum_c sum_i e_{i,c} e_{i+1,c} / sum_c sum_i e_{i,c}^2, pooled over the two
        coordinates (0 for residuals that are all 0).
    sd : float
        1 / sqrt(2 (n - 1)), the standard deviation of rho for independent noise (the
        Durbin-Watson statistic is about 2 (1 - rho)).

    Notes
    -----
    The residual of the right model is the tracking noise, independent from frame to
    frame: rho scatters about 0 by sd.  A model that misses the motion (a wrong Omega, k,
    axis or sense of rotation, or the wrong mechanism) leaves a smooth error, correlated
    from one frame to the next: rho approaches the share of that error in the residual
    variance, many times sd.
    """
    e = np.asarray(residuals, dtype=float)
    pairs = 2 * (e.shape[0] - 1)
    if pairs <= 0:
        return 0.0, math.inf
    with np.errstate(all="ignore"):
        scale = float(np.max(np.abs(e))) if e.size else 0.0
        if not math.isfinite(scale) or scale == 0.0:
            return 0.0, 1.0 / math.sqrt(pairs)
        e = e / scale
        rho = float(np.sum(e[1:] * e[:-1]) / np.sum(e * e))
    return rho, 1.0 / math.sqrt(pairs)


class _Fitter:
    """The least-squares problem of one model on one film, in the order of `_Layout`."""

    def __init__(self, lay: _Layout, tau: NDArray, xy: NDArray, setup: Setup) -> None:
        self.lay, self.tau, self.k, self.scale = lay, tau, setup.k, setup.radius
        self.data = xy.ravel()
        self.n_obs = 2 * tau.size
        #: RSS (m^2) of a fit that reproduces the positions to rounding (`EXACT_FIT`)
        self.rss_floor = self.n_obs * (EXACT_FIT * self.scale * float(np.max(np.abs(xy)))) ** 2
        self.lo, self.hi = (math.log(b) for b in BOUNDS[lay.model])
        self.s_max = math.log(OMEGA_FACTOR)

    def clamp(self, theta: NDArray[np.float64]) -> tuple[float, float]:
        """ln c and s held inside their ranges."""
        g = min(max(float(theta[self.lay.i_c]), self.lo), self.hi)
        s = 0.0
        if self.lay.fit_omega:
            s = min(max(float(theta[self.lay.i_s]), -self.s_max), self.s_max)
        return g, s

    def residuals(self, theta: NDArray[np.float64]) -> NDArray[np.float64]:
        """R (model - data) in m; a huge constant where the solution would overflow."""
        lay = self.lay
        z0, _, _, a = _unpack(lay, theta)
        g, s = self.clamp(theta)
        c, tau_s = math.exp(g), self.tau * math.exp(s)
        if lay.model == "slipping" and tau_s[-1] > max_time(c, self.k, z0):
            return np.full(self.n_obs, _OVERFLOW_RESIDUAL)
        try:
            z = _solve(lay.model, z0, tau_s, c, self.k)
        except ValueError:  # the rolling model's growing mode overflows
            return np.full(self.n_obs, _OVERFLOW_RESIDUAL)
        with np.errstate(all="ignore"):
            out = self.scale * ((z[:, :2] + a).ravel() - self.data)
        if not np.all(np.isfinite(out)):
            return np.full(self.n_obs, _OVERFLOW_RESIDUAL)
        return out

    def jacobian(self, theta: NDArray[np.float64]) -> NDArray[np.float64]:
        """d residuals / d theta (m); zero columns where a parameter is held at its range."""
        lay = self.lay
        z0, _, _, _ = _unpack(lay, theta)
        g, s = self.clamp(theta)
        try:
            others, j_c = _columns(lay, math.exp(g), s, z0, self.tau, self.k)
        except ValueError:
            return np.zeros((self.n_obs, lay.size))
        jac = _full_jacobian(others, j_c, lay)
        if not self.lo < theta[lay.i_c] < self.hi:
            jac[:, lay.i_c] = 0.0
        if lay.fit_omega and not -self.s_max < theta[lay.i_s] < self.s_max:
            jac[:, lay.i_s] = 0.0
        with np.errstate(all="ignore"):
            jac = self.scale * jac
        return np.where(np.isfinite(jac), jac, 0.0)

    def solve(self, theta0: NDArray[np.float64], fixed_c: float | None = None):
        """Levenberg-Marquardt from theta0; with ``fixed_c`` (ln c) that one is held."""
        lay = self.lay
        if fixed_c is None:
            fun, jac, x0 = self.residuals, self.jacobian, theta0
        else:

            def full(x: NDArray[np.float64]) -> NDArray[np.float64]:
                return np.insert(x, lay.i_c, fixed_c)

            def fun(x: NDArray[np.float64]) -> NDArray[np.float64]:
                return self.residuals(full(x))

            def jac(x: NDArray[np.float64]) -> NDArray[np.float64]:
                return np.delete(self.jacobian(full(x)), lay.i_c, axis=1)

            x0 = np.delete(theta0, lay.i_c)
        # Levenberg-Marquardt (MINPACK): its own small QR, no multithreaded LAPACK call per
        # step, which on a busy machine costs far more than the arithmetic.  Beyond BOUNDS
        # the coefficient is held at the bound (zero derivative), where the fit then stops.
        with np.errstate(all="ignore"):
            return least_squares(
                fun,
                x0,
                jac=jac,
                method="lm",
                x_scale="jac",
                ftol=1e-12,
                xtol=1e-12,
                gtol=1e-12,
                max_nfev=400 if fixed_c is None else 100,
            )

    def profile(self, g: float, theta: NDArray[np.float64]) -> float:
        """RSS minimised over every parameter but ln c, held at g (from ``theta``)."""
        res = self.solve(theta, fixed_c=g)
        r = self.residuals(np.insert(res.x, self.lay.i_c, g))
        return float(r @ r)


def _limit(fitter: _Fitter, theta: NDArray[np.float64], rss: float, bound: str) -> float:
    """One-sided 95 % limit of a coefficient that ran into a bound of `BOUNDS`.

    The profile RSS_p(c) (every other parameter refitted) is followed from the bound
    inwards, half a decade at a time, until RSS_p - RSS_min exceeds z_0.95^2 s^2 with
    s^2 = RSS_min / (N - p), or the RSS of a fit exact to rounding if that is larger (a
    noiseless film, where differences of rounding errors are no evidence); the crossing is
    then found by Brent's method in ln c.  The result is a lower limit at the upper bound
    and an upper limit at the lower one; the other end of `BOUNDS` if the film does not
    constrain the coefficient at all.
    """
    lay = fitter.lay
    sigma2 = rss / max(fitter.n_obs - lay.size, 1)
    target = max(Z95_ONE_SIDED**2 * sigma2, fitter.rss_floor)
    start = fitter.hi if bound == "upper" else fitter.lo
    end = fitter.lo if bound == "upper" else fitter.hi
    step = math.copysign(0.5 * math.log(10.0), end - start)
    best = {"rss": rss}

    def excess(g: float) -> float:
        value = fitter.profile(g, theta)
        best["rss"] = min(best["rss"], value)
        return value - best["rss"] - target

    prev, g = start, start + step
    while (end - g) * step > 0:
        if excess(g) > 0:
            try:
                return math.exp(brentq(excess, prev, g, xtol=1e-3))
            except ValueError:  # the minimum moved while scanning: take the bracket's end
                return math.exp(g)
        prev, g = g, g + step
    return math.exp(end)


def _least_squares(
    film: Film, setup: Setup, lay: _Layout
) -> tuple[_Fitter, Any, NDArray[np.float64], NDArray[np.float64]]:
    """The least-squares fit of `fit_model`, without its standard errors and limits.

    Returns the problem, the optimiser's result, the parameters (ln c and ln Omega held
    inside their ranges) and the residuals there (m).
    """
    tau, xy = _dimensionless(film, setup)
    n_obs, p = 2 * tau.size, lay.size
    if n_obs <= p:
        raise ValueError(
            f"{tau.size} frames give {n_obs} coordinates; the {lay.model} model has {p} "
            f"parameters, so at least {p // 2 + 1} frames are needed"
        )
    fitter = _Fitter(lay, tau, xy, setup)
    c0, s0 = start_values(lay.model, tau, xy, setup.k, fit_axis=lay.fit_axis)
    theta0 = np.concatenate(
        [
            s0[: lay.n_state],
            [math.log(c0)],
            [0.0] if lay.fit_omega else [],
            s0[lay.n_state :] if lay.fit_axis else [],
        ]
    )
    res = fitter.solve(theta0)
    theta = res.x.copy()
    g, s = fitter.clamp(theta)
    theta[lay.i_c] = g
    if lay.fit_omega:
        theta[lay.i_s] = s
    return fitter, res, theta, fitter.residuals(theta)


def fit_model(
    film: Film,
    setup: Setup,
    model: str,
    *,
    fit_omega: bool = False,
    fit_axis: bool = False,
) -> ModelFit:
    """Fit one model to a film by nonlinear least squares on its exact solution.

    Parameters
    ----------
    film : Film
        Tracked positions in the lab frame (SI units).
    setup : Setup
        Ball radius, turntable rate, inertia ratio and axis position.
    model : {"slipping", "rolling_resistance"}
    fit_omega : bool
        Fit Omega too (from ``setup.omega``, within a factor `OMEGA_FACTOR`).
    fit_axis : bool
        Fit the position of the axis too (from ``setup.axis``); only the rolling model
        depends on it.

    Returns
    -------
    ModelFit

    Raises
    ------
    ValueError
        If the film has no more coordinates 2 n than parameters p, or bad numbers.

    Notes
    -----
    Residuals R (r(tau_i) + a - r_i) in m, r from `turntable.solve` (2.7) or
    `turntable.rolling.solve`, tau_i = Omega (t_i - t_0); parameters the initial state and
    ln c, and ln Omega, a if asked (module docstring).  A trial point at which the solution
    would overflow a double over the film (`turntable.max_time`, relevant only for very long
    films) gets a huge residual, so the optimiser steps back.  A coefficient at a bound of
    `BOUNDS` gets a one-sided 95 % limit (`_limit`).
    """
    lay = _layout(model, fit_omega, fit_axis)
    setup = check_setup(setup)
    fitter, res, theta, r = _least_squares(film, setup, lay)
    tau, n_obs, p = fitter.tau, fitter.n_obs, lay.size
    g, s = fitter.clamp(theta)
    rss = float(r @ r)
    sigma = math.sqrt(rss / (n_obs - p))
    z0, _, _, a = _unpack(lay, theta)
    c = math.exp(g)
    try:
        others, j_c = _columns(lay, c, s, z0, tau, setup.k)
        jac = setup.radius * _full_jacobian(others, j_c, lay)
        with np.errstate(all="ignore"):
            ses = [_stderr_of(jac, i, sigma) for i in range(p)]
    except (ValueError, np.linalg.LinAlgError):
        ses = [math.nan] * p
    bound = None
    if fitter.hi - g < 1e-6:
        bound = "upper"
    elif g - fitter.lo < 1e-6:
        bound = "lower"
    limit = _limit(fitter, theta, rss, bound) if bound is not None else math.nan
    omega = setup.omega * math.exp(s)
    axis = tuple(float(v) for v in np.asarray(setup.axis) + setup.radius * a)
    residuals = -r.reshape(-1, 2)
    rho, rho_sd = whiteness(residuals)
    rate = float(_rates(model, np.float64(c), setup.k)[0].imag)
    return ModelFit(
        model=model,
        coefficient=c,
        stderr=c * ses[lay.i_c],
        log_stderr=ses[lay.i_c],
        state0=z0,
        t0=float(film.t[0]),
        rss=rss,
        rms_residual=math.sqrt(rss / n_obs),
        aic=aic(rss, n_obs, p),
        n_parameters=p,
        n_observations=n_obs,
        converged=bool(res.status > 0),
        at_bound=bound is not None,
        residuals=residuals,
        aicc=aicc(rss, n_obs, p),
        bound=bound,
        limit=limit,
        omega=omega,
        omega_stderr=omega * ses[lay.i_s] if lay.fit_omega else math.nan,
        omega_at_bound=lay.fit_omega and fitter.s_max - abs(s) < 1e-6,
        axis=(axis[0], axis[1]),
        axis_stderr=(
            (setup.radius * ses[lay.i_axis], setup.radius * ses[lay.i_axis + 1])
            if lay.fit_axis
            else (math.nan, math.nan)
        ),
        autocorrelation=rho,
        autocorrelation_sd=rho_sd,
        orbital_rate=rate,
        exact=rss <= fitter.rss_floor,
    )


class FilmFit(NamedTuple):
    """Both models fitted to one film, and the selection.

    Attributes
    ----------
    fits : dict
        {model: ModelFit}, in the order of `MODELS`.
    selected : str or None
        The model of smaller AICc; None when the film is too short to compare them
        (fewer than `MIN_DOF` coordinates left, see `min_frames`) or a fit failed.
    aicc_difference : float
        AICc of the other model minus AICc of the selected one (>= 0); nan if none.
    akaike_weights : dict
        {model: exp(-Delta_i / 2) / sum_j exp(-Delta_j / 2)}, Delta_i = AICc_i - min AICc
        (nan if an AICc is undefined).
    decisive : bool
        Whether a model is selected with an AICc difference of at least `DECISIVE` and
        fits the film at least as well as the other (a smaller or equal RSS).
    reason : str
        Why the selection is not decisive ("" if it is).
    """

    fits: dict[str, ModelFit]
    selected: str | None
    aicc_difference: float
    akaike_weights: dict[str, float]
    decisive: bool = True
    reason: str = ""


def fit_film(
    film: Film, setup: Setup, *, fit_omega: bool = False, fit_axis: bool = False
) -> FilmFit:
    """Fit both models to a film and select one by AICc (see `fit_model`, `FilmFit`).

    Parameters
    ----------
    film : Film
    setup : Setup
    fit_omega, fit_axis : bool
        As in `fit_model`, for both models.

    Returns
    -------
    FilmFit

    Notes
    -----
    Akaike weights: w_i = exp(-Delta_i / 2) / sum_j exp(-Delta_j / 2), the relative
    likelihood of each model given the data; AICc differences of `DECISIVE` (10) or more
    are read as decisive, provided the selected model also fits at least as well (its RSS
    is not larger): otherwise the difference is the penalty on the other model's extra
    parameters alone, which on a short film exceeds 10 by itself (2 q + 2 K_s (K_s + 1) /
    (N - K_s - 1) - 2 K_r (K_r + 1) / (N - K_r - 1) = 10.6 for 10 frames) and says nothing
    about the film.  AICc = AIC + 2 K (K + 1) / (N - K - 1) corrects AIC's overconfidence
    on short films; with N - K - 1 < `MIN_DOF` for the larger model no model is selected,
    because the comparison then rests on a handful of residual degrees of freedom (with
    AIC, 5-frame films selected the wrong model in half the cases, some of them with a
    difference above 10).
    """
    fits = {
        model: fit_model(film, setup, model, fit_omega=fit_omega, fit_axis=fit_axis)
        for model in MODELS
    }
    aiccs = {m: f.aicc for m, f in fits.items()}
    n_obs = next(iter(fits.values())).n_observations
    big = max(fits.values(), key=lambda f: f.n_parameters)
    dof = n_obs - (big.n_parameters + 1) - 1
    finite = all(math.isfinite(a) for a in aiccs.values())
    weights = {m: math.nan for m in fits}
    if finite:
        low = min(aiccs.values())
        rel = {m: math.exp(-(a - low) / 2.0) for m, a in aiccs.items()}
        weights = {m: w / sum(rel.values()) for m, w in rel.items()}
    if dof < MIN_DOF:
        n = n_obs // 2
        reason = (
            f"no model selected: {n} frames give N = {n_obs} coordinates, and the "
            f"{big.model} model has p = {big.n_parameters} parameters, so only "
            f"N - p - 2 = {dof} are left for AICc to compare the models; at least {MIN_DOF} "
            f"are needed ({min_frames(fit_omega, fit_axis)} frames)"
        )
        return FilmFit(fits, None, math.nan, weights, False, reason)
    if not finite:
        bad = [m for m, a in aiccs.items() if not math.isfinite(a)]
        reason = f"no model selected: the fit of {' and '.join(bad)} gave no finite AICc"
        return FilmFit(fits, None, math.nan, weights, False, reason)
    if all(f.exact for f in fits.values()):
        reason = (
            "no model selected: both models reproduce the positions to rounding (rms "
            + " and ".join(f"{f.rms_residual:.2g} m" for f in fits.values())
            + "); the film carries no noise by which to weigh them"
        )
        return FilmFit(fits, None, math.nan, weights, False, reason)
    best = min(aiccs, key=aiccs.__getitem__)
    other = next(m for m in fits if m != best)
    diff = aiccs[other] - aiccs[best]
    # The model with fewer parameters can win by the penalty on the other's parameters
    # alone; that is no evidence from the film unless it also fits at least as well.
    fits_better = fits[best].rss <= fits[other].rss
    decisive = diff >= DECISIVE and fits_better
    reason = ""
    if diff < DECISIVE:
        reason = (
            f"the selection of {best} is not decisive: AICc difference {diff:.3g} < "
            f"{DECISIVE:g} (Akaike weight {weights[best]:.3g})"
        )
    elif not fits_better:
        reason = (
            f"the selection of {best} is not decisive: its AICc difference {diff:.3g} comes "
            f"from the penalty on the {fits[other].n_parameters} parameters of {other} alone, "
            f"which fits the film better (rms {fits[other].rms_residual:.3g} m against "
            f"{fits[best].rms_residual:.3g} m)"
        )
    return FilmFit(fits, best, diff, weights, decisive, reason)


def frame_step(film: Film, setup: Setup) -> float:
    """Return the median step Omega (t_{i+1} - t_i) between frames, rad (0 for one frame)."""
    t = np.asarray(film.t, dtype=float)
    return float(setup.omega * np.median(np.diff(t))) if t.size > 1 else 0.0


class Consistency(NamedTuple):
    """The fit repeated with Omega and the axis free: are the given values right?

    Attributes
    ----------
    refit : FilmFit
        `fit_film` with ``fit_omega`` and ``fit_axis``.
    freed : tuple of str
        What was given and is now free: "omega", "axis" (the axis only matters for the
        rolling model).
    model : str
        The model judged: the one selected by the fit that is checked, else the one
        ``refit`` selects, else the one of smaller RSS.  (Not simply the one ``refit``
        selects: with the axis free the rolling model can mimic a slipping ball of large
        mu0, whose spiral centre it takes for the axis, and ``refit`` may then prefer it,
        not decisively, with an axis far from the given one.)
    omega_z : float
        (Omega fitted - Omega given) / its standard error for that model (nan if Omega was
        fitted anyway, or its error is not finite).
    axis_z : tuple of float
        The same for each coordinate of the axis (nan unless the judged model is the
        rolling one and the axis was given).
    selection_changed : bool
        Whether ``refit`` decisively selects another model than the fit it checks.
    """

    refit: FilmFit
    freed: tuple[str, ...]
    model: str
    omega_z: float
    axis_z: tuple[float, float]
    selection_changed: bool


def consistency(
    film: Film,
    setup: Setup,
    result: FilmFit,
    *,
    fit_omega: bool = False,
    fit_axis: bool = False,
) -> Consistency | None:
    """Check the given Omega and axis: fit again with them free and compare.

    Parameters
    ----------
    film, setup : Film, Setup
        As given to `fit_film`.
    result : FilmFit
        The fit to check, made with ``fit_omega`` and ``fit_axis`` as given here.
    fit_omega, fit_axis : bool
        What that fit freed already; None is returned if both were.

    Returns
    -------
    Consistency or None

    Notes
    -----
    The whiteness of the residuals (`whiteness`) detects a wrong Omega or axis only when
    the error it leaves is larger than the noise; a small error is partly absorbed by the
    coefficient, the initial state, or the other model (a 0.4 % error in Omega on a film of
    30 frames/s, 6 s, 0.3 mm noise made the rolling model fit a slipping film with white
    residuals).  The direct test is the fit with Omega (and the axis) free: if the given
    value is right, the fitted one scatters about it by its standard error, and
    |z| > `CONSISTENCY_Z` happens with probability 6e-5.  Where the wrong Omega has made
    the other model win, the refit selects the right one again (``selection_changed`` if
    it does so decisively).
    """
    freed = tuple(n for n, fixed in (("omega", not fit_omega), ("axis", not fit_axis)) if fixed)
    if not freed:
        return None
    setup = check_setup(setup)
    refit = fit_film(film, setup, fit_omega=True, fit_axis=True)
    model = result.selected or refit.selected or min(refit.fits, key=lambda m: refit.fits[m].rss)
    f = refit.fits[model]

    def z(value: float, given: float, se: float) -> float:
        return (value - given) / se if math.isfinite(se) and se > 0 else math.nan

    omega_z = z(f.omega, setup.omega, f.omega_stderr) if "omega" in freed else math.nan
    axis_z = (math.nan, math.nan)
    if "axis" in freed and model == "rolling_resistance":
        axis_z = (
            z(f.axis[0], setup.axis[0], f.axis_stderr[0]),
            z(f.axis[1], setup.axis[1], f.axis_stderr[1]),
        )
    changed = bool(
        refit.decisive and result.selected is not None and refit.selected != result.selected
    )
    return Consistency(refit, freed, model, omega_z, axis_z, changed)


def checked_selection(result: FilmFit, check: Consistency | None) -> FilmFit:
    """Return the fit with its selection not decisive where `consistency` contradicts it.

    Parameters
    ----------
    result : FilmFit
        The fit with the given Omega and axis.
    check : Consistency or None
        The same fit with them free (`consistency`).

    Returns
    -------
    FilmFit
        ``result`` itself, unless its selection is decisive and the check finds the given
        Omega or axis more than `CONSISTENCY_Z` standard errors from the ones the film
        prefers, or selects another model decisively with them free: then a copy with
        ``decisive`` False and ``reason`` saying why.  (A wrong Omega can make the wrong
        model win by a large AICc difference: the difference then measures the fit to the
        wrong rate, not the evidence for the model.)
    """
    if check is None or not result.decisive:
        return result
    why = []
    if check.selection_changed:
        why.append(
            f"with {' and '.join(check.freed)} free the film selects {check.refit.selected} "
            "decisively"
        )
    if abs(check.omega_z) > CONSISTENCY_Z:
        why.append(f"the given Omega is {check.omega_z:+.3g} standard errors from the film's")
    if max(abs(v) for v in check.axis_z) > CONSISTENCY_Z:
        why.append(f"the given axis is more than {CONSISTENCY_Z:g} standard errors from the film's")
    if not why:
        return result
    reason = (
        f"the selection of {result.selected} is not decisive: it rests on the given Omega or "
        f"axis, which the film contradicts ({'; '.join(why)})"
    )
    return result._replace(decisive=False, reason=reason)


def problems(
    result: FilmFit, film: Film, setup: Setup, check: Consistency | None = None
) -> list[str]:
    """Return what a user must know about a fit, one line each (empty if nothing).

    Parameters
    ----------
    result : FilmFit
    film : Film
    setup : Setup
        As given to `fit_film` (Omega before any fit of it).
    check : Consistency, optional
        The fit repeated with Omega and the axis free (`consistency`).

    Returns
    -------
    list of str
        In this order, each where it applies: frames too far apart to follow the ball
        (Omega dt above `MAX_FRAME_STEP`: a time unit or rate mistake); each fit that did
        not converge; each coefficient at a bound of `BOUNDS`, with its one-sided limit;
        each fitted Omega at the end of its range; a selection that is not decisive or not
        made (`FilmFit.reason`); a relative standard error above `LINEAR_RELATIVE_ERROR`
        of the selected model (of each, with none selected or a selection that is not
        decisive, `checked_selection`); residuals of the selected
        model (or, with none selected,
        of the better fit) that are not white noise (`whiteness`), which means that
        neither model fits to the noise level; with ``check``, a given Omega or axis more
        than `CONSISTENCY_Z` standard errors from the one the film prefers (judged on the
        model selected, if decisively), and a selection that changes decisively when they
        are free.
    """
    out: list[str] = []
    step = frame_step(film, setup)
    if step > MAX_FRAME_STEP:
        out.append(
            f"the turntable turns {step:.3g} rad between frames ({2 * math.pi / step:.2g} frames "
            "per turn): too few to follow the ball; check that t is in seconds and "
            "--omega/--rpm"
        )
    for model, f in result.fits.items():
        name = COEFFICIENT[model]
        if not f.converged:
            out.append(f"{model}: the least-squares fit did not converge")
        if f.bound is not None:
            lo, hi = BOUNDS[model]
            end = hi if f.bound == "upper" else lo
            other = lo if f.bound == "upper" else hi
            kind = "lower" if f.bound == "upper" else "upper"
            if math.isclose(f.limit, other, rel_tol=1e-9):
                out.append(
                    f"{model}: {name} ran into the {f.bound} end {end:g} of its search range "
                    f"and the film does not constrain it anywhere in [{lo:g}, {hi:g}]; no value "
                    f"is reported"
                )
            else:
                sign = ">" if f.bound == "upper" else "<"
                out.append(
                    f"{model}: {name} ran into the {f.bound} end {end:g} of its search range; "
                    f"the film only shows {name} {sign} {f.limit:.3g} (one-sided 95 % limit, "
                    f"reported as {name}_{kind}_limit instead of a value)"
                )
        if f.omega_at_bound:
            out.append(
                f"{model}: the fitted Omega {f.omega:.4g} rad/s ran into the end of its range "
                f"(a factor {OMEGA_FACTOR:g} from --omega/--rpm)"
            )
    if result.reason:
        out.append(result.reason)
    # the relative error of the selected model; of both where the selection is not decisive
    shown = checked_selection(result, check)
    for model in [shown.selected] if shown.selected and shown.decisive else list(result.fits):
        f = result.fits[model]
        if f.bound is None and not math.isfinite(f.log_stderr):
            out.append(
                f"{model}: the film does not constrain {COEFFICIENT[model]} (its standard error "
                "is not finite): the value reported is no measurement"
            )
        elif f.bound is None and f.log_stderr > LINEAR_RELATIVE_ERROR:
            out.append(
                f"{model}: the relative standard error of {COEFFICIENT[model]} is "
                f"{f.log_stderr:.2g}, above {LINEAR_RELATIVE_ERROR:g}, where the fit is no "
                "longer locally linear: its standard error and interval are only indicative "
                "and can miss the truth"
            )
    judged = result.selected or min(result.fits, key=lambda m: result.fits[m].rss)
    f = result.fits[judged]
    if not f.white:
        out.append(
            f"neither model fits to the noise level: the residuals of the {judged} fit "
            f"(rms {f.rms_residual:.3g} m) are correlated from frame to frame (lag-1 "
            f"autocorrelation {f.autocorrelation:.3g}, {abs(f.whiteness_z):.3g} times its "
            "spread for white noise); check --omega/--rpm, --k, --axis and the sign of y"
        )
    # Omega and the axis are judged on the model the film decisively selects: with no model
    # known, each model's freed values can wander (on a short film the rolling model with
    # the axis free mimics a slipping ball), and their linearised errors are too small.
    if check is not None and result.decisive:
        g = check.refit.fits[check.model]
        if abs(check.omega_z) > CONSISTENCY_Z:
            out.append(
                f"the film prefers Omega = {g.omega:.6g} +- {g.omega_stderr:.2g} rad/s "
                f"({check.model} model with Omega free), {check.omega_z:+.3g} standard errors "
                f"from the given {setup.omega:.6g} rad/s: check --omega/--rpm (and --k), or "
                "fit it with --fit-omega"
            )
        if max(abs(v) for v in check.axis_z) > CONSISTENCY_Z:
            out.append(
                f"the film prefers the axis at ({g.axis[0]:.4g}, {g.axis[1]:.4g}) m +- "
                f"({g.axis_stderr[0]:.2g}, {g.axis_stderr[1]:.2g}) m ({check.model} model "
                f"with the axis free), not at the given ({setup.axis[0]:.4g}, "
                f"{setup.axis[1]:.4g}) m: check --axis, or fit it with --fit-axis"
            )
    if check is not None and check.selection_changed:
        out.append(
            f"with {' and '.join(check.freed)} free the film selects {check.refit.selected} "
            f"decisively (AICc difference {check.refit.aicc_difference:.3g}), not "
            f"{result.selected}: the selection rests on the given values; rerun with "
            "--fit-omega" + (" --fit-axis" if "axis" in check.freed else "")
        )
    return out


def _finite(x: float) -> float | None:
    return float(x) if math.isfinite(x) else None


def result_json(
    result: FilmFit,
    setup: Setup,
    film: Film,
    mass: float | None = None,
    source: str = "",
    check: Consistency | None = None,
) -> dict[str, Any]:
    """Return the fit as the JSON object that ``turntable fit`` prints.

    Parameters
    ----------
    result : FilmFit
    setup : Setup
        As given to `fit_film`.
    film : Film
        Its ``synthetic`` flag (a SYNTHETIC comment in the file) is copied to "data".
    mass : float, optional
        Mass of the ball in kg; adds the dimensional coefficients
        mu0_dim = mu0 m Omega (kg/s, force per slip velocity) and
        delta_dim = delta m R^2 Omega (kg m^2/s, torque per angular velocity), with the
        model's Omega (the fitted one with ``fit_omega``).
    source : str
        Name of the data file.
    check : Consistency, optional
        The fit repeated with Omega and the axis free (`consistency`), reported under
        "consistency" and in the warnings.

    Returns
    -------
    dict
        Keys "selected", "selection", "slipping", "rolling_resistance", "consistency",
        "warnings" (`problems`), "data", "setup", "units" (README, "Fitting your own
        film").  Non-finite numbers are None.
    """
    setup = check_setup(setup)
    fits = result.fits
    fit_omega = any(math.isfinite(f.omega_stderr) for f in fits.values())
    fit_axis = math.isfinite(fits["rolling_resistance"].axis_stderr[0])
    shown = checked_selection(result, check)
    out: dict[str, Any] = {
        "selected": result.selected,
        "selection": {
            "criterion": (
                "AICc = N ln(RSS/N) + 2 K + 2 K (K + 1) / (N - K - 1), K = p + 1; decisive "
                f"from a difference of {DECISIVE:g}, unless the fit with Omega and the axis "
                f"free contradicts the given ones (|z| > {CONSISTENCY_Z:g}) or selects the "
                f"other model; no selection if N - K - 1 < {MIN_DOF}"
            ),
            "aicc_difference": _finite(result.aicc_difference),
            "akaike_weights": {m: _finite(w) for m, w in result.akaike_weights.items()},
            "decisive": bool(shown.decisive),
            "reason": shown.reason or None,
        },
    }
    for model, f in fits.items():
        name = COEFFICIENT[model]
        factor, unit = 1.0, ""
        if mass is not None:
            m = _validate.positive_scalar("mass", mass)
            factor = m * f.omega * (1.0 if model == "slipping" else setup.radius**2)
            unit = "kg_per_s" if model == "slipping" else "kg_m2_per_s"
        entry: dict[str, Any] = {}
        if f.bound is None:
            lo, hi = f.ci95
            entry.update(
                {
                    name: f.coefficient,
                    f"{name}_stderr": _finite(f.stderr),
                    f"{name}_relative_stderr": _finite(f.log_stderr),
                    f"{name}_ci95": [_finite(lo), _finite(hi)],
                }
            )
            if mass is not None:
                entry[f"{name}_dim_{unit}"] = f.coefficient * factor
                entry[f"{name}_dim_stderr_{unit}"] = _finite(f.stderr * factor)
                entry[f"{name}_dim_ci95_{unit}"] = [_finite(lo * factor), _finite(hi * factor)]
        else:
            kind = "lower" if f.bound == "upper" else "upper"
            entry.update(
                {
                    name: None,
                    f"{name}_stderr": None,
                    f"{name}_relative_stderr": None,
                    f"{name}_ci95": None,
                    f"{name}_{kind}_limit": f.limit,
                    f"{name}_search_bound": f.coefficient,
                }
            )
            if mass is not None:
                entry[f"{name}_dim_{kind}_limit_{unit}"] = f.limit * factor
        entry.update(
            {
                "rms_residual_m": _finite(f.rms_residual),
                "aic": _finite(f.aic),
                "aicc": _finite(f.aicc),
                "n_parameters": f.n_parameters,
                "state0": [_finite(v) for v in f.state0],
                "converged": f.converged,
                "at_bound": f.at_bound,
                "omega_rad_s": f.omega,
                "omega_stderr_rad_s": _finite(f.omega_stderr),
                "axis_m": list(f.axis),
                "axis_stderr_m": (
                    [_finite(v) for v in f.axis_stderr] if math.isfinite(f.axis_stderr[0]) else None
                ),
                "residual_lag1_autocorrelation": _finite(f.autocorrelation),
                "residual_lag1_white_sd": _finite(f.autocorrelation_sd),
                "residuals_white": f.white,
                "orbital_turns": _finite(
                    f.orbital_rate * f.omega * (film.t[-1] - film.t[0]) / (2.0 * math.pi)
                ),
            }
        )
        out[model] = entry
    out["consistency"] = None
    if check is not None:
        g = check.refit.fits[check.model]
        out["consistency"] = {
            "freed": list(check.freed),
            "model": check.model,
            "selected": check.refit.selected,
            "aicc_difference": _finite(check.refit.aicc_difference),
            "decisive": check.refit.decisive,
            "selection_changed": check.selection_changed,
            "omega_rad_s": g.omega,
            "omega_stderr_rad_s": _finite(g.omega_stderr),
            "omega_z": _finite(check.omega_z),
            "axis_m": list(g.axis),
            "axis_stderr_m": [_finite(v) for v in g.axis_stderr],
            "axis_z": [_finite(v) for v in check.axis_z],
            "threshold_z": CONSISTENCY_Z,
        }
    out["warnings"] = problems(result, film, setup, check)
    duration = float(film.t[-1] - film.t[0])
    selected = fits[result.selected] if result.selected else None
    out["data"] = {
        "file": source,
        "synthetic": bool(getattr(film, "synthetic", False)),
        "n_frames": int(film.t.size),
        "n_observations": 2 * int(film.t.size),
        "t0_s": float(film.t[0]),
        "duration_s": duration,
        "turntable_turns": float(setup.omega * duration / (2.0 * math.pi)),
        "ball_turns": (
            _finite(selected.orbital_rate * selected.omega * duration / (2.0 * math.pi))
            if selected
            else None
        ),
        "frame_step_rad": frame_step(film, setup),
    }
    out["setup"] = {
        "radius_m": setup.radius,
        "omega_rad_s": setup.omega,
        "k": setup.k,
        "axis_m": list(setup.axis),
        "fit_omega": fit_omega,
        "fit_axis": fit_axis,
        **({"mass_kg": float(mass)} if mass is not None else {}),
    }
    out["units"] = {
        "mu0": "mu0_dim / (m Omega), dimensionless",
        "delta": "delta_dim / (m R^2 Omega), dimensionless",
        "state0": (
            "dimensionless state (x, y, vx, vy, wx, wy) at t0_s: position relative to the "
            "model's axis_m in units of R, velocity in units of R Omega, spin in units of "
            "Omega (the model's omega_rad_s)"
        ),
        "stderr": "from the Jacobian at the optimum and the residual variance RSS/(N - p)",
        "relative_stderr": "standard error of ln(coefficient), i.e. stderr / coefficient",
        "ci95": "95 % interval exp(ln c -+ 1.96 relative_stderr): use it when relative_stderr "
        "is not small",
        "limit": (
            "a coefficient at the end of its search range is no measurement: null, with a "
            "one-sided 95 % limit (*_lower_limit or *_upper_limit) from the profile of the RSS"
        ),
        "residual_lag1_autocorrelation": (
            "of the residuals, pooled over x and y; about 0 +- residual_lag1_white_sd for a "
            f"model that fits to the noise level; residuals_white is false beyond "
            f"{WHITENESS_Z:g} times that spread"
        ),
        "orbital_turns": "turns of the ball about its spiral centre during the film",
        "consistency": (
            "both models fitted again with Omega and the axis free: the judged model's "
            "Omega and axis, and their distance from the given ones in standard errors "
            "(omega_z, axis_z; a warning beyond threshold_z)"
        ),
        "turntable_turns": "turns of the turntable during the film (data)",
    }
    return out


# --------------------------------------------------------------------------- design
def _truth_jacobian(
    model: str,
    coefficient: float,
    state0: ArrayLike,
    setup: Setup,
    camera: Camera,
    fit_omega: bool = False,
    fit_axis: bool = False,
) -> tuple[_Layout, NDArray[np.float64]]:
    lay = _layout(model, fit_omega, fit_axis)
    setup = check_setup(setup)
    c = _validate.positive_scalar(COEFFICIENT[model], coefficient)
    z0 = _validate.state("state0", state0)
    tau = setup.omega * frame_times(camera)
    if 2 * tau.size <= lay.size:
        raise ValueError(
            f"too few frames: the camera gives {tau.size} frames ({2 * tau.size} coordinates) "
            f"for the {lay.size} parameters of the {model} model"
        )
    if model == "rolling_resistance":
        # validates the constraint (ValueError naming the slip)
        rolling.solve(z0, tau[:1], c, setup.k)
    others, j_c = _columns(lay, c, 0.0, z0, tau, setup.k)
    return lay, setup.radius * _full_jacobian(others, j_c, lay)


def predicted_stderr(
    model: str,
    coefficient: float,
    state0: ArrayLike,
    setup: Setup,
    camera: Camera,
    *,
    fit_omega: bool = False,
    fit_axis: bool = False,
) -> float:
    """Return the standard error of the coefficient that a film can reach (Cramer-Rao).

    Parameters
    ----------
    model : {"slipping", "rolling_resistance"}
    coefficient : float
        True mu0 or delta (dimensionless).
    state0 : array_like
        True dimensionless state at the first frame (on the no-slip constraint for the
        rolling model; `turntable.no_slip_state` projects one there).
    setup : Setup
        Ball radius, turntable rate and inertia ratio.
    camera : Camera
        Frame rate, tracking noise (m per coordinate) and duration.
    fit_omega, fit_axis : bool
        Whether Omega (and, rolling, the axis) are fitted too, i.e. nuisance parameters.

    Returns
    -------
    float
        se(c); the relative error is se(c) / c.

    Raises
    ------
    ValueError
        For fewer coordinates than parameters, or bad numbers.

    Notes
    -----
    Fisher information F = J^T J / sigma^2 over the frames, J the derivatives of the
    positions (m) with respect to all parameters at the truth; the others are nuisances,
    so var(ln c) = [F^-1]_cc = sigma^2 / |(I - P) j_c|^2 (module docstring), and
    se(c) = c sqrt(var(ln c)).  It is what `fit_model` reports, on average, for films of
    this camera, as long as the fit is locally linear: for a predicted relative error
    above about 0.2 the estimates scatter more than this (Fig. 8).
    """
    noise = _validate.positive_scalar("noise", camera.noise)
    lay, jac = _truth_jacobian(model, coefficient, state0, setup, camera, fit_omega, fit_axis)
    return float(coefficient) * _stderr_of(jac, lay.i_c, noise)


class Distinguishability(NamedTuple):
    """How well a film tells a slipping ball from one rolling without slipping.

    Attributes
    ----------
    delta : float
        Coefficient of the rolling motion closest to the noiseless slipping film.
    rms_distance : float
        rms distance per coordinate between the two, m.
    noncentrality : float
        lambda = (sum of squared distances over the frames) / noise^2.
    expected_aicc_difference : float
        Expected AICc(rolling) - AICc(slipping), about lambda - (p_slipping - p_rolling)
        for lambda much smaller than the number of coordinates.
    selection_probability : float
        Probability that AICc selects the slipping model.
    """

    delta: float
    rms_distance: float
    noncentrality: float
    expected_aicc_difference: float
    selection_probability: float


def distinguishability(
    mu0: float, state0: ArrayLike, setup: Setup, camera: Camera
) -> Distinguishability:
    """Return how well a film of a slipping ball rules out rolling without slipping.

    Parameters
    ----------
    mu0 : float
        Friction coefficient of the slipping ball (dimensionless).
    state0 : array_like
        Its dimensionless state at the first frame.
    setup, camera : Setup, Camera
        As in `predicted_stderr`.

    Returns
    -------
    Distinguishability

    Raises
    ------
    ValueError
        If the camera gives fewer frames than `min_frames` (too few for AICc to compare
        the 7 parameters of the slipping model with the 5 of the rolling one), or bad
        numbers.

    Notes
    -----
    The noiseless film of the slipping ball is fitted with the rolling model
    (`fit_model`); lambda = RSS_min / sigma^2.  With noise, and both models linearised
    about their fits, RSS_s = sigma^2 chi^2_{N - p_s} and RSS_r = RSS_s + sigma^2 X with X
    independent of RSS_s, a noncentral chi-square with q = p_s - p_r = 2 degrees of
    freedom and noncentrality lambda (the rolling fit also absorbs part of the noise).
    Then AICc_r - AICc_s = N ln(1 + X sigma^2 / RSS_s) - D with
    D = 2 q + 2 K_s (K_s + 1) / (N - K_s - 1) - 2 K_r (K_r + 1) / (N - K_r - 1)
    (K = p + 1), whose mean is about N ln((N - p_r + lambda) / (N - p_s)) - D
    (= lambda - q for lambda << N and many frames), and the slipping model is selected when
    (X / q) / (RSS_s / (N - p_s)), a noncentral F variable, exceeds
    (e^{D / N} - 1)(N - p_s) / q: probability about P(chi'^2_q(lambda) > 2 q) for many
    frames (e^-2 = 0.14 at lambda = 0, when the two motions coincide).  Valid while the
    fits are locally linear.
    """
    from scipy.special import ncfdtr

    setup = check_setup(setup)
    noise = _validate.positive_scalar("noise", camera.noise)
    t = frame_times(camera)
    p_s, p_r = n_parameters("slipping"), n_parameters("rolling_resistance")
    if t.size < min_frames():
        raise ValueError(
            f"too few frames for a selection: the camera gives {t.size} frames "
            f"({2 * t.size} coordinates) for the {p_s} parameters of the slipping model "
            f"(and the noise variance); AICc needs N - p - 2 >= {MIN_DOF}, at least "
            f"{min_frames()} frames (fps * duration_s + 1)"
        )
    xy = positions("slipping", mu0, state0, t, setup)
    # the fit of `fit_model`, without the standard errors and the limit at a bound of
    # delta (the profile of the RSS: a third of the time), which are not needed here
    lay = _layout("rolling_resistance", False, False)
    fitter, _, theta, r = _least_squares(Film(t, xy[:, 0], xy[:, 1]), setup, lay)
    rss, n = float(r @ r), fitter.n_obs
    q = p_s - p_r
    k_s, k_r = p_s + 1, p_r + 1
    d = 2.0 * q + 2.0 * k_s * (k_s + 1) / (n - k_s - 1) - 2.0 * k_r * (k_r + 1) / (n - k_r - 1)
    lam = rss / noise**2
    threshold = math.expm1(d / n) * (n - p_s) / q
    return Distinguishability(
        delta=math.exp(theta[lay.i_c]),
        rms_distance=math.sqrt(rss / n),
        noncentrality=lam,
        expected_aicc_difference=n * math.log((n - p_r + lam) / (n - p_s)) - d,
        # 1 - the CDF of the noncentral F (scipy.special: scipy.stats.ncf.sf gives the same
        # value to 1e-16, but importing scipy.stats costs 0.4 s); the probability is above
        # about e^-2, so the subtraction loses no digit that matters
        selection_probability=float(1.0 - ncfdtr(q, n - p_s, lam, threshold)),
    )


class Measurability(NamedTuple):
    """`measurability` over a grid of mu0 (1-D arrays of the grid's length).

    Attributes
    ----------
    mu0, mu0_stderr : numpy.ndarray
        The grid and the predicted standard error of mu0 for a slipping ball.
    delta_stderr : numpy.ndarray
        Predicted standard error of delta for a rolling ball with delta equal to the
        grid's value.
    closest_delta, rms_distance, expected_aicc_difference, selection_probability
        `Distinguishability` of each slipping ball from the closest rolling motion.
    """

    mu0: NDArray[np.float64]
    mu0_stderr: NDArray[np.float64]
    delta_stderr: NDArray[np.float64]
    closest_delta: NDArray[np.float64]
    rms_distance: NDArray[np.float64]
    expected_aicc_difference: NDArray[np.float64]
    selection_probability: NDArray[np.float64]


def measurability(
    mu0: Sequence[float] | NDArray[np.float64],
    state0: ArrayLike,
    setup: Setup,
    camera: Camera,
) -> Measurability:
    """Return what a camera can measure, for each mu0 of a grid.

    Parameters
    ----------
    mu0 : sequence of float
        Friction coefficients of the slipping ball.
    state0 : array_like
        Dimensionless state of the ball at the first frame, e.g. from `state_from_si`.
        The rolling ball starts from its projection on the no-slip constraint
        (`turntable.no_slip_state`: same position and conserved quantities).
    setup, camera : Setup, Camera

    Returns
    -------
    Measurability
        For each mu0: `predicted_stderr` of mu0; for delta equal to it, the rolling
        ball's `predicted_stderr` of delta; and the `distinguishability` of the slipping
        ball from the closest rolling motion.
    """
    mu0 = _validate.positive("mu0", mu0).ravel()
    setup = check_setup(setup)
    z0 = _validate.state("state0", state0)
    z_roll = no_slip_state(z0, setup.k)
    rows = []
    for m in mu0:
        d = distinguishability(m, z0, setup, camera)
        rows.append(
            (
                predicted_stderr("slipping", m, z0, setup, camera),
                predicted_stderr("rolling_resistance", m, z_roll, setup, camera),
                d.delta,
                d.rms_distance,
                d.expected_aicc_difference,
                d.selection_probability,
            )
        )
    cols = np.array(rows).T
    return Measurability(mu0, *cols)


# --------------------------------------------------------------------------- reading results
def setup_from_json(result: dict[str, Any], model: str | None = None) -> Setup:
    """Return the `Setup` recorded in a result of `result_json` (``turntable fit``).

    With ``model``, Omega and the axis are that model's (fitted ones with ``--fit-omega``,
    ``--fit-axis``).
    """
    s = result["setup"]
    omega, axis = s["omega_rad_s"], s["axis_m"]
    if model is not None:
        entry = result[_check_model(model)]
        omega, axis = entry.get("omega_rad_s", omega), entry.get("axis_m", axis)
    return check_setup(Setup(s["radius_m"], omega, s["k"], (axis[0], axis[1])))


def fitted_coefficient(result: dict[str, Any], model: str) -> float:
    """Return the coefficient with which a model's path is drawn: the fitted value, or
    where the search stopped when it is reported as a limit (``*_search_bound``)."""
    entry = result[_check_model(model)]
    name = COEFFICIENT[model]
    value = entry.get(name)
    return float(value if value is not None else entry[f"{name}_search_bound"])


def fitted_positions(result: dict[str, Any], model: str, t: ArrayLike) -> NDArray[np.float64]:
    """Return the positions (m) of one fitted model of a `result_json` at times ``t`` (s).

    Parameters
    ----------
    result : dict
        The JSON object of ``turntable fit``.
    model : {"slipping", "rolling_resistance"}
    t : array_like
        Times in s, not before the first frame ``result["data"]["t0_s"]``.

    Returns
    -------
    numpy.ndarray
        Shape (len(t), 2), from `positions` with the fitted coefficient, state0, Omega
        and axis.

    Raises
    ------
    ValueError
        If the result holds no finite fit of that model.
    """
    entry = result[_check_model(model)]
    state0 = entry["state0"]
    if any(v is None for v in state0):
        raise ValueError(f"the result holds no finite fit of the {model} model")
    return positions(
        model,
        fitted_coefficient(result, model),
        state0,
        t,
        setup_from_json(result, model),
        result["data"]["t0_s"],
    )


def indistinguishable_above(table: Measurability, probability: float) -> float:
    """Return the mu0 above which AICc selects the slipping model less often than ``probability``.

    Parameters
    ----------
    table : Measurability
        From `measurability`, on an increasing grid of mu0.
    probability : float
        Required probability of selecting the slipping model, in (e^-2, 1).

    Returns
    -------
    float
        The crossing of the selection probability with ``probability`` after the last
        grid point where it is at least ``probability``, interpolated linearly in ln mu0;
        inf if the last grid point is still above, the first grid value if none is.
    """
    prob = float(probability)
    mu0, sel = np.asarray(table.mu0), np.asarray(table.selection_probability)
    if np.any(np.diff(mu0) <= 0):
        raise ValueError("table.mu0 must increase")
    above = np.flatnonzero(sel >= prob)
    if above.size == 0:
        return float(mu0[0])
    i = int(above[-1])
    if i == mu0.size - 1:
        return math.inf
    x0, x1 = math.log(mu0[i]), math.log(mu0[i + 1])
    frac = (sel[i] - prob) / (sel[i] - sel[i + 1])
    return math.exp(x0 + frac * (x1 - x0))


def reliable_range(
    mu0: ArrayLike, relative_stderr: ArrayLike, level: float
) -> tuple[float, float] | None:
    """Return the range of mu0 where the predicted relative error stays below ``level``.

    Parameters
    ----------
    mu0 : array_like
        Increasing grid.
    relative_stderr : array_like
        Predicted se(mu0) / mu0 on the grid (`Measurability`).
    level : float
        Largest relative error for which the Cramer-Rao bound is taken as reached (the
        fit is then locally linear; config ``fig8_measurability.reliable_relative_error``).

    Returns
    -------
    (low, high) or None
        The longest run of grid points below ``level``, its ends interpolated linearly in
        (ln mu0, ln relative error) to the crossings (a grid end if no crossing); None if
        no grid point is below ``level``.
    """
    x = np.log(_validate.positive("mu0", mu0).ravel())
    y = np.log(_validate.positive("relative_stderr", relative_stderr).ravel())
    target = math.log(_validate.positive_scalar("level", level))
    below = y < target
    if not below.any():
        return None
    runs, start = [], None
    for i, b in enumerate(below):
        if b and start is None:
            start = i
        if (not b or i == below.size - 1) and start is not None:
            runs.append((start, i if b else i - 1))
            start = None
    i0, i1 = max(runs, key=lambda r: r[1] - r[0])

    def cross(i: int, j: int) -> float:
        frac = (target - y[i]) / (y[j] - y[i])
        return math.exp(x[i] + frac * (x[j] - x[i]))

    low = cross(i0 - 1, i0) if i0 > 0 else math.exp(x[0])
    high = cross(i1, i1 + 1) if i1 < x.size - 1 else math.exp(x[-1])
    return low, high


def measurability_json(
    table: Measurability, probability: float, rig: Any, reliable_level: float | None = None
) -> dict[str, Any]:
    """Return `measurability` results as a JSON object (lists), with the set-up, the
    `indistinguishable_above` value for ``probability`` and, with ``reliable_level``, the
    `reliable_range` of mu0 where the predicted relative error is below it.

    ``rig`` is a `turntable.film.Rig` (set-up, camera, start state, mass).
    """
    limit = indistinguishable_above(table, probability)
    out = {
        "setup": {
            "radius_m": rig.setup.radius,
            "omega_rad_s": rig.setup.omega,
            "k": rig.setup.k,
            "fps": rig.camera.fps,
            "noise_m": rig.camera.noise,
            "duration_s": rig.camera.duration,
            "state0": [float(v) for v in rig.state0],
        },
        "selection_probability": float(probability),
        "indistinguishable_above_mu0": limit if math.isfinite(limit) else None,
        "table": {name: [float(v) for v in getattr(table, name)] for name in table._fields},
    }
    if reliable_level is not None:
        span = reliable_range(table.mu0, table.mu0_stderr / table.mu0, reliable_level)
        out["reliable_relative_error"] = float(reliable_level)
        out["reliable_mu0_range"] = list(span) if span is not None else None
    return out
