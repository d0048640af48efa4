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

Start values come from the data alone.  For a fixed coefficient both models are linear in
their amplitudes: in complex form (r = x + i y)

    slipping:  r(tau) = r_c + A e^{lambda_+ tau} + B e^{lambda_- tau}   (2.7)
    rolling:   r(tau) = A_g e^{lambda_g tau} + A_c e^{lambda_c tau}

(lambda_+- = alpha1 + i beta, alpha2 - i beta of (2.5)-(2.6); lambda_g, lambda_c of
`turntable.rolling`), so on a log grid of the coefficient the amplitudes are a linear least
squares problem (variable projection).  The best grid point, refined by a bounded scalar
search, gives the coefficient and, from the amplitudes, the initial state.

Standard errors come from the Jacobian J at the optimum and the residual variance
s^2 = RSS / (N - p) (N = 2n coordinates, p parameters), with the initial state as
nuisance parameters: se(ln c) = s / |(I - P) j_c|, j_c the column of ln c and P the
projection on the columns of the state; se(c) = c se(ln c) (delta method).  The same
formula with the camera's noise instead of s, at the true parameters, is the Cramer-Rao
bound that `predicted_stderr` returns: the Fisher information J^T J / sigma^2 over the
frames, reduced to the coefficient.

The models are compared by Akaike's information criterion
AIC = N ln(RSS / N) + 2 (p + 1) (Gaussian noise of unknown variance, the + 1), reported
with the difference and the Akaike weights.  `distinguishability` predicts, for a
slipping ball, how far the best rolling trajectory stays from it and hence the expected
AIC difference and the probability that the slipping model is selected.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import least_squares, minimize_scalar

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


def _check_model(model: str) -> str:
    if model not in MODELS:
        raise ValueError(f"model must be one of {MODELS}; got {model!r}")
    return model


def n_parameters(model: str) -> int:
    """Return the number of fitted parameters of ``model``: the initial state and ln c."""
    return N_STATE[_check_model(model)] + 1


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


