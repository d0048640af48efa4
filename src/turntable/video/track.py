"""From a video to a film: the ball's centre in the lab frame, frame by frame.

`track_video` reads the video once.  On the first frame it finds the platter (`find_platter`,
its rim refined to a fraction of a pixel), the ball (the blob of the platter whose area is
closest to that of a ball of radius R seen there) and the mark (the largest other blob in
the outer part of the platter).  It then follows both from frame to frame in windows about
where their last steps predict them (neither is measured where the mark passes next to the
ball), and collects the rim's points on a dozen frames spread over the video.  `calibrate`
then fits the camera and Omega; the ball's centre is the point R above the platter whose
sphere's image is centred on the blob (`camera.sphere_centre`).  A frame where the ball is
not measured is a gap of the film (never a guessed position), named in the warnings.
"""

from __future__ import annotations

import math
import os
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import NDArray

from turntable.film import Film
from turntable.video import camera
from turntable.video.calibrate import Calibration, calibrate
from turntable.video.decode import Video, VideoError, VideoInfo
from turntable.video.detect import Blob, Ellipse, blobs, find_platter, levels, refine_rim, window

__all__ = ["Track", "track_video"]

#: Rim points are collected on this many frames, spread over the video.
RIM_FRAMES = 12
#: A blob differs from the platter's grey level by at least this many times the platter's
#: spread (and at least `MIN_CONTRAST` levels).
CONTRAST_SPREAD, MIN_CONTRAST = 5.0, 12.0
#: Fewest frames in which the mark must be found.
MIN_MARK_FRAMES = 10


class Track(NamedTuple):
    """A tracked video.

    Attributes
    ----------
    film : Film
        Times (s, from the first frame) and the ball's centre (m) in the lab frame of
        `turntable.video.camera` (the axis at the origin), y mirrored if the platter turns
        clockwise seen from above, so that it turns counterclockwise in (x, y); only the
        frames where the ball was found.
    calibration : Calibration
    info : VideoInfo
    lost : list of int
        Frames where the ball was not found (gaps of the film).
    image : numpy.ndarray
        The ball's image centre (u, v) in px for every frame (nan where lost).
    mark_image : numpy.ndarray
        The mark's image (u, v) in px for every frame (nan where not found).
    rim : Ellipse
    first_frame : numpy.ndarray
        The first frame (grey), for drawing.
    mirrored : bool
        Whether y was mirrored (the platter turns clockwise seen from above).
    times : numpy.ndarray
        Time of every frame, s from the first.
    ball_radius, platter_radius : float
        R and P, m.
    """

    film: Film
    calibration: Calibration
    info: VideoInfo
    lost: list[int]
    image: NDArray[np.float64]
    mark_image: NDArray[np.float64]
    rim: Ellipse
    first_frame: NDArray[np.uint8]
    mirrored: bool
    times: NDArray[np.float64]
    ball_radius: float
    platter_radius: float


def frame_ranges(frames: list[int]) -> str:
    """'3, 7-9, 12' for [3, 7, 8, 9, 12]."""
    out, start = [], None
    for i, f in enumerate(frames):
        if start is None:
            start = f
        if i + 1 == len(frames) or frames[i + 1] != f + 1:
            out.append(str(start) if start == f else f"{start}-{f}")
            start = None
    return ", ".join(out)


class _State:
    """What is followed from frame to frame: the last position and the step per frame."""

    def __init__(self) -> None:
        self.last: NDArray | None = None
        self.step: NDArray | None = None
        self.misses = 0

    def predict(self) -> NDArray:
        assert self.last is not None
        if self.step is None:
            return self.last
        return self.last + (self.misses + 1) * self.step

    def speed(self) -> float | None:
        """Px per frame, once known."""
        return None if self.step is None else float(np.hypot(*self.step))

    def found(self, uv: NDArray) -> None:
        if self.last is not None:
            self.step = (uv - self.last) / (self.misses + 1)
        self.last, self.misses = uv, 0

    def miss(self) -> None:
        self.misses += 1


class _Turning(_State):
    """The mark: followed in angle about the rim's centre, in the frame where the rim is a
    circle, so that a prediction across misses stays on the mark's path."""

    def __init__(self, rim: Ellipse) -> None:
        super().__init__()
        self.rim = rim
        c, s = math.cos(rim.angle), math.sin(rim.angle)
        self.to_circle = np.array([[c / rim.a, s / rim.a], [-s / rim.b, c / rim.b]])
        self.turn = 0.0

    def _polar(self, uv: NDArray) -> tuple[float, float]:
        p = self.to_circle @ (uv - self.rim.centre)
        return math.atan2(p[1], p[0]), math.hypot(p[0], p[1])

    def predict(self) -> NDArray:
        assert self.last is not None
        if self.step is None:
            return self.last
        angle, radius = self._polar(self.last)
        angle += (self.misses + 1) * self.turn
        p = radius * np.array([math.cos(angle), math.sin(angle)])
        return np.linalg.solve(self.to_circle, p) + self.rim.centre

    def found(self, uv: NDArray) -> None:
        if self.last is not None:
            step = self._polar(uv)[0] - self._polar(self.last)[0]
            self.turn = (step + math.pi) % (2 * math.pi) - math.pi
            self.turn /= self.misses + 1
        super().found(uv)


