"""The nonlinear least-squares fit of one model (`fit_model`) and of both (`fit_film`).

Standard errors come from the Jacobian J at the optimum and the residual variance
s^2 = RSS / (N - p) (N = 2n coordinates, p parameters).  Where the residuals are
correlated from frame to frame (`turntable.fit.whiteness`; a tracker's errors can be), the
larger of two estimates replaces it: that for AR(1) noise of the residuals' lag-1
autocorrelation rho, sqrt((1 + rho) / (1 - rho)) times it, exact for smooth columns of J;
and Newey-West's with 1.3 sqrt(n) lags (`turntable.fit.parameters`), which also holds for
longer memory but falls short on few informative frames (the scores of the fitted film sum
to zero).  Errors that drift slowly, as a tracker's do with where the ball is, can pass the
test of whiteness and are partly absorbed by the fit; the standard error is at least that for
white noise plus an exponentially correlated part, both fitted to the residuals' products
with the absorbed part accounted for (`turntable.fit.parameters.slow_noise`).
se(c) = c se(ln c) (delta method), and the 95 % interval exp(ln c +- 1.96 se(ln c)),
which stays positive and is the honest form when se(ln c) is not small.

A coefficient that ends at an end of `BOUNDS` is not a measurement: the film is then
consistent with every larger (or smaller) value, and `fit_model` gives instead a one-sided
95 % limit from the profile of the residual sum of squares,
RSS_profile(c) - RSS_min = z_0.95^2 s^2 (z_0.95 = 1.645).  With fewer than `MIN_DOF`
coordinates left (N - K - 1 for the larger model) no model is selected.
"""

from __future__ import annotations

import math
from statistics import NormalDist
from typing import Any

import numpy as np
from numpy.typing import NDArray

from turntable import _validate
from turntable.film import Film, Setup, check_setup
from turntable.fit.models import BOUNDS, MIN_DOF, MODELS, _solve, min_frames
from turntable.fit.parameters import (
    _columns,
    _full_jacobian,
    _hac_stderr_of,
    _Layout,
    _layout,
    _slow_stderr_of,
    _stderr_of,
    _unpack,
    newey_west_lags,
    slow_noise,
)
from turntable.fit.results import (
    DECISIVE,
    WHITENESS_Z,
    FilmFit,
    ModelFit,
    aic,
    aicc,
    frame_noise,
    whiteness,
)
from turntable.fit.start import _rates, start_values
from turntable.solution import max_time

#: With ``fit_omega``, :math:`\Omega` is searched within this factor of the given value.
OMEGA_FACTOR = 2.0
#: Residual of a trial point whose solution would overflow a double (see `max_time`).
_OVERFLOW_RESIDUAL = 1e100
#: One-sided 95 % quantile of the normal distribution (the limits at a bound).
Z95_ONE_SIDED = NormalDist().inv_cdf(0.95)
#: A fit whose rms residual is at most this fraction of the largest distance of the tracked
#: centre from the axis reproduces the positions to rounding: the film carries no noise by
#: which to weigh the fits (a noiseless film, or a ball at rest tracked to whole pixels).
EXACT_FIT = 1e-9


