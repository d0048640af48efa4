r"""The no-slip constraint of the slipping ball and its no-slip limit (3.3)
(`turntable.solution`): the slip velocity, the state after the initial layer, and the motion
as :math:`\mu_0 \to \infty`.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from turntable import _validate
from turntable._conserved import _complex_state, _real_state, spiral_centre
from turntable._public import public_module


@public_module("turntable.solution")
def no_slip_state(z0: ArrayLike, k: float) -> NDArray[np.float64]:
    r"""Return the state on the no-slip constraint reached after the initial layer.

    Parameters
    ----------
    z0 : array_like
        State(s) with last axis (x, y, vx, vy, wx, wy), possibly with slip,
        as in `conserved`.
    k : float
        Inertia ratio, > 0.

    Returns
    -------
    numpy.ndarray
        The state(s), of the shape of z0, with the same r and the same
        conserved quantities as z0 whose slip velocity
        :math:`u = v + \gamma \times \omega - \gamma \times r` vanishes.

    Notes
    -----
    Section 3: in complex form :math:`u = v + i (\omega - r) = 0` and
    :math:`c = v - i k \omega` fix :math:`v = i k (r - r_c) / (k + 1)` and :math:`\omega = r + i v`.

    Examples
    --------
    The state jumps to the constraint u = 0 keeping position and angular momentum:

    >>> from turntable import conserved, no_slip_state, slip_velocity
    >>> z = no_slip_state([0, 0, 1, 0, 0, 0], 0.4)
    >>> z.round(6)
    array([0.      , 0.      , 0.714286, 0.      , 0.      , 0.714286])
    >>> slip_velocity(z), conserved(z, 0.4)
    (array([0., 0.]), array([0., 1.]))
    """
    z0 = _validate.states("z0", z0)
    k = _validate.positive_scalar("k", k)
    r0, v0, w0 = (z0[..., j] + 1j * z0[..., j + 1] for j in (0, 2, 4))
    rc = w0 + 1j * v0 / k
    v = 1j * k / (k + 1.0) * (r0 - rc)
    return _real_state(np.asarray(r0), np.asarray(v), np.asarray(r0 + 1j * v))


@public_module("turntable.solution")
def slip_velocity(z: ArrayLike) -> NDArray[np.float64]:
    r"""Return the slip velocity :math:`u = v + \gamma \times w - \gamma \times r`, as (ux, uy).

    Parameters
    ----------
    z : array_like
        State(s) with last axis (x, y, vx, vy, wx, wy).

    Returns
    -------
    numpy.ndarray
        (ux, uy) on the last axis, the other axes those of ``z``.

    See Also
    --------
    turntable.rolling.state_on_constraint : A state with u = 0.

    Notes
    -----
    Section 1 (dimensionless): u is the velocity of the ball's contact
    point relative to the plane; the no-slip constraint is u = 0.

    Examples
    --------
    Moving at speed 1 without spin, the ball slips at 1:

    >>> from turntable import slip_velocity
    >>> slip_velocity([0, 0, 1, 0, 0, 0])
    array([1., 0.])
    """
    z = _validate.states("z", z)
    return np.stack([z[..., 2] - z[..., 5] + z[..., 1], z[..., 3] + z[..., 4] - z[..., 0]], axis=-1)


@public_module("turntable.solution")
def nonholonomic(z0: ArrayLike, t: ArrayLike, k: float) -> NDArray[np.float64]:
    r"""Return the no-slip (:math:`\mu_0 \to \infty`) motion started from ``z0``.

    Parameters
    ----------
    z0 : array_like
        Initial state (x, y, vx, vy, wx, wy).  If it violates the no-slip
        constraint, the motion starts from `no_slip_state` (z0): the state
        after the initial layer, with the same r(0) and conserved quantities.
    t : array_like
        1-D array of non-negative times.
    k : float
        Inertia ratio, > 0.

    Returns
    -------
    numpy.ndarray
        Shape (len(t), 6).

    See Also
    --------
    turntable.solve : The slipping ball.
    turntable.nonholonomic_period : The period of this motion.

    Notes
    -----
    Equation (3.3): the centre circles about :math:`(x_0, y_0)` of (2.8) at the
    constant rate :math:`k / (k + 1)` with constant radius,
    :math:`r(t) = r_c + (r(0) - r_c)\, e^{i k t / (k + 1)}`,
    :math:`v = i k (r - r_c) / (k + 1)`, :math:`\omega = r_c + (r - r_c) / (k + 1)`.

    Examples
    --------
    After one `nonholonomic_period` the ball is back where it started:

    >>> from turntable import nonholonomic, nonholonomic_period
    >>> z = nonholonomic([0, 0, 1, 0, 0, 0], [0.0, nonholonomic_period(0.4)], 0.4)
    >>> bool(abs(z[1] - z[0]).max() < 1e-14)
    True
    """
    t = _validate.times("t", t)
    z0 = no_slip_state(_validate.state("z0", z0), k)
    r0, _, _ = _complex_state(z0)
    rc = complex(*spiral_centre(z0, k))
    omega = k / (k + 1.0)
    rho = (r0 - rc) * np.exp(1j * omega * t)
    return _real_state(rc + rho, 1j * omega * rho, rc + rho / (k + 1.0))
