"""Drawing of the turntable animation with Pillow (no ffmpeg): palette frames, GIF writing.

Top view of the fixed frame Oxyz: the plane turning about O (spokes and rings), the trail of
the ball's centre, the spiral centre (x0, y0), and the ball with a body-fixed texture (six
coloured longitude segments and two polar caps), so that its own rotation shows. Frames use
one fixed palette and no anti-aliasing, so two runs write the same bytes.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
from numpy.typing import NDArray
from PIL import Image, ImageDraw, ImageFont

from turntable._atomic import replacing

# Palette indices and colours (RGB).
WHITE, PLANE, RING, SPOKE, MARK, TRAIL, CENTRE, TEXT, OUTLINE = range(9)
SEGMENTS = (9, 10, 11)  # longitude segments of the ball, repeated twice
CAP_NORTH, CAP_SOUTH = 12, 13
PALETTE = [
    (255, 255, 255), (236, 236, 231), (205, 205, 198), (168, 168, 160), (214, 96, 77),
    (33, 102, 172), (0, 0, 0), (40, 40, 40), (20, 20, 20),
    (230, 171, 2), (27, 158, 119), (117, 112, 179), (178, 24, 43), (60, 60, 60),
]  # fmt: skip


def _font(size: int) -> ImageFont.FreeTypeFont:
    """DejaVu Sans (shipped with matplotlib) at `size` pixels: it has the Greek letters and
    the arrows of the labels."""
    import matplotlib

    path = Path(matplotlib.get_data_path(), "fonts", "ttf", "DejaVuSans.ttf")
    return ImageFont.truetype(str(path), size)


class Panel:
    """One view of half-width `extent` (units of R) about O, `size` pixels wide: a square
    plot between a band for the title above and one for the time below."""

    def __init__(self, size: int, extent: float, title: str) -> None:
        self.size, self.extent, self.title = size, extent, title
        self.scale = size / (2.0 * extent)
        self.font = _font(max(10, size // 24))
        self.band = self.font.size + 6

    def px(self, xy: NDArray[np.float64]) -> NDArray[np.float64]:
        """Pixel coordinates of points (x, y) (y upwards)."""
        xy = np.atleast_2d(xy)
        pixels = np.column_stack([(xy[:, 0] + self.extent), (self.extent - xy[:, 1])]) * self.scale
        return pixels + np.array([0.0, self.band])

    def draw(self, t: float, trail: NDArray, ball: NDArray, q: NDArray, centre: NDArray):
        """The panel at time t: plane turned by t, trail (n, 2), ball at `ball`, attitude q."""
        img = Image.new("P", (self.size, self.size + 2 * self.band), WHITE)
        img.putpalette([c for rgb in PALETTE for c in rgb])
        d = ImageDraw.Draw(img)
        o = self.px(np.zeros(2))[0]
        rim = 0.98 * self.extent * self.scale
        d.ellipse([*(o - rim), *(o + rim)], fill=PLANE, outline=SPOKE, width=2)
        step = 2.0 * max(1, math.ceil(self.extent / 32.0))  # at most 16 rings however wide
        for radius in np.arange(step, self.extent, step) * self.scale:
            d.ellipse([*(o - radius), *(o + radius)], outline=RING)
        for j in range(12):  # spokes turning with the plane (rate Omega = 1)
            a = t + j * np.pi / 6
            end = o + rim * np.array([np.cos(a), -np.sin(a)])
            d.line([*o, *end], fill=MARK if j == 0 else SPOKE, width=3 if j == 0 else 1)
        if len(trail) > 1:
            d.line([tuple(p) for p in self.px(trail)], fill=TRAIL, width=2)
        c = self.px(centre)[0]
        d.line([c[0] - 6, c[1], c[0] + 6, c[1]], fill=CENTRE, width=2)
        d.line([c[0], c[1] - 6, c[0], c[1] + 6], fill=CENTRE, width=2)
        self._ball(img, self.px(ball)[0], q)
        d.text((self.size / 2, 3), self.title, fill=TEXT, font=self.font, anchor="ma")
        d.text((self.size / 2, self.size + 2 * self.band - 3), f"tΩ = {t:5.1f}", fill=TEXT,
               font=self.font, anchor="md")  # fmt: skip
        return img

    def _ball(self, img: Image.Image, c: NDArray, q: NDArray) -> None:
        """Paint the visible (upper) hemisphere of the ball with its body-fixed texture."""
        r = self.scale  # ball radius R in pixels
        i0, j0 = int(np.floor(c[0] - r)), int(np.floor(c[1] - r))
        jj, ii = np.mgrid[j0 : j0 + int(2 * r) + 3, i0 : i0 + int(2 * r) + 3]
        x, y = (ii + 0.5 - c[0]) / r, (c[1] - jj - 0.5) / r
        inside = (x * x + y * y < 1.0) & (ii >= 0) & (jj >= 0)
        inside &= (ii < img.width) & (jj < img.height)
        p = np.stack([x, y, np.sqrt(np.clip(1.0 - x * x - y * y, 0.0, None))], -1)[inside]
        b = p @ q  # body-fixed coordinates of the visible points: Q^T p
        seg = np.floor((np.arctan2(b[:, 1], b[:, 0]) + np.pi) / (np.pi / 3)).astype(int) % 6
        colour = np.asarray(SEGMENTS)[seg % 3]
        colour = np.where(b[:, 2] > 0.8, CAP_NORTH, np.where(b[:, 2] < -0.8, CAP_SOUTH, colour))
        rim = (x * x + y * y)[inside] > (1.0 - 2.0 / r) ** 2
        pixels = np.asarray(img).copy()
        pixels[jj[inside], ii[inside]] = np.where(rim, OUTLINE, colour)
        img.paste(Image.fromarray(pixels, mode="P"))


def side_by_side(frames: list[Image.Image], gap: int = 4) -> Image.Image:
    """Join panels left to right with a white gap."""
    out = Image.new("P", (sum(f.width for f in frames) + gap * (len(frames) - 1),
                          frames[0].height), WHITE)  # fmt: skip
    out.putpalette([c for rgb in PALETTE for c in rgb])
    x = 0
    for f in frames:
        out.paste(f, (x, 0))
        x += f.width + gap
    return out


def save_gif(frames: list[Image.Image], path: str | Path, frame_ms: int) -> None:
    """Write an endlessly looping GIF atomically (temporary file, then rename)."""
    with replacing(path) as tmp:
        frames[0].save(
            tmp, format="GIF", save_all=True, append_images=frames[1:], duration=frame_ms,
            loop=0, optimize=False,
        )  # fmt: skip
