"""Helpers of `turntable.video.render`: checks of a Scene, the platter's polar texture, the
lens distortion, the mains flicker."""

from __future__ import annotations

import math
import numbers
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from turntable.film import Setup, check_setup
from turntable.video import camera
from turntable.video.camera import Pose
from turntable.video.decode import SYNTHETIC

#: The colour fields of a Scene.
COLOURS = ("ball_colour", "platter_colour", "label_colour", "mark_colour", "table_colour")
#: Allowed values of the Scene's fields that are words.
CHOICES = {
    "ball_finish": ("matte", "specular"),
    "mark_shape": ("disc", "square", "strip"),
    "mark_along": ("tangential", "radial"),
}
#: Closed ranges of the Scene's numeric fields (checked when they are set).
RANGES = {
    "mark_radius": (1e-3, 20.0),
    "mark_aspect": (1.0, 20.0),
    "platter_grain": (0.0, 100.0),
    "grooves": (0.0, 100.0),
    "groove_pitch": (0.008, 0.5),
    "label_radius": (0.0, 0.6),
    "light_elevation_deg": (10.0, 90.0),
    "light_azimuth_deg": (-360.0, 360.0),
    "shadow": (0.0, 1.0),
    "lens_k1": (-0.3, 0.3),
    "readout": (0.0, 1.0),
    "flicker": (0.0, 0.99),
    "flicker_hz": (1.0, 1000.0),
    "flicker_phase_deg": (-360.0, 360.0),
}


def check_output(path: Path, setup: Setup) -> Setup:
    """A rendered video's file name says SYNTHETIC, and its turntable's axis is the origin;
    returns the checked setup."""
    if SYNTHETIC not in path.name:
        raise ValueError(f"a rendered video's file name must contain {SYNTHETIC}; got {path.name}")
    setup = check_setup(setup)
    if setup.axis != (0.0, 0.0):
        raise ValueError(
            "the axis of a rendered turntable is the origin: setup.axis must be (0, 0)"
        )
    return setup


def rgb(value: Any, name: str) -> NDArray[np.float64]:
    """A colour as 3 floats in [0, 255], or a one-line ValueError naming the field."""
    try:
        c = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        c = np.array([np.nan])
    if c.shape != (3,) or not np.all((c >= 0) & (c <= 255)):
        raise ValueError(f"Scene.{name} must be 3 numbers (RGB) in [0, 255]; got {value!r}")
    return c


def check(scene: Any) -> None:
    """Raise a one-line ValueError naming the first bad field of ``scene``."""
    for name in COLOURS:
        rgb(getattr(scene, name), name)
    for name, allowed in CHOICES.items():
        if getattr(scene, name) not in allowed:
            raise ValueError(f"Scene.{name} must be one of {allowed}; got {getattr(scene, name)!r}")
    for name, (low, high) in RANGES.items():
        value = getattr(scene, name)
        if not (isinstance(value, numbers.Real) and low <= value <= high):
            raise ValueError(f"Scene.{name} must be a number in [{low}, {high}]; got {value!r}")


def light(scene: Any) -> NDArray[np.float64]:
    """Unit vector towards the light, lab frame."""
    a, e = math.radians(scene.light_azimuth_deg), math.radians(scene.light_elevation_deg)
    return np.array([math.cos(e) * math.cos(a), math.cos(e) * math.sin(a), math.sin(e)])


def _label(rng: np.random.Generator, rho: NDArray, phi: NDArray) -> NDArray:
    """Brightness (1 paper, below 1 print) of a record's label at radius ``rho`` (units of
    its radius) and angle ``phi``: a spindle hole, two rings and lines of text-like blocks."""
    rho, phi = np.broadcast_arrays(rho, phi)
    x, y = rho * np.cos(phi), rho * np.sin(phi)
    ink = (rho < 0.07) | ((rho > 0.3) & (rho < 0.33)) | ((rho > 0.9) & (rho < 0.94))
    for low, high in ((0.47, 0.58), (0.62, 0.72), (-0.6, -0.48), (-0.74, -0.66)):
        line = (y > low) & (y < high)
        end = math.sqrt(0.85**2 - max(low**2, high**2))
        start = -end + rng.uniform(0, 0.1)
        while start < end:
            stop = min(start + rng.uniform(0.05, 0.25), end)
            ink |= line & (x > start) & (x < stop)
            start = stop + rng.uniform(0.03, 0.06)
    return np.where(ink, 0.3, 1.0)


