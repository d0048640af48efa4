"""Smoke test of the benchmarks: the eigenvalue benchmark runs and meets its target, the
driver ``benchmarks/run.py`` knows every topic, and results are merged into the shared file."""

from __future__ import annotations

import importlib.util
import json
import math
import os
import subprocess
import sys
from pathlib import Path
from types import ModuleType

import numpy as np
import pytest

BENCHMARKS = Path(__file__).resolve().parents[1] / "benchmarks"


def _load(name: str) -> ModuleType:
    """A benchmark script, imported as a module (its main() is not run)."""
    spec = importlib.util.spec_from_file_location(f"benchmarks_{name}", BENCHMARKS / f"{name}.py")
    assert spec is not None
    assert spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def bench() -> ModuleType:
    """benchmarks/eigenvalues.py."""
    return _load("eigenvalues")


@pytest.fixture(scope="module")
def common() -> ModuleType:
    """benchmarks/_common.py (results file, versions, command line)."""
    return _load("_common")


def test_every_topic_is_run_by_the_driver() -> None:
    run = _load("run")
    names = [topic.NAME for topic in run.TOPICS]
    assert names == ["eigenvalues", "solution", "speed", "fit"]
    for topic in run.TOPICS:
        assert callable(topic.run)
        assert callable(topic.print_result)
        assert Path(topic.__file__).name == f"{topic.NAME}.py"


def test_eigenvalue_section_on_a_small_grid(bench: ModuleType) -> None:
    res = bench.bench_eigenvalues([1e-6, 1.0, 1e9], [0.4, 1.0])
    worst = res["methods"]["turntable.eigenvalues"]["worst"]
    for q in ("alpha1", "alpha2", "beta"):
        assert isinstance(worst[q], float)
        assert math.isfinite(worst[q])
        assert worst[q] <= bench.EIGENVALUE_TARGET
    assert res["pass"] is True
    # The reference agrees with itself at more digits and with mpmath.eig of L.
    ref = res["reference"]
    assert ref["max_relative_change_with_40_more_digits"] < 1e-40
    assert ref["max_relative_difference_to_mpmath_eig_of_L_at_decades"] < 1e-40
    # The measurement can see a wrong answer: the plain double-precision form
    # loses every digit of alpha1 at mu0 = 1e9 (eps^2 / 8 is below one ulp of 1).
    assert res["methods"]["textbook complex128"]["by_decade"]["1e9"]["alpha1"] > 0.1


def test_results_are_merged_into_the_shared_file(common: ModuleType, tmp_path: Path) -> None:
    out = tmp_path / "benchmarks.json"
    out.write_text(json.dumps({"other": {"x": 1}, "eigenvalues": "stale"}))
    common.write_results(out, {"eigenvalues": {"pass": True}, "meta": common.meta()})
    data = json.loads(out.read_text())
    assert data["other"] == {"x": 1}
    assert data["eigenvalues"] == {"pass": True}
    assert set(data["meta"]) >= {"python", "numpy", "scipy"}
    # Each key written records the provenance of the run that wrote it (turntable.provenance).
    assert set(data["provenance"]) == {"eigenvalues", "meta"}
    record = data["provenance"]["eigenvalues"]
    assert len(record["git_commit"]) == 40 or record["git_commit"] == "unknown"
    assert isinstance(record["git_dirty"], bool | None)
    assert record["packages"]["numpy"] == np.__version__
    assert set(record["packages"]) >= {"scipy", "mpmath", "sympy", "matplotlib", "snakemake"}
    assert [p.name for p in tmp_path.iterdir()] == ["benchmarks.json"]


