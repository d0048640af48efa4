r"""Stage 5, the camera: from the rim of the platter and a mark turning with it.

The rim is a circle of radius :math:`P` in the plane :math:`z = 0`; the mark, a point of the
platter at a distance :math:`r_m` from the axis, is at the angle :math:`\varphi_0 + \Omega
t`. ``calibrate`` fits, by least squares, a pinhole camera (`turntable.video.camera`: focal
length, tilt, roll, look-at point, distance; the principal point at the image's centre,
square pixels) together with :math:`r_m`, :math:`\varphi_0` and :math:`\Omega`, to the image
points of the rim and the tracked image of the mark, and a rolling shutter's readout time:
the mark at row v of a frame is seen at that frame's time plus :math:`\text{readout} \cdot v
/ \text{height}`.
The rim alone (an ellipse: five numbers) cannot fix the camera's perspective; the mark's
uniform turning fixes the rest, and the axis's image with it. Priors keep the focal length
(:math:`\ln f` within 0.3 of the logarithm of the image's width: a field of view of 40 to 70
degrees) and the roll (within 1 rad of its start) defined where the data cannot: a camera
looking straight down, whose image does not depend on them. The rim's ellipse is weighed as
known to a thousandth of its size at best (``RIM_BIAS``): weighed as its many points would
have it, its small biases set the tilt of such a camera, and the rest of the camera follows
them.

The lens's radial distortion k1 (`turntable.video.camera.Pose`) is measured on the mark's
track alone: thousands of images, over several turns, of a point turning uniformly on one
circle of the platter's plane, which a pinhole sees on an ellipse and a bending lens does
not.  The rim's edge would pass its own bias to k1: up to a pixel on the near side, from the
platter's side and its shadow.  The camera is fitted again with that k1 where the mark
measures it to a fifth (``LENS_Z``); elsewhere the lens is a pinhole's, with k1 known only
to within :math:`\sqrt{k_1^2 + s_e^2}` of 0 (:math:`k_1` and its standard error :math:`s_e` as the
mark measures them), which the standard
errors of the camera and the covariance of the parameters carry (``Lens``).

A camera looking nearly straight down shows its focal length, apart from its tilt, only in
the ellipticity of its images, of the order of the tilt squared: an error of their shape of a
ten-thousandth of their size, which the mark's tracked images carry, moves it, and the
distance with it, far beyond the scatter of the images.  The covariance of the parameters
carries it (``turntable.video.covariance``), and with it the scale of the plane of the
ball's centre, R above the platter, seen from that distance.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray
from scipy.optimize import least_squares

from turntable.video import camera
from turntable.video.camera import Pose
from turntable.video.covariance import covariance, focal_floor, follows_held, lag1
from turntable.video.platter import Ellipse

#: Spread of the priors on ln(focal length / image width), on the roll (rad) and on the
#: rolling shutter's readout time (frame intervals).
PRIOR_LOG_FOCAL = 0.3
#: ... and of the camera from the rim alone, whose focal length the rim cannot fix: an
#: ellipse is the image of the rim for a one-parameter family of cameras, down to a focal
#: length of a tenth of the image's width at a tilt near 90 degrees, which a rim seen with a
#: bias of a fraction of a pixel (the platter's side, beneath its rim) then fits best.
RIM_PRIOR_LOG_FOCAL = 0.01
PRIOR_ROLL = 1.0
PRIOR_READOUT = 2.0
#: The share of its semi-major axis to which the rim's ellipse is known at best, however many
#: its points: its edge (the platter's side, shading, shadow) is biased in a shape an ellipse
#: takes up, stretched by 0.11-0.14 % of its radius in MuJoCo's renders lit from one side.
RIM_BIAS = 0.001
#: The lens's k1 is kept if the mark measures it to a fifth (`LENS_Z` standard errors from 0,
#: above the 3.3, and 4.0 on a mark as large as the ball, to which the mark's own small biases
#: put the k1 of the benchmark's distortion-free lenses: kept there, k1 = 0.011 moved that
#: video's positions by 0.003 R; left out, a phone's k1 = -0.07 measured to 6.5-7.8 standard
#: errors put them 0.03-0.04 R off) and within +-`MAX_K1` (a phone's main camera, whose barrel
#: distortion moves the corners of a 60-degree field of view inward by up to 5 %: k1 = -0.114;
#: a wide-angle or fisheye lens bends more than this model describes).  A k1 within
#: ``AT_BOUND`` of +-`MAX_K1` is the bound's, not a measurement (a pinhole's camera looking
#: straight down, its k1 fitted at 0.1499997, had its positions 0.045 R off and its
#: coefficient 4.4 standard errors).
LENS_Z, MAX_K1, AT_BOUND = 5.0, 0.15, 1e-3
#: Rows are read from the top down within this many frame intervals: where the readout is
#: hard to tell from the camera's tilt (a camera looking nearly straight down), the bounds
#: keep it physical.
MAX_READOUT = 1.2


class _At:
    """Where each parameter sits in the vector theta of a calibration.

    theta = (ln f, tilt, roll, look-at x, look-at y, ln distance: the camera's six;
    ln r_m, phi0, Omega: the mark's circle and the platter's rate; the readout time in frame
    intervals; the lens's k1).  The camera alone (`_rim_fit`) is the first `CAMERA`.
    """

    LOG_FOCAL, TILT, ROLL, LOOK_X, LOOK_Y, LOG_DISTANCE = range(6)
    LOG_MARK_RADIUS, PHASE, OMEGA, READOUT, K1 = range(6, 11)
    CAMERA = 6
    SIZE = 11
    LOOK = slice(LOOK_X, LOOK_Y + 1)
    #: Everything but k1: what the Jacobian of a fit with k1 held covers.
    HELD_K1 = slice(0, K1)


class Lens(NamedTuple):
    """What the mark's track says of the lens's radial distortion.

    Attributes
    ----------
    measured : bool
        Whether k1 was measured (to `LENS_Z` standard errors, within +-`MAX_K1`) and kept;
        otherwise the camera is a pinhole's, and k1 is 0 known to within ``spread``.
    k1, k1_stderr : float
        k1 as the mark alone measures it, and its standard error.
    shift : numpy.ndarray
        The calibration's parameters moved by one standard error of k1 (the others
        following it): sqrt(k1^2 + k1_stderr^2), at most `MAX_K1`, if not measured;
        k1_stderr if measured.
    """

    measured: bool
    k1: float
    k1_stderr: float
    shift: NDArray[np.float64]

    @property
    def spread(self) -> float:
        """The standard error of the k1 that the camera uses."""
        return float(abs(self.shift[_At.K1]))


class Calibration(NamedTuple):
    """The fitted camera and turntable, with standard errors.

    Attributes
    ----------
    pose : Pose
    omega, omega_stderr : float
        Rate of the platter, rad/s, counterclockwise seen from above (negative: clockwise).
    mark_radius : float
        Distance of the mark from the axis, m.
    derived, stderr : dict
        tilt_deg, roll_deg, axis_u_px, axis_v_px, m_per_px (at the axis, geometric mean of
        the two directions), focal_px, distance_m, lens_k1 (the lens's radial distortion: 0
        if the mark's track does not tell it from 0, its standard error then
        sqrt(k1^2 + se^2) of the mark's measurement), and their standard errors.
    rim_rms_px, mark_rms_px : float
        Rms distance of the rim points and of the mark's images from the fitted camera.
    mark_lag1 : float
        Lag-1 autocorrelation of the mark's residuals (the standard errors are widened by
        sqrt((1 + r) / (1 - r)) for r > 0).
    readout, readout_stderr : float
        A rolling shutter's readout time, s: row v of a frame is seen ``readout * v / height``
        after the frame's time (0 for a global shutter).
    lens : Lens
        The lens's k1 as the mark measures it, and whether the camera uses it.
    parameters, covariance : numpy.ndarray
        The fitted parameters (`_At`) and their covariance, the uncertainty of k1 and what
        follows from it included, and the images' systematic error of the focal length
        (``turntable.video.covariance.MARK_SHAPE``).
    interval : float
        The frame interval, s (the unit of the readout time among the parameters).
    """

    pose: Pose
    omega: float
    omega_stderr: float
    mark_radius: float
    derived: dict[str, float]
    stderr: dict[str, float]
    rim_rms_px: float
    mark_rms_px: float
    mark_lag1: float
    readout: float = 0.0
    readout_stderr: float = 0.0
    lens: Lens | None = None
    parameters: NDArray[np.float64] | None = None
    covariance: NDArray[np.float64] | None = None
    interval: float = 1.0

    def times(self, t: NDArray[np.float64], v: NDArray[np.float64]) -> NDArray[np.float64]:
        """When image points at rows ``v`` of frames at times ``t`` were seen."""
        return t + self.readout * np.asarray(v) / self.pose.size[1]


def _pose(theta: NDArray, size: tuple[int, int]) -> Pose:
    """The camera of a parameter vector: the camera's six, and k1 if it has one (else 0)."""
    k1 = float(theta[_At.K1]) if len(theta) > _At.K1 else 0.0
    return Pose(
        math.exp(theta[_At.LOG_FOCAL]),
        theta[_At.TILT],
        theta[_At.ROLL],
        (theta[_At.LOOK_X], theta[_At.LOOK_Y]),
        math.exp(theta[_At.LOG_DISTANCE]),
        size,
        k1,
    )


