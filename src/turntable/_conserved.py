r"""The complex form of a state and what the slipping ball's motion conserves
(`turntable.solution`): :math:`c = v - i k \omega` and the centre of the spiral.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from turntable import _validate
from turntable._public import public_module


def _complex_state(z0: NDArray[np.float64]) -> tuple[complex, complex, complex]:
    return complex(z0[0], z0[1]), complex(z0[2], z0[3]), complex(z0[4], z0[5])


def _real_state(
    r: NDArray[np.complex128], v: NDArray[np.complex128], w: NDArray[np.complex128]
) -> NDArray[np.float64]:
    r, v, w = np.broadcast_arrays(r, v, w)
    return np.stack([r.real, r.imag, v.real, v.imag, w.real, w.imag], axis=-1)


@public_module("turntable.solution")
def conserved(z: ArrayLike, k: float) -> NDArray[np.float64]:
    r"""Return the two conserved quantities :math:`(k\omega_x - v_y, k\omega_y + v_x)`.

    Parameters
    ----------
    z : array_like
        State(s) with last axis (x, y, vx, vy, wx, wy).
    k : float
        Inertia ratio, > 0.

    Returns
    -------
    numpy.ndarray
        Array of shape ``z.shape[:-1] + (2,)``.

    Notes
    -----
    Angular momentum about the contact point, Section 2: in complex form
    :math:`c = v - i k \omega` is constant along every solution of (1.7).

    Examples
    --------
    >>> from turntable import conserved, solve
    >>> z = solve([0, 0, 1, 0, 0, 0], [0.0, 5.0], mu0=1.0, k=0.4)
    >>> conserved(z, 0.4).round(12)
    array([[0., 1.],
           [0., 1.]])
    """
    k = _validate.positive_scalar("k", k)
    z = _validate.states("z", z)
    return np.stack([k * z[..., 4] - z[..., 3], k * z[..., 5] + z[..., 2]], axis=-1)


@public_module("turntable.solution")
def spiral_centre(z0: ArrayLike, k: float) -> NDArray[np.float64]:
    r"""Return the centre :math:`(x_0, y_0)` of the spiral traced by the ball's centre.

    Parameters
    ----------
    z0 : array_like
        State(s) with last axis (x, y, vx, vy, wx, wy), as in `conserved`.
    k : float
        Inertia ratio, > 0.

    Returns
    -------
    numpy.ndarray
        ``[x0, y0]``, of shape ``z0.shape[:-1] + (2,)``.

    See Also
    --------
    turntable.solve : The motion about it.

    Notes
    -----
    Equation (2.8), from the conserved quantities:
    :math:`x_0 = (k \omega_x(0) - v_y(0)) / k`, :math:`y_0 = (k \omega_y(0) + v_x(0)) / k`.
    It does not depend on r(0).  The sign in :math:`y_0` is +: the centre is the fixed point
    :math:`x_0 e_1 + y_0 e_2` with the same conserved c as z0, and at a fixed point
    :math:`v = 0`, :math:`\omega = (x_0, y_0)`, so :math:`c = -i k (x_0 + i y_0)`.

    Examples
    --------
    >>> from turntable import spiral_centre
    >>> spiral_centre([0, 0, 1, 0, 0, 0], 0.4)
    array([0. , 2.5])
    """
    z0 = _validate.states("z0", z0)
    k = _validate.positive_scalar("k", k)
    return np.stack([(k * z0[..., 4] - z0[..., 3]) / k, (k * z0[..., 5] + z0[..., 2]) / k], axis=-1)
