"""What a user gets from ``turntable track`` and ``turntable fit`` on videos of a renderer
the project did not write: right, refused or wrong.

Every video is SYNTHETIC, drawn by an independent numpy ray caster
(``benchmarks/raycast_scene.py``, written without reading the project's renderer or
tracker): the 18 `raycast_scene.SCENES` (wood-grain and granite platters, vignetting,
sensor noise, 250 kbit/s H.264, balls with caps or a stripe, clockwise platters, a platter
partly out of the frame, an off-centre label, two lamps, a camera straight down, 1080p at
25 frames/s with crf 30, 45 rpm), the ball moving as `turntable.solve` says (k = 0.4).

Each video is tracked and fitted through the command line, as a user would, without seeds::

    turntable track VIDEO --ball-radius R --platter-radius P --rpm N -o NAME.csv --json --plot
    turntable fit NAME.csv --radius R --plot

and compared with the truth: the exit status and the one-line refusal; the positions' rms
error in ball radii after the best rotation about the axis; Omega's relative error; the
fitted mu0's z (its error over its reported standard error).  Each scene is

- *refused*: ``turntable track`` (or ``turntable fit``) stops with its one line;
- *wrong* (a confident wrong answer): exit status 0 and positions off by more than
  `WRONG_RMS` ball radii (rms), or Omega by more than `WRONG_OMEGA`, or mu0 by more than
  `WRONG_Z` of its standard errors (``benchmarks/video.py``'s thresholds);
- *right*: otherwise;

and within the filming guide (``docs/guides/filming.md``) or not (`outside_guide`: the
platter not wholly in the image, a striped ball, an unusually low bitrate, a mark larger
than half the ball's diameter, a ball staying on a label of its colour).  A refused scene is
tracked again with the first frame's seeds ``--ball-at U,V --mark-at U,V`` read off the
truth (as a user reads them off ``--plot``); that result is reported beside it (``seeded``)
and does not change its verdict.

Run ``python benchmarks/raycast.py [--cases NAME ...] [--keep DIR]`` (``--keep``: render
into DIR and reuse the videos found there, rendered from the same scene, their first frame
the one drawn now; the command line's outputs go to DIR/out).  One process at a time:
rendering the 18 takes about 20 min, tracking and fitting them about 10 min (2 cores); 6 of
them, one rendered, took 3.4 min.  The result is merged into ``results/benchmarks.json``
under ``raycast``.
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import dataclasses
import json
import subprocess
import time
from typing import Any

import cv2
import numpy as np

from raycast_scene import SCENES, Camera, Scene, frames, render, seeds, simulate
from results_file import run_cases
from turntable._blas import one_blas_thread
from turntable.video.uncertainty import TRACKER_ERROR
from video import ON_LABEL_S, SAME_COLOUR, WRONG_OMEGA, WRONG_RMS, WRONG_Z

#: The command line of the package installed beside this Python.
TURNTABLE = str(Path(sys.executable).with_name("turntable"))
#: The parts of a coefficient's standard error that a row records (``turntable fit``'s).
_PARTS = ("statistical", "calibration", "tracker")
#: A bitrate (bit/s) below this is not a camera's or a phone's usual one (the guide's
#: "Compression"; phones record 720p at several Mbit/s).
USUAL_BITRATE = 1_000_000


def outside_guide(sc: Scene) -> list[str]:
    """What the filming guide asks that scene ``sc`` does not (empty: within the guide).

    Parameters
    ----------
    sc : Scene
        The scene.

    Returns
    -------
    list of str
        The reasons: the platter not wholly in the image, a stripe around the ball, a bitrate
        below `USUAL_BITRATE`, a mark larger than half the ball's diameter, the ball's centre
        on a label of its colour for `ON_LABEL_S` or longer.
    """
    reasons = []
    cam = Camera(sc)
    a = np.linspace(0.0, 2 * np.pi, 720, endpoint=False)
    rim = cam.project(np.stack([sc.P * np.cos(a), sc.P * np.sin(a), np.zeros_like(a)], -1))
    size = np.array([sc.width, sc.height])
    if np.any(rim < -0.5) or np.any(rim > size - 0.5):
        reasons.append("the platter is not wholly inside the image")
    if sc.ball_marks == "stripe":
        reasons.append("a stripe around the ball")
    if sc.bitrate is not None and sc.bitrate < USUAL_BITRATE:
        reasons.append(f"{sc.bitrate / 1000:g} kbit/s is not a camera's usual bitrate")
    if sc.mark_diam_R > 1.0:
        reasons.append("a mark larger than half the ball's diameter")
    t = np.arange(round(sc.duration * sc.fps)) / sc.fps
    pos, _, _ = simulate(sc, t)
    ang = (-1.0 if sc.clockwise else 1.0) * sc.rpm * 2 * np.pi / 60 * t + np.radians(sc.phase0_deg)
    on_platter = np.stack(
        [np.cos(ang) * pos[:, 0] + np.sin(ang) * pos[:, 1],
         -np.sin(ang) * pos[:, 0] + np.cos(ang) * pos[:, 1]], -1
    )  # fmt: skip
    on = np.hypot(*(on_platter - sc.label_offset).T) < sc.label_r_frac * sc.P
    same = np.max(np.abs(np.subtract(sc.ball_color, sc.label_color))) <= SAME_COLOUR
    edges = np.flatnonzero(np.diff(np.concatenate([[0], on.astype(int), [0]])))
    longest = max(
        (t[b - 1] - t[a] for a, b in zip(edges[::2], edges[1::2], strict=True)), default=0
    )
    if same and longest >= ON_LABEL_S:
        reasons.append(f"the ball stays {longest:.1f} s on a label of its colour")
    return reasons


def _lines(text: str) -> list[str]:
    """The lines of a command's stderr, without its progress bars."""
    return [ln for ln in text.splitlines() if ln.strip() and "%|" not in ln and "\r" not in ln]


