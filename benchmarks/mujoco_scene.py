"""SYNTHETIC videos of a ball on a turntable drawn by MuJoCo's renderer, not the project's.

`render_mujoco` has the meaning of `turntable.video.render.render_video`: the ball's centre
moves as one of the friction models says (`turntable.fit.positions`, R above the platter's
top surface z = 0), the platter (radius P of its top surface) turns counterclockwise seen
from above at Omega (clockwise if the scene says so), and the frames are written as H.264
(libx264, yuv420p, PyAV) into a file whose name contains SYNTHETIC.  MuJoCo's dynamics are not
used: the platter and the ball are mocap bodies placed each frame; only its OpenGL renderer
draws them (shading, specular highlights, 4x multisampling, shadows of a directional light).

MuJoCo is a benchmark dependency (``pip install -e '.[bench]'``), never a runtime one.  It
renders offscreen through EGL (``MUJOCO_GL=egl``, the default here; Mesa's llvmpipe on a
machine without GPU: Debian's libegl1, libegl-mesa0, libgl1-mesa-dri) or OSMesa
(``MUJOCO_GL=osmesa``: libosmesa6).

Run ``python benchmarks/mujoco_scene.py --out DIR [--check]`` to render four example videos
(1280x720, 240 frames/s, 2 s) and, with ``--check``, compare the ball's image in one frame of
each with the pinhole projection of its true centre.
"""

from __future__ import annotations

import math
import os
import time
from dataclasses import dataclass, replace
from fractions import Fraction
from pathlib import Path
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from turntable.film import Film, Setup
from turntable.fit import positions
from turntable.video import _scene
from turntable.video.decode import SYNTHETIC, write_video

__all__ = ["SYNTHETIC", "MujocoRendered", "MujocoScene", "project", "render_mujoco"]


RGBA = tuple[float, float, float, float]


