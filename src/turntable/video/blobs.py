"""Blobs of one colour on the platter: where a window of a picture lies nearer a target's
colour than the platter's, as components with their centres to a fraction of a pixel.

A pixel's *share* is its CIELAB colour's step from the platter's towards the target's,
as a fraction of the whole step: 0 on the platter, 1 on the target.  A blob is a connected
component of shares above ``THRESHOLD`` (a shadow, a groove or the platter's grain stays below
it), its holes filled (a highlight).  Its centre weighs each pixel of the filled blob by 1,
and each pixel of the one-pixel band about it by the part of it the blob covers: its share
ramped from 0 at ``FLOOR`` to 1 at 1 - ``FLOOR`` (1/2 at 1/2), so that neither the shading of a
ball nor a shadow beside it (a share below ``FLOOR``) pulls the centre aside.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

from turntable.video import chroma, hue, ring
from turntable.video import limb as limb_module
from turntable.video.colours import OFF_LINE, Colour, Colours
from turntable.video.decode import Picture, lab
from turntable.video.rays import along_rays
from turntable.video.robust import circle_centre, inliers

try:
    import cv2
except ImportError:  # without the extra [video]
    cv2 = None

#: A pixel belongs to a blob where its share is above this.
THRESHOLD = 0.45
#: In the band about a blob, the share below which a pixel does not count.
FLOOR = 0.25

#: Outline points farther than this (px) from the fitted circle are left out.
EDGE_OFF = 1.0
#: ... and those farther than this many spreads (`turntable.video.robust.inliers`) from the
#: others, the spread at least ``EDGE_FLOOR`` px (an outline to a tenth of a pixel is not cut
#: finer), over at most ``EDGE_ROUNDS`` fits.
EDGE_SPREADS, EDGE_FLOOR, EDGE_ROUNDS = 3.0, 0.1, 6
#: An outline is a fall to a share below this (2 px beyond it): not the edge of a highlight.
BELOW = 0.75
#: A ray whose share rises again by this share of a clear fall's depth within 2 px beyond its
#: fall has no say in the outline.
RISE = 0.15
#: The outline is where the share crosses half-way down its fall, unless that is farther than
#: this (px) from the fall's steepest point (two falls run together): then the steepest point.
HALF_WAY = 0.5
#: Rays are sampled every ``RAY_STEP`` px, from ``RAY_FROM`` to ``RAY_TO`` times the radius
#: (and 3 px more): the outline of a ball whose predicted size is off by a third lies on them.
RAY_STEP, RAY_FROM, RAY_TO = 0.25, 0.3, 1.7
#: What lies within this (px) beyond a fall tells a fall to the platter (`BELOW`) from one
#: off a highlight, and a shaded limb (`RISE`).
BEYOND_PX = 2
#: A fall counts where it is at least ``STEEP`` of the ray's steepest, and that at least
#: ``MIN_FALL`` (share per px): the grain of the platter falls less.
STEEP, MIN_FALL = 0.5, 0.1
#: The clearest falls' depth is this percentile of the falls'; a fall shallower than
#: ``1 / SHALLOW`` of it weighs in proportion.
CLEAR_PERCENTILE, SHALLOW = 90, 2.0
#: A blob is taken as round, and centred by its outline, where its area is within these
#: factors of the circle's.
ROUND_AREA = (0.4, 2.5)
#: A ball in a blob of a like colour (`merged_ball`): found by this many outline points at
#: least (half of the rays), within this share of the radius of where it is predicted.
MERGED_POINTS, MERGED_REACH = 24, 0.25
#: A ball whose blob runs into something of another colour that its share does not tell from
#: it (an orange ball on a red label, both far from a grey platter's colour on the line to the
#: ball's): that thing is what of the blob lies beyond ``AROUND`` of the ball's radii from
#: where it is predicted, at least ``AROUND_MIN`` of the ball's image area; its colour is
#: told from the ball's where they differ by ``AROUND_CONTRAST`` (CIELAB) at least (a
#: label of the ball's own colour is not: the ball is not seen on it).
AROUND, AROUND_MIN, AROUND_CONTRAST = 1.5, 0.25, 10.0
#: A ball whose hard shadow merges into its blob (a black ball on a light platter): the
#: outline's points on the shadow's far edge pull the least-squares circle aside.  The circle
#: of the ball's radius through the most of the outline's weight within ``ARC_PX`` px (tried
#: through each pair of points at least ``ARC_CHORD`` radii apart: nearer pairs fix no centre)
#: is taken instead where it carries ``ARC_GAIN`` times the weight the least-squares circle
#: carries within ``ARC_PX`` and at least ``ARC_MIN`` of all the weight (the half of the
#: outline that borders the platter): a ball of another size than the one predicted lies on
#: no such arc, and is left to ``ball_size``.  The rays are cast again from the arc's centre
#: (from the blob's centroid, pulled into the shadow, fewer of them reach the ball's free
#: edge: there the arc need carry ``ARC_FIRST`` of the weight only).
ARC_PX, ARC_CHORD, ARC_GAIN, ARC_MIN, ARC_FIRST = 1.0, 1.0, 1.25, 0.5, 0.3
#: An arc's circle is the ball's only where the share falls outward across it, by at
#: least ``ARC_STEP``, on ``ARC_EDGE`` of the rays (sampled ``ARC_ACROSS`` px either side):
#: on the shadow's side too, from the ball into its lighter shadow.  About the far end of a
#: shadow it rises into the ball, or stays level in the shadow; a shadow as dark as the ball
#: shows no edge, and no check can tell them apart.  A ray across the ball's shaded limb,
#: darker than the platter (`turntable.video.limb`), confirms it too.
ARC_STEP, ARC_EDGE, ARC_ACROSS = 0.05, 0.9, 1.5
#: No arc is taken for an image of the ball smaller than this radius (px): there ``ARC_PX`` and
#: ``ARC_ACROSS`` are so large a share of it that a ball of 1.5 times the radius given (a
#: wrong --ball-radius) passed, and its track jumped; ``ball_size`` refuses it.
ARC_MIN_PX = 8.0

#: Looked at again (``turntable.video.hue``), the fit begins with the points within this
#: (px) of the circle found.
AGAIN_PX = 2.0

_KERNEL = np.ones((3, 3), np.uint8)


class Blob(NamedTuple):
    """A blob: centre (u, v) and area (filled, weighted) in px; whether it touches a pixel
    outside the allowed region or the window's cut by the image's edge; whether it runs out
    of the window (its area and centre are then not its own); the radius (px) of the ball's
    part, lit or shaded, in the circle through its outline where that circle is confirmed
    all round (`turntable.video.limb.disc_radius`), else nan; whether its centre is that of a
    circle through its outline (not its centroid, the outline not found)."""

    u: float
    v: float
    area: float
    touches: bool
    cut: bool = False
    disc: float = math.nan
    outlined: bool = False


def blobs(
    picture: Picture,
    box: tuple[slice, slice],
    colour: Colour | Colours,
    allowed: NDArray[np.bool_],
    threshold: float = THRESHOLD,
    outline: float = 0.0,
) -> list[Blob]:
    """The blobs of ``colour`` in the window ``box`` of ``picture`` (only ``allowed`` pixels).

    With ``outline`` (a radius, px), a round blob's centre is that of the circle of that
    radius through its outline (`outline_centre`) instead of its weighted centroid; where
    that circle borders something of another hue (a red label under a green ball), the
    outline there is found again on the step from that thing's colour to the ball's
    (`_on_other_hue`).
    """
    if box[0].stop - box[0].start < 3 or box[1].stop - box[1].start < 3:
        return []  # a window off the image
    lab_img = lab(picture, box)
    share = colour.share(lab_img)
    ok = allowed[box]
    mask = ((share > threshold) & ok).astype(np.uint8)
    n, labels, stats, _ = cv2.connectedComponentsWithStats(mask, connectivity=8)
    v0, u0 = box[0].start, box[1].start
    height, width = picture.y.shape
    out = []
    for i in range(1, n):
        x, y, w, h, _area = stats[i]
        sl = (
            slice(max(y - 2, 0), min(y + h + 2, mask.shape[0])),
            slice(max(x - 2, 0), min(x + w + 2, mask.shape[1])),
        )
        region = (labels[sl] == i).astype(np.uint8)
        contours, _ = cv2.findContours(region, cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_NONE)
        filled = np.zeros_like(region)
        cv2.drawContours(filled, contours, -1, 1, -1)
        band = cv2.dilate(filled, _KERNEL).astype(bool) & ~filled.astype(bool)
        covered = np.clip((share[sl] - FLOOR) / (1 - 2 * FLOOR), 0.0, 1.0)
        wt = filled.astype(np.float32) + band * covered
        total = float(wt.sum())
        if total <= 0:
            continue
        vv, uu = np.mgrid[sl[0], sl[1]]
        touches = (
            bool((band & ~ok[sl]).any())
            or (x == 0 and u0 == 0)
            or (y == 0 and v0 == 0)
            or (x + w + u0 >= width)
            or (y + h + v0 >= height)
        )
        centre = np.array([(wt * uu).sum(), (wt * vv).sum()]) / total
        disc, outlined = math.nan, False
        if outline and ROUND_AREA[0] < total / (math.pi * outline**2) < ROUND_AREA[1]:
            edge = colour.edge_share(lab_img, share)
            found, arc = _outline(edge, centre, outline, centre, local=(lab_img, colour))
            outlined = found is not centre
            centre = ring.edge_centre(edge, found, outline, found)
            if arc:  # its shadow left out: the blob's weight within the ball's circle
                total = float(wt[np.hypot(uu - centre[0], vv - centre[1]) < outline + ARC_PX].sum())
            if _round(edge, centre, outline, 48, limb=True):
                disc = limb_module.disc_radius(edge, centre, outline, threshold)
        cut = x == 0 or y == 0 or x + w >= mask.shape[1] or y + h >= mask.shape[0]
        u, v = float(centre[0]) + u0, float(centre[1]) + v0
        out.append(Blob(u, v, total, touches, cut, disc, outlined))
    return out


def merged_ball(
    picture: Picture,
    box: tuple[slice, slice],
    colour: Colour | Colours,
    near: NDArray,
    radius: float,
) -> Blob | None:
    """A ball whose blob runs into something of a like colour (a label it crosses): its
    centre from the outline about ``near`` where half of the rays find it (the half that
    borders the platter, at least), within R / 4 of ``near``; None if not.  The rays that end
    on another hue are looked at again (`_on_other_hue`), and a ray into another colour
    confirms the circle through an arc (a cream ring touching a white ball: `_round`).  Where
    the share does not tell the ball from what it runs into (a red label under an orange
    ball), the ball's colour is told from that thing's (`_told_from_around`), and then, on the
    rays that end on it, by chromaticity (a red ball by a salmon label: `video.chroma`)."""
    lab_img = lab(picture, box)
    start = np.array([near[0] - box[1].start, near[1] - box[0].start])
    h, w = lab_img.shape[:2]
    if not (0 <= start[0] < w and 0 <= start[1] < h):
        return None
    share = colour.share(lab_img)
    if share[int(start[1]), int(start[0])] < THRESHOLD:
        return None
    edge = colour.edge_share(lab_img, share)
    # a ring of a like share touching a ball of one colour is of another; a ball of two, shaded,
    # is of neither of its own (a two-tone ball: 0.037 -> 0.041 R with them)
    seen = (lab_img, colour.targets) if isinstance(colour, Colour) else None
    centre = _outline(edge, start, radius, None, 48, MERGED_POINTS, (lab_img, colour), seen)[0]
    told = None
    if centre is None:
        told = _told_from_around(lab_img, share, edge, colour, start, radius)
    if told is not None:
        centre = outline_centre(told[0], start, radius, None, min_points=MERGED_POINTS)
    if centre is None and told is not None:  # a label of the ball's hue, paler
        label = chroma.on_label(share, start, radius, 48, THRESHOLD)
        apart = chroma.told_apart(lab_img, edge, colour.targets, told[1], start, radius, label)
        centre = outline_centre(apart, start, radius, None, min_points=MERGED_POINTS)
    if centre is None or np.hypot(*(centre - start)) > MERGED_REACH * radius:
        return None
    return Blob(float(centre[0]) + box[1].start, float(centre[1]) + box[0].start,
                math.pi * radius**2, False, outlined=True)  # fmt: skip


def _told_from_around(lab_img, share, edge, colour, start, radius: float):
    """``edge`` where the ball's blob runs into something of another colour (`AROUND`):
    each pixel's share weighed by how much nearer the ball's colour it lies than that
    thing's (1 on the ball, 0 on it, 1/2 half-way), so that the ball's outline is seen
    against it too, and that thing's colour; None where nothing of another colour lies
    around the ball."""
    h, w = share.shape
    vv, uu = np.mgrid[0:h, 0:w]
    beyond = (share > THRESHOLD) & (np.hypot(uu - start[0], vv - start[1]) > AROUND * radius)
    if beyond.sum() < AROUND_MIN * math.pi * radius**2:
        return None
    other = np.median(lab_img[beyond], axis=0)
    if min(np.linalg.norm(other - c) for c in colour.targets) < AROUND_CONTRAST:
        return None
    to_ball = np.minimum.reduce(
        [np.linalg.norm(lab_img - c.astype(np.float32), axis=-1) for c in colour.targets]
    )
    to_other = np.linalg.norm(lab_img - other.astype(np.float32), axis=-1)
    nearer = 0.5 + (to_other - to_ball) / np.maximum(to_other + to_ball, 1e-6)
    return edge * np.clip(nearer, 0.0, 1.0).astype(np.float32), other


def outline_centre(
    share: NDArray[np.float32],
    start: NDArray,
    radius: float,
    fallback: NDArray | None,
    rays: int = 48,
    min_points: int = 12,
) -> NDArray | None:
    """The centre (window px) of the circle of radius ``radius`` (px) through a round blob's
    outline, in four steps.

    1. The share is sampled along each of ``rays`` rays from ``start`` (`_profiles`).
    2. On each ray, the outline lies on the first steep fall of the share, going out, to
       below `BELOW` (not off a highlight), taken whole (`_first_fall`).
    3. The outline point is where the share crosses half-way down that fall, or its steepest
       point where the two lie more than `HALF_WAY` apart (the ball's fall runs into that of
       a shadow beside it); a ray weighs by its fall's depth and not at all where the share
       rises again beyond it, on a ball's shaded limb (`_outline_points`).
    4. The circle of the given radius nearest the points is fitted by weighted least
       squares, outliers (`EDGE_OFF`, `EDGE_SPREADS`) left out and taken back if the circle
       moves to them (`_fit_outline`).

    A shadow beside the ball begins with a second fall, which is never reached.  A hard
    shadow as dark as the ball is taken into its outline: then the circle through the arc
    that borders the platter (`_arc`), the rays cast again from its centre.  Falls back
    to ``fallback`` with fewer than ``min_points`` points, or fewer than half as many kept
    with weight.
    """
    return _outline(share, start, radius, fallback, rays, min_points)[0]


def _outline(
    share, start, radius: float, fallback, rays=48, min_points=12, local=None, colours=None
):
    """`outline_centre`, and whether the centre is that of the arc bordering the platter.
    With ``local`` (the window's CIELAB colours and the `Colour`), the rays that end on
    something of another hue are looked at again (`_on_other_hue`); with ``colours`` (those
    and the ball's colours), a ray into something of another colour confirms an arc (`_round`)."""
    got = _outline_plain(share, start, radius, fallback, rays, min_points, colours)
    if local is None or got[0] is None or got[0] is fallback:
        return got
    profiles = _on_other_hue(share, *local, got[0], radius, rays)
    if profiles is None:
        return got
    arc_min = ARC_MIN if got[1] else math.inf  # an arc's circle is looked for again
    again = _outline_fit(share, got[0], radius, None, rays, min_points, arc_min, profiles)
    return got if again is None or again[1] != got[1] else again


def _outline_plain(share, start, radius: float, fallback, rays: int, min_points: int, colours):
    """`_outline` without ``local``."""
    arc_min = ARC_FIRST if radius >= ARC_MIN_PX else math.inf
    got = _outline_fit(share, start, radius, fallback, rays, min_points, arc_min)
    if got is None or not got[1]:
        return (None, False) if got is None else got
    got = _outline_fit(share, got[0], radius, None, rays, min_points, ARC_MIN)
    if got is None or not _round(share, got[0], radius, rays, limb=True, colours=colours):
        return fallback, False
    return got[0], True


def _on_other_hue(share, lab_img, colour, start, radius: float, rays: int):
    """The rays' profiles (`_profiles`) from ``start``, those that end on something of another
    hue replaced by the step from its colour to the ball's (``turntable.video.hue``); None
    where too few do."""
    got = hue.other_hue(lab_img, colour.lines, start, radius, rays, OFF_LINE)
    if got is None:
        return None
    other, bg, step = got
    r, a, prof = _profiles(share, start, radius, rays)
    prof[other] = hue.mix_profiles(lab_img, start, r, a[other], bg, step)
    return r, a, prof


def _outline_fit(
    share, start, radius: float, fallback, rays: int, min_points: int, arc_min, profiles=None
):
    """`outline_centre`'s four steps from ``start``: the centre, and whether it is an arc's
    (None if it falls back to None).  ``profiles``: `_profiles`' of the rays looked at again
    from a centre found (`_on_other_hue`): then the fit begins with the points within
    `AGAIN_PX` of its circle."""
    # 1. the share along each ray, and its fall per px
    again = profiles is not None
    r, a, prof = profiles if again else _profiles(share, start, radius, rays)
    fall = (prof[:, :-2] - prof[:, 2:]) / (2 * RAY_STEP)  # centred, at samples 1 .. n-2
    peaked = np.maximum.accumulate(prof[:, :-2], axis=1) > THRESHOLD
    # 2. the first steep fall to near the platter on each ray
    top = fall.max(axis=1, keepdims=True)
    strong = (fall >= STEEP * top) & (prof[:, 1:-1] < prof[:, :1]) & (top > MIN_FALL) & peaked
    ray, sample = np.nonzero(strong)
    ends = np.searchsorted(ray, np.arange(1, rays + 1)).tolist()
    sample = sample.tolist()
    found = []
    for k, (f, p) in enumerate(zip(fall.tolist(), prof.tolist(), strict=True)):
        got = _first_fall(f, p, sample[ends[k - 1] if k else 0 : ends[k]])
        if got is not None:
            found.append((k, *got))
    if len(found) < min_points:
        return None if fallback is None else (fallback, False)
    # 3. where each crosses half-way, and its weight
    pts, weight = _outline_points(np.array(found).T, r, a, prof, fall, start)
    # 4. the circle through them
    # from a centre found (the rays looked at again): its circle's points kept first
    keep = np.abs(np.hypot(*(pts - start).T) - radius) < AGAIN_PX if again else None
    return _fit_outline(pts, weight, start, radius, fallback, min_points, arc_min, keep)


def _profiles(share, start, radius: float, rays: int):
    """The radii sampled (px), the rays' angles and the share along each ray (rays, radii)."""
    r = np.arange(RAY_FROM * radius, RAY_TO * radius + 3.0, RAY_STEP)
    a = np.linspace(0.0, 2 * math.pi, rays, endpoint=False)
    return r, a, along_rays(share, start, a, r)


def _first_fall(f: list[float], p: list[float], starts: list[int]) -> tuple[int, int, int] | None:
    """The first fall of a ray at least `STEEP` of its steepest, from above `THRESHOLD`,
    that ends below `BELOW`: where it begins, its steepest point and where it ends (indices
    of ``f``, the fall per px); None if none.  ``starts``: where the fall is that steep,
    below the ray's start and past a share above `THRESHOLD` (the ray's fall reaching
    `MIN_FALL`).  A fall is taken whole, while it stays above half its own steepest (a
    ripple on its way down does not end it).  On lists: a ray is some 60 samples, which
    numpy takes longer to index than Python."""
    beyond = int(BEYOND_PX / RAY_STEP)
    end = None
    for i in starts:
        if end is not None and i <= end:
            continue
        end, peak = i, f[i]
        while end + 1 < len(f) and f[end + 1] > STEEP * peak:
            end += 1
            peak = max(peak, f[end])
        run = f[i : end + 1]
        j = i + run.index(max(run))
        if p[min(j + 1 + beyond, len(p) - 1)] < BELOW:
            break  # a fall to near the platter or a shadow, not off a highlight
    else:
        return None
    while i > 0 and f[i - 1] > STEEP * peak:
        i -= 1
    return i, j, end


def _outline_points(found, r, a, prof, fall, start):
    """The outline's points (window px) of the falls ``found`` (ray, begin, steepest, end)
    and their weights: by the fall's depth against the clearest falls', 0 where the share
    rises again by `RISE` of it within `BEYOND_PX` beyond the fall."""
    k, begin, j, end = found
    beyond = int(BEYOND_PX / RAY_STEP)
    f = fall[k[:, None], np.clip(j[:, None] + np.arange(-1, 2), 0, fall.shape[1] - 1)]
    den = f[:, 0] - 2 * f[:, 1] + f[:, 2]
    ok = (den < 0) & (j > 0) & (j < fall.shape[1] - 1)
    x = j + np.where(ok, 0.5 * (f[:, 0] - f[:, 2]) / np.where(ok, den, -1.0), 0.0)
    steepest = r[0] + (x + 1) * RAY_STEP  # the peak of the parabola through the fall about it
    p, n = prof[k], np.arange(k.size)
    inside, outside = p[n, begin], p[n, end + 2]
    level = 0.5 * (inside + outside)
    below = np.argmax((np.arange(p.shape[1]) > begin[:, None]) & (p < level[:, None]), axis=1)
    hi, lo = p[n, below - 1], p[n, below]
    half = r[0] + (below - 1 + (hi - level) / np.maximum(hi - lo, 1e-6)) * RAY_STEP
    rr = np.where(np.abs(half - steepest) < HALF_WAY, half, steepest)
    pts = np.column_stack([start[0] + np.cos(a[k]) * rr, start[1] + np.sin(a[k]) * rr])
    depth = inside - outside
    after = p[n[:, None], np.minimum(end[:, None] + 2 + np.arange(beyond + 1), p.shape[1] - 1)]
    rise = (after - np.minimum.accumulate(after, axis=1)).max(axis=1)
    clear = float(np.percentile(depth, CLEAR_PERCENTILE))
    weight = np.clip(SHALLOW * depth / clear, 0.0, 1.0) * (rise < RISE * clear)
    return pts[weight > 0], weight[weight > 0]


def _fit_outline(pts, weight, start, radius: float, fallback, min_points: int, arc_min, keep=None):
    """The centre of the circle of radius ``radius`` nearest the weighted points, refitted
    without the outliers until they stay the same (at most `EDGE_ROUNDS` fits); from the arc
    that carries the most weight (`_arc`) where that is a clearly better circle and carries
    ``arc_min`` of the weight.  With whether it is the arc's; None if it falls back to None."""
    keep = np.ones(len(pts), bool) if keep is None else keep
    centre = _refit(pts, weight, start, keep, radius, fallback, min_points)
    plain = None if centre is None else (centre, False)
    support = 0.0 if centre is None else _support(pts, weight, centre, radius)
    # no arc carries more than all the weight: the search is skipped where that cannot win
    if arc_min > 1.0 or weight.sum() < ARC_GAIN * support:
        return plain
    arc, on_arc = _arc(pts, weight, radius)
    if arc is None or (weight * on_arc).sum() < arc_min * weight.sum():
        return plain
    if (weight * on_arc).sum() < ARC_GAIN * support:
        return plain
    centre = _refit(pts, weight, arc, on_arc, radius, None, min_points)
    return plain if centre is None else (centre, True)


def _round(share, centre, radius: float, rays: int, limb: bool, colours=None) -> bool:
    """Whether the share falls outward across the circle on `ARC_EDGE` of the rays, or, with
    ``limb``, crosses the ball's shaded limb (`turntable.video.limb.confirmed`), or, with
    ``colours`` (CIELAB window, the ball's colours), crosses into something of another colour
    (`turntable.video.hue.borders_another_colour`)."""
    prof = limb_module.across(share, centre, radius, rays, ARC_ACROSS)
    ok = limb_module.confirmed(prof, ARC_STEP, limb)
    if colours is not None:
        ok |= hue.borders_another_colour(*colours, centre, radius, rays, ARC_ACROSS)
    return float(np.mean(ok)) >= ARC_EDGE


def _support(pts, weight, centre, radius: float) -> float:
    """The weight of the points within `ARC_PX` of the circle."""
    return float((weight * (np.abs(np.hypot(*(pts - centre).T) - radius) < ARC_PX)).sum())


def _arc(pts, weight, radius: float):
    """The centre of the circle of radius ``radius`` through the most weight within `ARC_PX`,
    of those through two points at least `ARC_CHORD` radii apart, and which points lie on it;
    (None, None) if no pair is."""
    i, j = np.triu_indices(len(pts), 1)
    chord = pts[j] - pts[i]
    half = 0.5 * np.hypot(*chord.T)
    ok = (half >= 0.5 * ARC_CHORD * radius) & (half < radius)
    if not ok.any():
        return None, None
    mid, chord, half = 0.5 * (pts[i] + pts[j])[ok], chord[ok], half[ok]
    normal = np.c_[-chord[:, 1], chord[:, 0]] / (2 * half[:, None])
    h = np.sqrt(radius**2 - half**2)[:, None]
    centres = np.vstack([mid + h * normal, mid - h * normal])
    dist = np.hypot(pts[None, :, 0] - centres[:, :1], pts[None, :, 1] - centres[:, 1:])
    on = np.abs(dist - radius) < ARC_PX
    best = int(np.argmax(on @ weight))
    return centres[best], on[best]


def _refit(pts, weight, start, keep, radius: float, fallback, min_points: int):
    """`_fit_outline`'s rounds from ``start``, the points ``keep`` kept first."""
    centre = np.asarray(start, float)
    for _ in range(EDGE_ROUNDS):
        if 2 * keep.sum() < min_points:
            return fallback
        centre = circle_centre(pts[keep], radius, start=centre, weights=weight[keep])
        dev = np.hypot(*(pts - centre).T) - radius  # of every point: a dropped one may return
        again = inliers(dev, EDGE_SPREADS, EDGE_FLOOR, kept=keep, centred=True, most=EDGE_OFF)
        if (again == keep).all():
            break
        keep = again
    return centre
