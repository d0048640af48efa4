"""Stage 4, following the ball and the mark from frame to frame.

Each is looked for in a window about where its last steps predict it (the mark along its
circle about the rim's centre), as a blob of its own colour (`turntable.video.blobs`) of
about its own size; a ball whose blob runs into a label of a like colour, by its
outline; a ball of two colours (``ball_colours``), by both.  Where the mark passes next to
the ball, so that their images may touch, neither is measured on that frame; a frame where
the ball is not found is a gap, never a guessed position.  The rim's points are collected
on ``RIM_FRAMES`` frames spread over the video.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

from turntable.video import camera
from turntable.video.blobs import Blob, blobs, merged_ball
from turntable.video.camera import Pose
from turntable.video.colours import Colour, Colours
from turntable.video.decode import Picture, VideoError, lab, rgb, window
from turntable.video.find import RIM_MARGIN_PX, Candidate, Found
from turntable.video.platter import Ellipse, Platter, rim_points_again
from turntable.video.seeds import Seed, end_before
from turntable.video.two_colours import ball_colours

#: Rim points are collected on this many frames, spread over the video (every
#: ``RIM_EVERY`` frames where the video does not say how many it has).
RIM_FRAMES, RIM_EVERY = 12, 30
#: The ball's blob is taken within these factors of its area where first found, or of its
#: area on the first frame, until it is found (``BALL_AREA_FIRST``: the probe's blobs are
#: cut at another threshold).
BALL_AREA, BALL_AREA_FIRST = (0.5, 1.7), (0.4, 2.5)
#: A seed after the first frame takes a blob whose centre is within this many radii of the
#: ball's image: a seed on its edge, the blob's centre moved by a shadow by half a radius.
SEED_ON_BALL = 1.5
#: The ball's window reaches ``BALL_WINDOW`` of its radii and ``WINDOW_PX`` px about where it
#: is predicted, and its step and 2 radii more for each frame it is not found.
BALL_WINDOW, WINDOW_PX = 2.5, 4.0
#: A lost ball is looked for where its last step leads over at most this many frames.
COAST = 5
#: The mark's blob within these factors of its own (``MARK_AREA_FIRST`` until found).
MARK_AREA, MARK_AREA_FIRST = (0.25, 4.0), (0.2, 5.0)
#: The mark's window reaches ``MARK_WINDOW`` of its radii and `WINDOW_PX` px about where it
#: is predicted, and its step (2 px more) for each frame since it was found.
MARK_WINDOW = 3.0
#: A blob of more than this many times the area of the ball's circle whose outline is not
#: found (its centre its centroid) may be the ball run into something of a like share (a
#: cream ring on a label beside a white ball: 1.7, its centroid 1.4 R off the ball): the
#: ball is looked for by its outline about where it is predicted first (`merged_ball`).
#: A ball's own blob covers 0.85-1.06 of its circle on S13's frames.
ALONE_AREA = 1.3
#: A blob is taken for the nearest to the prediction, its distance (px) and this many times
#: its area's log-ratio to the expected one added.
AREA_WEIGHT = 3.0
#: The ball's and the mark's images may touch within this many px more than their radii:
#: neither is measured then.
TOUCH_PX = 4.0
#: The ball is inside the image where it lies ``EDGE_RADII`` of its radii and ``EDGE_PX`` px
#: from its edge.
EDGE_RADII, EDGE_PX = 1.5, 2.0
#: The ball or the mark not found for at least this long (s) and this many frames is lost,
#: not in a gap: where it is is no longer predicted well enough to take the next blob of its
#: colour for it.  A seed in a later frame (`turntable.video.seeds`) follows it from there.
MAX_GAP_S, MAX_GAP_FRAMES = 0.5, 10
#: The mark's turn from where it was last seen within these factors of the platter's (the
#: image's angles about the rim's centre are the plane's within a factor 1 / cos(tilt)), where
#: the platter turns by at least `TURN_SEEN` (rad) in between.
TURN_AGREE, TURN_SEEN = (0.4, 2.5), 0.03


class Paths(NamedTuple):
    """What following gives: per frame, the time (s), the ball's centre, its area (px) and
    the mark's centre (px, nan where not measured); the rim's points and how many frames they
    come from; per frame, the radius (px) of the ball's part, lit or shaded, in the circle
    through its outline (`turntable.video.blobs.Blob`'s ``disc``), if measured."""

    t: NDArray[np.float64]
    ball: NDArray[np.float64]
    ball_area: NDArray[np.float64]
    mark: NDArray[np.float64]
    rim_points: NDArray[np.float64]
    rim_frames: int
    ball_disc: NDArray[np.float64] | None = None


class Seeds(NamedTuple):
    """Seeds by frame (`turntable.video.seeds`); those of the first frame placed the ball and
    the mark already (`turntable.video.find`)."""

    ball: dict[int, Seed]
    mark: dict[int, Seed]


class LostAt(NamedTuple):
    """Where the ball or the mark was lost: the frame (RGB), its number and the ball and the
    mark where they were last seen (``turntable.video.find.Candidate``), for drawing."""

    image: NDArray[np.uint8]
    candidates: list[Candidate]
    frame: int


class _State:
    """What is followed: the last position and the step per frame, known from the second
    frame it is found on (the first is the frame of ``uv``); its area (px) where first
    found, and the time it was last found; where it was lost (frame, time, picture) while
    it is not found, and whether it is given up until its next seed."""

    def __init__(self, uv: NDArray) -> None:
        self.last: NDArray = uv
        self.step: NDArray | None = None
        self.misses = 0
        self.seen = False
        self.area: float | None = None
        self.reseeded = False
        self.t_last: float | None = None
        self.lost_at: tuple[int, float, NDArray[np.uint8]] | None = None
        self.given_up = False

    def predict(self) -> NDArray:
        """Where the last step leads (over at most `COAST` frames)."""
        if self.step is None:
            return self.last
        return self.last + min(self.misses + 1, COAST) * self.step

    def speed(self) -> float | None:
        """Px per frame, once known."""
        return None if self.step is None else float(np.hypot(*self.step))

    def found(self, uv: NDArray, area: float, t: float) -> None:
        if self.seen:
            self.step = (uv - self.last) / (self.misses + 1)
        self.last, self.misses, self.seen, self.lost_at = uv, 0, True, None
        self.area, self.t_last, self.reseeded = self.area or area, t, False

    def miss(self, index: int, t: float, picture: Picture) -> None:
        if self.misses == 0 and not self.given_up:
            self.lost_at = (index, t, rgb(picture))
        self.misses += 1

    def reference_area(self, first: float) -> float | None:
        """The area its blob is compared with: its own where first found, else ``first`` (in
        the first frame); none where it is seeded again (the blob at the seed, of any size)."""
        return None if self.reseeded else self.area or first

    def lost_too_long(self, t: float) -> bool:
        """Not found for longer than a gap can be."""
        return (
            self.lost_at is not None
            and self.misses >= MAX_GAP_FRAMES
            and t - self.lost_at[1] >= MAX_GAP_S
        )

    def reseed(self, uv: NDArray) -> None:
        """Followed again from ``uv``, its step not known."""
        self.last, self.step, self.misses, self.seen = uv, None, 0, False
        self.lost_at, self.given_up, self.area, self.t_last = None, False, None, None
        self.reseeded = True


class _Turning(_State):
    """The mark: followed in angle about the rim's centre, in the frame where the rim is a
    circle, so that a prediction across misses stays on the mark's path."""

    def __init__(self, uv: NDArray, rim: Ellipse, rate: float | None = None) -> None:
        super().__init__(uv)
        self.rim, self.rate = rim, rate
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

    def found(self, uv: NDArray, area: float, t: float) -> None:
        if self.seen:
            step = self._polar(uv)[0] - self._polar(self.last)[0]
            self.turn = ((step + math.pi) % (2 * math.pi) - math.pi) / (self.misses + 1)
        super().found(uv, area, t)

    def turns_with_the_platter(self, b: Blob, t: float) -> bool:
        """Whether ``b`` at time ``t`` is as far on from where the mark was last seen as the
        platter turns (within `TURN_AGREE`), where that is far enough to tell
        (`TURN_SEEN`): a bright spot that stays where it is is not the mark."""
        if self.rate is None or self.t_last is None:
            return True
        expected = self.rate * (t - self.t_last)
        if expected < TURN_SEEN:
            return True
        step = self._polar(np.array([b.u, b.v]))[0] - self._polar(self.last)[0]
        turn = abs((step + math.pi) % (2 * math.pi) - math.pi)
        return TURN_AGREE[0] * expected <= turn <= TURN_AGREE[1] * expected

    def reseed(self, uv: NDArray) -> None:
        """Followed again from ``uv``, turning as before."""
        step = self.step
        super().reseed(uv)
        self.step = step


def _pick(found: list[Blob], near: NDArray, area: float | None, factors) -> Blob | None:
    """The blob nearest ``near`` and of nearly ``area`` (within ``factors``; any if None)."""
    if area is None:
        return min(found, key=lambda b: math.hypot(b.u - near[0], b.v - near[1]), default=None)
    ok = [b for b in found if factors[0] * area < b.area < factors[1] * area]
    if not ok:
        return None
    return min(
        ok,
        key=lambda b: (
            math.hypot(b.u - near[0], b.v - near[1]) + AREA_WEIGHT * abs(math.log(b.area / area))
        ),
    )


def _inside_image(b: Blob, shape: tuple[int, int], r_px: float) -> bool:
    m = EDGE_RADII * r_px + EDGE_PX
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
    seeds: Seeds | None = None,
) -> Paths:
    """Follow the ball and the mark through ``frames`` (see the module's docstring).

    ``frame_count`` (0 if unknown) spreads the rim's frames; ``mark_step`` is how far (px)
    the mark may move in one frame before its rate is known; ``pose`` (the camera the rim
    gives) and ``ball_radius`` (m) give the radius of the ball's image where it is;
    ``seeds`` (the seeds of the frames after the first) put the ball or the mark where they
    say, in their frames, and following goes on from there.

    Raises
    ------
    VideoError
        The ball reaching the platter's rim or the image's edge; the ball or the mark lost
        for longer than a gap can be (`MAX_GAP_S`, `MAX_GAP_FRAMES`) with no seed after it,
        or not found at a seed.  Its ``found`` is a `LostAt` where one of them was lost.
    """
    seeds = seeds or Seeds({}, {})
    run = _Run(frame_count, platter, rim_points, found, mark_step, pose, ball_radius, seeds)
    index = -1
    for index, t, picture in frames:
        run.frame(index, t, picture)
    _refuse_seeds_past_the_end(seeds, index)
    return run.paths()


