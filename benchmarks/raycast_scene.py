"""SYNTHETIC videos of a ball on a turntable drawn by an independent numpy ray caster.

Written without reading the project's renderer (``turntable.video.render``) or tracker: a
pinhole camera, tilted and turned; a disc platter of a texture (dark, grey, light, wood
grain, speckled granite) with a label, a spindle and a mark near the rim, on a table (wood,
cloth, white); a ball, plain or with two caps or a stripe, its orientation integrated from
its angular velocity; soft shadows of one or two lamps; vignetting; sensor noise; H.264
(libx264, yuv420p, PyAV) at a crf or a bitrate.  Only the ball's motion comes from the
package, through its public API: `turntable.solve` (the slipping ball with viscous friction,
dimensionless: length R, time 1/Omega, k = 0.4).

`SCENES` holds the scenes, each named with SYNTHETIC, and `render` writes ``NAME.mp4``,
``NAME_truth.npz`` (the ball's true positions, its pixel, the scene) and ``NAME_frame0.png``.
The same scene gives the same images: the textures are drawn from the scene's seed and the
sensor noise (OpenCV's generator) from its initial state, set again for every video.  The
H.264 files of the scenes 854 pixels wide (chroma of an odd width) are not: the same frames
give other bytes from one run to the next (with one encoder thread too), and their tracking
varies a little; ``benchmarks/raycast.py --keep`` reuses the files of a folder.

``benchmarks/raycast.py`` renders, tracks and fits them.  Render one scene with
``python benchmarks/raycast_scene.py --out DIR [NAME ...]``.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import time
from collections.abc import Iterator
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

import av
import cv2
import numpy as np
from numpy.typing import NDArray

import turntable

__all__ = ["K_INERTIA", "SCENES", "Camera", "Scene", "frames", "render", "seeds", "simulate"]

#: The ball's moment of inertia over m R^2 (a solid ball).
K_INERTIA = 0.4


@dataclass
class Scene:
    """A video: its camera, platter, ball, light and encoding (SI units, degrees)."""

    name: str
    unusual: str
    width: int = 1280
    height: int = 720
    fps: float = 60.0
    duration: float = 5.0
    rpm: float = 100.0 / 3.0
    clockwise: bool = False
    R: float = 0.0125  # ball radius, m
    P: float = 0.15  # platter radius, m
    thickness: float = 0.03  # platter top above the table, m
    tilt_deg: float = 20.0
    azimuth_deg: float = 0.0
    roll_deg: float = 0.0
    hfov_deg: float = 55.0
    fill: float = 0.85  # platter diameter / image height (sets the distance)
    target: tuple = (0.0, 0.0)  # where the camera's axis meets the platter plane, m
    mu0: float = 1.0
    z0: tuple = (4.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    phase0_deg: float = 37.0  # the platter's angle at t = 0
    platter: str = "dark"  # dark | grey | light | wood | granite
    table: str = "wood"  # wood | cloth | white
    ball_color: tuple = (0.92, 0.92, 0.9)
    ball_marks: str = "none"  # none | two | stripe
    ball_mark_color: tuple = (0.8, 0.05, 0.05)
    spec: float = 0.3
    mark_color: tuple = (0.95, 0.95, 0.95)
    mark_diam_R: float = 0.8  # platter mark diameter in ball radii (<= 1 within the guide)
    mark_r_frac: float = 0.88
    label_r_frac: float = 0.3
    label_offset: tuple = (0.0, 0.0)  # label centre offset, m
    label_color: tuple = (0.75, 0.15, 0.1)
    # (direction, intensity, angular radius in rad) of each lamp
    lamps: list = field(default_factory=lambda: [((0.3, -0.2, 1.0), 0.75, 0.02)])
    ambient: float = 0.3
    vignette: float = 0.0  # fractional darkening at the image corner
    noise: float = 0.0  # sensor noise sigma, in 8-bit levels at mid grey
    crf: int | None = 20
    bitrate: int | None = None  # bit/s, overrides crf
    seed: int = 1


def rot_z(a: float) -> NDArray[np.float64]:
    """Rotation by ``a`` (rad) about z."""
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1.0]])


def rot_x(a: float) -> NDArray[np.float64]:
    """Rotation by ``a`` (rad) about x."""
    c, s = np.cos(a), np.sin(a)
    return np.array([[1.0, 0, 0], [0, c, -s], [0, s, c]])


def rodrigues(w: NDArray[np.float64], dt: float) -> NDArray[np.float64]:
    """Rotation of a body turning at angular velocity ``w`` (rad/s) for ``dt`` (s)."""
    th = np.linalg.norm(w) * dt
    if th < 1e-15:
        return np.eye(3)
    a = w / np.linalg.norm(w)
    Kx = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + np.sin(th) * Kx + (1 - np.cos(th)) * Kx @ Kx


class Camera:
    """The scene's pinhole camera: its axes and position in the world (platter top z = 0).

    Parameters
    ----------
    sc : Scene
        The scene: image size, field of view, tilt, azimuth, roll, fill and target.
    """

    def __init__(self, sc: Scene) -> None:
        W, H = sc.width, sc.height
        self.W, self.H = W, H
        self.f = (W / 2) / np.tan(np.radians(sc.hfov_deg) / 2)
        self.cx, self.cy = (W - 1) / 2, (H - 1) / 2
        th = np.radians(sc.tilt_deg)
        # straight down: x right = +x, image down = -y, forward = -z; tilt about x then azimuth
        Rm = rot_z(np.radians(sc.azimuth_deg)) @ rot_x(th)
        xc, yc, zc = Rm @ [1.0, 0, 0], Rm @ [0, -1.0, 0], Rm @ [0, 0, -1.0]
        r = np.radians(sc.roll_deg)
        xc, yc = np.cos(r) * xc + np.sin(r) * yc, -np.sin(r) * xc + np.cos(r) * yc
        self.axes = np.stack([xc, yc, zc])  # rows: camera x, y, z in world
        # distance so that the platter's diameter spans `fill` of the image height
        dist = (2 * sc.P) / (sc.fill * H / self.f)
        self.C = np.array([sc.target[0], sc.target[1], 0.0]) - dist * zc

    def rays(self, u: NDArray[np.float64], v: NDArray[np.float64]) -> NDArray[np.float64]:
        """Unit directions (world) of the rays through pixels ``u``, ``v``."""
        d = (
            ((u - self.cx) / self.f)[..., None] * self.axes[0]
            + ((v - self.cy) / self.f)[..., None] * self.axes[1]
            + self.axes[2]
        )
        return d / np.linalg.norm(d, axis=-1, keepdims=True)

    def project(self, p: Any) -> NDArray[np.float64]:
        """Pixels (u, v) of world points ``p`` (..., 3), m."""
        q = (np.asarray(p) - self.C) @ self.axes.T
        return np.stack(
            [self.f * q[..., 0] / q[..., 2] + self.cx, self.f * q[..., 1] / q[..., 2] + self.cy],
            -1,
        )


def value_noise(shape: tuple[int, int], cells: int, rng: np.random.Generator) -> NDArray:
    """Smooth noise of ``shape``: ``cells`` random values across, cubically interpolated."""
    g = rng.random((cells + 3, cells + 3)).astype(np.float32)
    return cv2.resize(g, (shape[1], shape[0]), interpolation=cv2.INTER_CUBIC)


def fbm(n: int, rng: np.random.Generator, octaves=(4, 8, 16, 32, 64)) -> NDArray:
    """Fractal noise (n x n, 0-1): `value_noise` of ``octaves``, each 0.6 of the last."""
    out = np.zeros((n, n), np.float32)
    amp, tot = 1.0, 0.0
    for c in octaves:
        out += amp * value_noise((n, n), c, rng)
        tot += amp
        amp *= 0.6
    return out / tot


def platter_texture(sc: Scene, n: int, rng: np.random.Generator) -> NDArray[np.float32]:
    """Albedo (linear RGB, n x n) over [-P, P]^2 in the platter frame."""
    P = sc.P
    x = np.linspace(-P, P, n, dtype=np.float32)
    X, Y = np.meshgrid(x, x)
    if sc.platter == "wood":
        warp = fbm(n, rng) - 0.5
        d = np.hypot(X - 0.9, Y + 2.3) + 0.006 * warp  # rings of a far-away centre: grain
        g = 0.5 + 0.5 * np.sin(2 * np.pi * d / 0.0045)
        g = g**2.5
        fine = fbm(n, rng, (64, 128, 256)) - 0.5
        a, b = np.array([0.30, 0.17, 0.08]), np.array([0.16, 0.08, 0.035])
        tex = a + (b - a) * np.clip(g + 0.4 * fine, 0, 1)[..., None]
    elif sc.platter == "granite":
        sp = fbm(n, rng, (32, 64, 128, 256, 512))
        speck = (rng.random((n, n)) < 0.02).astype(np.float32)
        speck = cv2.GaussianBlur(speck, (0, 0), 1.2) * 6
        v = 0.10 + 0.12 * sp + 0.25 * np.clip(speck, 0, 1)
        tex = np.stack([v, v * 0.97, v * 1.03], -1)
    else:
        base = {"dark": 0.035, "grey": 0.2, "light": 0.6}[sc.platter]
        v = base * (1 + 0.06 * (fbm(n, rng, (16, 64, 256)) - 0.5))
        tex = np.stack([v, v, v], -1)
    tex = tex.astype(np.float32)
    # label (off-centre if asked), spindle, mark
    lx, ly = sc.label_offset
    lab = np.hypot(X - lx, Y - ly) < sc.label_r_frac * P
    tex[lab] = np.array(sc.label_color, np.float32)
    ring = np.abs(np.hypot(X - lx, Y - ly) - 0.6 * sc.label_r_frac * P) < 0.0015
    tex[ring & lab] = np.array([0.9, 0.85, 0.6], np.float32)
    tex[np.hypot(X, Y) < 0.0036] = np.array([0.5, 0.5, 0.52], np.float32)  # spindle top
    mr = sc.mark_r_frac * P
    mark = np.hypot(X - mr, Y) < sc.mark_diam_R * sc.R / 2
    tex[mark] = np.array(sc.mark_color, np.float32)
    return tex


def table_texture(sc: Scene, X: NDArray, Y: NDArray, rng: np.random.Generator) -> NDArray:
    """Albedo (linear RGB) of the table at its points ``X``, ``Y`` (m)."""
    if sc.table == "wood":
        n = fbm(512, rng)
        w = cv2.resize(n, (64, 64))
        mx, my = ((X + 1) * 31).astype(np.float32), ((Y + 1) * 31).astype(np.float32)
        warp = cv2.remap(w, mx, my, cv2.INTER_LINEAR, borderMode=cv2.BORDER_REFLECT)
        d = Y * 1.0 + 0.01 * warp
        g = 0.5 + 0.5 * np.sin(2 * np.pi * d / 0.012)
        a, b = np.array([0.55, 0.38, 0.2]), np.array([0.42, 0.27, 0.13])
        return a + (b - a) * g[..., None]
    if sc.table == "cloth":
        return np.broadcast_to(np.array([0.12, 0.25, 0.14]), (*X.shape, 3)).copy()
    return np.broadcast_to(np.array([0.8, 0.8, 0.78]), (*X.shape, 3)).copy()


def lamps_of(sc: Scene) -> list[tuple[NDArray[np.float64], float, float]]:
    """The lamps: unit direction towards the lamp, intensity, angular radius (rad)."""
    out = []
    for d, power, ang in sc.lamps:
        d = np.asarray(d, float)
        out.append((d / np.linalg.norm(d), power, ang))
    return out


def simulate(sc: Scene, times: NDArray[np.float64]) -> tuple[NDArray, NDArray, NDArray]:
    """The ball's motion at ``times`` (s) by `turntable.solve`.

    Returns
    -------
    pos : ndarray
        The ball's centre (x, y) in the lab frame, m (the world's: y mirrored if clockwise).
    w : ndarray
        Its angular velocity's horizontal components, rad/s, in the same frame.
    z : ndarray
        The dimensionless state (counterclockwise platter) of `turntable.solve`.
    """
    Om = sc.rpm * 2 * np.pi / 60
    z = turntable.solve(np.asarray(sc.z0, float), times * Om, sc.mu0, K_INERTIA)
    pos = z[:, :2] * sc.R  # lab frame, counterclockwise platter, m
    w = z[:, 4:6] * Om  # rad/s, horizontal components
    if sc.clockwise:  # mirror y: the world platter turns clockwise
        pos = pos * [1, -1]
        w = w * [-1, 1]  # pseudovector under y -> -y
    return pos, w, z


def frames(sc: Scene) -> Iterator[tuple[NDArray[np.uint8], NDArray, NDArray]]:
    """Draw the frames of scene ``sc``, one at a time.

    Parameters
    ----------
    sc : Scene
        The scene.

    Yields
    ------
    image : ndarray
        The frame, H x W x 3, RGB, uint8 (before the encoding).
    pixel : ndarray
        The projection (u, v) of the ball's true centre.
    platter_xy : ndarray
        The ball's centre in the platter's frame (x, y), m.
    """
    rng = np.random.default_rng(sc.seed)
    cv2.setRNGSeed(0)  # OpenCV's generator (the noise) in its initial state
    cam = Camera(sc)
    W, H = sc.width, sc.height
    lamps = lamps_of(sc)
    sign = -1.0 if sc.clockwise else 1.0
    Om = sc.rpm * 2 * np.pi / 60
    nfr = round(sc.duration * sc.fps)
    times = np.arange(nfr) / sc.fps
    pos, wlab, _ = simulate(sc, times)
    rr = np.hypot(*pos.T) / sc.R
    if not rr.max() < sc.P / sc.R - 3:
        raise ValueError(f"{sc.name}: the ball comes too near the rim: {rr.max():.2f} R")

    # static geometry: top-plane points and the coverage of the top disc (4x4 samples)
    u, v = np.meshgrid(np.arange(W, dtype=float), np.arange(H, dtype=float))
    d = cam.rays(u, v)
    s = -cam.C[2] / d[..., 2]
    ptop = cam.C + s[..., None] * d
    rc = np.hypot(ptop[..., 0], ptop[..., 1])
    cov = (rc < sc.P).astype(np.float32)
    mpp0 = 2 * sc.P / (sc.fill * H)
    near = np.nonzero(np.abs(rc - sc.P) < 4 * mpp0 / np.cos(np.radians(sc.tilt_deg)) + 2 * mpp0)
    ss = 4
    acc = np.zeros(near[0].shape, np.float32)
    for i in range(ss):
        for j in range(ss):
            dd = cam.rays(u[near] + (i + 0.5) / ss - 0.5, v[near] + (j + 0.5) / ss - 0.5)
            sj = -cam.C[2] / dd[..., 2]
            pj = cam.C + sj[..., None] * dd
            acc += np.hypot(pj[..., 0], pj[..., 1]) < sc.P
    cov[near] = acc / (ss * ss)
    # outside: table (or the platter's side where the table point lies under the platter)
    st = (-sc.thickness - cam.C[2]) / d[..., 2]
    ptab = cam.C + st[..., None] * d
    tab = table_texture(sc, ptab[..., 0], ptab[..., 1], rng)
    side = np.hypot(ptab[..., 0], ptab[..., 1]) < sc.P
    tab[side] = np.array([0.08, 0.08, 0.09])
    light_flat = sc.ambient + sum(power * max(L[2], 0) for L, power, _ in lamps)
    # the platter edge shadow on the table is ignored; the table is lit evenly
    outside = (tab * light_flat).astype(np.float32)
    del d, ptab, st
    # texture
    ntex = 2048 if max(W, H) > 1300 else 1536
    tex = platter_texture(sc, ntex, rng)
    px = (ntex - 1) / (2 * sc.P)
    # blur the texture to about half a pixel's footprint (anti-aliasing of the 1x sampling)
    mpp = 2 * sc.P / (sc.fill * H) * 1.0  # rough metres per pixel
    sig = 0.5 * mpp * px
    if sig > 0.5:
        tex = cv2.GaussianBlur(tex, (0, 0), sig)
    X0 = ptop[..., 0].astype(np.float32)
    Y0 = ptop[..., 1].astype(np.float32)
    # vignetting
    rn = np.hypot((u - cam.cx) / cam.cx, (v - cam.cy) / cam.cy) / np.sqrt(2)
    vig = (1 - sc.vignette * rn**2).astype(np.float32)[..., None]
    # ball orientation (body to world), integrated from the lab angular velocity
    Rb = [np.eye(3)]
    for i in range(1, nfr):
        dt = (times[i] - times[i - 1]) / 4
        M = Rb[-1]
        for q in range(4):
            a = (q + 0.5) / 4
            w3 = np.array([*(wlab[i - 1] * (1 - a) + wlab[i] * a), 0.0])
            M = rodrigues(w3, dt) @ M
        Rb.append(M)
    m1 = np.array([0.0, 0.0, 1.0])
    m2 = np.array([np.sin(2.0), 0.0, np.cos(2.0)])
    m2 /= np.linalg.norm(m2)
    stripe_axis = np.array([0.3, 0.9, 0.2])
    stripe_axis /= np.linalg.norm(stripe_axis)

    # fast path: lit platter texture in sRGB uint8, warped by a homography per frame; the
    # ball, its shadows and the rim are recomputed in linear light inside a box around them.
    g = 1 / 2.2
    tex_lin = tex
    tex8 = np.clip((tex * light_flat) ** g * 255 + 0.5, 0, 255).astype(np.uint8)
    out8 = np.clip(outside**g * 255 + 0.5, 0, 255).astype(np.uint8)
    inside = (cov >= 1).astype(np.uint8)
    rim = (cov > 0) & (cov < 1)
    rim_idx = np.nonzero(rim)
    cov_rim = cov[rim_idx][:, None]
    Kc = np.array([[cam.f, 0, cam.cx], [0, cam.f, cam.cy], [0, 0, 1.0]])
    Rcw = cam.axes
    Hp = Kc @ np.column_stack([Rcw[:, 0], Rcw[:, 1], -Rcw @ cam.C])  # plane z=0 -> pixel
    Hinv = np.linalg.inv(Hp)
    vig8 = np.repeat((vig[..., 0] ** g)[..., None], 3, -1).astype(np.float32)
    for i in range(nfr):
        ang = sign * Om * times[i] + np.radians(sc.phase0_deg)
        c, s_ = np.cos(ang), np.sin(ang)
        T = np.array([[px * c, px * s_, sc.P * px], [-px * s_, px * c, sc.P * px], [0, 0, 1.0]])
        M = T @ Hinv
        top8 = cv2.warpPerspective(
            tex8,
            M,
            (W, H),
            flags=cv2.INTER_LINEAR | cv2.WARP_INVERSE_MAP,
            borderMode=cv2.BORDER_REFLECT,
        )
        img8 = out8.copy()
        cv2.copyTo(top8, inside, img8)
        img8[rim_idx] = (
            cov_rim * top8[rim_idx] ** (1 / g) / 255 ** (1 / g) + (1 - cov_rim) * outside[rim_idx]
        ) ** g * 255 + 0.5
        bc = np.array([pos[i, 0], pos[i, 1], sc.R])
        plat = np.array([c * bc[0] + s_ * bc[1], -s_ * bc[0] + c * bc[1]])
        pix = cam.project(bc)
        # box: the ball and its shadows
        pts = [
            bc + sc.R * 1.05 * np.array([a, b, e])
            for a in (-1, 1)
            for b in (-1, 1)
            for e in (-1, 1)
        ]
        for L, _, angr in lamps:
            if L[2] <= 0.05:
                continue
            sc_c = bc - bc[2] / L[2] * L
            ext = sc.R / L[2] + bc[2] / L[2] * np.tan(angr) * 2 + sc.R
            pts += [sc_c + np.array([a * ext, b * ext, 0]) for a in (-1, 1) for b in (-1, 1)]
        pc = cam.project(np.array(pts))
        u0, v0 = np.floor(pc.min(0)).astype(int) - 3
        u1, v1 = np.ceil(pc.max(0)).astype(int) + 3
        u0, v0 = max(u0, 0), max(v0, 0)
        u1, v1 = min(u1, W - 1), min(v1, H - 1)
        sl = (slice(v0, v1 + 1), slice(u0, u1 + 1))
        Xb, Yb = X0[sl], Y0[sl]
        Xp = c * Xb + s_ * Yb
        Yp = -s_ * Xb + c * Yb
        alb = cv2.remap(
            tex_lin,
            ((Xp + sc.P) * px).astype(np.float32),
            ((Yp + sc.P) * px).astype(np.float32),
            cv2.INTER_LINEAR,
            borderMode=cv2.BORDER_REFLECT,
        )
        Pb = ptop[sl].reshape(-1, 3)
        light = np.full(Pb.shape[0], sc.ambient)
        rel = bc - Pb
        for L, power, angr in lamps:
            along = rel @ L
            cr = rel - along[:, None] * L
            dist = np.sqrt((cr * cr).sum(1))
            pen = np.maximum(along, 1e-4) * np.tan(angr) + 1e-5
            vis = np.clip((dist - sc.R + pen) / (2 * pen), 0, 1)
            vis = vis * vis * (3 - 2 * vis)
            vis[along < 0] = 1
            light += power * max(L[2], 0) * vis
        hh, ww = v1 - v0 + 1, u1 - u0 + 1
        cb = cov[sl][..., None]
        img = cb * alb * light.reshape(hh, ww, 1) + (1 - cb) * outside[sl]
        # ball: supersampled rays in its own box
        pcb = pc[:8]
        bu0, bv0 = np.floor(pcb.min(0)).astype(int) - 2
        bu1, bv1 = np.ceil(pcb.max(0)).astype(int) + 2
        bu0, bv0 = max(bu0, u0), max(bv0, v0)
        bu1, bv1 = min(bu1, u1), min(bv1, v1)
        bsl = (slice(bv0 - v0, bv1 - v0 + 1), slice(bu0 - u0, bu1 - u0 + 1))
        hh, ww = bv1 - bv0 + 1, bu1 - bu0 + 1
        sb = 4
        uu, vv = np.meshgrid(
            bu0 - 0.5 + (np.arange(sb * ww) + 0.5) / sb, bv0 - 0.5 + (np.arange(sb * hh) + 0.5) / sb
        )
        dr = cam.rays(uu, vv)
        oc = cam.C - bc
        b = (dr * oc).sum(-1)
        cc = oc @ oc - sc.R**2
        disc = b * b - cc
        hit = disc > 0
        tt = -b - np.sqrt(np.maximum(disc, 0))
        ph = cam.C + tt[..., None] * dr
        n = (ph - bc) / sc.R
        nb = n @ Rb[i]  # body-frame direction: R^T n
        col = np.broadcast_to(np.array(sc.ball_color), n.shape).copy()
        if sc.ball_marks == "two":
            cap = np.cos(np.radians(22))
            msk = (nb @ m1 > cap) | (nb @ m2 > cap)
            col[msk] = sc.ball_mark_color
        elif sc.ball_marks == "stripe":
            msk = np.abs(nb @ stripe_axis) < np.sin(np.radians(12))
            col[msk] = sc.ball_mark_color
        sh = np.full(n.shape[:2], sc.ambient * 0.9)
        spec = np.zeros(n.shape[:2])
        for L, power, _ in lamps:
            sh += power * np.clip(n @ L, 0, None)
            hv = L - dr
            hv /= np.linalg.norm(hv, axis=-1, keepdims=True)
            spec += power * np.clip((n * hv).sum(-1), 0, None) ** 60
        bcol = col * sh[..., None] + sc.spec * spec[..., None]
        bcol[~hit] = 0
        alpha = hit.reshape(hh, sb, ww, sb).mean((1, 3))[..., None]
        bsum = bcol.reshape(hh, sb, ww, sb, 3).sum((1, 3)) / (sb * sb)
        img[bsl] = img[bsl] * (1 - alpha) + bsum
        img8[sl] = np.clip(np.clip(img, 0, 1) ** g * 255 + 0.5, 0, 255).astype(np.uint8)
        # camera: vignetting (in sRGB: the gamma of a product), noise
        if sc.vignette > 0:
            img8 = cv2.multiply(img8, vig8, dtype=cv2.CV_8U)
        if sc.noise > 0:
            nz = np.empty((H, W, 3), np.int16)
            cv2.randn(nz, 0, sc.noise)
            img8 = cv2.add(img8.astype(np.int16), nz, dtype=cv2.CV_16S)
            img8 = np.clip(img8, 0, 255).astype(np.uint8)
        yield np.ascontiguousarray(img8), pix, plat


def render(sc: Scene, folder: Path) -> Path:
    """Render scene ``sc`` into ``folder``: ``NAME.mp4``, ``NAME_truth.npz``, ``NAME_frame0.png``.

    Parameters
    ----------
    sc : Scene
        The scene (its name carries SYNTHETIC).
    folder : Path
        Where to write the files (made if missing).

    Returns
    -------
    Path
        The truth file: ``t``, ``lab_xy_m`` (the world's lab frame), ``platter_xy_m``,
        ``pix_uv`` (the ball centre's projection), ``omega``, ``clockwise``, ``mu0``, ``k``,
        ``R``, ``P``, ``zdim`` (the dimensionless state), ``axis_pix``, ``fps`` and ``scene``
        (its fields as JSON).
    """
    if "SYNTHETIC" not in sc.name:
        raise ValueError(f"{sc.name}: the name of a rendered video carries SYNTHETIC")
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    nfr = round(sc.duration * sc.fps)
    times = np.arange(nfr) / sc.fps
    pos, _, zdim = simulate(sc, times)
    cam = Camera(sc)
    Om = sc.rpm * 2 * np.pi / 60
    sign = -1.0 if sc.clockwise else 1.0
    cont = av.open(str(folder / f"{sc.name}.mp4"), "w")
    stream = cont.add_stream("libx264", rate=round(sc.fps))
    stream.width, stream.height, stream.pix_fmt = sc.width, sc.height, "yuv420p"
    if sc.bitrate:
        stream.bit_rate = sc.bitrate
        stream.options = {"preset": "medium"}
    else:
        stream.options = {"crf": str(sc.crf), "preset": "medium"}
    pix_true = np.zeros((nfr, 2))
    plat_true = np.zeros((nfr, 2))
    for i, (img8, pix, plat) in enumerate(frames(sc)):
        pix_true[i], plat_true[i] = pix, plat
        fr = av.VideoFrame.from_ndarray(img8, format="rgb24")
        fr.pts = i
        for pk in stream.encode(fr):
            cont.mux(pk)
        if i == 0:
            cv2.imwrite(str(folder / f"{sc.name}_frame0.png"), img8[..., ::-1])
    for pk in stream.encode():
        cont.mux(pk)
    cont.close()
    truth = folder / f"{sc.name}_truth.npz"
    np.savez(
        truth,
        t=times,
        lab_xy_m=pos,
        platter_xy_m=plat_true,
        pix_uv=pix_true,
        omega=Om,
        omega_signed=sign * Om,
        clockwise=sc.clockwise,
        mu0=sc.mu0,
        k=K_INERTIA,
        R=sc.R,
        P=sc.P,
        zdim=zdim,
        axis_pix=cam.project(np.zeros(3)),
        fps=sc.fps,
        scene=json.dumps(asdict(sc)),
    )
    return truth


def seeds(sc: Scene) -> tuple[str, str]:
    """The first frame's pixels of the ball and of the mark, as ``--ball-at`` / ``--mark-at``
    take them (``"U,V"``), read off the truth as a user reads them off ``--plot``."""
    cam = Camera(sc)
    pos, _, _ = simulate(sc, np.zeros(1))
    bu, bv = cam.project(np.array([pos[0, 0], pos[0, 1], sc.R]))
    a = np.radians(sc.phase0_deg)  # the platter's angle at t = 0, either way it turns
    mr = sc.mark_r_frac * sc.P
    mu, mv = cam.project(np.array([mr * np.cos(a), mr * np.sin(a), 0.0]))
    return f"{bu:.0f},{bv:.0f}", f"{mu:.0f},{mv:.0f}"


WHITE, BLACK = (0.95, 0.95, 0.95), (0.02, 0.02, 0.02)
TWO_LAMPS = [((0.6, -0.3, 0.55), 0.5, 0.08), ((-0.5, -0.4, 0.6), 0.4, 0.12)]

_LIST = [
    Scene(
        "S01_SYNTHETIC_wood_platter",
        "wood-grain platter, white table, 720p60",
        duration=4,
        platter="wood",
        table="white",
        mark_color=WHITE,
        tilt_deg=20,
        mu0=1.0,
        z0=(4.0, 0, 0, 0, 0, 0),
        seed=1,
    ),
    Scene(
        "S02_SYNTHETIC_granite_1080p50_45rpm",
        "speckled granite platter, orange ball, 1080p50, 45 rpm",
        width=1920,
        height=1080,
        fps=50,
        duration=4,
        rpm=45,
        platter="granite",
        table="wood",
        ball_color=(0.9, 0.35, 0.05),
        mark_color=(0.9, 0.85, 0.1),
        tilt_deg=25,
        azimuth_deg=30,
        mu0=1.5,
        z0=(0, 4.5, -0.3, 0, 0, 0),
        seed=2,
    ),
    Scene(
        "S03_SYNTHETIC_vignette_noise_480p25",
        "strong vignetting + sensor noise, 854x480 at 25 fps",
        width=854,
        height=480,
        fps=25,
        duration=6,
        platter="dark",
        table="wood",
        mark_color=WHITE,
        vignette=0.55,
        noise=7,
        tilt_deg=15,
        mu0=0.8,
        z0=(-3.5, 1.0, 0, 0, 0, 0),
        seed=3,
    ),
    Scene(
        "S04_SYNTHETIC_lowbitrate",
        "H.264 at 250 kbit/s (heavy blocking), blue ball, grey platter",
        duration=4,
        platter="grey",
        table="white",
        ball_color=(0.05, 0.15, 0.7),
        mark_color=WHITE,
        bitrate=250_000,
        crf=None,
        tilt_deg=25,
        mu0=1.0,
        z0=(3.0, -3.0, 0, 0, 0, 0),
        seed=4,
    ),
    Scene(
        "S05_SYNTHETIC_ball_two_marks_240fps",
        "white ball with two red caps, 240 fps",
        fps=240,
        duration=3,
        platter="dark",
        table="cloth",
        ball_marks="two",
        mark_color=WHITE,
        tilt_deg=30,
        azimuth_deg=-20,
        mu0=2.0,
        z0=(4.5, 1.0, 0.2, 0.5, 0, 0),
        seed=5,
    ),
    Scene(
        "S06_SYNTHETIC_striped_ball_cw_120fps",
        "yellow ball with a black stripe, clockwise, 120 fps",
        fps=120,
        duration=3,
        clockwise=True,
        platter="light",
        table="cloth",
        ball_color=(0.9, 0.75, 0.05),
        ball_marks="stripe",
        ball_mark_color=(0.02, 0.02, 0.02),
        mark_color=BLACK,
        label_color=(0.1, 0.2, 0.6),
        tilt_deg=10,
        mu0=1.2,
        z0=(4.0, 2.0, 0, 0, 0, 0),
        seed=6,
    ),
    Scene(
        "S07_SYNTHETIC_platter_out_of_frame",
        "OUTSIDE GUIDE: platter partly out of the frame",
        duration=4,
        platter="dark",
        table="wood",
        mark_color=WHITE,
        fill=1.05,
        target=(0.0, -0.04),
        tilt_deg=20,
        mu0=1.0,
        z0=(4.0, 0, 0, 0, 0, 0),
        seed=7,
    ),
    Scene(
        "S08_SYNTHETIC_offcentre_label",
        "large label 12 mm off-centre that the ball crosses",
        duration=4,
        platter="dark",
        table="white",
        mark_color=WHITE,
        label_r_frac=0.45,
        label_offset=(0.012, -0.006),
        label_color=(0.7, 0.1, 0.08),
        tilt_deg=20,
        mu0=0.7,
        z0=(5.5, 0.5, 0, 0, 0, 0),
        seed=8,
    ),
    Scene(
        "S09_SYNTHETIC_two_lamps_soft_shadows",
        "black ball, light platter, two soft shadows from two lamps",
        duration=4,
        platter="light",
        table="cloth",
        ball_color=(0.03, 0.03, 0.03),
        spec=0.5,
        mark_color=BLACK,
        label_color=(0.2, 0.5, 0.2),
        lamps=TWO_LAMPS,
        ambient=0.25,
        tilt_deg=20,
        azimuth_deg=15,
        mu0=1.0,
        z0=(-4.0, -1.0, 0, 0, 0, 0),
        seed=9,
    ),
    Scene(
        "S10_SYNTHETIC_topdown_480p50",
        "straight down (tilt 0), 854x480 at 50 fps, light-grey shiny ball, noise",
        width=854,
        height=480,
        fps=50,
        duration=4,
        platter="dark",
        table="white",
        ball_color=(0.6, 0.6, 0.62),
        spec=0.8,
        mark_color=WHITE,
        noise=4,
        tilt_deg=0,
        mu0=1.5,
        z0=(0, -4.0, 0, 0, 0, 0),
        seed=10,
    ),
    Scene(
        "S11_SYNTHETIC_cw_1080p25_tilt35_crf30",
        "clockwise, tilt 35, 1080p at 25 fps, crf 30, red ball",
        width=1920,
        height=1080,
        fps=25,
        duration=6,
        clockwise=True,
        platter="grey",
        table="wood",
        ball_color=(0.75, 0.05, 0.05),
        mark_color=WHITE,
        crf=30,
        tilt_deg=35,
        azimuth_deg=160,
        mu0=1.0,
        z0=(4.0, 0.0, 0, 0, 0, 0),
        seed=11,
    ),
    Scene(
        "S12_SYNTHETIC_combo",
        "wood + vignetting + noise + 1 Mbit/s + two lamps + striped ball, 50 fps, 45 rpm",
        fps=50,
        duration=4,
        rpm=45,
        platter="wood",
        table="white",
        ball_color=(0.92, 0.92, 0.9),
        ball_marks="stripe",
        ball_mark_color=(0.1, 0.1, 0.6),
        mark_color=WHITE,
        lamps=TWO_LAMPS,
        vignette=0.4,
        noise=5,
        bitrate=1_000_000,
        crf=None,
        tilt_deg=25,
        azimuth_deg=-40,
        mu0=1.0,
        z0=(3.5, 2.0, 0, 0, 0, 0),
        seed=12,
    ),
    Scene(
        "S13_SYNTHETIC_wood_480p25_7s_mu05",
        "wood platter, 854x480 at 25 fps, 7 s, tilt 30, noise, mu0 0.5 (wide spiral)",
        width=854,
        height=480,
        fps=25,
        duration=7,
        platter="wood",
        table="white",
        mark_color=WHITE,
        noise=3,
        tilt_deg=30,
        azimuth_deg=70,
        mu0=0.5,
        z0=(3.5, 0, 0, -0.5, 0, 0),
        seed=13,
    ),
    Scene(
        "S14_SYNTHETIC_black_ball_white_caps_1080p50_vignette",
        "black ball with two white caps, grey platter, two lamps, vignetting, 1080p50",
        width=1920,
        height=1080,
        fps=50,
        duration=4,
        platter="grey",
        table="white",
        ball_color=(0.03, 0.03, 0.03),
        ball_marks="two",
        ball_mark_color=(0.9, 0.9, 0.9),
        mark_color=(0.9, 0.9, 0.1),
        lamps=TWO_LAMPS,
        vignette=0.4,
        tilt_deg=12,
        azimuth_deg=200,
        mu0=1.8,
        z0=(-1.0, 4.5, 0, 0, 0, 0),
        seed=14,
    ),
]
_S06, _S11 = _LIST[5], _LIST[10]
_LIST += [
    # why S06 is refused: its yellow ball without the stripe; the striped ball on a dark platter
    dataclasses.replace(
        _S06,
        name="S06b_SYNTHETIC_yellow_ball_light_grey_cw_120fps",
        ball_marks="none",
        unusual="S06 without the stripe: plain yellow ball on "
        "light-grey platter, clockwise, 120 fps",
    ),
    dataclasses.replace(
        _S06,
        name="S06c_SYNTHETIC_striped_ball_dark_platter_cw_120fps",
        platter="dark",
        mark_color=WHITE,
        unusual="S06's striped yellow ball on a dark platter, clockwise, 120 fps",
    ),
    # why S11 is refused: turning counterclockwise; a blue label beside its red ball
    dataclasses.replace(
        _S11,
        name="S11b_SYNTHETIC_ccw_1080p25_tilt35_crf30",
        clockwise=False,
        unusual="S11 turning counterclockwise (red ball beside red label, tilt "
        "35, 1080p25, crf 30)",
    ),
    dataclasses.replace(
        _S11,
        name="S11c_SYNTHETIC_cw_1080p25_tilt35_crf30_bluelabel",
        label_color=(0.1, 0.2, 0.6),
        unusual="S11 with a blue label instead of a red one (clockwise, tilt 35, 1080p25, crf 30)",
    ),
]
#: The scenes by name (ball radius R = 12.5 mm, platter radius P = 150 mm unless they say).
SCENES: dict[str, Scene] = {s.name: s for s in sorted(_LIST, key=lambda s: s.name)}


def main() -> None:
    """Render the scenes named on the command line (all by default) into ``--out``."""
    parser = argparse.ArgumentParser(description=__doc__.partition("\n")[0])
    parser.add_argument("names", nargs="*", metavar="NAME", help="scenes (all by default)")
    parser.add_argument("--out", type=Path, required=True, help="folder of the videos")
    args = parser.parse_args()
    unknown = sorted(set(args.names) - set(SCENES))
    if unknown:
        parser.error(f"unknown scenes {unknown}; the scenes are {list(SCENES)}")
    for name in args.names or list(SCENES):
        start = time.perf_counter()
        render(SCENES[name], args.out)
        print(f"{name}: {time.perf_counter() - start:.0f} s", flush=True)


if __name__ == "__main__":
    main()