@dataclass(frozen=True)
class MujocoScene:
    """What MuJoCo draws, and how it is filmed.

    Attributes
    ----------
    size : tuple of int
        (width, height) of the video, px.
    fps, duration : float
        Frame rate (1/s) and length (s).
    platter_radius : float
        P, the radius of the platter's top surface (the plane z = 0), m.
    platter_thickness : float
        Height of the platter's side above the table, m (seen under a tilt, below the rim).
    tilt_deg, azimuth_deg, roll_deg : float
        Tilt of the optical axis from the vertical; azimuth of the camera about the platter's
        axis (0: it stands on the side of negative y and x points right in the image, as
        `turntable.video.camera.Pose` has it); roll about the optical axis, degrees.
    fovy_deg : float
        Vertical field of view, degrees (36 degrees: 60 across a 16:9 image, a phone's).
        The camera's distance is chosen so that the platter's image spans 85 % of the
        image's height (or 90 % of its width) and is centred.
    zoom_out, pan_deg : float
        Then the camera is moved back along its optical axis to ``zoom_out`` times its
        distance from the plane z = 0 (the platter smaller in the image) and turned by
        ``pan_deg`` degrees about its own downward axis (the platter off the image's centre).
    ball_rgba : tuple of float
        Colour of the ball, RGBA in 0-1.
    ball_specular, ball_shininess : float
        MuJoCo's material specular (0-1) and shininess (0-1) of the ball.
    ball_checker : tuple of two RGB, optional
        The ball painted with MuJoCo's builtin checker of these two colours (0-1; a cube
        texture, 64 texels a side), times ``ball_rgba``; None: plain.
    platter_rgba, table_rgba : tuple of float
        Colours of the platter (top and side) and of the table under it.
    platter_specular, platter_shininess : float
        The platter's material specular and shininess (0.9 and 0.6: glossy).
    table_wood : bool
        The table textured as wood (a brown gradient with random darker marks, repeated
        6 x 6), times ``table_rgba``.
    mark_shape : {"strip", "dot"}
        The mark near the rim, turning with the platter: a thin box (a strip of tape) or a
        thin cylinder (a dot).
    mark_size : tuple of float
        Strip: (length, width), m; dot: (diameter, unused).
    mark_along : {"tangential", "radial"}
        Direction of a strip's length.
    mark_at : float
        Distance of the mark's centre from the axis, in units of P.
    mark_rgba : tuple of float
        Colour of the mark.
    second_dot : tuple of float, optional
        (x, y, diameter), m, of a second dot of the mark's colour on the platter (x towards
        the mark); None: none.
    label_radius : float
        Radius of the label at the platter's centre, in units of P (0: none).
    label_rgba : tuple of float
        Colour of the label.
    light_azimuth_deg, light_elevation_deg : float
        Direction towards the directional light, which casts shadows: angle from the lab's
        x axis counterclockwise, and above the platter, degrees.
    light_diffuse, ambient : float
        Diffuse intensity of that light; ambient light (grey level 0-1); MuJoCo's headlight
        (from the camera, no shadow) adds ``headlight`` of diffuse light.
    headlight : float
        Diffuse intensity of the headlight.
    shadow_size : int
        Side of the shadow map, texels (MuJoCo's ``quality/shadowsize``).
    slices : int
        Slices of the ball, the label and a dot (MuJoCo's ``quality/numslices``; a quarter
        as many stacks); they cost time.
    rim_sides : int
        Sides of the platter, a prism (a mesh): 720 keep its rim within 0.003 px of a
        circle of 300 px.
    samples : int
        Multisampling of the offscreen buffer (MuJoCo's ``quality/offsamples``; 0: none).
    noise : float
        Standard deviation of the sensor noise, levels (0-255), the same in the three
        colours; seeded.
    shutter : float
        Exposure as a fraction of the frame interval; with ``blur_samples`` > 1 each frame is
        the mean of that many renders over it (motion blur) and the truth is at its middle.
    blur_samples : int
        Renders per frame (1: no blur, the truth at the frame time).
    crf : int
        libx264's constant rate factor (0: lossless).
    clockwise : bool
        The platter turns clockwise as the camera sees it: the ball is drawn at (x, -y) and
        the platter turns the other way; the returned positions stay the model's.
    """

    size: tuple[int, int] = (1280, 720)
    fps: float = 240.0
    duration: float = 2.0
    platter_radius: float = 0.15
    platter_thickness: float = 0.002
    tilt_deg: float = 20.0
    azimuth_deg: float = 0.0
    roll_deg: float = 0.0
    fovy_deg: float = 36.0
    ball_rgba: RGBA = (0.95, 0.95, 0.95, 1.0)
    ball_specular: float = 0.3
    ball_shininess: float = 0.3
    ball_checker: tuple[tuple[float, float, float], tuple[float, float, float]] | None = None
    platter_rgba: RGBA = (0.18, 0.18, 0.18, 1.0)
    platter_specular: float = 0.05
    platter_shininess: float = 0.1
    table_rgba: RGBA = (0.55, 0.45, 0.35, 1.0)
    table_wood: bool = False
    mark_shape: str = "dot"
    mark_size: tuple[float, float] = (0.008, 0.008)
    mark_along: str = "tangential"
    mark_at: float = 0.88
    mark_rgba: RGBA = (0.92, 0.92, 0.92, 1.0)
    second_dot: tuple[float, float, float] | None = None
    label_radius: float = 0.0
    label_rgba: RGBA = (0.8, 0.15, 0.15, 1.0)
    light_azimuth_deg: float = -121.0
    light_elevation_deg: float = 60.0
    light_diffuse: float = 0.6
    ambient: float = 0.3
    headlight: float = 0.2
    shadow_size: int = 2048
    samples: int = 4
    slices: int = 64
    rim_sides: int = 720
    noise: float = 2.0
    shutter: float = 0.0
    blur_samples: int = 1
    crf: int = 18
    clockwise: bool = False
    zoom_out: float = 1.0
    pan_deg: float = 0.0


class Camera(NamedTuple):
    """The pinhole camera MuJoCo renders through (lab frame, m; image in px, pixel centres
    at whole numbers, u right, v down)."""

    position: tuple[float, float, float]
    axes: tuple[tuple[float, ...], ...]  # rows: right, down, viewing direction
    focal: float
    size: tuple[int, int]


