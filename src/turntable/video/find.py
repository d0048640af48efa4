"""Stage 3, finding the ball and the mark on the first frames.

Everything on the platter whose colour differs from the platter's by more than its grain
(CIELAB distance above ``CONTRAST_NOISE`` times the platter's median one, and at least
``MIN_CONTRAST``) is a candidate, bright or dark, of any hue.  Each candidate is followed over
the first ``PROBE_SECONDS`` of the video and its path seen on the platter's plane through the
camera that the rim alone gives.  What tells them apart is how they move:

- the **mark** turns rigidly with the platter: on a circle about the axis, at least
  ``MARK_MIN_RADIUS`` of P from it, at a constant rate that a platter can have (``RATE_RANGE``,
  or within 5 % of ``--rpm``); of several, the one nearest the rim;
- the **ball** does not; it is round and of the size that R and the rim's scale predict; of
  several, the one that differs most from the platter (not its shadow).

Two candidates that could each be the ball are refused, as is a scene with no mark: the seeds
``--ball-at U,V`` and ``--mark-at U,V`` (pixels of the first frame) then say which is which.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

from turntable.video import camera
from turntable.video.blobs import THRESHOLD, Colour
from turntable.video.camera import Pose
from turntable.video.decode import Picture, VideoError, lab, window
from turntable.video.platter import Platter

try:
    import cv2
except ImportError:  # without the extra [video]
    cv2 = None

#: A candidate differs from the platter by this many times the platter's median distance
#: from its own colour, and by at least ``MIN_CONTRAST`` (CIELAB units).
CONTRAST_NOISE, MIN_CONTRAST = 5.0, 10.0
#: Candidates are followed over this long (s), at least `PROBE_FRAMES` frames.
PROBE_SECONDS, PROBE_FRAMES = 0.3, 10
#: A mark is at least this far from the axis, in units of P.
MARK_MIN_RADIUS = 0.45
#: Rates a platter can turn at, rad/s (3 to 115 rpm).
RATE_RANGE = (0.3, 12.0)
#: The ball's image area within these factors of a ball of radius R's, its axis ratio below
#: `MAX_ELONGATION`.
AREA_RANGE, MAX_ELONGATION = (0.35, 2.8), 2.0
#: A ball's image is a disc (with its shadow, a bulge on it): its region, holes filled, covers
#: at least this share of its convex hull.  A ball's shaded limb and its shadow alone, its lit
#: side of the platter's colour, make a crescent that covers 0.5-0.75.
MIN_SOLIDITY = 0.8
#: Rates of a mark seen in two probe frames agree within this share (a mark seeded where it
#: does not stand out: `_turning_through`).
SEED_RATE_AGREE = 0.15
SEED_HINT = "give the first frame's pixel with --ball-at U,V and --mark-at U,V"


class Candidate(NamedTuple):
    """Something on the platter on the first frame, and what its motion says it is."""

    u: float
    v: float
    area: float
    colour: NDArray[np.float64]
    contrast: float
    elongation: float
    #: the share of its convex hull that it covers, its holes filled
    solidity: float = 1.0
    #: distance from the axis in units of P if it turns rigidly with the platter, else nan
    turns_at: float = math.nan
    #: a part of a larger region, split from it by colour
    split: bool = False
    kind: str = "other"  # "ball", "mark", "other"


class Found(NamedTuple):
    """The ball and the mark on the first frame, with the colour each is followed by."""

    ball: Candidate
    mark: Candidate
    ball_colour: Colour
    mark_colour: Colour
    candidates: list[Candidate]
    #: the rate (rad/s, on the platter's plane, either way) the mark turns at over the
    #: probe, None if not measured
    mark_rate: float | None = None


class _Path:
    """A candidate followed over the probe's frames."""

    def __init__(self, c: Candidate) -> None:
        self.c = c
        self.t: list[float] = []
        self.uv: list[tuple[float, float]] = []

    def predict(self, t: float) -> NDArray:
        """Where it is at time t, if it goes on as in its last step."""
        if len(self.uv) < 2:
            return np.array(self.uv[-1])
        (u0, v0), (u1, v1) = self.uv[-2:]
        t0, t1 = self.t[len(self.uv) - 2], self.t[len(self.uv) - 1]
        return np.array([u1, v1]) + (np.array([u1 - u0, v1 - v0])) * (t - t1) / (t1 - t0)


