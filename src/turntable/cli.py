"""The ``turntable`` command.

``turntable claims [REPORT.json]`` prints, for each claim of a claims report
(``results/claims.json`` by default, written by ``make``), one line: its id, its verdict
and the reproduced value that decides it with its bound
(`turntable.claims.report.decisive_lines`).  A report that cannot be read gets one line on
stderr and exit status 2.

``turntable fit DATA.csv --radius R (--omega W | --rpm N) [--k K] [--axis X Y] [--mass M]
[--fit-omega] [--fit-axis] [--plot FIG.png]`` fits the slipping and the rolling-resistance
models to a tracked trajectory or a video (`turntable.fitting.fit_file`) and prints one
JSON object on stdout (`turntable.fit.result_json`).

Bad input (a file that cannot be read or parsed, see `turntable.film.read_film`; a
negative, zero or non-finite number; a value too large for the fit; too few frames) gets a
one-line message on stderr and exit status 2, before any fitting is done.  A completed fit
exits with status 0 and logs, after the JSON, one warning per problem of the fit
(`turntable.fit.problems`: a coefficient at a bound, a selection that is not decisive,
residuals that are not white noise, frames too far apart), each starting with
``turntable fit: warning:``.  With ``--plot``, the JSON is written before the figure; a
figure that cannot be drawn gets one line on stderr and exit status 1.  A closed stdout
(``turntable fit ... | head``) ends the command quietly.  ``python -m turntable`` runs the
same.

``-q`` shows errors only, ``-v`` (``-vv``) also the package's log lines of level INFO
(DEBUG); on a terminal, tracking and fitting a video show a progress bar on stderr.
``--json`` prints the results of ``track`` and ``claims`` as one JSON object.  ``turntable
--print-completion bash`` (or zsh, tcsh) prints a shell completion script (shtab).
"""

from __future__ import annotations

import argparse
import json
import logging
import os
import re
import sys
import warnings
from collections.abc import Sequence
from importlib.metadata import version
from pathlib import Path
from typing import Any, NoReturn

import numpy as np

from turntable import tracker
from turntable._blas import one_blas_thread
from turntable._plot_check import check_plot
from turntable._progress import Progress
from turntable._terminal import bars, logged
from turntable._validate import InputError
from turntable.fitting import fitted_film

log = logging.getLogger(__name__)

#: The claims report ``turntable claims`` reads unless told another (written by ``make``).
DEFAULT_CLAIMS_REPORT = "results/claims.json"
#: Exit status for bad input (as argparse uses for a bad command line).
BAD_INPUT = 2
#: Exit status when the fit was printed but the figure of ``--plot`` could not be drawn.
PLOT_FAILED = 1
#: The shells whose completion ``--print-completion`` prints (shtab's).
SHELLS = ("bash", "zsh", "tcsh")
#: A negative number as a value (``--axis -1e-05 0``), not an option.
_NEGATIVE_NUMBER = re.compile(r"-\.?\d")

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

    def error(self, message: str) -> NoReturn:
        _fail(f"{self.prog}: error: {message}")


def _fail(message: str) -> NoReturn:
    print(" ".join(message.split()) if "\n" in message else message, file=sys.stderr)
    raise SystemExit(BAD_INPUT)


def _common(suppress: bool) -> argparse.ArgumentParser:
    """-q and -v, on the command and on each subcommand (the subcommand's win)."""
    default = {"default": argparse.SUPPRESS} if suppress else {}
    common = argparse.ArgumentParser(add_help=False)
    loud = common.add_mutually_exclusive_group()
    loud.add_argument(
        "-q", "--quiet", action="store_true", help="errors only: no warning, no progress bar",
        **default,
    )  # fmt: skip
    loud.add_argument(
        "-v", "--verbose", action="count", help="more log lines (-vv: debugging)",
        **(default or {"default": 0}),
    )  # fmt: skip
    return common


def _parser() -> argparse.ArgumentParser:
    parser = _Parser(
        prog="turntable", description="The ball on a turntable.", parents=[_common(False)]
    )
    parser.add_argument("--version", action="version", version=f"%(prog)s {version('turntable')}")
    parser.add_argument(
        "--print-completion", choices=SHELLS, help="print a shell completion script and exit"
    )
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    p = sub.add_parser(
        "fit",
        help="fit the friction models to a tracked trajectory",
        description=_DESCRIPTION,
        formatter_class=argparse.RawDescriptionHelpFormatter,
        parents=[_common(True)],
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
    p.add_argument("--json", action="store_true", help="print JSON (as fit always does)")
    _add_claims_parser(sub)
    from turntable.video.cli import add_parser

    add_parser(sub, [_common(True)])
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
        parents=[_common(True)],
    )
    p.add_argument(
        "--json",
        action="store_true",
        help="print one JSON object: the summary and, per claim, its verdict and deciding value",
    )
    p.add_argument(
        "report",
        nargs="?",
        default=DEFAULT_CLAIMS_REPORT,
        metavar="REPORT.json",
        help=f"claims report written by make (default {DEFAULT_CLAIMS_REPORT})",
    )