class MujocoRendered(NamedTuple):
    """The truth of a rendered video: the true centres at the frame times, Omega, the camera."""

    film: Film
    omega: float
    tilt_deg: float
    camera: Camera


def project(cam: Camera, points: ArrayLike) -> NDArray[np.float64]:
    """Image points (u, v), px, of lab points (x, y, z), m, shape (..., 3)."""
    d = (np.asarray(points, dtype=float) - np.asarray(cam.position)) @ np.asarray(cam.axes).T
    w, h = cam.size
    u = (w - 1) / 2 + cam.focal * d[..., 0] / d[..., 2]
    v = (h - 1) / 2 + cam.focal * d[..., 1] / d[..., 2]
    return np.stack([u, v], axis=-1)


def _back_project(cam: Camera, uv: NDArray) -> NDArray:
    """Points (x, y) of the plane z = 0 seen at image points ``uv``."""
    w, h = cam.size
    ray = np.array([(uv[0] - (w - 1) / 2) / cam.focal, (uv[1] - (h - 1) / 2) / cam.focal, 1.0])
    ray = ray @ np.asarray(cam.axes)
    s = -cam.position[2] / ray[2]
    return np.asarray(cam.position[:2]) + s * ray[:2]


def _rot_z(a: float) -> NDArray:
    return np.array([[math.cos(a), -math.sin(a), 0], [math.sin(a), math.cos(a), 0], [0, 0, 1.0]])


def _camera(scene: MujocoScene) -> Camera:
    """The camera: tilted by tilt from the vertical towards +y (standing at negative y),
    rolled, turned by the azimuth about the platter's axis; distance and look-at point such
    that the platter's rim is centred and spans 85 % of the height (90 % of the width)."""
    width, height = scene.size
    focal = (height / 2) / math.tan(math.radians(scene.fovy_deg) / 2)
    b, a = math.radians(scene.tilt_deg), math.radians(scene.roll_deg)
    view = np.array([0.0, math.sin(b), -math.cos(b)])
    x0, y0 = np.array([1.0, 0.0, 0.0]), np.array([0.0, -math.cos(b), -math.sin(b)])
    axes = np.array(
        [math.cos(a) * x0 + math.sin(a) * y0, -math.sin(a) * x0 + math.cos(a) * y0, view]
    )
    p = scene.platter_radius
    s = np.linspace(0, 2 * math.pi, 721)
    rim = np.column_stack([p * np.cos(s), p * np.sin(s), np.zeros_like(s)])
    look, dist = np.zeros(2), focal * 2 * p / (0.85 * height)
    for _ in range(8):
        cam = Camera(
            tuple(np.r_[look, 0.0] - dist * view), tuple(map(tuple, axes)), focal, (width, height)
        )
        img = project(cam, rim)
        span = max(np.ptp(img[:, 1]) / (0.85 * height), np.ptp(img[:, 0]) / (0.9 * width))
        middle = (img.min(axis=0) + img.max(axis=0)) / 2
        look = (
            look
            + _back_project(cam, middle)
            - _back_project(cam, np.array([(width - 1) / 2, (height - 1) / 2]))
        )
        dist *= span
    turn = _rot_z(math.radians(scene.azimuth_deg))
    cam = Camera(
        tuple(np.r_[look, 0.0] - dist * view), tuple(map(tuple, axes)), focal, (width, height)
    )
    cam = cam._replace(
        position=tuple(turn @ np.asarray(cam.position)),
        axes=tuple(map(tuple, np.asarray(cam.axes) @ turn.T)),
    )
    if scene.zoom_out == 1 and scene.pan_deg == 0:
        return cam
    axes, pos = np.asarray(cam.axes), np.asarray(cam.position)
    if scene.zoom_out != 1:
        s = -pos[2] / axes[2][2]  # along the optical axis to the plane z = 0
        pos = (pos + s * axes[2]) - scene.zoom_out * s * axes[2]
    if scene.pan_deg != 0:
        c, d = math.cos(math.radians(scene.pan_deg)), math.sin(math.radians(scene.pan_deg))
        axes = np.array([c * axes[0] + d * axes[2], axes[1], -d * axes[0] + c * axes[2]])
    return cam._replace(position=tuple(pos), axes=tuple(map(tuple, axes)))


