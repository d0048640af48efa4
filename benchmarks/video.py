"""From SYNTHETIC videos to friction: tracking accuracy and speed, Omega, coverage, selection.

Renders videos with `turntable.video.render.render_video` (1280x720, 240 frames/s, 10 s;
``--quick``: 2 s) of random balls: models alternating, the camera tilted uniformly in
0-35 degrees and rolled by up to 5, ball radius 6-10 mm on a platter of radius 15 cm at
33 1/3 rpm, starting 4-9 cm from the axis with a random velocity; the coefficient
log-uniform in mu0 [0.05, 20] or delta [0.003, 0.3], redrawn until the film can measure it
(Fig. 8: predicted relative standard error below the configured reliable level,
`turntable.fit.predicted_stderr` for the camera at the tracking noise measured here).  Each
video is tracked (`turntable.video.track.track_video`) and fitted with the Omega and axis
measured in it, as ``turntable fit VIDEO`` does.

Measured: the rms distance of the tracked positions from the truth in ball radii (target at
most 0.05), after the rotation about the axis that best aligns the two frames (the lab
frame's orientation is a convention, undefined for a camera looking straight down);
Omega's error in units of its reported standard error (|z| < 1 and < 2 in 68 % and 95 %
of the videos if the error is right); the fraction of videos whose true
coefficient lies within two reported standard errors of the fit of the true model (target
at least 90 %); the fraction where the true model is selected, among the videos where
`turntable.fit.distinguishability` gives a selection probability of at least 0.95; the
wall time of tracking a 2400-frame 720p video (target at most 20 s).

Run ``python benchmarks/video.py [--quick] [--videos N]``; the result is merged into
``results/benchmarks.json`` under the key ``video``.
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from blas_threads import one_blas_thread

if __name__ == "__main__":
    one_blas_thread()

import math
import tempfile
import time
from typing import Any

import numpy as np

import _common
import turntable as tt
from turntable import film, fit
from turntable.config import validate
from turntable.video.render import Scene, render_video
from turntable.video.track import track_video

NAME = "video"
PLATTER = 0.15
RPM = 100.0 / 3.0
#: Tracking noise per coordinate assumed for the choice of measurable coefficients, m.
NOISE = 1.5e-4


def _truth(rng: np.random.Generator, i: int, duration: float, level: float) -> dict[str, Any]:
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
    return {"model": model, "coefficient": c, "state0": z0, "setup": setup, "distinct": distinct}


def one_video(rng, i, duration, level, folder: Path) -> dict[str, Any]:
    truth = _truth(rng, i, duration, level)
    setup = truth["setup"]
    scene = Scene(
        tilt_deg=float(rng.uniform(0.0, 35.0)),
        roll_deg=float(rng.uniform(-5.0, 5.0)),
        size=(1280, 720),
        fps=240.0,
        duration=duration,
        platter_radius=PLATTER,
    )
    path = folder / f"bench_{i}_SYNTHETIC.mp4"
    rendered = render_video(
        path, truth["model"], truth["coefficient"], truth["state0"], setup, scene, seed=i
    )
    start = time.perf_counter()
    track, _ = track_video(path, setup.radius, PLATTER)
    seconds = time.perf_counter() - start
    path.unlink()
    keep = np.setdiff1d(np.arange(rendered.film.t.size), track.lost)
    # the lab frame's orientation about the axis is a convention (x perpendicular to the
    # tilt's direction, undefined for a camera looking straight down): compare after the
    # rotation about the axis that best aligns the tracked positions with the true ones
    got = track.film.x + 1j * track.film.y
    true = rendered.film.x[keep] + 1j * rendered.film.y[keep]
    turn = np.angle(np.sum(true * np.conj(got)))
    err = np.abs(got * np.exp(1j * turn) - true)
    cal = track.calibration
    measured = film.Setup(setup.radius, abs(cal.omega), setup.k, (0.0, 0.0))
    result = fit.fit_film(track.film, measured)
    check = fit.consistency(track.film, measured, result)
    out = fit.result_json(result, measured, track.film, check=check)
    name = fit.COEFFICIENT[truth["model"]]
    entry = out[truth["model"]]
    value, se = entry[name], entry[f"{name}_stderr"]
    return {
        "model": truth["model"],
        "coefficient": truth["coefficient"],
        "tilt_deg": scene.tilt_deg,
        "radius_m": setup.radius,
        "frames": int(rendered.film.t.size),
        "lost": len(track.lost),
        "rms_error_radii": float(np.sqrt(np.mean(err**2)) / setup.radius),
        "frame_rotation_deg": float(np.degrees(turn)),
        "max_error_radii": float(err.max() / setup.radius),
        "omega_z": float((abs(cal.omega) - setup.omega) / cal.omega_stderr),
        "fitted": value,
        "stderr": se,
        "covered": bool(value is not None and se and abs(value - truth["coefficient"]) < 2 * se),
        "distinguishable": truth["distinct"],
        "selected": out["selected"],
        "decisive": out["selection"]["decisive"],
        "track_seconds": seconds,
        "track_frames_per_s": rendered.film.t.size / seconds,
    }


def run(quick: bool, videos: int = 20) -> dict[str, Any]:
    """Render, track and fit ``videos`` videos (10 s each, 2 s if ``quick``)."""
    duration = 2.0 if quick else 10.0
    config: dict[str, Any] = {}
    validate(config, _common.ROOT / "workflow" / "schemas" / "config.schema.yaml")
    level = config["fig8_measurability"]["reliable_relative_error"]
    rng = np.random.default_rng(2026)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for i in range(videos):
            rows.append(one_video(rng, i, duration, level, Path(tmp)))
            r = rows[-1]
            print(
                f"video {i}: {r['model']} {r['coefficient']:.3g} tilt {r['tilt_deg']:.0f}: "
                f"rms {r['rms_error_radii']:.3f} R, Omega z {r['omega_z']:+.2f}, covered "
                f"{r['covered']}, selected {r['selected']}, {r['track_seconds']:.1f} s",
                flush=True,
            )
    rms = np.array([r["rms_error_radii"] for r in rows])
    z = np.abs([r["omega_z"] for r in rows])
    distinct = [r for r in rows if r["distinguishable"]]
    full = [r["track_seconds"] for r in rows if r["frames"] >= 2400]
    return {
        "videos": len(rows),
        "duration_s": duration,
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
        "track_seconds_2400_frames_max": float(max(full)) if full else None,
        "track_frames_per_s_median": float(np.median([r["track_frames_per_s"] for r in rows])),
        "track_target_seconds": 20.0,
        "rows": rows,
    }


def print_result(res: dict[str, Any]) -> None:
    print(
        f"\n{res['videos']} SYNTHETIC videos of {res['duration_s']:g} s: position rms "
        f"median {res['position_rms_radii_median']:.3f} R, worst "
        f"{res['position_rms_radii_max']:.3f} R "
        f"({_common.pf(res['position_rms_radii_max'] <= 0.05)}); Omega within 1 / 2 SE: "
        f"{res['omega_within_1se']:.2f} / {res['omega_within_2se']:.2f}; "
        f"coverage {res['coverage_2se']:.2f} ({_common.pf(res['coverage_2se'] >= 0.9)}); "
        f"selection {res['selection_accuracy_distinguishable']:.2f} over "
        f"{res['distinguishable_videos']}; tracking {res['track_frames_per_s_median']:.0f} "
        f"frames/s, 2400 frames in {res['track_seconds_2400_frames_max']} s"
    )


def main(argv: list[str] | None = None) -> int:
    """Run this benchmark; ``--videos N`` sets the number of videos (20)."""
    argv = sys.argv[1:] if argv is None else list(argv)
    videos = 20
    if "--videos" in argv:
        i = argv.index("--videos")
        videos = int(argv[i + 1])
        del argv[i : i + 2]
    global run
    base = run
    run = lambda quick: base(quick, videos)  # noqa: E731
    return _common.main([sys.modules[__name__]], __file__, __doc__.splitlines()[0], argv)


if __name__ == "__main__":
    sys.exit(main())
