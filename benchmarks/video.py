"""From videos to friction on scenes of several kinds and two renderers: tracked or refused,
position error, Omega, coverage, selection, speed, and confident wrong answers.

Every video is SYNTHETIC: 1280x720 at 240 frames/s (but ``mujoco_rates``), of a random ball
of either model on a platter of radius 15 cm at 33 1/3 rpm (coefficient drawn, as Fig. 8
says a film at its frame rate can measure it, at the tracking noise `NOISE`), tilt 0-35
degrees, roll up to 5.  The scene families
(`FAMILIES`):

- rendered by `turntable.video.render` within the filming guide: a white ball on a dark platter
  (``classic``, 10 s: the speed is measured on these), a coloured ball on a grey platter with a
  strip of tape (``colour``), a dark ball on a light platter with its shadow (``dark``), a
  specular ball crossing a printed label (``specular``), and a phone's video (``phone``: a
  main camera's barrel distortion after its own correction, k1 down to -0.02, a rolling
  shutter, mains flicker, variable frame rate, grooves; ``phone_lens``: the same with a barrel
  distortion moving the image's corners inward by up to 5 % and a readout of up to a frame);
- rendered by it outside the guide: a mark as large as the ball (``big_mark``), a ball of
  nearly the platter's colour (``camouflage``);
- rendered by MuJoCo (``mujoco``, `mujoco_scene.render_mujoco`), a renderer the project did
  not write: its shading, anti-aliasing and shadows; and the same at other sizes and frame
  rates (``mujoco_rates``, `RATES`: 1080p at 60 and 120 frames/s, 720p at 30 and 60).

Each video is tracked as ``turntable track`` does (timed) and, if tracked, fitted as
``turntable fit VIDEO`` does.  Its positions are compared with the truth at the film's times
(a rolling shutter's row delay added to each frame's time, as the fit sees them), after the
best rotation about the axis (``rms_error_radii_frame_time``: at the frame's own time, which
counts the ball's move over the row delay as an error).  A *confident wrong answer* is a
video tracked with exit status 0 whose positions are off by more than `WRONG_RMS` ball radii
(rms), whose Omega is off by more than `WRONG_OMEGA`, or whose fit selects the other model
decisively where the two can be told apart (as ``benchmarks/unseen.py`` counts).

Run ``python benchmarks/video.py [--per-family 7] [--workers 2] [--keep DIR] [--families F ...]
[--fps F] [--size W H]`` (``--keep``: render into DIR and reuse the videos found there,
rendered from the same draw; ``--fps``, ``--size``: every video at that frame rate and size,
lighter to render, the coefficients drawn measurable at that rate); the result is
merged into ``results/benchmarks.json`` under ``video``.
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
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
from turntable._blas import one_blas_thread
from turntable.config import validate
from turntable.video.decode import VideoError
from turntable.video.render import Scene, render_video
from turntable.video.track import track_video
from turntable.video.uncertainty import TRACKER_ERROR, carry

PLATTER = 0.15
RPM = 100.0 / 3.0
#: Tracking noise per coordinate assumed for the choice of measurable coefficients, m.
NOISE = 1.5e-4
#: Thresholds of a wrong answer: positions (rms, ball radii), Omega (relative).
WRONG_RMS, WRONG_OMEGA = 0.25, 0.01
#: A coefficient more than this many of its reported standard errors off is a confident wrong
#: answer.
WRONG_Z = 4.0
GREYS = {"white": (240, 240, 235), "black": (25, 25, 28), "steel": (170, 172, 178)}
COLOURS = [(200, 30, 30), (235, 120, 20), (30, 80, 200), (40, 160, 60), (230, 200, 40)]


def rgba(c: tuple[float, ...]) -> tuple[float, ...]:
    """MuJoCo's colour (0-1, opaque) of an RGB colour in 0-255."""
    return (*(x / 255 for x in c), 1.0)


def _colour(rng: np.random.Generator) -> tuple[float, ...]:
    return tuple(float(c) for c in COLOURS[rng.integers(len(COLOURS))])


def _classic(rng):
    return {}, 10.0


def _colourful(rng):
    grey = float(rng.uniform(110, 170))
    return {
        "ball_colour": _colour(rng),
        "platter_colour": (grey, grey, grey + 4),
        "table_colour": (150.0, 110.0, 70.0),
        "mark_shape": "strip",
        "mark_aspect": 2.0,
        "mark_radius": float(rng.uniform(0.35, 0.55)),
        "mark_colour": (245.0, 245.0, 245.0) if rng.random() < 0.5 else (20.0, 20.0, 20.0),
        "mark_along": "tangential" if rng.random() < 0.5 else "radial",
    }, 5.0