class _Run:
    """Following through the frames: the ball's and the mark's states, and what each frame
    adds to the paths."""

    def __init__(  # the arguments of `follow`
        self, frame_count, platter, rim_points, found, mark_step, pose, ball_radius, seeds
    ) -> None:
        rim = platter.rim
        self.platter, self.found, self.seeds = platter, found, seeds
        self.mark_step, self.pose, self.ball_radius = mark_step, pose, ball_radius
        self.every = max(frame_count // RIM_FRAMES, 1) if frame_count else RIM_EVERY
        self.sizes = _Sizes(
            math.sqrt(found.ball.area / math.pi), math.sqrt(found.mark.area / math.pi)
        )
        self.ball = _State(np.array([found.ball.u, found.ball.v]))
        self.mark = _Turning(np.array([found.mark.u, found.mark.v]), rim, found.mark_rate)
        self.times, self.ball_uv, self.areas, self.mark_uv = [], [], [], []
        self.discs: list[float] = []
        self.rim_pts = [rim_points]
        self.allowed = None
        self.ball_colour: Colour | Colours | None = None

    def frame(self, index: int, t: float, picture: Picture) -> None:
        """Follow both on one frame."""
        ball, mark, found, seeds = self.ball, self.mark, self.found, self.seeds
        rim = self.platter.rim
        if self.allowed is None:
            self.allowed = rim.mask(picture.shape, 1.0 - RIM_MARGIN_PX / rim.b)
            self.ball_colour = ball_colours(picture, found)
        self.times.append(t)
        # the rim's points, on frames spread over the video
        if index % self.every == 0 and index:
            self.rim_pts.append(rim_points_again(self.platter.level(lab(picture)), rim))
        # a seed of this frame puts the ball or the mark where it says
        if index:
            _reseed(ball, seeds.ball.get(index))
            _reseed(mark, seeds.mark.get(index))
        # the ball, refused at the rim or the image's edge; the mark, unless it touches it
        got = m = None
        if not ball.given_up:
            r = (self.pose, self.ball_radius, self.sizes, rim.a)
            got = _ball_blob(picture, ball, found, self.ball_colour, self.allowed, *r)
            _refuse_at_the_edge(got, picture, self.sizes.ball, index, t)
        if not mark.given_up:
            r = (got, self.sizes, self.mark_step, t)
            got, m = _mark_blob(picture, mark, found, self.allowed, *r)
        for state, blob in ((ball, got), (mark, m)):
            if blob is None:
                state.miss(index, t, picture)
            else:
                state.found(np.array([blob.u, blob.v]), blob.area, t)
        self.ball_uv.append((math.nan, math.nan) if got is None else (got.u, got.v))
        self.areas.append(math.nan if got is None else got.area)
        self.discs.append(math.nan if got is None else got.disc)
        self.mark_uv.append((math.nan, math.nan) if m is None else (m.u, m.v))
        # a seed where nothing is found, or one of them lost for longer than a gap can be
        _check_seeded(seeds, index, got, m, found, picture)
        _give_up_or_refuse(ball, "ball", seeds.ball, index, t, found, ball, mark)
        _give_up_or_refuse(mark, "mark", seeds.mark, index, t, found, ball, mark)

    def paths(self) -> Paths:
        """What the frames so far give."""
        return Paths(
            np.array(self.times),
            np.array(self.ball_uv).reshape(-1, 2),
            np.array(self.areas),
            np.array(self.mark_uv).reshape(-1, 2),
            np.vstack(self.rim_pts),
            len(self.rim_pts),
            np.array(self.discs),
        )


class _Sizes(NamedTuple):
    """Radii (px) of the ball's and the mark's images in the first frame."""

    ball: float
    mark: float


def _ball_blob(
    picture, ball, found: Found, colour, allowed, pose, ball_radius, sizes: _Sizes, reach
):
    """The ball's blob of ``colour`` in a window about where it is predicted, at most
    ``reach`` px from it (None if not found)."""
    near = ball.predict()
    v = ball.speed()
    r_px = sizes.ball
    half = BALL_WINDOW * r_px + WINDOW_PX + (ball.misses + 1) * (0 if v is None else v + 2 * r_px)
    half = min(half, reach)  # a ball lost for long: looked for about where it was
    box = window(tuple(near), half, picture.shape)
    radius = float(camera.image_radius(pose, near, ball_radius)[0])
    seen = [
        b for b in blobs(picture, box, colour, allowed, outline=radius) if b.touches or not b.cut
    ]
    if ball.reseeded:  # a seed's ball: under the seed, of the first frame's ball's size there
        first = float(camera.image_radius(pose, [(found.ball.u, found.ball.v)], ball_radius)[0])
        seen = [b for b in seen if math.hypot(b.u - near[0], b.v - near[1]) < SEED_ON_BALL * radius]
        got = _pick(seen, near, found.ball.area * (radius / first) ** 2, BALL_AREA_FIRST)
    else:
        got = _pick(
            seen,
            near,
            ball.reference_area(found.ball.area),
            BALL_AREA if ball.area else BALL_AREA_FIRST,
        )
    if got is None:
        got = merged_ball(picture, box, colour, near, radius)
    elif not got.outlined and got.area > ALONE_AREA * math.pi * radius**2:
        got = merged_ball(picture, box, colour, near, radius) or got
    return got


def _refuse_at_the_edge(got: Blob | None, picture, r_px: float, index: int, t: float) -> None:
    if got is not None and got.touches:
        where = (
            "the platter's rim" if _inside_image(got, picture.shape, r_px) else "the image's edge"
        )
        raise VideoError(
            f"the ball reaches {where} at frame {index} (t = {t:.3f} s): "
            + (
                f"end the film before it does, {end}"
                if (end := end_before(index))
                else "too soon for a film to end before it"
            )
        )


def _mark_blob(picture, mark: _Turning, found: Found, allowed, got, sizes: _Sizes, mark_step, t):
    """The ball's blob and the mark's, unless the mark passes so close to the ball that their
    images may touch: then neither is measured on this frame."""
    near = mark.predict()
    v = mark.speed()
    r_px, r_mark = sizes
    if got is not None and math.hypot(got.u - near[0], got.v - near[1]) < r_px + r_mark + TOUCH_PX:
        return None, None
    half = (
        MARK_WINDOW * r_mark + WINDOW_PX + (mark_step if v is None else v + 2) * (mark.misses + 1)
    )
    box = window(tuple(near), half, picture.shape)
    candidates = [
        b
        for b in blobs(picture, box, found.mark_colour, allowed)
        if (got is None or math.hypot(b.u - got.u, b.v - got.v) > r_px)
        and mark.turns_with_the_platter(b, t)
    ]
    m = _pick(
        candidates,
        near,
        mark.reference_area(found.mark.area),
        MARK_AREA if mark.area else MARK_AREA_FIRST,
    )
    return got, m


def _reseed(state: _State, seed: Seed | None) -> None:
    if seed is not None:
        state.reseed(np.array([seed.u, seed.v]))


def _option(name: str) -> str:
    return "--ball-at" if name == "ball" else "--mark-at"


def _seen_last(found: Found, ball: _State, mark: _State) -> list[Candidate]:
    """The ball and the mark where they were last seen, as candidates to draw."""
    return [
        found.ball._replace(u=float(ball.last[0]), v=float(ball.last[1])),
        found.mark._replace(u=float(mark.last[0]), v=float(mark.last[1])),
    ]


def _check_seeded(seeds: Seeds, index: int, got, m, found: Found, picture: Picture) -> None:
    """Refuse a seed after the first frame where nothing of its colour is found (on the
    first, the search found it: a mark in a lamp's spot is followed out of it)."""
    for name, seed, blob in (("ball", seeds.ball, got), ("mark", seeds.mark, m)):
        if not index or index not in seed or blob is not None:
            continue
        other = "mark" if name == "ball" else "ball"
        where = getattr(found, name)._replace(u=seed[index].u, v=seed[index].v)
        raise VideoError(
            f"{_option(name)} {seed[index]}: the {name} is not found there (nothing of its "
            f"colour and size, or the {other} next to it); --plot draws frame {index}",
            LostAt(rgb(picture), [where], index),
        )


def _give_up_or_refuse(state, name, later, index, t, found, ball, mark) -> None:
    """A thing lost for longer than a gap can be is given up until its next seed; with no
    seed after it, the video is refused, naming the frame where it was lost."""
    if state.given_up or not state.lost_too_long(t):
        return
    if any(frame > index for frame in later):
        state.given_up = True
        return
    frame, at, image = state.lost_at
    seen = _seen_last(found, ball, mark)
    if state.t_last is None and frame in later:  # not found once from its seed
        raise VideoError(
            f"{_option(name)} {later[frame]}: the {name} is not followed from there (not found "
            f"for {state.misses} frames): put the seed on the {name}; --plot draws frame {frame}",
            LostAt(image, seen, frame),
        )
    raise VideoError(
        f"the {name} is lost at frame {frame} (t = {at:.3f} s) and not found for "
        f"{state.misses} frames ({t - at:.2g} s): give {_option(name)} {frame}:U,V, a pixel "
        f"on it in frame {frame} (or in a later frame where it is seen)"
        + (f", or {end} to end the film before it" if (end := end_before(frame)) else "")
        + f"; --plot draws frame {frame}",
        LostAt(image, seen, frame),
    )


def _refuse_seeds_past_the_end(seeds: Seeds, last: int) -> None:
    for name, later in (("ball", seeds.ball), ("mark", seeds.mark)):
        for frame, seed in later.items():
            if frame > last:
                raise VideoError(
                    f"{_option(name)} {seed}: frame {frame} is past the end of the video "
                    f"(frames 0-{last})"
                )


__all__ = ["Colour", "LostAt", "Paths", "Seeds", "follow"]
