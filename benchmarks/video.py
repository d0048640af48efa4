"""From SYNTHETIC videos to friction: tracking accuracy and speed, Omega, coverage, selection.

Renders videos with `turntable.video.render.render_video` (1280x720, 240 frames/s, 10 s)
of random balls: models alternating, the camera tilted uniformly in 0-35 degrees and
rolled by up to 5, every third platter clockwise and every fourth video at a variable frame
rate (frame times off the grid by up to 0.15 intervals), ball radius 6-10 mm on a platter
of radius 15 cm at 33 1/3 rpm, starting 4-9 cm from the axis with a random velocity; the
coefficient log-uniform in mu0 [0.05, 20] or delta [0.003, 0.3], redrawn until the film
can measure it (Fig. 8: predicted relative standard error below the configured reliable
level, `turntable.fit.predicted_stderr` at the tracking noise `NOISE`).  The videos are
rendered by ``--workers`` processes, then each is tracked alone (timed) and fitted as
``turntable fit VIDEO`` does: Omega and the axis measured in the video, the rolling
model's axis fitted.

Measured: the rms distance of the tracked positions from the truth in ball radii (target at
most 0.05), after the rotation about the axis that best aligns the two frames (the lab
frame's orientation is a convention, undefined for a camera looking straight down);
Omega's error in units of its reported standard error; the fraction of videos whose true
coefficient lies within two reported standard errors of the fit of the true model (target
at least 90 %); the fraction where the true model is selected, among the videos where
`turntable.fit.distinguishability` gives a selection probability of at least 0.95; the
wall time of tracking a 2400-frame 720p video (target at most 20 s).

Run ``python benchmarks/video.py [--videos 20] [--seconds 10] [--workers 2] [--keep DIR]``
(``--keep``: render into DIR and reuse the videos found there); the result is merged into
``results/benchmarks.json`` under the key ``video``.
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from blas_threads import one_blas_thread

if __name__ == "__main__":
    one_blas_thread()

import argparse
import math
import tempfile
import time
from concurrent.futures import ProcessPoolExecutor
from typing import Any

import numpy as np

import turntable as tt
from results_file import ROOT, merge_results
from turntable import film, fit
from turntable.config import validate
from turntable.video.render import Scene, render_video
from turntable.video.track import track_video

PLATTER = 0.15
RPM = 100.0 / 3.0
#: Tracking noise per coordinate assumed for the choice of measurable coefficients, m.
NOISE = 1.5e-4


def draw(rng: np.random.Generator, i: int, duration: float, level: float) -> dict[str, Any]:
    """The ball and the camera of video ``i``."""
    model = fit.MODELS[i % 2]
    radius = float(rng.uniform(0.006, 0.010))
    setup = film.Setup(radius, film.rpm_to_omega(RPM), 0.4, (0.0, 0.0))
    camera = film.Camera(240.0, NOISE, duration)
    while True:
        r0, a0 = rng.uniform(0.04, 0.09), rng.uniform(0, 2 * math.pi)
        v = rng.normal(0.0, 0.03, 2)
        z0 = film.state_from_si([r0 * math.cos(a0), r0 * math.sin(a0)], v, [0.0, 0.0], setup)
        if model == "rolling_resistance":
            z0 = tt.no_slip_state(z0, setup.k)
        lo, hi = (0.05, 20.0) if model == "slipping" else (0.003, 0.3)
        c = float(math.exp(rng.uniform(math.log(lo), math.log(hi))))
        try:
            xy = fit.positions(model, c, z0, np.linspace(0, duration + 0.01, 400), setup)
        except ValueError:
            continue
        if np.max(np.hypot(xy[:, 0], xy[:, 1])) > PLATTER - 2.5 * radius:
            continue  # the ball would reach the rim
        se = fit.predicted_stderr(model, c, z0, setup, camera)
        if se / c < level:
            break
    distinct = (
        fit.distinguishability(c, z0, setup, camera).selection_probability >= 0.95
        if model == "slipping"
        else True
    )
    scene = Scene(
        tilt_deg=float(rng.uniform(0.0, 35.0)),
        roll_deg=float(rng.uniform(-5.0, 5.0)),
        size=(1280, 720),
        fps=240.0,
        duration=duration,
        platter_radius=PLATTER,
        clockwise=i % 3 == 2,
        jitter=0.3 if i % 4 == 3 else 0.0,
    )
    return {"model": model, "coefficient": c, "state0": z0, "setup": setup, "scene": scene,
            "distinct": distinct, "seed": i}  # fmt: skip


def render(truth: dict[str, Any], path: Path) -> Path:
    """Render the video of ``truth`` unless it is there, rendered from the same draw; its
    true positions beside it."""
    truth_file = path.with_suffix(".truth.npz")
    key = repr((truth["model"], truth["coefficient"], list(truth["state0"]), truth["setup"],
                truth["scene"], truth["seed"]))  # fmt: skip
    if path.exists() and truth_file.exists() and str(np.load(truth_file)["key"]) == key:
        return truth_file
    r = render_video(path, truth["model"], truth["coefficient"], truth["state0"],
                     truth["setup"], truth["scene"], seed=truth["seed"])  # fmt: skip
    np.savez(truth_file, t=r.film.t, x=r.film.x, y=r.film.y, key=key)
    return truth_file


def measure(truth: dict[str, Any], path: Path, truth_file: Path) -> dict[str, Any]:
    """Track (timed) and fit one video; compare with the truth."""
    setup, scene = truth["setup"], truth["scene"]
    true = np.load(truth_file)
    start = time.perf_counter()
    track, _ = track_video(path, setup.radius, PLATTER)
    seconds = time.perf_counter() - start
    keep = np.setdiff1d(np.arange(true["t"].size), track.lost)
    got = track.film.x + 1j * track.film.y
    exact = true["x"][keep] + 1j * true["y"][keep]
    turn = np.angle(np.sum(exact * np.conj(got)))
    err = np.abs(got * np.exp(1j * turn) - exact)
    cal = track.calibration
    measured = film.Setup(setup.radius, abs(cal.omega), setup.k, (0.0, 0.0))
    result = fit.fit_film(track.film, measured, fit_axis=True)
    own = result.fits[truth["model"]]
    c = truth["coefficient"]
    return {
        "model": truth["model"],
        "coefficient": c,
        "tilt_deg": scene.tilt_deg,
        "clockwise": scene.clockwise,
        "variable_frame_rate": bool(scene.jitter),
        "radius_m": setup.radius,
        "frames": int(true["t"].size),
        "lost": len(track.lost),
        "rms_error_radii": float(np.sqrt(np.mean(err**2)) / setup.radius),
        "max_error_radii": float(err.max() / setup.radius),
        "omega_z": float((abs(cal.omega) - setup.omega) / cal.omega_stderr),
        "fitted": own.coefficient,
        "stderr": own.stderr,
        "z": float((own.coefficient - c) / own.stderr),
        "covered": bool(own.bound is None and abs(own.coefficient - c) < 2 * own.stderr),
        "residual_lag1": own.autocorrelation,
        "residual_over_noise": own.noise_ratio,
        "distinguishable": truth["distinct"],
        "selected": result.selected,
        "decisive": fit.checked_selection(
            result, fit.consistency(track.film, measured, result, fit_axis=True)
        ).decisive,
        "track_seconds": seconds,
        "track_frames_per_s": true["t"].size / seconds,
    }


def run(videos: int, seconds: float, workers: int, folder: Path) -> dict[str, Any]:
    config: dict[str, Any] = {}
    validate(config, ROOT / "workflow" / "schemas" / "config.schema.yaml")
    level = config["fig8_measurability"]["reliable_relative_error"]
    rng = np.random.default_rng(2026)
    truths = [draw(rng, i, seconds, level) for i in range(videos)]
    paths = [folder / f"bench_{i}_SYNTHETIC.mp4" for i in range(videos)]
    with ProcessPoolExecutor(workers) as pool:
        truth_files = list(pool.map(render, truths, paths))
    rows = []
    for i, (truth, path, truth_file) in enumerate(zip(truths, paths, truth_files, strict=True)):
        r = measure(truth, path, truth_file)
        rows.append(r)
        print(
            f"video {i}: {r['model']} {r['coefficient']:.3g} tilt {r['tilt_deg']:.0f}"
            f"{' clockwise' if r['clockwise'] else ''}{' VFR' if r['variable_frame_rate'] else ''}"
            f": rms {r['rms_error_radii']:.4f} R, Omega z {r['omega_z']:+.2f}, z {r['z']:+.2f}, "
            f"selected {r['selected']}, tracked in {r['track_seconds']:.1f} s",
            flush=True,
        )
    rms = np.array([r["rms_error_radii"] for r in rows])
    z = np.abs([r["omega_z"] for r in rows])
    distinct = [r for r in rows if r["distinguishable"]]
    full = [r["track_seconds"] for r in rows if r["frames"] >= 2400]
    return {
        "videos": len(rows),
        "duration_s": seconds,
        "size": [1280, 720],
        "fps": 240.0,
        "position_rms_radii_max": float(rms.max()),
        "position_rms_radii_median": float(np.median(rms)),
        "position_target_radii": 0.05,
        "omega_within_1se": float(np.mean(z < 1)),
        "omega_within_2se": float(np.mean(z < 2)),
        "coverage_2se": float(np.mean([r["covered"] for r in rows])),
        "coverage_target": 0.9,
        "selection_accuracy_distinguishable": float(
            np.mean([r["selected"] == r["model"] for r in distinct]) if distinct else math.nan
        ),
        "distinguishable_videos": len(distinct),
        "decisive": int(sum(r["decisive"] for r in rows)),
        "track_seconds_2400_frames_median": float(np.median(full)) if full else None,
        "track_seconds_2400_frames_max": float(max(full)) if full else None,
        "track_target_seconds": 20.0,
        "rows": rows,
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.partition("\n")[0])
    parser.add_argument("--videos", type=int, default=20)
    parser.add_argument("--seconds", type=float, default=10.0)
    parser.add_argument("--workers", type=int, default=2, help="processes that render")
    parser.add_argument("--keep", type=Path, help="render into this folder, reuse its videos")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="turntable-video-") as tmp:
        folder = args.keep or Path(tmp)
        folder.mkdir(parents=True, exist_ok=True)
        res = run(args.videos, args.seconds, args.workers, folder)
    res["command"] = "python " + " ".join(["benchmarks/video.py", *sys.argv[1:]])
    merge_results(ROOT / "results/benchmarks.json", {"video": res})
    ok = {True: "PASS", False: "FAIL"}
    print(
        f"\n{res['videos']} SYNTHETIC videos of {res['duration_s']:g} s: position rms median "
        f"{res['position_rms_radii_median']:.4f} R, worst {res['position_rms_radii_max']:.4f} R "
        f"({ok[res['position_rms_radii_max'] <= 0.05]}); Omega within 1 / 2 SE: "
        f"{res['omega_within_1se']:.2f} / {res['omega_within_2se']:.2f}; coverage "
        f"{res['coverage_2se']:.2f} ({ok[res['coverage_2se'] >= 0.9]}); selection "
        f"{res['selection_accuracy_distinguishable']:.2f} over {res['distinguishable_videos']}; "
        f"2400 frames tracked in {res['track_seconds_2400_frames_median']} s (median), "
        f"{res['track_seconds_2400_frames_max']} s (max)"
    )


if __name__ == "__main__":
    main()
