"""``turntable track VIDEO --ball-radius R --platter-radius P [-o FILM.csv] [--rpm N]
[--ball-at [N:]U,V ...] [--mark-at [N:]U,V ...] [--plot F]``.

Tracks the ball of a video (`turntable.video.track.track_video`) and writes FILM.csv (t, x,
y in s and m, the lab frame, the axis at the origin; comment lines say how it was made)
and FILM.json beside it (the calibration with its standard errors, the frame times, the
lost frames, the checks).  Both are written only when everything has succeeded, each under a
temporary name then renamed.  Bad input, and a track that fails a check, raise
`turntable._validate.InputError`: one line on stderr and exit status 2 (with ``--plot``, the
first frame, or the frame where the ball or the mark was lost, is drawn with what was
found); warnings (lost frames, a given --rpm the video
contradicts) are logged, one line each.  With ``--json`` the summary is one JSON object.
"""

from __future__ import annotations

import argparse
import json
import logging
import math
import os
import sys
from pathlib import Path
from typing import Any

from turntable._progress import Progress
from turntable._validate import InputError

log = logging.getLogger(__name__)

#: Suffixes that `turntable fit` takes for a video rather than a film.
VIDEO_SUFFIXES = (".mp4", ".mov", ".m4v", ".mkv", ".avi", ".webm", ".mts", ".3gp")

_DESCRIPTION = """\
Track a ball on a turntable in a video and write the film that `turntable fit` reads.

The first frame must show the whole platter, in contrast with what surrounds it, the ball
in contrast with the platter (by colour or brightness), and a small mark on the platter near
its rim.  Where the search cannot tell which is which, --ball-at and --mark-at say it;
where the ball or the mark is lost, --ball-at N:U,V and --mark-at N:U,V resume from frame N,
and --last-frame N ends the film at frame N.
Writes FILM.csv (t, x, y: s from the first frame, by the container's
timestamps; the ball's centre in m, in the lab frame, the axis at the origin, the platter
turning counterclockwise) and FILM.json (camera, Omega, metres per pixel, the image of the
axis, each with its standard error; the frame times; the frames where the ball was lost,
which are gaps of the film)."""


def add_parser(sub: Any, parents: list[argparse.ArgumentParser]) -> None:
    """Add the ``track`` command to the subparsers of ``turntable``, with the options of
    ``parents``."""
    p = sub.add_parser(
        "track",
        help="track the ball of a video: the film that turntable fit reads",
        description=_DESCRIPTION,
        formatter_class=argparse.RawDescriptionHelpFormatter,
        parents=parents,
    )
    p.add_argument("video", metavar="VIDEO", help="the video (any format FFmpeg reads)")
    add_video_options(p, "--ball-radius")
    p.add_argument(
        "-o", "--output", metavar="FILM.csv", help="the film (default: VIDEO with suffix .csv)"
    )
    p.add_argument(
        "--rpm", type=float, metavar="N", help="the platter's rate: the mark must turn within 1 %%"
    )
    p.add_argument(
        "--plot",
        metavar="FIG.png",
        help="draw the first frame with the rim, axis, mark, track (or, on an error, with what "
        "was found)",
    )
    p.add_argument(
        "--json",
        action="store_true",
        help="print one JSON object (the files written, the tracking, the warnings)",
    )


def _seed(text: str) -> Any:
    from turntable.video.seeds import parse_seed

    try:
        return parse_seed(text)
    except ValueError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def add_video_options(p: argparse.ArgumentParser, radius: str | None) -> None:
    """--ball-radius (when ``radius`` names it), --platter-radius and the seeds."""
    if radius:
        p.add_argument(radius, type=float, required=True, metavar="R", help="ball radius, m")
    p.add_argument(
        "--platter-radius",
        type=float,
        required=bool(radius),
        metavar="P",
        help="radius of the platter's rim, m",
    )
    for option, what in (("--ball-at", "ball"), ("--mark-at", "mark")):
        p.add_argument(
            option,
            type=_seed,
            action="append",
            metavar="[N:]U,V",
            help=f"a pixel on the {what} in the video's frame N (0, the first, by default); "
            "again for another frame, where it was lost",
        )
    p.add_argument(
        "--last-frame",
        type=int,
        metavar="N",
        help="the last frame to track (0 the first), as Tracker's end frame: the film ends there",
    )


