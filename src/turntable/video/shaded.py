"""A small ball's centre from its whole image: the image of a shaded disc fitted to it.

A small ball lit from one side (a white ball on a mid-grey platter, a high lamp behind it)
fades towards its edge on its lit side, to about the platter's shade at the edge itself, and
its shaded side runs into its shadow: its outline is seen nowhere sharply, and the points
``turntable.video.blobs`` takes on it lie about a pixel inside the ball's edge, more than a
small ball's 0.05 R.  Here the ball's image is fitted as a whole instead: a disc whose shade
is that of a matte sphere, an ambient level plus a light from any direction
(:math:`a + \\max(0, g \\cdot n)`, :math:`n` the sphere's normal), on the platter, averaged
over each pixel (``SUPER`` samples a side) and blurred by ``BLUR`` px.  The shade is measured
as the share of the step from the platter's colour to the ball's, in the picture's RGB
(nearer linear in the shading than CIELAB; a camera's gamma is not undone).  What lies
outside the disc and darker than the platter (``SHADOW``) is a shadow, and is left out of
the fit.  The fit
starts from the best of a grid of centres about the outline's (``GRID``); the disc's radius
is fitted too, and is the size ``turntable.video.check`` judges the ball by.

Only a small ball (``SMALL_PX``) whose blob is its lit part (``LIT_ONLY``) is fitted (some
tenths of a second a frame), and the fit is taken only where it holds (``FIT_RMS``); any
other ball keeps the centre from its outline.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from turntable.video.decode import Picture, _rgb

try:
    import cv2
except ImportError:  # without the extra [video]
    cv2 = None

#: Only an image of the ball smaller than this radius (px) is fitted: a larger one's outline
#: is sharp enough (`turntable.video.check`'s ``DISC_MIN_PX`` is this).
SMALL_PX = 15.0
#: ... and only where its blob covers less than this share of its circle: its lit part only
#: (0.59 on unseen.py's ``720p60_r5_P017_tilt30``; 0.79 and more on the good tracks of
#: MuJoCo's scenes, a radius of 0.89 and more, `turntable.video.check`'s ``BALL_SIZE``).
LIT_ONLY = 0.7
#: The fit is taken where its residuals are within this (rms, share); else the outline's.
FIT_RMS = 0.15
#: Samples of a pixel, a side; and the blur (px, a Gaussian's standard deviation).
SUPER, BLUR = 3, 0.5
#: Outside the disc, a share below this is a shadow (left out).
SHADOW = -0.15
#: The pixels fitted lie within this (px) of the disc's edge as first placed.
MARGIN = 4.0
#: The fit's robust loss scale (share).
LOSS_SCALE = 0.1
#: The centre is fitted within this share of the radius of where it starts, and the radius
#: within these factors of the one predicted.
REACH, SIZES = 0.5, (0.6, 1.6)
#: The fit starts from the best centre of a grid this far (px) either way of the start in
#: these steps, then of a finer grid about that (a start half a pixel off can stay in a
#: wrong minimum, the shading's gradient taking up the shift).
GRID = ((2.0, 1.0), (0.5, 0.5))


def small_ball(picture: Picture, box: tuple[slice, slice], colour, share: NDArray[np.float32],
               centre: NDArray, radius: float, area: float,
               disc: float) -> tuple[NDArray, float]:  # fmt: skip
    """The centre (window px) of a small ball's blob of ``area`` (px) and the radius (px) of
    the ball's image: the shaded disc's (`fit`) where the blob is the lit part of a small
    ball (`SMALL_PX`, `LIT_ONLY`) of one colour and the fit holds (`FIT_RMS`), else
    ``centre`` and ``disc`` (nan for a small ball: its outline is not its edge).

    Parameters
    ----------
    picture : Picture
        The frame.
    box : tuple of slice
        The window (rows, columns) that ``share`` and ``centre`` are in.
    colour : turntable.video.blobs.Colour or turntable.video.blobs.Colours
        The ball's colour and the platter's (a ball of several colours is not fitted).
    share : numpy.ndarray
        The window's share (CIELAB), 0 off the line between the two colours.
    centre : numpy.ndarray
        The centre from the blob's outline (u, v), window px.
    radius : float
        The radius (px) of the ball's image as predicted.
    area : float
        The blob's area (px).
    disc : float
        The radius (px) of the ball's part in the circle through the outline, or nan.

    Returns
    -------
    centre : numpy.ndarray
    disc : float
    """
    if radius >= SMALL_PX:
        return centre, disc
    if not hasattr(colour, "target") or area >= LIT_ONLY * math.pi * radius**2:
        return centre, math.nan
    ball, platter = lab_to_rgb(colour.target), lab_to_rgb(colour.platter)
    if np.allclose(ball, platter, atol=1e-3):
        return centre, math.nan
    got = fit(rgb_share(_rgb(picture, box), ball, platter), centre, radius, share != 0)
    if got is None or got[2] > FIT_RMS:
        return centre, math.nan
    return got[0], got[1]


def rgb_share(rgb: NDArray[np.float32], ball: NDArray, platter: NDArray) -> NDArray[np.float64]:
    """Each pixel's share of the step from ``platter``'s RGB to ``ball``'s (0 on the
    platter, 1 on the ball)."""
    step = np.asarray(ball, float) - np.asarray(platter, float)
    return (rgb - np.asarray(platter, np.float32)) @ step / float(step @ step)


def lab_to_rgb(colour: NDArray) -> NDArray[np.float64]:
    """The RGB (0-1) of a CIELAB colour, as ``turntable.video.decode.lab`` measures it."""
    lab = np.asarray(colour, np.float32).reshape(1, 1, 3)
    return cv2.cvtColor(lab, cv2.COLOR_Lab2RGB).reshape(3).astype(float)


def _image(p, uu, vv):
    """The model's image at the pixels (uu, vv): p = (u, v, radius, a, gx, gy, gz)."""
    cu, cv, r, a, gx, gy, gz = p
    sub = (np.arange(SUPER) + 0.5) / SUPER - 0.5
    x = (uu[..., None, None] + sub[:, None] - cu) / r
    y = (vv[..., None, None] + sub[None, :] - cv) / r
    rho2 = x * x + y * y
    z = np.sqrt(np.clip(1.0 - rho2, 0.0, 1.0))
    shade = a + np.maximum(0.0, gx * x + gy * y + gz * z)
    m = np.where(rho2 < 1.0, shade, 0.0).mean(axis=(-1, -2))
    return cv2.GaussianBlur(m.astype(np.float32), (0, 0), BLUR).astype(float)