def _dark(rng):
    light = float(rng.uniform(170, 215))
    return {
        "ball_colour": GREYS["black"],
        "platter_colour": (light, light - 5, light - 15),
        "table_colour": (60.0, 60.0, 65.0),
        "mark_colour": (20.0, 20.0, 120.0),
        "mark_shape": "square",
        "mark_radius": 0.4,
        "shadow": float(rng.uniform(0.3, 0.5)),
        "light_elevation_deg": float(rng.uniform(50, 75)),
        "light_azimuth_deg": float(rng.uniform(-180, 180)),
    }, 5.0


def _specular(rng):
    return {
        "ball_colour": GREYS["steel"] if rng.random() < 0.5 else _colour(rng),
        "ball_finish": "specular",
        "platter_colour": (30.0, 30.0, 35.0),
        "label_radius": 0.3,
        "label_colour": _colour(rng),
        "mark_colour": (240.0, 220.0, 40.0),
        "shadow": float(rng.uniform(0.2, 0.4)),
    }, 5.0


def _phone(rng):
    return {
        "ball_colour": GREYS["white"] if rng.random() < 0.5 else _colour(rng),
        "platter_colour": (40.0, 40.0, 40.0),
        "grooves": 10.0,
        "lens_k1": float(rng.uniform(-0.02, 0.0)),
        "readout": float(rng.uniform(0.3, 0.9)),
        "flicker": float(rng.uniform(0.02, 0.08)),
        "flicker_phase_deg": float(rng.uniform(0, 360)),
        "jitter": 0.3,
        "noise": 4.0,
    }, 5.0


#: The strongest barrel distortion of ``phone_lens``: it moves the corners of the image
#: (1280x720, a 60-degree field of view: r^2 = 0.439 in focal lengths) inward by 5 %.
PHONE_K1 = -0.05 / 0.439


def _phone_lens(rng):
    fields, duration = _phone(rng)
    return fields | {
        "lens_k1": float(rng.uniform(PHONE_K1, 0.0)),
        "readout": float(rng.uniform(0.0, 1.0)),
    }, duration


def _big_mark(rng):
    return {"mark_radius": 1.0, "mark_shape": "disc"}, 5.0


def _camouflage(rng):
    return {"ball_colour": (52.0, 50.0, 50.0)}, 5.0


def _mujoco(rng):
    ball = [GREYS["white"], GREYS["steel"], *COLOURS][rng.integers(2 + len(COLOURS))]
    dark = rng.random() < 0.5
    platter = (35.0, 35.0, 40.0) if dark else (150.0, 150.0, 155.0)
    return {
        "ball_rgba": rgba(ball),
        "ball_specular": float(rng.uniform(0.1, 0.8)),
        "platter_rgba": rgba(platter),
        "mark_shape": "strip" if rng.random() < 0.5 else "dot",
        "mark_rgba": rgba((240, 240, 240) if dark else (20, 20, 20)),
        "label_radius": 0.3 if rng.random() < 0.5 else 0.0,
        "light_azimuth_deg": float(rng.uniform(-180, 180)),
        "light_elevation_deg": float(rng.uniform(50, 80)),
    }, 5.0


#: (width, height, frames/s) of the videos of family ``mujoco_rates``: a phone's and a
#: camera's other modes.
RATES = [(1920, 1080, 60.0), (1280, 720, 60.0), (1280, 720, 30.0), (1920, 1080, 120.0)]


def _mujoco_rates(rng):
    fields, duration = _mujoco(rng)
    width, height, fps = RATES[rng.integers(len(RATES))]
    return fields | {"size": (width, height), "fps": fps}, duration


#: A ball and a platter of nearly its shade, which the filming guide rules out (a ball of the
#: platter's colour): MuJoCo's steel ball on its mid-grey or light grey platter.
NEAR_SHADE = [(GREYS["steel"], (150.0, 150.0, 155.0)), (GREYS["steel"], (190.0, 190.0, 195.0))]


#: A ball of its label's colour (no channel differing by more than this, 0-1) is lost on the
#: label, which the guide allows for less than `ON_LABEL_S` (s) at a time.
SAME_COLOUR, ON_LABEL_S = 0.1, 0.5


