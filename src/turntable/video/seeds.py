"""Seeds: a pixel on the ball or on the mark in a frame of the video, as Tracker's key frames.

``--ball-at N:U,V`` and ``--mark-at N:U,V`` say where the ball and the mark are in frame N
(``U,V`` alone: in the first frame, N = 0); each may be given more than once.  A seed in the
first frame tells the search (`turntable.video.find`) which is which; a seed in a later frame
resumes following (`turntable.video.follow`) from it, where the ball or the mark was lost.
``--last-frame N`` ends the film at frame N, as Tracker's end frame.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterable
from typing import NamedTuple

#: A film has at least this many frames: the mark is found on 10 at least
#: (``turntable.video.track.MIN_MARK_FRAMES``), and the fit compares the models on 20
#: coordinates or more.
MIN_FILM_FRAMES = 20

__all__ = [
    "Seed",
    "by_frame",
    "check_frames",
    "check_last_frame",
    "end_before",
    "on_first_frame",
    "parse_seed",
    "seeds_of",
]


class Seed(NamedTuple):
    """A pixel (u, v) on the ball or the mark in frame ``frame`` (0 the first)."""

    frame: int
    u: float
    v: float

    def __str__(self) -> str:
        return f"{self.frame}:{self.u:g},{self.v:g}"


def parse_seed(text: str) -> Seed:
    """``N:U,V`` or ``U,V`` (frame 0) as a `Seed`.

    Raises
    ------
    ValueError
        Not two finite numbers, or a frame that is not a whole number >= 0; one line.

    Examples
    --------
    >>> parse_seed("812:310.5,92")
    Seed(frame=812, u=310.5, v=92.0)
    >>> parse_seed("310.5,92").frame
    0
    """
    text = text.strip()  # a negative frame reaches here as " -1:U,V" (``turntable.cli``)
    frame_text, _, pixel = text.rpartition(":")
    frame = _frame(frame_text, text) if _ else 0
    try:
        u, v = (float(x) for x in pixel.split(","))
    except ValueError:
        raise ValueError(
            f"expected [N:]U,V (a frame, then two numbers, px); got {text!r}"
        ) from None
    if not (math.isfinite(u) and math.isfinite(v)):
        raise ValueError(f"expected finite U,V; got {text!r}")
    return Seed(frame, u, v)


def _frame(frame_text: str, text: str) -> int:
    try:
        frame = int(frame_text)
    except ValueError:
        raise ValueError(f"the frame N of N:U,V must be a whole number; got {text!r}") from None
    if frame < 0:
        raise ValueError(f"the frame N of N:U,V must be 0 or more (0 is the first); got {text!r}")
    return frame


def seeds_of(value: tuple[float, float] | Iterable[Seed] | None) -> list[Seed]:
    """The seeds of an argument: none, a pixel of the first frame (u, v), or seeds."""
    if value is None:
        return []
    items = list(value)
    if len(items) == 2 and all(isinstance(x, int | float) for x in items):
        return [Seed(0, float(items[0]), float(items[1]))]
    return sorted(Seed(*s) for s in items)


def check_frames(
    option: str,
    seeds: list[Seed],
    frames: int,
    last: int | None = None,
    size: tuple[int, int] | None = None,
) -> None:
    """Refuse two seeds in one frame, a frame past the end of a video of ``frames`` frames
    (0: not known) or after the last frame tracked, ``last``, and a pixel outside an image of
    ``size`` (width, height).

    Raises
    ------
    ValueError
        One line naming the option and the seed.
    """
    for a, b in itertools.pairwise(seeds):
        if a.frame == b.frame:
            raise ValueError(f"{option} is given twice for frame {a.frame} ({a}, {b})")
    for s in seeds:
        if frames and s.frame >= frames:
            raise ValueError(
                f"{option} {s}: frame {s.frame} is past the end of the video "
                f"(frames 0-{frames - 1})"
            )
        if last is not None and s.frame > last:
            raise ValueError(f"{option} {s}: frame {s.frame} is after --last-frame {last}")
        if size is not None and not (0 <= s.u < size[0] and 0 <= s.v < size[1]):
            raise ValueError(f"{option} {s}: outside the image ({size[0]}x{size[1]} px)")


def end_before(frame: int) -> str | None:
    """``--last-frame N`` that ends the film before ``frame``, if that leaves a film."""
    return f"--last-frame {frame - 1}" if frame >= MIN_FILM_FRAMES else None


def check_last_frame(last: int | None, frames: int) -> None:
    """Refuse a last frame that leaves fewer than `MIN_FILM_FRAMES` frames, or past the end
    of a video of ``frames`` frames (0: not known).

    Raises
    ------
    ValueError
        One line naming --last-frame.
    """
    if last is None:
        return
    if last + 1 < MIN_FILM_FRAMES:
        raise ValueError(
            f"--last-frame {last}: a film needs {MIN_FILM_FRAMES} frames at least (0 is the "
            f"first): --last-frame {MIN_FILM_FRAMES - 1} or more"
        )
    if frames and last >= frames:
        raise ValueError(f"--last-frame {last}: past the end of the video (frames 0-{frames - 1})")


def on_first_frame(seeds: list[Seed]) -> tuple[float, float] | None:
    """The pixel of the seed in frame 0, if any (for the search)."""
    return next(((s.u, s.v) for s in seeds if s.frame == 0), None)


def by_frame(seeds: list[Seed]) -> dict[int, Seed]:
    """The seeds by frame (for following)."""
    return {s.frame: s for s in seeds}