def _derived(theta: NDArray, size: tuple[int, int]) -> NDArray[np.float64]:
    pose = _pose(theta, size)
    axis = camera.project(pose, np.zeros(2))
    # the Jacobian of image -> plane at the axis's image
    eps = 0.5
    d = [
        (camera.back_project(pose, axis + e) - camera.back_project(pose, axis - e)) / (2 * eps)
        for e in (np.array([eps, 0.0]), np.array([0.0, eps]))
    ]
    scale = math.sqrt(abs(np.linalg.det(np.column_stack(d))))
    return np.array(
        [
            math.degrees(theta[_At.TILT]),
            math.degrees(theta[_At.ROLL]),
            axis[0],
            axis[1],
            scale,
            math.exp(theta[_At.LOG_FOCAL]),
            math.exp(theta[_At.LOG_DISTANCE]),
            theta[_At.K1] if len(theta) > _At.K1 else 0.0,
            theta[_At.OMEGA] if len(theta) > _At.OMEGA else math.nan,
        ]
    )


_DERIVED = (
    "tilt_deg", "roll_deg", "axis_u_px", "axis_v_px", "m_per_px", "focal_px", "distance_m",
    "lens_k1",
)  # fmt: skip


class _Problem:
    def __init__(
        self, rim_pts, mark_t, mark_uv, size, platter_radius, rim: Ellipse, roll0, rim_frames
    ):
        self.rim_frames = rim_frames
        steps = np.diff(mark_t)
        self.interval = float(np.median(steps[steps > 0])) if np.any(steps > 0) else 1.0
        self.row = mark_uv[:, 1] / size[1] if len(mark_uv) else mark_uv
        self.rim_pts, self.mark_t, self.mark_uv = rim_pts, mark_t, mark_uv
        self.size, self.p = size, platter_radius
        self.px_per_m = rim.a / platter_radius
        self.log_f0, self.roll0 = math.log(size[0]), roll0
        self.prior_log_focal = PRIOR_LOG_FOCAL
        self.sigma_rim = self.sigma_mark = 1.0
        self.ellipse = rim
        self.k1 = 0.0

    def rim(self, theta: NDArray) -> NDArray:
        q = camera.back_project(_pose(theta, self.size), self.rim_pts)
        return (np.hypot(q[:, 0], q[:, 1]) - self.p) * self.px_per_m / self.sigma_rim

    def mark(self, theta: NDArray) -> NDArray:
        seen = self.mark_t + theta[_At.READOUT] * self.interval * self.row
        ang = theta[_At.PHASE] + theta[_At.OMEGA] * seen
        r = math.exp(theta[_At.LOG_MARK_RADIUS])
        pred = camera.project(
            _pose(theta, self.size), r * np.column_stack([np.cos(ang), np.sin(ang)])
        )
        return ((pred - self.mark_uv) / self.sigma_mark).ravel()

    def priors(self, theta: NDArray) -> NDArray:
        return np.array(
            [
                (theta[_At.LOG_FOCAL] - self.log_f0) / self.prior_log_focal,
                (theta[_At.ROLL] - self.roll0) / PRIOR_ROLL,
                theta[_At.READOUT] / PRIOR_READOUT if len(theta) > _At.READOUT else 0.0,
            ]
        )

    def all(self, theta: NDArray) -> NDArray:
        return np.concatenate([self.rim(theta), self.mark(theta), self.priors(theta)])

    def rim_only(self, camera6: NDArray) -> NDArray:
        return np.concatenate([self.rim(self.with_camera(camera6)), self.priors(camera6)])

    def with_camera(self, camera6: NDArray) -> NDArray:
        """The full parameter vector of the camera's six: the mark's and the readout's 0, k1
        held."""
        theta = np.zeros(_At.SIZE)
        theta[: _At.CAMERA] = camera6
        theta[_At.K1] = self.k1
        return theta