def within_guide(family: str, fields: dict[str, Any], t: np.ndarray, r: np.ndarray) -> bool:
    """Whether a video of ``family`` with the scene ``fields``, its ball at ``r`` (m) from the
    axis at times ``t`` (s), is filmed as the guide asks."""
    pair = (fields.get("ball_rgba"), fields.get("platter_rgba"))
    return (
        FAMILIES[family][1]
        and pair not in [(rgba(b), rgba(p)) for b, p in NEAR_SHADE]
        and not _stays_on_its_colour(family, fields, t, r)
    )


def _stays_on_its_colour(family: str, fields: dict[str, Any], t, r) -> bool:
    """The ball's centre on a label of the ball's colour for `ON_LABEL_S` or longer."""
    if FAMILIES[family][2] == "mujoco":
        from mujoco_scene import MujocoScene

        scene = MujocoScene(**fields)
        ball, label = np.array(scene.ball_rgba[:3]), np.array(scene.label_rgba[:3])
    else:
        scene = Scene(**fields)
        ball, label = np.array(scene.ball_colour) / 255, np.array(scene.label_colour) / 255
    if scene.label_radius <= 0 or np.max(np.abs(ball - label)) > SAME_COLOUR:
        return False
    on = np.concatenate([[False], r < scene.label_radius * scene.platter_radius, [False]])
    edges = np.flatnonzero(np.diff(on.astype(int)))
    return any(t[b - 1] - t[a] >= ON_LABEL_S for a, b in zip(edges[::2], edges[1::2], strict=True))


#: name: (draw of the scene's fields and the duration, within the filming guide, renderer)
FAMILIES = {
    "classic": (_classic, True, "turntable"),
    "colour": (_colourful, True, "turntable"),
    "dark": (_dark, True, "turntable"),
    "specular": (_specular, True, "turntable"),
    "phone": (_phone, True, "turntable"),
    "phone_lens": (_phone_lens, True, "turntable"),
    "big_mark": (_big_mark, False, "turntable"),
    "camouflage": (_camouflage, False, "turntable"),
    "mujoco": (_mujoco, True, "mujoco"),
    "mujoco_rates": (_mujoco_rates, True, "mujoco"),
}


def draw(
    rng: np.random.Generator,
    i: int,
    family: str,
    level: float,
    *,
    radius: float | None = None,
    platter: float = PLATTER,
    rpm: float = RPM,
    duration: float | None = None,
    r0range: tuple[float, float] | None = None,
    scene: dict[str, Any] | None = None,
) -> dict[str, Any]:
    """The ball, the camera and the scene of video ``i`` of a family.

    The keyword arguments change the family's video, its random draws left as they are: the
    ball's radius (m), the platter's, its rpm, the duration (s), the range of the ball's
    initial distance from the axis (m; by default 4-9 cm times P / 15 cm) and fields of the
    scene (``fps`` also sets the frame rate at which the coefficient must be measurable).
    """
    make, _, renderer = FAMILIES[family]
    fields, drawn = make(rng)
    fields |= scene or {}
    duration = duration or drawn
    model = fit.MODELS[i % 2]
    drawn_radius = float(rng.uniform(0.006, 0.010))
    radius = radius or drawn_radius
    setup = film.Setup(radius, film.rpm_to_omega(rpm), 0.4, (0.0, 0.0))
    camera = film.Camera(fields.get("fps", 240.0), NOISE, duration)
    lo_r0, hi_r0 = r0range or (0.04 * platter / PLATTER, 0.09 * platter / PLATTER)
    while True:
        r0, a0 = rng.uniform(lo_r0, hi_r0), rng.uniform(0, 2 * math.pi)
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
        if np.max(np.hypot(xy[:, 0], xy[:, 1])) > platter - 2.5 * radius:
            continue  # the ball would reach the rim
        se = fit.predicted_stderr(model, c, z0, setup, camera)
        if se / c < level:
            break
    distinct = (
        fit.distinguishability(c, z0, setup, camera).selection_probability >= 0.95
        if model == "slipping"
        else True
    )
    scene = {
        "tilt_deg": float(rng.uniform(0.0, 35.0)),
        "roll_deg": float(rng.uniform(-5.0, 5.0)),
        "size": (1280, 720),
        "fps": 240.0,
        "duration": duration,
        "platter_radius": platter,
        "clockwise": bool(rng.random() < 1 / 3),
    } | fields
    t = np.linspace(0, duration + 0.01, 400)
    guide = within_guide(family, scene, t, np.hypot(xy[:, 0], xy[:, 1]))
    return {"family": family, "within_guide": guide, "renderer": renderer,
            "model": model, "coefficient": c, "state0": z0, "setup": setup, "scene": scene,
            "distinct": distinct, "seed": i}  # fmt: skip