def platter_texture(
    scene: Any, rng: np.random.Generator, n_r: int, n_phi: int, blur_cells: float
) -> NDArray[np.uint8]:
    """Polar texture (n_r, n_phi, 4) RGBA of the platter (grain, grooves, the label),
    row i at radius (i + 1/2) P / n_r, blurred along the angle by ``blur_cells`` (the
    platter's turn over the exposure, signed)."""
    grain = rng.standard_normal((n_r, n_phi))
    f = np.fft.rfft(grain, axis=1)
    f *= np.exp(-0.5 * (2 * math.pi * np.fft.rfftfreq(n_phi) * 2.0) ** 2)  # Gaussian, 2 cells
    grain = np.fft.irfft(f, n=n_phi, axis=1)
    grain /= grain.std()
    r = (np.arange(n_r) + 0.5) / n_r
    grey = (
        scene.platter_grain * grain
        + scene.grooves * np.cos(2 * math.pi * r / scene.groove_pitch)[:, None]
    )
    tex = rgb(scene.platter_colour, "platter_colour")[:, None, None] + grey[None]
    if scene.label_radius > 0:
        rows = min(math.ceil(scene.label_radius * n_r) + 1, n_r)
        phi = np.arange(n_phi) * (2 * math.pi / n_phi)
        paper = _label(rng, r[:rows, None] / scene.label_radius, phi[None, :])
        label = rgb(scene.label_colour, "label_colour")[:, None, None] * paper[None]
        w = np.clip((r[:rows] - scene.label_radius) * n_r + 0.5, 0.0, 1.0)[None, :, None]
        tex[:, :rows] = w * tex[:, :rows] + (1 - w) * label
    width = max(round(abs(blur_cells)), 1)
    if width > 1:  # the mean of cells i, i - 1, ... (turning counterclockwise; else i, i + 1, ...)
        kernel = np.r_[np.ones(width), np.zeros(n_phi - width)] / width
        box = np.fft.rfft(kernel if blur_cells > 0 else np.roll(kernel[::-1], 1))
        tex = np.fft.irfft(np.fft.rfft(tex, axis=2) * box, n=n_phi, axis=2)
    out = np.full((n_r, n_phi, 4), 255, dtype=np.uint8)
    out[..., :3] = np.clip(np.moveaxis(tex, 0, -1) + 0.5, 0, 255)
    return out


def image(pose: Pose, points: ArrayLike) -> NDArray[np.float64]:
    """Pixels (n, 2) of lab points (n, 3) (in front of the camera), through its lens."""
    cam = (np.asarray(points, dtype=float) - camera.centre(pose)) @ camera.rotation(pose).T
    uv = pose.focal * cam[:, :2] / cam[:, 2:] + np.asarray(pose.principal)
    return camera.distort(pose, uv)


def window(pose: Pose, points: ArrayLike) -> tuple[slice, slice] | None:
    """The window (rows, columns) of the image around lab points (n, 3), or None if it
    is outside."""
    width, height = pose.size
    uv = image(pose, points)
    (u0, v0), (u1, v1) = uv.min(axis=0), uv.max(axis=0)
    v0, v1 = max(math.floor(v0) - 2, 0), min(math.ceil(v1) + 3, height)
    u0, u1 = max(math.floor(u0) - 2, 0), min(math.ceil(u1) + 3, width)
    return (slice(v0, v1), slice(u0, u1)) if v0 < v1 and u0 < u1 else None


def brighten(img: NDArray[np.int16], gain: NDArray) -> None:
    """Multiply the rows of an image (levels 0-255) by ``gain`` in place, in 1/128 of the
    light (at most one level off; faster than in floats)."""
    change = img * np.round(128 * (gain - 1)).astype(np.int16)[:, None, None]
    change += 64
    change >>= 7
    img += change


