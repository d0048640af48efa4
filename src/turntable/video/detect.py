"""Finding things in one grey image: the platter's rim (an ellipse), blobs (ball, mark).

OpenCV does the image work: Otsu's threshold and connected components for the platter and
the blobs, `cv2.fitEllipseDirect` for the rim.  Positions are refined to a fraction of a
pixel: the rim by the crossing of the half-way grey level along each normal of the
ellipse, a blob by its centroid weighted by its contrast, clipped where the blob is
opaque (so that each pixel of the edge counts by the share of it the blob covers).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

try:
    import cv2
except ImportError:  # without the extra [video]: the module imports, its functions do not run
    cv2 = None


class Ellipse(NamedTuple):
    """Centre (px), semi-axes a >= b (px), angle of the major axis from u towards v (rad)."""

    centre: tuple[float, float]
    a: float
    b: float
    angle: float

    def radius(self, points: NDArray[np.float64]) -> NDArray[np.float64]:
        """The normalised radius of points: 1 on the ellipse, 0 at its centre."""
        d = np.asarray(points, float) - self.centre
        c, s = math.cos(self.angle), math.sin(self.angle)
        return np.hypot((d[:, 0] * c + d[:, 1] * s) / self.a, (-d[:, 0] * s + d[:, 1] * c) / self.b)

    def mask(self, shape: tuple[int, int], scale: float = 1.0) -> NDArray[np.bool_]:
        """Pixels inside the ellipse scaled by ``scale`` about its centre."""
        m = np.zeros(shape, np.uint8)
        axes = (max(round(self.a * scale), 1), max(round(self.b * scale), 1))
        centre = (round(self.centre[0]), round(self.centre[1]))
        cv2.ellipse(m, centre, axes, math.degrees(self.angle), 0, 360, 1, -1)
        return m.astype(bool)


def fit_ellipse(points: NDArray[np.float64]) -> Ellipse:
    """Least-squares ellipse through points (`cv2.fitEllipseDirect`)."""
    (cx, cy), (w, h), deg = cv2.fitEllipseDirect(np.asarray(points, np.float32))
    angle = math.radians(deg)
    if h > w:
        w, h, angle = h, w, angle + math.pi / 2
    angle = (angle + math.pi / 2) % math.pi - math.pi / 2
    return Ellipse((float(cx), float(cy)), w / 2.0, h / 2.0, angle)


def find_platter(img: NDArray[np.uint8]) -> Ellipse | None:
    """The platter: the largest region of either side of Otsu's threshold that lies wholly in
    the image and is an ellipse (its area within 5 % of the fitted ellipse's); None if none."""
    height, width = img.shape
    blur = cv2.GaussianBlur(img, (0, 0), 2.0)
    _, mask = cv2.threshold(blur, 0, 255, cv2.THRESH_BINARY + cv2.THRESH_OTSU)
    best: tuple[float, Ellipse] | None = None
    for m in (mask, 255 - mask):
        n, labels, stats, _ = cv2.connectedComponentsWithStats(m, connectivity=8)
        for i in range(1, n):
            x, y, w, h, area = stats[i]
            if x == 0 or y == 0 or x + w >= width or y + h >= height or area < 0.02 * img.size:
                continue
            region = (labels == i).astype(np.uint8)
            contours, _ = cv2.findContours(region, cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_NONE)
            contour = max(contours, key=len)
            if len(contour) < 20:
                continue
            e = fit_ellipse(contour[:, 0, :].astype(float))
            filled = cv2.contourArea(contour)
            if abs(filled / (math.pi * e.a * e.b) - 1) < 0.05 and (
                best is None or filled > best[0]
            ):
                best = (filled, e)
    return None if best is None else best[1]


def levels(img: NDArray[np.uint8], rim: Ellipse) -> tuple[float, float]:
    """Median grey levels of the platter (inside 0.9 of the rim) and of what surrounds it."""
    inner = rim.mask(img.shape, 0.9)
    ring = rim.mask(img.shape, 1.15) & ~rim.mask(img.shape, 1.05)
    outside = float(np.median(img[ring])) if ring.any() else float(np.median(img[~inner]))
    return float(np.median(img[inner])), outside


def rim_points(
    img: NDArray[np.uint8], rim: Ellipse, mid: float, n: int = 360, reach: float = 6.0
) -> NDArray[np.float64]:
    """Points of the rim to a fraction of a pixel: where the grey level crosses ``mid`` along
    the normal of ``rim`` at ``n`` angles (the crossing nearest the ellipse)."""
    s = np.linspace(0, 2 * math.pi, n, endpoint=False)
    c, si = math.cos(rim.angle), math.sin(rim.angle)
    u1, u2 = np.array([c, si]), np.array([-si, c])
    on = (
        np.array(rim.centre) + (rim.a * np.cos(s))[:, None] * u1 + (rim.b * np.sin(s))[:, None] * u2
    )
    normal = (rim.b * np.cos(s))[:, None] * u1 + (rim.a * np.sin(s))[:, None] * u2
    normal /= np.linalg.norm(normal, axis=1, keepdims=True)
    steps = np.arange(-reach, reach + 1e-9, 0.25)
    pts = on[:, None, :] + steps[None, :, None] * normal[:, None, :]
    smooth = cv2.GaussianBlur(img.astype(np.float32), (0, 0), 1.0)
    prof = cv2.remap(
        smooth,
        pts[..., 0].astype(np.float32),
        pts[..., 1].astype(np.float32),
        cv2.INTER_LINEAR,
        borderMode=cv2.BORDER_REPLICATE,
    ) - np.float32(mid)
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


def refine_rim(img: NDArray[np.uint8], rim: Ellipse, mid: float) -> tuple[Ellipse, NDArray]:
    """The rim fitted again to its points to a fraction of a pixel, outliers (the ball or
    the mark at the rim) left out; returns the ellipse and the points kept."""
    pts = rim_points(img, rim, mid)
    for _ in range(3):
        if len(pts) < 20:
            break
        rim = fit_ellipse(pts)
        dev = (rim.radius(pts) - 1.0) * rim.b
        spread = 1.4826 * np.median(np.abs(dev - np.median(dev))) + 0.05
        pts = pts[np.abs(dev) < 4 * spread]
        pts = rim_points(img, rim, mid) if _ == 0 else pts
    return rim, pts


class Blob(NamedTuple):
    """A blob: centroid (u, v) in px, area in px, whether it touches the masked region."""

    u: float
    v: float
    area: float
    touches: bool


def blobs(
    img: NDArray[np.uint8],
    box: tuple[slice, slice],
    level: float,
    sign: float,
    threshold: float,
    allowed: NDArray[np.bool_],
) -> list[Blob]:
    """The blobs of a window of the image that differ from ``level`` by more than
    ``threshold`` in the direction ``sign``, counting only the ``allowed`` pixels."""
    sub = (img[box].astype(np.float32) - np.float32(level)) * np.float32(sign)
    ok = allowed[box]
    sub[~ok] = 0.0
    mask = (sub > threshold).astype(np.uint8)
    n, labels, stats, _ = cv2.connectedComponentsWithStats(mask, connectivity=8)
    out = []
    weight = np.clip(sub / np.float32(2 * threshold), 0.0, 1.0)
    v0, u0 = box[0].start, box[1].start
    kernel = np.ones((5, 5), np.uint8)
    for i in range(1, n):
        x, y, w, h, _area = stats[i]
        sl = (
            slice(max(y - 2, 0), min(y + h + 2, mask.shape[0])),
            slice(max(x - 2, 0), min(x + w + 2, mask.shape[1])),
        )
        region = cv2.dilate((labels[sl] == i).astype(np.uint8), kernel).astype(bool)
        wt = weight[sl] * region
        total = float(wt.sum())
        if total <= 0:
            continue
        vv, uu = np.mgrid[sl[0], sl[1]]
        touches = (
            bool((region & ~ok[sl]).any())
            or (x == 0 and u0 == 0)
            or (y == 0 and v0 == 0)
            or (x + w >= img.shape[1] - u0)
            or (y + h >= img.shape[0] - v0)
        )
        out.append(
            Blob(
                float((wt * uu).sum() / total) + u0,
                float((wt * vv).sum() / total) + v0,
                total,
                touches,
            )
        )
    return out


def window(centre: tuple[float, float], half: float, shape: tuple[int, int]) -> tuple[slice, slice]:
    """The window of half-width ``half`` px about ``centre``, cut to the image."""
    u, v = centre
    return (
        slice(max(int(v - half), 0), min(int(v + half) + 2, shape[0])),
        slice(max(int(u - half), 0), min(int(u + half) + 2, shape[1])),
    )