def _f(*xs: float) -> str:
    return " ".join(f"{x:.9g}" for x in xs)


def scene_xml(scene: MujocoScene, radius: float, cam: Camera) -> str:
    """The MJCF model: a table, the platter (a mocap body: its top surface z = 0, radius P,
    with the mark and the label on it), the ball (a mocap sphere), a directional light that
    casts shadows, the fixed camera ``cam``."""
    w, h = scene.size
    p, half = scene.platter_radius, scene.platter_thickness / 2
    film = 1e-4  # half thickness of the tape and the label, m: just above the surface
    if scene.mark_shape == "strip":
        length, width = scene.mark_size
        if scene.mark_along == "radial":
            length, width = width, length
        elif scene.mark_along != "tangential":
            raise ValueError(f"mark_along: 'tangential' or 'radial'; got {scene.mark_along!r}")
        mark = (f'<geom type="box" size="{_f(width / 2, length / 2, film)}" '
                f'pos="{_f(scene.mark_at * p, 0, film)}" material="mark"/>')  # fmt: skip
    elif scene.mark_shape == "dot":
        mark = (f'<geom type="cylinder" size="{_f(scene.mark_size[0] / 2, film)}" '
                f'pos="{_f(scene.mark_at * p, 0, film)}" material="mark"/>')  # fmt: skip
    else:
        raise ValueError(f"mark_shape must be 'strip' or 'dot'; got {scene.mark_shape!r}")
    label = ""
    if scene.label_radius > 0:
        label = (f'<geom type="cylinder" size="{_f(scene.label_radius * p, film / 2)}" '
                 f'pos="{_f(0, 0, film / 2)}" material="label"/>')  # fmt: skip
    if scene.second_dot is not None:
        x, y, diameter = scene.second_dot
        label += (f'\n      <geom type="cylinder" size="{_f(diameter / 2, film)}" '
                  f'pos="{_f(x, y, film)}" material="mark"/>')  # fmt: skip
    ball = table = ""  # textures, and their use by the materials
    if scene.ball_checker is not None:
        ball = ('<texture name="ball" type="cube" builtin="checker" '
                f'rgb1="{_f(*scene.ball_checker[0])}" rgb2="{_f(*scene.ball_checker[1])}" '
                'width="64" height="64"/>\n    <material name="ball" texture="ball"')  # fmt: skip
    if scene.table_wood:
        table = ('<texture name="table" type="2d" builtin="gradient" rgb1="0.72 0.52 0.32" '
                 'rgb2="0.55 0.38 0.22" width="512" height="512" mark="random" random="0.3" '
                 'markrgb="0.42 0.27 0.15"/>\n    '
                 '<material name="table" texture="table" texrepeat="6 6"')  # fmt: skip
    shine = f'specular="{_f(scene.platter_specular)}" shininess="{_f(scene.platter_shininess)}"'
    az, el = math.radians(scene.light_azimuth_deg), math.radians(scene.light_elevation_deg)
    towards = np.array([math.cos(el) * math.cos(az), math.cos(el) * math.sin(az), math.sin(el)])
    right, down, _ = cam.axes
    amb, head, sun = (_f(*[x] * 3) for x in (scene.ambient, scene.headlight, scene.light_diffuse))
    # the platter: a prism of rim_sides sides (a MuJoCo cylinder has numslices, and many
    # slices cost every round geom), top z = 0, vertices on the circle of radius P
    s = 2 * math.pi * np.arange(scene.rim_sides) / scene.rim_sides
    ring = np.column_stack([p * np.cos(s), p * np.sin(s)])
    prism = np.vstack([np.column_stack([ring, np.zeros(len(s))]),
                       np.column_stack([ring, np.full(len(s), -2 * half)])])  # fmt: skip
    platter = _f(*prism.ravel())
    return f"""<mujoco model="turntable">
  <compiler angle="radian"/>
  <option><flag contact="disable" gravity="disable"/></option>
  <statistic extent="{_f(4 * p)}" center="0 0 0"/>
  <visual>
    <global offwidth="{w}" offheight="{h}"/>
    <quality shadowsize="{scene.shadow_size}" offsamples="{scene.samples}"
             numslices="{scene.slices}" numstacks="{max(scene.slices // 4, 8)}"/>
    <headlight ambient="{amb}" diffuse="{head}" specular="0.1 0.1 0.1"/>
    <map znear="0.02" zfar="10" shadowclip="1"/>
  </visual>
  <asset>
    <mesh name="platter" vertex="{platter}"/>
    {ball or '<material name="ball"'} rgba="{_f(*scene.ball_rgba)}"
              specular="{_f(scene.ball_specular)}" shininess="{_f(scene.ball_shininess)}"/>
    <material name="platter" rgba="{_f(*scene.platter_rgba)}" {shine}/>
    {table or '<material name="table"'} rgba="{_f(*scene.table_rgba)}" specular="0" shininess="0"/>
    <material name="mark" rgba="{_f(*scene.mark_rgba)}" specular="0.05" shininess="0.1"/>
    <material name="label" rgba="{_f(*scene.label_rgba)}" specular="0.05" shininess="0.1"/>
  </asset>
  <worldbody>
    <light name="sun" type="directional" castshadow="true" pos="{_f(*(0.5 * towards))}"
           dir="{_f(*(-towards))}" diffuse="{sun}" specular="0.3 0.3 0.3"/>
    <geom name="table" type="box" size="2 2 0.01" pos="{_f(0, 0, -2 * half - 0.01)}"
          material="table"/>
    <body name="platter" mocap="true">
      <geom name="platter" type="mesh" mesh="platter" material="platter"/>
      {mark}
      {label}
    </body>
    <body name="ball" mocap="true" pos="{_f(0, 0, radius)}">
      <geom name="ball" type="sphere" size="{_f(radius)}" material="ball"/>
    </body>
    <camera name="cam" pos="{_f(*cam.position)}" xyaxes="{_f(*right, *(-np.asarray(down)))}"
            fovy="{_f(scene.fovy_deg)}"/>
  </worldbody>
</mujoco>
"""


