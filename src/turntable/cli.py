"""The ``turntable`` command.

``turntable claims [REPORT.json]`` prints, for each claim of a claims report
(``results/claims.json`` by default, written by ``make``), one line: its id, its verdict
and the reproduced value that decides it with its bound
(`turntable.claims.report.decisive_lines`).  A report that cannot be read gets one line on
stderr and exit status 2.

``turntable fit DATA.csv --radius R (--omega W | --rpm N) [--k K] [--axis X Y] [--mass M]
[--fit-omega] [--fit-axis] [--plot FIG.png]`` fits the slipping and the rolling-resistance
models to a tracked trajectory (`turntable.fit.fit_film`) and prints one JSON object on
stdout (`turntable.fit.result_json`).

Bad input (a file that cannot be read or parsed, see `turntable.film.read_film`; a
negative, zero or non-finite number; a value too large for the fit; too few frames) gets a
one-line message on stderr and exit status 2, before any fitting is done.  A completed fit
exits with status 0 and prints, after the JSON, one line on stderr per problem of the fit
(`turntable.fit.problems`: a coefficient at a bound, a selection that is not decisive,
residuals that are not white noise, frames too far apart), each starting with
``turntable fit: warning:``.  With ``--plot``, the JSON is written before the figure; a
figure that cannot be drawn gets one line on stderr and exit status 1.  A closed stdout
(``turntable fit ... | head``) ends the command quietly.  ``python -m turntable`` runs the
same.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import re
import sys
import warnings
from collections.abc import Sequence
from pathlib import Path
from typing import Any, NoReturn

import numpy as np

from turntable import film as film_io
from turntable import fit, tracker
from turntable._json import finite_or_none
from turntable._plot_check import check_plot

#: The claims report ``turntable claims`` reads unless told another (written by ``make``).
DEFAULT_CLAIMS_REPORT = "results/claims.json"
#: Exit status for bad input (as argparse uses for a bad command line).
BAD_INPUT = 2
#: Exit status when the fit was printed but the figure of ``--plot`` could not be drawn.
PLOT_FAILED = 1
#: Largest |value - axis| / radius (and |t| Omega) accepted: beyond it squares and sums of
#: the residuals would come close to overflowing a double.
MAX_DIMENSIONLESS = 1e100

_DESCRIPTION = """\
Fit both friction models to a filmed ball and select one.