def test_the_pipeline_benchmark_writes_every_row_between_the_guides_markers(
    tmp_path: Path,
) -> None:
    pipeline = _load("pipeline")
    runs = [{name: 1.0 + i for name in pipeline.ROWS}
            | {f"{name[:-2]}_cpu_s": 2.0 + 2 * i for name in pipeline.ROWS}
            | {"setup_s": 2.0, "build_s": 3.0} for i in range(3)]  # fmt: skip
    result = {"commands": ["python benchmarks/pipeline.py"], "cpu_count": 2, "machine": "m",
              "load_average_1min": {"min": 1.0, "max": 2.0}} | pipeline.summary(runs)  # fmt: skip
    guide = tmp_path / "guide.md"
    guide.write_text(f"before\n{pipeline.BEGIN}\nold\n{pipeline.END}\nafter\n")
    pipeline.write_guide(result, guide)
    text = guide.read_text()
    assert text.startswith(f"before\n{pipeline.BEGIN}\n")
    assert text.endswith(f"{pipeline.END}\nafter\n")
    assert "old" not in text
    for what, command, target in pipeline.ROWS.values():
        assert f"| {what} | `{command}` | 1, 2, 3 | 2 s | 4 s | {target:g} s |" in text
    assert pipeline.BEGIN in pipeline.GUIDE.read_text()


