r"""Stage 6, checks: a track that contradicts itself is refused before anything is written.

Each check compares two things the video says independently; ``checks`` returns every one,
with its value and its limit, and ``first_failure`` the line that names the first that failed
and the option that would help.

- ``rate``: the mark turns at a rate a platter can have (``RATE_RANGE``), or within 1 % of
  ``--rpm``;
- ``mark_on_circle``: the mark's images lie on the fitted camera's circle, turning steadily
  (rms within ``MARK_RMS_PX`` px or half the mark's size);
- ``axis``: the centre of the mark's circle, seen through the camera the rim alone gives, is
  the rim's centre (within 3 % of P);
- ``tilt``: the mark's circle and the rim are seen under the same tilt (their images' axis
  ratios within 0.03; when the mark has covered half a turn);
- ``ball_found``: the ball is found on at least half of the frames (``MIN_FOUND``);
- ``ball_moves``: the ball moves relative to the platter (the spread of its path in the
  platter's frame at least R / 2), not rigidly with it;
- ``ball_path``: the ball does not jump: at most 2 % of its positions are more than R / 4
  (and what an acceleration of :math:`2 \Omega^2 P` could do) off the line between their neighbours;
- ``ball_smooth``: the ball's path is smooth: its positions scatter about a quadratic in
  time through their neighbours (over ``SMOOTH_S`` s, or 2.5 frames, either side) by at
  most ``SMOOTH_R`` R (rms), whatever the frame rate;
- ``ball_size``: the ball's image is the size that R and the fitted camera predict (within
  a factor ``BALL_SIZE`` in radius).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import NDArray

from turntable.video import camera
from turntable.video.calibrate import Calibration
from turntable.video.camera import Pose
from turntable.video.find import RATE_RANGE, Found
from turntable.video.follow import Paths
from turntable.video.platter import Ellipse, fit_ellipse
from turntable.video.robust import circle_centre

#: The mark's rate within this share of ``--rpm`` (a platter's rate is within 1 % of its
#: setting).
RPM_AGREE = 0.01
#: The mark's images within this many px (rms) of the fitted circle, or half its size.
MARK_RMS_PX = 2.0
#: The mark's circle centred within this share of P of the rim's centre.
AXIS_OFF = 0.03
#: The images' axis ratios of the mark's circle and the rim within this; compared once the
#: mark has covered ``TILT_TURN`` rad in at least ``TILT_FRAMES`` frames (less of an ellipse
#: does not fix its axis ratio).
TILT_AGREE, TILT_TURN, TILT_FRAMES = 0.03, math.pi, 10
#: The share of the frames the ball must be found on (on good tracks, at most a third are
#: gaps: where it passes the mark or runs into a label of its colour).
MIN_FOUND = 0.5
#: The ball's path in the platter's frame spreads over at least this (R): a blob that turns
#: with the platter is a mark or a label.
MIN_SPREAD_R = 0.5
#: A jump: a position more than ``JUMP_R`` R off the line between its neighbours, beyond the
#: a b c / 2 that an acceleration a = 4 Omega^2 P gives over steps b and c; at most
#: ``JUMP_SHARE`` of the positions jump.
JUMP_R, JUMP_SHARE = 0.25, 0.02
#: The ball's scatter about its smooth path: the limit (rms, in R) and the half-window (s, and
#: at least ``SMOOTH_FRAMES`` frames).
SMOOTH_R, SMOOTH_S, SMOOTH_FRAMES = 0.06, 0.05, 2.5
#: The ball's image radius over the one R and the camera predict: 0.89-1.17 on good tracks of
#: MuJoCo's scenes; 0.77 where a small white ball's shaded limb, darker than the platter, was
#: left out and its centre taken from its lit side.
BALL_SIZE = (0.8, 1.4)
#: A ball whose blob is its lit part only (`turntable.video.limb`): its size is that of its
#: part, lit or shaded, in the circle through its outline, where that circle is confirmed all
#: round on ``DISC_FRAMES`` of the frames it is found on at least (else its blob's area, which
#: a ball larger than predicted keeps): on the other frames its centre is a fallback (the lit
#: part's centroid, 2-5 px off on unseen.py's ``1080p60_P010``, confirmed on 68 % of its
#: frames and 0.078 R off, before its dark ring centred it (`turntable.video.ring`: 99.7 %,
#: 0.020 R); ``radial_tape_dark``: 93 %, 0.043 R).  Not for an image of the ball smaller than
#: ``DISC_MIN_PX`` in radius (px): an outline seen on the lit side only lies ~0.9 px inside
#: the ball's edge (unseen.py's ``720p60_r5_P017_tilt30``: the median of its 17 rays of 48
#: that weigh), and the circle of the ball's radius through it is as far off, more than the
#: 0.06 R of ``SMOOTH_R`` below 15 px (0.12 R there, at 10 px).
DISC_FRAMES, DISC_MIN_PX = 0.9, 15.0
#: What each check says when it fails, and the option that helps.
HELP = {
    "rate": "it may not be the mark: give --mark-at U,V (or check --rpm)",
    "mark_on_circle": "it may not be the mark: give --mark-at U,V",
    "axis": "it may not be the mark: give --mark-at U,V",
    "tilt": "it may not be the mark: give --mark-at U,V",
    "ball_found": (
        "it may be of nearly the platter's colour: film it in more contrast with the platter, "
        "or give --ball-at U,V"
    ),
    "ball_moves": "it may be a mark or a label, not the ball: give --ball-at U,V",
    "ball_path": "it may have been taken for something else on the way: give --ball-at U,V",
    "ball_smooth": (
        "it may have been confused with its shadow or a label: give --ball-at U,V, or film the "
        "ball in more contrast with the platter"
    ),
    "ball_size": (
        "check --ball-radius and --platter-radius, or film the ball in more contrast with the "
        "platter, or give --ball-at U,V"
    ),
}


class _Seen(NamedTuple):
    """What the checks compare: the track's stages, and the ball's positions on the frames
    where it was found (m, on the plane of its centre) at their times (s, the rolling
    shutter's delay added)."""

    cal: Calibration
    paths: Paths
    found: Found
    rim: Ellipse
    rim_pose: Pose
    ball_radius: float
    platter_radius: float
    rpm: float | None
    t: NDArray[np.float64]
    seen: NDArray[np.bool_]
    xy: NDArray[np.float64]
    ts: NDArray[np.float64]

    @property
    def rate(self) -> float:
        return abs(self.cal.omega)


#: A check's result: its value, its limit, whether it passed, and what it says if not.
_Result = tuple[float, Any, bool, str]


def _rate(s: _Seen) -> _Result:
    rpm_seen = s.rate * 30 / math.pi
    if s.rpm is None:
        ok = RATE_RANGE[0] <= s.rate <= RATE_RANGE[1]
        says = f"the mark turns at {rpm_seen:.3g} rpm, not a rate a platter has"
        return s.rate, list(RATE_RANGE), ok, says
    off = s.rate / (s.rpm * math.pi / 30) - 1
    says = f"the mark turns at {rpm_seen:.4g} rpm, not at the given --rpm {s.rpm:g}"
    return off, RPM_AGREE, abs(off) <= RPM_AGREE, says


def _mark_on_circle(s: _Seen) -> _Result:
    rms = s.cal.mark_rms_px
    limit = max(MARK_RMS_PX, 0.5 * math.sqrt(s.found.mark.area / math.pi))
    says = f"the mark's images are {rms:.2g} px (rms) off a circle turning steadily"
    return rms, limit, rms <= limit, says


def _axis(s: _Seen) -> _Result:
    q = camera.back_project(s.rim_pose, s.paths.mark[_mark_seen(s)])
    off = float(np.hypot(*circle_centre(q))) / s.platter_radius
    says = f"the mark's circle is centred {off:.2g} P from the rim's centre"
    return off, AXIS_OFF, off <= AXIS_OFF, says


def _tilt(s: _Seen) -> _Result | None:
    ok = _mark_seen(s)
    span = s.rate * float(np.ptp(s.t[ok])) if ok.sum() > 1 else 0.0
    if span < TILT_TURN or ok.sum() < TILT_FRAMES:
        return None
    e = fit_ellipse(s.paths.mark[ok])
    diff = abs(e.b / e.a - s.rim.b / s.rim.a)
    tilts = [math.degrees(math.acos(min(x, 1.0))) for x in (s.rim.b / s.rim.a, e.b / e.a)]
    says = f"the rim is seen tilted by {tilts[0]:.1f} deg, the mark's circle by {tilts[1]:.1f} deg"
    return diff, TILT_AGREE, diff <= TILT_AGREE, says


def _ball_found(s: _Seen) -> _Result:
    share = float(s.seen.mean())
    says = f"the ball was found on {100 * share:.0f} % of the frames only"
    return share, MIN_FOUND, share >= MIN_FOUND, says


def _ball_moves(s: _Seen) -> _Result:
    z = (s.xy[:, 0] + 1j * s.xy[:, 1]) * np.exp(-1j * s.cal.omega * s.ts)
    spread = float(np.sqrt(np.mean(np.abs(z - z.mean()) ** 2))) / s.ball_radius
    says = (
        f"the ball's path in the platter's frame spreads over {spread:.2g} R only: it turns "
        "with the platter"
    )
    return spread, MIN_SPREAD_R, spread >= MIN_SPREAD_R, says


def _ball_path(s: _Seen) -> _Result:
    jumps, ts, xy = 0.0, s.ts, s.xy
    if len(ts) > 2:
        before, after = ts[1:-1] - ts[:-2], ts[2:] - ts[1:-1]
        w = (before / (before + after))[:, None]
        off = np.hypot(*(xy[1:-1] - ((1 - w) * xy[:-2] + w * xy[2:])).T)
        allowed = JUMP_R * s.ball_radius + 2 * s.rate**2 * s.platter_radius * before * after
        jumps = float(np.mean(off > allowed))
    says = f"the ball jumps on {100 * jumps:.2g} % of the frames"
    return jumps, JUMP_SHARE, jumps <= JUMP_SHARE, says


def _ball_smooth(s: _Seen) -> _Result:
    step = float(np.median(np.diff(s.ts))) if len(s.ts) > 1 else 0.0
    half = max(SMOOTH_S, SMOOTH_FRAMES * step)
    smooth = _scatter(s.ts, s.xy, half) / s.ball_radius
    says = f"the ball's positions scatter by {smooth:.2g} R about a smooth path"
    return smooth, SMOOTH_R, smooth <= SMOOTH_R, says


def _ball_size(s: _Seen) -> _Result:
    ball = s.paths.ball[s.seen]
    predicted = float(np.median(camera.image_radius(s.cal.pose, ball, s.ball_radius)))
    measured = math.sqrt(float(np.nanmedian(s.paths.ball_area)) / math.pi)
    disc = np.zeros(0) if s.paths.ball_disc is None else s.paths.ball_disc[s.seen]
    confirmed = disc.size > 0 and np.mean(np.isfinite(disc)) >= DISC_FRAMES
    if measured < BALL_SIZE[0] * predicted and confirmed and predicted >= DISC_MIN_PX:
        measured = max(measured, float(np.nanmedian(disc)))
    ratio = measured / predicted
    says = (
        f"the ball's image is {2 * measured:.3g} px across, a ball of the given radius there "
        f"would be {2 * predicted:.3g} px"
    )
    return ratio, list(BALL_SIZE), BALL_SIZE[0] <= ratio <= BALL_SIZE[1], says


#: The checks, in the order they are reported (the first that fails names the refusal).
CHECKS: dict[str, Callable[[_Seen], _Result | None]] = {
    "rate": _rate,
    "mark_on_circle": _mark_on_circle,
    "axis": _axis,
    "tilt": _tilt,
    "ball_found": _ball_found,
    "ball_moves": _ball_moves,
    "ball_path": _ball_path,
    "ball_smooth": _ball_smooth,
    "ball_size": _ball_size,
}


def _mark_seen(s: _Seen) -> NDArray[np.bool_]:
    return np.isfinite(s.paths.mark[:, 0])


def _scatter(t: np.ndarray, xy: np.ndarray, half: float) -> float:
    """rms distance of each position (n, 2) at the times ``t`` from the quadratic in time
    fitted to the others within ``half`` of it (positions with neighbours on both sides
    and at least 4 of them)."""
    out = []
    for i in range(len(t)):
        near = np.flatnonzero(np.abs(t - t[i]) <= half)
        near = near[near != i]
        if len(near) < 4 or near[0] > i or near[-1] < i:
            continue
        dt = t[near] - t[i]
        coef = np.linalg.lstsq(np.c_[np.ones_like(dt), dt, dt**2], xy[near], rcond=None)[0]
        out.append(float(np.sum((xy[i] - coef[0]) ** 2)))
    return math.sqrt(np.mean(out)) if out else 0.0


def checks(
    cal: Calibration,
    paths: Paths,
    found: Found,
    rim: Ellipse,
    rim_pose: Pose,
    ball_radius: float,
    platter_radius: float,
    rpm: float | None,
) -> dict[str, dict[str, Any]]:
    """Every check of `CHECKS` that applies: {name: {"value", "limit", "passed", "says"}}."""
    t = paths.t - paths.t[0]
    seen = np.isfinite(paths.ball[:, 0])
    xy = camera.sphere_centre(cal.pose, paths.ball[seen], ball_radius)
    ts = cal.times(t[seen], paths.ball[seen, 1])
    s = _Seen(cal, paths, found, rim, rim_pose, ball_radius, platter_radius, rpm, t, seen, xy, ts)
    out: dict[str, dict[str, Any]] = {}
    for name, check in CHECKS.items():
        result = check(s)
        if result is not None:
            value, limit, passed, says = result
            out[name] = {"value": value, "limit": limit, "passed": bool(passed), "says": says}
    return out


def first_failure(results: dict[str, dict[str, Any]], given: Iterable[str] = ()) -> str | None:
    """One line naming the first check that failed and what would help; None if none.

    A seed's option in ``given`` (``--ball-at``, ``--mark-at``) is not asked for again: the
    help asks for it on the frame where the track goes astray instead.
    """
    for name, r in results.items():
        if not r["passed"]:
            return f"{r['says']}: {_not_again(HELP[name], given)}"
    return None


def _not_again(help_text: str, given: Iterable[str]) -> str:
    for option in given:
        help_text = help_text.replace(
            f"give {option} U,V",
            f"check {option} (--plot draws the track), or give {option} N:U,V too, on the "
            "frame N where it goes astray",
        )
    return help_text