def render(truth: dict[str, Any], path: Path) -> Path:
    """Render the video of ``truth`` unless it is there, rendered from the same draw; its
    true positions beside it."""
    truth_file = path.with_suffix(".truth.npz")
    key = repr((truth["model"], truth["coefficient"], list(truth["state0"]), truth["setup"],
                sorted(truth["scene"].items()), truth["seed"], truth["renderer"]))  # fmt: skip
    if path.exists() and truth_file.exists() and str(np.load(truth_file)["key"]) == key:
        return truth_file
    args = (truth["model"], truth["coefficient"], truth["state0"], truth["setup"])
    if truth["renderer"] == "mujoco":
        from mujoco_scene import MujocoScene, render_mujoco

        r = render_mujoco(path, *args, MujocoScene(**truth["scene"]), seed=truth["seed"])
    else:
        r = render_video(path, *args, Scene(**truth["scene"]), seed=truth["seed"])
    np.savez(truth_file, t=r.film.t, x=r.film.x, y=r.film.y, key=key)
    return truth_file


def truth_at(truth: dict[str, Any], true: Any, keep: np.ndarray, delay: np.ndarray) -> np.ndarray:
    """The true positions (x + iy, m) of frames ``keep`` of a rendered video, ``delay`` (s)
    after each frame's time (the film's times: a rolling shutter's row delay added).

    The truth file holds each frame's position at the middle of its shutter's opening, which
    ``turntable.video.render`` files under the frame's time (half the opening earlier) and
    MuJoCo's renderer under its own time; checked to reproduce.
    """
    model, c, z0, setup = truth["model"], truth["coefficient"], truth["state0"], truth["setup"]
    t = np.asarray(true["t"], float)[keep]
    if truth["renderer"] == "turntable":
        scene = Scene(**truth["scene"])
        t = t + scene.shutter / scene.fps / 2
    xy = fit.positions(model, c, z0, t, setup)
    drift = np.max(np.hypot(xy[:, 0] - true["x"][keep], xy[:, 1] - true["y"][keep]))
    if not drift < 1e-6 * setup.radius:
        raise ValueError(f"the truth is not reproduced at the frame times ({drift:.3g} m off)")
    xy = fit.positions(model, c, z0, t + delay, setup)
    return xy[:, 0] + 1j * xy[:, 1]


def _off(got: np.ndarray, exact: np.ndarray, radius: float) -> tuple[np.ndarray, float]:
    """The distances (m) of positions from the truth after the best rotation about the axis,
    and their rms in units of ``radius``."""
    turn = np.angle(np.sum(exact * np.conj(got)))
    err = np.abs(got * np.exp(1j * turn) - exact)
    return err, float(np.sqrt(np.mean(err**2)) / radius)


