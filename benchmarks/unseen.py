"""Confident wrong answers of the video tracker on MuJoCo scenes the video benchmark does not
draw: right, refused or wrong.

Every video is SYNTHETIC, rendered by MuJoCo (`mujoco_scene.render_mujoco`).  Each of the 39
`CASES` is drawn as ``benchmarks/video.py`` draws a video of family ``mujoco`` (its generator
seeded 1000 + the case's seed, the model by the seed's parity, the coefficient measurable at
the case's frame rate; 3 s at 240 frames/s, 1280x720, a platter of 15 cm at 33 1/3 rpm) and
then changed: balls of the platter's grey or of the mark's colour, hard and low light, black
and steel balls, a wooden table, a glossy platter, thick platters, a radial strip, a second
sticker, a checkered ball, the ball crossing the mark's circle, a camera zoomed out and
panned, tilts of 0-1 degrees, 45 rpm, motion blur, 10 s, balls of 5 and 15 mm, platters of
10 and 17 cm, 720p and 1080p at 30 and 60 frames/s.

Each video is tracked and fitted as ``benchmarks/video.py`` does (`video.measure`) and is

- *refused*: ``turntable track`` stops with its one line;
- *wrong* (a confident wrong answer): tracked with exit status 0, and its positions off by
  more than `WRONG_RMS` ball radii (rms, after the best rotation about the axis) or its Omega
  off by more than `WRONG_OMEGA`, or its fit decisively selects the wrong model where the two
  models are distinguishable;
- *right*: otherwise.

Run ``python benchmarks/unseen.py [--cases NAME ...] [--keep DIR]`` (``--keep``: render into
DIR and reuse the videos found there, rendered from the same draw; MuJoCo takes about a
minute a video); the result is merged into ``results/benchmarks.json`` under ``unseen``.
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from typing import Any

import numpy as np

from results_file import run_cases
from turntable._blas import one_blas_thread
from video import COLOURS, GREYS, draw, measure, reliable_level, render, rgba

#: Thresholds of a confident wrong answer: positions (rms, ball radii), Omega (relative).
WRONG_RMS, WRONG_OMEGA = 0.05, 0.005
#: Duration of the videos, s, unless the case says otherwise.
DURATION = 3.0

WHITE, BLACK, STEEL = (rgba(GREYS[k]) for k in ("white", "black", "steel"))
RED, ORANGE, BLUE, _, YELLOW = (rgba(c) for c in COLOURS)
DARK, GREY, LIGHT = rgba((35, 35, 40)), rgba((150, 150, 155)), rgba((190, 190, 195))
INK, NAVY = rgba((20, 20, 20)), rgba((20, 20, 120))
DARK_WHITE = {"ball_rgba": WHITE, "platter_rgba": DARK, "mark_rgba": WHITE}
BLACK_LIGHT = {"ball_rgba": BLACK, "platter_rgba": LIGHT, "mark_rgba": NAVY}
HD30, HD60 = {"size": (1920, 1080), "fps": 30.0}, {"size": (1920, 1080), "fps": 60.0}

#: name: (seed, changes: keyword arguments of `video.draw`, ``scene`` the MujocoScene's fields)
CASES: dict[str, tuple[int, dict[str, Any]]] = {
    "base": (5000, {}),
    "white_ball_hard_light": (5001, {"scene": DARK_WHITE | {
        "ambient": 0.08, "headlight": 0.0, "light_diffuse": 0.9, "light_elevation_deg": 45.0}}),
    "black_ball_hard_shadow": (5002, {"scene": BLACK_LIGHT | {
        "ambient": 0.1, "headlight": 0.05, "light_diffuse": 0.9, "light_elevation_deg": 40.0}}),
    "same_colour_mark_red": (5003, {"scene": {
        "ball_rgba": RED, "mark_rgba": RED, "mark_shape": "dot", "platter_rgba": DARK}}),
    "two_tone_ball": (5004, {"scene": DARK_WHITE | {
        "ball_rgba": (1.0, 1.0, 1.0, 1.0), "ball_checker": ((0.95, 0.95, 0.93), (0.8, 0.1, 0.1))}}),
    "ball_crosses_mark_circle": (5005, {"scene": DARK_WHITE | {"mark_at": 0.75},
                                        "r0range": (0.10, 0.125)}),
    "label_same_as_ball": (5006, {"scene": {
        "label_radius": 0.3, "label_rgba": RED, "ball_rgba": RED}, "r0range": (0.02, 0.06)}),
    "steel_on_lightgrey": (5007, {"scene": {
        "ball_rgba": STEEL, "platter_rgba": LIGHT, "mark_rgba": INK}}),
    "lightgrey_platter_wood": (5008, {"scene": {
        "platter_rgba": LIGHT, "mark_rgba": INK, "ball_rgba": BLUE, "table_wood": True}}),
    "dark_platter_wood": (5009, {"scene": {
        "platter_rgba": rgba((30, 30, 32)), "table_rgba": rgba((139, 90, 43)),
        "mark_rgba": YELLOW, "ball_rgba": WHITE, "table_wood": True}}),
    "black_ball_light_platter_lowsun": (5010, {"scene": BLACK_LIGHT | {
        "light_elevation_deg": 35.0, "light_diffuse": 0.8}}),
    "same_colour_mark_white_sq": (5011, {"scene": DARK_WHITE | {
        "mark_shape": "strip", "mark_size": (0.008, 0.008)}}),
    "tilt35_r5mm_P017": (5012, {"scene": {"tilt_deg": 35.0}, "radius": 0.005, "platter": 0.17}),
    "tilt0_r15mm_P010": (5013, {"scene": {"tilt_deg": 0.0}, "radius": 0.015, "platter": 0.10}),
    "720p30_r5mm": (5014, {"scene": {"size": (1280, 720), "fps": 30.0}, "radius": 0.005}),
    "radial_tape_dark": (5015, {"scene": {
        "mark_shape": "strip", "mark_size": (0.008, 0.004), "mark_along": "radial",
        "mark_rgba": INK, "platter_rgba": GREY}}),
    "steel_ball_shiny_headlight": (5016, {"scene": {
        "ball_rgba": STEEL, "ball_specular": 1.0, "ball_shininess": 0.9, "headlight": 0.5,
        "platter_rgba": DARK}}),
    "mark_outer_095": (5017, {"scene": {
        "mark_at": 0.95, "mark_shape": "dot", "mark_size": (0.006, 0.006)}}),
    "blue_slipmat_red_ball": (5018, {"scene": {
        "platter_rgba": rgba((30, 50, 120)), "ball_rgba": RED, "mark_rgba": YELLOW,
        "label_radius": 0.3, "label_rgba": WHITE}}),
    "azimuth90_cw_roll": (5019, {"scene": {
        "azimuth_deg": 90.0, "roll_deg": 5.0, "clockwise": True, "tilt_deg": 30.0}}),
    "second_sticker": (5020, {"scene": {
        "platter_rgba": DARK, "mark_rgba": WHITE, "second_dot": (0.0, 0.06, 0.008)}}),
    "orange_mark_on_wood_like_platter": (5021, {"scene": {
        "platter_rgba": rgba((150, 110, 70)), "table_rgba": rgba((40, 40, 40)),
        "ball_rgba": WHITE, "mark_rgba": ORANGE}}),
    "thick_platter_tilt30": (5022, {"scene": {"platter_thickness": 0.025, "tilt_deg": 30.0}}),
    "offcentre_small": (5023, {"scene": {"tilt_deg": 25.0, "zoom_out": 1.6, "pan_deg": 12.0}}),
    "glossy_black_platter": (5024, {"scene": DARK_WHITE | {
        "platter_rgba": rgba((20, 20, 22)), "tilt_deg": 25.0,
        "platter_specular": 0.9, "platter_shininess": 0.6}}),
    "roll15": (5025, {"scene": {"roll_deg": 15.0, "tilt_deg": 20.0}}),
    "thick_platter_tilt15_dark": (5026, {"scene": {
        "platter_thickness": 0.02, "tilt_deg": 15.0, "platter_rgba": DARK, "mark_rgba": WHITE}}),
    "mark_inner_080": (5027, {"scene": {"mark_at": 0.80}}),
    "1080p30_45rpm": (5028, {"scene": HD30, "rpm": 45.0}),
    "720p60_r5_P017_tilt30": (5029, {"scene": {"size": (1280, 720), "fps": 60.0,
                                               "tilt_deg": 30.0},
                                     "radius": 0.005, "platter": 0.17, "duration": 5.0}),
    "1080p60_P010": (5030, {"scene": HD60, "platter": 0.10, "duration": 5.0}),
    "blur_120_1of500": (5031, {"scene": {"fps": 120.0, "shutter": 0.24, "blur_samples": 3}}),
    "ten_seconds_120": (5032, {"scene": {"fps": 120.0}, "duration": 10.0}),
    "1080p30_33rpm": (5028, {"scene": HD30}),
    "720p30_45rpm": (5028, {"scene": {"size": (1280, 720), "fps": 30.0}, "rpm": 45.0}),
    "black_ball_high_sun": (5034, {"scene": BLACK_LIGHT | {
        "label_radius": 0.0, "light_elevation_deg": 80.0}}),
    "1080p60_tilt1_white_dark": (5035, {"scene": HD60 | DARK_WHITE | {"tilt_deg": 1.0},
                                        "duration": 5.0}),
    "1080p30_tilt1_white_dark": (5036, {"scene": HD30 | DARK_WHITE | {"tilt_deg": 1.0}}),
    "steel_on_grey150": (5033, {"scene": {
        "ball_rgba": STEEL, "platter_rgba": GREY, "mark_rgba": INK,
        "label_radius": 0.0}}),
}  # fmt: skip


def truth_of(name: str, level: float) -> dict[str, Any]:
    """The draw of case ``name``: `video.draw`'s of family ``mujoco``, changed."""
    seed, changes = CASES[name]
    changes = {"duration": DURATION} | changes
    return draw(np.random.default_rng(1000 + seed), seed, "mujoco", level, **changes)


