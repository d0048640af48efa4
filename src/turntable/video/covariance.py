"""The covariance of a calibration's parameters (``turntable.video.calibrate``): the fit's,
widened for the mark's correlated errors, plus the systematic shifts of all the parameters
with one held (the lens's k1 by its uncertainty; the focal length by the images' systematic
error, ``focal_floor``).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

__all__ = ["MARK_SHAPE", "covariance", "focal_floor", "follows_held", "lag1"]

#: The shape of the images of the mark's circle is known to this share of its size at best,
#: however many its points: its tracked centre carries errors of ~0.01 px that repeat at the
#: same place of the image on every turn (the harmonics of the residuals of
#: phone_lens_7_SYNTHETIC against its true camera: 0.005-0.013 px on a circle of 135 px).
#: To first order in the tilt b, a camera's image of the platter's plane depends on b and
#: the focal length f through b / f only; f itself is seen in the ellipticity of the images,
#: of order b^2, and so ln f is measured to `MARK_SHAPE` / b^2 at best (`focal_floor`).
MARK_SHAPE = 1e-4


def lag1(e: NDArray) -> float:
    """The lag-1 autocorrelation of residuals ``e`` (n, 2)."""
    e = e - e.mean(axis=0)
    den = float(np.sum(e * e))
    return float(np.sum(e[1:] * e[:-1]) / den) if den > 0 else 0.0


def focal_floor(jac: NDArray, r1: float, prior: float, tilt: float, i: int) -> float:
    """The standard error that the images' systematic errors (`MARK_SHAPE`) add to the fitted
    ln f (parameter ``i`` of the fit whose Jacobian is ``jac``), beyond the fit's own.

    The fit weighs the images as if their scatter (lag-1 autocorrelation ``r1``) were all
    their error: its ln f is the weighted mean of the images' own, of variance s_i^2, and the
    prior's (``prior`` = s_p), the images' weight w = s_p^2 / (s_p^2 + s_i^2).  Their
    systematic error, `MARK_SHAPE` / b^2 in ln f (b = ``tilt``, rad), moves the fitted ln f
    by w times it.  At a tilt of several degrees it is a fraction of the fit's own; for a
    camera looking nearly straight down it is the larger part.
    """
    var = float(np.linalg.pinv(jac.T @ jac)[i, i]) * ((1 + r1) / (1 - r1) if r1 > 0 else 1.0)
    prior2 = prior**2
    var = min(var, prior2 * (1 - 1e-9))
    own = 1.0 / (1.0 / var - 1.0 / prior2)  # the images' alone
    floor = min(MARK_SHAPE / max(tilt**2, 1e-12), 1e6)
    return prior2 / (prior2 + own) * floor


def follows_held(jac: NDArray, i: int) -> NDArray:
    """d theta / d theta_i: how the fitted parameters follow a change of parameter ``i`` held
    (1 in it), from the Jacobian ``jac`` of the fit."""
    others = np.delete(jac, i, axis=1)
    shift = -np.linalg.pinv(others.T @ others) @ others.T @ jac[:, i]
    return np.insert(shift, i, 1.0)


def covariance(jac: NDArray, r1: float, fitted: slice, size: int, *shifts: NDArray) -> NDArray:
    """The parameters' covariance (``size`` of them): the fit's (of the parameters
    ``fitted``), widened by sqrt((1 + r) / (1 - r)) for a lag-1 autocorrelation ``r1`` > 0,
    plus the shift of all of them with each of ``shifts``."""
    cov = np.zeros((size, size))
    cov[fitted, fitted] = np.linalg.pinv(jac.T @ jac)
    if r1 > 0:
        cov *= (1 + r1) / (1 - r1)
    for shift in shifts:
        cov += np.outer(shift, shift)
    return cov