def _pick(found: list[Blob], near: NDArray, area: float) -> Blob | None:
    ok = [b for b in found if 0.25 * area < b.area < 4.0 * area]
    if not ok:
        return None
    return min(
        ok,
        key=lambda b: math.hypot(b.u - near[0], b.v - near[1]) + 3 * abs(math.log(b.area / area)),
    )


def _first(img, rim, platter_level, spread, allowed, ball_area) -> tuple[Blob, float, Blob]:
    """Ball and mark on the first frame, with the sign of the ball's contrast."""
    full = (slice(0, img.shape[0]), slice(0, img.shape[1]))
    threshold = max(CONTRAST_SPREAD * spread, MIN_CONTRAST)
    found = [
        (s, b) for s in (1.0, -1.0) for b in blobs(img, full, platter_level, s, threshold, allowed)
    ]
    candidates = [(s, b) for s, b in found if 0.5 * ball_area < b.area < 2.0 * ball_area]
    if not candidates:
        raise VideoError(
            f"no ball found on the first frame: no blob of about {ball_area:.0f} px (a ball of "
            f"the given radius) differs from the platter by {threshold:.0f} grey levels or more"
        )
    sign, ball = min(candidates, key=lambda sb: abs(math.log(sb[1].area / ball_area)))
    others = [
        b
        for s, b in found
        if b is not ball and b.area >= 4 and 0.6 < rim.radius(np.array([[b.u, b.v]]))[0] < 0.98
    ]
    if not others:
        raise VideoError(
            "no mark found on the platter: put a small mark of another size than the ball "
            "near the rim, in contrast with the platter"
        )
    return ball, sign, max(others, key=lambda b: b.area)


def track_video(
    path: str | os.PathLike[str],
    ball_radius: float,
    platter_radius: float,
    rpm: float | None = None,
) -> tuple[Track, list[str]]:
    """Track the ball of a video; return the track and the warnings (one line each).

    Parameters
    ----------
    path : str or path-like
        The video (any container and codec that PyAV reads).
    ball_radius, platter_radius : float
        R and P, m.
    rpm : float, optional
        The platter's rate as given, checked against the one measured (a warning if they
        differ by more than 4 standard errors and 0.1 %).

    Returns
    -------
    track : Track
    warnings : list of str

    Raises
    ------
    VideoError
        A video that cannot be read or has no frame, no platter, no ball or no mark on its
        first frame, a ball that reaches the platter's rim or the image's edge, a mark lost
        in nearly every frame.

    Examples
    --------
    A SYNTHETIC video, 480x270 px at 30 frames/s for 1 s, of a ball slipping on a platter
    at 45 rpm:

    >>> import tempfile, pathlib
    >>> import numpy as np
    >>> from turntable.film import Setup, rpm_to_omega
    >>> from turntable.video.render import Scene, render_video
    >>> from turntable.video.track import track_video
    >>> setup = Setup(radius=0.008, omega=rpm_to_omega(45.0), k=0.4)
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "ball_SYNTHETIC.mp4"
    >>> scene = Scene(size=(480, 270), fps=30.0, duration=1.0)
    >>> truth = render_video(path, "slipping", 2.0, [7, 0, 0, 0.4, 0, 0], setup, scene)
    >>> track, warnings = track_video(path, ball_radius=0.008, platter_radius=0.15)
    >>> err = np.hypot(track.film.x - truth.film.x, track.film.y - truth.film.y)
    >>> print(f"{track.film.t.size} frames, Omega {abs(track.calibration.omega):.3f} rad/s, "
    ...       f"rms error {np.sqrt(np.mean(err**2)) / 0.008:.2f} R")
    31 frames, Omega 4.711 rad/s, rms error 0.01 R
    """
    with Video(path) as video:
        return _track(video, ball_radius, platter_radius, rpm)