def flicker_gain(scene: Any, t: float, dt_rows: NDArray, exposure: float) -> NDArray:
    """Brightness 1 + a sin(2 pi f t + phase) of the mains light averaged over each row's
    exposure, which starts at t + dt_rows."""
    w = 2 * math.pi * scene.flicker_hz
    mid = w * (t + dt_rows + exposure / 2) + math.radians(scene.flicker_phase_deg)
    return 1 + scene.flicker * np.sin(mid) * np.sinc(w * exposure / 2 / math.pi)


def mark_cover(
    scene: Any, x: NDArray, y: NDArray, foot: NDArray, angles: list, halves: tuple, at: float
) -> NDArray:
    """Share of each pixel (plane points x, y; foot m/px) covered by the mark, averaged over
    its angles (each a scalar or per row); ``halves``: its half radial and tangential sizes
    (a disc: its radius twice)."""
    cov = np.zeros(x.shape)
    for a in angles:
        c, s = np.cos(a), np.sin(a)
        radial, tangential = x * c + y * s - at, y * c - x * s
        if scene.mark_shape == "disc":
            cov += np.clip(0.5 + (halves[0] - np.hypot(radial, tangential)) / foot, 0, 1)
        else:
            cov += np.clip(0.5 + (halves[0] - np.abs(radial)) / foot, 0, 1) * np.clip(
                0.5 + (halves[1] - np.abs(tangential)) / foot, 0, 1
            )
    return cov / len(angles)


def shadow_cover(
    x: NDArray, y: NDArray, foot: NDArray, centres: list, radius: float, light: NDArray
) -> NDArray:
    """Share of the light that the ball (centres (x, y) at height R) hides from the plane
    points (x, y, 0), averaged over the centres: inside the sphere's projection along the
    light, softened over 1.5 px."""
    lx, ly, lz = light
    cov = np.zeros(x.shape)
    for cx, cy in centres:
        wx, wy = x - cx, y - cy
        along = wx * lx + wy * ly - radius * lz
        dist = np.sqrt(np.maximum(wx**2 + wy**2 + radius**2 - along**2, 0))
        cov += np.clip(0.5 + (radius - dist) / (1.5 * foot), 0, 1)
    return cov / len(centres)


def sphere(
    d: NDArray,
    centres: list,
    radius: float,
    focal: float,
    light: NDArray,
    colour: NDArray,
    shading: tuple[float, float, float],
) -> tuple[NDArray, NDArray]:
    """Rays ``d`` (..., 3) cast at a sphere, centres (from the eye) ``centres``: the share
    of each pixel it covers and its light (..., 3) there (times the share), averaged
    over the centres.  ``shading``: the ambient share of the light (the rest Lambert's),
    the peak of the Blinn-Phong highlight (share of white) and its exponent."""
    ambient, specular, shininess = shading
    halfway = light - d
    halfway /= np.linalg.norm(halfway, axis=-1, keepdims=True)
    cov_sum = np.zeros(d.shape[:-1])
    light_sum = np.zeros((*d.shape[:-1], 3))
    for centre in centres:
        s = np.stack(np.broadcast_arrays(*centre), axis=-1)
        tca = np.sum(d * s, axis=-1)
        dist2 = np.maximum(np.sum(s * s, axis=-1) - tca**2, 0.0)
        cov = np.clip(0.5 + (radius - np.sqrt(dist2)) / (tca / focal), 0, 1)
        hit = d * (tca - np.sqrt(np.maximum(radius**2 - dist2, 0.0)))[..., None] - s
        normal = hit / np.linalg.norm(hit, axis=-1, keepdims=True)
        lambert = np.maximum(normal @ light, 0.0)
        shade = colour * (ambient + (1 - ambient) * lambert)[..., None]
        if specular:
            highlight = np.maximum(np.sum(normal * halfway, axis=-1), 0.0) ** shininess
            shade += 255.0 * specular * (highlight * (lambert > 0))[..., None]
        cov_sum += cov
        light_sum += cov[..., None] * np.minimum(shade, 255.0)
    return cov_sum / len(centres), light_sum / len(centres)