def measure(truth: dict[str, Any], path: Path, truth_file: Path) -> dict[str, Any]:
    """Track (timed) and fit one video; compare with the truth."""
    setup, scene = truth["setup"], truth["scene"]
    true = np.load(truth_file)
    row = {k: truth[k] for k in ("family", "within_guide", "renderer", "model", "coefficient")}
    row |= {"tilt_deg": scene["tilt_deg"], "clockwise": scene["clockwise"],
            "radius_m": setup.radius, "frames": int(true["t"].size),
            "size": list(scene["size"]), "fps": scene["fps"]}  # fmt: skip
    start = time.perf_counter()
    try:
        track, _ = track_video(path, setup.radius, scene["platter_radius"])
    except VideoError as exc:
        return row | {"tracked": False, "refusal": str(exc).split(": ", 1)[1], "wrong": False}
    seconds = time.perf_counter() - start
    keep = np.setdiff1d(np.arange(true["t"].size), track.lost)
    got = track.film.x + 1j * track.film.y
    # the truth at the film's times: a rolling shutter's row delay, which the film's times
    # carry, moves the ball on; at the frame's own time for comparison
    delay = track.film.t - track.times[keep]
    exact = truth_at(truth, true, keep, delay)
    framed = true["x"][keep] + 1j * true["y"][keep]
    err, rms = _off(got, exact, setup.radius)
    rms_framed = _off(got, framed, setup.radius)[1]
    cal = track.calibration
    omega_error = float(abs(cal.omega) / setup.omega - 1)
    row |= {
        "tracked": True,
        "lost": len(track.lost),
        "rms_error_radii": rms,
        "rms_error_radii_frame_time": rms_framed,
        "max_error_radii": float(err.max() / setup.radius),
        "omega_relative_error": omega_error,
        "omega_z": float((abs(cal.omega) - setup.omega) / cal.omega_stderr),
        "wrong": bool(rms > WRONG_RMS or abs(omega_error) > WRONG_OMEGA),
        "track_seconds": seconds,
        "checks": {k: float(v["value"]) for k, v in track.checks.items()},
    }
    measured = film.Setup(setup.radius, abs(cal.omega), setup.k, (0.0, 0.0))
    statistical = fit.fit_film(track.film, measured, fit_axis=True)
    options = {"omega_measured": True, "fit_omega": False, "fit_axis": True}
    result, parts, _ = carry(track, measured, statistical, **options)
    own = result.fits[truth["model"]]
    stat = statistical.fits[truth["model"]].stderr
    name = fit.COEFFICIENT[truth["model"]]
    c = truth["coefficient"]
    z = float((own.coefficient - c) / own.stderr)
    check = fit.consistency(track.film, measured, result, fit_axis=True)
    decisive = fit.checked_selection(result, check).decisive
    wrong_model = bool(decisive and truth["distinct"] and result.selected != truth["model"])
    return row | {
        "fitted": own.coefficient,
        "stderr": own.stderr,
        "stderr_statistical": stat,
        "stderr_calibration": parts[truth["model"]][f"{name}_stderr_calibration"],
        "stderr_tracker": parts[truth["model"]][f"{name}_stderr_tracker"],
        "tracker_error": TRACKER_ERROR,
        "at_bound": own.bound is not None,
        "lens_measured": cal.lens.measured,
        "z": z,
        "z_statistical": float((own.coefficient - c) / stat),
        "covered": bool(own.bound is None and abs(z) < 2),
        "covered_statistical": bool(own.bound is None and abs(own.coefficient - c) < 2 * stat),
        "confident_wrong_coefficient": bool(own.bound is None and abs(z) > WRONG_Z),
        "residual_over_noise": own.noise_ratio,
        "distinguishable": truth["distinct"],
        "selected": result.selected,
        "decisive": decisive,
        "wrong": row["wrong"] or wrong_model,
        "wrong_model": wrong_model,
    }


def summary(rows: list[dict[str, Any]]) -> dict[str, Any]:
    """What a set of videos gives: tracked, refused, wrong; positions, Omega, coverage."""
    tracked = [r for r in rows if r["tracked"]]
    right = [r for r in tracked if not r["wrong"]]
    distinct = [r for r in right if r["distinguishable"]]
    full = [r["track_seconds"] for r in tracked if r["frames"] >= 2400]

    def stat(f, key):
        return float(f([r[key] for r in right])) if right else None

    return {
        "videos": len(rows),
        "tracked": len(tracked),
        "refused": len(rows) - len(tracked),
        "confident_wrong": sum(r["wrong"] for r in rows),
        "position_rms_radii_median": stat(np.median, "rms_error_radii"),
        "position_rms_radii_max": stat(np.max, "rms_error_radii"),
        "omega_relative_error_max": float(max(abs(r["omega_relative_error"]) for r in right))
        if right
        else None,
        "coverage_2se": stat(np.mean, "covered"),
        "coverage_2se_statistical_only": stat(np.mean, "covered_statistical"),
        "largest_abs_z": float(max(abs(r["z"]) for r in right)) if right else None,
        "largest_abs_z_statistical_only": float(max(abs(r["z_statistical"]) for r in right))
        if right
        else None,
        "confident_wrong_coefficient": sum(
            r.get("confident_wrong_coefficient", False) for r in rows
        ),
        "decisive_wrong_model": sum(r.get("wrong_model", False) for r in rows),
        "right_model_where_distinguishable": float(
            np.mean([r["selected"] == r["model"] for r in distinct])
        )
        if distinct
        else None,
        "distinguishable": len(distinct),
        "track_seconds_2400_frames_max": float(max(full)) if full else None,
        "refusals": sorted({r["refusal"] for r in rows if not r["tracked"]}),
    }


def reliable_level() -> float:
    """The relative standard error up to which a coefficient counts as measurable (Fig. 8's
    ``reliable_relative_error`` of the configuration)."""
    config: dict[str, Any] = {}
    validate(config, ROOT / "workflow" / "schemas" / "config.schema.yaml")
    return config["fig8_measurability"]["reliable_relative_error"]