def _rim_fit(prob: _Problem, b0: float, roll0: float) -> NDArray:
    """The camera's six parameters from the rim alone."""
    size, rim, platter_radius = prob.size, prob.ellipse, prob.p
    f0 = float(size[0])
    theta = np.zeros(_At.CAMERA)
    theta[_At.LOG_FOCAL], theta[_At.TILT], theta[_At.ROLL] = math.log(f0), b0, roll0
    theta[_At.LOG_DISTANCE] = math.log(f0 * platter_radius / rim.a)
    for _ in range(2):  # the look-at point that puts the axis at the ellipse's centre
        q = camera.back_project(_pose(theta, size), np.array(rim.centre))
        theta[_At.LOOK] -= q
    return least_squares(prob.rim_only, theta, method="lm", x_scale="jac").x


def rim_camera(
    rim_pts: NDArray[np.float64], rim: Ellipse, size: tuple[int, int], platter_radius: float
) -> Pose:
    """A camera from the rim alone: right in scale and tilt, its focal length (the image's
    width) and which side of the platter is nearer set by the priors (enough to see paths
    on the platter's plane)."""
    roll0 = (-rim.angle + math.pi) % (2 * math.pi) - math.pi
    prob = _Problem(rim_pts, np.zeros(0), np.zeros((0, 2)), size, platter_radius, rim, roll0, 1)
    prob.prior_log_focal = RIM_PRIOR_LOG_FOCAL
    return _pose(_rim_fit(prob, math.acos(min(rim.b / rim.a, 1.0)), roll0), size)