def fit(
    share: NDArray, start: NDArray, radius: float, usable: NDArray[np.bool_] | None = None
) -> tuple[NDArray, float, float] | None:
    """The centre (window px), the radius (px) and the rms residual (share) of the shaded
    disc fitted to ``share`` from ``start`` and ``radius`` (px), the pixels not ``usable``
    left out; None if the fit fails or the disc does not lie wholly in the window."""
    from scipy.optimize import least_squares

    reach = REACH * radius
    half = SIZES[1] * radius + reach + MARGIN
    rows = slice(int(start[1] - half), int(start[1] + half) + 2)
    cols = slice(int(start[0] - half), int(start[0] + half) + 2)
    if rows.start < 0 or cols.start < 0 or rows.stop > share.shape[0] or cols.stop > share.shape[1]:
        return None
    s = share[rows, cols].astype(float)
    vv, uu = np.mgrid[rows, cols].astype(float)
    near = np.hypot(uu - start[0], vv - start[1]) < radius + MARGIN
    if usable is not None:
        near &= usable[rows, cols]

    def residual(p):
        m = _image(p, uu, vv)
        out = np.hypot(uu - p[0], vv - p[1]) > p[2] - 0.5
        return np.where(out & (s < SHADOW), 0.0, m - s)[near]

    def cost(p):
        z = (residual(p) / LOSS_SCALE) ** 2
        return float(np.sum(np.sqrt(1.0 + z) - 1.0))

    p0 = np.r_[start, radius, np.zeros(4)]
    for reach_px, step in GRID:  # the best of a coarse grid, then of a fine one about it
        steps = np.arange(-reach_px, reach_px + 0.1 * step, step)
        grid = [p0[:2] + np.array([du, dv]) for du in steps for dv in steps]
        p0 = min((np.r_[c, radius, _shading(s, uu, vv, c, radius, near)] for c in grid), key=cost)
    lo = np.r_[start - reach, SIZES[0] * radius, np.full(4, -np.inf)]
    hi = np.r_[start + reach, SIZES[1] * radius, np.full(4, np.inf)]
    try:
        sol = least_squares(residual, p0, bounds=(lo, hi), loss="soft_l1", f_scale=LOSS_SCALE)
    except (ValueError, np.linalg.LinAlgError):
        return None
    if not sol.success or sol.active_mask[:3].any():
        return None
    return sol.x[:2], float(sol.x[2]), float(np.sqrt(np.mean(sol.fun**2)))


def _shading(s, uu, vv, c, r, near, rounds: int = 4):
    """The shading (a, gx, gy, gz) that best explains ``s`` about the disc at ``c`` of radius
    ``r``: a linear fit, the lit side (g . n > 0) found again each round."""
    x, y = (uu - c[0]) / r, (vv - c[1]) / r
    inside = near & (x * x + y * y < 1.0)
    x, y = x[inside], y[inside]
    z = np.sqrt(np.clip(1.0 - x * x - y * y, 0.0, 1.0))
    basis = np.c_[x, y, z]
    lit = np.ones(x.size, bool)
    g = np.zeros(4)
    for _ in range(rounds):
        a = np.c_[np.ones(x.size), basis * lit[:, None]]
        g = np.linalg.lstsq(a, s[inside], rcond=None)[0]
        again = basis @ g[1:] > 0
        if (again == lit).all():
            break
        lit = again
    return g
