"""A ball lit from high above on a platter of about its shaded limb's shade (a white ball under
a lamp near the zenith on a mid-grey platter): its lit part fades, all round, into a ring
darker than the platter, its shaded limb (a negative share, `turntable.video.blobs`), and its
shadow peeks out beside it.  Its blob is its lit part only, and the outline of that lies
inside the ball by a varying few px: the ball's edge is where the ring meets the platter.

On each ray from the blob's centre the ring's outer edge is where the share rises half-way
from the ring's darkest back to the platter's, with the platter beyond (``edge_points``).  A
shadow's far edge lies on such rays too, on a circle of about the ball's radius beside it.
The ball's circle is the one of its radius through the most of these points (within
``ON_PX``) with nothing of the ball's lit colour just outside it, as a shadow's circle has: it
cuts the ball's lit side (``edge_centre``).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from turntable.video.rays import along_rays
from turntable.video.robust import circle_centre, inliers

try:
    import cv2
except ImportError:  # without the extra [video]
    cv2 = None

#: A ray crosses the ring where its share falls below minus this (a white ball's shaded limb
#: on a mid-grey platter under a high lamp: -0.5 to -0.9); a ball is ringed where
#: ``RING_RAYS`` of the rays cross it, and is seen as large as ``RING_MIN_PX`` (px, radius) at
#: least: on a smaller image the ring is a pixel or two wide and its edge not found to a pixel.
RING_DARK, RING_RAYS, RING_MIN_PX = 0.3, 0.75, 15.0
#: The platter: a share within this of 0, from 1 to 3 px beyond the ring's edge.
PLATTER_SHARE = 0.15
#: The rays are sampled every ``STEP`` px from ``FROM`` to ``TO`` times the radius (and 3 px
#: more).
STEP, FROM, TO = 0.25, 0.6, 1.6
#: Points within ``ON_PX`` px of a circle lie on it; the ball's circle carries ``SUPPORT`` of
#: the rays' points at least, and no ray's share ``OUTSIDE`` px beyond it is above ``LIT``.
ON_PX, SUPPORT, OUTSIDE, LIT = 1.0, 1 / 3, (1.5, 3.0), 0.25
#: The circle through the refit's points, its radius free, is of the radius given within this
#: share (1.003-1.034 on the 301 frames of ``1080p60_P010``, 1.025 on the rendered ball of
#: the tests): given 5 % too small, the circle of that radius through them lay 2.6 px
#: (0.07 R) off the ball's centre.  Given 5 % too large, the ring is used, 1.6 px off, and
#: the size check refuses the ball.
SIZE_AGREE = 0.04
#: Outliers of the refit: ``SPREADS`` spreads (`turntable.video.robust.inliers`), the spread at
#: least ``FLOOR`` px, over at most ``ROUNDS`` fits.
SPREADS, FLOOR, ROUNDS = 3.0, 0.1, 6


def edge_points(share: NDArray[np.float32], start: NDArray, radius: float,
                rays: int = 48) -> tuple[NDArray[np.float64], float]:  # fmt: skip
    """The ring's outer edge on each ray from ``start`` that crosses it and then reaches the
    platter (window px), and the share of the rays that cross a ring.

    Parameters
    ----------
    share : numpy.ndarray
        The share of each pixel of the window.
    start : numpy.ndarray
        Where the rays are cast from (u, v), window px.
    radius : float
        The ball's radius, px.
    rays : int
        How many rays, evenly spread in angle.

    Returns
    -------
    points : numpy.ndarray
        Shape (n, 2).
    ringed : float
        The share of the rays whose share falls below -`RING_DARK`.
    """
    r = np.arange(FROM * radius, TO * radius + 3.0, STEP)
    a = np.linspace(0.0, 2 * math.pi, rays, endpoint=False)
    prof = along_rays(share, start, a, r)
    index, px = np.arange(r.size), int(1 / STEP)
    pts, ringed = [], 0
    for k, p in enumerate(prof):
        dark = np.flatnonzero(p < -RING_DARK)
        if not dark.size:
            continue
        ringed += 1
        back = np.flatnonzero((index > dark[0]) & (p > -PLATTER_SHARE))
        if not back.size:
            continue
        low = max(back[0] - 2 * px, dark[0])  # the ring's darkest, 2 px before it ends
        m = low + int(np.argmin(p[low : back[0]]))
        level = 0.5 * p[m]
        if not (p[m + 1 :] > level).any():
            continue
        j = m + 1 + int(np.argmax(p[m + 1 :] > level))
        beyond = p[j + px : j + 3 * px]
        if beyond.size < 2 * px or np.abs(beyond).max() > PLATTER_SHARE:
            continue
        rr = r[0] + (j - 1 + (level - p[j - 1]) / max(p[j] - p[j - 1], 1e-6)) * STEP
        pts.append((start[0] + math.cos(a[k]) * rr, start[1] + math.sin(a[k]) * rr))
    return np.array(pts, float).reshape(-1, 2), ringed / rays


def edge_centre(share: NDArray[np.float32], start: NDArray, radius: float, fallback: NDArray,
                rays: int = 48) -> NDArray:  # fmt: skip
    """The centre (window px) of a ringed ball's circle: of radius ``radius`` through the
    most of `edge_points`, nothing lit outside it, refitted without outliers; ``fallback``
    where the ball is not ringed, no such circle carries `SUPPORT` of the rays, or the
    points' own circle is not of that radius (`SIZE_AGREE`).

    Parameters
    ----------
    share : numpy.ndarray
        The share of each pixel of the window.
    start : numpy.ndarray
        Where the rays are cast from (u, v), window px: inside the ball's lit part.
    radius : float
        The ball's radius, px.
    fallback : numpy.ndarray
        The centre returned where the ball is not found by its ring.
    rays : int
        How many rays, evenly spread in angle.

    Returns
    -------
    numpy.ndarray
        The centre (u, v).
    """
    if radius < RING_MIN_PX:
        return fallback
    pts, ringed = edge_points(share, start, radius, rays)
    if ringed < RING_RAYS or len(pts) < SUPPORT * rays:
        return fallback
    centres = _through_pairs(pts, radius)
    if not len(centres):
        return fallback
    dist = np.hypot(pts[None, :, 0] - centres[:, :1], pts[None, :, 1] - centres[:, 1:])
    on = np.abs(dist - radius) < ON_PX
    count = np.where(_nothing_lit_outside(share, centres, radius, rays), on.sum(axis=1), -1)
    best = int(np.argmax(count))
    if count[best] < SUPPORT * rays:
        return fallback
    centre, keep = centres[best], on[best]
    for _ in range(ROUNDS):
        centre = circle_centre(pts[keep], radius, start=centre)
        dev = np.hypot(*(pts - centre).T) - radius
        again = inliers(dev, SPREADS, FLOOR, kept=keep, centred=True, most=ON_PX)
        if (again == keep).all():
            break
        keep = again
    clear = _nothing_lit_outside(share, centre[None], radius, rays)[0]
    free = circle_centre(pts[keep])  # the radius free: is it the ball's?
    sized = abs(np.mean(np.hypot(*(pts[keep] - free).T)) / radius - 1.0) < SIZE_AGREE
    return centre if clear and sized and keep.sum() >= SUPPORT * rays else fallback


def _through_pairs(pts: NDArray[np.float64], radius: float) -> NDArray[np.float64]:
    """The centres of the circles of radius ``radius`` through each pair of points at least a
    radius apart (nearer pairs fix no centre), both of each pair's two."""
    i, j = np.triu_indices(len(pts), 1)
    chord = pts[j] - pts[i]
    half = 0.5 * np.hypot(*chord.T)
    ok = (half >= 0.5 * radius) & (half < radius)
    mid, chord, half = 0.5 * (pts[i] + pts[j])[ok], chord[ok], half[ok]
    normal = np.c_[-chord[:, 1], chord[:, 0]] / (2 * half[:, None])
    h = np.sqrt(radius**2 - half**2)[:, None]
    return np.vstack([mid + h * normal, mid - h * normal])


def _nothing_lit_outside(share, centres: NDArray[np.float64], radius: float, rays: int):
    """Whether no ray's share `OUTSIDE` px beyond each circle is above `LIT`."""
    a = np.linspace(0.0, 2 * math.pi, rays, endpoint=False)
    clear = np.ones(len(centres), bool)
    for w in OUTSIDE:
        pu = (centres[:, :1] + np.cos(a) * (radius + w)).astype(np.float32)
        pv = (centres[:, 1:] + np.sin(a) * (radius + w)).astype(np.float32)
        got = cv2.remap(share, pu, pv, cv2.INTER_LINEAR, borderMode=cv2.BORDER_REPLICATE)
        clear &= (got <= LIT).all(axis=1)
    return clear
