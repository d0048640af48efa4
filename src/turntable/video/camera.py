"""A pinhole camera above the platter: the map between the image and planes parallel to it.

The lab frame: the platter is the plane z = 0, its axis the z axis, z up; the ball's
centre moves in the plane z = R.  The camera looks at the point (lx, ly, 0) from a
distance d, its optical axis tilted by ``tilt`` from the downward vertical towards +y
(the camera stands on the side of negative y), and turned by ``roll`` about that axis.
Image coordinates (u, v) are in pixels, u to the right and v down, pixel centres at whole
numbers; the principal point is the centre of the image and the pixels are square.  At
zero tilt and roll, x points right in the image and y up.  The lens may bend the pinhole's
image radially (``Pose.k1``, a phone's barrel distortion): `project` and `back_project`
include it.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["Pose", "back_project", "image_radius", "project", "sphere_centre"]


class Pose(NamedTuple):
    r"""A camera: focal length (px), tilt and roll (rad), look-at point (m), distance (m),
    image size (px), and its lens's radial distortion :math:`k_1`: a pinhole image point x (from the
    principal point, in units of the focal length) is seen at :math:`x (1 + k_1 |x|^2)`.

    Examples
    --------
    A camera 0.5 m above the axis, looking straight down:

    >>> from turntable.video.camera import Pose, project
    >>> pose = Pose(focal=1000.0, tilt=0.0, roll=0.0, look_at=(0.0, 0.0), distance=0.5,
    ...             size=(1280, 720))
    >>> project(pose, [[0.0, 0.0], [0.05, 0.0]])
    array([[639.5, 359.5],
           [739.5, 359.5]])
    """

    focal: float
    tilt: float
    roll: float
    look_at: tuple[float, float]
    distance: float
    size: tuple[int, int]  # (width, height)
    k1: float = 0.0

    @property
    def principal(self) -> tuple[float, float]:
        """The image centre (u, v), px."""
        return (self.size[0] - 1) / 2.0, (self.size[1] - 1) / 2.0


def rotation(pose: Pose) -> NDArray[np.float64]:
    """Rows: the camera's right, down and viewing directions in the lab frame."""
    b, a = pose.tilt, pose.roll
    z = np.array([0.0, math.sin(b), -math.cos(b)])
    x0 = np.array([1.0, 0.0, 0.0])
    y0 = np.array([0.0, -math.cos(b), -math.sin(b)])
    return np.array([math.cos(a) * x0 + math.sin(a) * y0, -math.sin(a) * x0 + math.cos(a) * y0, z])


def centre(pose: Pose) -> NDArray[np.float64]:
    """Position of the camera in the lab frame, m."""
    b = pose.tilt
    lx, ly = pose.look_at
    return np.array([lx, ly - pose.distance * math.sin(b), pose.distance * math.cos(b)])


def intrinsic(pose: Pose) -> NDArray[np.float64]:
    cx, cy = pose.principal
    return np.array([[pose.focal, 0.0, cx], [0.0, pose.focal, cy], [0.0, 0.0, 1.0]])


def homography(pose: Pose, height: float = 0.0) -> NDArray[np.float64]:
    """Return H (3 x 3) with (u, v, 1) ~ H (x, y, 1) for points of the plane z = height,
    (u, v) the pinhole's image (before the lens's distortion, `distort`).

    Notes
    -----
    H = K [r1 r2 (height r3 - Rot c)], with K the intrinsic matrix, r_i the columns of
    the rotation Rot (`rotation`) and c the camera's centre.
    """
    rot = rotation(pose)
    t = height * rot[:, 2] - rot @ centre(pose)
    return intrinsic(pose) @ np.column_stack([rot[:, 0], rot[:, 1], t])


def apply(h: NDArray[np.float64], points: ArrayLike) -> NDArray[np.float64]:
    """Apply a homography to points of shape (..., 2)."""
    p = np.asarray(points, dtype=float)
    w = p[..., 0, None] * h[2, 0] + p[..., 1, None] * h[2, 1] + h[2, 2]
    q = np.stack(
        [
            p[..., 0] * h[0, 0] + p[..., 1] * h[0, 1] + h[0, 2],
            p[..., 0] * h[1, 0] + p[..., 1] * h[1, 1] + h[1, 2],
        ],
        axis=-1,
    )
    return q / w


