r"""What a fit returns, and the criteria that compare and judge fits.

The models are compared by the small-sample corrected Akaike criterion
AICc = N ln(RSS / N) + 2 K + 2 K (K + 1) / (N - K - 1), K = p + 1 (Gaussian noise of
unknown variance, the + 1), reported with the difference and the Akaike weights; a
difference below `DECISIVE` is not decisive.  Whether a model fits to the noise level is
told by the lag-1 autocorrelation of its residuals (`whiteness`): white noise gives about
0 with a spread of 1 / sqrt(number of pairs); a wrong :math:`\Omega`, k, axis or sign of y leaves
smooth structure and a large positive value.
"""

from __future__ import annotations

import math
from statistics import NormalDist
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

#: Two-sided 95 % quantile of the normal distribution (the ``*_ci95`` intervals).
Z95 = NormalDist().inv_cdf(0.975)
#: AICc differences of at least this much are decisive (Burnham and Anderson: above 10,
#: essentially no support for the other model).
DECISIVE = 10.0
#: A video's selection is decisive where its AICc difference, less this many of its standard
#: errors from the camera's calibration, is still decisive: as the coefficients' error bars
#: are read (``turntable.video.uncertainty``).
SELECTION_Z = 2.0
#: Residuals count as not white when their lag-1 autocorrelation exceeds this many times
#: its spread :math:`1 / \sqrt{\mathrm{pairs}}` for white noise (false alarm about 3e-5 for white
#: noise).
WHITENESS_Z = 4.0
#: Correlated residuals whose rms is more than this many times the film's frame-to-frame
#: noise (`frame_noise`) mean that the model does not describe the film; a tracker's
#: correlated errors stay below (at most 1.9 times on 30 rendered videos).  A small misfit
#: can too (a rate 0.4 % off: 1.3 times): the check with :math:`\Omega` free catches that one.
NOISE_FACTOR = 3.0


class ModelFit(NamedTuple):
    r"""The fit of one model to a film.

    Attributes
    ----------
    model : str
        "slipping" or "rolling_resistance".
    coefficient, stderr : float
        The dimensionless coefficient (:math:`\mu_0` or :math:`\delta`) and its standard error.  At
        a bound (``bound`` not None) the coefficient is where the search stopped, not a measurement.
    log_stderr : float
        Standard error of the coefficient's logarithm (the relative standard error).
    state0 : numpy.ndarray
        Dimensionless state (x, y, vx, vy, wx, wy) at the first frame t0 (relative to
        ``axis``, velocities in units of :math:`R \Omega`).
    t0 : float
        Time of the first frame, s.
    rss : float
        Residual sum of squares, m².
    rms_residual : float
        :math:`\sqrt{\mathrm{RSS}/N}`, m: the rms residual per coordinate (N = 2n coordinates).
    aic : float
        :math:`N \ln(\mathrm{RSS} / N) + 2K`, :math:`K = p + 1`.
    aicc : float
        :math:`\mathrm{AIC} + 2K (K + 1) / (N - K - 1)`; inf if :math:`N \le K + 1`.
    n_parameters, n_observations : int
        :math:`p` and :math:`N`.
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
        at the lower one, ``_limit``); nan otherwise.
    omega, omega_stderr : float
        :math:`\Omega` (rad/s) of the fit: the given one, or the fitted one with its standard error
        (nan when given).
    omega_at_bound : bool
        With ``fit_omega``: :math:`\Omega` ran into its search range (factor `OMEGA_FACTOR`).
    axis, axis_stderr : tuple of float
        Position of the axis (m): the given one, or the fitted one (rolling model with
        ``fit_axis``) with its standard errors (nan when given).
    autocorrelation, autocorrelation_sd : float
        Lag-1 autocorrelation of the residuals and its spread for white noise (`whiteness`).
    orbital_rate : float
        Angular rate of the growing mode (:math:`\beta`, or :math:`\operatorname{Im}\lambda_g`)
        in units of :math:`\Omega`: the ball turns about its spiral centre
        :math:`\text{orbital\_rate}\; \Omega T / (2\pi)` times in a film of length T.
    exact : bool
        Whether the fit reproduces the positions to rounding (`EXACT_FIT`): then there is no
        noise, the residuals count as white, and AICc cannot weigh it against another
        exact fit.
    noise : float
        The film's frame-to-frame noise per coordinate, m (`frame_noise`).

    Examples
    --------
    >>> from turntable import fit
    >>> from turntable.film import Camera, Setup, state_from_si
    >>> setup = Setup(radius=0.005, omega=3.5, k=0.4)
    >>> camera = Camera(fps=30.0, noise=2e-4, duration=2.0)
    >>> z0 = state_from_si([0.05, 0.0], [0.0, 0.0], [0.0, 0.0], setup)
    >>> film = fit.simulate_film("slipping", 3.0, z0, setup, camera, seed=1)
    >>> result = fit.fit_film(film, setup)
    >>> slipping = result.fits["slipping"]
    >>> print(f"{slipping.coefficient:.2f} ± {slipping.stderr:.2f}, "
    ...       f"rms {slipping.rms_residual * 1e3:.2f} mm")
    2.93 ± 0.28, rms 0.17 mm
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
    noise: float = math.nan

    @property
    def ci95(self) -> tuple[float, float]:
        r"""95 % interval :math:`e^{\ln c \mp 1.96\, \mathrm{se}(\ln c)}` of the coefficient
        (not at a bound)."""
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

    @property
    def noise_ratio(self) -> float:
        """The rms residual in units of the film's noise (inf for a film without noise)."""
        if self.noise > 0:
            return self.rms_residual / self.noise
        return math.inf if self.noise == 0 else math.nan

    @property
    def describes(self) -> bool:
        """Whether the model describes the film: white residuals, or correlated ones at
        most `NOISE_FACTOR` times the film's noise (``noise``)."""
        return self.white or self.noise_ratio <= NOISE_FACTOR