def _gl_default() -> None:
    """EGL unless MUJOCO_GL says otherwise (before mujoco is imported)."""
    os.environ.setdefault("MUJOCO_GL", "egl")
    os.environ.setdefault("PYOPENGL_PLATFORM", os.environ["MUJOCO_GL"])


def render_mujoco(
    path: str | os.PathLike[str],
    model: str,
    coefficient: float,
    state0: ArrayLike,
    setup: Setup,
    scene: MujocoScene | None = None,
    seed: int = 0,
) -> MujocoRendered:
    """Render a SYNTHETIC video of the ball of one friction model with MuJoCo; write H.264.

    Parameters
    ----------
    path : str or path-like
        The video (.mp4, .mkv or .mov); its name must contain SYNTHETIC.
    model, coefficient, state0, setup
        As for `turntable.fit.positions`; ``state0`` is the state at t = 0 (the first
        frame's opening); the axis of ``setup`` must be (0, 0).
    scene : MujocoScene, optional
        By default ``MujocoScene()``.
    seed : int
        Seed of the sensor noise.

    Returns
    -------
    MujocoRendered
        ``film``: the true centres (m, lab frame, the model's: counterclockwise platter) at
        the frame times (at the middle of the exposure if blurred), ``synthetic=True``;
        ``omega``; ``tilt_deg``; ``camera``.
    """

    _gl_default()
    import mujoco

    path = Path(path)
    setup = _scene.check_output(path, setup)
    scene = scene or MujocoScene()
    width, height = scene.size
    if width % 2 or height % 2:
        raise ValueError(f"yuv420p needs an even width and height; got {scene.size}")
    n = math.floor(scene.duration * scene.fps * (1 + 1e-12)) + 1
    time_base = Fraction(1, 90000)
    t = np.round(np.arange(n) / scene.fps * time_base.denominator) / time_base.denominator
    k = max(int(scene.blur_samples), 1)
    exposure = scene.shutter / scene.fps if k > 1 else 0.0
    offsets = exposure * (np.arange(k) + 0.5) / k if k > 1 else np.zeros(1)
    samples = (t[:, None] + offsets[None, :]).ravel()
    ball = positions(model, coefficient, state0, samples, setup).reshape(n, k, 2)
    xy = positions(model, coefficient, state0, t + exposure / 2, setup)
    reach = float(np.max(np.hypot(ball[..., 0], ball[..., 1])))
    if reach > scene.platter_radius - setup.radius:
        raise ValueError(
            f"the ball leaves the platter ({reach:.4g} m from the axis, P - R = "
            f"{scene.platter_radius - setup.radius:.4g} m)"
        )
    sign = -1.0 if scene.clockwise else 1.0
    ball[..., 1] *= sign
    cam = _camera(scene)
    mj = mujoco.MjModel.from_xml_string(scene_xml(scene, setup.radius, cam))
    data = mujoco.MjData(mj)
    platter_id, ball_id = mj.body("platter").mocapid[0], mj.body("ball").mocapid[0]
    rng = np.random.default_rng(seed)
    noise = None
    if scene.noise > 0:
        noise = np.round(rng.standard_normal((2 * height, 2 * width, 1), dtype=np.float32)
                         * np.float32(scene.noise)).astype(np.int16)  # fmt: skip
        noise = np.repeat(noise, 3, axis=2)
    renderer = mujoco.Renderer(mj, height, width)

    def frame(i: int, ti: float) -> NDArray[np.uint8]:
        acc = np.zeros((height, width, 3), dtype=np.float32)
        for j in range(k):
            angle = sign * setup.omega * (ti + offsets[j])
            data.mocap_quat[platter_id] = (math.cos(angle / 2), 0, 0, math.sin(angle / 2))
            data.mocap_pos[ball_id] = (ball[i, j, 0], ball[i, j, 1], setup.radius)
            mujoco.mj_forward(mj, data)
            renderer.update_scene(data, camera="cam")
            acc += renderer.render()
        img = np.round(acc / k).astype(np.int16) if k > 1 else acc.astype(np.int16)
        if noise is not None:
            dv, du = rng.integers(0, height), rng.integers(0, width)
            img += noise[dv : dv + height, du : du + width]
        return np.clip(img, 0, 255).astype(np.uint8)

    try:
        write_video(path, ((ti, frame(i, ti)) for i, ti in enumerate(t)), scene.fps,
                    (width, height), scene.crf,
                    f"rendered by MuJoCo {mujoco.__version__} (benchmarks/mujoco_scene.py) from "
                    f"the exact solution of the {model} model ({coefficient!r})")  # fmt: skip
    finally:
        renderer.close()
    return MujocoRendered(Film(t + exposure / 2, xy[:, 0], xy[:, 1], synthetic=True),
                          setup.omega, scene.tilt_deg, cam)  # fmt: skip


