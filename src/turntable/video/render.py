r"""SYNTHETIC videos of a ball on a turntable, rendered from the exact solutions.

`render_video` draws, frame by frame and in colour, what a camera above the turntable would
film: a textured platter of radius P turning counterclockwise at :math:`\Omega`, with grooves, a
label at its centre and a mark (a disc, a square or a strip of tape) near its rim, on a
table; a shaded ball (matte or shiny) whose centre is R above the platter, moving as one of
the friction models says (`turntable.fit.positions`), and its shadow; what a phone adds:
motion blur, a rolling shutter, barrel distortion, mains flicker, sensor noise, H.264
(libx264, ``turntable.video.decode.yuv420``).  By default the scene is grey: a dark platter, a
white round mark, a bright matte ball, no label, no shadow.  The file's name must contain
SYNTHETIC, and its metadata say it is rendered.
"""

from __future__ import annotations

import functools
import math
import os
from fractions import Fraction
from pathlib import Path
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from turntable._progress import Progress, counted
from turntable.film import Film, Setup
from turntable.fit.models import positions
from turntable.video import _scene, camera
from turntable.video.camera import Pose
from turntable.video.decode import SYNTHETIC, write_video

__all__ = ["SYNTHETIC", "Rendered", "Scene", "render_video"]

#: Share of the light on the ball that is ambient (the rest is Lambert's, from the light).
AMBIENT = 0.5
#: Peak of a specular ball's highlight (share of white) and its Blinn-Phong exponent.
SPECULAR, SHININESS = 0.8, 60.0
#: Samples in time over the shutter's opening (motion blur).
BLUR_SAMPLES = 4
RGB = tuple[float, float, float]