def aic(rss: float, n_observations: int, n_params: int) -> float:
    r"""Return Akaike's criterion :math:`N \ln(\mathrm{RSS}/N) + 2 (p + 1)` of a Gaussian
    least-squares fit.

    The + 1 counts the noise variance, estimated as RSS / N.  An exact fit (RSS = 0,
    only for noiseless data) counts as RSS = the smallest positive double.

    Parameters
    ----------
    rss : float
        Residual sum of squares, :math:`\ge 0`.
    n_observations : int
        Number N of fitted coordinates.
    n_params : int
        Number p of fitted parameters.

    Returns
    -------
    float
        The criterion.

    See Also
    --------
    turntable.fit.aicc : Corrected for a small sample.

    Examples
    --------
    >>> from turntable import fit
    >>> print(f"{fit.aic(rss=1e-6, n_observations=100, n_params=3):.2f}")
    -1834.07
    """
    rss = max(float(rss), float(np.finfo(float).tiny))
    return n_observations * math.log(rss / n_observations) + 2.0 * (n_params + 1)


def aicc(rss: float, n_observations: int, n_params: int) -> float:
    r"""Return the small-sample corrected criterion
    :math:`\mathrm{AICc} = \mathrm{AIC} + 2K(K + 1)/(N - K - 1)`.

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
        model; inf when :math:`N \le K + 1`, where it is undefined.

    See Also
    --------
    turntable.fit.aic : Uncorrected.

    Examples
    --------
    Above `aic` by 2 K (K + 1) / (N - K - 1), K = p + 1:

    >>> from turntable import fit
    >>> print(f"{fit.aicc(1e-6, 100, 3) - fit.aic(1e-6, 100, 3):.4f}")
    0.4211
    """
    k = n_params + 1
    if n_observations - k - 1 <= 0:
        return math.inf
    return aic(rss, n_observations, n_params) + 2.0 * k * (k + 1) / (n_observations - k - 1)


