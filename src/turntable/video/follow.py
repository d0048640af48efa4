"""Stage 4, following the ball and the mark from frame to frame.

Each is looked for in a window about where its last steps predict it (the mark along its
circle about the rim's centre), as a blob of its own colour (`turntable.video.blobs`) of
about its own size; a ball whose blob runs into a label of a like colour, by its
outline.  Where the mark passes next to the ball, so that their images may touch,
neither is measured on that frame; a frame where the ball is not found is a gap, never a
guessed position.  The rim's points are collected on ``RIM_FRAMES`` frames spread over the
video.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

from turntable.video import camera
from turntable.video.blobs import Blob, Colour, blobs, merged_ball
from turntable.video.camera import Pose
from turntable.video.decode import Picture, VideoError, lab, window
from turntable.video.find import Found
from turntable.video.platter import Ellipse, Platter, rim_points_again

#: Rim points are collected on this many frames, spread over the video.
RIM_FRAMES = 12
#: The ball's blob is taken within these factors of its area on the first frame.
BALL_AREA = (0.5, 1.7)
#: A lost ball is looked for where its last step leads over at most this many frames.
COAST = 5
#: The mark's blob within these factors of its own.
MARK_AREA = (0.25, 4.0)


class Paths(NamedTuple):
    """What following gives: per frame, the time (s), the ball's centre, its area (px) and
    the mark's centre (px, nan where not measured); the rim's points and how many frames they
    come from."""

    t: NDArray[np.float64]
    ball: NDArray[np.float64]
    ball_area: NDArray[np.float64]
    mark: NDArray[np.float64]
    rim_points: NDArray[np.float64]
    rim_frames: int


class _State:
    """What is followed: the last position and the step per frame, known from the second
    frame it is found on (the first is the frame of ``uv``)."""

    def __init__(self, uv: NDArray) -> None:
        self.last: NDArray = uv
        self.step: NDArray | None = None
        self.misses = 0
        self.seen = False

    def predict(self) -> NDArray:
        """Where the last step leads (over at most `COAST` frames)."""
        if self.step is None:
            return self.last
        return self.last + min(self.misses + 1, COAST) * self.step

    def speed(self) -> float | None:
        """Px per frame, once known."""
        return None if self.step is None else float(np.hypot(*self.step))

    def found(self, uv: NDArray) -> None:
        if self.seen:
            self.step = (uv - self.last) / (self.misses + 1)
        self.last, self.misses, self.seen = uv, 0, True

    def miss(self) -> None:
        self.misses += 1


class _Turning(_State):
    """The mark: followed in angle about the rim's centre, in the frame where the rim is a
    circle, so that a prediction across misses stays on the mark's path."""

    def __init__(self, uv: NDArray, rim: Ellipse) -> None:
        super().__init__(uv)
        self.rim = rim
        c, s = math.cos(rim.angle), math.sin(rim.angle)
        self.to_circle = np.array([[c / rim.a, s / rim.a], [-s / rim.b, c / rim.b]])
        self.turn = 0.0

    def _polar(self, uv: NDArray) -> tuple[float, float]:
        p = self.to_circle @ (uv - self.rim.centre)
        return math.atan2(p[1], p[0]), math.hypot(p[0], p[1])

    def predict(self) -> NDArray:
        if self.step is None:
            return self.last
        angle, radius = self._polar(self.last)
        angle += (self.misses + 1) * self.turn
        p = radius * np.array([math.cos(angle), math.sin(angle)])
        return np.linalg.solve(self.to_circle, p) + self.rim.centre

    def found(self, uv: NDArray) -> None:
        if self.seen:
            step = self._polar(uv)[0] - self._polar(self.last)[0]
            self.turn = ((step + math.pi) % (2 * math.pi) - math.pi) / (self.misses + 1)
        super().found(uv)


def _pick(found: list[Blob], near: NDArray, area: float, factors) -> Blob | None:
    ok = [b for b in found if factors[0] * area < b.area < factors[1] * area]
    if not ok:
        return None
    return min(
        ok,
        key=lambda b: math.hypot(b.u - near[0], b.v - near[1]) + 3 * abs(math.log(b.area / area)),
    )


def _inside_image(b: Blob, shape: tuple[int, int], r_px: float) -> bool:
    m = 1.5 * r_px + 2
    return m < b.u < shape[1] - 1 - m and m < b.v < shape[0] - 1 - m


