r"""The closed-form motion of the rolling ball (`turntable.rolling`): the state on the no-slip
constraint, the modes of (R4) and the moving centre of the spiral.

The derivation is in docs/theory.md; `turntable.rolling` exports these names.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from turntable import _validate
from turntable._public import public_module
from turntable._rolling_spectrum import _spectrum_rolling
from turntable.solution import slip_velocity

#: Largest slip |u| accepted by `solve`, relative to 1 + max |z0|.
SLIP_TOLERANCE = 1e-10


@public_module("turntable.rolling")
def state_on_constraint(xyv: ArrayLike) -> NDArray[np.float64]:
    """Return the state (x, y, vx, vy, wx, wy) with w from the no-slip constraint.

    Parameters
    ----------
    xyv : array_like
        Finite numbers (x, y, vx, vy), shape (4,) or (..., 4) for several states.

    Returns
    -------
    numpy.ndarray
        Shape (6,) or (..., 6).

    Notes
    -----
    (R1): w = r + i v, i.e. wx = x - vy, wy = y + vx.

    Examples
    --------
    >>> from turntable import rolling
    >>> rolling.state_on_constraint([1, 0, 0, 1])
    array([1., 0., 0., 1., 1., 0.])
    """
    arr = _validate._as_float_array("xyv", xyv, "finite numbers (x, y, vx, vy)")
    if arr.ndim == 0 or arr.shape[-1] != 4 or not np.all(np.isfinite(arr)):
        raise ValueError(
            f"xyv must be finite numbers (x, y, vx, vy), shape (4,) or (..., 4); got {xyv!r}"
        )
    x, y, vx, vy = np.moveaxis(arr, -1, 0)
    return np.stack([x, y, vx, vy, x - vy, y + vx], axis=-1)


class _Modes(NamedTuple):
    ag: complex
    ac: complex
    lg: complex
    lc: complex
    delta: float
    k: float


def _modes(z0: ArrayLike, delta: float, k: float) -> _Modes:
    z0 = _validate.state("z0", z0)
    delta = _validate.positive_scalar("delta", delta)
    k = _validate.positive_scalar("k", k)
    u = slip_velocity(z0)
    if np.hypot(*u) > SLIP_TOLERANCE * (1.0 + np.max(np.abs(z0))):
        raise ValueError(
            "z0 violates the no-slip constraint of the rolling model: slip velocity "
            f"u = v + gamma x w - gamma x r = ({u[0]:.6g}, {u[1]:.6g}) is not 0 "
            "(build z0 with rolling.state_on_constraint)"
        )
    s = _spectrum_rolling(np.float64(delta), np.float64(k))
    lg, lc = complex(s.sigma_g, s.nu_g), complex(s.sigma_c, s.nu_c)
    r0, v0 = complex(z0[0], z0[1]), complex(z0[2], z0[3])
    d = lg - lc
    return _Modes((v0 - lc * r0) / d, (lg * r0 - v0) / d, lg, lc, delta, k)


def _mode_states(amp: NDArray[np.complex128], lam: complex) -> NDArray[np.float64]:
    v = lam * amp
    w = amp + 1j * v
    return np.stack([amp.real, amp.imag, v.real, v.imag, w.real, w.imag], axis=-1)


def _time_limit(m: _Modes) -> float:
    """Largest t at which the rolling solution and each of its modes are finite doubles.

    Every component of a mode A e^{lambda t} (position, velocity lambda A e^{lambda t} and
    spin w = r + i v) is at most |A| (1 + |lambda|) |e^{lambda t}|; the centre's mode
    decays, so the sum stays below (|A_g| (1 + |lambda_g|) + |A_c| (1 + |lambda_c|))
    e^{sigma_g t}.  Without a growing part (A_g = 0, e.g. z0 = 0) there is no limit.
    """
    if m.ag == 0:
        return np.inf
    size = abs(m.ag) * (1.0 + abs(m.lg)) + abs(m.ac) * (1.0 + abs(m.lc))
    return float(_validate.growth_limit(m.lg.real, size))


def _exp(lam: complex, t: NDArray[np.float64], amp: complex) -> NDArray[np.complex128]:
    """amp e^{lam t} for times already checked against `_time_limit` (0 if amp is 0).

    A decaying mode may underflow to 0, and for huge t its exponent lam.real t may round
    to -inf (e^{-inf} = 0 exactly): both are harmless.  Im lam t stays finite: nu_g lies
    between k / (k + 1) and 1, |nu_c| below 1 / (k + 1).
    """
    if amp == 0:
        return np.zeros(t.shape, dtype=complex)
    with np.errstate(under="ignore", over="ignore" if lam.real < 0 else None):
        return amp * np.exp(lam.real * t) * (np.cos(lam.imag * t) + 1j * np.sin(lam.imag * t))


@public_module("turntable.rolling")
class RollingModes(NamedTuple):
    """The growing spiral and its moving centre, each of shape (len(t), 6).

    Examples
    --------
    The spiral and its centre add up to the solution:

    >>> import numpy as np
    >>> from turntable import rolling
    >>> z0 = rolling.state_on_constraint([0, 0, 1, 0])
    >>> modes = rolling.modal_terms(z0, [0.0, 10.0], 0.1, 0.4)
    >>> bool(np.allclose(modes.spiral + modes.centre, rolling.solve(z0, [0.0, 10.0], 0.1, 0.4)))
    True
    """

    spiral: NDArray[np.float64]
    centre: NDArray[np.float64]


@public_module("turntable.rolling")
def modal_terms(z0: ArrayLike, t: ArrayLike, delta: float, k: float) -> RollingModes:
    r"""Split the rolling motion into the growing spiral and its moving centre.

    Parameters
    ----------
    z0 : array_like
        Initial state on the no-slip constraint (x, y, vx, vy, wx, wy).
    t : array_like
        1-D array of non-negative times.
    delta, k : float
        Rolling-resistance coefficient and inertia ratio, > 0.

    Returns
    -------
    RollingModes
        ``spiral`` carries :math:`A_g e^{\lambda_g t}`, ``centre`` :math:`A_c e^{\lambda_c t}`
        (with their v and :math:`\omega = r + i v`); they sum to `solve`.

    Notes
    -----
    :math:`A_g = (v_0 - \lambda_c r_0) / (\lambda_g - \lambda_c)`,
    :math:`A_c = (\lambda_g r_0 - v_0) / (\lambda_g - \lambda_c)` (:doc:`/theory`).

    Examples
    --------
    The spiral and its centre add up to the motion:

    >>> from turntable import rolling
    >>> z0, t = rolling.state_on_constraint([0, 0, 1, 0]), [0.0, 1.0, 10.0]
    >>> parts = rolling.modal_terms(z0, t, 0.1, 0.4)
    >>> z = rolling.solve(z0, t, 0.1, 0.4)
    >>> bool(abs(parts.spiral + parts.centre - z).max() < 1e-14)
    True
    """
    t = _validate.times("t", t)
    m = _modes(z0, delta, k)
    _validate.times_within(
        "t",
        t,
        _time_limit(m),
        f"for delta={m.delta:g}, k={m.k:g}, e^(sigma_g t) times the size of the solution "
        "overflows a double beyond it",
    )
    return RollingModes(
        _mode_states(_exp(m.lg, t, m.ag), m.lg), _mode_states(_exp(m.lc, t, m.ac), m.lc)
    )


@public_module("turntable.rolling")
def solve(z0: ArrayLike, t: ArrayLike, delta: float, k: float) -> NDArray[np.float64]:
    r"""Return the exact rolling motion :math:`z(t)` from :math:`z_0`.

    Parameters
    ----------
    z0 : array_like
        Initial state (x, y, vx, vy, wx, wy); it must satisfy the no-slip
        constraint u = 0 (to `SLIP_TOLERANCE` relative to 1 + max |z0|),
        otherwise ValueError names the slip.
    t : array_like
        1-D array of non-negative times, in any order.
    delta, k : float
        Rolling-resistance coefficient and inertia ratio, finite and > 0.

    Returns
    -------
    numpy.ndarray
        Shape (len(t), 6).

    Raises
    ------
    ValueError
        For bad input, a z0 with slip, or times at which the growing mode
        overflows (the message names the largest representable t).

    See Also
    --------
    turntable.rolling.modal_terms : The same solution as spiral and centre.
    turntable.solve : The slipping ball.

    Notes
    -----
    :math:`r(t) = A_g e^{\lambda_g t} + A_c e^{\lambda_c t}`, :math:`v = \dot r`,
    :math:`\omega = r + i v` (:doc:`/theory`).

    Examples
    --------
    The ball stays on the constraint (no slip):

    >>> import numpy as np
    >>> from turntable import rolling
    >>> z0 = rolling.state_on_constraint([0, 0, 1, 0])
    >>> z = rolling.solve(z0, np.linspace(0.0, 10.0, 3), 0.1, 0.4)
    >>> bool(abs(rolling.slip_velocity(z)).max() < 1e-14)
    True
    """
    spiral, centre = modal_terms(z0, t, delta, k)
    return spiral + centre


@public_module("turntable.rolling")
def spiral_centre(z0: ArrayLike, t: ArrayLike, delta: float, k: float) -> NDArray[np.float64]:
    r"""Return the position of the spiral's centre, shape (len(t), 2).

    Parameters
    ----------
    z0 : array_like
        Initial state on the no-slip constraint (x, y, vx, vy, wx, wy).
    t : array_like
        1-D array of non-negative times.
    delta, k : float
        Rolling-resistance coefficient and inertia ratio, finite and > 0.

    Returns
    -------
    numpy.ndarray
        (x, y) of the centre at each time, shape (len(t), 2).

    See Also
    --------
    modal_terms : The spiral and its centre apart.
    turntable.spiral_centre : The fixed centre of the slipping ball's spiral.

    Notes
    -----
    :math:`r_c(t) = A_c e^{\lambda_c t}`: it moves, spiralling into the turntable's
    axis at the rate :math:`|\sigma_c|` (`centre_decay_rate`).

    Examples
    --------
    The centre moves from its start towards the axis:

    >>> from turntable import rolling
    >>> z0 = rolling.state_on_constraint([0, 0, 1, 0])
    >>> rolling.spiral_centre(z0, [0.0, 10.0], 0.1, 0.4).round(3)
    array([[-1.169,  1.591],
           [-0.007,  0.308]])
    """
    return modal_terms(z0, t, delta, k).centre[:, :2]