def distort(pose: Pose, uv: ArrayLike) -> NDArray[np.float64]:
    """Pixels (..., 2) at which the lens of ``pose`` shows the pinhole image points ``uv``."""
    uv = np.asarray(uv, dtype=float)
    if pose.k1 == 0:
        return uv
    c = np.asarray(pose.principal)
    r2 = np.sum((uv - c) ** 2, axis=-1, keepdims=True) / pose.focal**2
    return c + (uv - c) * (1 + pose.k1 * r2)


def undistort(pose: Pose, pixels: ArrayLike) -> NDArray[np.float64]:
    """Pinhole image points (..., 2) that the lens of ``pose`` shows at ``pixels``: Newton's
    iterations on the radius (kept below the radius where the distortion turns back).

    Examples
    --------
    >>> from turntable.video import camera
    >>> pose = camera.Pose(1000.0, 0.3, 0.0, (0.0, 0.0), 0.4, (1280, 720), k1=-0.02)
    >>> seen = camera.distort(pose, [[1100.0, 650.0]])
    >>> print(seen.round(3), camera.undistort(pose, seen).round(9))
    [[1097.27  648.278]] [[1100.  650.]]
    """
    pixels = np.asarray(pixels, dtype=float)
    if pose.k1 == 0:
        return pixels
    u, v, k1 = pixels[..., 0], pixels[..., 1], pose.k1
    cx, cy = pose.principal
    rd = np.hypot(u - cx, v - cy) / pose.focal
    ru = rd.copy()
    r_max = 1 / math.sqrt(-3 * k1) if k1 < 0 else np.inf  # where r (1 + k1 r^2) turns
    for _ in range(8):
        ru = np.clip(ru - (ru * (1 + k1 * ru**2) - rd) / (1 + 3 * k1 * ru**2), 0, 0.999 * r_max)
    scale = np.where(rd > 0, ru / np.maximum(rd, 1e-300), 1.0)
    return np.stack([cx + (u - cx) * scale, cy + (v - cy) * scale], axis=-1)


def project(pose: Pose, points: ArrayLike, height: float = 0.0) -> NDArray[np.float64]:
    """Image points (u, v) of points (x, y) of the plane z = height.

    Parameters
    ----------
    pose : Pose
        The camera.
    points : array_like
        Points (x, y) of the plane, m, shape (..., 2).
    height : float, optional
        Height z of the plane, m.

    Returns
    -------
    numpy.ndarray
        The image points (u, v), px, of the shape of ``points``.

    See Also
    --------
    turntable.video.camera.back_project : The inverse.

    Examples
    --------
    The axis seen by a camera 40 cm away looking straight at it is at the image's centre:

    >>> from turntable.video import camera
    >>> pose = camera.Pose(1000.0, 0.3, 0.0, (0.0, 0.0), 0.4, (1280, 720))
    >>> print(camera.project(pose, [[0.0, 0.0]]))
    [[639.5 359.5]]
    """
    return distort(pose, apply(homography(pose, height), points))


def back_project(pose: Pose, pixels: ArrayLike, height: float = 0.0) -> NDArray[np.float64]:
    """Points (x, y) of the plane z = height seen at the image points ``pixels`` (u, v).

    Parameters
    ----------
    pose : Pose
        The camera.
    pixels : array_like
        Image points (u, v), px, shape (..., 2).
    height : float, optional
        Height z of the plane, m.

    Returns
    -------
    numpy.ndarray
        The points (x, y), m, of the shape of ``pixels``.

    See Also
    --------
    turntable.video.camera.project : The inverse.

    Examples
    --------
    >>> from turntable.video import camera
    >>> pose = camera.Pose(1000.0, 0.3, 0.0, (0.0, 0.0), 0.4, (1280, 720))
    >>> uv = camera.project(pose, [[0.05, -0.02]], height=0.01)
    >>> print(camera.back_project(pose, uv, height=0.01).round(12))
    [[ 0.05 -0.02]]
    """
    return apply(np.linalg.inv(homography(pose, height)), undistort(pose, pixels))