def _components(lab_img, platter: Platter, allowed, threshold):
    """Components of the pixels farther from the platter's colour than ``threshold``; those
    cut by the edge of ``allowed`` (the platter's side or its shadow beyond a rim fitted a
    pixel too wide) have area 0."""
    dist = np.linalg.norm(lab_img - platter.colour.astype(np.float32), axis=-1)
    mask = ((dist > threshold) & allowed).astype(np.uint8)
    _, labels, stats, centroids = cv2.connectedComponentsWithStats(mask, connectivity=8)
    inside = cv2.erode(allowed.astype(np.uint8), np.ones((3, 3), np.uint8)).astype(bool)
    stats[np.unique(labels[allowed & ~inside]), 4] = 0
    return dist, labels, stats[1:], centroids[1:]


def _parts(lab_img, platter: Platter, allowed, threshold: float, largest: float):
    """The parts of a CIELAB window that differ from the platter: (window of the part's
    box, its mask there, the box's corner (u, v)), the 40 largest components, each larger
    than any ball split by colour (`_split`)."""
    _, labels, stats, _ = _components(lab_img, platter, allowed, threshold)
    for i in np.argsort(-stats[:, 4])[:40]:
        x, y, w, h, area = stats[i]
        if area < 3:
            continue
        region = (labels[y : y + h, x : x + w] == i + 1).astype(np.uint8)
        sub = lab_img[y : y + h, x : x + w]
        for part in _split(sub, region) if area > largest else [region]:
            if part.sum() >= 3:
                yield sub, part, np.array([x, y], float), area > largest


def _candidate(lab_img, region, platter: Platter, origin) -> Candidate | None:
    """A region of a CIELAB window as a candidate: its centroid, area, shape, and the colour
    of its more distinct half (a ball's, not its shadow's)."""
    area = int(region.sum())
    if area < 3:
        return None
    pix = lab_img[region.astype(bool)]
    dist = np.linalg.norm(pix - platter.colour.astype(np.float32), axis=1)
    colour = np.median(pix[dist >= np.median(dist)], axis=0).astype(float)
    v, u = np.nonzero(region)
    return Candidate(
        float(u.mean() + origin[0]),
        float(v.mean() + origin[1]),
        float(area),
        colour,
        float(np.linalg.norm(colour - platter.colour)),
        *_shape(region),
    )


def _split(lab_img, region) -> list[NDArray[np.uint8]]:
    """A region larger than any ball (a ball touching a label, say) split by colour: three
    k-means clusters of its CIELAB colours, each cut into its connected parts."""
    pix = lab_img[region.astype(bool)].astype(np.float32)
    criteria = (cv2.TERM_CRITERIA_EPS + cv2.TERM_CRITERIA_MAX_ITER, 20, 0.5)
    cv2.setRNGSeed(0)
    _, which, _ = cv2.kmeans(pix, 3, None, criteria, 2, cv2.KMEANS_PP_CENTERS)
    cluster = np.full(region.shape, -1, np.int32)
    cluster[region.astype(bool)] = which.ravel()
    parts = []
    for k in range(3):
        n, labels = cv2.connectedComponents((cluster == k).astype(np.uint8), connectivity=8)
        parts += [(labels == i).astype(np.uint8) for i in range(1, n)]
    return parts


def _shape(region: NDArray[np.uint8]) -> tuple[float, float]:
    """Axis ratio of a region, from its second moments, and its solidity (`MIN_SOLIDITY`)."""
    m = cv2.moments(region, binaryImage=True)
    if m["m00"] < 3:
        return 1.0, 1.0
    a, b, c = m["mu20"] / m["m00"], m["mu11"] / m["m00"], m["mu02"] / m["m00"]
    root = math.sqrt(max((a - c) ** 2 + 4 * b * b, 0.0))
    lo, hi = (a + c - root) / 2, (a + c + root) / 2
    contours, _ = cv2.findContours(region, cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_NONE)
    filled = sum(cv2.contourArea(k) + 0.5 * cv2.arcLength(k, True) for k in contours)
    hull = cv2.convexHull(np.concatenate(contours))
    solidity = filled / max(cv2.contourArea(hull) + 0.5 * cv2.arcLength(hull, True), 1.0)
    return math.sqrt(hi / max(lo, 1e-9)), min(solidity, 1.0)