def follow(
    frames: Iterable[tuple[int, float, Picture]],
    frame_count: int,
    platter: Platter,
    rim_points: NDArray[np.float64],
    found: Found,
    mark_step: float,
    pose: Pose,
    ball_radius: float,
) -> Paths:
    """Follow the ball and the mark through ``frames`` (see the module's docstring).

    ``frame_count`` (0 if unknown) spreads the rim's frames; ``mark_step`` is how far (px)
    the mark may move in one frame before its rate is known; ``pose`` (the camera the rim
    gives) and ``ball_radius`` (m) give the radius of the ball's image where it is.

    Raises
    ------
    VideoError
        The ball reaching the platter's rim or the image's edge.
    """
    rim = platter.rim
    every = max(frame_count // RIM_FRAMES, 1) if frame_count else 30
    r_px = math.sqrt(found.ball.area / math.pi)
    r_mark = math.sqrt(found.mark.area / math.pi)
    # the areas as `blobs` measures them, from the first frame
    ball_area: float | None = None
    mark_area: float | None = None
    ball = _State(np.array([found.ball.u, found.ball.v]))
    mark = _Turning(np.array([found.mark.u, found.mark.v]), rim)
    times, ball_uv, areas, mark_uv, rim_pts = [], [], [], [], [rim_points]
    allowed = None
    for index, t, picture in frames:
        if allowed is None:
            allowed = rim.mask(picture.shape, 1.0 - 3.0 / rim.b)
        times.append(t)
        if index % every == 0 and index:
            rim_pts.append(rim_points_again(platter.level(lab(picture)), rim))
        near = ball.predict()
        v = ball.speed()
        half = 2.5 * r_px + 4 + (ball.misses + 1) * (0 if v is None else v + 2 * r_px)
        half = min(half, rim.a)  # a ball lost for long: looked for about where it was
        box = window(tuple(near), half, picture.shape)
        radius = float(camera.image_radius(pose, near, ball_radius)[0])
        got = _pick(
            [
                b
                for b in blobs(picture, box, found.ball_colour, allowed, outline=radius)
                if b.touches or not b.cut
            ],
            near,
            ball_area or found.ball.area,
            BALL_AREA if ball_area else (0.4, 2.5),
        )
        if got is None:
            got = merged_ball(picture, box, found.ball_colour, near, radius)
        if got is not None and ball_area is None:
            ball_area = got.area
        if got is not None and got.touches:
            where = (
                "the platter's rim"
                if _inside_image(got, picture.shape, r_px)
                else "the image's edge"
            )
            raise VideoError(
                f"the ball reaches {where} at frame {index} (t = {t:.3f} s): cut the video "
                "before it does"
            )
        # the mark, unless it passes so close to the ball that their images may touch:
        # then neither is measured on this frame
        near = mark.predict()
        v = mark.speed()
        m = None
        if got is not None and math.hypot(got.u - near[0], got.v - near[1]) < r_px + r_mark + 4:
            got = None
        else:
            half = 3 * r_mark + 4 + (mark_step if v is None else v + 2) * (mark.misses + 1)
            box = window(tuple(near), half, picture.shape)
            candidates = [
                b
                for b in blobs(picture, box, found.mark_colour, allowed)
                if got is None or math.hypot(b.u - got.u, b.v - got.v) > r_px
            ]
            m = _pick(
                candidates,
                near,
                mark_area or found.mark.area,
                MARK_AREA if mark_area else (0.2, 5.0),
            )
            if m is not None and mark_area is None:
                mark_area = m.area
        if got is None:
            ball.miss()
            ball_uv.append((math.nan, math.nan))
            areas.append(math.nan)
        else:
            ball.found(np.array([got.u, got.v]))
            ball_uv.append((got.u, got.v))
            areas.append(got.area)
        if m is None:
            mark.miss()
            mark_uv.append((math.nan, math.nan))
        else:
            mark.found(np.array([m.u, m.v]))
            mark_uv.append((m.u, m.v))
    return Paths(
        np.array(times),
        np.array(ball_uv).reshape(-1, 2),
        np.array(areas),
        np.array(mark_uv).reshape(-1, 2),
        np.vstack(rim_pts),
        len(rim_pts),
    )


__all__ = ["Colour", "Paths", "follow"]
