"""A tracked video read back from the files ``turntable track`` writes: `read_track`.

Beside the film (``-o FILM.csv``: t, x, y), ``turntable track`` writes FILM.json: the
calibration as a person reads it, and under ``"saved"`` what a fit needs to carry the camera's
uncertainty into the coefficient (``turntable.video.uncertainty``): the calibration's
parameters and their covariance, the ball's image on every frame and the tracking's warnings
(`saved_json`).  ``turntable fit FILM.csv`` then fits the track as ``turntable fit VIDEO``
fits the video, without tracking it again.
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from turntable._validate import InputError

if TYPE_CHECKING:  # the video's modules load OpenCV and scipy.optimize: imported when read
    from turntable.video.calibrate import Calibration
    from turntable.video.track import Track

__all__ = ["is_track", "read_track", "saved_json"]

#: The parameters of a calibration by name, in the order of its vector (`_At`).
NAMES = [
    "log_focal_px", "tilt_rad", "roll_rad", "look_at_x_m", "look_at_y_m", "log_distance_m",
    "log_mark_radius_m", "mark_phase_rad", "omega_rad_s", "readout_frames", "lens_k1",
]  # fmt: skip
#: How far the film read from FILM.csv may lie from the film its calibration makes: the CSV's
#: ten significant digits.
MATCH = 1e-8


def saved_json(track: Track, warnings: list[str], rpm: float | None) -> dict[str, Any]:
    """What `read_track` needs beyond the calibration's JSON, under ``"saved"`` (``rpm``: the
    ``--rpm`` the tracking was given, or None)."""
    cal = track.calibration
    return {
        "rpm_given": rpm,
        "parameters": dict(zip(NAMES, map(float, cal.parameters), strict=True)),
        "covariance": cal.covariance.tolist(),
        "lens_shift": cal.lens.shift.tolist(),
        "frame_interval_s": cal.interval,
        "frame_rate": track.info.rate,
        "ball_image_px": [None if np.isnan(u) else [u, v] for u, v in track.image.tolist()],
        "warnings": warnings,
    }


def _json_of(path: str | Path) -> Path:
    return Path(path).with_suffix(".json")


def is_track(path: str | Path) -> bool:
    """Whether ``path`` is a film written by ``turntable track`` with its calibration beside
    it (FILM.json with ``"saved"``)."""
    if Path(path).suffix.lower() != ".csv":
        return False
    try:
        doc = json.loads(_json_of(path).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return False
    return isinstance(doc, dict) and "saved" in doc


def _calibration(doc: dict[str, Any], size: tuple[int, int]) -> Calibration:
    from turntable.video.calibrate import Calibration, Lens, _At, _pose

    saved = doc["saved"]
    theta = np.array([saved["parameters"][n] for n in NAMES])
    lens = doc["lens"]
    return Calibration(
        pose=_pose(theta, size),
        omega=float(theta[_At.OMEGA]),
        omega_stderr=doc["omega_stderr_rad_s"],
        mark_radius=doc["mark_radius_m"],
        derived=doc["camera"],
        stderr=doc["camera_stderr"],
        rim_rms_px=doc["rim_rms_px"],
        mark_rms_px=doc["mark_rms_px"],
        mark_lag1=doc["mark_residual_lag1"],
        readout=doc["readout_s"],
        readout_stderr=doc["readout_stderr_s"],
        lens=Lens(
            lens["k1_measured"],
            lens["k1_from_mark"],
            lens["k1_from_mark_stderr"],
            np.array(saved["lens_shift"]),
        ),
        parameters=theta,
        covariance=np.array(saved["covariance"]),
        interval=saved["frame_interval_s"],
    )


def read_track(path: str | Path) -> tuple[Track, list[str], float | None]:
    """The `~turntable.video.track.Track` of a film written by ``turntable track`` (its
    positions, times and calibration; without the video's pictures), the tracking's warnings
    and the ``--rpm`` it was given (None if none).

    Raises
    ------
    InputError
        FILM.json is not one that this version of ``turntable track`` writes, or the film is
        not the one its calibration makes (edited, or another track's).
    """
    try:
        track, saved = _read(path)
    except (KeyError, TypeError, ValueError, OSError) as exc:
        raise InputError(
            f"{_json_of(path)}: not the calibration of a film that this version of turntable "
            f"track writes ({type(exc).__name__}: {exc}); track the video again"
        ) from None
    _check_film(path, track.film)
    return track, list(saved["warnings"]), saved["rpm_given"]


def _read(path: str | Path) -> tuple[Track, dict[str, Any]]:
    from turntable.film import Film
    from turntable.video.decode import VideoInfo
    from turntable.video.platter import Ellipse
    from turntable.video.track import Track
    from turntable.video.uncertainty import film_with

    doc = json.loads(_json_of(path).read_text())
    saved, video = doc["saved"], doc["video"]
    size = (video["width_px"], video["height_px"])
    info = VideoInfo(
        video["file"], *size, video["frames"], video["codec"], saved["frame_rate"],
        video["metadata"],
    )  # fmt: skip
    image = np.array([p or [math.nan, math.nan] for p in saved["ball_image_px"]], float)
    ellipse = doc["rim_ellipse_px"]
    track = Track(
        film=Film(np.zeros(0), np.zeros(0), np.zeros(0)),
        calibration=_calibration(doc, size),
        info=info,
        lost=doc["lost_frames"],
        image=image,
        mark_image=np.full_like(image, math.nan),
        rim=Ellipse(tuple(ellipse["centre"]), *ellipse["semi_axes"], ellipse["angle_rad"]),
        first_frame=np.zeros((0, 0, 3), np.uint8),
        mirrored=doc["y_mirrored"],
        times=np.array(doc["frame_times_s"]),
        ball_radius=doc["ball_radius_m"],
        platter_radius=doc["platter_radius_m"],
        checks=doc["checks"],
        candidates=[],
    )
    film, _ = film_with(track, track.calibration.parameters)
    return track._replace(film=film._replace(synthetic=info.synthetic)), saved


def _check_film(path: str | Path, film) -> None:
    """Refuse a film whose CSV the calibration beside it does not make (edited, or another
    track's)."""
    from turntable.film import read_film

    read = read_film(path)
    rows = np.column_stack([read.t, read.x, read.y])
    made = np.column_stack([film.t, film.x, film.y])
    scale = np.maximum(np.abs(made).max(axis=0, initial=0.0), 1e-300)
    if rows.shape != made.shape or not (np.abs(rows - made) <= MATCH * scale).all():
        raise InputError(
            f"{path}: its positions are not those that {_json_of(path).name} makes of the "
            "ball's images (the film or its calibration was changed): track the video again, "
            f"or move {_json_of(path).name} away to fit the film alone (--rpm or --omega)"
        )