# --------------------------------------------------------------------------- the Jacobian
def _jacobian(
    model: str, c: float, p: NDArray[np.float64], tau: NDArray[np.float64], k: float
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Columns of d r / d p (state, exact) and d r / d ln c (central difference), (2n, .).

    The solution is linear in the initial state, so column j is the solution from the
    j-th unit vector of the parameters.
    """
    ns = N_STATE[model]
    j_state = np.empty((2 * tau.size, ns))
    for j in range(ns):
        e = np.zeros(ns)
        e[j] = 1.0
        j_state[:, j] = _solve(model, _full_state(model, e), tau, c, k)[:, :2].ravel()
    z0 = _full_state(model, p)
    up = _solve(model, z0, tau, c * math.exp(LOG_STEP), k)[:, :2]
    down = _solve(model, z0, tau, c * math.exp(-LOG_STEP), k)[:, :2]
    return j_state, ((up - down) / (2.0 * LOG_STEP)).ravel()


def _log_stderr(j_state: NDArray[np.float64], j_c: NDArray[np.float64], sigma: float) -> float:
    """se of ln c with the state as nuisance: sigma / |(I - P) j_c| (see module docstring)."""
    coef, *_ = np.linalg.lstsq(j_state, j_c, rcond=None)
    norm = float(np.linalg.norm(j_c - j_state @ coef))
    return sigma / norm if norm > 0 else math.inf


# --------------------------------------------------------------------------- start values
def _rates(model: str, c: NDArray[np.float64], k: float) -> NDArray[np.complex128]:
    """The two rates of each coefficient c, shape c.shape + (2,): growing, then the other."""
    if model == "slipping":
        s = spectrum(c, k)
        return np.stack([s.alpha1 + 1j * s.beta, s.alpha2 - 1j * s.beta], axis=-1)
    return rolling.eigenvalues(c, k)[..., [0, 2]]


def _basis(
    model: str, c: NDArray[np.float64], tau: NDArray[np.float64], k: float
) -> tuple[NDArray[np.complex128], NDArray[np.complex128], NDArray[np.float64]]:
    """Columns of the amplitudes for each coefficient c: shape c.shape + (n, m).

    Each exponential e^{lambda tau} is scaled to at most 1 on the film: it is written
    e^{lambda (tau - ref)} with ref the last time for the growing one, 0 otherwise, so
    that nothing overflows.  Returns the columns, the rates and the refs.
    """
    rates = _rates(model, c, k)
    refs = np.where(rates.real > 0, tau[-1], 0.0)
    with np.errstate(under="ignore"):
        cols = np.exp(rates[..., None, :] * (tau[:, None] - refs[..., None, :]))
    if model == "slipping":
        cols = np.concatenate([np.ones((*cols.shape[:-1], 1), dtype=complex), cols], axis=-1)
    return cols, rates, refs


def _residual_sums(
    model: str,
    c: NDArray[np.float64],
    tau: NDArray[np.float64],
    r: NDArray[np.complex128],
    k: float,
) -> NDArray[np.float64]:
    """Residual sum of squares of the best amplitudes, for each coefficient of c.

    The residual is r minus its projection Q Q^H r on the columns (Householder QR of
    each stack, stable also where the columns nearly coincide).
    """
    cols, _, _ = _basis(model, c, tau, k)
    q, _ = np.linalg.qr(cols)
    coef = np.conj(np.swapaxes(q, -1, -2)) @ r
    res = r - (q @ coef[..., None])[..., 0]
    return np.sum(np.abs(res) ** 2, axis=-1)


def _initial_state(
    model: str, c: float, tau: NDArray[np.float64], r: NDArray[np.complex128], k: float
) -> NDArray[np.float64]:
    """Initial state of the best amplitudes for coefficient c (module docstring)."""
    cols, rates, refs = _basis(model, np.float64(c), tau, k)
    a, *_ = np.linalg.lstsq(cols, r, rcond=None)
    with np.errstate(under="ignore"):
        amp = a[-2:] * np.exp(-rates * refs)
    r0, v0 = amp.sum(), rates @ amp
    if model == "slipping":
        r0 += a[0]
        w0 = a[0] - 1j * v0 / k
        return np.array([r0.real, r0.imag, v0.real, v0.imag, w0.real, w0.imag])
    return np.array([r0.real, r0.imag, v0.real, v0.imag])


def start_values(
    model: str, tau: NDArray[np.float64], xy: NDArray[np.float64], k: float
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

    Returns
    -------
    coefficient : float
    state : numpy.ndarray
        The initial state (6 numbers, or (x, y, vx, vy) for the rolling model).

    Notes
    -----
    Variable projection (module docstring): the residual of the best amplitudes on a
    grid of `GRID_PER_DECADE` points per decade over `BOUNDS`, then a bounded search
    (Brent) in ln c between the neighbours of the best grid point; on a subset of the
    frames (`START_FRAMES`, `START_STEP`), which is plenty for a start.
    """
    lo, hi = (math.log(b) for b in BOUNDS[model])
    grid = np.linspace(lo, hi, round((hi - lo) / math.log(10.0) * GRID_PER_DECADE) + 1)
    # Every stride-th frame, so that at most START_FRAMES remain, but never more than
    # START_STEP apart in tau (both models turn at a rate below 1, so no aliasing).
    step = float(np.median(np.diff(tau))) if tau.size > 1 else 1.0
    stride = max(1, min(math.ceil(tau.size / START_FRAMES), math.floor(START_STEP / step)))
    keep = np.unique(np.append(np.arange(0, tau.size, stride), tau.size - 1))
    tau, r = tau[keep], xy[keep, 0] + 1j * xy[keep, 1]
    rss = _residual_sums(model, np.exp(grid), tau, r, k)
    i = int(np.argmin(rss))
    a, b = grid[max(i - 1, 0)], grid[min(i + 1, grid.size - 1)]
    res = minimize_scalar(
        lambda g: float(_residual_sums(model, np.exp(np.float64(g)), tau, r, k)),
        bounds=(a, b),
        method="bounded",
        options={"xatol": 1e-6},
    )
    g = float(res.x) if res.fun <= rss[i] else float(grid[i])
    c = math.exp(g)
    return c, _initial_state(model, c, tau, r, k)


# --------------------------------------------------------------------------- fitting
class ModelFit(NamedTuple):
    """The fit of one model to a film.

    Attributes
    ----------
    model : str
        "slipping" or "rolling_resistance".
    coefficient, stderr : float
        The dimensionless coefficient (mu0 or delta) and its standard error.
    log_stderr : float
        Standard error of ln coefficient (the relative standard error).
    state0 : numpy.ndarray
        Dimensionless state (x, y, vx, vy, wx, wy) at the first frame t0.
    t0 : float
        Time of the first frame, s.
    rss : float
        Residual sum of squares, m^2.
    rms_residual : float
        sqrt(RSS / N), m: the rms residual per coordinate (N = 2n coordinates).
    aic : float
        N ln(RSS / N) + 2 (p + 1).
    n_parameters, n_observations : int
        p and N.
    converged : bool
        Whether `scipy.optimize.least_squares` met a convergence criterion.
    at_bound : bool
        Whether the coefficient ended at an end of `BOUNDS`.
    residuals : numpy.ndarray
        Data minus fit, m, shape (n, 2).
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


def fit_model(film: Film, setup: Setup, model: str) -> ModelFit:
    """Fit one model to a film by nonlinear least squares on its exact solution.

    Parameters
    ----------
    film : Film
        Tracked positions in the lab frame (SI units).
    setup : Setup
        Ball radius, turntable rate, inertia ratio and axis position.
    model : {"slipping", "rolling_resistance"}

    Returns
    -------
    ModelFit

    Raises
    ------
    ValueError
        If the film has no more coordinates 2 n than parameters p, or bad numbers.

    Notes
    -----
    Residuals R (r(tau_i) - r_i) in m, r from `turntable.solve` (2.7) or
    `turntable.rolling.solve`; parameters the initial state and ln c (module docstring).
    A trial point at which the solution would overflow a double over the film
    (`turntable.max_time`, relevant only for very long films) gets a huge residual, so the
    optimiser steps back.
    """
    _check_model(model)
    setup = check_setup(setup)
    tau, xy = _dimensionless(film, setup)
    n_obs, p = 2 * tau.size, n_parameters(model)
    if n_obs <= p:
        raise ValueError(
            f"{tau.size} frames give {n_obs} coordinates; the {model} model has {p} "
            f"parameters, so at least {p // 2 + 1} frames are needed"
        )
    k, scale = setup.k, setup.radius
    data = xy.ravel()

    lo, hi = (math.log(b) for b in BOUNDS[model])

    def coefficient(theta: NDArray[np.float64]) -> float:
        return math.exp(min(max(theta[-1], lo), hi))

    def residuals(theta: NDArray[np.float64]) -> NDArray[np.float64]:
        c, z0 = coefficient(theta), _full_state(model, theta[:-1])
        if model == "slipping" and tau[-1] > max_time(c, k, z0):
            return np.full(n_obs, _OVERFLOW_RESIDUAL)
        try:
            z = _solve(model, z0, tau, c, k)
        except ValueError:  # the rolling model's growing mode overflows
            return np.full(n_obs, _OVERFLOW_RESIDUAL)
        return scale * (z[:, :2].ravel() - data)

    def jacobian(theta: NDArray[np.float64]) -> NDArray[np.float64]:
        j_state, j_c = _jacobian(model, coefficient(theta), theta[:-1], tau, k)
        inside = lo < theta[-1] < hi
        return scale * np.column_stack([j_state, j_c if inside else np.zeros_like(j_c)])

    c0, s0 = start_values(model, tau, xy, k)
    # Levenberg-Marquardt (MINPACK): its own small QR, no multithreaded LAPACK call per
    # step, which on a busy machine costs far more than the arithmetic.  Beyond BOUNDS
    # the coefficient is held at the bound (zero derivative), where the fit then stops.
    res = least_squares(
        residuals,
        np.append(s0, math.log(c0)),
        jac=jacobian,
        method="lm",
        x_scale="jac",
        ftol=1e-12,
        xtol=1e-12,
        gtol=1e-12,
        max_nfev=400,
    )
    theta = res.x
    theta[-1] = min(max(theta[-1], lo), hi)
    c = math.exp(theta[-1])
    r = residuals(theta)
    rss = float(r @ r)
    sigma = math.sqrt(rss / (n_obs - p))
    j_state, j_c = _jacobian(model, c, theta[:-1], tau, k)
    log_se = _log_stderr(scale * j_state, scale * j_c, sigma)
    return ModelFit(
        model=model,
        coefficient=c,
        stderr=c * log_se,
        log_stderr=log_se,
        state0=_full_state(model, theta[:-1]),
        t0=float(film.t[0]),
        rss=rss,
        rms_residual=math.sqrt(rss / n_obs),
        aic=aic(rss, n_obs, p),
        n_parameters=p,
        n_observations=n_obs,
        converged=bool(res.status > 0),
        at_bound=bool(min(theta[-1] - lo, hi - theta[-1]) < 1e-6),
        residuals=-r.reshape(-1, 2),
    )


class FilmFit(NamedTuple):
    """Both models fitted to one film, and the selection.

    Attributes
    ----------
    fits : dict
        {model: ModelFit}, in the order of `MODELS`.
    selected : str
        The model of smaller AIC.
    aic_difference : float
        AIC of the other model minus AIC of the selected one (>= 0).
    akaike_weights : dict
        {model: exp(-Delta_i / 2) / sum_j exp(-Delta_j / 2)}, Delta_i = AIC_i - min AIC.
    """

    fits: dict[str, ModelFit]
    selected: str
    aic_difference: float
    akaike_weights: dict[str, float]


def fit_film(film: Film, setup: Setup) -> FilmFit:
    """Fit both models to a film and select one by AIC (see `fit_model`, `FilmFit`).

    Notes
    -----
    Akaike weights: w_i = exp(-Delta_i / 2) / sum_j exp(-Delta_j / 2), the relative
    likelihood of each model given the data; AIC differences above 10 are usually read
    as decisive.
    """
    fits = {model: fit_model(film, setup, model) for model in MODELS}
    aics = {m: f.aic for m, f in fits.items()}
    best = min(aics, key=aics.__getitem__)
    rel = {m: math.exp(-(a - aics[best]) / 2.0) for m, a in aics.items()}
    total = sum(rel.values())
    other = max(aics.values()) - aics[best]
    return FilmFit(fits, best, other, {m: w / total for m, w in rel.items()})


def result_json(
    result: FilmFit, setup: Setup, film: Film, mass: float | None = None, source: str = ""
) -> dict[str, Any]:
    """Return the fit as the JSON object that ``turntable fit`` prints.

    Parameters
    ----------
    result : FilmFit
    setup : Setup
    film : Film
    mass : float, optional
        Mass of the ball in kg; adds the dimensional coefficients
        mu0_dim = mu0 m Omega (kg/s, force per slip velocity) and
        delta_dim = delta m R^2 Omega (kg m^2/s, torque per angular velocity).
    source : str
        Name of the data file.
    """
    setup = check_setup(setup)
    out: dict[str, Any] = {
        "selected": result.selected,
        "selection": {
            "criterion": "AIC = N ln(RSS/N) + 2 (p + 1)",
            "aic_difference": result.aic_difference,
            "akaike_weights": result.akaike_weights,
        },
    }
    for model, f in result.fits.items():
        name = COEFFICIENT[model]
        entry: dict[str, Any] = {
            name: f.coefficient,
            f"{name}_stderr": f.stderr,
            f"{name}_relative_stderr": f.log_stderr,
            "rms_residual_m": f.rms_residual,
            "aic": f.aic,
            "n_parameters": f.n_parameters,
            "state0": [float(v) for v in f.state0],
            "converged": f.converged,
            "at_bound": f.at_bound,
        }
        if mass is not None:
            m = _validate.positive_scalar("mass", mass)
            factor = m * setup.omega * (1.0 if model == "slipping" else setup.radius**2)
            unit = "kg_per_s" if model == "slipping" else "kg_m2_per_s"
            entry[f"{name}_dim_{unit}"] = f.coefficient * factor
            entry[f"{name}_dim_stderr_{unit}"] = f.stderr * factor
        out[model] = entry
    out["data"] = {
        "file": source,
        "n_frames": int(film.t.size),
        "n_observations": 2 * int(film.t.size),
        "t0_s": float(film.t[0]),
        "duration_s": float(film.t[-1] - film.t[0]),
        "turns": float(setup.omega * (film.t[-1] - film.t[0]) / (2.0 * math.pi)),
    }
    out["setup"] = {
        "radius_m": setup.radius,
        "omega_rad_s": setup.omega,
        "k": setup.k,
        "axis_m": list(setup.axis),
        **({"mass_kg": float(mass)} if mass is not None else {}),
    }
    out["units"] = {
        "mu0": "mu0_dim / (m Omega), dimensionless",
        "delta": "delta_dim / (m R^2 Omega), dimensionless",
        "state0": (
            "dimensionless state (x, y, vx, vy, wx, wy) at t0_s: position relative to the "
            "axis in units of R, velocity in units of R Omega, spin in units of Omega"
        ),
        "stderr": "from the Jacobian at the optimum and the residual variance RSS/(N - p)",
    }
    return out


# --------------------------------------------------------------------------- design
def _truth_jacobian(
    model: str, coefficient: float, state0: ArrayLike, setup: Setup, camera: Camera
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    _check_model(model)
    setup = check_setup(setup)
    c = _validate.positive_scalar(COEFFICIENT[model], coefficient)
    z0 = _validate.state("state0", state0)
    tau = setup.omega * frame_times(camera)
    p = _state_parameters(model, z0)
    if model == "rolling_resistance":
        # validates the constraint (ValueError naming the slip)
        rolling.solve(z0, tau[:1], c, setup.k)
    j_state, j_c = _jacobian(model, c, p, tau, setup.k)
    return tau, setup.radius * j_state, setup.radius * j_c


def predicted_stderr(
    model: str, coefficient: float, state0: ArrayLike, setup: Setup, camera: Camera
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

    Returns
    -------
    float
        se(c); the relative error is se(c) / c.

    Notes
    -----
    Fisher information F = J^T J / sigma^2 over the frames, J the derivatives of the
    positions (m) with respect to the initial state and ln c at the truth; the state is
    a nuisance, so var(ln c) = [F^-1]_cc = sigma^2 / |(I - P) j_c|^2 (module docstring),
    and se(c) = c sqrt(var(ln c)).  It is what `fit_model` reports, on average, for
    films of this camera.
    """
    noise = _validate.positive_scalar("noise", camera.noise)
    _, j_state, j_c = _truth_jacobian(model, coefficient, state0, setup, camera)
    return float(coefficient) * _log_stderr(j_state, j_c, noise)


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
    expected_aic_difference : float
        Expected AIC(rolling) - AIC(slipping), about lambda - (p_slipping - p_rolling)
        for lambda much smaller than the number of coordinates.
    selection_probability : float
        Probability that AIC selects the slipping model.
    """

    delta: float
    rms_distance: float
    noncentrality: float
    expected_aic_difference: float
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

    Notes
    -----
    The noiseless film of the slipping ball is fitted with the rolling model
    (`fit_model`); lambda = RSS_min / sigma^2.  With noise, and both models linearised
    about their fits, RSS_s = sigma^2 chi^2_{N - p_s} and RSS_r = RSS_s + sigma^2 X with X
    independent of RSS_s, a noncentral chi-square with q = p_s - p_r = 2 degrees of
    freedom and noncentrality lambda (the rolling fit also absorbs part of the noise).
    Then AIC_r - AIC_s = N ln(1 + X sigma^2 / RSS_s) - 2 q, whose mean is about
    N ln((N - p_r + lambda) / (N - p_s)) - 2 q (= lambda - q for lambda << N), and the
    slipping model is selected when (X / q) / (RSS_s / (N - p_s)), a noncentral F
    variable, exceeds (e^{2 q / N} - 1)(N - p_s) / q: probability about
    P(chi'^2_q(lambda) > 2 q) for many frames (e^-2 = 0.14 at lambda = 0, when the two
    motions coincide).  Valid while the fits are locally linear.
    """
    from scipy.stats import ncf

    setup = check_setup(setup)
    noise = _validate.positive_scalar("noise", camera.noise)
    t = frame_times(camera)
    xy = positions("slipping", mu0, state0, t, setup)
    fit = fit_model(Film(t, xy[:, 0], xy[:, 1]), setup, "rolling_resistance")
    p_s, p_r = n_parameters("slipping"), n_parameters("rolling_resistance")
    q, n = p_s - p_r, fit.n_observations
    lam = fit.rss / noise**2
    threshold = math.expm1(2.0 * q / n) * (n - p_s) / q
    return Distinguishability(
        delta=fit.coefficient,
        rms_distance=fit.rms_residual,
        noncentrality=lam,
        expected_aic_difference=n * math.log((n - p_r + lam) / (n - p_s)) - 2.0 * q,
        selection_probability=float(ncf.sf(threshold, q, n - p_s, lam)),
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
    closest_delta, rms_distance, expected_aic_difference, selection_probability
        `Distinguishability` of each slipping ball from the closest rolling motion.
    """

    mu0: NDArray[np.float64]
    mu0_stderr: NDArray[np.float64]
    delta_stderr: NDArray[np.float64]
    closest_delta: NDArray[np.float64]
    rms_distance: NDArray[np.float64]
    expected_aic_difference: NDArray[np.float64]
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
                d.expected_aic_difference,
                d.selection_probability,
            )
        )
    cols = np.array(rows).T
    return Measurability(mu0, *cols)


# --------------------------------------------------------------------------- reading results
def setup_from_json(result: dict[str, Any]) -> Setup:
    """Return the `Setup` recorded in a result of `result_json` (``turntable fit``)."""
    s = result["setup"]
    return check_setup(Setup(s["radius_m"], s["omega_rad_s"], s["k"], tuple(s["axis_m"])))


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
        Shape (len(t), 2), from `positions` with the fitted coefficient and state0.
    """
    entry = result[_check_model(model)]
    return positions(
        model,
        entry[COEFFICIENT[model]],
        entry["state0"],
        t,
        setup_from_json(result),
        result["data"]["t0_s"],
    )


def indistinguishable_above(table: Measurability, probability: float) -> float:
    """Return the mu0 above which AIC selects the slipping model less often than ``probability``.

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


def measurability_json(table: Measurability, probability: float, rig: Any) -> dict[str, Any]:
    """Return `measurability` results as a JSON object (lists), with the set-up and the
    `indistinguishable_above` value for ``probability``.

    ``rig`` is a `turntable.film.Rig` (set-up, camera, start state, mass).
    """
    limit = indistinguishable_above(table, probability)
    return {
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