def _track(video: Video, ball_radius: float, platter_radius: float, rpm: float | None):
    info = video.info
    name = info.path
    times: list[float] = []
    ball_uv: list[tuple[float, float]] = []
    mark_uv: list[tuple[float, float]] = []
    rim_pts: list[NDArray] = []
    every = max(info.frames // RIM_FRAMES, 1) if info.frames else 30
    ball: _State = _State()
    mark: _State = _State()
    for index, t, img in video.frames():
        if index == 0:
            first = img.copy()
            rim0 = find_platter(img)
            if rim0 is None:
                raise VideoError(
                    f"{name}: no platter found on the first frame: no elliptic region in "
                    "contrast with its surroundings lies wholly inside the image"
                )
            platter_level, outside = levels(img, rim0)
            rim, pts = refine_rim(img, rim0, (platter_level + outside) / 2)
            inner = rim.mask(img.shape, 0.9)
            spread = 1.4826 * float(np.median(np.abs(img[inner] - platter_level)))
            allowed = rim.mask(img.shape, 1.0 - 3.0 / rim.b)
            r_px = ball_radius / platter_radius * rim.a
            ball_area = math.pi * r_px**2
            b0, sign, m0 = _first(img, rim, platter_level, spread, allowed, ball_area)
            threshold = max(CONTRAST_SPREAD * spread, MIN_CONTRAST)
            mark_sign = sign if b0.area else 1.0
            mark_area, ball_area = m0.area, b0.area
            r_mark = math.sqrt(mark_area / math.pi)
            mark_step = (
                (rpm / 60 * 2 * math.pi if rpm else 8.0) * rim.a * 0.95 / (info.rate or 30.0)
            )
            mark = _Turning(rim)
        times.append(t)
        if index % every == 0 and index:
            rim_pts.append(_rim_points(img, rim, platter_level, outside))
        elif index == 0:
            rim_pts.append(pts)
        # the ball
        if index == 0:
            found: Blob | None = b0
        else:
            near = ball.predict()
            v = ball.speed()
            half = 2.5 * r_px + 4 + (ball.misses + 1) * (0 if v is None else v + 2 * r_px)
            box = window(tuple(near), half, img.shape)
            found = _pick(blobs(img, box, platter_level, sign, threshold, allowed), near, ball_area)
        if found is not None and found.touches:
            where = (
                "the platter's rim" if _inside_image(found, img.shape, r_px) else "the image's edge"
            )
            raise VideoError(
                f"{name}: the ball reaches {where} at frame {index} (t = {t:.3f} s): cut the "
                "video before it does"
            )
        # the mark, unless it passes so close to the ball that their images may touch:
        # then neither is measured on this frame
        m: Blob | None = m0
        if index:
            near = mark.predict()
            v = mark.speed()
            half = 3 * r_mark + 4 + (mark_step if v is None else v + 2) * (mark.misses + 1)
            m = None
            if found is not None and math.hypot(found.u - near[0], found.v - near[1]) < (
                r_px + r_mark + 4
            ):
                found = None
            else:
                box = window(tuple(near), half, img.shape)
                candidates = [
                    b
                    for b in blobs(img, box, platter_level, mark_sign, threshold, allowed)
                    if found is None or math.hypot(b.u - found.u, b.v - found.v) > r_px
                ]
                m = _pick(candidates, near, mark_area)
        if found is None:
            ball.miss()
            ball_uv.append((math.nan, math.nan))
        else:
            ball.found(np.array([found.u, found.v]))
            ball_uv.append((found.u, found.v))
        if m is None:
            mark.miss()
            mark_uv.append((math.nan, math.nan))
        else:
            mark.found(np.array([m.u, m.v]))
            mark_uv.append((m.u, m.v))
    if not times:
        raise VideoError(f"{name}: the video has no frame")
    return _finish(
        info,
        np.array(times),
        np.array(ball_uv),
        np.array(mark_uv),
        rim_pts,
        rim,
        first,
        ball_radius,
        platter_radius,
        rpm,
    )


def _inside_image(b: Blob, shape: tuple[int, int], r_px: float) -> bool:
    m = 1.5 * r_px + 2
    return m < b.u < shape[1] - 1 - m and m < b.v < shape[0] - 1 - m


def _rim_points(img, rim, platter_level, outside) -> NDArray:
    from turntable.video.detect import rim_points

    pts = rim_points(img, rim, (platter_level + outside) / 2)
    dev = (rim.radius(pts) - 1.0) * rim.b
    return pts[np.abs(dev) < 1.5]


def _finish(info, t, ball_uv, mark_uv, rim_pts, rim, first, ball_radius, platter_radius, rpm):
    t0 = t[0]
    t = t - t0
    ok_mark = np.isfinite(mark_uv[:, 0])
    if ok_mark.sum() < MIN_MARK_FRAMES:
        raise VideoError(
            f"{info.path}: the mark was found on {int(ok_mark.sum())} frames only (at least "
            f"{MIN_MARK_FRAMES} are needed to measure the platter's rate)"
        )
    cal = calibrate(
        np.vstack(rim_pts),
        rim,
        t[ok_mark],
        mark_uv[ok_mark],
        (info.width, info.height),
        platter_radius,
        len(rim_pts),
    )
    ok = np.isfinite(ball_uv[:, 0])
    xy = camera.sphere_centre(cal.pose, ball_uv[ok], ball_radius)
    mirrored = cal.omega < 0
    if mirrored:
        xy[:, 1] *= -1
    warnings: list[str] = []
    lost = [int(i) for i in np.flatnonzero(~ok)]
    if lost:
        warnings.append(
            f"the ball was not found, or was next to the mark, on {len(lost)} of {t.size} frames "
            f"({frame_ranges(lost)}): "
            "they are gaps of the film"
        )
    omega = abs(cal.omega)
    if rpm is not None:
        given = 2 * math.pi * rpm / 60
        z = (omega - given) / cal.omega_stderr if cal.omega_stderr > 0 else math.inf
        if abs(z) > 4 and abs(omega / given - 1) > 1e-3:
            warnings.append(
                f"the platter turns at {omega * 60 / (2 * math.pi):.5g} +- "
                f"{cal.omega_stderr * 60 / (2 * math.pi):.2g} rpm in the video, not at the given "
                f"--rpm {rpm:g}"
            )
    film = Film(t[ok], xy[:, 0], xy[:, 1], synthetic=info.synthetic)
    track = Track(
        film,
        cal,
        info,
        lost,
        ball_uv,
        mark_uv,
        rim,
        first,
        mirrored,
        t,
        ball_radius,
        platter_radius,
    )
    return track, warnings


def calibration_json(track: Track, ball_radius: float, platter_radius: float) -> dict[str, Any]:
    """The calibration of a track as the JSON object written beside the film."""
    cal = track.calibration
    info = track.info
    return {
        "video": {
            "file": info.path,
            "synthetic": info.synthetic,
            "width_px": info.width,
            "height_px": info.height,
            "frames": int(track.times.size),
            "codec": info.codec,
            "metadata": info.metadata,
        },
        "ball_radius_m": ball_radius,
        "platter_radius_m": platter_radius,
        "omega_rad_s": abs(cal.omega),
        "omega_stderr_rad_s": cal.omega_stderr,
        "rpm": abs(cal.omega) * 60 / (2 * math.pi),
        "rpm_stderr": cal.omega_stderr * 60 / (2 * math.pi),
        "clockwise_from_above": track.mirrored,
        "y_mirrored": track.mirrored,
        "camera": {k: cal.derived[k] for k in cal.derived},
        "camera_stderr": {k: cal.stderr[k] for k in cal.stderr},
        "homography_plane_to_image": camera.homography(cal.pose).tolist(),
        "homography_ball_plane_to_image": camera.homography(cal.pose, ball_radius).tolist(),
        "mark_radius_m": cal.mark_radius,
        "rim_rms_px": cal.rim_rms_px,
        "mark_rms_px": cal.mark_rms_px,
        "mark_residual_lag1": cal.mark_lag1,
        "rim_ellipse_px": {
            "centre": list(track.rim.centre),
            "semi_axes": [track.rim.a, track.rim.b],
            "angle_rad": track.rim.angle,
        },
        "frame_times_s": [float(v) for v in track.times],
        "lost_frames": track.lost,
        "units": {
            "m_per_px": "metres of the platter per pixel at the axis's image",
            "tilt_deg": "angle of the optical axis from the vertical",
            "axis_u_px, axis_v_px": "image of the rotation axis (u right, v down)",
            "homography": (
                "(u, v, 1) ~ H (x, y, 1): plane z = 0, and the plane of the ball's centre z = R"
            ),
            "stderr": "from the least-squares fit of the camera to the rim and the mark",
        },
    }


def video_summary(track: Track, given_omega: bool) -> dict[str, Any]:
    """What ``turntable fit VIDEO`` reports of the tracking, under "video"."""
    cal = track.calibration
    return {
        "file": track.info.path,
        "synthetic": track.info.synthetic,
        "frames": int(track.times.size),
        "lost_frames": track.lost,
        "omega_rad_s": abs(cal.omega),
        "omega_stderr_rad_s": cal.omega_stderr,
        "omega_used": "given" if given_omega else "measured in the video",
        "axis": "measured in the video: the origin of the film",
        "clockwise_from_above": track.mirrored,
        "camera": dict(cal.derived),
        "camera_stderr": dict(cal.stderr),
    }
