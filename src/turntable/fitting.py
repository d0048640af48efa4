"""Fit a file, a film, a Tracker export or a video, as ``turntable fit`` does: `fit_file`.

It returns the JSON object that ``turntable fit`` prints (`turntable.fit.result_json`), and
raises `InputError` with one line for bad input, before any fitting is done.  What the
command shows on stderr besides (a Tracker export's units, a video's tracking notes) is
logged (``logging.getLogger("turntable.fitting")``).
"""

from __future__ import annotations

import logging
import math
import os
import warnings
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from turntable import film as film_io
from turntable import fit, tracker
from turntable._json import finite_or_none
from turntable._progress import Progress
from turntable._validate import InputError

if TYPE_CHECKING:
    from turntable.video.seeds import Seed

__all__ = ["MAX_DIMENSIONLESS", "InputError", "fit_file", "fitted_film"]

log = logging.getLogger(__name__)

#: Largest :math:`|\mathrm{value} - \mathrm{axis}| / R` (and :math:`|t| \Omega`) accepted:
#: beyond it squares and sums of
#: the residuals would come close to overflowing a double.
MAX_DIMENSIONLESS = 1e100


def _positive(option: str, value: float | None, unit: str) -> None:
    if value is not None and not (math.isfinite(value) and value > 0):
        raise InputError(f"{option} must be a finite number > 0 ({unit}); got {value}")


def _refuse_a_contradicted_rate(tracked, omega: float, rpm: float | None) -> None:
    """A rate given that the video contradicts would bias the fit: one line."""
    from turntable.video.track import rate_contradicted

    if omega == abs(tracked.calibration.omega):
        return
    says = rate_contradicted(tracked.calibration, omega)
    if says:
        given = f"--rpm {rpm:g}" if rpm is not None else f"--omega {omega:g}"
        raise InputError(f"{given}: {says}; leave it out to fit with the rate the video measures")


def _refuse_options_of_another_input(path, saved, video, axis_given, video_only) -> None:
    """One line for an option that the input does not take: seeds and --last-frame are for
    a video, --axis for a film (a video's axis is measured), --platter-radius not for a film
    in a table."""
    if video and not saved and Path(path).suffix.lower() in (".csv", ".txt"):
        raise InputError(
            f"--platter-radius: {path} is a film ({Path(path).suffix}); --platter-radius is for a "
            "video"
        )
    given = [option for option, is_given in video_only.items() if is_given]
    if given and (saved or not video):
        what = "a track; it is for its video" if saved else "a film; it is for a video"
        raise InputError(f"{given[0]}: {path} is {what} (turntable track VIDEO {given[0]})")
    if video and axis_given:
        what = "a track of a video" if saved else "a video"
        raise InputError(f"--axis: {path} is {what}, whose axis is measured; --axis is for a film")


def _same_as_tracked(
    path: str, option: str, value: float | None, tracked: float, unit: str
) -> None:
    if value is not None and value != tracked:
        raise InputError(
            f"{option} {value:g}{unit}: {path} was tracked with {tracked:g}{unit}; track the "
            "video again to change it"
        )


def _bounds(setup: film_io.Setup) -> dict[str, tuple[float, float]]:
    """Values the fit can take: |x - axis| / R and |t| Omega up to `MAX_DIMENSIONLESS`."""
    span = MAX_DIMENSIONLESS * setup.radius
    ax, ay = setup.axis
    time = MAX_DIMENSIONLESS / setup.omega
    return {
        "t": (-time, time),
        "x": (ax - span, ax + span),
        "y": (ay - span, ay + span),
    }


def _read(path: str, setup: film_io.Setup, p: int, units: str, track: str | None) -> film_io.Film:
    """The film of a CSV file or a Tracker export."""
    try:
        if tracker.is_tracker(path):
            data, label = tracker.read_tracker(path, track, tracker.UNITS[units])
            if data.t.size < p // 2 + 1:
                raise InputError(
                    f"{path}: track {label!r} has {data.t.size} frames with t, x and y; at "
                    f"least {p // 2 + 1} are needed"
                )
            log.warning(
                "%s: Tracker's track %r, its positions read in %s (the units calibrated in "
                "Tracker, which the file does not say: --units), its times in s",
                path, label, units,
            )  # fmt: skip
            return data
        return film_io.read_film(
            path,
            min_rows=p // 2 + 1,
            why=f"2 coordinates each, more than the {p} parameters of the slipping model",
            bounds=_bounds(setup),
            bounds_why=(
                f"too large for the fit: |x - axis| and |y - axis| must stay below "
                f"{MAX_DIMENSIONLESS:g} radii, |t| below {MAX_DIMENSIONLESS:g} / Omega; "
                "check the units (m, s)"
            ),
        )
    except film_io.FilmError as exc:
        raise InputError(str(exc)) from None