def _claims_json(report: dict[str, Any]) -> dict[str, Any]:
    """The summary of a claims report and, per claim, its verdict and deciding value."""
    claims = []
    for cid in report["order"]:
        claim = report["claims"][cid]
        key = claim["decisive"]
        claims.append(
            {
                "id": cid,
                "verdict": claim["verdict"],
                "decisive": key,
                "reproduced": claim["reproduced"][key],
                "bound": claim["tolerance"].get(key),
                "expected": claim["expected"],
            }
        )
    return {"summary": report["summary"], "claims": claims}


def claims_command(args: argparse.Namespace) -> int:
    """Run ``turntable claims``: read the report and print one line per claim (or JSON)."""
    try:
        from turntable.claims.report import decisive_lines
    except ImportError as exc:
        raise InputError(
            f"the claims need the extra [claims] ({exc.name} is missing): "
            "pip install 'turntable[claims]'"
        ) from None
    try:
        report = json.loads(Path(args.report).read_text(encoding="utf-8"))
        if args.json:
            text = json.dumps(_claims_json(report), indent=2, allow_nan=False)
        else:
            text = "\n".join(decisive_lines(report))
    except OSError as exc:
        raise InputError(
            f"cannot read {args.report}: {exc.strerror or exc} (make writes results/claims.json)"
        ) from None
    except (ValueError, KeyError, TypeError) as exc:
        raise InputError(
            f"{args.report} is not a claims report with a decisive value per claim "
            f"({type(exc).__name__}: {exc})"
        ) from None
    _write(text)
    return 0


def _write(text: str) -> None:
    """Print ``text``; a closed stdout (``| head``) ends the command quietly."""
    try:
        sys.stdout.write(text + "\n")
        sys.stdout.flush()
    except BrokenPipeError:
        # Python flushes stdout again at exit: point it at /dev/null so that this does not
        # raise a second time (see the signal module's notes on SIGPIPE).
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        raise SystemExit(1) from None


def fit_command(args: argparse.Namespace, progress: Progress | None = None) -> int:
    """Run ``turntable fit``: fit (`turntable.fitting.fit_file`), print the JSON, log the
    problems of the fit, draw."""
    if args.plot is not None:
        check_plot(args.plot, "turntable fit")
    out, data = fitted_film(
        args.data,
        args.radius,
        omega=args.omega,
        rpm=args.rpm,
        k=args.k,
        axis=args.axis,
        mass=args.mass,
        fit_omega=args.fit_omega,
        fit_axis=args.fit_axis,
        platter_radius=args.platter_radius,
        ball_at=args.ball_at,
        mark_at=args.mark_at,
        last_frame=args.last_frame,
        units=args.units,
        track=args.track,
        progress=progress,
    )
    _write(json.dumps(out, indent=2, allow_nan=False))
    for message in out["warnings"]:
        log.warning(message)
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


def parse_args(argv: Sequence[str]) -> argparse.Namespace:
    """The arguments of the command line ``argv``; a negative number such as ``-1e-05`` is a
    value, not an option."""
    return _parser().parse_args([f" {a}" if _NEGATIVE_NUMBER.match(a) else a for a in argv])


def _completion(shell: str) -> str:
    try:
        import shtab
    except ImportError:
        _fail("turntable: error: --print-completion needs shtab (pip install 'turntable[cli]')")
    return shtab.complete(_parser(), shell)


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of the ``turntable`` console script; returns the exit status."""
    one_blas_thread()
    args = parse_args(sys.argv[1:] if argv is None else list(argv))
    if args.print_completion:
        _write(_completion(args.print_completion).rstrip("\n"))
        return 0
    if args.command is None:
        _parser().error("the following arguments are required: COMMAND")
    prog = f"turntable {args.command}"
    with logged(prog, args.quiet, args.verbose), bars(args.quiet) as progress:
        try:
            if args.command == "fit":
                return fit_command(args, progress)
            if args.command == "claims":
                return claims_command(args)
            from turntable.video.cli import track_command

            return track_command(args, progress)
        except InputError as exc:
            if progress is not None:
                progress.close()
            _fail(f"{prog}: error: {exc}")


if __name__ == "__main__":
    sys.exit(main())