class Scene(NamedTuple):
    r"""What is filmed, and how.

    Attributes
    ----------
    platter_radius : float
        :math:`P`, m.
    tilt_deg, roll_deg : float
        Tilt of the optical axis from the vertical, and roll about it, degrees.
    size : tuple of int
        (width, height), px.
    fps, duration : float
        Frame rate (1/s) and length (s) of the video.
    shutter : float
        Exposure time as a fraction of the frame interval.
    noise : float
        Standard deviation of the sensor noise, levels (0-255), the same in the three colours
        (phones remove the chroma noise).
    mark_radius : float
        Size of the mark, in units of the ball's radius R: the radius of a disc, half the
        side of a square, half the short side of a strip.
    mark_at : float
        Distance of the mark's centre from the axis, in units of P.
    crf : int
        Quality of the H.264 encoding (libx264's constant rate factor; 0 is lossless).
    hidden : tuple of int
        Frames drawn without the ball (a hand over it, say): lost frames for the tracker.
    mark_hidden : tuple of int
        Frames drawn without the mark (a finger on it, say).
    clockwise : bool
        The platter turns clockwise as the camera sees it: the scene is the mirror image
        of the counterclockwise one.
    jitter : float
        Variable frame rate: each frame's time but the first is moved by up to
        :math:`\pm\, \mathrm{jitter} / 2` frame intervals (uniformly at random; at most 0.9), as
        phones record.
    ball_colour : tuple of float
        RGB (0-255) of the ball.
    ball_finish : {"matte", "specular"}
        Lambert shading, or with a Blinn-Phong highlight too (a steel or shiny plastic ball).
    platter_colour : tuple of float
        RGB (0-255) of the platter.
    platter_grain : float
        Standard deviation of the platter's grain, levels (0-255).
    grooves : float
        Amplitude of the brightness of the platter's concentric grooves, levels (0-255).
    groove_pitch : float
        Distance between the grooves, in units of P (at least 0.008).
    label_radius : float
        Radius of the label at the platter's centre, in units of P (0: no label).  It
        turns with the platter and is printed: a spindle hole, rings, lines of blocks.
    label_colour : tuple of float
        RGB (0-255) of the label's paper.
    mark_shape : {"disc", "square", "strip"}
        Shape of the mark; a strip is a rectangle of tape, ``mark_aspect`` times as long
        as it is wide.
    mark_aspect : float
        Length over width of a strip, at least 1.
    mark_along : {"tangential", "radial"}
        Direction of a strip's long side.
    mark_colour : tuple of float
        RGB (0-255) of the mark.
    table_colour : tuple of float
        RGB (0-255) of the table around the platter.
    light_azimuth_deg, light_elevation_deg : float
        Direction towards the (distant) light: angle from the lab's x axis counterclockwise,
        and above the platter (10 to 90), degrees.  It shades the ball.
    shadow : float
        Strength of the ball's shadow on the platter (0 none, 0.5 half the light removed):
        the sphere's projection along the light, with an edge soft over ~1.5 px.
    lens_k1 : float
        Radial distortion of the lens, :math:`x_d = x (1 + k_1 r^2)` in image coordinates
        normalised by the focal length; < 0 is barrel distortion (in [-0.3, 0.3]).
    readout : float
        Rolling shutter: row :math:`v` is exposed from
        :math:`t + \mathrm{readout}\, v / (\mathrm{height}\, \mathrm{fps})`, readout a fraction
        of the frame interval (0: a global shutter).
    flicker : float
        Mains flicker: the light is multiplied by
        :math:`1 + \mathrm{flicker}\, \sin(2 \pi f t + \varphi)` (:math:`f` ``flicker_hz``,
        :math:`\varphi` ``flicker_phase_deg``), averaged over each row's exposure.
    flicker_hz : float
        Frequency of the flicker (100 Hz for 50 Hz mains, 120 for 60 Hz).
    flicker_phase_deg : float
        Phase of the flicker at :math:`t = 0`, degrees.

    Examples
    --------
    >>> from turntable.video.render import Scene
    >>> scene = Scene(size=(640, 360), fps=60.0, duration=2.0, clockwise=True)
    >>> scene.platter_radius, scene.tilt_deg
    (0.15, 20.0)
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
    mark_hidden: tuple[int, ...] = ()
    clockwise: bool = False
    jitter: float = 0.0
    ball_colour: RGB = (245.0, 245.0, 245.0)
    ball_finish: str = "matte"
    platter_colour: RGB = (45.0, 45.0, 45.0)
    platter_grain: float = 6.0
    grooves: float = 4.0
    groove_pitch: float = 0.025
    label_radius: float = 0.0
    label_colour: RGB = (200.0, 40.0, 40.0)
    mark_shape: str = "disc"
    mark_aspect: float = 2.0
    mark_along: str = "tangential"
    mark_colour: RGB = (235.0, 235.0, 235.0)
    table_colour: RGB = (150.0, 150.0, 150.0)
    light_azimuth_deg: float = -121.0
    light_elevation_deg: float = 59.8
    shadow: float = 0.0
    lens_k1: float = 0.0
    readout: float = 0.0
    flicker: float = 0.0
    flicker_hz: float = 100.0
    flicker_phase_deg: float = 0.0


class Rendered(NamedTuple):
    """The truth of a rendered video: camera, frame times, the ball's centre (lab, m).

    Examples
    --------
    >>> import tempfile, pathlib
    >>> from turntable.film import Setup
    >>> from turntable.video.render import Scene, render_video
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "ball_SYNTHETIC.mp4"
    >>> scene = Scene(size=(320, 180), fps=30.0, duration=0.5)
    >>> truth = render_video(path, "slipping", 2.0, [7, 0, 0, 0.4, 0, 0], Setup(0.008, 3.49), scene)
    >>> truth.film.t.size, truth.omega
    (16, 3.49)
    """

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


class _Renderer:
    """Draws the frames (RGBA, uint8): the platter is a lookup in its polar texture, the
    mark, the shadow and the ball are drawn in windows around them."""

    n_r, n_phi = 512, 4096  # the platter's polar texture; n_phi a power of 2

    def __init__(self, scene: Scene, pose: Pose, radius: float, omega: float, seed: int) -> None:
        self.scene, self.pose, self.radius, self.omega = scene, pose, radius, omega
        self.rng, self.light = np.random.default_rng(seed), _scene.light(scene)
        width, height = scene.size
        v, u = np.mgrid[0:height, 0:width].astype(float)
        self.lens = lens = pose._replace(k1=scene.lens_k1)  # the pose: a pinhole's
        u, v_pin = np.moveaxis(camera.undistort(lens, np.stack([u, v], axis=-1)), -1, 0)
        self.rays = camera.rays(pose, u, v_pin).astype(np.float32)
        self.eye = camera.centre(pose)
        xy = camera.back_project(pose, np.stack([u, v_pin], axis=-1))
        self.x, self.y = xy[..., 0], xy[..., 1]
        r = np.hypot(self.x, self.y)
        # metres per pixel on the plane: the change of r from one pixel to the next
        self.foot = np.maximum(np.hypot(*np.gradient(r)), 1e-12)
        p, n_r, n_phi = scene.platter_radius, self.n_r, self.n_phi
        cover = np.where(self.rays[..., 2] < 0, np.clip(0.5 + (p - r) / self.foot, 0, 1), 0)
        cover = cover.ravel()
        self.exposure = scene.shutter / scene.fps
        self.offsets = self.exposure * (np.arange(BLUR_SAMPLES) + 0.5) / BLUR_SAMPLES
        self.row_dt = scene.readout / scene.fps / height  # rolling shutter: delay of a row
        turn = omega * self.exposure / (2 * math.pi) * n_phi
        tex = _scene.platter_texture(scene, self.rng, n_r, n_phi, turn)
        self.tex, self.tex32 = tex.reshape(-1, 4), tex.view(np.uint32).reshape(-1)
        inside = np.flatnonzero(cover > 0)
        phi = np.arctan2(self.y, self.x).ravel()[inside] / (2 * math.pi) * n_phi
        # the rolling shutter: row v sees the platter turned further by Omega row_dt v
        phi -= omega * self.row_dt * v.ravel()[inside] / (2 * math.pi) * n_phi
        cells = np.floor(phi).astype(np.int64) % n_phi
        rows = np.minimum((r.ravel()[inside] / p * n_r).astype(np.int64), n_r - 1)
        lookup = (rows * n_phi).astype(np.int32), cells.astype(np.int32)
        full = cover[inside] >= 1
        self.full, self.full_r, self.full_phi = inside[full], lookup[0][full], lookup[1][full]
        self.edge, self.edge_r, self.edge_phi = inside[~full], lookup[0][~full], lookup[1][~full]
        self.edge_cover = cover[self.edge, None].astype(np.float32)
        # the table: grain and a gradient of the light
        grain = 4.0 * self.rng.standard_normal((height, width)) + 15.0 * (v / height - 0.5)
        table = _scene.rgb(scene.table_colour, "table_colour") * (1 + grain / 150.0)[..., None]
        self.base = np.full((height, width, 4), 255, dtype=np.uint8)
        self.base[..., :3] = np.clip(table + 0.5, 0, 255)
        edge_table = table.reshape(-1, 3)[self.edge] * (1 - self.edge_cover)
        self.edge_table = edge_table.astype(np.float32)
        self.noise = None
        if scene.noise > 0:
            noise = self.rng.standard_normal((2 * height, 2 * width, 1), dtype=np.float32)
            noise = np.round(noise * np.float32(scene.noise)).astype(np.int16)
            self.noise = np.repeat(noise, 4, axis=2)  # contiguous: faster to add
        self.colour = {c: _scene.rgb(getattr(scene, c), c) for c in _scene.COLOURS}
        self._box = functools.partial(_scene.window, lens)  # lab points (n, 3)

    def _dt(self, box: tuple[slice, slice]) -> NDArray:
        """Delay (rows, 1) of the exposure of the window's rows (rolling shutter), s."""
        return self.row_dt * np.arange(box[0].start, box[0].stop, dtype=float)[:, None]

    def frame(
        self,
        t: float,
        ball: NDArray | None,
        velocity: NDArray | None = None,
        dt: float = 0.0,
        mark: bool = True,
    ) -> NDArray[np.uint8]:
        """Frame at t (RGBA, (height, width, 4)); ``ball``: the centres (samples, 2) over
        the shutter's opening, at delay ``dt`` of the rolling shutter, where the ball's
        velocities are ``velocity`` (samples, 2) (for the other rows); the mark unless
        ``mark`` is False."""
        sc = self.scene
        img = self.base.copy()
        mask = self.n_phi - 1
        s = np.int32(math.floor(self.omega * t / (2 * math.pi) * self.n_phi) & mask)
        img32 = img.view(np.uint32).reshape(-1)
        img32[self.full] = self.tex32[self.full_r + ((self.full_phi - s) & mask)]
        edge = self.tex[self.edge_r + ((self.edge_phi - s) & mask), :3]
        img.reshape(-1, 4)[self.edge, :3] = self.edge_table + self.edge_cover * edge + 0.5
        if mark:
            self._mark(img, t)
        if ball is not None:
            if velocity is None:
                velocity, dt = np.zeros_like(ball), 0.0
            if sc.shadow > 0:
                self._shadow(img, ball, velocity, dt)
            self._ball(img, ball, velocity, dt)
        dv, du = self.rng.integers(0, img.shape[0]), self.rng.integers(0, img.shape[1])
        h, w = img.shape[:2]
        noise = None if self.noise is None else self.noise[dv : dv + h, du : du + w]
        if sc.flicker == 0 and noise is None:
            return img
        out = img.astype(np.int16)
        if sc.flicker > 0:
            rows = self.row_dt * np.arange(h, dtype=float)
            _scene.brighten(out, _scene.flicker_gain(sc, t, rows, self.exposure))
        if noise is not None:
            out += noise
        return np.clip(out, 0, 255, out=out).astype(np.uint8)

    def _mark(self, img: NDArray, t: float) -> None:
        """Draw the mark, at angle Omega t on the circle of radius mark_at P."""
        sc, omega = self.scene, self.omega
        rho, at = sc.mark_radius * self.radius, sc.mark_at * sc.platter_radius
        long = sc.mark_aspect * rho if sc.mark_shape == "strip" else rho
        halves = (long, rho) if sc.mark_along == "radial" else (rho, long)  # radial, tangential
        times = t + self.offsets
        angles = omega * np.r_[times, times + sc.readout / sc.fps]
        reach = 1.5 * long * np.array([[0, 0, 0], [1, 1, 0], [-1, -1, 0], [1, -1, 0], [-1, 1, 0]])
        ends = at * np.column_stack([np.cos(angles), np.sin(angles), np.zeros_like(angles)])
        box = self._box((ends[:, None, :] + reach[None]).reshape(-1, 3))
        if box is None:
            return
        at_rows = [omega * (ti + self._dt(box)) for ti in times]
        cov = _scene.mark_cover(sc, self.x[box], self.y[box], self.foot[box], at_rows, halves, at)
        cov, win = cov[..., None], img[box][..., :3]
        img[box][..., :3] = win * (1 - cov) + self.colour["mark_colour"] * cov + 0.5

    def _centres(self, ball: NDArray, velocity: NDArray, dt: float, box: tuple[slice, slice]):
        """The ball's centres (x, y), each (rows, 1), seen by the window's rows."""
        late = self._dt(box) - dt
        return [
            (bx + vx * late, by + vy * late)
            for (bx, by), (vx, vy) in zip(ball, velocity, strict=True)
        ]

    def _spread(self, ball: NDArray, velocity: NDArray, dt: float) -> NDArray:
        """The ball's centres (n, 2) over the exposure and the readout."""
        late = np.array([-dt, self.scene.readout / self.scene.fps - dt])
        return (ball[:, None, :] + velocity[:, None, :] * late[None, :, None]).reshape(-1, 2)

    def _shadow(self, img: NDArray, ball: NDArray, velocity: NDArray, dt: float) -> None:
        """Darken the platter in the ball's shadow: the projection of the sphere along the
        light onto the plane z = 0, an ellipse."""
        big, lx, ly, lz = self.radius, *self.light
        along = np.array([lx, ly]) / max(math.hypot(lx, ly), 1e-12)
        centres = self._spread(ball, velocity, dt) - big * np.array([lx, ly]) / lz
        reach = 1.3 * big * np.array([along / lz, -along / lz, (-along[1], along[0])])
        reach = np.vstack([reach, -reach[2]])
        pts = (centres[:, None, :] + reach[None]).reshape(-1, 2)
        box = self._box(np.column_stack([pts, np.zeros(len(pts))]))
        if box is None:
            return
        centres = self._centres(ball, velocity, dt, box)
        cov = _scene.shadow_cover(
            self.x[box], self.y[box], self.foot[box], centres, big, self.light
        )
        dark = 1 - self.scene.shadow * cov[..., None]
        img[box][..., :3] = img[box][..., :3] * dark + 0.5

    def _ball(self, img: NDArray, ball: NDArray, velocity: NDArray, dt: float) -> None:
        """Draw the ball (its centres over the shutter's opening, shape (samples, 2)) by
        casting rays at the sphere."""
        pose, big, light = self.pose, self.radius, self.light
        centres = self._spread(ball, velocity, dt)
        reach = 1.3 * big * np.vstack([np.eye(3), -np.eye(3)])
        pts = np.column_stack([centres, np.full(len(centres), big)])
        box = self._box((pts[:, None, :] + reach[None]).reshape(-1, 3))
        if box is None:
            return
        centres = self._centres(ball, velocity, dt, box)
        cov, shade = _scene.sphere(
            self.rays[box].astype(float),
            [(cx - self.eye[0], cy - self.eye[1], big - self.eye[2]) for cx, cy in centres],
            big,
            pose.focal,
            light,
            self.colour["ball_colour"],
            (AMBIENT, SPECULAR if self.scene.ball_finish == "specular" else 0.0, SHININESS),
        )
        img[box][..., :3] = img[box][..., :3] * (1 - cov)[..., None] + shade + 0.5


