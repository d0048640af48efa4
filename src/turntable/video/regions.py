"""What on the platter differs from it: the regions of a CIELAB window farther from the
platter's colour than a threshold, split by colour where larger than any ball, as candidates
for the ball and the mark (`turntable.video.find`), with their shapes.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

from turntable.video import camera
from turntable.video.blobs import THRESHOLD
from turntable.video.camera import Pose
from turntable.video.colours import Colour
from turntable.video.decode import window
from turntable.video.platter import Platter

try:
    import cv2
except ImportError:  # without the extra [video]
    cv2 = None

#: A candidate differs from the platter by this much at least (CIELAB units).
MIN_CONTRAST = 10.0
#: At most this many components are candidates (the largest), each of at least
#: ``MIN_AREA_PX`` px.
MAX_PARTS, MIN_AREA_PX = 40, 3
#: The ball's image area within these factors of a ball of radius R's, its axis ratio below
#: `MAX_ELONGATION`.
AREA_RANGE, MAX_ELONGATION = (0.35, 2.8), 2.0
#: A ball's image is a disc (with its shadow, a bulge on it): its region, holes filled, covers
#: at least this share of its convex hull.  A ball's shaded limb and its shadow alone, its lit
#: side of the platter's colour, make a crescent that covers 0.5-0.75.
MIN_SOLIDITY = 0.8
#: A ball's region covers at least this share of its outline's inside: a highlight is a small
#: hole in it (0.94-1.00 on the balls of the benchmark's scenes).  The thin ring of a label's
#: edge, split from the label by colour, covers less than a tenth of the label; a steel ball
#: on a light grey platter, its lit side of the platter's grey, leaves its shaded limb as a
#: ring that covers 0.58 (a ball of nearly the platter's colour, which the guide rules out).
MIN_FILL = 0.8
#: A seed's colour is the median of the (2 ``SEED_PATCH`` + 1) px square about it.
SEED_PATCH = 2


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
    #: the share of its outline's inside that it covers (a ring about a label covers little)
    fill: float = 1.0
    #: distance from the axis in units of P if it turns rigidly with the platter, else nan
    turns_at: float = math.nan
    #: a part of a larger region, split from it by colour
    split: bool = False
    kind: str = "other"  # "ball", "mark", "other"


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
    for i in np.argsort(-stats[:, 4])[:MAX_PARTS]:
        x, y, w, h, area = stats[i]
        if area < MIN_AREA_PX:
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


def _split(lab_img, region, clusters: int = 3) -> list[NDArray[np.uint8]]:
    """A region larger than any ball (a ball touching a label, say) split by colour:
    ``clusters`` k-means clusters of its CIELAB colours, each cut into its connected parts."""
    pix = lab_img[region.astype(bool)].astype(np.float32)
    if len(pix) < clusters:
        return []
    criteria = (cv2.TERM_CRITERIA_EPS + cv2.TERM_CRITERIA_MAX_ITER, 20, 0.5)
    cv2.setRNGSeed(0)
    _, which, _ = cv2.kmeans(pix, clusters, None, criteria, 2, cv2.KMEANS_PP_CENTERS)
    cluster = np.full(region.shape, -1, np.int32)
    cluster[region.astype(bool)] = which.ravel()
    parts = []
    for k in range(clusters):
        n, labels = cv2.connectedComponents((cluster == k).astype(np.uint8), connectivity=8)
        parts += [(labels == i).astype(np.uint8) for i in range(1, n)]
    return parts


def _shape(region: NDArray[np.uint8]) -> tuple[float, float, float]:
    """Axis ratio of a region, from its second moments, its solidity (the share of its
    convex hull it covers, its holes filled: `MIN_SOLIDITY`) and the
    share of its outline's inside it covers (`MIN_FILL`)."""
    m = cv2.moments(region, binaryImage=True)
    if m["m00"] < 3:
        return 1.0, 1.0, 1.0
    a, b, c = m["mu20"] / m["m00"], m["mu11"] / m["m00"], m["mu02"] / m["m00"]
    root = math.sqrt(max((a - c) ** 2 + 4 * b * b, 0.0))
    lo, hi = (a + c - root) / 2, (a + c + root) / 2
    contours, _ = cv2.findContours(region, cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_NONE)
    filled = sum(cv2.contourArea(k) + 0.5 * cv2.arcLength(k, True) for k in contours)
    hull = cv2.convexHull(np.concatenate(contours))
    solidity = filled / max(cv2.contourArea(hull) + 0.5 * cv2.arcLength(hull, True), 1.0)
    fill = m["m00"] / max(filled, 1.0)
    return math.sqrt(hi / max(lo, 1e-9)), min(solidity, 1.0), min(fill, 1.0)


def _seeded(
    lab_img, origin, platter: Platter, at, reach: float, largest: float = math.inf
) -> Candidate | None:
    """The candidate at a seed: the pixels about it nearer its colour than the platter's.  A
    region of more than ``largest`` px (a ball beside a label of a like colour, their pixels
    one region) is split by colour as the unseeded search splits it (`_split`), and the part
    at the seed taken."""
    u, v = round(at[0] - origin[0]), round(at[1] - origin[1])
    h, w = lab_img.shape[:2]
    if not (SEED_PATCH <= u < w - SEED_PATCH and SEED_PATCH <= v < h - SEED_PATCH):
        return None
    k = SEED_PATCH
    colour = np.median(lab_img[v - k : v + k + 1, u - k : u + k + 1].reshape(-1, 3), axis=0)
    colour = colour.astype(float)
    contrast = float(np.linalg.norm(colour - platter.colour))
    if contrast < MIN_CONTRAST:
        return None
    box = window((u, v), reach, (h, w))
    share = Colour(colour, platter.colour).share(lab_img[box])
    _, labels, stats, _ = cv2.connectedComponentsWithStats(
        (share > THRESHOLD).astype(np.uint8), connectivity=8
    )
    i = labels[v - box[0].start, u - box[1].start]
    if i == 0:
        return None
    region = (labels == i).astype(np.uint8)
    split = bool(stats[i][4] > largest)
    if split:
        at_seed = (v - box[0].start, u - box[1].start)
        region = next((r for r in _split(lab_img[box], region) if r[at_seed]), region)
    pix = lab_img[box][region.astype(bool)]
    vv, uu = np.nonzero(region)
    return Candidate(
        float(uu.mean() + box[1].start + origin[0]),
        float(vv.mean() + box[0].start + origin[1]),
        float(region.sum()),
        np.median(pix, axis=0).astype(float),
        contrast,
        *_shape(region),
        split=split,
    )


def _ball_shaped(c: Candidate) -> bool:
    """Round and whole as a ball's image is (`MAX_ELONGATION`, `MIN_SOLIDITY`, `MIN_FILL`)."""
    return c.elongation < MAX_ELONGATION and c.solidity >= MIN_SOLIDITY and c.fill >= MIN_FILL


def _area_at(pose: Pose, uv: tuple[float, float], ball_radius: float) -> float:
    """Area (px^2) of the image of a ball of radius R seen at ``uv``."""
    return math.pi * float(camera.image_radius(pose, [uv], ball_radius)[0]) ** 2


def _a_ball(c: Candidate, pose: Pose, ball_radius: float) -> bool:
    """Of a ball's area where it lies (`AREA_RANGE`) and of its shape (`_ball_shaped`)."""
    area = c.area / _area_at(pose, (c.u, c.v), ball_radius)
    return AREA_RANGE[0] < area < AREA_RANGE[1] and _ball_shaped(c)
