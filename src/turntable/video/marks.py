"""Which of the candidates followed over the probe (`turntable.video.find`) turn with the
platter, as a mark does, and in which order they are tried as the mark.

A candidate turns with the platter where its path on the platter's plane is a uniform turning
about the axis (``turning``), at a rate a platter can have (``RATE_RANGE``, or within
``RPM_AGREE`` of ``--rpm``), off the axis (``turning_with_the_platter``).  Of those at least
``MARK_MIN_RADIUS`` of P from the axis, the ones of at least ``MARK_STANDOUT`` of the contrast
of the one that stands out most are tried first, each group nearest the rim first
(``in_order``): on a speckled platter a speck lighter than the grain turns with the platter
over the probe as well as the mark does, but fades in and out as it turns.  A seeded mark that
does not itself turn takes the rate of what turns out of it (``seeded_mark``,
``turning_through``).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from turntable.video import camera
from turntable.video.camera import Pose
from turntable.video.regions import Candidate

__all__ = [
    "MARK_MIN_RADIUS",
    "MARK_STANDOUT",
    "OFF_AXIS",
    "RATE_RANGE",
    "RPM_AGREE",
    "SEED_RATE_AGREE",
    "in_order",
    "seeded_mark",
    "turning",
    "turning_through",
    "turning_with_the_platter",
]

#: A mark is at least this far from the axis, in units of P.
MARK_MIN_RADIUS = 0.45
#: Rates a platter can turn at, rad/s (3 to 115 rpm).
RATE_RANGE = (0.3, 12.0)
#: A mark's rate within this share of ``--rpm``.
RPM_AGREE = 0.05
#: A path that turns is at least this far from the axis, in units of P (a label at the centre
#: turns, but tells nothing of the rate).
OFF_AXIS = 0.05
#: Rates of a mark seen in two probe frames agree within this share (a mark seeded where it
#: does not stand out: `turning_through`).
SEED_RATE_AGREE = 0.15
#: A mark stands out where its contrast is at least this share of the most a mark off the axis
#: has: the marks of the benchmark's 57 scenes have 0.78 of it at least (a ball that turns
#: with the platter over the probe may have more), the ray caster's granite specks 0.22 at most.
MARK_STANDOUT = 0.5


def in_order(marks, candidates: list[Candidate]):
    """The ``marks`` (index, rate) at least `MARK_MIN_RADIUS` from the axis, in the order
    they are tried: those of at least `MARK_STANDOUT` of the most contrast among them first,
    each group nearest the rim first."""
    off = [(i, w) for i, w in marks if candidates[i].turns_at >= MARK_MIN_RADIUS]
    most = max((candidates[i].contrast for i, _ in off), default=0.0)
    return sorted(
        off,
        key=lambda iw: (
            candidates[iw[0]].contrast < MARK_STANDOUT * most,
            -candidates[iw[0]].turns_at,
        ),
    )


def turning_with_the_platter(planes, candidates, tolerance, platter_radius, rpm):
    """The candidates whose paths turn rigidly about the axis, at a rate a platter can have
    (within `RPM_AGREE` of ``--rpm``), off the axis: [(index, rate)]; each one's distance
    from the axis set in ``candidates`` (``turns_at``)."""
    marks = []
    for i, plane in enumerate(planes):
        if plane is None:
            continue
        rate, centre, residual = turning(*plane)
        ok = RATE_RANGE[0] <= abs(rate) <= RATE_RANGE[1]
        if rpm is not None:
            ok = abs(abs(rate) / (rpm * math.pi / 30) - 1) < RPM_AGREE
        if residual < tolerance and ok and abs(centre) > OFF_AXIS * platter_radius:
            candidates[i] = candidates[i]._replace(turns_at=abs(centre) / platter_radius)
            marks.append((i, rate))
    return marks


def seeded_mark(m, rate, candidates, t0, seen, pose, tolerance, rpm):
    """The seeded mark and its rate: its own if it turns, else that of what turns out of it
    (`turning_through`, its area then set in ``candidates``), else None."""
    if rate is None:
        turning = turning_through(candidates[m], t0, seen, pose, tolerance, rpm)
        if turning is not None:
            rate = turning[0]
            candidates[m] = candidates[m]._replace(area=turning[1])
    return m, rate


def turning(t: NDArray, z: NDArray, rate: float | None = None) -> tuple[float, complex, float]:
    """The uniform turning about the axis nearest a path: its rate (fitted unless given), the
    position at t = 0 and the rms distance of the path from it."""
    if rate is None:
        rate = float(np.polyfit(t, np.unwrap(np.angle(z)), 1)[0])
    c = complex(np.mean(z * np.exp(-1j * rate * t)))
    return rate, c, float(np.sqrt(np.mean(np.abs(z - c * np.exp(1j * rate * t)) ** 2)))


def turning_through(c: Candidate, t0: float, seen, pose: Pose, tolerance: float, rpm):
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
    given = None if rpm is None else rpm * math.pi / 30
    low, high = RATE_RANGE if given is None else ((1 - RPM_AGREE) * given, (1 + RPM_AGREE) * given)
    best, agree = None, []
    for w in rates:
        if low <= abs(w) <= high:
            near_w = [i for i, x in enumerate(rates) if abs(x / w - 1) < SEED_RATE_AGREE]
            if len({frames[i] for i in near_w}) > len({frames[i] for i in agree}):
                best, agree = w, near_w
    if len({frames[i] for i in agree}) < len(seen) / 2:
        return None
    return best, float(np.median([sizes[i] for i in agree]))
