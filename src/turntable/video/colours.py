"""What a blob is looked for by: a colour and the platter's, and each pixel's *share* of the
step from the platter's colour to it (``turntable.video.blobs``).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

__all__ = ["EDGE_LIGHTNESS", "OFF_LINE", "Colour", "Colours"]

#: Colours farther than this, in units of the step from the platter's colour to the
#: target's, from the line between them have no share.
OFF_LINE = 0.6
#: Lightness difference (CIELAB) from which a blob's outline is found in lightness alone.
EDGE_LIGHTNESS = 15.0


class Colour(NamedTuple):
    """What is looked for: its CIELAB colour, and the platter's."""

    target: NDArray[np.float64]
    platter: NDArray[np.float64]

    def share(self, lab_img: NDArray[np.float32]) -> NDArray[np.float32]:
        """The share, 0 where a colour lies farther than `OFF_LINE` times the step from the
        line between the platter's and the target's (a label of another hue, say)."""
        step = (self.target - self.platter).astype(np.float32)
        step2 = float(step @ step)
        diff = lab_img - self.platter.astype(np.float32)
        along = diff @ step  # share * |step|^2
        # off the line: |diff|^2 - along^2 / |step|^2 > (OFF_LINE |step|)^2
        off2 = np.einsum("...i,...i->...", diff, diff) * step2 - along * along
        share = along / np.float32(step2)
        share[off2 > np.float32(OFF_LINE**2 * step2 * step2)] = 0.0
        return share

    @property
    def targets(self) -> list[NDArray[np.float64]]:
        """The colour looked for, as `Colours` has its colours."""
        return [self.target]

    @property
    def lines(self) -> list[tuple[NDArray[np.float64], NDArray[np.float64]]]:
        """(platter, target): the line of colours from the platter's to the target's."""
        return [(self.platter, self.target)]

    def edge_share(
        self, lab_img: NDArray[np.float32], share: NDArray[np.float32] | None = None
    ) -> NDArray[np.float32]:
        """The share in lightness alone where lightness makes at least half of the colours'
        distance, and `EDGE_LIGHTNESS` or more (the chroma of a 4:2:0 video has half the
        resolution), else `share` (that of ``lab_img``, if already computed)."""
        step = float(self.target[0] - self.platter[0])
        distance = float(np.linalg.norm(self.target - self.platter))
        share = self.share(lab_img) if share is None else share
        if abs(step) < max(EDGE_LIGHTNESS, 0.5 * distance):
            return share
        lightness = (lab_img[..., 0] - np.float32(self.platter[0])) / np.float32(step)
        return np.where(share == 0.0, np.float32(0.0), lightness)


class Colours(NamedTuple):
    """A ball of several colours (white with red squares, say), each on the line from the
    platter's: a pixel's share is the largest of its shares of them."""

    colours: tuple[Colour, ...]

    @property
    def targets(self) -> list[NDArray[np.float64]]:
        """The colours looked for (CIELAB)."""
        return [c.target for c in self.colours]

    @property
    def lines(self) -> list[tuple[NDArray[np.float64], NDArray[np.float64]]]:
        """The colours' `Colour.lines`."""
        return [(c.platter, c.target) for c in self.colours]

    def share(self, lab_img: NDArray[np.float32]) -> NDArray[np.float32]:
        """The largest of the colours' `Colour.share`."""
        return np.maximum.reduce([c.share(lab_img) for c in self.colours])

    def edge_share(
        self, lab_img: NDArray[np.float32], share: NDArray[np.float32] | None = None
    ) -> NDArray[np.float32]:
        """The largest of the colours' `Colour.edge_share` (``share`` is not used)."""
        return np.maximum.reduce([c.edge_share(lab_img) for c in self.colours])
