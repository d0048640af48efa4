"""SYNTHETIC videos of a ball on a turntable, rendered from the exact solutions.

`render_video` draws, frame by frame, what a camera above the turntable would film: a
dark textured platter of radius P turning counterclockwise at Omega, with a bright round
mark near its rim, on a grey table; a shaded bright ball whose centre is R above the
platter, moving as one of the friction models says (`turntable.fit.positions`); motion
blur over the shutter time, Gaussian sensor noise, H.264 (libx264, PyAV).  The file's name
must contain SYNTHETIC, and its metadata say it is rendered.
"""

from __future__ import annotations

import math
import os
from fractions import Fraction
from pathlib import Path
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from turntable.film import Film, Setup, check_setup
from turntable.fit.models import positions
from turntable.video import camera
from turntable.video.camera import Pose

__all__ = ["SYNTHETIC", "Rendered", "Scene", "render_video"]

#: Word that the file name and the metadata of every rendered video carry.
SYNTHETIC = "SYNTHETIC"
#: Grey levels (0-255) of the scene.
TABLE, PLATTER, MARK, BALL = 150.0, 45.0, 235.0, 245.0
#: Direction of the light (from above, towards the camera) and its ambient share.
LIGHT = np.array([-0.3, -0.5, 1.0]) / math.sqrt(1.34)
AMBIENT = 0.5
#: Samples in time over the shutter's opening (motion blur).
BLUR_SAMPLES = 4


class Scene(NamedTuple):
    """What is filmed, and how.

    Attributes
    ----------
    platter_radius : float
        P, m.
    tilt_deg, roll_deg : float
        Tilt of the optical axis from the vertical, and roll about it, degrees.
    size : tuple of int
        (width, height), px.
    fps, duration : float
        Frame rate (1/s) and length (s) of the video.
    shutter : float
        Exposure time as a fraction of the frame interval.
    noise : float
        Standard deviation of the sensor noise, grey levels.
    mark_radius : float
        Radius of the round mark, in units of the ball's radius R.
    mark_at : float
        Distance of the mark from the axis, in units of P.
    crf : int
        Quality of the H.264 encoding (libx264's constant rate factor; 0 is lossless).
    hidden : tuple of int
        Frames drawn without the ball (a hand over it, say): lost frames for the tracker.
    clockwise : bool
        The platter turns clockwise as the camera sees it: the scene is the mirror image
        of the counterclockwise one.
    jitter : float
        Variable frame rate: each frame's time but the first is moved by up to +- jitter / 2
        frame intervals (uniformly at random; at most 0.9), as phones record.
    """

    platter_radius: float = 0.15
    tilt_deg: float = 20.0
    roll_deg: float = 0.0
    size: tuple[int, int] = (640, 360)
    fps: float = 60.0
    duration: float = 2.0
    shutter: float = 0.5
    noise: float = 3.0
    mark_radius: float = 0.5
    mark_at: float = 0.88
    crf: int = 18
    hidden: tuple[int, ...] = ()
    clockwise: bool = False
    jitter: float = 0.0


class Rendered(NamedTuple):
    """The truth of a rendered video: camera, frame times, the ball's centre (lab, m)."""

    pose: Pose
    film: Film
    omega: float


def default_pose(scene: Scene) -> Pose:
    """A phone-like camera (60 degrees across) whose image of the platter is centred and
    spans 85 % of the image's height (or 90 % of its width)."""
    width, height = scene.size
    focal = width / (2.0 * math.tan(math.radians(30.0)))
    p = scene.platter_radius
    pose = Pose(
        focal,
        math.radians(scene.tilt_deg),
        math.radians(scene.roll_deg),
        (0.0, 0.0),
        focal * 2 * p / (0.85 * height),
        scene.size,
    )
    s = np.linspace(0, 2 * math.pi, 721)
    rim = p * np.column_stack([np.cos(s), np.sin(s)])
    for _ in range(6):
        img = camera.project(pose, rim)
        span = max(np.ptp(img[:, 1]) / (0.85 * height), np.ptp(img[:, 0]) / (0.9 * width))
        middle = (img.min(axis=0) + img.max(axis=0)) / 2
        shift = camera.back_project(pose, middle) - camera.back_project(pose, pose.principal)
        look = (pose.look_at[0] + shift[0], pose.look_at[1] + shift[1])
        pose = pose._replace(distance=pose.distance * span, look_at=look)
    return pose