def _fit(prob: _Problem, b0: float, roll0: float) -> tuple[NDArray, NDArray]:
    """The camera from the rim alone, then with the mark, each kind of point weighed by its
    own scatter, the lens's k1 held at ``prob.k1``; returns the parameters and the Jacobian."""
    size = prob.size
    theta = prob.with_camera(_rim_fit(prob, b0, roll0))
    # start of the mark's circle from its images seen through the rim-only camera
    q = camera.back_project(_pose(theta, size), prob.mark_uv)
    ang = np.unwrap(np.arctan2(q[:, 1], q[:, 0]))
    slope, phase = np.polyfit(prob.mark_t, ang, 1)
    theta[_At.LOG_MARK_RADIUS] = math.log(np.median(np.hypot(q[:, 0], q[:, 1])))
    theta[_At.PHASE], theta[_At.OMEGA] = phase, slope
    for _ in range(2):
        theta = _solve(prob.all, theta)[0]
        # the rim seen on several frames is one edge: its points count as those of one frame,
        # widened for their correlation along the rim
        rim_res = prob.rim(theta)
        r1 = max(lag1(rim_res[:, None]), 0.0)
        widen = math.sqrt(prob.rim_frames * (1 + r1) / (1 - min(r1, 0.99)))
        prob.sigma_rim *= max(float(np.sqrt(np.mean(rim_res**2))), 1e-3) * (widen if _ else 1.0)
        if _:  # each of the ellipse's numbers known to RIM_BIAS at best
            floor = RIM_BIAS * prob.ellipse.a * math.sqrt(rim_res.size / 2)
            prob.sigma_rim = max(prob.sigma_rim, floor)
        prob.sigma_mark *= max(float(np.sqrt(np.mean(prob.mark(theta) ** 2))), 1e-3)
    return _solve(prob.all, theta)


