"""Seeds on any frame (``--ball-at N:U,V``, ``--mark-at N:U,V``), on small SYNTHETIC videos
(320x180 at 30 frames/s): a mark lost mid-way is refused naming the frame, and followed from a
seed; a seed is followed where it does not stand out; bad seeds are one line."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("av")
pytest.importorskip("cv2")

from cli_here import run_here
from turntable import film
from turntable.video import camera
from turntable.video.check import first_failure
from turntable.video.decode import Video, VideoError, rgb, write_video
from turntable.video.render import Scene, render_video
from turntable.video.seeds import Seed
from turntable.video.track import track_video

RADIUS, PLATTER = 0.008, 0.15
SETUP = film.Setup(RADIUS, film.rpm_to_omega(100.0 / 3.0), 0.4, (0.0, 0.0))
STATE0 = [7.0, 0.0, 0.0, 0.4, 0.0, 0.0]
SCENE = Scene(tilt_deg=25.0, roll_deg=4.0, size=(320, 180), fps=30.0, duration=1.5)
#: The mark is drawn on none of these frames (0.67 s, longer than a gap can be).
HIDDEN = tuple(range(15, 35))
TRACK = ["--ball-radius", str(RADIUS), "--platter-radius", str(PLATTER)]


def mark_pixel(truth, frame: int) -> str:
    """The mark's centre in a frame (at the middle of its exposure), as U,V."""
    at = truth.omega * (truth.film.t[frame] + SCENE.shutter / SCENE.fps / 2)
    xy = SCENE.mark_at * PLATTER * np.array([[math.cos(at), math.sin(at)]])
    u, v = camera.project(truth.pose, xy)[0]
    return f"{u:.1f},{v:.1f}"


def ball_pixel(truth, frame: int) -> str:
    """The image of the ball's centre in a frame, as U,V."""
    xy = np.array([[truth.film.x[frame], truth.film.y[frame]]])
    u, v = camera.project(truth.pose, xy, RADIUS)[0]
    return f"{u:.1f},{v:.1f}"


@pytest.fixture(scope="module")
def hidden_mark(tmp_path_factory: pytest.TempPathFactory):
    """A video whose mark is hidden on frames 15-34."""
    path = tmp_path_factory.mktemp("seeds") / "hidden_mark_SYNTHETIC.mp4"
    truth = render_video(path, "slipping", 2.0, STATE0, SETUP, SCENE._replace(mark_hidden=HIDDEN))
    return path, truth


def test_a_mark_lost_mid_way_is_refused_naming_the_frame(hidden_mark, tmp_path, capsys) -> None:
    """One line naming the frame where the mark was lost and the seed that resumes from it;
    --plot draws that frame; nothing else is written."""
    path, _ = hidden_mark
    out, picture = tmp_path / "film.csv", tmp_path / "lost.png"
    res = run_here(capsys, "track", str(path), *TRACK, "-o", str(out), "--plot", str(picture))
    assert res.returncode == 2
    assert len(res.stderr.strip().splitlines()) == 1
    assert "the mark is lost at frame 15 " in res.stderr
    assert "give --mark-at 15:U,V" in res.stderr
    assert "--last-frame" not in res.stderr  # 15 frames before it are too few for a film
    assert sorted(p.name for p in tmp_path.iterdir()) == ["lost.png"]


def test_plot_draws_the_frame_where_the_mark_was_lost(hidden_mark) -> None:
    """What --plot draws on that error is frame 15, the mark where it was last seen."""
    path, truth = hidden_mark
    with pytest.raises(VideoError) as lost:
        track_video(path, RADIUS, PLATTER)
    with Video(path) as video:
        frame = next(rgb(p) for i, _, p in video.frames() if i == 15)
    assert lost.value.found.frame == 15
    np.testing.assert_array_equal(lost.value.found.image, frame)
    mark = next(c for c in lost.value.found.candidates if c.kind == "mark")
    seen = np.array([float(x) for x in mark_pixel(truth, 14).split(",")])
    assert np.hypot(mark.u - seen[0], mark.v - seen[1]) < 2.0


