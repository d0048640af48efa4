"""The predictions of `turntable.fit.design` at one friction: the standard error of a fit
(the Cramer-Rao bound) and how far a slipping ball stays from the closest rolling motion.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from turntable import _validate, rolling
from turntable._public import public_module
from turntable.film import Camera, Film, Setup, check_setup, frame_times
from turntable.fit.lsq import _least_squares
from turntable.fit.models import COEFFICIENT, MIN_DOF, min_frames, n_parameters, positions
from turntable.fit.parameters import _columns, _full_jacobian, _Layout, _layout, _stderr_of


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


@public_module("turntable.fit.design")
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
    r"""Return the standard error of the coefficient that a film can reach (Cramer-Rao).

    Parameters
    ----------
    model : {"slipping", "rolling_resistance"}
    coefficient : float
        True :math:`\mu_0` or :math:`\delta` (dimensionless).
    state0 : array_like
        True dimensionless state at the first frame (on the no-slip constraint for the
        rolling model; `turntable.no_slip_state` projects one there).
    setup : Setup
        Ball radius, turntable rate and inertia ratio.
    camera : Camera
        Frame rate, tracking noise (m per coordinate) and duration.
    fit_omega, fit_axis : bool
        Whether :math:`\Omega` (and, rolling, the axis) are fitted too, i.e. nuisance parameters.

    Returns
    -------
    float
        se(c); the relative error is se(c) / c.

    Raises
    ------
    ValueError
        For fewer coordinates than parameters, or bad numbers.

    See Also
    --------
    turntable.fit.measurability : Over a grid of frictions, with the selection.

    Notes
    -----
    Fisher information :math:`F = J^T J / \sigma^2` over the frames, J the derivatives of
    the positions (m) with respect to all parameters at the truth; the others are
    nuisances, so :math:`\operatorname{var}(\ln c) = [F^{-1}]_{cc} = \sigma^2 / |(I - P) j_c|^2`
    (P the projection on the other columns of J), and
    :math:`\operatorname{se}(c) = c \sqrt{\operatorname{var}(\ln c)}`.  It is what `fit_model`
    reports, on average, for films of this camera, as long as the fit is locally linear: for
    a predicted relative error above about 0.2 the estimates scatter more than this (Fig. 8).

    Examples
    --------
    >>> from turntable import fit
    >>> from turntable.film import Camera, Setup, state_from_si
    >>> setup = Setup(radius=0.005, omega=3.5, k=0.4)
    >>> camera = Camera(fps=30.0, noise=2e-4, duration=2.0)
    >>> z0 = state_from_si([0.05, 0.0], [0.0, 0.0], [0.0, 0.0], setup)
    >>> print(f"{fit.predicted_stderr('slipping', 3.0, z0, setup, camera):.2f}")
    0.33
    """
    noise = _validate.positive_scalar("noise", camera.noise)
    lay, jac = _truth_jacobian(model, coefficient, state0, setup, camera, fit_omega, fit_axis)
    return float(coefficient) * _stderr_of(jac, lay.i_c, noise)


@public_module("turntable.fit.design")
class Distinguishability(NamedTuple):
    r"""How well a film tells a slipping ball from one rolling without slipping.

    Attributes
    ----------
    delta : float
        Coefficient of the rolling motion closest to the noiseless slipping film.
    rms_distance : float
        rms distance per coordinate between the two, m.
    noncentrality : float
        :math:`\lambda` = (sum of squared distances over the frames) / noise².
    expected_aicc_difference : float
        Expected AICc(rolling) - AICc(slipping), about
        :math:`\lambda - (p_\text{slipping} - p_\text{rolling})` for :math:`\lambda` much
        smaller than the number of coordinates.
    selection_probability : float
        Probability that AICc selects the slipping model.

    Examples
    --------
    >>> from turntable import fit
    >>> from turntable.film import Camera, Setup, state_from_si
    >>> setup = Setup(radius=0.005, omega=3.5, k=0.4)
    >>> camera = Camera(fps=30.0, noise=2e-4, duration=2.0)
    >>> z0 = state_from_si([0.05, 0.0], [0.0, 0.0], [0.0, 0.0], setup)
    >>> d = fit.distinguishability(3.0, z0, setup, camera)
    >>> print(f"{d.rms_distance * 1e3:.2f} mm apart, "
    ...       f"expected AICc difference {d.expected_aicc_difference:.0f}")
    0.12 mm apart, expected AICc difference 35
    """

    delta: float
    rms_distance: float
    noncentrality: float
    expected_aicc_difference: float
    selection_probability: float


@public_module("turntable.fit.design")
def distinguishability(
    mu0: float, state0: ArrayLike, setup: Setup, camera: Camera
) -> Distinguishability:
    r"""Return how well a film of a slipping ball rules out rolling without slipping.

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

    See Also
    --------
    turntable.fit.measurability : Over a grid of frictions.

    Notes
    -----
    The noiseless film of the slipping ball is fitted with the rolling model
    (`fit_model`); :math:`\lambda = \mathrm{RSS}_\text{min} / \sigma^2`.  With noise, and
    both models linearised about their fits, :math:`\mathrm{RSS}_s = \sigma^2 \chi^2_{N - p_s}`
    and :math:`\mathrm{RSS}_r = \mathrm{RSS}_s + \sigma^2 X` with X independent of
    :math:`\mathrm{RSS}_s`, a noncentral chi-square with :math:`q = p_s - p_r = 2` degrees
    of freedom and noncentrality :math:`\lambda` (the rolling fit also absorbs part of the
    noise). Then

    .. math::

        \mathrm{AICc}_r - \mathrm{AICc}_s = N \ln(1 + X \sigma^2 / \mathrm{RSS}_s) - D,
        \quad D = 2 q + \frac{2 K_s (K_s + 1)}{N - K_s - 1} - \frac{2 K_r (K_r + 1)}{N - K_r - 1}

    (:math:`K = p + 1`), whose mean is about
    :math:`N \ln((N - p_r + \lambda) / (N - p_s)) - D` (:math:`= \lambda - q` for
    :math:`\lambda \ll N` and many frames), and the slipping model is selected when
    :math:`(X / q) / (\mathrm{RSS}_s / (N - p_s))`, a noncentral F variable, exceeds
    :math:`(e^{D / N} - 1)(N - p_s) / q`: probability about
    :math:`P(\chi'^2_q(\lambda) > 2 q)` for many frames (:math:`e^{-2} = 0.14` at
    :math:`\lambda = 0`, when the two motions coincide).  Valid while the fits are locally
    linear.

    Examples
    --------
    >>> from turntable import fit
    >>> from turntable.film import Camera, Setup, state_from_si
    >>> setup = Setup(radius=0.005, omega=3.5, k=0.4)
    >>> camera = Camera(fps=30.0, noise=2e-4, duration=2.0)
    >>> z0 = state_from_si([0.05, 0.0], [0.0, 0.0], [0.0, 0.0], setup)
    >>> d = fit.distinguishability(3.0, z0, setup, camera)
    >>> print(f"delta {d.delta:.5f}, selection probability {d.selection_probability:.4f}")
    delta 0.00545, selection probability 1.0000
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