def _solve(fun, theta: NDArray, held: tuple[int, ...] = (_At.K1,)) -> tuple[NDArray, NDArray]:
    """Least squares of the residuals ``fun(theta)`` over the parameters but ``held``, the
    readout between 0 and `MAX_READOUT` frame intervals, k1 within +-`MAX_K1`; returns the
    parameters and the Jacobian with respect to the free ones."""
    free = np.ones(theta.size, bool)
    free[list(held)] = False
    lo, hi = np.full(theta.size, -np.inf), np.full(theta.size, np.inf)
    lo[_At.READOUT], hi[_At.READOUT] = 0.0, MAX_READOUT
    lo[_At.K1], hi[_At.K1] = -MAX_K1, MAX_K1
    theta = theta.copy()
    theta[_At.READOUT] = min(max(theta[_At.READOUT], 1e-9), MAX_READOUT - 1e-9)

    def residuals(x: NDArray) -> NDArray:
        t = theta.copy()
        t[free] = x
        return fun(t)

    fit = least_squares(
        residuals, theta[free], method="trf", bounds=(lo[free], hi[free]), x_scale="jac"
    )
    theta[free] = fit.x
    return theta, fit.jac


def _lens(prob: _Problem, theta: NDArray) -> tuple[float, float]:
    """The lens's k1 and its standard error from the mark alone, its radius held (the mark
    alone cannot tell it from the camera's distance)."""

    def residuals(t: NDArray) -> NDArray:
        return np.concatenate([prob.mark(t), prob.priors(t)])

    theta, jac = _solve(residuals, theta, held=(_At.LOG_MARK_RADIUS,))
    res = prob.mark(theta).reshape(-1, 2) * prob.sigma_mark
    scale = max(float(np.sqrt(np.mean(res**2))), 1e-3) / prob.sigma_mark
    cov = np.linalg.pinv(jac.T @ jac) * scale**2
    r1 = lag1(res)
    if r1 > 0:
        cov *= (1 + r1) / (1 - r1)
    return float(theta[_At.K1]), float(math.sqrt(max(cov[-1, -1], 0.0)))


def _best(args: tuple, k1: float) -> tuple[NDArray, NDArray, _Problem]:
    """The camera, the lens's k1 held, fitted (`_fit`) with either side of the rim's ellipse
    taken as the nearer, whichever fits better: its parameters, Jacobian and problem."""
    rim_pts, rim, mark_t, mark_uv, size, platter_radius, rim_frames = args
    b0 = math.acos(min(rim.b / rim.a, 1.0))
    best = None
    for roll0 in (-rim.angle, -rim.angle + math.pi):
        roll0 = (roll0 + math.pi) % (2 * math.pi) - math.pi
        prob = _Problem(rim_pts, mark_t, mark_uv, size, platter_radius, rim, roll0, rim_frames)
        prob.k1 = k1
        theta, jac = _fit(prob, b0, roll0)
        # compared in pixels: each fit has weighed its points by its own scatter
        rim_px = prob.rim(theta) * prob.sigma_rim
        score = np.mean((prob.mark(theta) * prob.sigma_mark) ** 2) + np.mean(rim_px**2)
        if best is None or score < best[0]:
            best = (score, theta, jac, prob)
    return best[1:]