def verdict(row: dict[str, Any]) -> str:
    """right, refused or wrong (see the module's docstring)."""
    if not row["tracked"]:
        return "refused"
    off = row["rms_error_radii"] > WRONG_RMS or abs(row["omega_relative_error"]) > WRONG_OMEGA
    wrong_model = row["decisive"] and row["distinguishable"] and row["selected"] != row["model"]
    return "wrong" if off or wrong_model else "right"


def run(names: list[str], folder: Path) -> dict[str, Any]:
    """Render (or reuse), track and fit the cases ``names`` one at a time."""
    level = reliable_level()
    rows = []
    for name in names:
        truth = truth_of(name, level)
        path = folder / f"{name}_{truth['seed']}_SYNTHETIC.mp4"
        row = measure(truth, path, render(truth, path))
        row |= {"case": name, "seed": truth["seed"], "verdict": verdict(row)}
        row["wrong"] = row["verdict"] == "wrong"
        rows.append(row)
        what = (
            f"rms {row['rms_error_radii']:.4f} R, Omega {row['omega_relative_error']:+.2e}, "
            f"{row['model']} -> {row['selected']}{' (decisive)' * row['decisive']}"
            if row["tracked"]
            else row["refusal"]
        )
        print(f"{name} ({truth['seed']}): {row['verdict']}: {what}", flush=True)
    count = {v: sum(r["verdict"] == v for r in rows) for v in ("right", "refused", "wrong")}
    within = [r for r in rows if r["within_guide"]]
    return {
        "synthetic": True,
        "renderer": "mujoco",
        "thresholds": {"position_rms_radii": WRONG_RMS, "omega_relative": WRONG_OMEGA},
        "cases": len(rows),
        **count,
        "within_guide": len(within),
        "right_within_guide": sum(r["verdict"] == "right" for r in within),
        "refusals": {r["case"]: r["refusal"] for r in rows if r["verdict"] == "refused"},
        "wrong_cases": [r["case"] for r in rows if r["wrong"]],
        "rows": rows,
    }


def main() -> None:
    res = run_cases("unseen.py", __doc__, list(CASES), run, "unseen")
    wrong = ": " + ", ".join(res["wrong_cases"]) if res["wrong"] else ""
    print(f"\n{res['cases']} cases: {res['right']} right, {res['refused']} refused, "
          f"{res['wrong']} wrong{wrong}; within the filming guide {res['within_guide']}, of "
          f"which {res['right_within_guide']} right")  # fmt: skip
    for name, line in res["refusals"].items():
        print(f"  refused {name}: {line}")


if __name__ == "__main__":
    one_blas_thread()
    main()
