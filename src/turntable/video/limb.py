"""A ball lit from one side on a platter of about its shaded side's shade (a white ball on a
mid-grey platter, a low lamp beside it): its blob is its lit part only, and its outline is
seen on its lit side only.  The circle of the ball's radius through that arc is the ball's
where, on the rest of the circle, the ball's shaded limb lies inside it: darker than the
platter, away from the ball's lit colour (a negative share, `turntable.video.blobs`), as a
platter, a shadow beside a smaller ball or a label is not.  Its size is then that of the
circle's part the ball covers, lit or shaded (``disc_radius``), not the lit blob's area.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from turntable.video.rays import along_rays

#: A ray crosses the ball's shaded limb where the share just inside the circle is below minus
#: this: darker than the platter by a tenth of the ball's step from it (a white ball's shaded
#: side on a mid-grey platter is at -0.6 to -0.9); the platter's grain stays above it.
LIMB_DARK = 0.1


def across(share: NDArray[np.float32], centre: NDArray, radius: float, rays: int,
           width: float) -> NDArray[np.float32]:  # fmt: skip
    """The share ``width`` px inside and outside the circle on each of ``rays`` rays.

    Parameters
    ----------
    share : numpy.ndarray
        The share of each pixel of the window.
    centre : numpy.ndarray
        The circle's centre (u, v), window px.
    radius : float
        The circle's radius, px.
    rays : int
        How many rays, evenly spread in angle.
    width : float
        How far inside and outside the circle the share is sampled, px.

    Returns
    -------
    numpy.ndarray
        Shape (rays, 2): the share inside, then outside.
    """
    a = np.linspace(0.0, 2 * math.pi, rays, endpoint=False)
    return along_rays(share, centre, a, radius + np.array([-width, width]))


def confirmed(profile: NDArray[np.float32], step: float, limb: bool) -> NDArray[np.bool_]:
    """Which rays confirm the circle: the share falls outward across it by ``step`` at least
    (the ball's outline), or, with ``limb``, the ball's shaded limb lies inside it (a share
    below -`LIMB_DARK`).

    Parameters
    ----------
    profile : numpy.ndarray
        `across`'s share inside and outside the circle on each ray.
    step : float
        The least fall of the share across the circle.
    limb : bool
        Whether a shaded limb inside the circle confirms it.

    Returns
    -------
    numpy.ndarray
        One bool a ray.
    """
    falls = profile[:, 0] - profile[:, 1] >= step
    return falls | (profile[:, 0] <= -LIMB_DARK) if limb else falls


def disc_radius(share: NDArray[np.float32], centre: NDArray, radius: float,
                threshold: float) -> float:  # fmt: skip
    """The radius (px) of a disc of the area the ball covers in the circle: its lit part (a
    share above ``threshold``) and its shaded limb (a share below -`LIMB_DARK`).

    Parameters
    ----------
    share : numpy.ndarray
        The share of each pixel of the window.
    centre : numpy.ndarray
        The circle's centre (u, v), window px.
    radius : float
        The circle's radius, px.
    threshold : float
        The share above which a pixel is of the ball's lit colour.

    Returns
    -------
    float
        ``radius`` times the square root of the part of the circle covered.

    Examples
    --------
    A disc of radius 10 px, its left half lit (share 1), its right half shaded (share -0.8),
    on a platter (share 0):

    >>> import numpy as np
    >>> vv, uu = np.mgrid[0:40, 0:40]
    >>> inside = np.hypot(uu - 20, vv - 20) < 10
    >>> share = np.where(inside, np.where(uu < 20, 1.0, -0.8), 0.0).astype(np.float32)
    >>> print(round(disc_radius(share, np.array([20.0, 20.0]), 10.0, 0.45), 1))
    10.0
    """
    h, w = share.shape
    vv, uu = np.mgrid[0:h, 0:w]
    inside = np.hypot(uu - centre[0], vv - centre[1]) < radius
    if not inside.any():
        return math.nan
    ball = (share > threshold) | (share < -LIMB_DARK)
    return radius * math.sqrt(float(ball[inside].mean()))
