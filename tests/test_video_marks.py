"""The search for the mark (`turntable.video.find`, `turntable.video.marks`) on a speckled
platter: a film drawn here, of a granite-like platter whose specks turn with it as the mark
does, and of a ball."""

from __future__ import annotations

import math

import numpy as np
import pytest

cv2 = pytest.importorskip("cv2")

from turntable.video.calibrate import rim_camera  # noqa: E402
from turntable.video.decode import Picture, lab, yuv420  # noqa: E402
from turntable.video.find import find  # noqa: E402
from turntable.video.platter import find_platter  # noqa: E402

SIZE = (320, 240)  # px
CENTRE = (160.0, 120.0)  # the axis's image, px
RIM_PX = 110.0  # the platter's radius in the image, seen from straight above
P, R = 0.15, 0.0125  # m
RPM, FPS, FRAMES = 45.0, 30.0, 12
MARK_AT = 0.6  # of P from the axis, at angle 0 on the first frame
MARK_PX = 4.0  # the mark's radius, px


def _platter_texture(rng: np.random.Generator) -> np.ndarray:
    """RGB (float) of the platter in its own frame, a square of side 2 RIM_PX + 1 about the
    axis: a grey grain, specks a little lighter than it here and there, and a yellow mark
    of radius MARK_PX at MARK_AT."""
    n = 2 * int(RIM_PX) + 1
    grain = cv2.GaussianBlur(rng.normal(0.0, 20.0, (n, n)).astype(np.float32), (0, 0), 0.8)
    specks = (rng.random((n, n)) < 0.004).astype(np.float32)
    specks = cv2.GaussianBlur(specks, (0, 0), 1.0) * 2 * math.pi * 60.0
    grey = 90.0 + grain + np.clip(specks, 0, 60.0)
    tex = np.dstack([grey, 0.98 * grey, 1.03 * grey])
    v, u = np.mgrid[0:n, 0:n] - RIM_PX
    tex[np.hypot(u - MARK_AT * RIM_PX, v) < MARK_PX] = (235.0, 215.0, 30.0)
    return tex


def _film(seed: int = 3) -> tuple[list[tuple[float, Picture]], tuple[float, float], np.ndarray]:
    """The first frames of a film of the platter turning at RPM seen from straight above, on a
    brown table, with an orange ball of radius R moving across it on its own: (time, picture)
    of each frame, the mark's image on the first frame and the ball's images (px)."""
    rng = np.random.default_rng(seed)
    tex = _platter_texture(rng).astype(np.float32)
    v, u = np.mgrid[0 : SIZE[1], 0 : SIZE[0]].astype(float)
    on_platter = np.hypot(u - CENTRE[0], v - CENTRE[1]) < RIM_PX
    ball_px = R / P * RIM_PX
    omega = RPM * math.pi / 30
    probe, balls = [], []
    for k in range(FRAMES):
        t = k / FPS
        turn = cv2.getRotationMatrix2D((RIM_PX, RIM_PX), -math.degrees(omega * t), 1.0)
        turn[:, 2] += np.array(CENTRE) - RIM_PX
        seen = cv2.warpAffine(tex, turn, SIZE, flags=cv2.INTER_LINEAR)
        img = np.where(on_platter[..., None], seen, np.array([150.0, 105.0, 60.0]))
        ball = (CENTRE[0] - 40.0 + 60.0 * t, CENTRE[1] + 30.0 - 20.0 * t)
        img[np.hypot(u - ball[0], v - ball[1]) < ball_px] = (235.0, 95.0, 20.0)
        frame = yuv420(np.clip(img + 0.5, 0, 255).astype(np.uint8))
        h, w = SIZE[1], SIZE[0]
        y, cb, cr = frame[:h], frame[h : h + h // 4], frame[h + h // 4 :]
        probe.append((t, Picture(y, cb.reshape(h // 2, w // 2), cr.reshape(h // 2, w // 2), False)))
        balls.append(ball)
    mark = (CENTRE[0] + MARK_AT * RIM_PX, CENTRE[1])
    return probe, mark, np.array(balls)


def test_the_mark_is_the_dot_that_stands_out_not_a_speck_nearer_the_rim() -> None:
    """A granite-like platter: among its specks, some nearer the rim than the yellow mark are
    lighter than the grain by just enough to be candidates, and turn with the platter over
    the probe as the mark does.  The search took the one nearest the rim for the mark (the
    ray caster's S02: followed over the film it faded in and out, 7.2 px off a circle, and the
    track was refused); the mark is the dot that stands out, as a person sees at once."""
    probe, mark, balls = _film()
    platter, rim_pts = find_platter(lab(probe[0][1]))
    pose = rim_camera(rim_pts, platter.rim, SIZE, P)
    found = find(probe, platter, pose, R, P, rpm=RPM)
    specks = [
        c
        for c in found.candidates
        if c.turns_at > MARK_AT + 0.05 and np.hypot(c.u - mark[0], c.v - mark[1]) > 3 * MARK_PX
    ]
    assert specks, "no speck nearer the rim turns with the platter: the film tests nothing"
    assert np.hypot(found.mark.u - mark[0], found.mark.v - mark[1]) < 1.0
    assert np.hypot(found.ball.u - balls[0, 0], found.ball.v - balls[0, 1]) < 1.0