@pytest.mark.parametrize(("keep", "threads"), [(False, 1), (True, 2)], ids=["unset", "set"])
def test_one_blas_thread_after_numpy_is_imported(keep: bool, threads: int) -> None:
    """numpy loads its BLAS with 2 threads; then `one_blas_thread` limits it to 1, unless
    the environment still sets a number, which wins."""
    code = (
        "import os, sys, numpy\n"
        "from threadpoolctl import threadpool_info\n"
        f"sys.path.insert(0, {str(BENCHMARKS)!r})\n"
        "from turntable._blas import one_blas_thread\n"
        f"if not {keep}: del os.environ['OPENBLAS_NUM_THREADS']\n"
        "one_blas_thread()\n"
        "print(*{i['num_threads'] for i in threadpool_info() if i['user_api'] == 'blas'})\n"
    )
    env = {k: v for k, v in os.environ.items() if not k.endswith("_NUM_THREADS")}
    env["OPENBLAS_NUM_THREADS"] = "2"
    out = subprocess.run(
        [sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True
    )
    assert out.stdout.split() == [str(threads)]


def test_the_tracker_s_error_is_estimated_from_the_videos_it_spreads() -> None:
    """``benchmarks/tracker_error.py``: 400 videos whose ln(fitted / true) is drawn with a
    statistical part s and a tracker's part sigma u, sigma = 0.002 (fixed seed), give sigma
    back within 15 % (its spread for 400 such videos: about 6 %), below its 90 % limit; with
    sigma = 0, the limit is below 0.0015."""
    module = _load("tracker_error")
    rng = np.random.default_rng(36)
    s = rng.uniform(0.002, 0.05, 400)
    u = rng.uniform(1.0, 30.0, 400)
    for sigma in (0.002, 0.0):
        d = rng.normal(0.0, np.hypot(s, sigma * u))
        data = [(di, si, ui, math.exp(-di)) for di, si, ui in zip(d, s, u, strict=True)]
        best, upper = module.estimate(data)
        assert best <= upper
        if sigma:
            assert best == pytest.approx(sigma, rel=0.15)
        else:
            assert upper < 0.0015


def test_the_tracker_s_error_is_tested_on_each_renderer_sized_on_the_others() -> None:
    """Sigma 0.002 for renderers "a" and "b", 0.004 for "c" (300 videos each): sized on "a"
    and "b", it is too small for "c", whose coverage falls short of 85 %; "a", judged with
    sigma sized on "b" and "c", is covered."""
    module = _load("tracker_error")
    rng = np.random.default_rng(7)
    data, renderer = {}, {}
    for name, sigma in (("a", 0.002), ("b", 0.002), ("c", 0.004)):
        s, u = rng.uniform(0.002, 0.01, 300), rng.uniform(5.0, 30.0, 300)
        for i, d in enumerate(rng.normal(0.0, np.hypot(s, sigma * u))):
            data[f"{name}{i}"] = (d, s[i], u[i], math.exp(-d))
            renderer[f"{name}{i}"] = name
    got = module.across_renderers(data, renderer)
    assert got["tested_on_c"]["sized_on"] == ["a", "b"]
    assert got["tested_on_c"]["sigma_ml"] == pytest.approx(0.002, rel=0.2)
    assert got["tested_on_c"]["videos_tested"] == 300
    assert got["tested_on_c"]["coverage_2se"] < 0.85
    assert got["tested_on_a"]["coverage_2se"] > 0.97
    own = module.by_renderer(data, renderer)
    assert own["c"]["sigma_ml"] == pytest.approx(0.004, rel=0.2)
    assert own["a"]["sigma_upper_90"] < own["c"]["sigma_ml"]


def test_the_video_benchmark_compares_positions_at_the_film_s_times() -> None:
    """``benchmarks/video.py``: a rolling shutter's film is seen a row delay after each
    frame's time, and its positions are compared with the truth at those times (the truth
    file holds them at the middle of each frame's opening, checked to reproduce): a ball seen
    0.5 frame intervals later (60 frames/s) is 0.03-0.07 R from where it was at the frame's
    time, as much as the target of 0.05 R."""
    from turntable import fit
    from turntable.film import Setup

    video = _load("video")
    setup = Setup(0.008, 3.49, 0.4)
    state0 = [7.0, 0.0, 0.0, 0.4, 0.0, 0.0]
    t = np.arange(30) / 60.0
    xy = fit.positions("slipping", 2.0, state0, t + 0.5 / 60 / 2, setup)  # shutter 0.5
    true = {"t": t, "x": xy[:, 0], "y": xy[:, 1]}
    truth = {"model": "slipping", "coefficient": 2.0, "state0": state0, "setup": setup,
             "renderer": "turntable", "scene": {"fps": 60.0}}  # fmt: skip
    keep = np.arange(1, 30, 2)
    at_frames = video.truth_at(truth, true, keep, np.zeros(keep.size))
    np.testing.assert_allclose(at_frames, (xy[:, 0] + 1j * xy[:, 1])[keep], rtol=0, atol=1e-12)
    delay = np.full(keep.size, 0.5 / 60)
    later = fit.positions("slipping", 2.0, state0, t[keep] + 0.5 / 60 / 2 + delay, setup)
    seen = video.truth_at(truth, true, keep, delay)
    np.testing.assert_allclose(seen, later[:, 0] + 1j * later[:, 1], rtol=0, atol=1e-12)
    moved = np.abs(seen - at_frames) / setup.radius
    assert moved.min() > 0.03
    assert moved.max() < 0.07
    with pytest.raises(ValueError, match="not reproduced"):
        video.truth_at(truth | {"renderer": "mujoco"}, true, keep, delay)


def test_a_ball_of_the_platter_s_shade_is_outside_the_guide_in_both_video_benchmarks() -> None:
    """A steel ball on MuJoCo's mid-grey platter is refused as a ball of the platter's
    colour, which the filming guide rules out: the benchmarks count it outside the guide,
    whether the family drew it or a case of ``unseen.py`` asked for it."""
    sys.path.insert(0, str(BENCHMARKS))
    video, unseen = _load("video"), _load("unseen")
    steel, grey = unseen.STEEL, unseen.GREY
    t, off = np.linspace(0.0, 5.0, 501), np.full(501, 0.1)  # 10 cm from the axis
    assert not video.within_guide("mujoco", {"ball_rgba": steel, "platter_rgba": grey}, t, off)
    assert video.within_guide("mujoco", {"ball_rgba": steel, "platter_rgba": unseen.DARK}, t, off)
    assert video.within_guide("mujoco", {"ball_rgba": unseen.WHITE, "platter_rgba": grey}, t, off)
    assert not video.within_guide("camouflage", {}, t, off)
    level = 0.05
    assert not unseen.truth_of("steel_on_grey150", level)["within_guide"]
    assert unseen.truth_of("base", level)["within_guide"]


RED, BLUE = (200 / 255, 30 / 255, 30 / 255, 1.0), (30 / 255, 80 / 255, 200 / 255, 1.0)


@pytest.mark.parametrize(
    ("family", "ball", "on_label_s", "within"),
    [
        pytest.param("mujoco", {"ball_rgba": RED}, 0.6, False, id="red-stays"),
        pytest.param("mujoco", {"ball_rgba": RED}, 0.4, True, id="red-crosses"),
        pytest.param("mujoco", {"ball_rgba": BLUE}, 2.0, True, id="blue-stays"),
        pytest.param("specular", {"ball_colour": (200, 30, 30)}, 0.6, False, id="project-red"),
    ],
)
def test_a_ball_that_stays_on_a_label_of_its_colour_is_outside_the_guide(
    family, ball, on_label_s, within
) -> None:
    """The guide lets a ball cross a label of its colour, where it is lost, for less than
    0.5 s; the ball's centre is on the 4.5 cm label for ``on_label_s``."""
    sys.path.insert(0, str(BENCHMARKS))
    video = _load("video")
    t = np.linspace(0.0, 5.0, 501)
    r = np.where((t >= 1.0) & (t < 1.0 + on_label_s), 0.03, 0.1)
    fields = ball | {"label_radius": 0.3, "platter_radius": 0.15}
    assert video.within_guide(family, fields, t, r) is within


def test_the_ray_caster_draws_the_ball_where_its_centre_projects() -> None:
    """``benchmarks/raycast_scene.py``: in 10 frames of a tiny SYNTHETIC scene (160x90, a
    white ball of 5 px radius on a dark platter and label, lit from above), its bright pixels
    near its centre's projection are centred on it within 0.5 px (a tenth of its radius:
    perspective and shading move them a little), and it moves."""
    sys.path.insert(0, str(BENCHMARKS))
    scenes = importlib.import_module("raycast_scene")  # a dataclass: imported, not `_load`ed
    scene = scenes.Scene(
        "tiny_SYNTHETIC", "smoke test", width=160, height=90, fps=100.0, duration=0.1,
        R=0.02, z0=(4.0, 0.0, 0.0, 2.0, 0.0, 0.0), lamps=[((0.0, 0.0, 1.0), 0.7, 0.02)],
        label_color=(0.05, 0.05, 0.05), tilt_deg=20.0,
    )  # fmt: skip
    drawn = list(scenes.frames(scene))
    assert len(drawn) == 10
    for image, (u, v), _ in drawn:
        assert image.shape == (90, 160, 3)
        assert image.dtype == np.uint8
        rows, cols = np.mgrid[0:90, 0:160]
        near = np.hypot(cols - u, rows - v) < 10
        ball = near & (image.mean(axis=2) > 128)
        assert 40 < ball.sum() < 120  # a disc of radius 5 px: 79 px
        assert abs(cols[ball].mean() - u) < 0.5
        assert abs(rows[ball].mean() - v) < 0.5
    assert np.hypot(*(drawn[-1][1] - drawn[0][1])) > 1.0


def test_the_raycast_benchmark_counts_a_platter_out_of_the_frame_outside_the_guide() -> None:
    """``benchmarks/raycast.py``: the scene whose platter is partly out of the image, and the
    striped ball, are outside the filming guide; the wood platter's scene is within it."""
    raycast = _load("raycast")
    scenes = raycast.SCENES
    assert all("SYNTHETIC" in name for name in scenes)
    assert raycast.outside_guide(scenes["S01_SYNTHETIC_wood_platter"]) == []
    assert raycast.outside_guide(scenes["S07_SYNTHETIC_platter_out_of_frame"]) == [
        "the platter is not wholly inside the image"
    ]
    assert raycast.outside_guide(scenes["S06_SYNTHETIC_striped_ball_cw_120fps"]) == [
        "a stripe around the ball"
    ]