# ---------------------------------------------------------------------------------------
# The four examples and the check of the ball's image against the projected truth.

GREY, WHITE = (0.5, 0.5, 0.5, 1.0), (0.95, 0.95, 0.93, 1.0)
_RED = MujocoScene(ball_rgba=(0.8, 0.08, 0.08, 1.0), ball_specular=0.3, ball_shininess=0.3,
                   platter_rgba=GREY, table_rgba=(0.45, 0.33, 0.2, 1.0), mark_shape="strip",
                   mark_size=(0.016, 0.008), mark_rgba=WHITE, tilt_deg=0.0)  # fmt: skip


def _red(c: NDArray) -> NDArray:
    return (c[..., 0] > 90) & (c[..., 0] - c[..., 1:].max(-1) > 50)


#: name: (scene, the ball's pixels in a decoded frame (RGB 0-255, float) as a mask)
EXAMPLES = {
    "red_grey_strip_tilt0": (_RED, _red),
    "red_grey_strip_tilt32": (replace(_RED, tilt_deg=32.0), _red),
    "white_black_dot_tilt20": (
        MujocoScene(ball_rgba=WHITE, platter_rgba=(0.04, 0.04, 0.045, 1.0), mark_shape="dot",
                    mark_size=(0.006, 0.006), mark_rgba=WHITE, tilt_deg=20.0),
        lambda c: c.mean(-1) > 100,
    ),
    "steel_blue_label_tilt15": (
        MujocoScene(ball_rgba=(0.6, 0.61, 0.64, 1.0), ball_specular=1.0, ball_shininess=0.9,
                    platter_rgba=(0.05, 0.08, 0.32, 1.0), mark_shape="dot",
                    mark_size=(0.008, 0.008), mark_rgba=(0.95, 0.82, 0.1, 1.0),
                    label_radius=0.3, label_rgba=(0.8, 0.1, 0.1, 1.0), tilt_deg=15.0),
        lambda c: (np.ptp(c, axis=-1) < 45) & (c.mean(-1) > 60),
    ),
}  # fmt: skip