def run(
    per_family: int,
    workers: int,
    folder: Path,
    families: list[str],
    scene: dict[str, Any] | None = None,
) -> dict[str, Any]:
    level = reliable_level()
    rng = np.random.default_rng(2026)
    count = {f: per_family if FAMILIES[f][1] else max(per_family // 2, 2) for f in families}
    truths = [draw(rng, i, f, level, scene=scene) for f in families for i in range(count[f])]
    paths = [folder / f"{t['family']}_{t['seed']}_SYNTHETIC.mp4" for t in truths]
    with ProcessPoolExecutor(workers) as pool:
        truth_files = list(pool.map(render, truths, paths))
    rows = []
    for truth, path, truth_file in zip(truths, paths, truth_files, strict=True):
        r = measure(truth, path, truth_file)
        rows.append(r)
        what = (
            f"rms {r['rms_error_radii']:.4f} R ({r['rms_error_radii_frame_time']:.4f} at the "
            f"frame's time), Omega {100 * r['omega_relative_error']:+.3f} %, "
            f"z {r['z']:+.2f} ({r['z_statistical']:+.2f} statistical), "
            f"{'WRONG ' * r['wrong']}tracked in {r['track_seconds']:.1f} s"
            if r["tracked"]
            else f"refused: {r['refusal']}"
        )
        print(f"{path.name}: {r['model']} tilt {r['tilt_deg']:.0f}: {what}", flush=True)
    within = [r for r in rows if r["within_guide"]]
    return {
        "videos_as": sorted({f"{r['size'][0]}x{r['size'][1]} at {r['fps']:g}" for r in rows}),
        "targets": {
            "tracked_within_guide": 0.95,
            "position_rms_radii": 0.05,
            "omega_relative": 0.005,
            "coverage_2se": 0.9,
            "largest_abs_z": WRONG_Z,
            "confident_wrong": 0,
            "track_seconds_2400_frames": 10.0,
        },
        "within_guide": summary(within),
        "outside_guide": summary([r for r in rows if not r["within_guide"]]),
        "families": {f: summary([r for r in rows if r["family"] == f]) for f in families},
        "rows": rows,
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.partition("\n")[0])
    parser.add_argument("--per-family", type=int, default=7, help="videos of each family")
    parser.add_argument("--families", nargs="+", choices=sorted(FAMILIES), default=list(FAMILIES))
    parser.add_argument("--workers", type=int, default=2, help="processes that render")
    parser.add_argument("--keep", type=Path, help="render into this folder, reuse its videos")
    parser.add_argument("--fps", type=float, help="every video at this frame rate")
    parser.add_argument("--size", type=int, nargs=2, metavar=("W", "H"), help="... this size")
    args = parser.parse_args()
    scene = {"fps": args.fps} if args.fps else {}
    scene |= {"size": tuple(args.size)} if args.size else {}
    with tempfile.TemporaryDirectory(prefix="turntable-video-") as tmp:
        folder = args.keep or Path(tmp)
        folder.mkdir(parents=True, exist_ok=True)
        res = run(args.per_family, args.workers, folder, args.families, scene)
    res["command"] = "python " + " ".join(["benchmarks/video.py", *sys.argv[1:]])
    merge_results(ROOT / "results/benchmarks.json", {"video": res})
    print()
    groups = {"within the guide": res["within_guide"], "outside": res["outside_guide"]}
    for name, s in (groups | res["families"]).items():
        print(
            f"{name}: {s['tracked']}/{s['videos']} tracked, {s['refused']} refused, "
            f"{s['confident_wrong']} confident wrong; rms median {s['position_rms_radii_median']} "
            f"max {s['position_rms_radii_max']} R; Omega max {s['omega_relative_error_max']}; "
            f"coverage {s['coverage_2se']} (statistical SE alone "
            f"{s['coverage_2se_statistical_only']}), largest |z| {s['largest_abs_z']} "
            f"({s['largest_abs_z_statistical_only']}), {s['confident_wrong_coefficient']} "
            f"coefficients > {WRONG_Z:g} SE off; right model "
            f"{s['right_model_where_distinguishable']} "
            f"of {s['distinguishable']}; 2400 frames in {s['track_seconds_2400_frames_max']} s"
        )


if __name__ == "__main__":
    one_blas_thread()
    main()
