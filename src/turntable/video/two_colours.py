"""The colours the ball is followed by (``turntable.video.follow``): its own, and a second where
the first frame shows one on it (a white ball with red squares).
"""

from __future__ import annotations

import math

import numpy as np

from turntable.video.blobs import THRESHOLD
from turntable.video.colours import Colour, Colours
from turntable.video.decode import Picture, lab, window
from turntable.video.find import Found

__all__ = ["SECOND_CONTRAST", "SECOND_INNER", "SECOND_SHARE", "ball_colours"]

#: A ball of two colours (white with red squares): where at least ``SECOND_SHARE`` of the
#: disc within ``SECOND_INNER`` of its radius on the first frame (its shaded limb left out) is
#: not of the ball's colour but differs from the platter by at least ``SECOND_CONTRAST`` of the
#: ball's colour's distance from it, the ball is followed by both colours: by its colour
#: alone, its blob was one of its squares, its centre off by up to 0.15 R, and lost where the
#: squares turned away.  A highlight or a shaded side covers less of the disc.
SECOND_SHARE, SECOND_INNER, SECOND_CONTRAST = 0.25, 0.7, 0.5


def ball_colours(picture: Picture, found: Found) -> Colour | Colours:
    """The colours the ball is followed by: its own, and a second where the first frame shows
    one on it (`SECOND_SHARE`)."""
    colour, ball = found.ball_colour, found.ball
    r = SECOND_INNER * math.sqrt(ball.area / math.pi)
    box = window((ball.u, ball.v), r, picture.shape)
    pix = lab(picture, box)
    vv, uu = np.mgrid[box[0], box[1]]
    pix = pix[np.hypot(uu - ball.u, vv - ball.v) < r]
    far = SECOND_CONTRAST * np.linalg.norm(colour.target - colour.platter)
    other = (colour.share(pix) < THRESHOLD) & (
        np.linalg.norm(pix - colour.platter.astype(np.float32), axis=-1) > far
    )
    if not len(pix) or other.mean() < SECOND_SHARE:
        return colour
    return Colours((colour, Colour(np.median(pix[other], axis=0).astype(float), colour.platter)))