def example_state(setup: Setup, platter: float, duration: float, seed: int) -> NDArray:
    """An initial state as ``benchmarks/video.py`` draws one: the ball 4-9 cm from the axis,
    a random velocity (0.03 m/s per component), no spin; redrawn until the slipping ball
    (mu0 = 2) stays 2.5 R inside the rim."""
    from turntable import film

    rng = np.random.default_rng(seed)
    while True:
        r0, a0 = rng.uniform(0.04, 0.09), rng.uniform(0, 2 * math.pi)
        v = rng.normal(0.0, 0.03, 2)
        z0 = film.state_from_si([r0 * math.cos(a0), r0 * math.sin(a0)], v, [0.0, 0.0], setup)
        xy = positions("slipping", 2.0, z0, np.linspace(0, duration + 0.01, 400), setup)
        if np.max(np.hypot(xy[:, 0], xy[:, 1])) <= platter - 2.5 * setup.radius:
            return z0


def sphere_centroid(cam: Camera, centre: ArrayLike, radius: float, sub: int = 8) -> NDArray:
    """Centroid (u, v), px, of the image of a sphere, by casting sub x sub rays per pixel."""
    c = np.asarray(centre, dtype=float)
    u0, v0 = project(cam, c)
    span = 3 * cam.focal * radius / np.linalg.norm(c - np.asarray(cam.position)) + 3
    g = (np.arange(-span * sub, span * sub + 1) + 0.5) / sub
    u, v = np.meshgrid(np.floor(u0) + g, np.floor(v0) + g)
    w, h = cam.size
    rays = np.stack(
        [(u - (w - 1) / 2) / cam.focal, (v - (h - 1) / 2) / cam.focal, np.ones_like(u)], -1
    )
    rays = rays @ np.asarray(cam.axes)
    rays /= np.linalg.norm(rays, axis=-1, keepdims=True)
    oc = c - np.asarray(cam.position)
    miss = np.linalg.norm(oc - (rays @ oc)[..., None] * rays, axis=-1)
    hit = miss < radius
    return np.array([u[hit].mean(), v[hit].mean()])


def _segmented_centroid(scene: MujocoScene, cam: Camera, centre: NDArray, angle: float) -> NDArray:
    """Centroid (u, v) of the ball's pixels in MuJoCo's segmentation rendering (which geom
    each pixel shows: no shading, no anti-aliasing) of the scene at one instant."""
    _gl_default()
    import mujoco

    mj = mujoco.MjModel.from_xml_string(scene_xml(scene, centre[2], cam))
    data = mujoco.MjData(mj)
    data.mocap_quat[mj.body("platter").mocapid[0]] = (
        math.cos(angle / 2),
        0,
        0,
        math.sin(angle / 2),
    )
    data.mocap_pos[mj.body("ball").mocapid[0]] = centre
    mujoco.mj_forward(mj, data)
    renderer = mujoco.Renderer(mj, scene.size[1], scene.size[0])
    try:
        renderer.enable_segmentation_rendering()
        renderer.update_scene(data, camera="cam")
        seg = renderer.render()
    finally:
        renderer.close()
    v, u = np.nonzero(
        (seg[..., 0] == mj.geom("ball").id) & (seg[..., 1] == mujoco.mjtObj.mjOBJ_GEOM)
    )
    return np.array([u.mean(), v.mean()])


