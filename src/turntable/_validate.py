"""Argument checks shared by the public functions.

Every public entry point validates its arguments here before doing any work,
so that bad input raises a :class:`ValueError` that names the argument and
what it must be, instead of propagating NaN or inf.  Complex input is refused
(numpy would silently keep its real part), and `times_within` refuses times at
which a growing solution would overflow a double.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray


def _as_float_array(name: str, value: Any, what: str) -> NDArray[np.float64]:
    if isinstance(value, (str, bytes)) or value is None:
        raise ValueError(f"{name} must be {what}; got {value!r}")
    try:
        is_complex = np.iscomplexobj(np.asarray(value))
    except (TypeError, ValueError):
        is_complex = False
    if is_complex:
        raise ValueError(f"{name} must be {what}; got a complex value {value!r}")
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be {what}; got {value!r}") from None
    if np.asarray(value).dtype == bool:
        raise ValueError(f"{name} must be {what}; got a boolean {value!r}")
    return arr


def positive(name: str, value: ArrayLike) -> NDArray[np.float64]:
    """Return ``value`` as a float array whose entries are finite and > 0."""
    what = "a finite positive number (or an array of them)"
    arr = _as_float_array(name, value, what)
    if arr.size == 0:
        raise ValueError(f"{name} must be {what}; got an empty array")
    if not np.all(np.isfinite(arr)) or not np.all(arr > 0):
        raise ValueError(f"{name} must be {what}; got {value!r}")
    return arr


def positive_scalar(name: str, value: ArrayLike) -> float:
    """Return ``value`` as a Python float that is finite and > 0."""
    arr = positive(name, value)
    if arr.ndim != 0:
        raise ValueError(f"{name} must be a single finite positive number; got shape {arr.shape}")
    return float(arr)


def state(name: str, value: ArrayLike) -> NDArray[np.float64]:
    """Return ``value`` as a float array of six finite numbers."""
    what = "six finite numbers (x, y, vx, vy, wx, wy)"
    arr = _as_float_array(name, value, what)
    if arr.shape != (6,):
        raise ValueError(f"{name} must be {what}; got shape {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} must be {what}; got {value!r}")
    return arr


def states(name: str, value: ArrayLike) -> NDArray[np.float64]:
    """Return ``value`` as a float array of finite states, last axis of length 6."""
    what = "finite states with a last axis (x, y, vx, vy, wx, wy) of length 6"
    arr = _as_float_array(name, value, what)
    if arr.shape[-1:] != (6,):
        raise ValueError(f"{name} must be {what}; got shape {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} must be {what}; got non-finite values")
    return arr


def times(name: str, value: ArrayLike, *, increasing: bool = False) -> NDArray[np.float64]:
    """Return ``value`` as a finite, non-negative 1-D float array."""
    what = "a finite 1-D array of times >= 0"
    if increasing:
        what += " in increasing order"
    arr = _as_float_array(name, value, what)
    if arr.ndim != 1:
        raise ValueError(f"{name} must be {what}; got shape {arr.shape}")
    if not np.all(np.isfinite(arr)) or np.any(arr < 0):
        raise ValueError(f"{name} must be {what}; got non-finite or negative times")
    if increasing and np.any(np.diff(arr) <= 0):
        raise ValueError(f"{name} must be {what}; got times that do not increase")
    return arr


#: Natural logarithm of the largest double: exp(x) overflows for x above it.
LOG_MAX = float(np.log(np.finfo(float).max))

#: Room left below LOG_MAX by `growth_limit`, so that rate * (room / rate) rounded up by
#: a few units in the last place still gives a finite exp (those units are about 1e-13).
_LOG_MARGIN = 1e-10


def finite_scalar(name: str, value: ArrayLike) -> float:
    """Return ``value`` as a Python float that is finite (any sign)."""
    what = "a single finite real number"
    arr = _as_float_array(name, value, what)
    if arr.ndim != 0 or not np.isfinite(arr):
        raise ValueError(f"{name} must be {what}; got {value!r}")
    return float(arr)


def growth_limit(rate: ArrayLike, scale: float = 1.0) -> NDArray[np.float64]:
    """Return the largest t at which ``scale * exp(rate * t)`` is still a finite double.

    That is ``(LOG_MAX - ln max(1, scale)) / rate`` (infinite where rate <= 0), less
    1e-10 / rate, so that ``exp(rate * t)`` computed in doubles is finite up to it.
    """
    rate = np.asarray(rate, dtype=float)
    room = LOG_MAX - _LOG_MARGIN - (max(0.0, float(np.log(scale))) if scale > 0 else 0.0)
    with np.errstate(divide="ignore"):
        return np.where(rate > 0, room / np.where(rate > 0, rate, 1.0), np.inf)


def times_within(name: str, t: NDArray[np.float64], t_max: float, why: str) -> None:
    """Raise ValueError if a time of ``t`` exceeds ``t_max``, naming ``t_max`` and why."""
    if t.size and float(np.max(t)) > t_max:
        raise ValueError(
            f"{name} must be at most {t_max:.17g}, the largest time this solution can "
            f"represent ({why}); got max({name}) = {float(np.max(t)):.17g}"
        )


class InputError(ValueError):
    """Input that a command refuses before doing any work; the message is one line.

    Examples
    --------
    >>> from turntable.fitting import InputError
    >>> str(InputError("--radius must be positive (m); got -1.0"))
    '--radius must be positive (m); got -1.0'
    """