def find(
    probe: list[tuple[float, Picture]],
    platter: Platter,
    pose: Pose,
    ball_radius: float,
    platter_radius: float,
    ball_at: tuple[float, float] | None = None,
    mark_at: tuple[float, float] | None = None,
    rpm: float | None = None,
) -> Found:
    """The ball and the mark (see the module's docstring).

    Parameters
    ----------
    probe : list of (float, Picture)
        The first frames and their times (s).
    platter : Platter
    pose : Pose
        The camera that the rim alone gives (for the candidates' paths on the plane).
    ball_radius, platter_radius : float
        R and P, m.
    ball_at, mark_at : tuple of float, optional
        Seeds: pixels (u, v) of the first frame on or next to the ball and the mark.
    rpm : float, optional
        The platter's rate as given.

    Raises
    ------
    VideoError
        No ball, two possible balls, no mark, or a seed with nothing there; its ``found``
        holds the candidates.
    """
    rim = platter.rim
    shape = probe[0][1].shape
    allowed = rim.mask(shape, 1.0 - 3.0 / rim.b)
    box = window(rim.centre, rim.a + 3, shape)
    origin = np.array([box[1].start, box[0].start], float)
    lab0 = lab(probe[0][1], box)
    ring = (rim.mask(shape, 0.9) & ~rim.mask(shape, 0.35))[box]
    noise = float(np.median(np.linalg.norm(lab0[ring] - platter.colour.astype(np.float32), axis=1)))
    threshold = max(CONTRAST_NOISE * noise, MIN_CONTRAST)
    largest = AREA_RANGE[1] * _area_at(pose, rim.centre, ball_radius)
    paths = []
    for sub, part, corner, split in _parts(lab0, platter, allowed[box], threshold, largest):
        c = _candidate(sub, part, platter, origin + corner)
        if c is not None:
            c = c._replace(split=split)
            paths.append(_Path(c))
            paths[-1].t.append(probe[0][0])
            paths[-1].uv.append((c.u, c.v))
    seeded = {}
    for option, at in (("--ball-at", ball_at), ("--mark-at", mark_at)):
        if at is not None:
            seeded[option] = len(paths)
            c = _seeded(lab0, origin, platter, at, 4 * math.sqrt(_area_at(pose, at, ball_radius)))
            if c is None:
                raise VideoError(
                    f"{option} {at[0]:g},{at[1]:g}: nothing there differs from the platter; "
                    "--plot shows the candidates",
                    [p.c for p in paths],
                )
            paths.append(_Path(c))
            paths[-1].t.append(probe[0][0])
            paths[-1].uv.append((c.u, c.v))
    seen = []
    for t, picture in probe[1:]:
        found = [
            (*(np.argwhere(part)[:, ::-1].mean(axis=0) + origin + corner), part.sum())
            for _, part, corner, _ in _parts(
                lab(picture, box), platter, allowed[box], threshold, largest
            )
        ]
        st = np.array(found, float).reshape(-1, 3)
        cen, areas = st[:, :2], st[:, 2]
        seen.append((t, cen, areas))
        for p in paths:
            if len(p.uv) < len(p.t):
                continue  # lost: not followed further
            near = p.predict(t)
            step = float(np.hypot(*(near - p.uv[-1])))
            if len(p.uv) == 1:  # as far as the fastest platter would take it
                arm = float(np.hypot(p.c.u - rim.centre[0], p.c.v - rim.centre[1]))
                step = RATE_RANGE[1] * arm * (t - p.t[0])
            gate = 3.0 + 1.5 * math.sqrt(p.c.area / math.pi) + step
            d = np.hypot(cen[:, 0] - near[0], cen[:, 1] - near[1])
            ok = (d < gate) & (areas > 0.3 * p.c.area) & (areas < 3.3 * p.c.area)
            if ok.any():
                j = int(np.argmin(np.where(ok, d, np.inf)))
                p.uv.append((float(cen[j, 0]), float(cen[j, 1])))
            p.t.append(t)
    planes = [_on_plane(p, len(probe), pose) for p in paths]
    candidates = [p.c for p in paths]
    tolerance = max(0.15 * ball_radius, 1.5 * platter_radius / rim.a)
    marks = []
    for i, plane in enumerate(planes):
        if plane is None:
            continue
        rate, centre, residual = _turning(*plane)
        ok = RATE_RANGE[0] <= abs(rate) <= RATE_RANGE[1]
        if rpm is not None:
            ok = abs(abs(rate) / (rpm * math.pi / 30) - 1) < 0.05
        if residual < tolerance and ok and abs(centre) > 0.05 * platter_radius:
            candidates[i] = candidates[i]._replace(turns_at=abs(centre) / platter_radius)
            marks.append((i, rate))
    if mark_at is not None:
        m = seeded["--mark-at"]
        rate = dict(marks).get(m)
        turning = None
        if rate is None:
            turning = _turning_through(candidates[m], probe[0][0], seen, pose, tolerance, rpm)
        if turning is not None:
            rate = turning[0]
            candidates[m] = candidates[m]._replace(area=turning[1])
        marks = [(m, rate)]
    else:
        marks = sorted(
            ((i, w) for i, w in marks if candidates[i].turns_at >= MARK_MIN_RADIUS),
            key=lambda iw: -candidates[iw[0]].turns_at,
        )
    if not marks:
        raise VideoError(
            "no mark found on the platter: nothing near the rim turns with it at a rate a "
            f"platter can have; put a small mark near the rim, in contrast with the platter, or "
            f"{SEED_HINT}",
            candidates,
        )
    for m, rate in marks:
        # the ball does not turn with the platter: not rigidly at the mark's rate
        rigid = [
            rate is not None and planes[i] is not None and _turning(*planes[i], rate)[2] < tolerance
            for i in range(len(candidates))
        ]
        others = [c if i != m and not rigid[i] else None for i, c in enumerate(candidates)]
        ball = seeded.get("--ball-at")
        # of those followed over the probe and whole, if any, else split, else all
        for keep in (
            lambda i, c: planes[i] is not None and not c.split,
            lambda i, c: planes[i] is not None,
            lambda i, c: True,
        ):
            if ball is None:
                chosen = [c if c is not None and keep(i, c) else None for i, c in enumerate(others)]
                ball = _choose_ball(chosen, pose, ball_radius)
        if ball is not None:
            break
    if ball is None:
        expected = _area_at(pose, pose.principal, ball_radius)
        raise VideoError(
            f"no ball found on the first frame: nothing round of about {expected:.0f} px (a ball "
            "of the given radius at the rim's scale) differs from the platter and moves on its "
            f"own; check --ball-radius and --platter-radius, or {SEED_HINT}",
            candidates,
        )
    candidates[ball] = candidates[ball]._replace(kind="ball")
    candidates[m] = candidates[m]._replace(kind="mark")
    return Found(
        candidates[ball],
        candidates[m],
        Colour(candidates[ball].colour, platter.colour),
        Colour(candidates[m].colour, platter.colour),
        candidates,
        None if rate is None else abs(rate),
    )