def check(
    path: Path, scene: MujocoScene, rendered: MujocoRendered, radius: float, is_ball, frame: int
) -> dict:
    """Offsets (px) at ``frame`` of a counterclockwise scene without blur: the projected true
    centre and the centroid of the sphere's image (ray cast: the perspective shift), against
    the centroid of the ball-coloured pixels of the decoded frame near it, and against the
    centroid of the ball in MuJoCo's segmentation rendering.  Saves the frame as a PNG in
    /tmp."""
    import av
    from PIL import Image

    with av.open(str(path)) as video:
        for i, f in enumerate(video.decode(video=0)):
            if i == frame:
                img = f.to_ndarray(format="rgb24")
                break
    png = Path("/tmp") / f"{path.stem}_frame{frame}.png"
    Image.fromarray(img).save(png)
    cam, fl = rendered.camera, rendered.film
    centre = np.array([fl.x[frame], fl.y[frame], radius])
    proj = project(cam, centre)
    expected = sphere_centroid(cam, centre, radius)
    reach = 2.0 * cam.focal * radius / np.linalg.norm(centre - np.asarray(cam.position))
    v, u = np.mgrid[0 : img.shape[0], 0 : img.shape[1]]
    mask = (np.hypot(u - proj[0], v - proj[1]) < reach) & is_ball(img.astype(float))
    seen = np.array([u[mask].mean(), v[mask].mean()])
    segmented = _segmented_centroid(scene, cam, centre, rendered.omega * fl.t[frame])
    return {
        "png": str(png),
        "ball_px": int(mask.sum()),
        "projected_centre": proj.round(2).tolist(),
        "perspective_shift": (expected - proj).round(3).tolist(),
        "coloured_minus_projected": (seen - proj).round(3).tolist(),
        "coloured_minus_sphere_image": (seen - expected).round(3).tolist(),
        "segmented_minus_sphere_image": (segmented - expected).round(3).tolist(),
    }


def main(argv: list[str] | None = None) -> None:
    import argparse
    import json

    from turntable import film

    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", type=Path, required=True, help="directory of the videos")
    parser.add_argument("--duration", type=float, default=2.0, help="s (default 2)")
    parser.add_argument("--check", action="store_true", help="compare one frame with the truth")
    args = parser.parse_args(argv)
    args.out.mkdir(parents=True, exist_ok=True)
    setup = film.Setup(radius=0.0075, omega=film.rpm_to_omega(100 / 3), k=0.4, axis=(0.0, 0.0))
    for seed, (name, (scene, is_ball)) in enumerate(EXAMPLES.items()):
        scene = replace(scene, size=(1280, 720), fps=240.0, duration=args.duration)
        state0 = example_state(setup, scene.platter_radius, scene.duration, seed)
        path = args.out / f"mujoco_{name}_{SYNTHETIC}.mp4"
        start = time.perf_counter()
        truth = render_mujoco(path, "slipping", 2.0, state0, setup, scene, seed=seed)
        per_frame = (time.perf_counter() - start) / truth.film.t.size
        np.savez(path.with_suffix(".truth.npz"), t=truth.film.t, x=truth.film.x, y=truth.film.y)
        print(f"{path}  ({truth.film.t.size} frames, {per_frame:.3f} s/frame)", flush=True)
        if args.check:
            res = check(path, scene, truth, setup.radius, is_ball, truth.film.t.size // 2)
            print("  " + json.dumps(res), flush=True)


if __name__ == "__main__":
    main()
