"""From a video to a film: the stages in order, and the `Track` they make.

`track_video` decodes the video (``decode``), finds the platter's rim on the first frame
(``platter``), the ball and the mark on the first frames (``find``), follows both through the
video (``follow``), fits the camera and the platter's rate to the rim and the turning mark
(``calibrate``) and checks that what it found agrees with itself (``check``).  The ball's centre
is the point R above the platter whose sphere's image is centred on the ball's blob
(`~turntable.video.camera.sphere_centre`).  A frame where the ball is not measured is a gap
of the film (never a guessed position), named in the warnings.  Each stage takes plain data
and returns plain data.
"""

from __future__ import annotations

import itertools
import math
import os
from collections.abc import Sequence
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import NDArray

from turntable._progress import Progress, counted
from turntable.film import Film
from turntable.video import camera
from turntable.video.calibrate import Calibration, calibrate, rim_camera
from turntable.video.check import checks, first_failure
from turntable.video.decode import Picture, Video, VideoError, VideoInfo, lab, rgb
from turntable.video.find import PROBE_FRAMES, PROBE_SECONDS, Candidate, find
from turntable.video.follow import LostAt, Paths, Seeds, follow
from turntable.video.platter import Ellipse, find_platter
from turntable.video.seeds import (
    Seed,
    by_frame,
    check_frames,
    check_last_frame,
    on_first_frame,
    seeds_of,
)
from turntable.video.uncertainty import lens_note, lens_shift_radii

__all__ = ["FirstLook", "Track", "track_video"]

#: Fewest frames in which the mark, and the ball, must be found.
MIN_MARK_FRAMES = 10
#: The probe (`turntable.video.find`) has at most this many frames, whatever the frame rate.
MAX_PROBE_FRAMES = 120
#: Before its rate is measured, the mark may turn this fast (rad/s, 76 rpm; or as ``--rpm``
#: says), at a frame rate of ``FRAME_RATE`` where the video does not say.
FAST_RATE, FRAME_RATE = 8.0, 30.0
#: A rate given (--rpm, --omega) that the video's differs from by more than ``RATE_Z`` of its
#: standard errors and ``RATE_SHARE`` is contradicted (33.3 for 33 1/3 rpm is, at 0.1 %).
RATE_Z, RATE_SHARE = 4.0, 1e-3
#: The platter differs from what surrounds it by at least this (CIELAB distance).
MIN_RIM_CONTRAST = 8.0
#: A warning where the camera's distance, which the ball's height above the platter is seen
#: from, is known so poorly (a camera looking nearly straight down) that two of its standard
#: errors move the positions at the rim by more than this (ball radii): one may not be all it
#: is off by (``turntable.video.covariance.MARK_SHAPE``).
DISTANCE_WARNING_R = 0.05


class FirstLook(NamedTuple):
    """What was found on the first frame, or on the frame where the ball or the mark was
    lost: the image (RGB), the rim (None if not found), the candidates for the ball and the
    mark (``turntable.video.find.Candidate``) and the frame's number.

    Examples
    --------
    >>> import numpy as np
    >>> from turntable.video.track import FirstLook
    >>> look = FirstLook(np.zeros((270, 480, 3), np.uint8), None, [])
    >>> look.image.shape, look.rim
    ((270, 480, 3), None)
    """

    image: NDArray[np.uint8]
    rim: Ellipse | None
    candidates: list[Candidate]
    frame: int = 0


