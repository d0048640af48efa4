"""The public module of a name that a private module defines."""

from __future__ import annotations

from collections.abc import Callable
from typing import TypeVar

T = TypeVar("T")


def public_module(name: str) -> Callable[[T], T]:
    """Set the ``__module__`` of a function or class to the module that exports it.

    Tracebacks, reprs and the documentation then name it where it is imported from, e.g.
    ``turntable.film.FilmError`` rather than the private module that defines it.

    Parameters
    ----------
    name : str
        The public module, e.g. ``"turntable.film"``.

    Returns
    -------
    callable
        A decorator that sets ``__module__`` and returns its argument.

    Examples
    --------
    >>> from turntable._public import public_module
    >>> @public_module("turntable.film")
    ... class Example(ValueError):
    ...     pass
    >>> Example.__module__
    'turntable.film'
    """

    def decorate(obj: T) -> T:
        obj.__module__ = name
        return obj

    return decorate
