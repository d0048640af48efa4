"""Films exported by Tracker (Open Source Physics), read as Tracker writes them.

One track: the first line is the track's name (``mass_A``), the second the column names
(``t``, ``x``, ``y``, and any others), then one line per frame.  Several tracks (Tracker
6): a first line ``#multi:``, a line with each track's name above its first column, then
the column names.  The delimiter is the one of the column names' line: a tab (Tracker's
default), else a comma, a semicolon or spaces.  Numbers may be written ``1.245986911E1``;
a cell left empty (a frame where the track has no point, or a column of the track longer
than the others) makes that frame a gap.  Tracker's positions are in the units the user
calibrated in Tracker, which the file does not say: `read_tracker` multiplies them by
``scale`` (metres per unit); the times are in seconds.
"""

from __future__ import annotations

import math
import os
import re
from pathlib import Path

import numpy as np

from turntable.film import Film, FilmError

#: Metres per unit of the units Tracker can be calibrated in (``--units``).
UNITS = {"m": 1.0, "cm": 0.01, "mm": 0.001, "in": 0.0254, "ft": 0.3048}
MULTI = "#multi:"


def _lines(path: str | os.PathLike[str]) -> list[str]:
    name = os.fspath(path)
    try:
        text = Path(path).read_bytes().decode("utf-8-sig")
    except OSError as exc:
        raise FilmError(f"{name}: cannot read the file: {exc.strerror or exc}") from None
    except UnicodeDecodeError:
        raise FilmError(f"{name}: not UTF-8 text") from None
    return [line.rstrip("\r") for line in text.split("\n")]


def _split(line: str, delimiter: str | None) -> list[str]:
    cells = line.split(delimiter) if delimiter else line.split()
    return [c.strip().strip('"') for c in cells]


def _delimiter(header: str) -> str | None:
    return next((d for d in ("\t", ",", ";") if d in header), None)


def is_tracker(path: str | os.PathLike[str]) -> bool:
    """Whether a file looks like a Tracker export: ``#multi:`` first, or a first line of one
    name followed by a line naming t, x and y."""
    try:
        lines = [line for line in _lines(path) if line.strip()][:3]
    except FilmError:
        return False
    if lines and lines[0].strip().lower().startswith(MULTI):
        return True
    if len(lines) < 2 or lines[0].lstrip().startswith("#"):
        return False
    first = [c for c in _split(lines[0], _delimiter(lines[1])) if c]
    names = set(_split(lines[1], _delimiter(lines[1])))
    return len(first) == 1 and {"t", "x", "y"} <= names and first[0] not in ("t", "x", "y")


def read_tracker(
    path: str | os.PathLike[str], track: str | None = None, scale: float = 1.0
) -> tuple[Film, str]:
    """Read one track of a Tracker export; return the film (x, y times ``scale``) and its name.

    Parameters
    ----------
    path : str or path-like
    track : str, optional
        The track's name, in a file of several tracks (by default the first one).
    scale : float
        Metres per unit of Tracker's positions (`UNITS`).

    Raises
    ------
    FilmError
        For a file without the lines above, a track not in the file, a cell that is not a
        number, times that do not increase; the message names the file and the line.
    """
    name = os.fspath(path)
    lines = _lines(path)
    rows = [(i + 1, line) for i, line in enumerate(lines) if line.strip()]
    multi = bool(rows) and rows[0][1].strip().lower().startswith(MULTI)
    if len(rows) < 2 + multi:
        raise FilmError(f"{name}: not a Tracker export (a track's name, then the column names)")
    head_no, head = rows[1 + multi]
    delimiter = _delimiter(head)
    columns = _split(head, delimiter)
    tracks = _split(rows[multi][1], delimiter)
    if multi:
        starts = [(i, c) for i, c in enumerate(tracks) if c]
        if not starts:
            raise FilmError(f"{name}:{rows[1][0]}: no track names after {MULTI}")
        names = [c for _, c in starts]
        chosen = names.index(track) if track is not None and track in names else 0
        if track is not None and track not in names:
            raise FilmError(f"{name}: no track {track!r} (the file has {', '.join(names)})")
        first = starts[chosen][0]
        end = starts[chosen + 1][0] if chosen + 1 < len(starts) else len(columns)
        span = range(first, end)
        label = names[chosen]
    else:
        span = range(len(columns))
        label = next(c for c in tracks if c)
        if track is not None and track != label:
            raise FilmError(f"{name}: no track {track!r} (the file has {label})")
    where = {}
    for c in ("t", "x", "y"):
        hits = [i for i in span if columns[i] == c] or (
            [i for i, col in enumerate(columns) if col == c] if c == "t" else []
        )
        if not hits:
            raise FilmError(f"{name}:{head_no}: track {label!r} has no column '{c}'")
        where[c] = hits[0]
    t, x, y = [], [], []
    for number, line in rows[2 + multi :]:
        cells = _split(line, delimiter)
        values = [cells[where[c]] if where[c] < len(cells) else "" for c in ("t", "x", "y")]
        if any(v == "" for v in values):
            continue  # a frame without a point of this track: a gap
        try:
            tv, xv, yv = (float(v) for v in values)
        except ValueError:
            bad = next(v for v in values if not re.fullmatch(r"[-+0-9.eE]+", v))
            raise FilmError(f"{name}:{number}: {bad!r} is not a number") from None
        if not all(math.isfinite(v) for v in (tv, xv, yv)):
            raise FilmError(f"{name}:{number}: a value is not a finite number")
        if t and tv <= t[-1]:
            raise FilmError(f"{name}:{number}: t = {tv:g} does not increase")
        t.append(tv)
        x.append(xv * scale)
        y.append(yv * scale)
    return Film(np.array(t), np.array(x), np.array(y)), label
