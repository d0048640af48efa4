"""A ball beside a label of its own hue but paler (a red ball by a salmon label), its shadow
on the label: told from the label by *chromaticity*, which shading leaves as it is.

A pixel's distance in CIELAB from the ball's colour and from the label's does not tell the
ball's shaded limb (a dark red) from the ball's shadow on the label (a dark salmon): both lie
about as far from either (``turntable.video.blobs``).  Their chromaticity (``chromaticity``:
each linear RGB channel's share of the three) is that of their surface in any light: a red
ball's red channel carries 0.87 of it, a salmon label's 0.75.  A blend of the ball with the
grey platter, on the ball's rim, has the label's chromaticity as well (the label is about
the ball's colour mixed with grey): chromaticity tells the ball from the label only on the
rays that end on the label (``on_label``), and the share is kept on the others
(``told_apart``).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from turntable.video.rays import along_rays

try:
    import cv2
except ImportError:  # without the extra [video]
    cv2 = None

__all__ = ["BEYOND", "chromaticity", "on_label", "told_apart"]

#: A ray ends on the label where the median of its share at these many of the ball's radii
#: from where the ball is predicted lies above the blob's threshold: beyond the ball and its
#: prediction's error (`turntable.video.blobs.MERGED_REACH`), within its shadow's reach.
BEYOND = (1.3, 1.5, 1.7)


def chromaticity(lab_img: NDArray) -> NDArray[np.float32]:
    """Each linear RGB channel's share of the three, of CIELAB colours (..., 3)."""
    lab_img = np.asarray(lab_img, np.float32)
    flat = np.ascontiguousarray(lab_img.reshape(-1, 1, 3))
    rgb = cv2.cvtColor(flat, cv2.COLOR_Lab2LRGB).reshape(lab_img.shape)
    return rgb / np.maximum(rgb.sum(axis=-1, keepdims=True), np.float32(1e-3))


def on_label(share: NDArray[np.float32], start, radius: float, rays: int, threshold: float):
    """Which of ``rays`` rays from ``start`` end on the label: their share at `BEYOND` radii
    above ``threshold``."""
    angles = np.linspace(0.0, 2 * np.pi, rays, endpoint=False)
    seen = along_rays(share, start, angles, radius * np.array(BEYOND, np.float32))
    return np.median(seen, axis=1) > threshold


def told_apart(lab_img, edge, targets, other, start, radius: float, label) -> NDArray:
    """``edge`` weighed, about the rays ``label`` (`on_label`), by how much nearer the ball's
    chromaticity a pixel's lies than that of ``other`` (the label's CIELAB colour): 1 on the
    ball, 0 on the label and on the ball's shadow on it, 1/2 half-way."""
    h, w = edge.shape
    mine = chromaticity(lab_img)
    to_ball = np.minimum.reduce([np.linalg.norm(mine - chromaticity(t), axis=-1) for t in targets])
    to_other = np.linalg.norm(mine - chromaticity(other), axis=-1)
    nearer = np.clip(0.5 + (to_other - to_ball) / np.maximum(to_other + to_ball, 1e-6), 0, 1)
    vv, uu = np.mgrid[0:h, 0:w]
    angle = np.arctan2(vv - start[1], uu - start[0]) % (2 * np.pi)
    ray = np.rint(angle * (len(label) / (2 * np.pi))).astype(int) % len(label)
    return np.where(label[ray], edge * nearer, edge).astype(np.float32)
