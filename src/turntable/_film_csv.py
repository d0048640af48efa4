"""The CSV file of a film: `read_film`, `write_film`, and the `FilmError` of a file that
cannot be used.

The format is described in `turntable.film`, which exports these names.
"""

from __future__ import annotations

import csv
import math
import os
import re
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

from turntable._atomic import write_text
from turntable._public import public_module

#: The columns a film must have: time (s) and the centre's position (m).
COLUMNS = ("t", "x", "y")
#: Field delimiters, in the order the header is searched for them: the first one the
#: header line holds is the file's.
DELIMITERS = (",", "\t", ";")
#: Word of a comment line that marks a film as simulated (`turntable.fit.synthetic_header`
#: writes it).
SYNTHETIC_MARK = "SYNTHETIC"
_MARK = re.compile(rf"\b{SYNTHETIC_MARK}\b")


@public_module("turntable.film")
class FilmError(ValueError):
    """A film file that cannot be used; the message names file, line and column.

    Examples
    --------
    >>> import os, tempfile
    >>> from turntable.film import FilmError, read_film
    >>> path = os.path.join(tempfile.mkdtemp(), "film.csv")
    >>> with open(path, "w") as f:
    ...     _ = f.write("t,x\\n0,0.05\\n")
    >>> try:
    ...     read_film(path)
    ... except FilmError as error:
    ...     print("FilmError:", str(error).split(": ", 1)[1])
    FilmError: the header has no column 'y' (it names 't', 'x'; columns t, x, y are needed)
    """


@public_module("turntable.film")
class Film(NamedTuple):
    """Tracked positions of the ball's centre in the lab frame (SI units).

    Attributes
    ----------
    t : numpy.ndarray
        Times of the frames in s, strictly increasing, shape (n,).
    x, y : numpy.ndarray
        Position of the centre in m, shape (n,).
    synthetic : bool
        Whether the film is marked as simulated: `read_film` sets it for a file with a
        comment line containing the word SYNTHETIC (as `turntable.fit.synthetic_header` writes).

    Examples
    --------
    The film that ships with the package:

    >>> from turntable.film import EXAMPLE_FILM, read_film
    >>> film = read_film(EXAMPLE_FILM)
    >>> film.t.size, film.synthetic
    (301, True)
    """

    t: NDArray[np.float64]
    x: NDArray[np.float64]
    y: NDArray[np.float64]
    synthetic: bool = False


def _number(text: str, path: str, line: int, field: int, name: str) -> float:
    where = f"{path}:{line}: column '{name}' (field {field})"
    try:
        value = float(text)
    except ValueError:
        raise FilmError(f"{where}: {text.strip()!r} is not a number") from None
    if not math.isfinite(value):
        raise FilmError(f"{where}: {text.strip()!r} is not a finite number")
    return value