def whiteness(residuals: ArrayLike) -> tuple[float, float]:
    r"""Return the lag-1 autocorrelation of residuals and its spread for white noise.

    Parameters
    ----------
    residuals : array_like
        Shape (n, 2): data minus fit of each coordinate at each frame, in frame order.

    Returns
    -------
    rho : float
        :math:`\sum_c \sum_i e_{i,c} e_{i+1,c} / \sum_c \sum_i e_{i,c}^2`, pooled over the
        two coordinates (0 for residuals that are all 0).
    sd : float
        :math:`1 / \sqrt{2 (n - 1)}`, the standard deviation of rho for independent noise
        (the Durbin-Watson statistic is about :math:`2 (1 - \rho)`).

    Notes
    -----
    The residual of the right model is the tracking noise, independent from frame to
    frame: rho scatters about 0 by sd.  A model that misses the motion (a wrong :math:`\Omega`, k,
    axis or sense of rotation, or the wrong mechanism) leaves a smooth error, correlated
    from one frame to the next: rho approaches the share of that error in the residual
    variance, many times sd.

    Examples
    --------
    White noise has a lag-1 autocorrelation within a few times its spread of 0:

    >>> import numpy as np
    >>> from turntable import fit
    >>> r, sd = fit.whiteness(np.random.default_rng(0).normal(size=(500, 2)))
    >>> bool(abs(r) < 3 * sd)
    True
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


def frame_noise(t: ArrayLike, xy: ArrayLike) -> float:
    r"""Return the noise per coordinate of tracked positions, from their third differences.

    Parameters
    ----------
    t : array_like
        Frame times, increasing (any unit).
    xy : array_like
        Shape (n, 2): the positions at those times.

    Returns
    -------
    float
        :math:`\sqrt{\operatorname{median}(e^2) / m_1}` over both coordinates, e the third
        divided differences of four consecutive frames divided by the root of the sum of
        their squared weights; nan for fewer than 4 frames.

    Notes
    -----
    The third divided difference of frames i..i+3 is :math:`\sum_j w_j x_j`,
    :math:`w_j = 1 / \prod_{k \ne j} (t_j - t_k)`: it vanishes for a quadratic, so a motion
    smooth over four frames leaves little of it, while independent noise of variance
    :math:`s^2` gives it the variance :math:`s^2 \sum_j w_j^2` (for equal steps, the
    binomial 1, 3, 3, 1: :math:`20 s^2 / (6\, \Delta t^3)^2`).
    The frame times count as they are, so a variable frame rate (or a gap) is no noise.
    :math:`m_1 \approx 0.4549` is the median of chi-square with one degree of freedom
    (`scipy.special.chdtri`): the median keeps the few differences across a gap of lost
    frames from counting.  Noise correlated from frame to frame gives a smaller value: it
    is the noise that no smooth model can follow.

    Examples
    --------
    >>> import numpy as np
    >>> from turntable import fit
    >>> t = np.sort(np.random.default_rng(1).uniform(0.0, 2.0, 400))  # uneven steps
    >>> noise = np.random.default_rng(0).normal(0, 1e-3, (400, 2))
    >>> xy = np.c_[np.cos(t), np.sin(t)] + noise
    >>> print(f"{fit.frame_noise(t, xy):.1e}")
    1.0e-03
    """
    from scipy.special import chdtri

    t = np.asarray(t, dtype=float)
    xy = np.asarray(xy, dtype=float)
    n = t.size - 3
    if n < 1:
        return math.nan
    windows = np.stack([t[j : j + n] for j in range(4)], axis=1)
    w = np.ones((n, 4))
    for j in range(4):
        for k in range(4):
            if k != j:
                w[:, j] /= windows[:, j] - windows[:, k]
    w /= np.sqrt(np.sum(w**2, axis=1, keepdims=True))
    e = np.stack([sum(w[:, j, None] * xy[j : j + n] for j in range(4))])
    return math.sqrt(float(np.median(e**2)) / chdtri(1, 0.5))


class FilmFit(NamedTuple):
    r"""Both models fitted to one film, and the selection.

    Attributes
    ----------
    fits : dict
        {model: ModelFit}, in the order of `MODELS`.
    selected : str or None
        The model of smaller AICc; None when the film is too short to compare them
        (fewer than `MIN_DOF` coordinates left, see `min_frames`) or a fit failed.
    aicc_difference : float
        AICc of the other model minus AICc of the selected one (:math:`\ge 0`); nan if none.
    akaike_weights : dict
        {model: :math:`e^{-\Delta_i / 2} / \sum_j e^{-\Delta_j / 2}`},
        :math:`\Delta_i = \mathrm{AICc}_i - \min \mathrm{AICc}`
        (nan if an AICc is undefined).
    decisive : bool
        Whether a model is selected with an AICc difference of at least `DECISIVE` and
        fits the film at least as well as the other (a smaller or equal RSS); of a video,
        also with its camera's calibration moved (``turntable.video.uncertainty``).
    reason : str
        Why the selection is not decisive ("" if it is).

    Examples
    --------
    >>> from turntable import fit
    >>> from turntable.film import Camera, Setup, state_from_si
    >>> setup = Setup(radius=0.005, omega=3.5, k=0.4)
    >>> camera = Camera(fps=30.0, noise=2e-4, duration=2.0)
    >>> z0 = state_from_si([0.05, 0.0], [0.0, 0.0], [0.0, 0.0], setup)
    >>> film = fit.simulate_film("slipping", 3.0, z0, setup, camera, seed=1)
    >>> result = fit.fit_film(film, setup)
    >>> list(result.fits), result.selected
    (['slipping', 'rolling_resistance'], 'slipping')
    >>> print(f"Akaike weight of slipping {result.akaike_weights['slipping']:.3f}")
    Akaike weight of slipping 1.000
    """

    fits: dict[str, ModelFit]
    selected: str | None
    aicc_difference: float
    akaike_weights: dict[str, float]
    decisive: bool = True
    reason: str = ""
