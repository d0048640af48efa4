"""``turntable fit FILM.csv`` of a film that ``turntable track`` wrote: the same numbers as
``turntable fit VIDEO``, without tracking again; a film that its calibration does not make, or
a ball radius other than the tracked one, is refused with one line. On a small SYNTHETIC video
(320x180 at 30 frames/s, a clockwise platter and a lens's distortion)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

pytest.importorskip("av")
pytest.importorskip("cv2")

from cli_here import run_here
from turntable import cli, film
from turntable.video.render import Scene, render_video

RADIUS, PLATTER = 0.008, 0.15
SETUP = film.Setup(RADIUS, film.rpm_to_omega(100.0 / 3.0), 0.4, (0.0, 0.0))
SCENE = Scene(
    tilt_deg=30.0,
    roll_deg=4.0,
    size=(320, 180),
    fps=30.0,
    duration=2.0,
    lens_k1=0.05,
    clockwise=True,
)
FIT = ["--radius", str(RADIUS), "--k", "0.4"]


@pytest.fixture(scope="module")
def tracked(tmp_path_factory: pytest.TempPathFactory):
    """The video, and the film `turntable track` wrote of it."""
    folder = tmp_path_factory.mktemp("saved")
    video = folder / "ball_SYNTHETIC.mp4"
    render_video(video, "slipping", 2.0, [7.0, 0.0, 0.0, 0.4, 0.0, 0.0], SETUP, SCENE)
    out = folder / "film.csv"
    code = cli.main(["track", str(video), "--ball-radius", str(RADIUS), "--platter-radius",
                     str(PLATTER), "-o", str(out), "-q"])  # fmt: skip
    assert code == 0
    return video, out


def test_the_fit_of_the_track_is_the_fit_of_the_video(tracked, capsys) -> None:
    """Every number and every warning alike; only the file named differs."""
    video, track = tracked
    of_video = run_here(capsys, "fit", str(video), *FIT, "--platter-radius", str(PLATTER))
    of_track = run_here(capsys, "fit", str(track), *FIT)
    assert of_video.returncode == of_track.returncode == 0, of_track.stderr
    assert of_track.stderr == of_video.stderr
    a, b = json.loads(of_video.stdout), json.loads(of_track.stdout)
    assert a["data"].pop("file") == str(video)
    assert b["data"].pop("file") == str(track)
    assert a["video"].pop("file") == b["video"].pop("file") == str(video)
    assert a == b
    assert a["video"]["stderr_parts"]  # the camera's uncertainty carried


@pytest.mark.parametrize("rate", [["--rpm", "33.25"], ["--omega", "3.482"]], ids=["rpm", "omega"])
def test_a_rate_the_video_contradicts_is_refused(tracked, capsys, rate) -> None:
    """0.25 % off the 33 1/3 rpm the mark measures to a hundredth of a percent: a fit
    with it would be biased; refused with one line, for the video and for its track."""
    video, track = tracked
    says = "the platter turns at 33.3"
    tracked_without = "was tracked without --rpm"  # a track's --rpm must be the tracked one
    for args, expected in (
        ([str(video), "--platter-radius", str(PLATTER)], says),
        ([str(track)], tracked_without if rate[0] == "--rpm" else says),
    ):
        res = run_here(capsys, "fit", *args, *FIT, *rate)
        assert res.returncode == 2, res.stderr
        assert len(res.stderr.strip().splitlines()) == 1
        assert f"{rate[0]} {rate[1]}: " in res.stderr
        assert expected in res.stderr


def _moved(lines: list[str], doc: dict) -> None:
    t, x, y = lines[-1].split(",")
    lines[-1] = f"{t},{float(x) + 1e-4:.10g},{y}"


def _lost(lines: list[str], doc: dict) -> None:
    """Frame 5 lost: its row and its image gone, named among the lost frames."""
    rows = [i for i, line in enumerate(lines) if line[:1].isdigit()]
    del lines[rows[5]]
    doc["saved"]["ball_image_px"][5] = None
    doc["lost_frames"] = [5]


def _older(lines: list[str], doc: dict) -> None:
    del doc["saved"]["lens_shift"]


def _not_a_track(lines: list[str], doc: dict) -> None:
    del doc["saved"]


def _copy(track: Path, folder: Path, edit=None) -> Path:
    """FILM.csv and FILM.json of ``track`` in ``folder``, changed by ``edit(lines, doc)``."""
    lines = track.read_text().splitlines()
    doc = json.loads(track.with_suffix(".json").read_text())
    if edit is not None:
        edit(lines, doc)
    copy = folder / "film.csv"
    copy.write_text("\n".join(lines) + "\n\n")  # a blank line at the end is read as none
    copy.with_suffix(".json").write_text(json.dumps(doc))
    return copy


@pytest.mark.parametrize(
    ("edit", "args"),
    [
        pytest.param(None, FIT, id="as-written"),
        pytest.param(None, [*FIT, "--omega", "3.4907"], id="omega-given"),
        pytest.param(_lost, FIT, id="a-frame-lost"),
        pytest.param(_not_a_track, [*FIT, "--rpm", "33.3"], id="json-without-saved-is-a-film"),
    ],
)
def test_a_track_is_fitted(tracked, tmp_path, capsys, edit, args) -> None:
    _, track = tracked
    res = run_here(capsys, "fit", str(_copy(track, tmp_path, edit)), *args)
    assert res.returncode == 0, res.stderr
    out = json.loads(res.stdout)
    assert ("video" in out) == (edit is not _not_a_track)


@pytest.mark.parametrize(
    ("edit", "args", "says"),
    [
        pytest.param(_moved, FIT, "its positions are not those", id="film-edited"),
        pytest.param(_older, FIT, "not the calibration of a film that this version",
                     id="json-of-another-version"),
        pytest.param(None, ["--radius", "0.009", "--k", "0.4"], "was tracked with 0.008 m",
                     id="radius"),
        pytest.param(None, [*FIT, "--platter-radius", "0.2"], "was tracked with 0.15 m",
                     id="platter-radius"),
        pytest.param(None, [*FIT, "--rpm", "45"], "--rpm 45: ", id="rpm-not-tracked-with"),
        pytest.param(None, [*FIT, "--ball-at", "3,3"], "--ball-at: ", id="seed"),
        pytest.param(None, [*FIT, "--last-frame", "5"], "--last-frame: ", id="last-frame"),
        pytest.param(None, [*FIT, "--axis", "0.01", "0.01"], "--axis: ", id="axis"),
        pytest.param(_not_a_track, [*FIT, "--rpm", "33.3", "--mark-at", "5:1,1"],
                     "--mark-at: ", id="seed-on-a-film"),
        pytest.param(_not_a_track, [*FIT, "--platter-radius", "0.15"], "--platter-radius: ",
                     id="platter-radius-on-a-film"),
    ],
)  # fmt: skip
def test_a_track_that_does_not_hold_together_is_refused(tracked, tmp_path, capsys, edit, args,
                                                       says) -> None:  # fmt: skip
    """Exit status 2, one line naming the file or option."""
    _, track = tracked
    res = run_here(capsys, "fit", str(_copy(track, tmp_path, edit)), *args)
    assert res.returncode == 2, res.stderr
    assert len(res.stderr.strip().splitlines()) == 1, res.stderr
    assert says in res.stderr