def best_rotation(truth: np.ndarray, est: np.ndarray) -> tuple[float, np.ndarray]:
    """The rotation about the axis (rad) that brings ``truth`` (n x 2) nearest ``est``, and
    ``truth`` so rotated."""
    dot = (truth * est).sum()
    crs = (truth[:, 0] * est[:, 1] - truth[:, 1] * est[:, 0]).sum()
    th = np.arctan2(crs, dot)
    c, s = np.cos(th), np.sin(th)
    return float(th), truth @ np.array([[c, s], [-s, c]])


def track_and_fit(
    sc: Scene, video: Path, truth_file: Path, out: Path, extra: tuple[str, ...] = ()
) -> dict[str, Any]:
    """Track (with the options ``extra``) and fit one video through the command line.

    Parameters
    ----------
    sc : Scene
        The scene of the video.
    video, truth_file : Path
        The video and its truth (`raycast_scene.render`).
    out : Path
        The folder of the command line's outputs (``NAME.csv``, ``NAME.json``, plots).
    extra : tuple of str
        More options of ``turntable track`` (the seeds).

    Returns
    -------
    dict
        Exit statuses, the refusal, the warnings, the errors and the fitted coefficient.
    """
    tr = np.load(truth_file)
    name = sc.name + ("_seeded" if extra else "")
    csv = out / f"{name}.csv"
    row: dict[str, Any] = {"options": list(extra)}
    start = time.perf_counter()
    cmd = [TURNTABLE, "track", str(video), "--ball-radius", str(sc.R), "--platter-radius",
           str(sc.P), "--rpm", f"{sc.rpm:.4f}", "-o", str(csv), "--json",
           "--plot", str(out / f"{name}_track.png"), *extra]  # fmt: skip
    p = subprocess.run(cmd, capture_output=True, text=True, check=False)
    row |= {"track_exit": p.returncode, "track_seconds": round(time.perf_counter() - start, 1)}
    lines = _lines(p.stderr)
    if p.returncode != 0:
        last = lines[-1] if lines else p.stderr.strip()[-300:]
        return row | {"refusal": last.replace("turntable track: error: ", "").replace(
            f"{video}: ", "")}  # fmt: skip
    row["warnings"] = [ln.replace(f"{video}: ", "") for ln in lines if "warning" in ln]
    film = json.loads(csv.with_suffix(".json").read_text())
    row["omega_relative_error"] = film["omega_rad_s"] / float(tr["omega"]) - 1
    row["clockwise_reported"] = film.get("clockwise_from_above")
    data = [ln for ln in csv.read_text().splitlines() if ln.strip() and not ln.startswith("#")]
    head = data[0].split(",")
    arr = np.array([[float(v) for v in ln.split(",")] for ln in data[1:]])
    t, x, y = (arr[:, head.index(k)] for k in ("t", "x", "y"))
    idx = np.rint(t * float(tr["fps"])).astype(int)
    truth = tr["lab_xy_m"][idx].copy()
    if bool(tr["clockwise"]):
        truth[:, 1] *= -1  # the film's convention: the platter turning counterclockwise
    est = np.column_stack([x, y])
    th, turned = best_rotation(truth, est)
    err = np.hypot(*(turned - est).T) / sc.R
    row |= {
        "frames_tracked": len(t),
        "frames": len(tr["t"]),
        "rms_error_radii": float(np.sqrt(np.mean(err**2))),
        "max_error_radii": float(err.max()),
        "rotation_deg": float(np.degrees(th)),
    }
    start = time.perf_counter()
    cmd = [
        TURNTABLE,
        "fit",
        str(csv),
        "--radius",
        str(sc.R),
        "--plot",
        str(out / f"{name}_fit.png"),
    ]
    p = subprocess.run(cmd, capture_output=True, text=True, check=False)
    row |= {"fit_exit": p.returncode, "fit_seconds": round(time.perf_counter() - start, 1)}
    lines = _lines(p.stderr)
    row["warnings"] += [ln for ln in lines if "warning" in ln]
    if p.returncode != 0:
        return row | {"refusal": lines[-1] if lines else p.stderr.strip()[-300:]}
    fit = json.loads(p.stdout)
    slipping = fit.get("slipping") or {}
    mu0, se = slipping.get("mu0"), slipping.get("mu0_stderr")
    parts = fit["video"]["stderr_parts"]["slipping"]
    row |= {
        "selected": fit.get("selected"),
        "decisive": (fit.get("selection") or {}).get("decisive"),
        "mu0": mu0,
        "mu0_stderr": se,
        "mu0_limits": {k: v for k, v in slipping.items() if "limit" in k},
        "z": (mu0 - sc.mu0) / se if mu0 is not None and se else None,
        # the parts of the standard error, for benchmarks/tracker_error.py
        "at_bound": bool(slipping.get("at_bound")),
        **{f"stderr_{p}": parts[f"mu0_stderr_{p}"] for p in _PARTS},
        "tracker_error": TRACKER_ERROR,
    }
    return row


