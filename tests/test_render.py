"""`turntable.video.render` draws what a Scene says: the colours of the ball, the platter, the
label, the mark, the table and the shadow where they must be; a grey default; a strip's
shape; the lens's distortion, the rolling shutter and the flicker; one-line errors."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("av")

import av

from turntable import film
from turntable.video import camera
from turntable.video.render import AMBIENT, Rendered, Scene, default_pose, render_video

RADIUS, PLATTER, OMEGA = 0.015, 0.15, 3.49
SETUP = film.Setup(RADIUS, OMEGA, 0.4, (0.0, 0.0))
#: A nearly free ball at rest at (-90, 45) mm.
STILL = ("slipping", 1e-4, [-6.0, 3.0, 0.0, 0.0, 0.0, 0.0])
#: Small, sharp, clean: no noise, lossless, a short exposure, a platter without grain.
CLEAN = Scene(
    size=(320, 180),
    fps=30.0,
    duration=0.2,
    tilt_deg=0.0,
    noise=0.0,
    crf=0,
    shutter=0.1,
    platter_grain=0.0,
    grooves=0.0,
)
COLOURFUL = {
    "ball_colour": (200, 40, 30),
    "platter_colour": (60, 110, 60),
    "table_colour": (150, 140, 120),
    "mark_colour": (250, 230, 40),
    "mark_radius": 1.0,
    "label_radius": 0.4,
    "label_colour": (40, 70, 180),
    "shadow": 0.6,
    "light_azimuth_deg": 0.0,
    "light_elevation_deg": 40.0,
}


def render(path: Path, scene: Scene, **kwargs) -> tuple[Rendered, list[np.ndarray]]:
    """Render the still ball and decode the frames (RGB, float)."""
    truth = render_video(path, *STILL, SETUP, scene, **kwargs)
    with av.open(str(path)) as video:
        frames = [f.to_ndarray(format="rgb24").astype(float) for f in video.decode(video=0)]
    return truth, frames


def patch(img: np.ndarray, uv: np.ndarray, half: int = 1) -> np.ndarray:
    """Mean colour of the (2 half + 1)^2 pixels around the image point ``uv``."""
    u, v = np.round(np.asarray(uv).ravel()).astype(int)
    return img[v - half : v + half + 1, u - half : u + half + 1].reshape(-1, 3).mean(axis=0)


def mark_angle(img: np.ndarray, pose: camera.Pose) -> float:
    """Angle (rad, counterclockwise, lab) of the centroid of the bright mark at tilt 0."""
    v, u = np.nonzero(img[..., 1] > 220)
    x, y = camera.back_project(pose, [[u.mean(), v.mean()]])[0]
    return math.atan2(y, x)


@pytest.fixture(scope="module", params=[False, True], ids=["counterclockwise", "clockwise"])
def colourful(request, tmp_path_factory):
    path = tmp_path_factory.mktemp("render") / "colour_SYNTHETIC.mp4"
    truth, frames = render(path, CLEAN._replace(clockwise=request.param, **COLOURFUL))
    return request.param, truth, frames


def test_ball_has_its_shaded_colour(colourful) -> None:
    clockwise, truth, frames = colourful
    i = 3
    x, y = truth.film.x[i], (-1 if clockwise else 1) * truth.film.y[i]
    centre = np.array([x, y, RADIUS])
    normal = camera.centre(truth.pose) - centre
    normal /= np.linalg.norm(normal)
    light = np.array([math.cos(math.radians(40.0)), 0.0, math.sin(math.radians(40.0))])
    shaded = np.array(COLOURFUL["ball_colour"]) * (AMBIENT + (1 - AMBIENT) * (normal @ light))
    seen = patch(frames[i], camera.project(truth.pose, [[x, y]], height=RADIUS))
    np.testing.assert_allclose(seen, shaded, atol=12)


def test_platter_table_label_and_mark_have_their_colours(colourful) -> None:
    clockwise, truth, frames = colourful
    pose, sign = truth.pose, -1 if clockwise else 1
    for i in (0, 4):
        img = frames[i]
        np.testing.assert_allclose(
            patch(img, camera.project(pose, [[0.0, -0.11]])), (60, 110, 60), atol=6
        )
        np.testing.assert_allclose(patch(img, (3, 3)), (150, 140, 120), rtol=0.1)
        # on the label's paper, between its inner ring and its lines of print
        for a in np.linspace(0, 2 * math.pi, 8, endpoint=False):
            at = 0.4 * 0.4 * PLATTER * np.array([[math.cos(a), math.sin(a)]])
            np.testing.assert_allclose(patch(img, camera.project(pose, at)), (40, 70, 180), atol=12)
        a = OMEGA * (truth.film.t[i] + 0.1 / 30.0 / 2)
        mark = 0.88 * PLATTER * np.array([[math.cos(a), sign * math.sin(a)]])
        np.testing.assert_allclose(patch(img, camera.project(pose, mark)), (250, 230, 40), atol=12)


def test_shadow_falls_away_from_the_light(colourful) -> None:
    """The light comes from +x, 40 degrees high: the shadow is on the -x side of the ball."""
    clockwise, truth, frames = colourful
    x, y = truth.film.x[2], (-1 if clockwise else 1) * truth.film.y[2]
    img = frames[2]
    dark = patch(img, camera.project(truth.pose, [[x - 1.9 * RADIUS, y]]))
    lit = patch(img, camera.project(truth.pose, [[x + 1.9 * RADIUS, y]]))
    np.testing.assert_allclose(lit, (60, 110, 60), atol=6)
    np.testing.assert_allclose(dark, 0.4 * np.array([60, 110, 60]), atol=6)


def test_a_specular_ball_has_a_white_highlight(tmp_path) -> None:
    brightest = {}
    for finish in ("matte", "specular"):
        scene = CLEAN._replace(ball_colour=(200, 40, 30), ball_finish=finish, duration=0.0)
        truth, (img,) = render(tmp_path / f"{finish}_SYNTHETIC.mp4", scene)
        u, v = np.round(camera.project(truth.pose, [[-0.09, 0.045]], height=RADIUS)[0]).astype(int)
        brightest[finish] = img[v - 8 : v + 9, u - 8 : u + 9].min(axis=-1).max()
    assert brightest["matte"] < 80
    assert brightest["specular"] > 150


def test_default_scene_is_grey_as_before(tmp_path) -> None:
    scene = Scene(size=(320, 180), fps=30.0, duration=0.2)
    truth, frames = render(tmp_path / "grey_SYNTHETIC.mp4", scene)
    stack = np.array(frames)
    assert np.abs(np.diff(stack, axis=-1)).max() <= 2
    img = frames[0]
    assert abs(patch(img, camera.project(truth.pose, [[0.0, -0.11]]), 3)[0] - 45) < 6
    assert abs(patch(img, (4, 90), 3)[0] - 150) < 6
    a = OMEGA * 0.5 / 30.0 / 2
    mark = 0.88 * PLATTER * np.array([[math.cos(a), math.sin(a)]])
    assert patch(img, camera.project(truth.pose, mark), 0)[0] > 200


@pytest.mark.parametrize("along", ["tangential", "radial"])
def test_strip_has_its_aspect_ratio(along, tmp_path) -> None:
    """A 20 x 40 mm strip at angle 0, seen from above: its image's second moments."""
    scene = CLEAN._replace(
        mark_shape="strip", mark_radius=1.0, mark_aspect=2.0, mark_along=along, shutter=0.01,
        mark_colour=(255, 255, 255), mark_at=0.6, duration=0.0, hidden=(0,),
    )  # fmt: skip
    setup = SETUP._replace(radius=0.01)
    path = tmp_path / "strip_SYNTHETIC.mp4"
    truth = render_video(path, *STILL, setup, scene)
    with av.open(str(path)) as video:
        img = next(video.decode(video=0)).to_ndarray(format="rgb24")[..., 1].astype(float)
    u0, v0 = np.round(camera.project(truth.pose, [[0.6 * PLATTER, 0.0]])[0]).astype(int)
    window = img[v0 - 20 : v0 + 21, u0 - 20 : u0 + 21]
    weight = np.clip((window - 45.0) / (255.0 - 45.0), 0, 1)
    v, u = np.mgrid[-20:21, -20:21]
    mean = [np.average(u, weights=weight), np.average(v, weights=weight)]
    cov = np.cov(np.stack([u.ravel() - mean[0], v.ravel() - mean[1]]), aweights=weight.ravel())
    values, vectors = np.linalg.eigh(cov)
    assert math.sqrt(values[1] / values[0]) == pytest.approx(2.0, rel=0.2)
    # the long side: tangential is along the image's v (y up), radial along u (x right)
    expected = [0.0, 1.0] if along == "tangential" else [1.0, 0.0]
    assert abs(vectors[:, 1] @ expected) > 0.98