def _on_plane(p: _Path, frames: int, pose: Pose) -> tuple[NDArray, NDArray] | None:
    """A candidate's times and positions on the platter's plane (x + i y), if it was followed
    over most of the probe."""
    if len(p.uv) < max(0.6 * frames, 3):
        return None
    q = camera.back_project(pose, np.array(p.uv))
    return np.array(p.t[: len(p.uv)]), q[:, 0] + 1j * q[:, 1]


def _turning(t: NDArray, z: NDArray, rate: float | None = None) -> tuple[float, complex, float]:
    """The uniform turning about the axis nearest a path: its rate (fitted unless given), the
    position at t = 0 and the rms distance of the path from it."""
    if rate is None:
        rate = float(np.polyfit(t, np.unwrap(np.angle(z)), 1)[0])
    c = complex(np.mean(z * np.exp(-1j * rate * t)))
    return rate, c, float(np.sqrt(np.mean(np.abs(z - c * np.exp(1j * rate * t)) ** 2)))


def _turning_through(c: Candidate, t0: float, seen, pose: Pose, tolerance: float, rpm):
    """What turns out of a seeded region that does not itself turn (a mark seeded inside a
    lamp's bright spot, which stays where it is): the rate of a platter (rad/s) that the
    most probe frames agree on (within `SEED_RATE_AGREE`), from the blobs of no more than
    the region's size at the seed's distance from the axis, and their median area; None if
    fewer than half of the frames agree.  ``seen`` holds, for each frame after the first,
    its time, the blobs' centres (n, 2) and their areas."""
    z0 = complex(*camera.back_project(pose, np.array([[c.u, c.v]]))[0])
    rates, sizes, frames = [], [], []
    for k, (t, cen, areas) in enumerate(seen):
        small = areas <= 1.5 * c.area
        q = camera.back_project(pose, cen[small]).reshape(-1, 2)
        z = q[:, 0] + 1j * q[:, 1]
        near = np.abs(np.abs(z) - abs(z0)) < 2 * tolerance
        rates += list(np.angle(z[near] / z0) / (t - t0))
        sizes += list(areas[small][near])
        frames += [k] * int(near.sum())
    low, high = (
        RATE_RANGE if rpm is None else (0.95 * rpm * math.pi / 30, 1.05 * rpm * math.pi / 30)
    )
    best, agree = None, []
    for w in rates:
        if low <= abs(w) <= high:
            near_w = [i for i, x in enumerate(rates) if abs(x / w - 1) < SEED_RATE_AGREE]
            if len({frames[i] for i in near_w}) > len({frames[i] for i in agree}):
                best, agree = w, near_w
    if len({frames[i] for i in agree}) < len(seen) / 2:
        return None
    return best, float(np.median([sizes[i] for i in agree]))