class Track(NamedTuple):
    """A tracked video.

    Attributes
    ----------
    film : Film
        Times (s, from the first frame; a rolling shutter's row delay added) and the ball's
        centre (m) in the lab frame of
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
        The first frame (RGB), for drawing.
    mirrored : bool
        Whether y was mirrored (the platter turns clockwise seen from above).
    times : numpy.ndarray
        Time of every frame, s from the first.
    ball_radius, platter_radius : float
        :math:`R` and :math:`P`, m.
    checks : dict
        Every check of `turntable.video.check` (all passed), with its value and limit.
    candidates : list of Candidate
        What was found on the first frame, the ball and the mark among it.

    Examples
    --------
    >>> from turntable.video.track import Track
    >>> Track._fields[:4]
    ('film', 'calibration', 'info', 'lost')
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
    checks: dict[str, dict[str, Any]]
    candidates: list[Candidate]


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


def track_video(
    path: str | os.PathLike[str],
    ball_radius: float,
    platter_radius: float,
    rpm: float | None = None,
    ball_at: tuple[float, float] | Sequence[Seed] | None = None,
    mark_at: tuple[float, float] | Sequence[Seed] | None = None,
    progress: Progress | None = None,
    last_frame: int | None = None,
) -> tuple[Track, list[str]]:
    """Track the ball of a video; return the track and the warnings (one line each).

    Parameters
    ----------
    path : str or path-like
        The video (any container and codec that PyAV reads).
    ball_radius, platter_radius : float
        :math:`R` and :math:`P`, m.
    rpm : float, optional
        The platter's rate as given: the mark must turn within 1 % of it (a warning if they
        differ by more than 4 standard errors and 0.1 %).
    ball_at, mark_at : tuple of float or list of Seed, optional
        Seeds: a pixel (u, v) of the first frame on the ball, and on the mark; or seeds
        on any frames (``turntable.video.seeds.Seed``), where following resumes.
    progress : callable, optional
        Called as ``progress("tracking", frames read, frames of the video)`` for each frame
        read (the total None when the container does not say).
    last_frame : int, optional
        The last frame to track (0 the first), as Tracker's end frame: the film ends there.

    Returns
    -------
    track : Track
    warnings : list of str

    Raises
    ------
    VideoError
        A video that cannot be read or has no frame, no platter, no ball or no mark on its
        first frame, a ball that reaches the platter's rim or the image's edge, a mark lost
        in nearly every frame or lost for longer than a gap can be, a seed on nothing or past
        the video's end or ``last_frame``, a ``last_frame`` past the video's end, a failed
        check (`turntable.video.check`).  Its ``found`` is the `FirstLook`, for drawing.

    See Also
    --------
    turntable.video.render.render_video : A SYNTHETIC video to track.

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
    >>> omega = abs(track.calibration.omega)
    >>> print(f"{track.film.t.size} frames, Omega {omega:.3f} rad/s, "
    ...       f"rms error {np.sqrt(np.mean(err**2)) / 0.008:.2f} R")
    31 frames, Omega 4.708 rad/s, rms error 0.04 R
    """
    ball_at, mark_at = seeds_of(ball_at), seeds_of(mark_at)
    with Video(path) as video:
        info = _check_frames(video.info, ball_at, mark_at, last_frame)
        frames = video.frames()
        if last_frame is not None:
            frames = itertools.takewhile(lambda frame: frame[0] <= last_frame, frames)
        try:
            frames = counted(frames, progress, "tracking", info.frames or None)
            got = _track(info, frames, ball_radius, platter_radius, rpm, ball_at, mark_at)
        except VideoError as exc:
            message = str(exc)
            if not message.startswith(video.info.path):
                message = f"{video.info.path}: {message}"
            raise VideoError(message, exc.found) from None
    # a container that does not count its frames: its end is known once read
    _check_frames(video.info._replace(frames=got[0].times.size), [], [], last_frame)
    return got


def _check_frames(info: VideoInfo, ball_at: list[Seed], mark_at: list[Seed], last: int | None):
    """The video's info, its frames counted up to ``last``; bad seeds or ``last`` refused."""
    try:
        check_last_frame(last, info.frames)
        for option, given in (("--ball-at", ball_at), ("--mark-at", mark_at)):
            check_frames(option, given, info.frames, last, (info.width, info.height))
    except ValueError as exc:
        raise VideoError(f"{info.path}: {exc}") from None
    return info if last is None else info._replace(frames=last + 1)