def verdict(row: dict[str, Any]) -> str:
    """right, refused or wrong (see the module's docstring)."""
    if row["track_exit"] != 0 or row.get("fit_exit") != 0:
        return "refused"
    off = row["rms_error_radii"] > WRONG_RMS or abs(row["omega_relative_error"]) > WRONG_OMEGA
    return "wrong" if off or (row["z"] is not None and abs(row["z"]) > WRONG_Z) else "right"


def _reuse(sc: Scene, folder: Path) -> Path | None:
    """The truth file of ``sc`` in ``folder`` if its video was rendered from the same scene
    and its first frame (``NAME_frame0.png``) is the one `raycast_scene.frames` draws."""
    truth = folder / f"{sc.name}_truth.npz"
    if not (truth.exists() and (folder / f"{sc.name}.mp4").exists()):
        return None
    scene = json.loads(json.dumps(dataclasses.asdict(sc)))
    if json.loads(str(np.load(truth)["scene"])) != scene:
        return None
    first = cv2.imread(str(folder / f"{sc.name}_frame0.png"))
    drawn = next(frames(sc))[0]
    return truth if first is not None and np.array_equal(first[..., ::-1], drawn) else None


def _say(row: dict[str, Any]) -> str:
    if row["track_exit"] != 0 or row.get("fit_exit") != 0:
        return row["refusal"]
    z = "" if row["z"] is None else f", z {row['z']:+.2f}"
    return (
        f"rms {row['rms_error_radii']:.4f} R, Omega {row['omega_relative_error']:+.1e}"
        f", mu0 {row['mu0']} (true {row['mu0_true']}){z}"
    )


