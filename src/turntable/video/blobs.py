"""Blobs of one colour on the platter: where a window of a picture lies nearer a target's
colour than the platter's, as components with their centres to a fraction of a pixel.

A pixel's *share* is its CIELAB colour's step from the platter's towards the target's,
as a fraction of the whole step: 0 on the platter, 1 on the target.  A blob is a connected
component of shares above `THRESHOLD` (a shadow, a groove or the platter's grain stays below
it), its holes filled (a highlight).  Its centre weighs each pixel of the filled blob by 1,
and each pixel of the one-pixel band about it by the part of it the blob covers: its share
ramped from 0 at `FLOOR` to 1 at 1 - `FLOOR` (1/2 at 1/2), so that neither the shading of a
ball nor a shadow beside it (a share below `FLOOR`) pulls the centre aside.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

from turntable.video.decode import Picture, lab

try:
    import cv2
except ImportError:  # without the extra [video]
    cv2 = None

#: A pixel belongs to a blob where its share is above this.
THRESHOLD = 0.45
#: In the band about a blob, the share below which a pixel does not count.
FLOOR = 0.25

_KERNEL = np.ones((3, 3), np.uint8)


class Colour(NamedTuple):
    """What is looked for: its CIELAB colour, and the platter's."""

    target: NDArray[np.float64]
    platter: NDArray[np.float64]

    def share(self, lab_img: NDArray[np.float32]) -> NDArray[np.float32]:
        step = self.target - self.platter
        d = (step / float(step @ step)).astype(np.float32)
        return (lab_img - self.platter.astype(np.float32)) @ d


class Blob(NamedTuple):
    """A blob: centre (u, v) and area (filled, weighted) in px; whether it touches a pixel
    outside the allowed region or the window's cut by the image's edge."""

    u: float
    v: float
    area: float
    touches: bool


def blobs(
    picture: Picture,
    box: tuple[slice, slice],
    colour: Colour,
    allowed: NDArray[np.bool_],
    threshold: float = THRESHOLD,
) -> list[Blob]:
    """The blobs of ``colour`` in the window ``box`` of ``picture`` (only ``allowed`` pixels)."""
    share = colour.share(lab(picture, box))
    ok = allowed[box]
    mask = ((share > threshold) & ok).astype(np.uint8)
    n, labels, stats, _ = cv2.connectedComponentsWithStats(mask, connectivity=8)
    v0, u0 = box[0].start, box[1].start
    height, width = picture.y.shape
    out = []
    for i in range(1, n):
        x, y, w, h, _area = stats[i]
        sl = (
            slice(max(y - 2, 0), min(y + h + 2, mask.shape[0])),
            slice(max(x - 2, 0), min(x + w + 2, mask.shape[1])),
        )
        region = (labels[sl] == i).astype(np.uint8)
        contours, _ = cv2.findContours(region, cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_NONE)
        filled = np.zeros_like(region)
        cv2.drawContours(filled, contours, -1, 1, -1)
        band = cv2.dilate(filled, _KERNEL).astype(bool) & ~filled.astype(bool)
        covered = np.clip((share[sl] - FLOOR) / (1 - 2 * FLOOR), 0.0, 1.0)
        wt = filled.astype(np.float32) + band * covered
        total = float(wt.sum())
        if total <= 0:
            continue
        vv, uu = np.mgrid[sl[0], sl[1]]
        touches = (
            bool((band & ~ok[sl]).any())
            or (x == 0 and u0 == 0)
            or (y == 0 and v0 == 0)
            or (x + w + u0 >= width)
            or (y + h + v0 >= height)
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
