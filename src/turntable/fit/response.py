"""How a fit's coefficient follows a change of its film: the linear response of the
least-squares estimate, (J^T J)^-1 J^T (change of the residuals), by one Gauss-Newton step
from the fit (`fit_response`), or as the weight of each position
(`coefficient_influence`); a camera's calibration and a tracker's smooth error are carried
into a coefficient's standard error with them (`turntable.video.uncertainty`).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from turntable.film import Film, Setup, check_setup
from turntable.fit.lsq import _dimensionless, _Fitter, _least_squares
from turntable.fit.parameters import _layout


def fit_response(
    film: Film,
    setup: Setup,
    model: str,
    variants: list[tuple[Film, Setup]],
    *,
    fit_omega: bool = False,
    fit_axis: bool = False,
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Return how ln c and ln RSS of a fit move, to first order, when the film and the setup
    are replaced by each of ``variants`` (the same frames, measured by another camera).

    One Gauss-Newton step from the fit of ``film`` on each variant, less the step on
    ``film`` itself: the linear response of the least-squares estimate,
    (J^T J)^-1 J^T (change of the residuals), without a fit per variant; the residual sum of
    squares after the step, RSS = |r + J step|^2, is that of the linearised refit.

    Parameters
    ----------
    film : Film
    setup : Setup
    model : str
    variants : list of (Film, Setup)
        Each with as many frames as ``film``.
    fit_omega, fit_axis : bool
        As in `fit_model`.

    Returns
    -------
    d_log_c, d_log_rss : numpy.ndarray
        The changes of ln c and of ln RSS for each variant.
    """
    lay = _layout(model, fit_omega, fit_axis)
    fitter, _, theta, _ = _least_squares(film, check_setup(setup), lay)
    base, base_rss = _gauss_newton_step(fitter, theta)
    changes, rss = [], []
    for other, other_setup in variants:
        tau, xy = _dimensionless(other, check_setup(other_setup))
        step, other_rss = _gauss_newton_step(_Fitter(lay, tau, xy, other_setup), theta)
        changes.append(step[lay.i_c] - base[lay.i_c])
        rss.append(math.log(other_rss / base_rss))
    return np.array(changes), np.array(rss)


def _gauss_newton_step(
    fitter: _Fitter, theta: NDArray[np.float64]
) -> tuple[NDArray[np.float64], float]:
    """The least-squares step -J^+ r of ``fitter`` from ``theta``, and |r + J step|^2."""
    jac, res = fitter.jacobian(theta), fitter.residuals(theta)
    step = np.linalg.lstsq(jac, -res, rcond=None)[0]
    return step, float(np.sum((res + jac @ step) ** 2))


def coefficient_influence(
    film: Film, setup: Setup, model: str, *, fit_omega: bool = False, fit_axis: bool = False
) -> NDArray[np.float64]:
    """Return d ln c / d(x_i, y_i) of the fit (1/m, shape (n, 2)): how ln c moves, to first
    order, when the film's positions move by small amounts.

    The row of ln c in the pseudo-inverse J^+ of the residuals' Jacobian (m) at the fit: a
    move dxy of the positions moves ln c by sum(influence * dxy), as `fit_response`
    finds for the film so moved.

    Parameters
    ----------
    film : Film
    setup : Setup
    model : str
    fit_omega, fit_axis : bool
        As in `fit_model`.

    Returns
    -------
    numpy.ndarray
        Shape (n, 2), 1/m: zero where the coefficient is held at an end of its range.
    """
    lay = _layout(model, fit_omega, fit_axis)
    setup = check_setup(setup)
    fitter, _, theta, _ = _least_squares(film, setup, lay)
    row = np.linalg.pinv(fitter.jacobian(theta))[lay.i_c]
    return row.reshape(-1, 2)