@public_module("turntable.film")
def read_film(
    path: str | os.PathLike[str],
    min_rows: int = 1,
    why: str = "",
    bounds: Mapping[str, tuple[float, float]] | None = None,
    bounds_why: str = "",
) -> Film:
    """Read a film (t, x, y) from a CSV file; see the module docstring for the format.

    Parameters
    ----------
    path : str or path-like
        The CSV file.
    min_rows : int
        Fewest frames accepted.
    why : str
        Reason for ``min_rows``, added to the message if there are fewer frames.
    bounds : mapping, optional
        {column: (low, high)}: values of t, x or y outside [low, high] are refused.
    bounds_why : str
        Reason for ``bounds``, added to the message.

    Returns
    -------
    Film
        With ``synthetic`` True if a comment line contains the word SYNTHETIC.

    Raises
    ------
    FilmError
        For a file that cannot be read or is not UTF-8 text, a header without one of the
        columns t, x, y (or with one of them twice; quotes around a name are not part of
        it), a row with another number of fields
        than the header, a value that is not a finite number, a time that does not
        increase, a value outside ``bounds``, or fewer than ``min_rows`` frames.  The
        message starts with ``<file>:<line>:`` and names the column and its field number
        where there is one.

    See Also
    --------
    turntable.film.write_film : The file it reads.

    Examples
    --------
    >>> import os, tempfile
    >>> from turntable.film import read_film
    >>> path = os.path.join(tempfile.mkdtemp(), "film.csv")
    >>> lines = ["# tracked by hand", "t;x;y;quality", "0;0.05;0;1", "0.1;0.049;0.017;1"]
    >>> with open(path, "w") as f:
    ...     _ = f.write(os.linesep.join(lines))
    >>> read_film(path)
    Film(t=array([0. , 0.1]), x=array([0.05 , 0.049]),
         y=array([0.   , 0.017]), synthetic=False)
    >>> read_film(path, min_rows=15, why="for a fit")
    Traceback (most recent call last):
    ...
    turntable.film.FilmError: ...film.csv:4: 2 frames (lines 3-4); need at least 15 (for a fit)
    """
    name = os.fspath(path)
    try:
        raw = Path(path).read_bytes()
    except OSError as exc:
        raise FilmError(f"{name}: cannot read the file: {exc.strerror or exc}") from None
    header: dict[str, int] | None = None
    delimiter = ","
    n_fields = 0
    header_line = 0
    columns: dict[str, list[float]] = {c: [] for c in COLUMNS}
    first = last = 0
    prev_t = -math.inf
    prev_line = 0
    synthetic = False
    for number, chunk in enumerate(raw.split(b"\n"), start=1):
        try:
            text = chunk.decode("utf-8")
        except UnicodeDecodeError:
            raise FilmError(f"{name}:{number}: not UTF-8 text") from None
        text = text.lstrip("\ufeff").rstrip("\r")
        if text.lstrip().startswith("#"):
            synthetic = synthetic or bool(_MARK.search(text))
            continue
        if not text.strip():
            continue
        if header is None:
            delimiter = next((d for d in DELIMITERS if d in text), ",")
        fields = [f.strip() for f in next(csv.reader([text], delimiter=delimiter))]
        if header is None:
            header, header_line, n_fields = {}, number, len(fields)
            for i, field in enumerate(fields, start=1):
                if field in COLUMNS and field in header:
                    raise FilmError(
                        f"{name}:{number}: column '{field}' appears twice in the header "
                        f"(fields {header[field]} and {i})"
                    )
                header.setdefault(field, i)
            missing = [c for c in COLUMNS if c not in header]
            if missing:
                raise FilmError(
                    f"{name}:{number}: the header has no column '{missing[0]}' (it names "
                    f"{', '.join(repr(f) for f in fields)}; columns t, x, y are needed)"
                )
            continue
        if len(fields) != n_fields:
            raise FilmError(
                f"{name}:{number}: {len(fields)} fields, but the header on line "
                f"{header_line} has {n_fields}"
            )
        values = {c: _number(fields[header[c] - 1], name, number, header[c], c) for c in COLUMNS}
        for c, (low, high) in (bounds or {}).items():
            if not low <= values[c] <= high:
                raise FilmError(
                    f"{name}:{number}: column '{c}' (field {header[c]}): {values[c]:g} is "
                    f"outside [{low:.3g}, {high:.3g}]" + (f" ({bounds_why})" if bounds_why else "")
                )
        if values["t"] <= prev_t:
            raise FilmError(
                f"{name}:{number}: column 't' (field {header['t']}): t = {values['t']:g} does "
                f"not increase (t = {prev_t:g} on line {prev_line}); the times must increase "
                "strictly"
            )
        prev_t, prev_line = values["t"], number
        for c in COLUMNS:
            columns[c].append(values[c])
        first = first or number
        last = number
    if header is None:
        raise FilmError(f"{name}:1: no header line (a line naming the columns t, x, y)")
    n = len(columns["t"])
    if n < min_rows:
        rows = f"lines {first}-{last}" if n else f"none after the header on line {header_line}"
        reason = f" ({why})" if why else ""
        raise FilmError(
            f"{name}:{last or header_line}: {n} frames ({rows}); need at least {min_rows}{reason}"
        )
    return Film(*(np.array(columns[c]) for c in COLUMNS), synthetic=synthetic)


@public_module("turntable.film")
def write_film(
    path: str | os.PathLike[str], film: Film, comments: Sequence[str] = (), digits: int = 10
) -> None:
    """Write ``film`` as CSV (header ``t,x,y``), atomically, after ``"# "`` comment lines.

    Parameters
    ----------
    path : str or path-like
        The file; written under a temporary name in the same folder, then renamed.
    film : Film
        The frames.
    comments : sequence of str
        Lines written first, each prefixed with ``"# "``.
    digits : int
        Significant digits of each number.

    See Also
    --------
    turntable.film.read_film : Reads it back.

    Examples
    --------
    >>> import os, tempfile
    >>> from turntable.film import Film, read_film, write_film
    >>> path = os.path.join(tempfile.mkdtemp(), "film.csv")
    >>> film = Film([0.0, 0.1], [0.05, 0.049], [0.0, 0.017])
    >>> write_film(path, film, ["SYNTHETIC example"])
    >>> with open(path) as f:
    ...     print(f.read())
    # SYNTHETIC example
    t,x,y
    0,0.05,0
    0.1,0.049,0.017
    <BLANKLINE>
    >>> read_film(path).synthetic
    True
    """
    path = Path(path)
    lines = [f"# {c}" for c in comments] + ["t,x,y"]
    lines += [
        f"{t:.{digits}g},{x:.{digits}g},{y:.{digits}g}"
        for t, x, y in zip(film.t, film.x, film.y, strict=True)
    ]
    write_text(path, "\n".join(lines) + "\n")
