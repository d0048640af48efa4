"""An image sampled along rays from a point: the profiles that the outlines of the ball
(``turntable.video.blobs``), its limb (``limb``), a ring (``ring``), a label's hue (``hue``)
and chromaticity (``chroma``) are read from.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

try:
    import cv2
except ImportError:  # without the extra [video]
    cv2 = None

__all__ = ["along_rays"]


def along_rays(img: NDArray, start, angles: NDArray, at: NDArray) -> NDArray:
    """``img`` (bilinear, its edge repeated beyond it) at distances ``at`` (px) from ``start``
    (u, v) along rays at ``angles`` (rad): shape (rays, len(at)) and ``img``'s channels."""
    pu = (start[0] + np.cos(angles)[:, None] * at).astype(np.float32)
    pv = (start[1] + np.sin(angles)[:, None] * at).astype(np.float32)
    return cv2.remap(img, pu, pv, cv2.INTER_LINEAR, borderMode=cv2.BORDER_REPLICATE)
