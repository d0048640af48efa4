"""Fitting shared by the stages: which residuals are outliers, and the centre of a circle.

A residual is an outlier when it lies more than a number of *spreads* from the others: the
median absolute deviation, scaled to a normal distribution's standard deviation (as
`scipy.stats.median_abs_deviation` with ``scale="normal"``, without importing scipy.stats,
a second of a command's start), plus a floor, the noise below
which points of a perfect fit are never cut.  Each stage names its own number of spreads and
floor, with its reason.
"""

from __future__ import annotations

import math
from statistics import NormalDist

import numpy as np
from numpy.typing import NDArray

#: A normal distribution's standard deviation over its median absolute deviation, 1.4826.
MAD_TO_SD = 1 / NormalDist().inv_cdf(0.75)


def spread(dev: NDArray[np.float64], floor: float) -> float:
    """The residuals' robust standard deviation plus ``floor``.

    Parameters
    ----------
    dev : numpy.ndarray
        Residuals.
    floor : float
        Added to the scaled median absolute deviation, in the residuals' units.

    Returns
    -------
    float

    Examples
    --------
    >>> import numpy as np
    >>> from turntable.video.robust import spread
    >>> round(spread(np.array([-1.0, 0.0, 1.0, 100.0]), 0.1), 3)
    1.583
    """
    dev = np.asarray(dev, dtype=float)
    return float(np.median(np.abs(dev - np.median(dev)))) * MAD_TO_SD + floor


def inliers(
    dev: NDArray[np.float64],
    spreads: float,
    floor: float,
    *,
    kept: NDArray[np.bool_] | None = None,
    centred: bool = False,
    most: float = math.inf,
) -> NDArray[np.bool_]:
    """Which residuals lie within ``spreads`` spreads (`spread`), and within ``most``.

    Parameters
    ----------
    dev : numpy.ndarray
        Residuals of every point.
    spreads, floor : float
        How many spreads are kept, and the spread's floor.
    kept : numpy.ndarray of bool, optional
        The points the spread (and the median) is measured on; all if None.  Every point is
        judged, so that a point left out may come back.
    centred : bool
        Measure from the residuals' median instead of from 0.
    most : float
        The largest distance kept, whatever the spread.

    Returns
    -------
    numpy.ndarray of bool

    Examples
    --------
    >>> import numpy as np
    >>> from turntable.video.robust import inliers
    >>> inliers(np.array([-1.0, 0.0, 1.0, 100.0]), 4.0, 0.1)
    array([ True,  True,  True, False])
    """
    base = dev if kept is None else dev[kept]
    mid = float(np.median(base)) if centred else 0.0
    return np.abs(dev - mid) < min(spreads * spread(base, floor), most)


def circle_centre(
    points: NDArray[np.float64],
    radius: float | None = None,
    *,
    start: NDArray[np.float64] | None = None,
    weights: NDArray[np.float64] | None = None,
    steps: int = 3,
) -> NDArray[np.float64]:
    """The centre of the least-squares circle through points (n, 2).

    Without ``radius``, Kåsa's algebraic fit (the circle's radius free, unweighted).  With it,
    the circle of that radius nearest the points in distance, weighted by ``weights``:
    ``steps`` Gauss-Newton steps from ``start``.

    Parameters
    ----------
    points : numpy.ndarray
        Points (n, 2).
    radius : float, optional
        The circle's radius, if known.
    start : numpy.ndarray, optional
        Where the Gauss-Newton steps start (with ``radius``); the points' mean if None.
    weights : numpy.ndarray, optional
        The points' weights (with ``radius``); 1 if None.
    steps : int
        Gauss-Newton steps (with ``radius``).

    Returns
    -------
    numpy.ndarray
        The centre (2,).

    Examples
    --------
    >>> import numpy as np
    >>> from turntable.video.robust import circle_centre
    >>> a = np.linspace(0, 2 * np.pi, 8, endpoint=False)
    >>> pts = np.c_[3 + 2 * np.cos(a), -1 + 2 * np.sin(a)]
    >>> np.round(circle_centre(pts), 6), np.round(circle_centre(pts, 2.0, start=[2.5, 0]), 6)
    (array([ 3., -1.]), array([ 3., -1.]))
    """
    points = np.asarray(points, float)
    if radius is None:
        a = np.c_[2 * points, np.ones(len(points))]
        return np.linalg.lstsq(a, (points**2).sum(axis=1), rcond=None)[0][:2]
    centre = np.asarray(points.mean(axis=0) if start is None else start, float)
    sw = np.sqrt(np.ones(len(points)) if weights is None else weights)[:, None]
    for _ in range(steps):
        d = points - centre
        dist = np.maximum(np.hypot(d[:, 0], d[:, 1]), 1e-9)
        jac = -d / dist[:, None]
        centre = centre - np.linalg.lstsq(jac * sw, (dist - radius) * sw[:, 0], rcond=None)[0]
    return centre