def _track(info: VideoInfo, frames, ball_radius, platter_radius, rpm, ball_at, mark_at):
    first = next(frames, None)
    if first is None:
        raise VideoError("the video has no frame")
    lab0 = lab(first[2])
    image = rgb(first[2])
    got = find_platter(lab0)
    if got is None or got[0].contrast < MIN_RIM_CONTRAST:
        raise VideoError(
            "no platter found on the first frame: no elliptic region in contrast with its "
            "surroundings lies wholly inside the image",
            FirstLook(image, None, []),
        )
    platter, rim_pts = got
    size = (info.width, info.height)
    pose0 = rim_camera(rim_pts, platter.rim, size, platter_radius)
    probe: list[tuple[int, float, Picture]] = [(first[0], first[1], first[2].copy())]
    for index, t, picture in frames:
        probe.append((index, t, picture.copy()))
        enough = len(probe) >= PROBE_FRAMES and t - probe[0][1] >= PROBE_SECONDS
        if enough or len(probe) >= MAX_PROBE_FRAMES:
            break
    try:
        found = find(
            [(t, p) for _, t, p in probe],
            platter,
            pose0,
            ball_radius,
            platter_radius,
            on_first_frame(ball_at),
            on_first_frame(mark_at),
            rpm,
        )
    except VideoError as exc:
        raise VideoError(str(exc), FirstLook(image, platter.rim, exc.found or [])) from None
    look = FirstLook(image, platter.rim, found.candidates)
    fastest = rpm / 60 * 2 * math.pi if rpm else FAST_RATE
    mark_step = fastest * platter.rim.a / (info.rate or FRAME_RATE)
    try:
        paths = follow(
            itertools.chain(probe, frames),
            info.frames,
            platter,
            rim_pts,
            found,
            mark_step,
            pose0,
            ball_radius,
            Seeds(by_frame(ball_at), by_frame(mark_at)),
        )
    except VideoError as exc:
        raise VideoError(str(exc), _lost_look(exc.found, look)) from None
    ok_mark = np.isfinite(paths.mark[:, 0])
    if ok_mark.sum() < MIN_MARK_FRAMES:
        raise VideoError(
            f"the mark was found on {int(ok_mark.sum())} frames only (at least "
            f"{MIN_MARK_FRAMES} are needed to measure the platter's rate)",
            look,
        )
    found_ball = int(np.isfinite(paths.ball[:, 0]).sum())
    if found_ball < MIN_MARK_FRAMES:
        raise VideoError(
            f"the ball was found on {found_ball} frames only: give --ball-at N:U,V on it, in a "
            "frame N where it is seen",
            look,
        )
    t = paths.t - paths.t[0]
    cal = calibrate(
        paths.rim_points,
        platter.rim,
        t[ok_mark],
        paths.mark[ok_mark],
        size,
        platter_radius,
        paths.rim_frames,
    )
    results = checks(cal, paths, found, platter.rim, pose0, ball_radius, platter_radius, rpm)
    given = [o for o, s in (("--ball-at", ball_at), ("--mark-at", mark_at)) if s]
    failure = first_failure(results, given)
    if failure is not None:
        raise VideoError(failure, look)
    return _finish(info, paths, cal, results, look, ball_radius, platter_radius, rpm)


def rate_contradicted(cal: Calibration, omega: float) -> str | None:
    """Where the video's rate differs from ``omega`` (rad/s) by more than `RATE_Z` of its
    standard errors and `RATE_SHARE`: "the platter turns at ... rpm in the video"."""
    seen = abs(cal.omega)
    z = (seen - omega) / cal.omega_stderr if cal.omega_stderr > 0 else math.inf
    if abs(z) <= RATE_Z or abs(seen / omega - 1) <= RATE_SHARE:
        return None
    to_rpm = 60 / (2 * math.pi)
    return (
        f"the platter turns at {seen * to_rpm:.5g} +- {cal.omega_stderr * to_rpm:.2g} rpm in the "
        "video"
    )


def _lost_look(lost: LostAt | None, look: FirstLook) -> FirstLook:
    if lost is None:
        return look
    return FirstLook(lost.image, look.rim, lost.candidates, lost.frame)


