"""Stage 2, the platter: its rim (an ellipse in the image) and its colour.

The platter is the largest region of the first frame that lies wholly in the image and is an
ellipse: Otsu's threshold on each CIELAB channel in turn (so that a grey platter on a table
of another hue is found as well as a dark one on a light table), connected components, and
`cv2.fitEllipseDirect` on each outline, kept if its area is within 5 % of the ellipse's.  The
rim is then refined to a fraction of a pixel: the crossing, along each normal of the ellipse,
of the half-way level between the platter and its surroundings, measured along the line
between their colours.

A thick platter, or one that stands on a table its shadow darkens, may be found together with
its side or its shadow, a band of another colour beyond its top along part of the rim.  The
top's edge is then where the colour first leaves the platter's going out along each normal
(``top_edge``).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

from turntable.video.robust import inliers

try:
    import cv2
except ImportError:  # without the extra [video]: the module imports, its functions do not run
    cv2 = None

#: The rim's outline is a region's within this share of its fitted ellipse's area.
ELLIPSE_AREA = 0.05
#: A platter covers at least this share of the image; its outline has this many points.
MIN_PLATTER_SHARE, MIN_OUTLINE = 0.02, 20
#: The platter's colour is measured between these shares of the rim (a label at its centre
#: left out), the surroundings' between these (the rim's own edge left out).
PLATTER_RING, OUTSIDE_RING = (0.35, 0.9), (1.05, 1.15)
#: The rim is fitted this many times to its points; a point more than ``RIM_SPREADS``
#: spreads (`turntable.video.robust.inliers`) off it is left out (the ball or the mark at
#: the rim), the spread at least ``RIM_FLOOR`` px (a rim to a twentieth of a pixel is not cut
#: finer); with fewer than ``MIN_RIM_POINTS`` points, it is not fitted again.
RIM_ROUNDS, RIM_SPREADS, RIM_FLOOR, MIN_RIM_POINTS = 3, 4.0, 0.05, 20
#: On later frames, the rim's points within this (px) of the rim (the ball or the mark at the
#: rim left out).
RIM_AGAIN_PX = 1.5
#: The rim is looked for along its normals, sampled every ``STEP_PX`` px, within ``REACH_PX``
#: px of the ellipse it is refined about.
STEP_PX, REACH_PX = 0.25, 6.0
#: The top's edge, going out along a normal from ``SIDE_REACH`` of b inside the outline: where
#: the colour first differs from the platter's by ``SIDE_CONTRAST`` (CIELAB units) and
#: ``SIDE_GRAIN`` times the platter's grain (its median distance from its own colour), at
#: least; it lies where the distance crosses half-way between its values ``SIDE_PLATEAU_PX`` px
#: either side (the platter's grain on one, the side's colour on the other).  A
#: band lies between the top and the outline where the edge is more than ``SIDE_PX`` px
#: inside the outline on ``SIDE_SHARE`` of the normals at least: the ball or the mark at
#: the rim cover no more than a few of them; a thick platter's side and its shadow cover a
#: third of them or more.
SIDE_REACH, SIDE_CONTRAST, SIDE_GRAIN, SIDE_PLATEAU_PX = 0.1, 10.0, 5.0, 3.0
SIDE_PX, SIDE_SHARE = 3.0, 0.15


class Ellipse(NamedTuple):
    """Centre (px), semi-axes a >= b (px), angle of the major axis from u towards v (rad)."""

    centre: tuple[float, float]
    a: float
    b: float
    angle: float

    def radius(self, points: NDArray[np.float64]) -> NDArray[np.float64]:
        """The normalised radius of points: 1 on the ellipse, 0 at its centre."""
        d = np.asarray(points, float).reshape(-1, 2) - self.centre
        c, s = math.cos(self.angle), math.sin(self.angle)
        return np.hypot((d[:, 0] * c + d[:, 1] * s) / self.a, (-d[:, 0] * s + d[:, 1] * c) / self.b)

    def mask(self, shape: tuple[int, int], scale: float = 1.0) -> NDArray[np.bool_]:
        """Pixels inside the ellipse scaled by ``scale`` about its centre."""
        m = np.zeros(shape, np.uint8)
        axes = (max(round(self.a * scale), 1), max(round(self.b * scale), 1))
        centre = (round(self.centre[0]), round(self.centre[1]))
        cv2.ellipse(m, centre, axes, math.degrees(self.angle), 0, 360, 1, -1)
        return m.astype(bool)


class Platter(NamedTuple):
    """The rim, and the colours (CIELAB) of the platter and of what surrounds it.

    ``level`` maps a CIELAB image to the scalar in which the rim is an edge: 0 outside, 1 on
    the platter.
    """

    rim: Ellipse
    colour: NDArray[np.float64]
    outside: NDArray[np.float64]

    @property
    def contrast(self) -> float:
        """CIELAB distance between the platter and its surroundings."""
        return float(np.linalg.norm(self.colour - self.outside))

    def level(self, lab: NDArray[np.float32]) -> NDArray[np.float32]:
        d = (self.colour - self.outside) / self.contrast**2
        return ((lab - self.outside.astype(np.float32)) @ d.astype(np.float32)).astype(np.float32)


def fit_ellipse(points: NDArray[np.float64]) -> Ellipse:
    """Least-squares ellipse through points (`cv2.fitEllipseDirect`)."""
    (cx, cy), (w, h), deg = cv2.fitEllipseDirect(np.asarray(points, np.float32))
    angle = math.radians(deg)
    if h > w:
        w, h, angle = h, w, angle + math.pi / 2
    angle = (angle + math.pi / 2) % math.pi - math.pi / 2
    return Ellipse((float(cx), float(cy)), w / 2.0, h / 2.0, angle)


def find_rim(lab: NDArray[np.float32]) -> Ellipse | None:
    """The platter's outline on a CIELAB image: the largest region, on either side of Otsu's
    threshold of any channel, that lies wholly in the image and is an ellipse (its area within
    5 % of the fitted ellipse's); None if none."""
    height, width = lab.shape[:2]
    best: tuple[float, Ellipse] | None = None
    for channel in range(3):
        img = cv2.normalize(lab[..., channel], None, 0, 255, cv2.NORM_MINMAX).astype(np.uint8)
        blur = cv2.GaussianBlur(img, (0, 0), 2.0)
        _, mask = cv2.threshold(blur, 0, 255, cv2.THRESH_BINARY + cv2.THRESH_OTSU)
        for m in (mask, 255 - mask):
            n, labels, stats, _ = cv2.connectedComponentsWithStats(m, connectivity=8)
            for i in range(1, n):
                x, y, w, h, area = stats[i]
                if x == 0 or y == 0 or x + w >= width or y + h >= height:
                    continue
                if area < MIN_PLATTER_SHARE * height * width or (
                    best is not None and area < best[0]
                ):
                    continue
                region = (labels[y : y + h, x : x + w] == i).astype(np.uint8)
                contours, _ = cv2.findContours(region, cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_NONE)
                contour = max(contours, key=len)
                if len(contour) < MIN_OUTLINE:
                    continue
                e = fit_ellipse(contour[:, 0, :].astype(float) + np.array([x, y]))
                filled = cv2.contourArea(contour)
                if abs(filled / (math.pi * e.a * e.b) - 1) < ELLIPSE_AREA and (
                    best is None or filled > best[0]
                ):
                    best = (filled, e)
    return None if best is None else best[1]


def platter_colours(lab: NDArray[np.float32], rim: Ellipse) -> Platter:
    """The median colours of the platter (between 0.35 and 0.9 of the rim: a label at its
    centre left out) and of a ring just outside the rim."""
    shape = lab.shape[:2]
    inner = rim.mask(shape, PLATTER_RING[1]) & ~rim.mask(shape, PLATTER_RING[0])
    ring = rim.mask(shape, OUTSIDE_RING[1]) & ~rim.mask(shape, OUTSIDE_RING[0])
    if not ring.any():
        ring = ~rim.mask(shape, 1.0)
    return Platter(
        rim, np.median(lab[inner], axis=0).astype(float), np.median(lab[ring], axis=0).astype(float)
    )


def _along_normals(
    img: NDArray[np.float32], rim: Ellipse, n: int, steps: NDArray[np.float64]
) -> tuple[NDArray[np.float64], NDArray[np.float32]]:
    """The points ``steps`` px along the normal of ``rim`` at ``n`` angles (n, steps, 2), and
    ``img``, smoothed over a pixel, sampled at them (n, steps)."""
    s = np.linspace(0, 2 * math.pi, n, endpoint=False)
    c, si = math.cos(rim.angle), math.sin(rim.angle)
    u1, u2 = np.array([c, si]), np.array([-si, c])
    on = (
        np.array(rim.centre) + (rim.a * np.cos(s))[:, None] * u1 + (rim.b * np.sin(s))[:, None] * u2
    )
    normal = (rim.b * np.cos(s))[:, None] * u1 + (rim.a * np.sin(s))[:, None] * u2
    normal /= np.linalg.norm(normal, axis=1, keepdims=True)
    pts = on[:, None, :] + steps[None, :, None] * normal[:, None, :]
    smooth = cv2.GaussianBlur(img, (0, 0), 1.0)
    prof = cv2.remap(
        smooth,
        pts[..., 0].astype(np.float32),
        pts[..., 1].astype(np.float32),
        cv2.INTER_LINEAR,
        borderMode=cv2.BORDER_REPLICATE,
    )
    return pts, prof


def rim_points(
    level: NDArray[np.float32], rim: Ellipse, n: int = 360, reach: float = REACH_PX
) -> NDArray[np.float64]:
    """Points of the rim to a fraction of a pixel: where ``level`` (0 outside, 1 on the
    platter) crosses 1/2 along the normal of ``rim`` at ``n`` angles (the crossing nearest the
    ellipse)."""
    steps = np.arange(-reach, reach + 1e-9, STEP_PX)
    pts, prof = _along_normals(level, rim, n, steps)
    prof = prof - np.float32(0.5)
    out = []
    centre = len(steps) // 2
    for k in range(n):
        p = prof[k]
        cross = np.flatnonzero(np.sign(p[:-1]) != np.sign(p[1:]))
        if cross.size == 0:
            continue
        j = cross[np.argmin(np.abs(cross - centre))]
        frac = p[j] / (p[j] - p[j + 1])
        out.append(pts[k, j] + frac * (pts[k, j + 1] - pts[k, j]))
    return np.array(out).reshape(-1, 2)


def refine_rim(level: NDArray[np.float32], rim: Ellipse) -> tuple[Ellipse, NDArray]:
    """The rim fitted again to its points to a fraction of a pixel, outliers (the ball or
    the mark at the rim) left out; returns the ellipse and the points kept."""
    pts = rim_points(level, rim)
    for k in range(RIM_ROUNDS):
        if len(pts) < MIN_RIM_POINTS:
            break
        rim = fit_ellipse(pts)
        dev = (rim.radius(pts) - 1.0) * rim.b
        pts = pts[inliers(dev, RIM_SPREADS, RIM_FLOOR)]
        pts = rim_points(level, rim) if k == 0 else pts  # sampled again about the first fit
    return rim, pts


def top_edge(lab: NDArray[np.float32], platter: Platter) -> tuple[Ellipse, NDArray] | None:
    """The top's rim where a band of another colour (a thick platter's side, its shadow on
    the table) lies between it and the outline ``platter.rim`` (`SIDE_PX`, `SIDE_SHARE`):
    fitted to the points where the colour first leaves the platter's going out along each
    normal, outliers left out as in `refine_rim`; None where there is no band."""
    distance = np.linalg.norm(lab - platter.colour.astype(np.float32), axis=-1)
    rim = platter.rim
    inner = rim.mask(distance.shape, PLATTER_RING[1]) & ~rim.mask(distance.shape, PLATTER_RING[0])
    grain = float(np.median(distance[inner]))
    level = max(SIDE_CONTRAST, SIDE_GRAIN * grain)
    pts, depth = _first_departures(distance, rim, level, SIDE_REACH * rim.b)
    if len(pts) < MIN_RIM_POINTS or np.mean(depth < -SIDE_PX) < SIDE_SHARE:
        return None
    for _ in range(RIM_ROUNDS):
        rim = fit_ellipse(pts)
        dev = (rim.radius(pts) - 1.0) * rim.b
        pts = pts[inliers(dev, RIM_SPREADS, RIM_FLOOR)]
        if len(pts) < MIN_RIM_POINTS:
            return None
    return fit_ellipse(pts), pts


def _first_departures(distance, rim: Ellipse, level: float, reach_in: float, n: int = 360):
    """Where, going out along the normal of ``rim`` at ``n`` angles from ``reach_in`` px
    inside it, the colour's ``distance`` from the platter's first passes ``level``: the
    crossing, nearest that point, of the half-way level between its values `SIDE_PLATEAU_PX`
    either side (px), and how far it lies from ``rim`` (px, negative inside)."""
    steps = np.arange(-reach_in, REACH_PX + 1e-9, STEP_PX)
    pts, prof = _along_normals(distance.astype(np.float32), rim, n, steps)
    beyond = int(SIDE_PLATEAU_PX / STEP_PX)
    out, depth = [], []
    for k in range(n):
        p = prof[k]
        above = np.flatnonzero(p > level)
        if above.size == 0:
            continue
        j = int(above[0])
        half = 0.5 * (p[max(j - beyond, 0)] + p[min(j + beyond, p.size - 1)])
        while j > 0 and p[j - 1] > half:  # back down to the half-way crossing
            j -= 1
        while j < p.size - 1 and p[j] < half:  # or on up to it
            j += 1
        if j == 0:
            continue
        frac = (half - p[j - 1]) / max(p[j] - p[j - 1], 1e-6)
        out.append(pts[k, j - 1] + frac * (pts[k, j] - pts[k, j - 1]))
        depth.append(steps[j - 1] + frac * STEP_PX)
    return np.array(out).reshape(-1, 2), np.array(depth)


def rim_points_again(level: NDArray[np.float32], rim: Ellipse) -> NDArray[np.float64]:
    """The rim's points on a later frame, those within 1.5 px of ``rim`` (the ball or the
    mark at the rim left out)."""
    pts = rim_points(level, rim)
    return pts[np.abs((rim.radius(pts) - 1.0) * rim.b) < RIM_AGAIN_PX]


def find_platter(lab: NDArray[np.float32]) -> tuple[Platter, NDArray[np.float64]] | None:
    """The platter of a CIELAB image, its rim refined, and the rim's points; None if none."""
    rim0 = find_rim(lab)
    if rim0 is None:
        return None
    platter = platter_colours(lab, rim0)
    if platter.contrast < 1e-6:
        return None
    rim, pts = refine_rim(platter.level(lab), rim0)
    top = top_edge(lab, platter._replace(rim=rim))
    if top is not None:  # a thick platter's side, or its shadow: the top's edge is the rim
        rim, pts = top
    return platter._replace(rim=rim), pts