def test_a_seed_where_the_mark_is_seen_again_resumes_it(hidden_mark, tmp_path, capsys) -> None:
    """--mark-at 35:U,V on the first frame where it is drawn again: the mark is followed from
    there (and not on the hidden frames), Omega within 0.2 %, the ball within 0.05 R."""
    path, truth = hidden_mark
    out = tmp_path / "film.csv"
    seed = f"35:{mark_pixel(truth, 35)}"
    res = run_here(capsys, "track", str(path), *TRACK, "--mark-at", seed, "-o", str(out))
    assert res.returncode == 0, res.stderr
    calibration = json.loads(out.with_suffix(".json").read_text())
    assert calibration["omega_rad_s"] == pytest.approx(truth.omega, rel=2e-3)
    tracked = film.read_film(out)
    x = np.interp(tracked.t, truth.film.t, truth.film.x)
    y = np.interp(tracked.t, truth.film.t, truth.film.y)
    assert np.sqrt(np.mean((tracked.x - x) ** 2 + (tracked.y - y) ** 2)) < 0.05 * RADIUS


def test_fit_video_takes_seeds_on_any_frame(hidden_mark, capsys) -> None:
    path, truth = hidden_mark
    seed = f"35:{mark_pixel(truth, 35)}"
    res = run_here(capsys, "fit", str(path), "--radius", str(RADIUS), "--platter-radius",
                   str(PLATTER), "--mark-at", seed, "--ball-at", ball_pixel(truth, 0))  # fmt: skip
    assert res.returncode == 0, res.stderr


@pytest.mark.parametrize(
    ("seeds", "says"),
    [
        pytest.param(["--mark-at", "-3:100,50"], "must be 0 or more", id="negative-frame"),
        pytest.param(["--mark-at", "x:100,50"], "must be a whole number", id="frame-not-a-number"),
        pytest.param(["--ball-at", "2.5:100,50"], "must be a whole number", id="frame-not-whole"),
        pytest.param(["--ball-at", "3:100,y"], "expected [N:]U,V", id="pixel-not-a-number"),
        pytest.param(["--mark-at", "3:100"], "expected [N:]U,V", id="one-number"),
        pytest.param(["--mark-at", "3:nan,50"], "expected finite U,V", id="not-finite"),
        pytest.param(["--mark-at", "460:100,50"], "frame 460 is past the end", id="past-the-end"),
        pytest.param(["--ball-at", "5:1,2", "--ball-at", "5:3,4"], "twice for frame 5", id="twice"),
        pytest.param(["--last-frame", "18"], "needs 20 frames at least", id="last-frame-early"),
        pytest.param(["--ball-at", "2:320,50"], "outside the image (320x180 px)", id="outside"),
        pytest.param(["--last-frame", "46"], "past the end", id="last-frame-past-the-end"),
        pytest.param(
            ["--last-frame", "20", "--mark-at", "25:1,2"], "25 is after", id="seed-after-last-frame"
        ),
    ],
)
def test_bad_seeds_are_one_line_naming_the_option(hidden_mark, seeds, says, tmp_path, capsys):
    """Before any tracking: exit status 2, one line naming the option and what is wrong."""
    path, _ = hidden_mark
    res = run_here(capsys, "track", str(path), *TRACK, *seeds, "-o", str(tmp_path / "f.csv"))
    assert res.returncode == 2
    assert len(res.stderr.strip().splitlines()) == 1
    assert seeds[0] in res.stderr
    assert says in res.stderr
    assert list(tmp_path.iterdir()) == []


def _with_a_lamp_s_spot(src: Path, dst: Path, centre: np.ndarray, radius: float) -> None:
    """``src`` with a lamp's bright spot that stays where it is (a nearly white glow, its
    core ``radius`` px) added to every frame."""
    with Video(src) as video:
        frames = [(t, rgb(picture).astype(float)) for _, t, picture in video.frames()]
    v, u = np.mgrid[0 : SCENE.size[1], 0 : SCENE.size[0]]
    glow = np.clip(1.2 - np.hypot(u - centre[0], v - centre[1]) / radius, 0, 1)[..., None]
    lit = ((t, (im * (1 - glow) + 250 * glow).astype(np.uint8)) for t, im in frames)
    write_video(dst, lit, SCENE.fps, SCENE.size, 18, "rendered, with a lamp's spot added")