def test_barrel_distortion_moves_the_rim_as_k1_says(tmp_path) -> None:
    """The rim where it crosses the image's diagonal, 0.46 f from the centre: its image is
    moved to r (1 + k1 (r / f)^2)."""
    scene = CLEAN._replace(duration=0.0, hidden=(0,))
    pose = default_pose(scene)
    pose = pose._replace(distance=0.6 * pose.distance)
    rim = camera.project(pose, [[-PLATTER, 0.0]])[0]
    rho = float(np.hypot(*(rim - pose.principal)))  # the rim's image is a circle about it
    centre = np.array(pose.principal)
    corner = -centre / np.linalg.norm(centre)  # towards the top left corner
    crossings = {}
    for k1 in (0.0, -0.2):
        path = tmp_path / f"k1_{k1}_SYNTHETIC.mp4"
        _, (img,) = render(path, scene._replace(lens_k1=k1), pose=pose)
        s = np.arange(60.0, 175.0, 0.25)
        profile = 0.0
        for a in np.radians(np.linspace(-4, 4, 9)):
            c, d = math.cos(a), math.sin(a)
            direction = np.array([c * corner[0] - d * corner[1], d * corner[0] + c * corner[1]])
            u, v = (centre + s[:, None] * direction).T
            profile = profile + bilinear(img[..., 1], u, v)
        inner, outer = np.median(profile[s < 100]), np.median(profile[s > 150])
        crossings[k1] = np.interp((inner + outer) / 2, profile, s)
    assert crossings[0.0] == pytest.approx(rho, abs=0.5)
    expected = rho * (-0.2) * (rho / pose.focal) ** 2
    assert expected < -4
    assert crossings[-0.2] - crossings[0.0] == pytest.approx(expected, abs=0.5)


