"""Files written whole or not at all: a temporary file beside the target, then a rename.

Every output of the package, of the workflow's scripts and of the benchmarks is written
through `replacing` or `write_text`, so that an interrupted run never leaves a truncated
file under its final name, and a reader never sees a file half written.
"""

from __future__ import annotations

import os
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

#: Permissions of a written file: readable by everyone, like a file written in place.
MODE = 0o644


@contextmanager
def replacing(path: str | os.PathLike[str]) -> Iterator[Path]:
    """Yield a temporary path beside ``path``; rename it to ``path`` when the block ends.

    The temporary file is hidden (its name starts with a dot), unique (two writers of the
    same file do not share it) and keeps the suffix of ``path``, so that a writer that
    chooses its format by the suffix (matplotlib, PyAV) chooses as for ``path``. If the
    block raises, the temporary file is removed and ``path`` is left as it was.

    Parameters
    ----------
    path : str or os.PathLike
        The file to write. Its folder must exist.

    Yields
    ------
    pathlib.Path
        The temporary file (it exists, empty) to write in place of ``path``.

    See Also
    --------
    write_text : The whole text of a file at once.

    Examples
    --------
    >>> import tempfile
    >>> from pathlib import Path
    >>> folder = Path(tempfile.mkdtemp())
    >>> with replacing(folder / "out.txt") as tmp:
    ...     _ = tmp.write_text("done")
    >>> (folder / "out.txt").read_text(), sorted(p.name for p in folder.iterdir())
    ('done', ['out.txt'])
    """
    path = Path(path)
    fd, name = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=path.suffix)
    os.close(fd)
    tmp = Path(name)
    try:
        yield tmp
        os.chmod(tmp, MODE)
        os.replace(tmp, path)
    finally:
        tmp.unlink(missing_ok=True)


def write_text(path: str | os.PathLike[str], text: str) -> None:
    """Write ``text`` (UTF-8) to ``path`` through a temporary file and a rename.

    Parameters
    ----------
    path : str or os.PathLike
        The file to write. Its folder must exist.
    text : str
        The whole content.

    See Also
    --------
    replacing : For writers that need a path (figures, videos) or write in parts.
    """
    with replacing(path) as tmp:
        tmp.write_text(text, encoding="utf-8")