def calibrate(
    rim_pts: NDArray[np.float64],
    rim: Ellipse,
    mark_t: NDArray[np.float64],
    mark_uv: NDArray[np.float64],
    size: tuple[int, int],
    platter_radius: float,
    rim_frames: int = 1,
) -> Calibration:
    """Fit the camera (with the lens's k1 where the mark measures it), the mark's circle and
    Omega (see the module's docstring).

    Parameters
    ----------
    rim_pts : numpy.ndarray
        Image points (u, v) of the rim, px, shape (n, 2).
    rim : Ellipse
        The ellipse fitted to them (the start).
    mark_t, mark_uv : numpy.ndarray
        Times (s) and image points (px) of the mark.
    size : tuple of int
        (width, height) of the image.
    platter_radius : float
        P, m.
    rim_frames : int
        Number of frames the rim points come from.
    """
    args = (rim_pts, rim, mark_t, mark_uv, size, platter_radius, rim_frames)
    theta, jac, prob = _best(args, 0.0)
    k1, k1_se = _lens(prob, theta)
    lens = 0 < LENS_Z * k1_se <= abs(k1) < MAX_K1 * (1 - AT_BOUND)
    if lens:
        theta, jac, prob = _best(args, k1)
    # a lens not measured to LENS_Z is a pinhole's, with k1 known to its distance from 0,
    # and within the lenses the model takes (+-MAX_K1) however poorly the mark measures it
    k1_spread = k1_se if lens else min(math.hypot(k1, k1_se), MAX_K1)
    mark_res = prob.mark(theta).reshape(-1, 2) * prob.sigma_mark
    r1 = lag1(mark_res)
    k1_shift = k1_spread * _follows_k1(prob, theta, jac)
    floor = focal_floor(jac, r1, prob.prior_log_focal, float(theta[_At.TILT]), _At.LOG_FOCAL)
    focal_shift = floor * np.r_[follows_held(jac, _At.LOG_FOCAL), 0.0]  # k1 held at 0
    cov = covariance(jac, r1, _At.HELD_K1, _At.SIZE, k1_shift, focal_shift)
    g0 = _derived(theta, size)
    grad = _derived_gradient(theta, size)
    se = np.sqrt(np.maximum(np.einsum("ij,jk,ik->i", grad, cov, grad), 0.0))
    return Calibration(
        pose=_pose(theta, size),
        omega=float(theta[_At.OMEGA]),
        omega_stderr=float(math.sqrt(max(cov[_At.OMEGA, _At.OMEGA], 0.0))),
        mark_radius=float(math.exp(theta[_At.LOG_MARK_RADIUS])),
        derived={k: float(v) for k, v in zip(_DERIVED, g0, strict=False)},
        stderr={k: float(v) for k, v in zip(_DERIVED, se, strict=False)},
        rim_rms_px=float(np.sqrt(np.mean((prob.rim(theta) * prob.sigma_rim) ** 2))),
        mark_rms_px=float(np.sqrt(np.mean(mark_res**2))),
        mark_lag1=r1,
        readout=float(theta[_At.READOUT] * prob.interval),
        readout_stderr=float(math.sqrt(max(cov[_At.READOUT, _At.READOUT], 0.0)) * prob.interval),
        lens=Lens(lens, k1, k1_se, k1_shift),
        parameters=theta,
        covariance=cov,
        interval=prob.interval,
    )


def _follows_k1(prob: _Problem, theta: NDArray, jac: NDArray) -> NDArray:
    """d theta / d k1: how the fitted parameters follow a change of the held k1 (1 in k1)."""
    e = np.zeros_like(theta)
    e[_At.K1] = 1e-6
    change = prob.all(theta + e) - prob.all(theta - e)
    shift = -np.linalg.pinv(jac.T @ jac) @ jac.T @ change
    return np.r_[shift / 2e-6, 1.0]


def _derived_gradient(theta: NDArray, size: tuple[int, int]) -> NDArray:
    """d `_derived` / d theta by central differences."""
    g0 = _derived(theta, size)
    grad = np.empty((g0.size, theta.size))
    for j in range(theta.size):
        step = 1e-6 * max(abs(theta[j]), 1.0)
        e = np.zeros_like(theta)
        e[j] = step
        grad[:, j] = (_derived(theta + e, size) - _derived(theta - e, size)) / (2 * step)
    return grad


def camera_of(cal: Calibration, theta: NDArray) -> tuple[Pose, float, float]:
    """The camera, the readout time (s) and Omega (rad/s) of parameters ``theta`` of the
    calibration ``cal`` (`Calibration.parameters` moved, say, by its uncertainty)."""
    return (
        _pose(theta, cal.pose.size),
        float(theta[_At.READOUT]) * cal.interval,
        float(theta[_At.OMEGA]),
    )
