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

import math
import os
from fractions import Fraction
from pathlib import Path
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike

from turntable._progress import Progress, counted
from turntable.film import Film, Setup
from turntable.fit.models import positions
from turntable.video import _scene, camera
from turntable.video._frames import AMBIENT as AMBIENT
from turntable.video._frames import BLUR_SAMPLES, _Renderer
from turntable.video._frames import SHININESS as SHININESS
from turntable.video._frames import SPECULAR as SPECULAR
from turntable.video.camera import Pose
from turntable.video.decode import SYNTHETIC, write_video

__all__ = ["SYNTHETIC", "Rendered", "Scene", "render_video"]

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
