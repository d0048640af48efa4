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
from collections.abc import Iterable
from typing import Any

import numpy as np

from turntable.video import camera
from turntable.video.calibrate import Calibration
from turntable.video.camera import Pose
from turntable.video.find import RATE_RANGE, Found
from turntable.video.follow import Paths
from turntable.video.platter import Ellipse, fit_ellipse

#: The mark's images within this many px (rms) of the fitted circle, or half its size.
MARK_RMS_PX = 2.0
#: The ball's scatter about its smooth path: the limit (rms, in R) and the half-window (s).
SMOOTH_R, SMOOTH_S = 0.06, 0.05
#: The share of the frames the ball must be found on (on good tracks, at most a third are
#: gaps: where it passes the mark or runs into a label of its colour).
MIN_FOUND = 0.5
#: The ball's image radius over the one R and the camera predict: 0.89-1.17 on good tracks of
#: MuJoCo's scenes; 0.77 where a small white ball's shaded limb, darker than the platter, was
#: left out and its centre taken from its lit side.
BALL_SIZE = (0.8, 1.4)
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


def _circle_centre(xy: np.ndarray) -> np.ndarray:
    """Centre of the least-squares circle through points (Kasa's algebraic fit)."""
    a = np.c_[2 * xy, np.ones(len(xy))]
    sol = np.linalg.lstsq(a, (xy**2).sum(axis=1), rcond=None)[0]
    return sol[:2]


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
    """Every check: {name: {"value", "limit", "passed", "says"}}."""
    out: dict[str, dict[str, Any]] = {}
    t = paths.t - paths.t[0]

    def put(name: str, value: float, limit: Any, passed: bool, says: str) -> None:
        out[name] = {"value": value, "limit": limit, "passed": bool(passed), "says": says}

    rate = abs(cal.omega)
    rpm_seen = rate * 30 / math.pi
    if rpm is None:
        put(
            "rate",
            rate,
            list(RATE_RANGE),
            RATE_RANGE[0] <= rate <= RATE_RANGE[1],
            f"the mark turns at {rpm_seen:.3g} rpm, not a rate a platter has",
        )
    else:
        off = rate / (rpm * math.pi / 30) - 1
        put(
            "rate",
            off,
            0.01,
            abs(off) <= 0.01,
            f"the mark turns at {rpm_seen:.4g} rpm, not at the given --rpm {rpm:g}",
        )
    r_mark = math.sqrt(found.mark.area / math.pi)
    limit = max(MARK_RMS_PX, 0.5 * r_mark)
    put(
        "mark_on_circle",
        cal.mark_rms_px,
        limit,
        cal.mark_rms_px <= limit,
        f"the mark's images are {cal.mark_rms_px:.2g} px (rms) off a circle turning steadily",
    )
    ok = np.isfinite(paths.mark[:, 0])
    q = camera.back_project(rim_pose, paths.mark[ok])
    off = float(np.hypot(*_circle_centre(q))) / platter_radius
    put(
        "axis",
        off,
        0.03,
        off <= 0.03,
        f"the mark's circle is centred {off:.2g} P from the rim's centre",
    )
    span = rate * float(np.ptp(t[ok])) if ok.sum() > 1 else 0.0
    if span >= math.pi and ok.sum() >= 10:
        e = fit_ellipse(paths.mark[ok])
        diff = abs(e.b / e.a - rim.b / rim.a)
        tilts = [math.degrees(math.acos(min(x, 1.0))) for x in (rim.b / rim.a, e.b / e.a)]
        put(
            "tilt",
            diff,
            0.03,
            diff <= 0.03,
            f"the rim is seen tilted by {tilts[0]:.1f} deg, the mark's circle by "
            f"{tilts[1]:.1f} deg",
        )
    seen = np.isfinite(paths.ball[:, 0])
    share = float(seen.mean())
    put(
        "ball_found",
        share,
        MIN_FOUND,
        share >= MIN_FOUND,
        f"the ball was found on {100 * share:.0f} % of the frames only",
    )
    xy = camera.sphere_centre(cal.pose, paths.ball[seen], ball_radius)
    ts = cal.times(t[seen], paths.ball[seen, 1])
    z = (xy[:, 0] + 1j * xy[:, 1]) * np.exp(-1j * cal.omega * ts)
    spread = float(np.sqrt(np.mean(np.abs(z - z.mean()) ** 2))) / ball_radius
    put(
        "ball_moves",
        spread,
        0.5,
        spread >= 0.5,
        f"the ball's path in the platter's frame spreads over {spread:.2g} R only: it turns "
        "with the platter",
    )
    jumps = 0.0
    if len(ts) > 2:
        before, after = ts[1:-1] - ts[:-2], ts[2:] - ts[1:-1]
        w = (before / (before + after))[:, None]
        off = np.hypot(*(xy[1:-1] - ((1 - w) * xy[:-2] + w * xy[2:])).T)
        allowed = 0.25 * ball_radius + 2 * rate**2 * platter_radius * before * after
        jumps = float(np.mean(off > allowed))
    put(
        "ball_path",
        jumps,
        0.02,
        jumps <= 0.02,
        f"the ball jumps on {100 * jumps:.2g} % of the frames",
    )
    step = float(np.median(np.diff(ts))) if len(ts) > 1 else 0.0
    smooth = _scatter(ts, xy, max(SMOOTH_S, 2.5 * step)) / ball_radius
    put(
        "ball_smooth",
        smooth,
        SMOOTH_R,
        smooth <= SMOOTH_R,
        f"the ball's positions scatter by {smooth:.2g} R about a smooth path",
    )
    predicted = float(np.median(camera.image_radius(cal.pose, paths.ball[seen], ball_radius)))
    measured = math.sqrt(float(np.nanmedian(paths.ball_area)) / math.pi)
    ratio = measured / predicted
    put(
        "ball_size",
        ratio,
        list(BALL_SIZE),
        BALL_SIZE[0] <= ratio <= BALL_SIZE[1],
        f"the ball's image is {2 * measured:.3g} px across, a ball of the given radius there "
        f"would be {2 * predicted:.3g} px",
    )
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