def fit_file(
    path: str | os.PathLike[str],
    radius: float,
    *,
    omega: float | None = None,
    rpm: float | None = None,
    k: float = 0.4,
    axis: tuple[float, float] | None = None,
    mass: float | None = None,
    fit_omega: bool = False,
    fit_axis: bool = False,
    platter_radius: float | None = None,
    ball_at: tuple[float, float] | Sequence[Seed] | None = None,
    mark_at: tuple[float, float] | Sequence[Seed] | None = None,
    last_frame: int | None = None,
    units: str = "m",
    track: str | None = None,
    progress: Progress | None = None,
) -> dict[str, Any]:
    """Fit both friction models to the ball of a file and select one: the result of
    ``turntable fit``.

    Parameters
    ----------
    path : str or path-like
        A film (CSV: t, x, y in s and m), a Tracker export, a video (a suffix of
        ``turntable.video.cli.VIDEO_SUFFIXES``, or ``platter_radius`` given), or the film of
        a video that ``turntable track`` wrote (FILM.csv, its FILM.json beside it): fitted as
        its video is, without tracking it again (`turntable.video.saved`).
    radius : float
        The ball's radius, m.
    omega, rpm : float, optional
        The turntable's rate, rad/s or revolutions per minute; one of them for a film, none
        for a video (whose rate is measured).
    k : float
        The inertia ratio :math:`I / (m R^2)`.
    axis : tuple of float, optional
        The turntable's axis in the data's coordinates, m; by default (0, 0).
    mass : float, optional
        The ball's mass, kg: adds dimensional coefficients.
    fit_omega, fit_axis : bool
        Fit the rate, the axis too (`turntable.fit.fit_film`); a video's axis always is.
    platter_radius : float, optional
        A video's platter radius, m.
    ball_at, mark_at : tuple of float or list of Seed, optional
        A video's first frame: a pixel (u, v) on the ball, on the mark; or seeds on any
        frames (``turntable.video.seeds.Seed``), where following resumes.
    last_frame : int, optional
        A video's last frame to track (0 the first): the film ends there.
    units, track : str
        A Tracker export's units (``turntable.tracker.UNITS``) and track.
    progress : callable, optional
        ``progress(stage, done, total)``, called as a video is tracked and as the models
        are fitted.

    Returns
    -------
    dict
        What ``turntable fit`` prints: `turntable.fit.result_json`, with non-finite
        numbers as None, and for a video its tracking under ``"video"``.  Its
        ``"warnings"`` are the problems of the fit.

    Raises
    ------
    InputError
        Bad input, one line: a file that cannot be read or parsed, a number that is not
        finite and positive, too few frames, a video the tracking refuses.

    Examples
    --------
    >>> from turntable.film import EXAMPLE_FILM
    >>> from turntable.fitting import fit_file
    >>> out = fit_file(EXAMPLE_FILM, 0.005, rpm=100 / 3)
    >>> out["selected"], round(out["slipping"]["mu0"], 1)
    ('slipping', 3.0)
    >>> fit_file("no/such.csv", 0.005, rpm=45.0)
    Traceback (most recent call last):
    ...
    turntable._validate.InputError: no/such.csv: ...
    """
    return fitted_film(**locals())[0]


