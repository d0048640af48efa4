"""Design of an experiment: predicted standard errors, distinguishability, measurability.

`predicted_stderr` is the Cramer-Rao bound: the formula of the standard error with the
camera's noise instead of s, at the true parameters (the Fisher information
J^T J / sigma^2 over the frames, reduced to the coefficient).  It is reached only while the
fit is locally linear, i.e. while the relative error is small (about 0.2, Fig. 8).
`distinguishability` predicts, for a slipping ball, how far the best rolling trajectory
stays from it and hence the expected AICc difference and the probability that the slipping
model is selected.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from turntable import _validate, rolling
from turntable.film import Camera, Film, Setup, check_setup, frame_times
from turntable.fit.lsq import _least_squares
from turntable.fit.models import COEFFICIENT, MIN_DOF, min_frames, n_parameters, positions
from turntable.fit.parameters import _columns, _full_jacobian, _Layout, _layout, _stderr_of
from turntable.solution import no_slip_state


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


class Measurability(NamedTuple):
    r"""`measurability` over a grid of :math:`\mu_0` (1-D arrays of the grid's length).

    Attributes
    ----------
    mu0, mu0_stderr : numpy.ndarray
        The grid and the predicted standard error of :math:`\mu_0` for a slipping ball.
    delta_stderr : numpy.ndarray
        Predicted standard error of :math:`\delta` for a rolling ball with :math:`\delta`
        equal to the grid's value.
    closest_delta, rms_distance, expected_aicc_difference, selection_probability
        `Distinguishability` of each slipping ball from the closest rolling motion.

    Examples
    --------
    >>> from turntable import fit
    >>> from turntable.film import Camera, Setup, state_from_si
    >>> setup = Setup(radius=0.005, omega=3.5, k=0.4)
    >>> camera = Camera(fps=30.0, noise=2e-4, duration=2.0)
    >>> z0 = state_from_si([0.05, 0.0], [0.0, 0.0], [0.0, 0.0], setup)
    >>> table = fit.measurability([0.3, 3.0, 30.0], z0, setup, camera)
    >>> table.selection_probability.round(2)
    array([1.  , 1.  , 0.17])
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
    r"""Return what a camera can measure, for each :math:`\mu_0` of a grid.

    Parameters
    ----------
    mu0 : sequence of float
        Friction coefficients of the slipping ball.
    state0 : array_like
        Dimensionless state of the ball at the first frame, e.g. from
        `~turntable.film.state_from_si`.
        The rolling ball starts from its projection on the no-slip constraint
        (`turntable.no_slip_state`: same position and conserved quantities).
    setup, camera : Setup, Camera

    Returns
    -------
    Measurability
        For each :math:`\mu_0`: `predicted_stderr` of :math:`\mu_0`; for :math:`\delta`
        equal to it, the rolling ball's `predicted_stderr` of :math:`\delta`; and the
        `distinguishability` of the slipping ball from the closest rolling motion.

    See Also
    --------
    turntable.fit.predicted_stderr : The standard error at one friction.
    turntable.fit.distinguishability : Slipping against rolling at one friction.

    Examples
    --------
    >>> from turntable import fit
    >>> from turntable.film import Camera, Setup, state_from_si
    >>> setup = Setup(radius=0.005, omega=3.5, k=0.4)
    >>> camera = Camera(fps=30.0, noise=2e-4, duration=2.0)
    >>> z0 = state_from_si([0.05, 0.0], [0.0, 0.0], [0.0, 0.0], setup)
    >>> table = fit.measurability([0.3, 3.0, 30.0], z0, setup, camera)
    >>> (table.mu0_stderr / table.mu0).round(3)
    array([0.017, 0.111, 1.259])
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


def indistinguishable_above(table: Measurability, probability: float) -> float:
    r"""Return the :math:`\mu_0` above which AICc selects the slipping model less often than
    ``probability``.

    Parameters
    ----------
    table : Measurability
        From `measurability`, on an increasing grid of :math:`\mu_0`.
    probability : float
        Required probability of selecting the slipping model, in :math:`(e^{-2}, 1)`.

    Returns
    -------
    float
        The crossing of the selection probability with ``probability`` after the last
        grid point where it is at least ``probability``, interpolated linearly in
        :math:`\ln \mu_0`;
        inf if the last grid point is still above, the first grid value if none is.

    Examples
    --------
    >>> from turntable import fit
    >>> from turntable.film import Camera, Setup, state_from_si
    >>> setup = Setup(radius=0.005, omega=3.5, k=0.4)
    >>> camera = Camera(fps=30.0, noise=2e-4, duration=2.0)
    >>> z0 = state_from_si([0.05, 0.0], [0.0, 0.0], [0.0, 0.0], setup)
    >>> table = fit.measurability([0.3, 3.0, 30.0, 300.0], z0, setup, camera)
    >>> print(f"{fit.indistinguishable_above(table, 0.95):.2f}")
    3.45
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
    r"""Return the range of :math:`\mu_0` where the predicted relative error stays below ``level``.

    Parameters
    ----------
    mu0 : array_like
        Increasing grid.
    relative_stderr : array_like
        Predicted :math:`\mathrm{se}(\mu_0) / \mu_0` on the grid (`Measurability`).
    level : float
        Largest relative error for which the Cramer-Rao bound is taken as reached (the
        fit is then locally linear; config ``fig8_measurability.reliable_relative_error``).

    Returns
    -------
    (low, high) or None
        The longest run of grid points below ``level``, its ends interpolated linearly in
        (:math:`\ln \mu_0`, :math:`\ln` of the relative error) to the crossings (a grid end if no
        crossing); None if no grid point is below ``level``.

    Examples
    --------
    >>> from turntable import fit
    >>> low, high = fit.reliable_range([0.1, 1.0, 10.0, 100.0], [0.5, 0.1, 0.1, 0.5], 0.2)
    >>> print(f"{low:.3f} {high:.2f}")
    0.371 26.96
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
    `reliable_range` of ``mu0`` where the predicted relative error is below it.

    ``rig`` is a `turntable.film.Rig` (set-up, camera, start state, mass).

    Parameters
    ----------
    table : Measurability
        A table of `measurability`.
    probability : float
        Required probability of selecting the slipping model (`indistinguishable_above`).
    rig : Rig
        Set-up, camera, start state and mass of the films of the table.
    reliable_level : float, optional
        Largest predicted relative error of a reliable measurement (`reliable_range`).

    Returns
    -------
    dict
        The JSON object.

    Examples
    --------
    >>> from turntable import film, fit
    >>> rig = film.rig_from_config({
    ...     "radius_m": 0.005, "mass_kg": 0.00411, "k": 0.4, "rpm": 33.3, "axis_m": [0, 0],
    ...     "fps": 30.0, "noise_m": 2e-4, "duration_s": 2.0, "start_position_m": [0.05, 0],
    ...     "start_velocity_m_s": [0, 0], "start_spin_rad_s": [0, 0]})
    >>> table = fit.measurability([0.3, 3.0, 30.0], rig.state0, rig.setup, rig.camera)
    >>> out = fit.measurability_json(table, 0.95, rig, reliable_level=0.2)
    >>> out["reliable_mu0_range"], out["indistinguishable_above_mu0"]
    ([0.3, 5.2...], 3.4...)
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
