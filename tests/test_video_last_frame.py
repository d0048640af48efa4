"""``--last-frame N`` (Tracker's end frame), on a SYNTHETIC video (320x180 at 30 frames/s) of a
ball that runs into the platter's rim: refused naming the frame, and tracked up to the frame
the refusal names."""

from __future__ import annotations

import re

import numpy as np
import pytest

pytest.importorskip("av")
pytest.importorskip("cv2")

from cli_here import run_here
from turntable import film
from turntable.video.render import Scene, render_video

RADIUS, PLATTER = 0.008, 0.15
SETUP = film.Setup(RADIUS, film.rpm_to_omega(100.0 / 3.0), 0.4, (0.0, 0.0))
TRACK = ["--ball-radius", str(RADIUS), "--platter-radius", str(PLATTER)]


@pytest.fixture(scope="module")
def leaving(tmp_path_factory: pytest.TempPathFactory):
    """A nearly free ball running at 5 cm/s from 7 cm to R / 4 short of the rim (1.4 s)."""
    path = tmp_path_factory.mktemp("last") / "leaving_SYNTHETIC.mp4"
    state0 = [0.07 / RADIUS, 0.0, 0.05 / (RADIUS * SETUP.omega), 0.0, 0.0, 0.0]
    scene = Scene(tilt_deg=25.0, roll_deg=4.0, size=(320, 180), fps=30.0, duration=1.4)
    return path, render_video(path, "slipping", 1e-4, state0, SETUP, scene)


def test_the_rim_refusal_names_the_last_frame_to_give(leaving, tmp_path, capsys) -> None:
    path, _ = leaving
    res = run_here(capsys, "track", str(path), *TRACK, "-o", str(tmp_path / "f.csv"))
    assert res.returncode == 2
    reached = re.search(r"reaches the platter's rim at frame (\d+)", res.stderr)
    assert reached, res.stderr
    assert f"--last-frame {int(reached[1]) - 1}" in res.stderr
    assert list(tmp_path.iterdir()) == []


def test_the_film_ends_at_the_last_frame_given(leaving, tmp_path, capsys) -> None:
    """Tracked up to frame 30, where the ball is 3.75 R inside the rim: 31 frames, within
    0.05 R of the truth."""
    path, truth = leaving
    out = tmp_path / "f.csv"
    res = run_here(capsys, "track", str(path), *TRACK, "--last-frame", "30", "-o", str(out))
    assert res.returncode == 0, res.stderr
    tracked = film.read_film(out)
    assert tracked.t.size == 31
    assert tracked.t[-1] == pytest.approx(truth.film.t[30], abs=1e-3)  # the container's clock
    x = np.interp(tracked.t, truth.film.t, truth.film.x)
    y = np.interp(tracked.t, truth.film.t, truth.film.y)
    off = np.hypot(tracked.x - x, tracked.y - y)
    assert np.sqrt(np.mean(off**2)) < 0.05 * RADIUS


def test_a_track_takes_no_last_frame(leaving, tmp_path, capsys) -> None:
    """The film of turntable track is fitted as tracked: --last-frame is for its video."""
    path, _ = leaving
    out = tmp_path / "f.csv"
    run_here(capsys, "track", str(path), *TRACK, "--last-frame", "30", "-o", str(out))
    res = run_here(capsys, "fit", str(out), "--radius", str(RADIUS), "--last-frame", "20")
    assert res.returncode == 2
    assert "--last-frame: " in res.stderr
    assert "is a track" in res.stderr