def _texture(rng: np.random.Generator, n_r: int, n_phi: int, blur_cells: float) -> NDArray:
    """Polar texture of the platter (grain and grooves), blurred along the angle."""
    grain = rng.standard_normal((n_r, n_phi))
    kernel = np.exp(-0.5 * (np.arange(-6, 7) / 2.0) ** 2)
    grain = np.apply_along_axis(
        lambda g: np.convolve(np.r_[g[-6:], g, g[:6]], kernel, "valid"), 1, grain
    )
    grain /= grain.std()
    grooves = np.cos(np.linspace(0.0, 80.0 * math.pi, n_r))[:, None]
    tex = PLATTER + 6.0 * grain + 4.0 * grooves
    width = max(round(blur_cells), 1)
    if width > 1:
        f = np.fft.rfft(tex, axis=1)
        box = np.fft.rfft(np.r_[np.ones(width), np.zeros(n_phi - width)] / width)
        tex = np.fft.irfft(f * box, n=n_phi, axis=1)
    return tex.astype(np.float32)


class _Renderer:
    def __init__(self, scene: Scene, pose: Pose, radius: float, omega: float, seed: int) -> None:
        self.scene, self.pose, self.radius, self.omega = scene, pose, radius, omega
        self.rng = np.random.default_rng(seed)
        width, height = scene.size
        v, u = np.mgrid[0:height, 0:width].astype(float)
        self.rays = camera.rays(pose, u, v).astype(np.float32)
        self.eye = camera.centre(pose)
        xy = camera.back_project(pose, np.stack([u, v], axis=-1))
        down = self.rays[..., 2] < 0
        self.x, self.y = xy[..., 0], xy[..., 1]
        r = np.hypot(self.x, self.y)
        # metres per pixel on the plane: the change of r from one pixel to the next
        foot = np.hypot(*np.gradient(r))
        p = scene.platter_radius
        self.cover = np.where(down, np.clip(0.5 + (p - r) / np.maximum(foot, 1e-12), 0, 1), 0)
        self.inside = np.flatnonzero(self.cover > 0)
        self.n_r, self.n_phi = 512, 4096
        phi = np.mod(np.arctan2(self.y, self.x).ravel()[self.inside], 2 * math.pi)
        self.i_r = np.minimum(
            (r.ravel()[self.inside] / p * self.n_r).astype(np.int32), self.n_r - 1
        )
        self.phi_cells = (phi / (2 * math.pi) * self.n_phi).astype(np.int32) % self.n_phi
        exposure = scene.shutter / scene.fps
        self.exposure = exposure
        self.tex = _texture(
            self.rng, self.n_r, self.n_phi, abs(omega) * exposure / (2 * math.pi) * self.n_phi
        )
        table = TABLE + 4.0 * self.rng.standard_normal((height, width)) + 15.0 * (v / height - 0.5)
        self.base = (table * (1.0 - self.cover)).astype(np.float32)
        self.cover32 = self.cover.ravel()[self.inside].astype(np.float32)
        self.noise = self.rng.standard_normal((2 * height, 2 * width), dtype=np.float32)
        self.noise *= np.float32(scene.noise)
        self.foot = foot

    def _box(self, centre: NDArray, half: float) -> tuple[slice, slice]:
        width, height = self.scene.size
        u0, v0 = centre
        return (
            slice(max(int(v0 - half), 0), min(int(v0 + half) + 2, height)),
            slice(max(int(u0 - half), 0), min(int(u0 + half) + 2, width)),
        )

    def frame(self, t: float, ball: NDArray[np.float64] | None) -> NDArray[np.uint8]:
        sc, pose = self.scene, self.pose
        img = self.base.copy().ravel()
        shift = self.omega * t / (2 * math.pi) * self.n_phi
        i_phi = (self.phi_cells - np.int32(round(shift) % self.n_phi)) % self.n_phi
        img[self.inside] += self.cover32 * self.tex[self.i_r, i_phi]
        img = img.reshape(self.base.shape)
        times = t + self.exposure * (np.arange(BLUR_SAMPLES) + 0.5) / BLUR_SAMPLES
        # the mark: a disc on the platter, at angle Omega t
        rho, at = sc.mark_radius * self.radius, sc.mark_at * sc.platter_radius
        marks = at * np.column_stack([np.cos(self.omega * times), np.sin(self.omega * times)])
        centre = camera.project(pose, marks.mean(axis=0))
        half = (rho + at * abs(self.omega) * self.exposure) / self.foot[
            int(np.clip(centre[1], 0, sc.size[1] - 1)), int(np.clip(centre[0], 0, sc.size[0] - 1))
        ] + 3
        box = self._box(centre, half)
        x, y, foot = self.x[box], self.y[box], np.maximum(self.foot[box], 1e-12)
        cov = np.mean(
            [np.clip(0.5 + (rho - np.hypot(x - mx, y - my)) / foot, 0, 1) for mx, my in marks],
            axis=0,
        )
        img[box] = img[box] * (1 - cov) + MARK * cov
        if ball is not None:
            self._ball(img, ball)
        # sensor noise: a window at a random place of a larger field of noise
        dv, du = self.rng.integers(0, self.base.shape[0]), self.rng.integers(0, self.base.shape[1])
        img += self.noise[dv : dv + img.shape[0], du : du + img.shape[1]]
        return np.clip(img + 0.5, 0, 255).astype(np.uint8)

    def _ball(self, img: NDArray, ball: NDArray[np.float64]) -> None:
        """Draw the ball (its centres over the shutter's opening, shape (samples, 2))."""
        pose, radius = self.pose, self.radius
        centre = camera.project(pose, ball.mean(axis=0), height=radius)
        spread = np.ptp(camera.project(pose, ball, height=radius), axis=0).max()
        depth = np.linalg.norm(np.r_[ball.mean(axis=0), radius] - self.eye)
        half = 1.6 * radius * pose.focal / depth + spread + 3
        box = self._box(centre, half)
        d = self.rays[box].astype(float)
        cov_sum = np.zeros(d.shape[:2])
        light_sum = np.zeros(d.shape[:2])
        for bx, by in ball:
            s = np.array([bx, by, radius]) - self.eye
            tca = d @ s
            dist = np.sqrt(np.maximum(s @ s - tca**2, 0.0))
            cov = np.clip(0.5 + (radius - dist) / (tca / pose.focal), 0, 1)
            hit = d * (tca - np.sqrt(np.maximum(radius**2 - dist**2, 0.0)))[..., None] - s
            normal = hit / np.linalg.norm(hit, axis=-1, keepdims=True)
            shade = BALL * (AMBIENT + (1 - AMBIENT) * np.maximum(normal @ LIGHT, 0.0))
            cov_sum += cov
            light_sum += cov * shade
        n = len(ball)
        img[box] = img[box] * (1 - cov_sum / n) + light_sum / n


