"""A ball's outline where it borders something of another hue than the platter's and its own.

The outline is found along the line of colours from the platter's to the ball's
(``turntable.video.blobs``).  Where the ball lies on a label of another hue (a green ball on
a red label), the pixels just outside its circle are off that line, and so are those that
blend the label's colour with the ball's: the outline is cut short there, up to 1.6 px
inside the ball on its shaded side.  On such a ray the colour just outside the circle is
the background (``other_hue``), and the outline is looked for again on the step from it to
the ball's colour (``mix_profiles``).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from turntable.video.rays import along_rays

__all__ = [
    "BORDER_CONTRAST",
    "OTHER_CONTRAST",
    "OTHER_PX",
    "OTHER_RAYS",
    "borders_another_colour",
    "mix_profiles",
    "other_hue",
]

#: A ray ends on something of another hue where its colour ``OTHER_PX`` px beyond the circle
#: (the median of these) lies off the line from the platter's colour to the ball's (the
#: ``off_line`` of `other_hue`) and at least ``OTHER_CONTRAST`` of that line's length from
#: the ball's colour; such rays are looked at again where ``OTHER_RAYS`` of them at least.
OTHER_PX, OTHER_CONTRAST, OTHER_RAYS = (1.5, 2.25, 3.0), 0.5, 4
#: A ray crosses the ball's outline into something of another colour where the colours just
#: inside and just outside its circle differ by this much (CIELAB), and the one outside
#: differs as much from each of the ball's colours: a cream ring on a label touching a white
#: ball (11-21 on S13's frames; the ball's share, in lightness, rises into it from the ball's
#: shaded edge).  A shadow as dark as the ball, or the ball beyond a shadow's circle, differs
#: less.
BORDER_CONTRAST = 10.0


def other_hue(lab_img: NDArray, lines, start, radius: float, rays: int, off_line: float):
    """The rays from ``start`` that end on something of another hue, and the step on each.

    Parameters
    ----------
    lab_img : numpy.ndarray
        The window's CIELAB colours, float32 (h, w, 3).
    lines : list of (numpy.ndarray, numpy.ndarray)
        (platter, ball) colours of each of the ball's colours.
    start : tuple of float
        The circle's centre (u, v), px, in the window.
    radius : float
        The ball's image radius, px.
    rays : int
        Rays spread evenly over a turn.
    off_line : float
        How far off a line of colours (in its lengths) a colour is on no point of it.

    Returns
    -------
    tuple or None
        ``(other, background, step)``: which rays end on another hue, the colour beyond the
        circle on each and the step from it to the ball's colour nearest the colour just
        inside; None where fewer than `OTHER_RAYS` do.
    """
    angles = np.linspace(0.0, 2 * math.pi, rays, endpoint=False)
    at = radius + np.array([-OTHER_PX[1], *OTHER_PX], np.float32)  # inside, then outside
    seen = along_rays(lab_img, start, angles, at)
    outside = seen[:, 1:]  # the median of three: their sum less the largest and the least
    inside, bg = seen[:, 0], outside.sum(1) - outside.max(1) - outside.min(1)
    other = np.ones(rays, bool)
    for platter, ball in lines:
        step = (ball - platter).astype(np.float32)
        step2 = float(step @ step)
        diff = bg - platter.astype(np.float32)
        along = diff @ step
        other &= (diff * diff).sum(1) * step2 - along * along > off_line**2 * step2 * step2
        to = bg - ball.astype(np.float32)
        other &= (to * to).sum(1) > OTHER_CONTRAST**2 * step2
    if other.sum() < OTHER_RAYS:
        return None
    targets = np.array([ball for _, ball in lines], np.float32)
    nearest = np.argmin(np.linalg.norm(inside[other, None] - targets, axis=-1), axis=1)
    return other, bg[other], targets[nearest] - bg[other]


def mix_profiles(lab_img: NDArray, start, r: NDArray, angles: NDArray, bg, step) -> NDArray:
    """The share of ``step`` from ``bg`` that the colours at ``r`` (px) along each ray at
    ``angles`` from ``start`` have come (0 at the background, 1 at the ball's colour)."""
    along = along_rays(lab_img, start, angles, r)
    return (
        np.einsum("krc,kc->kr", along - bg[:, None], step)
        / np.einsum("kc,kc->k", step, step)[:, None]
    )


def borders_another_colour(lab_img: NDArray, targets, centre, radius: float, rays: int,
                           width: float) -> NDArray[np.bool_]:  # fmt: skip
    """Which of ``rays`` rays from ``centre`` cross the circle of ``radius`` (px) from the
    ball into something of another colour (`BORDER_CONTRAST`), its colours sampled ``width``
    px inside and outside it.

    Parameters
    ----------
    lab_img : numpy.ndarray
        The window's CIELAB colours, float32 (h, w, 3).
    targets : list of numpy.ndarray
        The ball's colours (CIELAB).
    centre : numpy.ndarray
        The circle's centre (u, v), window px.
    radius, width : float
        The circle's radius and how far either side of it the colours are sampled, px.
    rays : int
        How many rays, evenly spread in angle.

    Returns
    -------
    numpy.ndarray
        One bool a ray.
    """
    angles = np.linspace(0.0, 2 * math.pi, rays, endpoint=False)
    seen = along_rays(lab_img, centre, angles, radius + np.array([-width, width], np.float32))
    inside, outside = seen[:, 0], seen[:, 1]
    other = np.linalg.norm(outside - inside, axis=-1) >= BORDER_CONTRAST
    for target in targets:
        other &= np.linalg.norm(outside - np.float32(target), axis=-1) >= BORDER_CONTRAST
    return other