def _area_at(pose: Pose, uv: tuple[float, float], ball_radius: float) -> float:
    """Area (px) of the image of a ball of radius R seen at ``uv``."""
    return math.pi * float(camera.image_radius(pose, [uv], ball_radius)[0]) ** 2


def _seeded(lab_img, origin, platter: Platter, at, reach: float) -> Candidate | None:
    """The candidate at a seed: the pixels about it nearer its colour than the platter's."""
    u, v = round(at[0] - origin[0]), round(at[1] - origin[1])
    h, w = lab_img.shape[:2]
    if not (2 <= u < w - 2 and 2 <= v < h - 2):
        return None
    colour = np.median(lab_img[v - 2 : v + 3, u - 2 : u + 3].reshape(-1, 3), axis=0).astype(float)
    contrast = float(np.linalg.norm(colour - platter.colour))
    if contrast < MIN_CONTRAST:
        return None
    box = window((u, v), reach, (h, w))
    share = Colour(colour, platter.colour).share(lab_img[box])
    _, labels, stats, centroids = cv2.connectedComponentsWithStats(
        (share > THRESHOLD).astype(np.uint8), connectivity=8
    )
    i = labels[v - box[0].start, u - box[1].start]
    if i == 0:
        return None
    region = (labels == i).astype(np.uint8)
    pix = lab_img[box][region.astype(bool)]
    return Candidate(
        float(centroids[i][0] + box[1].start + origin[0]),
        float(centroids[i][1] + box[0].start + origin[1]),
        float(stats[i][4]),
        np.median(pix, axis=0).astype(float),
        contrast,
        *_shape(region),
    )


def _choose_ball(others, pose, ball_radius) -> int | None:
    """The ball among the candidates that do not turn with the platter (None elsewhere)."""
    ok = [
        i
        for i, c in enumerate(others)
        if c is not None
        and AREA_RANGE[0] < c.area / _area_at(pose, (c.u, c.v), ball_radius) < AREA_RANGE[1]
        and c.elongation < MAX_ELONGATION
        and c.solidity >= MIN_SOLIDITY
    ]
    if not ok:
        return None
    ok.sort(key=lambda i: -others[i].contrast)
    if len(ok) > 1:
        a, b = others[ok[0]], others[ok[1]]
        if b.contrast > 0.8 * a.contrast and b.area > 0.6 * a.area:
            raise VideoError(
                f"two things could be the ball, at ({a.u:.0f}, {a.v:.0f}) and ({b.u:.0f}, "
                f"{b.v:.0f}) px: give the ball's pixel of the first frame with --ball-at U,V",
                [c for c in others if c is not None],
            )
    return ok[0]