def test_a_mark_seeded_in_a_lamp_s_spot_is_followed_out_of_it(tmp_path, capsys) -> None:
    """A white mark on a grey platter starts inside a lamp's bright spot: seeded there, it is
    followed as it turns out of it (not the spot, which stays), and Omega is within 0.5 %."""
    clean, path = tmp_path / "clean_SYNTHETIC.mp4", tmp_path / "spot_SYNTHETIC.mp4"
    scene = SCENE._replace(platter_colour=(120.0, 120.0, 120.0))
    truth = render_video(clean, "slipping", 2.0, STATE0, SETUP, scene)
    mark = np.array([float(x) for x in mark_pixel(truth, 0).split(",")])
    _with_a_lamp_s_spot(clean, path, mark, 6.0)
    out = tmp_path / "film.csv"
    res = run_here(capsys, "track", str(path), *TRACK, "--mark-at", mark_pixel(truth, 0),
                   "--ball-at", ball_pixel(truth, 0), "-o", str(out))  # fmt: skip
    assert res.returncode == 0, res.stderr
    calibration = json.loads(out.with_suffix(".json").read_text())
    assert calibration["omega_rad_s"] == pytest.approx(truth.omega, rel=5e-3)


@pytest.mark.parametrize("option", ["--ball-at", "--mark-at"])
def test_a_failed_check_does_not_ask_for_a_seed_that_was_given(option) -> None:
    failed = {
        "rate": {"passed": False, "says": "the mark turns at 0.00149 rpm"},
        "ball_moves": {"passed": False, "says": "the ball's path spreads over 0.1 R only"},
    }
    first = {name: failed[name] for name in (["rate"] if option == "--mark-at" else ["ball_moves"])}
    assert f"give {option} U,V" in first_failure(first)
    assert f"give {option} U,V" not in first_failure(first, [option])
    assert f"{option} N:U,V" in first_failure(first, [option])


@pytest.mark.parametrize(
    "options",
    [
        pytest.param({"mark_at": [Seed(460, 100.0, 50.0)]}, id="seed-past-the-end"),
        pytest.param({"last_frame": 46}, id="last-frame-past-the-end"),
        pytest.param({"last_frame": 20, "ball_at": [Seed(25, 1.0, 2.0)]}, id="seed-after-it"),
    ],
)
def test_bad_frames_are_refused_before_a_frame_is_read(hidden_mark, options) -> None:
    path, _ = hidden_mark
    read: list[int] = []
    with pytest.raises(VideoError, match=r"past the end|is after"):
        track_video(path, RADIUS, PLATTER, progress=lambda *p: read.append(p[1]), **options)
    assert max(read, default=0) == 0


@pytest.mark.parametrize(
    "off_radii", [0.0, 0.9, 2.5], ids=["on-the-ball", "on-its-edge", "beside-it"]
)
def test_a_later_seed_takes_only_the_ball_under_it(hidden_mark, off_radii, tmp_path, capsys):
    """--ball-at 20:U,V on the ball, at its centre or on its edge, is followed (the ball
    within 0.05 R); 2.5 of its image's radii beside it, on the platter, it is refused with the
    frame named, not moved onto the nearest blob of the ball's colour."""
    path, truth = hidden_mark
    u, v = map(float, ball_pixel(truth, 20).split(","))
    xy = np.array([[truth.film.x[20], truth.film.y[20]]])
    r_px = float(camera.image_radius(truth.pose, camera.project(truth.pose, xy, RADIUS), RADIUS)[0])
    seed = f"20:{u + off_radii * r_px:.1f},{v:.1f}"
    out = tmp_path / "film.csv"
    seeds = ["--ball-at", seed, "--mark-at", f"35:{mark_pixel(truth, 35)}"]
    res = run_here(capsys, "track", str(path), *TRACK, *seeds, "-o", str(out))
    if off_radii > 1:
        assert res.returncode == 2
        assert f"--ball-at {seed}: the ball is not found there" in res.stderr
        return
    assert res.returncode == 0, res.stderr
    tracked = film.read_film(out)
    x = np.interp(tracked.t, truth.film.t, truth.film.x)
    y = np.interp(tracked.t, truth.film.t, truth.film.y)
    assert np.sqrt(np.mean((tracked.x - x) ** 2 + (tracked.y - y) ** 2)) < 0.05 * RADIUS