def render_video(
    path: str | os.PathLike[str],
    model: str,
    coefficient: float,
    state0: ArrayLike,
    setup: Setup,
    scene: Scene | None = None,
    seed: int = 0,
    pose: Pose | None = None,
) -> Rendered:
    """Render a SYNTHETIC video of the ball of one friction model and write it as H.264.

    Parameters
    ----------
    path : str or path-like
        The video (.mp4, .mkv or .mov); its name must contain SYNTHETIC.
    model, coefficient, state0, setup
        As for `turntable.fit.simulate_film`; the axis of ``setup`` must be (0, 0) (the
        platter's centre is the lab frame's origin).
    scene : Scene, optional
        By default ``Scene()``.
    seed : int
        Seed of the texture and the noise.
    pose : Pose, optional
        The camera; by default `default_pose`.

    Returns
    -------
    Rendered
        The camera and the true positions of the ball's centre at the frame times (m).

    Notes
    -----
    Frame i, at time t_i = i / fps of the video (moved by the jitter, rounded to the
    container's 1/90000 s), shows the scene averaged over the
    shutter's opening (`BLUR_SAMPLES` instants), the model's times t_i to t_i + e, e =
    shutter / fps; ``state0`` is the state at the first opening, and the true position of
    frame i is the one at its middle, t_i + e / 2, as a tracker sees it.  The ball's image
    is drawn by casting rays at a sphere whose centre is at height R, so that its image is the
    perspective image of a ball, not of a disc on the platter.  A clockwise scene draws
    the ball at (x, -y) and turns the platter the other way; the returned positions stay
    those of the model, in which the platter turns counterclockwise (as `turntable.video.track`
    reports a clockwise platter's film).

    Examples
    --------
    >>> import tempfile, pathlib
    >>> from turntable.film import Setup
    >>> from turntable.video.render import Scene, render_video
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "ball_SYNTHETIC.mp4"
    >>> scene = Scene(size=(320, 180), fps=30.0, duration=0.5, clockwise=True, jitter=0.5)
    >>> truth = render_video(path, "slipping", 2.0, [7, 0, 0, 0.4, 0, 0],
    ...                      Setup(radius=0.008, omega=3.49, k=0.4), scene)
    >>> print(truth.film.t.size, "frames", path.stat().st_size > 0)
    16 frames True
    """
    import av

    path = Path(path)
    if SYNTHETIC not in path.name:
        raise ValueError(f"a rendered video's file name must contain {SYNTHETIC}; got {path.name}")
    setup = check_setup(setup)
    if setup.axis != (0.0, 0.0):
        raise ValueError(
            "the axis of a rendered turntable is the origin: setup.axis must be (0, 0)"
        )
    scene = scene or Scene()
    pose = pose or default_pose(scene)
    n = math.floor(scene.duration * scene.fps * (1 + 1e-12)) + 1
    time_base = Fraction(1, 90000)
    t = np.arange(n) / scene.fps
    if not 0.0 <= scene.jitter <= 0.9:
        raise ValueError(f"Scene.jitter must be in [0, 0.9] frame intervals; got {scene.jitter}")
    if scene.jitter:
        shift = np.random.default_rng(seed).uniform(-0.5, 0.5, n) * scene.jitter / scene.fps
        shift[0] = 0.0  # state0 is the state at the first opening
        t = t + shift
    t = np.round(t * time_base.denominator) / time_base.denominator
    sign = -1.0 if scene.clockwise else 1.0
    renderer = _Renderer(scene, pose, setup.radius, sign * setup.omega, seed)
    # model time = video time + half the shutter time: the first opening starts at t = 0
    offsets = renderer.exposure * (np.arange(BLUR_SAMPLES) + 0.5) / BLUR_SAMPLES
    samples = (t[:, None] + offsets[None, :]).ravel()
    ball = positions(model, coefficient, state0, samples, setup).reshape(n, BLUR_SAMPLES, 2)
    xy = positions(model, coefficient, state0, t + renderer.exposure / 2, setup)
    radius_max = float(np.max(np.hypot(ball[..., 0], ball[..., 1])))
    if radius_max > scene.platter_radius - setup.radius:
        raise ValueError(
            f"the ball leaves the platter ({radius_max:.4g} m from the axis, P - R = "
            f"{scene.platter_radius - setup.radius:.4g} m)"
        )
    ball[..., 1] *= sign
    tmp = path.with_name(f".{path.name}.partial{path.suffix}")
    try:
        with av.open(str(tmp), "w") as out:
            out.metadata["title"] = f"{SYNTHETIC} turntable video"
            out.metadata["comment"] = (
                f"{SYNTHETIC}: rendered by turntable.video.render from the exact solution of the "
                f"{model} model ({coefficient!r}), not filmed"
            )
            stream = out.add_stream("libx264", rate=Fraction(scene.fps).limit_denominator(10000))
            stream.width, stream.height = scene.size
            stream.pix_fmt = "yuv420p"
            stream.time_base = time_base
            stream.codec_context.time_base = time_base
            stream.options = {"crf": str(scene.crf), "preset": "ultrafast"}
            hidden = set(scene.hidden)
            for i, ti in enumerate(t):
                img = renderer.frame(ti, None if i in hidden else ball[i])
                frame = av.VideoFrame.from_ndarray(img, format="gray")
                frame.pts = round(ti / time_base)
                frame.time_base = time_base
                out.mux(stream.encode(frame))
            out.mux(stream.encode(None))
        os.replace(tmp, path)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise
    return Rendered(pose, Film(t, xy[:, 0], xy[:, 1], synthetic=True), setup.omega)
