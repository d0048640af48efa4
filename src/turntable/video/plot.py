"""Drawing a tracked video: its first frame with the rim, the axis, the mark and the track."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from turntable.video import camera


def draw_frame(ax: Any, track: Any) -> None:
    """The first frame, grey, with the fitted rim (the circle of radius P seen by the fitted
    camera), the image of the axis, the mark's circle and its images, the ball's track."""
    cal = track.calibration
    ax.imshow(track.first_frame, interpolation="nearest")
    s = np.linspace(0, 2 * math.pi, 361)
    rim = camera.project(cal.pose, platter_circle(track, s))
    ax.plot(rim[:, 0], rim[:, 1], color="tab:orange", lw=0.8, label="rim (fitted camera)")
    mark = camera.project(cal.pose, cal.mark_radius * np.column_stack([np.cos(s), np.sin(s)]))
    ax.plot(mark[:, 0], mark[:, 1], color="tab:cyan", lw=0.6, ls="--", label="mark's circle")
    ax.plot(*track.mark_image[0], "o", mfc="none", color="tab:cyan", ms=6, label="mark")
    axis = camera.project(cal.pose, np.zeros(2))
    ax.plot(*axis, "+", color="tab:red", ms=10, mew=1.2, label="axis")
    ax.plot(track.image[:, 0], track.image[:, 1], color="tab:green", lw=0.8, label="ball's track")
    ax.set(xlim=(0, track.info.width - 1), ylim=(track.info.height - 1, 0), xticks=[], yticks=[])


def platter_circle(track: Any, s: np.ndarray) -> np.ndarray:
    """Points of the rim in the plane (radius P from the calibration's scale)."""
    p = track.platter_radius
    return p * np.column_stack([np.cos(s), np.sin(s)])


def plot_found(path: str, look: Any, name: str) -> None:
    """Draw what was found before an error (`turntable.video.track.FirstLook`) on its frame
    (the first, or the one where the ball or the mark was lost): the rim, and every candidate
    labelled with its place (u, v) and what it was taken for."""
    from matplotlib.figure import Figure

    h, w = look.image.shape[:2]
    fig = Figure(figsize=(6.4, 6.4 * h / w + 0.4), layout="constrained")
    ax = fig.add_subplot()
    ax.imshow(look.image, interpolation="nearest")
    if look.rim is not None:
        s = np.linspace(0, 2 * math.pi, 361)
        c, si = math.cos(look.rim.angle), math.sin(look.rim.angle)
        x, y = look.rim.a * np.cos(s), look.rim.b * np.sin(s)
        u, v = look.rim.centre[0] + c * x - si * y, look.rim.centre[1] + si * x + c * y
        ax.plot(u, v, color="tab:orange", lw=0.8, label="rim")
    colours = {"ball": "tab:green", "mark": "tab:cyan"}
    for cand in look.candidates:
        turns = "" if math.isnan(cand.turns_at) else f", turns at {cand.turns_at:.2f} P"
        ax.plot(cand.u, cand.v, "o", mfc="none", ms=8, color=colours.get(cand.kind, "tab:red"))
        ax.annotate(
            f"{cand.kind} ({cand.u:.0f},{cand.v:.0f}){turns}",
            (cand.u, cand.v),
            xytext=(6, 6),
            textcoords="offset points",
            fontsize=5,
            color=colours.get(cand.kind, "tab:red"),
        )
    ax.set(xlim=(0, w - 1), ylim=(h - 1, 0))
    frame = "the first frame" if look.frame == 0 else f"frame {look.frame}"
    ax.set_title(f"{name}: what was found on {frame} (u, v in px)", fontsize=8)
    fig.savefig(path, dpi=150)


def plot_track(path: str, track: Any) -> None:
    """Draw `draw_frame` into the file ``path`` (matplotlib, Agg)."""
    from matplotlib.figure import Figure

    w, h = track.info.width, track.info.height
    fig = Figure(figsize=(6.4, 6.4 * h / w + 0.4), layout="constrained")
    ax = fig.add_subplot()
    draw_frame(ax, track)
    synthetic = "SYNTHETIC video: " if track.info.synthetic else ""
    ax.set_title(f"{synthetic}{track.info.path}", fontsize=8)
    ax.legend(fontsize=6, loc="lower right")
    fig.savefig(path, dpi=150)
