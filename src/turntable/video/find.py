"""Stage 3, finding the ball and the mark on the first frames.

Everything on the platter whose colour differs from the platter's by more than its grain
(CIELAB distance above ``CONTRAST_NOISE`` times the platter's median one, and at least
``MIN_CONTRAST``) is a candidate, bright or dark, of any hue.  Each candidate is followed over
the first ``PROBE_SECONDS`` of the video and its path seen on the platter's plane through the
camera that the rim alone gives.  What tells them apart is how they move:

- the **mark** turns rigidly with the platter: on a circle about the axis, at least
  ``MARK_MIN_RADIUS`` of P from it, at a constant rate that a platter can have (``RATE_RANGE``,
  or within 5 % of ``--rpm``); of several, the one nearest the rim of those that stand out
  from the platter nearly as much as the one that stands out most (`turntable.video.marks`);
- the **ball** does not; it is round and of the size that R and the rim's scale predict; of
  several, the one that differs most from the platter (not its shadow).

Two candidates that could each be the ball are refused, as is a scene with no mark: the seeds
``--ball-at U,V`` and ``--mark-at U,V`` (pixels of the first frame) then say which is which.
A ball of nearly the platter's colour, of which only a crescent or a ring differs from the platter
(``CRESCENT_HINT``), is refused as such, seeded or not: no seed would help.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

from turntable.video import camera
from turntable.video.camera import Pose
from turntable.video.colours import Colour
from turntable.video.decode import Picture, VideoError, lab, window
from turntable.video.marks import (
    RATE_RANGE,
    in_order,
    seeded_mark,
    turning,
    turning_with_the_platter,
)
from turntable.video.platter import Platter
from turntable.video.regions import (
    AREA_RANGE,
    MAX_ELONGATION,
    MIN_CONTRAST,
    MIN_FILL,
    MIN_SOLIDITY,
    Candidate,
    _a_ball,
    _area_at,
    _ball_shaped,
    _candidate,
    _parts,
    _seeded,
    _split,
)

#: A candidate differs from the platter by this many times the platter's median distance
#: from its own colour, and by at least ``MIN_CONTRAST`` (CIELAB units).
CONTRAST_NOISE = 5.0
#: Candidates are followed over this long (s), at least `PROBE_FRAMES` frames.
PROBE_SECONDS, PROBE_FRAMES = 0.3, 10
#: A candidate not of a ball's shape (a black ball and its shadow on a light platter, cut as
#: one region) is split by colour into this many clusters, each part a candidate too.
RESPLIT_CLUSTERS = 2
#: A ball of nearly the platter's colour (a steel ball on a mid-grey platter): its lit side is
#: of the platter's grey, and what differs is its shaded limb with its shadow, a crescent that
#: covers less of its hull than `MIN_SOLIDITY` (0.58-0.76 on MuJoCo's steel balls on a platter
#: of grey 150), whole (`MIN_FILL`) and of a ball's area (`AREA_RANGE`).  Where it alone moves
#: on its own, the ball is refused as too like the platter: the mark may not be taken for the
#: ball (then the crescent, turning slowly over the probe, for the mark), and a seed on it
#: follows the crescent, not the ball (0.75 R off on such a scene, every check passed).
CRESCENT_HINT = (
    "the ball differs too little from the platter: a ball of nearly the platter's colour is "
    "not tracked (its lit side is of the platter's shade); film a ball in more contrast with "
    "the platter (white, black or coloured)"
)
#: A seed's region is looked for within this many times the radius of a ball's image there.
SEED_REACH = 4.0
#: Candidates lie this far (px) inside the rim: not the platter's side, nor its shadow beyond
#: a rim fitted a pixel too wide.
RIM_MARGIN_PX = 3.0
#: The platter's grain is measured between these shares of the rim (a label at its centre
#: left out).
GRAIN_RING = (0.35, 0.9)
#: A candidate is followed to the blob of ``PROBE_AREA`` times its area nearest where its last
#: step leads, within ``GATE_PX`` px and ``GATE_RADII`` of its radii of it, and as far as its
#: step, or on the second frame the fastest platter (`RATE_RANGE`), would take it.
PROBE_AREA, GATE_PX, GATE_RADII = (0.3, 3.3), 3.0, 1.5
#: A candidate followed over this share of the probe's frames (and 3 at least) has a path.
MIN_FOLLOWED = 0.6
#: A path turns rigidly where its rms distance from a uniform turning is below ``RIGID_R`` R,
#: or ``RIGID_PX`` px of the rim's scale, if more.
RIGID_R, RIGID_PX = 0.15, 1.5
#: A second candidate for the ball this close in contrast and area to the first makes the
#: choice ambiguous.
RIVAL_CONTRAST, RIVAL_AREA = 0.8, 0.6
SEED_HINT = "give the first frame's pixel with --ball-at U,V and --mark-at U,V"


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

    def __init__(self, c: Candidate, t0: float) -> None:
        self.c = c
        self.t: list[float] = [t0]
        self.uv: list[tuple[float, float]] = [(c.u, c.v)]

    def predict(self, t: float) -> NDArray:
        """Where it is at time t, if it goes on as in its last step."""
        if len(self.uv) < 2:
            return np.array(self.uv[-1])
        (u0, v0), (u1, v1) = self.uv[-2:]
        t0, t1 = self.t[len(self.uv) - 2], self.t[len(self.uv) - 1]
        return np.array([u1, v1]) + (np.array([u1 - u0, v1 - v0])) * (t - t1) / (t1 - t0)


class _Look(NamedTuple):
    """Where candidates are looked for: the window about the rim (its slices, and its corner
    (u, v) in the image), the pixels allowed in it, the CIELAB distance from the platter's
    colour a candidate has at least, and the area (px) above which a region is split."""

    platter: Platter
    box: tuple[slice, slice]
    origin: NDArray[np.float64]
    allowed: NDArray[np.bool_]
    threshold: float
    largest: float

    def parts(self, lab_img):
        """`_parts` of a CIELAB window."""
        return _parts(lab_img, self.platter, self.allowed, self.threshold, self.largest)


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
        No ball, a ball of nearly the platter's colour, two possible balls, no mark, or a
        seed with nothing there; its ``found`` holds the candidates.
    """
    t0, picture0 = probe[0]
    # 1. where candidates are looked for, and how far from the platter's colour they are
    look, lab0 = _look(picture0, platter, pose, ball_radius)
    # 2. the candidates of the first frame, and those at the seeds
    paths = [_Path(c, t0) for c in _first_candidates(look, lab0)]
    seeded = {}
    for option, at in (("--ball-at", ball_at), ("--mark-at", mark_at)):
        if at is not None:
            seeded[option] = len(paths)
            c = _at_seed(option, at, look, lab0, pose, ball_radius, paths)
            if option == "--ball-at" and any(is_(c, pose, ball_radius) for is_, _ in _SHAPES):
                raise VideoError(
                    f"--ball-at {at[0]:g},{at[1]:g} is on a crescent or a ring of a ball's "
                    f"size, not a whole ball (its shaded side or limb): {CRESCENT_HINT}",
                    [p.c for p in paths] + [c],
                )
            paths.append(_Path(c, t0))
    # 3. each followed over the probe, its path seen on the platter's plane
    seen = _follow_probe(paths, probe[1:], look)
    planes = [_on_plane(p, len(probe), pose) for p in paths]
    candidates = [p.c for p in paths]
    tolerance = max(RIGID_R * ball_radius, RIGID_PX * platter_radius / platter.rim.a)
    # 4. the marks: what turns rigidly with the platter, the one seeded or those near the rim
    marks = turning_with_the_platter(planes, candidates, tolerance, platter_radius, rpm)
    if mark_at is not None:
        m = seeded["--mark-at"]
        marks = [seeded_mark(m, dict(marks).get(m), candidates, t0, seen, pose, tolerance, rpm)]
    else:
        marks = in_order(marks, candidates)
    if not marks:
        raise VideoError(
            "no mark found on the platter: nothing near the rim turns with it at a rate a "
            f"platter can have; put a small mark near the rim, in contrast with the platter, or "
            f"{SEED_HINT}",
            candidates,
        )
    # 5. the ball: what does not turn with the mark, of a ball's size and shape
    m, rate, ball = _ball_and_its_mark(
        marks, planes, candidates, seeded.get("--ball-at"), pose, ball_radius, tolerance
    )
    if ball is None:
        across = 2 * math.sqrt(_area_at(pose, pose.principal, ball_radius) / math.pi)
        raise VideoError(
            f"no ball found on the first frame: nothing round of about {across:.0f} px across (a "
            "ball of the given radius at the rim's scale) differs from the platter and moves on "
            f"its own; check --ball-radius and --platter-radius, or {SEED_HINT}",
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


def _look(picture: Picture, platter: Platter, pose: Pose, ball_radius: float):
    """The `_Look` of the first frame, and the frame's CIELAB window: the contrast a candidate
    has is `CONTRAST_NOISE` times the platter's grain (its median distance from its own
    colour), and `MIN_CONTRAST` at least; a region larger than the largest ball is split."""
    rim = platter.rim
    shape = picture.shape
    allowed = rim.mask(shape, 1.0 - RIM_MARGIN_PX / rim.b)
    box = window(rim.centre, rim.a + RIM_MARGIN_PX, shape)
    origin = np.array([box[1].start, box[0].start], float)
    lab0 = lab(picture, box)
    ring = (rim.mask(shape, GRAIN_RING[1]) & ~rim.mask(shape, GRAIN_RING[0]))[box]
    noise = float(np.median(np.linalg.norm(lab0[ring] - platter.colour.astype(np.float32), axis=1)))
    threshold = max(CONTRAST_NOISE * noise, MIN_CONTRAST)
    largest = AREA_RANGE[1] * _area_at(pose, rim.centre, ball_radius)
    return _Look(platter, box, origin, allowed[box], threshold, largest), lab0


def _first_candidates(look: _Look, lab0) -> list[Candidate]:
    """The candidates of the first frame; of one not of a ball's shape, its parts by colour
    too (`RESPLIT_CLUSTERS`): a ball cut as one region with its shadow is one of them."""
    out = []
    for sub, part, corner, split in look.parts(lab0):
        c = _candidate(sub, part, look.platter, look.origin + corner)
        if c is None:
            continue
        out.append(c._replace(split=split))
        if _ball_shaped(c):
            continue
        for piece in _split(sub, part, RESPLIT_CLUSTERS):
            p = _candidate(sub, piece, look.platter, look.origin + corner)
            if p is not None:
                out.append(p._replace(split=True))
    return out


def _at_seed(option, at, look: _Look, lab0, pose, ball_radius, paths) -> Candidate:
    """The candidate at a seed; refused if nothing there differs from the platter.  A ball's
    seed whose region runs into something of a like colour, not of a ball's size and shape (a
    white ball touching a cream ring on a label: the ring's arc with it, its centroid 1.3 R
    off), is the candidate of the first frame of a ball's size and shape that covers the
    seed nearest, split from it by colour, if one does (`_a_ball`); else its region's part at
    the seed, by colour, where the region is larger than a ball's (`_seeded`)."""
    area = _area_at(pose, at, ball_radius)
    largest = AREA_RANGE[1] * area if option == "--ball-at" else math.inf
    c = _seeded(lab0, look.origin, look.platter, at, SEED_REACH * math.sqrt(area), largest)
    if c is None:
        raise VideoError(
            f"{option} {at[0]:g},{at[1]:g}: nothing there differs from the platter; "
            "--plot shows the candidates",
            [p.c for p in paths],
        )
    if option == "--ball-at" and not _a_ball(c, pose, ball_radius):
        off = {id(p.c): math.hypot(p.c.u - at[0], p.c.v - at[1]) for p in paths}
        balls = [p.c for p in paths if _a_ball(p.c, pose, ball_radius)]
        covering = [b for b in balls if off[id(b)] < math.sqrt(b.area / math.pi)]
        c = min(covering, key=lambda b: off[id(b)], default=c)
    return c


def _follow_probe(paths: list[_Path], probe, look: _Look) -> list:
    """Follow each path over the probe's frames (a path lost is not followed further);
    return, for each frame, its time, the blobs' centres (n, 2) and their areas."""
    centre = look.platter.rim.centre
    seen = []
    for t, picture in probe:
        found = [
            (*(np.argwhere(part)[:, ::-1].mean(axis=0) + look.origin + corner), part.sum())
            for _, part, corner, _ in look.parts(lab(picture, look.box))
        ]
        st = np.array(found, float).reshape(-1, 3)
        cen, areas = st[:, :2], st[:, 2]
        seen.append((t, cen, areas))
        for p in paths:
            if len(p.uv) < len(p.t):
                continue
            near = p.predict(t)
            step = float(np.hypot(*(near - p.uv[-1])))
            if len(p.uv) == 1:  # as far as the fastest platter would take it
                arm = float(np.hypot(p.c.u - centre[0], p.c.v - centre[1]))
                step = RATE_RANGE[1] * arm * (t - p.t[0])
            gate = GATE_PX + GATE_RADII * math.sqrt(p.c.area / math.pi) + step
            d = np.hypot(cen[:, 0] - near[0], cen[:, 1] - near[1])
            ok = (
                (d < gate) & (areas > PROBE_AREA[0] * p.c.area) & (areas < PROBE_AREA[1] * p.c.area)
            )
            if ok.any():
                j = int(np.argmin(np.where(ok, d, np.inf)))
                p.uv.append((float(cen[j, 0]), float(cen[j, 1])))
            p.t.append(t)
    return seen


def _ball_and_its_mark(marks, planes, candidates, ball, pose, ball_radius, tolerance):
    """The first of the ``marks`` (index, rate) with a ball, and the ball (``ball`` if
    seeded): of the candidates that do not turn rigidly at its rate, those followed over the
    probe and whole, if any, else split, else all (`_choose_ball`)."""
    m, rate, seeded = None, None, ball
    for n, (m, rate) in enumerate(marks):
        rigid = [
            rate is not None and planes[i] is not None and turning(*planes[i], rate)[2] < tolerance
            for i in range(len(candidates))
        ]
        others = [c if i != m and not rigid[i] else None for i, c in enumerate(candidates)]
        ball = seeded
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
        if n == 0:
            _refuse_a_crescent(others, pose, ball_radius)
    return m, rate, ball


def _crescent(c: Candidate, pose: Pose, ball_radius: float) -> bool:
    """Of a ball's area and whole, but not round: a ball's shaded side and its shadow, its lit
    side of the platter's colour (`CRESCENT_HINT`)."""
    area = c.area / _area_at(pose, (c.u, c.v), ball_radius)
    return AREA_RANGE[0] < area < AREA_RANGE[1] and c.fill >= MIN_FILL and c.solidity < MIN_SOLIDITY


def _ring(c: Candidate, pose: Pose, ball_radius: float) -> bool:
    """Round and of a ball's area with its inside, but hollow: a ball's shaded limb about its
    lit side of the platter's colour (`CRESCENT_HINT`)."""
    area = c.area / max(c.fill, 1e-9) / _area_at(pose, (c.u, c.v), ball_radius)
    round_ = c.elongation < MAX_ELONGATION and c.solidity >= MIN_SOLIDITY
    return AREA_RANGE[0] < area < AREA_RANGE[1] and c.fill < MIN_FILL and round_


#: What a ball of nearly the platter's colour shows, and how it is named.
_SHAPES = (
    (_crescent, "a crescent, not round (a ball's shaded side and its shadow)"),
    (_ring, "a ring, not whole (a ball's shaded limb)"),
)


def _refuse_a_crescent(others, pose, ball_radius) -> None:
    """Refuse a ball of nearly the platter's colour: a crescent (`_crescent`) or a ring
    (`_ring`) among the candidates that move on their own (the others None).  It is refused
    where the first mark has no ball: the next mark pairs it wrong (a mark of 0.65 R, taken
    for the ball, left the crescent turning slowly as a mark)."""
    for c in others:
        for test, shape in _SHAPES:
            if c is not None and test(c, pose, ball_radius):
                raise VideoError(
                    f"no ball found on the first frame: what moves on its own at ({c.u:.0f}, "
                    f"{c.v:.0f}) px, of a ball's size, is {shape}: {CRESCENT_HINT}",
                    [x for x in others if x is not None],
                )


def _on_plane(p: _Path, frames: int, pose: Pose) -> tuple[NDArray, NDArray] | None:
    """A candidate's times and positions on the platter's plane (x + i y), if it was followed
    over most of the probe."""
    if len(p.uv) < max(MIN_FOLLOWED * frames, 3):
        return None
    q = camera.back_project(pose, np.array(p.uv))
    return np.array(p.t[: len(p.uv)]), q[:, 0] + 1j * q[:, 1]


def _choose_ball(others, pose, ball_radius) -> int | None:
    """The ball among the candidates that do not turn with the platter (None elsewhere)."""
    ok = [i for i, c in enumerate(others) if c is not None and _a_ball(c, pose, ball_radius)]
    if not ok:
        return None
    ok.sort(key=lambda i: -others[i].contrast)
    if len(ok) > 1:
        a, b = others[ok[0]], others[ok[1]]
        if b.contrast > RIVAL_CONTRAST * a.contrast and b.area > RIVAL_AREA * a.area:
            raise VideoError(
                f"two things could be the ball, at ({a.u:.0f}, {a.v:.0f}) and ({b.u:.0f}, "
                f"{b.v:.0f}) px: give the ball's pixel of the first frame with --ball-at U,V",
                [c for c in others if c is not None],
            )
    return ok[0]