def track(
    video: str,
    ball_radius: float,
    platter_radius: float,
    rpm: float | None,
    frames: dict[str, Any] | None = None,
    plot: str | None = None,
    progress: Progress | None = None,
):
    """Track (`turntable.video.track.track_video`); return (track, warnings).

    ``frames``: ball_at, mark_at (the seeds) and last_frame.  A video that cannot be tracked
    raises `InputError` (with ``plot``, what was found is drawn first).
    """
    try:
        import av  # noqa: F401
        import cv2  # noqa: F401

        from turntable.video.decode import VideoError
        from turntable.video.track import track_video
    except ImportError as exc:
        raise InputError(
            f"reading a video needs the extra [video] ({exc.name} is missing): "
            "pip install 'turntable[video]'"
        ) from None
    if platter_radius <= ball_radius:
        raise InputError(f"--platter-radius {platter_radius:g} m must exceed the ball's radius")
    try:
        return track_video(
            video, ball_radius, platter_radius, rpm, **(frames or {}), progress=progress
        )
    except VideoError as exc:
        if plot is not None and exc.found is not None:
            from turntable.video.plot import plot_found

            plot_found(plot, exc.found, video)
        raise InputError(" ".join(str(exc).split())) from None


def header(track: Any, json_name: str) -> list[str]:
    cal, info = track.calibration, track.info
    d, se = cal.derived, cal.stderr
    lines = []
    if info.synthetic:
        lines.append(
            f"SYNTHETIC: tracked from a rendered video, not a filmed ball ({Path(info.path).name})"
        )
    lines += [
        f"tracked by turntable track from {Path(info.path).name} ({info.width}x{info.height}, "
        f"{track.times.size} frames, {info.codec}); calibration in {json_name}",
        "t: s from the first frame (container timestamps); x, y: the ball's centre, m, lab "
        "frame, axis at the origin, platter turning counterclockwise"
        + (" (y mirrored: it turns clockwise seen from above)" if track.mirrored else ""),
        f"Omega = {abs(cal.omega):.7g} +- {cal.omega_stderr:.2g} rad/s; tilt = "
        f"{d['tilt_deg']:.3f} +- {se['tilt_deg']:.2g} deg; {d['m_per_px'] * 1e3:.5g} mm/px at "
        f"the axis",
        f"frames where the ball was lost (gaps): {len(track.lost)}",
    ]
    return lines


def write_outputs(csv_path: Path, track: Any, cal_json: dict[str, Any]) -> None:
    """Write FILM.csv and FILM.json, each under a temporary name, then rename both."""
    from turntable._atomic import replacing
    from turntable.film import write_film

    json_path = csv_path.with_suffix(".json")
    with replacing(json_path) as tmp:
        tmp.write_text(json.dumps(cal_json, indent=1, allow_nan=False) + "\n", encoding="utf-8")
        write_film(csv_path, track.film, header(track, json_path.name))


def _check_number(option: str, value: float | None) -> None:
    if value is not None and not (math.isfinite(value) and value > 0):
        raise InputError(f"{option} must be a finite number > 0; got {value}")


def track_command(args: argparse.Namespace, progress: Progress | None = None) -> int:
    """Run ``turntable track``; bad input raises `InputError`."""
    from turntable._plot_check import check_plot

    _check_number("--ball-radius", args.ball_radius)
    _check_number("--platter-radius", args.platter_radius)
    _check_number("--rpm", args.rpm)
    out = Path(args.output or Path(args.video).with_suffix(".csv"))
    if out.suffix.lower() == ".json":
        raise InputError(f"-o {out}: the film is a .csv; its calibration goes beside it (.json)")
    folder = out.resolve().parent
    if not folder.is_dir() or not os.access(folder, os.W_OK):
        raise InputError(f"-o {out}: cannot write into the folder {folder}")
    if args.plot is not None:
        check_plot(args.plot, "turntable track")
    tracked, notes = track(
        args.video,
        args.ball_radius,
        args.platter_radius,
        args.rpm,
        {"ball_at": args.ball_at, "mark_at": args.mark_at, "last_frame": args.last_frame},
        args.plot,
        progress,
    )
    from turntable.video.saved import saved_json
    from turntable.video.track import calibration_json, video_summary

    cal_json = calibration_json(tracked, args.ball_radius, args.platter_radius)
    write_outputs(out, tracked, cal_json | {"saved": saved_json(tracked, notes, args.rpm)})
    for note in notes:
        log.warning(note)
    cal = tracked.calibration
    if args.json:
        summary = video_summary(tracked, given_omega=False)
        del summary["omega_used"], summary["axis"]
        summary |= {"film": str(out), "calibration": str(out.with_suffix(".json"))}
        print(json.dumps(summary | {"warnings": notes}, indent=2, allow_nan=False))
    else:
        print(
            f"{out}: {tracked.film.t.size} frames of the ball ({len(tracked.lost)} lost); "
            f"Omega = {abs(cal.omega):.6g} +- {cal.omega_stderr:.2g} rad/s; tilt "
            f"{cal.derived['tilt_deg']:.2f} deg; calibration in {out.with_suffix('.json')}"
        )
    if args.plot is not None:
        try:
            from turntable.video.plot import plot_track

            plot_track(args.plot, tracked)
        except Exception as exc:
            print(f"turntable track: error: --plot {args.plot}: {exc}", file=sys.stderr)
            return 1
    return 0