def _dimensionless(film: Film, setup: Setup) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    t = _validate.times("t", np.asarray(film.t) - film.t[0], increasing=True)
    xy = np.column_stack([film.x, film.y]) - np.asarray(setup.axis)
    if not np.all(np.isfinite(xy)) or xy.shape != (t.size, 2):
        raise ValueError("film.x and film.y must be finite and as long as film.t")
    return setup.omega * t, xy / setup.radius


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
        from scipy.optimize import least_squares

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
    from scipy.optimize import brentq

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
    r"""The least-squares fit of `fit_model`, without its standard errors and limits.

    Returns the problem, the optimiser's result, the parameters (:math:`\ln c` and
    :math:`\ln \Omega` held inside their ranges) and the residuals there (m).
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
    r"""Fit one model to a film by nonlinear least squares on its exact solution.

    Parameters
    ----------
    film : Film
        Tracked positions in the lab frame (SI units).
    setup : Setup
        Ball radius, turntable rate, inertia ratio and axis position.
    model : {"slipping", "rolling_resistance"}
    fit_omega : bool
        Fit :math:`\Omega` too (from ``setup.omega``, within a factor `OMEGA_FACTOR`).
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

    See Also
    --------
    turntable.fit.fit_film : Both models, and the selection.

    Notes
    -----
    Residuals :math:`R\,(r(\tau_i) + a - r_i)` in m, :math:`r` from `turntable.solve` (2.7) or
    `turntable.rolling.solve`, :math:`\tau_i = \Omega (t_i - t_0)`; parameters the initial
    state and :math:`\ln c`, and :math:`\ln \Omega`, :math:`a` if asked (module docstring).  A trial
    point at which the solution would overflow a double over the film (`turntable.max_time`,
    relevant only for very long films) gets a huge residual, so the optimiser steps back.  A
    coefficient at a bound of `BOUNDS` gets a one-sided 95 % limit (``_limit``).

    Examples
    --------
    >>> from turntable import fit
    >>> from turntable.film import Camera, Setup, state_from_si
    >>> setup = Setup(radius=0.005, omega=3.5, k=0.4)
    >>> camera = Camera(fps=30.0, noise=2e-4, duration=2.0)
    >>> z0 = state_from_si([0.05, 0.0], [0.0, 0.0], [0.0, 0.0], setup)
    >>> film = fit.simulate_film("slipping", 3.0, z0, setup, camera, seed=1)
    >>> result = fit.fit_model(film, setup, "slipping")
    >>> print(f"mu0 = {result.coefficient:.2f} +- {result.stderr:.2f}")
    mu0 = 2.93 +- 0.28
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
    residuals = -r.reshape(-1, 2)
    rho, rho_sd = whiteness(residuals)
    exact = rss <= fitter.rss_floor
    white = exact or not abs(rho / rho_sd) > WHITENESS_Z
    try:
        others, j_c = _columns(lay, c, s, z0, tau, setup.k)
        jac = setup.radius * _full_jacobian(others, j_c, lay)
        with np.errstate(all="ignore"):
            ses = [_stderr_of(jac, i, sigma) for i in range(p)]
            if not white:
                lags = newey_west_lags(tau.size)
                ar1 = math.sqrt((1 + rho) / (1 - rho)) if 0 < rho < 1 else 1.0
                ses = [max(ar1 * se, _hac_stderr_of(jac, i, r, lags)) for i, se in enumerate(ses)]
            if not exact:
                drift = slow_noise(jac, residuals)
                ses = [max(se, _slow_stderr_of(jac, i, drift)) for i, se in enumerate(ses)]
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
        exact=exact,
        noise=frame_noise(tau, fitter.data.reshape(-1, 2)) * setup.radius,
    )


def fit_film(
    film: Film, setup: Setup, *, fit_omega: bool = False, fit_axis: bool = False
) -> FilmFit:
    r"""Fit both models to a film and select one by AICc (see `fit_model`, `FilmFit`).

    Parameters
    ----------
    film : Film
    setup : Setup
    fit_omega, fit_axis : bool
        As in `fit_model`, for both models.

    Returns
    -------
    FilmFit

    See Also
    --------
    turntable.fit.fit_model : One model alone.
    turntable.fit.consistency : The fit again with the rate and the axis free.
    turntable.fit.simulate_film : A film to fit.

    Notes
    -----
    Akaike weights: :math:`w_i = e^{-\Delta_i / 2} / \sum_j e^{-\Delta_j / 2}`, the relative
    likelihood of each model given the data; AICc differences of `DECISIVE` (10) or more
    are read as decisive, provided the selected model also fits at least as well (its RSS
    is not larger): otherwise the difference is the penalty on the other model's extra
    parameters alone, which on a short film exceeds 10 by itself
    (:math:`2 q + \frac{2 K_s (K_s + 1)}{N - K_s - 1} - \frac{2 K_r (K_r + 1)}{N - K_r - 1} = 10.6`
    for 10 frames) and says nothing about the film.
    :math:`\mathrm{AICc} = \mathrm{AIC} + 2 K (K + 1) / (N - K - 1)` corrects AIC's overconfidence
    on short films; with N - K - 1 < `MIN_DOF` for the larger model no model is selected,
    because the comparison then rests on a handful of residual degrees of freedom (with
    AIC, 5-frame films selected the wrong model in half the cases, some of them with a
    difference above 10).

    Examples
    --------
    >>> from turntable import fit
    >>> from turntable.film import Camera, Setup, state_from_si
    >>> setup = Setup(radius=0.005, omega=3.5, k=0.4)
    >>> camera = Camera(fps=30.0, noise=2e-4, duration=2.0)
    >>> z0 = state_from_si([0.05, 0.0], [0.0, 0.0], [0.0, 0.0], setup)
    >>> film = fit.simulate_film("slipping", 3.0, z0, setup, camera, seed=1)
    >>> result = fit.fit_film(film, setup)
    >>> result.selected, result.decisive
    ('slipping', True)
    >>> mu0 = result.fits["slipping"].coefficient
    >>> print(f"mu0 = {mu0:.2f}, AICc difference {result.aicc_difference:.0f}")
    mu0 = 2.93, AICc difference 50
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