def run(names: list[str], folder: Path) -> dict[str, Any]:
    """Render (or reuse), track and fit the scenes ``names`` one at a time.

    Parameters
    ----------
    names : list of str
        Scenes of `raycast_scene.SCENES`.
    folder : Path
        Where the videos are rendered (and reused); the command line's outputs in its ``out``.

    Returns
    -------
    dict
        The summary and a row per scene.
    """
    out = folder / "out"
    out.mkdir(parents=True, exist_ok=True)
    rows = []
    for name in names:
        sc = SCENES[name]
        truth = _reuse(sc, folder)
        rendered = truth is None
        start = time.perf_counter()
        truth = truth or render(sc, folder)
        video = folder / f"{name}.mp4"
        reasons = outside_guide(sc)
        row = {
            "scene": name,
            "synthetic": True,
            "unusual": sc.unusual,
            "within_guide": not reasons,
            "outside_guide": reasons,
            "size": [sc.width, sc.height],
            "fps": sc.fps,
            "mu0_true": sc.mu0,
            "render_seconds": round(time.perf_counter() - start, 1) if rendered else None,
        }
        row |= track_and_fit(sc, video, truth, out)
        row["verdict"] = verdict(row)
        print(f"{name}: {row['verdict']}: {_say(row)}", flush=True)
        if row["verdict"] == "refused" and row["track_exit"] != 0:
            ball, mark = seeds(sc)
            seeded = track_and_fit(sc, video, truth, out, ("--ball-at", ball, "--mark-at", mark))
            seeded["mu0_true"] = sc.mu0
            seeded["verdict"] = verdict(seeded)
            row["seeded"] = seeded
            print(f"  seeded {ball} {mark}: {seeded['verdict']}: {_say(seeded)}", flush=True)
        rows.append(row)
    count = {v: sum(r["verdict"] == v for r in rows) for v in ("right", "refused", "wrong")}
    within = [r for r in rows if r["within_guide"]]
    return {
        "synthetic": True,
        "renderer": "numpy ray caster (benchmarks/raycast_scene.py)",
        "seeds": "none; a refused scene again with the first frame's seeds from the truth",
        "thresholds": {
            "position_rms_radii": WRONG_RMS,
            "omega_relative": WRONG_OMEGA,
            "abs_z": WRONG_Z,
        },
        "scenes": len(rows),
        **count,
        "within_guide": len(within),
        "right_within_guide": sum(r["verdict"] == "right" for r in within),
        "refusals": {r["scene"]: r["refusal"] for r in rows if r["verdict"] == "refused"},
        "seeded": {r["scene"]: r["seeded"]["verdict"] for r in rows if "seeded" in r},
        "wrong_cases": [r["scene"] for r in rows if r["verdict"] == "wrong"],
        "rows": rows,
    }


def main() -> None:
    """Run the scenes asked for and merge the result into ``results/benchmarks.json``."""
    res = run_cases("raycast.py", __doc__, list(SCENES), run, "raycast")
    wrong = ": " + ", ".join(res["wrong_cases"]) if res["wrong"] else ""
    print(f"\n{res['scenes']} SYNTHETIC scenes: {res['right']} right, {res['refused']} refused, "
          f"{res['wrong']} wrong{wrong}; within the filming guide {res['within_guide']}, of "
          f"which {res['right_within_guide']} right")  # fmt: skip
    for name, line in res["refusals"].items():
        print(f"  refused {name}: {line} (seeded: {res['seeded'].get(name, '-')})")


if __name__ == "__main__":
    one_blas_thread()
    main()