def _finish(info, paths: Paths, cal, results, look, ball_radius, platter_radius, rpm):
    t = paths.t - paths.t[0]
    ok = np.isfinite(paths.ball[:, 0])
    xy = camera.sphere_centre(cal.pose, paths.ball[ok], ball_radius)
    mirrored = cal.omega < 0
    if mirrored:
        xy[:, 1] *= -1
    warnings: list[str] = []
    lost = [int(i) for i in np.flatnonzero(~ok)]
    if lost:
        warnings.append(
            f"the ball was not found, or was next to the mark, on {len(lost)} of {t.size} frames "
            f"({frame_ranges(lost)}): they are gaps of the film"
        )
    share = cal.stderr["distance_m"] / cal.derived["distance_m"]  # of ln d
    scale = ball_radius / cal.derived["distance_m"] * share
    rim_r = 2 * platter_radius * scale / ball_radius  # two standard errors at the rim
    if rim_r > DISTANCE_WARNING_R:
        tilt = cal.derived["tilt_deg"]
        warnings.append(
            f"the camera's distance is known to +-{100 * share:.0f} % (one standard error) only "
            f"(tilt {tilt:.1f} deg, {t.size} frames), and so the positions may be scaled about "
            f"the axis by +-{100 * scale:.2g} % (+-{200 * scale:.2g} % at two standard errors; "
            f"{rim_r:.2g} R at the rim): R above the platter, seen from an uncertain distance; "
            "a fit of friction does not depend on it"
            + ("; a tilt of 10 degrees or more measures the distance" if tilt < 10 else "")
        )
    if rpm is not None and (says := rate_contradicted(cal, 2 * math.pi * rpm / 60)):
        warnings.append(f"{says}, not at the given --rpm {rpm:g}")
    film = Film(cal.times(t[ok], paths.ball[ok, 1]), xy[:, 0], xy[:, 1], synthetic=info.synthetic)
    track = Track(
        film=film,
        calibration=cal,
        info=info,
        lost=lost,
        image=paths.ball,
        mark_image=paths.mark,
        rim=look.rim,
        first_frame=look.image,
        mirrored=mirrored,
        times=t,
        ball_radius=ball_radius,
        platter_radius=platter_radius,
        checks=results,
        candidates=look.candidates,
    )
    note = lens_note(track)
    return track, warnings + ([note] if note else [])


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
        "readout_s": cal.readout,
        "readout_stderr_s": cal.readout_stderr,
        "lens": lens_json(track),
        "rim_ellipse_px": {
            "centre": list(track.rim.centre),
            "semi_axes": [track.rim.a, track.rim.b],
            "angle_rad": track.rim.angle,
        },
        "checks": track.checks,
        "frame_times_s": [float(v) for v in track.times],
        "lost_frames": track.lost,
        "units": {
            "m_per_px": "metres of the platter per pixel at the axis's image",
            "tilt_deg": "angle of the optical axis from the vertical",
            "axis_u_px, axis_v_px": "image of the rotation axis (u right, v down)",
            "homography": (
                "(u, v, 1) ~ H (x, y, 1): plane z = 0, and the plane of the ball's centre z = R; "
                "(u, v) before the lens's distortion: seen at (u, v) + k1 r^2 ((u, v) - centre), "
                "r the distance from the image's centre over focal_px, k1 = lens_k1"
            ),
            "stderr": (
                "from the least-squares fit of the camera to the rim and the mark, with the "
                "uncertainty of the lens's k1 (lens.k1_used_stderr) and what follows from it"
            ),
        },
    }


def lens_json(track: Track) -> dict[str, Any]:
    """Whether the lens's k1 is measured, what the mark's track says of it, and how far its
    uncertainty may move the positions."""
    lens = track.calibration.lens
    return {
        "k1_measured": lens.measured,
        "k1_used": track.calibration.derived["lens_k1"],
        "k1_used_stderr": lens.spread,
        "k1_from_mark": lens.k1,
        "k1_from_mark_stderr": lens.k1_stderr,
        "position_shift_radii": lens_shift_radii(track),
        "meaning": (
            "k1_measured false: the camera is a pinhole's (k1 = 0), k1 known only to within "
            "k1_used_stderr = sqrt(k1_from_mark^2 + k1_from_mark_stderr^2); "
            "position_shift_radii: the largest move of the film's positions (ball radii) for "
            "k1 moved by k1_used_stderr, the other parameters of the camera following it"
        ),
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
        "lens": lens_json(track),
        "checks": {name: bool(r["passed"]) for name, r in track.checks.items()},
    }