DATA.csv: a header line naming at least the columns t, x, y (s and m; other columns are
ignored; lines starting with # are comments), then one line per frame: the position of the
ball's centre in the lab (non-rotating) frame.  The turntable turns counterclockwise in
these coordinates (from x towards y); for a clockwise turntable, or image coordinates
with y pointing down, negate y.  Prints one JSON object on stdout: the fitted
coefficients mu0 = mu0_dim / (m Omega) (slipping with viscous friction) and
delta = delta_dim / (m R^2 Omega) (rolling without slipping against a resistance torque),
dimensionless, with standard errors, 95 % intervals, rms residuals, a test of the
residuals for white noise, AIC and AICc, the initial states, and the selected model with
the evidence (AICc difference, Akaike weights, whether it is decisive).  Problems of the
fit (a coefficient at the end of its range, reported as a limit; a selection that is not
decisive; residuals that are not white noise, i.e. a wrong Omega, k, axis or sign of y)
get one line each on stderr; the exit status is still 0."""


class _Parser(argparse.ArgumentParser):
    """An ArgumentParser whose errors are one line on stderr and exit status 2."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        # a value such as -1e-05 is a number, not an option (argparse does so from Python 3.13)
        self._negative_number_matcher = re.compile(r"-\.?\d")

    def error(self, message: str) -> NoReturn:
        _fail(f"{self.prog}: error: {message}")


def _fail(message: str) -> NoReturn:
    print(" ".join(message.split()) if "\n" in message else message, file=sys.stderr)
    raise SystemExit(BAD_INPUT)


def _parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="turntable", description="The ball on a turntable.")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    p = sub.add_parser(
        "fit",
        help="fit the friction models to a tracked trajectory",
        description=_DESCRIPTION,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("data", metavar="DATA.csv", help="tracked positions (t, x, y) in s and m")
    p.add_argument("--radius", type=float, required=True, metavar="R", help="ball radius, m")
    rate = p.add_mutually_exclusive_group()
    rate.add_argument(
        "--omega", type=float, metavar="W", help="turntable rate, rad/s (of a video: measured)"
    )
    rate.add_argument("--rpm", type=float, metavar="N", help="turntable rate, revolutions/min")
    from turntable.video.cli import add_video_options

    add_video_options(p, None)
    p.add_argument(
        "--units",
        choices=sorted(tracker.UNITS),
        default="m",
        help="units of the positions of a Tracker export (as calibrated in Tracker; default m)",
    )
    p.add_argument("--track", metavar="NAME", help="the track of a Tracker export of several")
    p.add_argument(
        "--k", type=float, default=0.4, help="inertia ratio I/(m R^2) (default 0.4, solid ball)"
    )
    p.add_argument(
        "--axis",
        type=float,
        nargs=2,
        metavar=("X", "Y"),
        help="position of the turntable's axis in the data's coordinates, m (default 0 0, "
        "which is where turntable track puts it)",
    )
    p.add_argument(
        "--mass", type=float, metavar="M", help="ball mass, kg: adds dimensional coefficients"
    )
    p.add_argument(
        "--fit-omega",
        action="store_true",
        help="fit the turntable's rate too, starting from --omega/--rpm (both models)",
    )
    p.add_argument(
        "--fit-axis",
        action="store_true",
        help="fit the axis position too, starting from --axis (the rolling model; the "
        "slipping motion does not depend on the axis; always for a video)",
    )
    p.add_argument(
        "--plot", metavar="FIG.png", help="draw data, both fits and the residuals (matplotlib)"
    )
    _add_claims_parser(sub)
    from turntable.video.cli import add_parser

    add_parser(sub)
    return parser


def _add_claims_parser(sub: Any) -> None:
    p = sub.add_parser(
        "claims",
        help="print each claim's verdict and the value that decides it",
        description=(
            "Print one line per claim of a claims report: its id, its verdict and the "
            "reproduced value that decides the verdict, with its bound (the claim's "
            "'decisive' key in the registry)."
        ),
    )
    p.add_argument(
        "report",
        nargs="?",
        default=DEFAULT_CLAIMS_REPORT,
        metavar="REPORT.json",
        help=f"claims report written by make (default {DEFAULT_CLAIMS_REPORT})",
    )


def claims_command(args: argparse.Namespace) -> int:
    """Run ``turntable claims``: read the report and print one line per claim."""
    from turntable.claims.report import decisive_lines

    try:
        report = json.loads(Path(args.report).read_text(encoding="utf-8"))
        lines = decisive_lines(report)
    except OSError as exc:
        _fail(
            f"turntable claims: error: cannot read {args.report}: {exc.strerror or exc} "
            "(make writes results/claims.json)"
        )
    except (ValueError, KeyError, TypeError) as exc:
        _fail(
            f"turntable claims: error: {args.report} is not a claims report with a "
            f"decisive value per claim ({type(exc).__name__}: {exc})"
        )
    try:
        sys.stdout.write("\n".join(lines) + "\n")
        sys.stdout.flush()
    except BrokenPipeError:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        raise SystemExit(1) from None
    return 0


def _positive(option: str, value: float | None, unit: str) -> None:
    if value is not None and not (math.isfinite(value) and value > 0):
        _fail(f"turntable fit: error: {option} must be a finite number > 0 ({unit}); got {value}")


def _warn(message: str) -> None:
    print(f"turntable fit: warning: {' '.join(message.split())}", file=sys.stderr)


def _write_json(out: dict[str, Any]) -> None:
    """Print the JSON object; a closed stdout (``| head``) ends the command quietly."""
    try:
        json.dump(out, sys.stdout, indent=2, allow_nan=False)
        sys.stdout.write("\n")
        sys.stdout.flush()
    except BrokenPipeError:
        # Python flushes stdout again at exit: point it at /dev/null so that this does not
        # raise a second time (see the signal module's notes on SIGPIPE).
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        raise SystemExit(1) from None


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


def _read(path: str, setup: film_io.Setup, p: int, args: argparse.Namespace) -> film_io.Film:
    """The film of a CSV file or a Tracker export, or one line and exit status 2."""
    if tracker.is_tracker(path):
        try:
            data, label = tracker.read_tracker(path, args.track, tracker.UNITS[args.units])
        except film_io.FilmError as exc:
            _fail(f"turntable fit: error: {exc}")
        if data.t.size < p // 2 + 1:
            _fail(
                f"turntable fit: error: {path}: track {label!r} has {data.t.size} frames with "
                f"t, x and y; at least {p // 2 + 1} are needed"
            )
        _warn(
            f"{path}: Tracker's track {label!r}, its positions read in {args.units} (the units "
            "calibrated in Tracker, which the file does not say: --units), its times in s"
        )
        return data
    try:
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
        _fail(f"turntable fit: error: {exc}")


def fit_command(args: argparse.Namespace) -> int:
    """Run ``turntable fit``: check everything, fit, print the JSON and the warnings, draw."""
    _positive("--radius", args.radius, "m")
    _positive("--omega", args.omega, "rad/s")
    _positive("--rpm", args.rpm, "revolutions per minute")
    _positive("--k", args.k, "dimensionless")
    _positive("--mass", args.mass, "kg")
    axis = (0.0, 0.0) if args.axis is None else (args.axis[0], args.axis[1])
    if not all(math.isfinite(a) for a in axis):
        _fail(f"turntable fit: error: --axis must be two finite numbers (m); got {args.axis}")
    if args.plot is not None:
        check_plot(args.plot, "turntable fit")
    from turntable.video.cli import VIDEO_SUFFIXES

    video = args.platter_radius is not None or Path(args.data).suffix.lower() in VIDEO_SUFFIXES
    if video and args.platter_radius is None:
        _fail(f"turntable fit: error: {args.data} is a video: give --platter-radius P (m)")
    if not video and args.omega is None and args.rpm is None:
        _fail("turntable fit: error: one of the arguments --omega --rpm is required")
    # a video's image of the ball's centre is off by a few thousandths of R in a fixed
    # direction, more than a rolling fit's precision: the rolling model's axis is fitted
    options = {"fit_omega": args.fit_omega, "fit_axis": args.fit_axis or video}
    p = max(fit.n_parameters(m, **options) for m in fit.MODELS)
    tracked = None
    if video:
        _positive("--platter-radius", args.platter_radius, "m")
        from turntable.video.cli import run_tracking

        tracked, notes = run_tracking(
            args.data,
            args.radius,
            args.platter_radius,
            args.rpm,
            "turntable fit",
            {"ball_at": args.ball_at, "mark_at": args.mark_at},
        )
        for message in notes:
            _warn(message)
    if args.omega is not None:
        omega = args.omega
    elif args.rpm is not None:
        omega = film_io.rpm_to_omega(args.rpm)
    else:
        omega = abs(tracked.calibration.omega)
    setup = film_io.Setup(args.radius, omega, args.k, axis)
    if tracked is not None:
        data = tracked.film
        if data.t.size < p // 2 + 1:
            _fail(
                f"turntable fit: error: {args.data}: the ball was found on {data.t.size} frames; "
                f"at least {p // 2 + 1} are needed"
            )
    else:
        data = _read(args.data, setup, p, args)
    # Extreme but accepted numbers may overflow inside the fit; what that does to the result
    # is reported (None in the JSON, a warning), not numpy's RuntimeWarning lines.
    with warnings.catch_warnings(), np.errstate(all="ignore"):
        warnings.simplefilter("ignore", RuntimeWarning)
        result = fit.fit_film(data, setup, **options)
        if tracked is not None:
            from turntable.video.uncertainty import carry

            measured = omega == abs(tracked.calibration.omega)
            result, parts, notes = carry(tracked, setup, result, omega_measured=measured, **options)
        check = fit.consistency(data, setup, result, **options)
        out = finite_or_none(
            fit.result_json(result, setup, data, args.mass, source=args.data, check=check)
        )
    if tracked is not None:
        from turntable.video.track import video_summary

        out["video"] = finite_or_none(
            video_summary(tracked, given_omega=omega != abs(tracked.calibration.omega))
        )
        out["video"]["stderr_parts"] = finite_or_none(parts)
        out["warnings"] += notes
    _write_json(out)
    for message in out["warnings"]:
        _warn(message)
    if args.plot is not None:
        from turntable.fit import plot as fitplot

        try:
            with warnings.catch_warnings(), np.errstate(all="ignore"):
                warnings.simplefilter("ignore")
                fitplot.plot_fit(args.plot, data, out)
        except Exception as exc:  # any failure to draw: one line, never a traceback
            reason = " ".join(str(exc).split()) or type(exc).__name__
            print(f"turntable fit: error: --plot {args.plot}: {reason}", file=sys.stderr)
            return PLOT_FAILED
    return 0


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of the ``turntable`` console script; returns the exit status."""
    args = _parser().parse_args(sys.argv[1:] if argv is None else list(argv))
    if args.command == "fit":
        return fit_command(args)
    if args.command == "claims":
        return claims_command(args)
    if args.command == "track":
        from turntable.video.cli import track_command

        return track_command(args)
    raise AssertionError(args.command)  # argparse allows only the commands above


if __name__ == "__main__":
    sys.exit(main())