def rays(pose: Pose, u: ArrayLike, v: ArrayLike) -> NDArray[np.float64]:
    """Unit directions (..., 3), in the lab frame, of the rays through pinhole image points
    (`undistort`)."""
    cx, cy = pose.principal
    d = np.stack(
        [
            (np.asarray(u) - cx) / pose.focal,
            (np.asarray(v) - cy) / pose.focal,
            np.ones(np.shape(u)),
        ],
        axis=-1,
    )
    d = d @ rotation(pose)
    return d / np.linalg.norm(d, axis=-1, keepdims=True)


def image_radius(pose: Pose, pixels: ArrayLike, radius: float) -> NDArray[np.float64]:
    r"""Radius (px) of the image of a sphere of radius ``radius`` whose centre, in the plane
    z = radius, is seen at ``pixels`` (u, v): :math:`f r / d`, :math:`f` the focal length and
    :math:`d` the centre's distance from the camera.

    Parameters
    ----------
    pose : Pose
        The camera.
    pixels : array_like
        Image points (u, v) of the sphere's centre, px, shape (..., 2).
    radius : float
        Radius of the sphere, m.

    Returns
    -------
    numpy.ndarray
        The radius of the image, px, of shape ``pixels.shape[:-1]``.

    Examples
    --------
    A ball of radius 1 cm, 40 cm below a camera of focal length 1000 px looking down at it:

    >>> from turntable.video import camera
    >>> pose = camera.Pose(1000.0, 0.0, 0.0, (0.0, 0.0), 0.4, (1280, 720))
    >>> print(camera.image_radius(pose, [pose.principal], 0.01).round(3))
    [25.641]
    """
    xy = back_project(pose, np.atleast_2d(np.asarray(pixels, dtype=float)), height=radius)
    depth = np.linalg.norm(np.column_stack([xy, np.full(len(xy), radius)]) - centre(pose), axis=1)
    return pose.focal * radius / depth


def sphere_centre(
    pose: Pose, pixels: ArrayLike, radius: float, iterations: int = 3
) -> NDArray[np.float64]:
    """Centres (x, y) in the plane z = radius of spheres whose images' centroids are ``pixels``.

    The image of a sphere is an ellipse whose centre lies off the image of the sphere's
    centre, away from the principal point: a sphere at angle phi from the optical axis,
    seen under the half-angle a = asin(R / distance), spans the angles phi - a to phi + a,
    so its image's centre is at f (tan(phi + a) + tan(phi - a)) / 2 from the principal
    point, the image of its centre at f tan(phi).  The shift is removed by fixed-point
    iteration from the point that ignores it.

    Parameters
    ----------
    pose : Pose
        The camera.
    pixels : array_like
        Centroids (u, v) of the images of the spheres, px, shape (..., 2).
    radius : float
        Radius of the spheres, m.
    iterations : int, optional
        Fixed-point iterations.

    Returns
    -------
    numpy.ndarray
        The centres (x, y), m, of the shape of ``pixels``.

    Examples
    --------
    A ball of radius 1 cm, 40 cm below a camera looking straight down, whose image is
    centred 100 mm off the axis (in the plane of its centre), has its centre nearer the axis:

    >>> from turntable.video import camera
    >>> pose = camera.Pose(1000.0, 0.0, 0.0, (0.0, 0.0), 0.4, (1280, 720))
    >>> uv = camera.project(pose, [[0.1, 0.0]], height=0.01)
    >>> x, y = camera.sphere_centre(pose, uv, 0.01)[0]
    >>> print(f"{1000 * x:.3f} mm")
    99.934 mm
    """
    uv = undistort(pose, np.atleast_2d(np.asarray(pixels, dtype=float)))
    pose = pose._replace(k1=0.0)
    rot, eye, f = rotation(pose), centre(pose), pose.focal
    xy = back_project(pose, uv, height=radius)
    for _ in range(iterations):
        c = np.column_stack([xy, np.full(len(xy), radius)]) - eye
        cam = c @ rot.T
        a = np.arcsin(np.minimum(radius / np.linalg.norm(c, axis=1), 1.0))
        off = np.hypot(cam[:, 0], cam[:, 1])
        phi = np.arctan2(off, cam[:, 2])
        direction = cam[:, :2] / np.maximum(off, np.finfo(float).tiny)[:, None]
        shift = f * ((np.tan(phi + a) + np.tan(phi - a)) / 2 - np.tan(phi))
        xy = back_project(pose, uv - shift[:, None] * direction, height=radius)
    return xy