def render_video(
    path: str | os.PathLike[str],
    model: str,
    coefficient: float,
    state0: ArrayLike,
    setup: Setup,
    scene: Scene | None = None,
    seed: int = 0,
    pose: Pose | None = None,
    progress: Progress | None = None,
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
        The camera; by default ``default_pose``.
    progress : callable, optional
        Called as ``progress("rendering", frames written, frames of the video)``.

    Returns
    -------
    Rendered
        The camera and the true positions of the ball's centre at the frame times (m).

    See Also
    --------
    turntable.video.track.track_video : Tracks it.

    Notes
    -----
    Frame i, at time t_i = i / fps of the video (moved by the jitter, rounded to the
    container's 1/90000 s), shows the scene averaged over the shutter's opening
    (``BLUR_SAMPLES`` instants), the model's times t_i to t_i + e, e = shutter / fps;
    ``state0`` is the state at the first opening, and the true position of frame i is the
    one at its middle, t_i + e / 2, as a tracker sees it. The ball's image is drawn by
    casting rays at a sphere whose centre is at height R, so that its image is the
    perspective image of a ball, not of a disc on the platter.  A clockwise scene draws
    the ball at (x, -y) and turns the platter the other way; the returned positions stay
    those of the model, in which the platter turns counterclockwise (as `turntable.video.track`
    reports a clockwise platter's film).  With a rolling shutter (``Scene.readout``), row v
    is exposed ``readout v / (height fps)`` later than the first: the platter, its label and
    the mark are drawn at each row's time; the ball and its shadow at the time of the row
    of the ball's image's centre, moved row by row along the ball's velocity there (linear
    over the few rows of its image); the returned positions stay those at t_i + e / 2, so
    the ball's image lags them by its row's delay, as a phone's would.

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

    path = Path(path)
    setup = _scene.check_output(path, setup)
    scene = scene or Scene()
    _scene.check(scene)
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
    samples = (t[:, None] + renderer.offsets[None, :]).ravel()
    ball = positions(model, coefficient, state0, samples, setup).reshape(n, BLUR_SAMPLES, 2)
    xy = positions(model, coefficient, state0, t + renderer.exposure / 2, setup)
    velocity, delay = None, np.zeros(n)
    if scene.readout:
        # the rolling shutter: the ball is seen later, as late as the row of its image
        middle = np.column_stack([xy[:, 0], sign * xy[:, 1], np.full(n, setup.radius)])
        rows = np.clip(_scene.image(renderer.lens, middle)[:, 1], 0, scene.size[1] - 1)
        delay = renderer.row_dt * rows
        later = samples + np.repeat(delay, BLUR_SAMPLES)
        ball = positions(model, coefficient, state0, later, setup).reshape(n, BLUR_SAMPLES, 2)
        step = 0.05 * scene.readout / scene.fps
        ahead = positions(model, coefficient, state0, later + step, setup)
        velocity = (ahead.reshape(n, BLUR_SAMPLES, 2) - ball) / step
        velocity[..., 1] *= sign
    radius_max = float(np.max(np.hypot(ball[..., 0], ball[..., 1])))
    if radius_max > scene.platter_radius - setup.radius:
        raise ValueError(
            f"the ball leaves the platter ({radius_max:.4g} m from the axis, P - R = "
            f"{scene.platter_radius - setup.radius:.4g} m)"
        )
    ball[..., 1] *= sign
    hidden, mark_hidden = set(scene.hidden), set(scene.mark_hidden)
    frames = (
        (ti, renderer.frame(ti, None if i in hidden else ball[i],
                            None if velocity is None else velocity[i], delay[i],
                            i not in mark_hidden))
        for i, ti in enumerate(t)
    )  # fmt: skip
    frames = counted(frames, progress, "rendering", n)
    write_video(path, frames, scene.fps, scene.size, scene.crf,
                f"rendered by turntable.video.render from the exact solution of the {model} "
                f"model ({coefficient!r})")  # fmt: skip
    return Rendered(pose, Film(t, xy[:, 0], xy[:, 1], synthetic=True), setup.omega)
