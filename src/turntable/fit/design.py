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

from turntable import _validate
from turntable.film import Camera, Setup, check_setup
from turntable.fit._predict import Distinguishability, distinguishability, predicted_stderr
from turntable.solution import no_slip_state

__all__ = [
    "Distinguishability",
    "Measurability",
    "distinguishability",
    "indistinguishable_above",
    "measurability",
    "measurability_json",
    "predicted_stderr",
    "reliable_range",
]


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
