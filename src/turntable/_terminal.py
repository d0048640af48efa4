"""What the ``turntable`` command shows on stderr: its log lines and its progress bars.

The package logs through `logging` (``logging.getLogger(__name__)``) and reports progress
through a ``progress(stage, done, total)`` callback; only the command line turns them into
lines and bars on a terminal.
"""

from __future__ import annotations

import contextlib
import logging
import sys
from collections.abc import Iterator
from typing import Any

from turntable._progress import Progress


class _Format(logging.Formatter):
    def __init__(self, prog: str) -> None:
        super().__init__()
        self.prog = prog

    def format(self, record: logging.LogRecord) -> str:
        message = " ".join(record.getMessage().split())
        return f"{self.prog}: {record.levelname.lower()}: {message}"


class _Stderr(logging.StreamHandler):
    """A handler that writes to the `sys.stderr` of the moment it emits, above the progress
    bars."""

    def emit(self, record: logging.LogRecord) -> None:
        if "tqdm" not in sys.modules:
            super().emit(record)
            return
        from tqdm import tqdm

        with tqdm.external_write_mode(file=sys.stderr):
            super().emit(record)

    @property
    def stream(self) -> Any:
        return sys.stderr

    @stream.setter
    def stream(self, _value: Any) -> None:
        pass


def level(quiet: bool, verbose: int) -> int:
    """The level of the log lines shown: errors only with ``-q``, INFO with ``-v``, DEBUG
    with ``-vv``, else warnings.

    >>> import logging
    >>> [logging.getLevelName(level(q, v)) for q, v in [(True, 0), (False, 0), (False, 2)]]
    ['ERROR', 'WARNING', 'DEBUG']
    """
    if quiet:
        return logging.ERROR
    return {0: logging.WARNING, 1: logging.INFO}.get(verbose, logging.DEBUG)


@contextlib.contextmanager
def logged(prog: str, quiet: bool = False, verbose: int = 0) -> Iterator[None]:
    """Show the package's log lines on stderr as ``PROG: LEVEL: message`` while inside."""
    logger = logging.getLogger("turntable")
    handler = _Stderr()
    handler.setFormatter(_Format(prog))
    old = logger.level, logger.propagate
    logger.addHandler(handler)
    logger.setLevel(level(quiet, verbose))
    logger.propagate = False
    try:
        yield
    finally:
        logger.removeHandler(handler)
        logger.setLevel(old[0])
        logger.propagate = old[1]


class Bars:
    """A tqdm bar on stderr for each stage that a `Progress` callback reports."""

    def __init__(self) -> None:
        self._stage: str | None = None
        self._bar: Any = None

    def __call__(self, stage: str, done: int, total: int | None) -> None:
        if stage != self._stage:
            from tqdm import tqdm

            self.close()
            self._stage = stage
            self._bar = tqdm(total=total, desc=stage, file=sys.stderr, leave=False)
        self._bar.update(done - self._bar.n)

    def close(self) -> None:
        """Take the current bar off the terminal."""
        if self._bar is not None:
            self._bar.close()
        self._stage = self._bar = None


@contextlib.contextmanager
def bars(quiet: bool = False) -> Iterator[Progress | None]:
    """A `Bars` callback when stderr is a terminal and tqdm is installed, else None."""
    if quiet or not sys.stderr.isatty():
        yield None
        return
    try:
        import tqdm  # noqa: F401
    except ImportError:
        yield None
        return
    shown = Bars()
    try:
        yield shown
    finally:
        shown.close()
