"""The ``progress`` callbacks of the long tasks (tracking, rendering, fitting a video).

The package reports progress by calling ``progress(stage, done, total)`` and draws
nothing itself: the command line turns the calls into bars (`turntable._terminal`).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator
from typing import TypeVar

T = TypeVar("T")

#: ``progress(stage, done, total)``: ``done`` of ``total`` steps of ``stage`` are done
#: (``total`` None when unknown).
Progress = Callable[[str, int, "int | None"], None]


def counted(
    items: Iterable[T], progress: Progress | None, stage: str, total: int | None
) -> Iterator[T]:
    """Yield `items`, calling ``progress(stage, i, total)`` after the i-th.

    >>> calls = []
    >>> list(counted("ab", lambda *a: calls.append(a), "reading", 2)), calls
    (['a', 'b'], [('reading', 1, 2), ('reading', 2, 2)])
    """
    for done, item in enumerate(items, start=1):
        yield item
        if progress is not None:
            progress(stage, done, total)