def fitted_film(
    path: str | os.PathLike[str],
    radius: float,
    *,
    omega: float | None = None,
    rpm: float | None = None,
    k: float = 0.4,
    axis: tuple[float, float] | None = None,
    mass: float | None = None,
    fit_omega: bool = False,
    fit_axis: bool = False,
    platter_radius: float | None = None,
    ball_at: tuple[float, float] | Sequence[Seed] | None = None,
    mark_at: tuple[float, float] | Sequence[Seed] | None = None,
    last_frame: int | None = None,
    units: str = "m",
    track: str | None = None,
    progress: Progress | None = None,
) -> tuple[dict[str, Any], film_io.Film]:
    """`fit_file`'s result, and the film that was fitted (of a video: tracked)."""
    path = os.fspath(path)
    for option, value, unit in [
        ("--radius", radius, "m"), ("--omega", omega, "rad/s"),
        ("--rpm", rpm, "revolutions per minute"), ("--k", k, "dimensionless"),
        ("--mass", mass, "kg"),
    ]:  # fmt: skip
        _positive(option, value, unit)
    if omega is not None and rpm is not None:
        raise InputError("give one of --omega and --rpm, not both")
    axis_given = axis is not None
    axis = (0.0, 0.0) if axis is None else (float(axis[0]), float(axis[1]))
    if not all(math.isfinite(a) for a in axis):
        raise InputError(f"--axis must be two finite numbers (m); got {list(axis)}")
    from turntable.video.cli import VIDEO_SUFFIXES
    from turntable.video.saved import is_track

    saved = is_track(path)  # a film of turntable track, its calibration beside it
    video = saved or platter_radius is not None or Path(path).suffix.lower() in VIDEO_SUFFIXES
    if video and platter_radius is None and not saved:
        raise InputError(f"{path} is a video: give --platter-radius P (m)")
    if not video and omega is None and rpm is None:
        raise InputError("one of the arguments --omega --rpm is required")
    video_only = {"--ball-at": bool(ball_at), "--mark-at": bool(mark_at),
                  "--last-frame": last_frame is not None}  # fmt: skip
    _refuse_options_of_another_input(path, saved, video, axis_given, video_only)
    # a video's image of the ball's centre is off by a few thousandths of R in a fixed
    # direction, more than a rolling fit's precision: the rolling model's axis is fitted
    options = {"fit_omega": fit_omega, "fit_axis": fit_axis or video}
    p = max(fit.n_parameters(m, **options) for m in fit.MODELS)
    tracked = None
    if saved:
        from turntable.video.saved import read_track

        tracked, notes, tracked_rpm = read_track(path)
        _same_as_tracked(path, "--radius", radius, tracked.ball_radius, " m")
        _same_as_tracked(path, "--platter-radius", platter_radius, tracked.platter_radius, " m")
        if rpm is not None and rpm != tracked_rpm:
            raise InputError(
                f"--rpm {rpm:g}: {path} was tracked "
                + (f"with --rpm {tracked_rpm:g}" if tracked_rpm else "without --rpm")
                + "; track the video again to check its rate against another (or give --omega)"
            )
    elif video:
        _positive("--platter-radius", platter_radius, "m")
        from turntable.video.cli import track as track_video

        tracked, notes = track_video(
            path, radius, platter_radius, rpm,
            {"ball_at": ball_at, "mark_at": mark_at, "last_frame": last_frame}, progress=progress,
        )  # fmt: skip
    if omega is None:
        omega = film_io.rpm_to_omega(rpm) if rpm is not None else abs(tracked.calibration.omega)
    if video:
        _refuse_a_contradicted_rate(tracked, omega, rpm)
        for message in notes:
            log.warning(message)
    setup = film_io.Setup(radius, omega, k, axis)
    if tracked is not None:
        data = tracked.film
        if data.t.size < p // 2 + 1:
            raise InputError(
                f"{path}: the ball was found on {data.t.size} frames; at least {p // 2 + 1} "
                "are needed"
            )
    else:
        data = _read(path, setup, p, units, track)
    log.info("%s: %d frames; fitting both models", path, data.t.size)
    if progress is not None:
        progress("fitting", 0, 2)
    # Extreme but accepted numbers may overflow inside the fit; what that does to the result
    # is reported (None in the JSON, a warning), not numpy's RuntimeWarning lines.
    with warnings.catch_warnings(), np.errstate(all="ignore"):
        warnings.simplefilter("ignore", RuntimeWarning)
        result = fit.fit_film(data, setup, **options)
        if tracked is not None:
            from turntable.video.uncertainty import carry

            measured = omega == abs(tracked.calibration.omega)
            result, parts, notes = carry(tracked, setup, result, omega_measured=measured, **options)
        if progress is not None:
            progress("fitting", 1, 2)
        check = fit.consistency(data, setup, result, **options)
        out = finite_or_none(fit.result_json(result, setup, data, mass, source=path, check=check))
    if progress is not None:
        progress("fitting", 2, 2)
    if tracked is not None:
        from turntable.video.track import video_summary

        out["video"] = finite_or_none(
            video_summary(tracked, given_omega=omega != abs(tracked.calibration.omega))
        )
        out["video"]["stderr_parts"] = finite_or_none(parts)
        out["warnings"] += notes
    return out, data
