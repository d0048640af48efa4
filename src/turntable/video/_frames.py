"""The frames of a rendered video (`turntable.video.render`): the platter looked up in its
polar texture, the mark, the shadow and the shaded ball drawn in windows around them, with
the motion blur, the rolling shutter and the flicker of the scene.
"""

from __future__ import annotations

import functools
import math
from typing import Any

import numpy as np
from numpy.typing import NDArray

from turntable.video import _scene, camera
from turntable.video.camera import Pose

#: Share of the light on the ball that is ambient (the rest is Lambert's, from the light).
AMBIENT = 0.5
#: Peak of a specular ball's highlight (share of white) and its Blinn-Phong exponent.
SPECULAR, SHININESS = 0.8, 60.0
#: Samples in time over the shutter's opening (motion blur).
BLUR_SAMPLES = 4


class _Renderer:
    """Draws the frames (RGBA, uint8): the platter is a lookup in its polar texture, the
    mark, the shadow and the ball are drawn in windows around them."""

    n_r, n_phi = 512, 4096  # the platter's polar texture; n_phi a power of 2

    def __init__(self, scene: Any, pose: Pose, radius: float, omega: float, seed: int) -> None:
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