def bilinear(img: np.ndarray, u: np.ndarray, v: np.ndarray) -> np.ndarray:
    """The image at the points (u, v), interpolated bilinearly."""
    u0, v0 = np.floor(u).astype(int), np.floor(v).astype(int)
    fu, fv = u - u0, v - v0
    return (
        img[v0, u0] * (1 - fu) * (1 - fv)
        + img[v0, u0 + 1] * fu * (1 - fv)
        + img[v0 + 1, u0] * (1 - fu) * fv
        + img[v0 + 1, u0 + 1] * fu * fv
    )


def test_rolling_shutter_shows_the_mark_later_by_its_row(tmp_path) -> None:
    """The mark near angle 0, near the middle row, is seen about half a readout later."""
    scene = CLEAN._replace(shutter=0.02, mark_colour=(255, 255, 255), duration=0.0, hidden=(0,))
    setup = SETUP._replace(omega=10.0)
    angles = {}
    for readout in (0.0, 1.0):
        path = tmp_path / f"readout_{readout}_SYNTHETIC.mp4"
        truth = render_video(path, *STILL, setup, scene._replace(readout=readout))
        with av.open(str(path)) as video:
            img = next(video.decode(video=0)).to_ndarray(format="rgb24").astype(float)
        angles[readout] = mark_angle(img, truth.pose)
    a0 = 10.0 * 0.02 / 30.0 / 2  # the middle of the exposure
    assert angles[0.0] == pytest.approx(a0, abs=0.01)
    # the mark is where it is when its row is read: a = a0 + Omega readout v(a) / (H fps)
    a = a0
    for _ in range(20):
        row = camera.project(truth.pose, 0.88 * PLATTER * np.array([[math.cos(a), math.sin(a)]]))
        a = a0 + 10.0 * row[0, 1] / 180 / 30.0
    assert a - a0 > 0.1
    assert angles[1.0] - angles[0.0] == pytest.approx(a - a0, abs=0.01)


def test_flicker_scales_the_light_of_each_frame(tmp_path) -> None:
    scene = CLEAN._replace(shutter=0.05, hidden=tuple(range(7)))
    means = {}
    for flicker in (0.0, 0.3):
        path = tmp_path / f"flicker_{flicker}_SYNTHETIC.mp4"
        truth, frames = render(path, scene._replace(flicker=flicker, flicker_phase_deg=30.0))
        means[flicker] = np.array([f.mean() for f in frames])
    e = 0.05 / 30.0
    w = 2 * math.pi * 100.0
    gain = 1 + 0.3 * np.sin(w * (truth.film.t + e / 2) + math.radians(30.0)) * np.sinc(
        w * e / 2 / math.pi
    )
    np.testing.assert_allclose(means[0.3] / means[0.0], gain, atol=0.01)


@pytest.mark.parametrize(
    ("field", "value"),
    [
        ("ball_colour", (300, 0, 0)),
        ("ball_colour", (1, 2)),
        ("table_colour", "grey"),
        ("ball_finish", "glossy"),
        ("mark_shape", "star"),
        ("mark_along", "diagonal"),
        ("mark_aspect", 0.5),
        ("label_radius", 0.9),
        ("groove_pitch", 0.001),
        ("light_elevation_deg", 0.0),
        ("shadow", 1.5),
        ("lens_k1", 0.5),
        ("readout", -0.1),
        ("flicker", 1.0),
    ],
)
def test_bad_scene_is_a_one_line_error_naming_the_field(field, value, tmp_path) -> None:
    path = tmp_path / "bad_SYNTHETIC.mp4"
    with pytest.raises(ValueError, match=f"Scene.{field} ") as error:
        render_video(path, *STILL, SETUP, CLEAN._replace(**{field: value}))
    assert "\n" not in str(error.value)
    assert not path.exists()
