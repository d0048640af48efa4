"""Independent references of the rolling-resistance model (`turntable.rolling`).

Under the names of `turntable.rolling`: ``from turntable.reference import rolling as ref``
gives ``ref.spectrum``, ``ref.solution``, ... next to the functions they check.  Nothing
here uses the reduction (R4) or the closed forms of `turntable.rolling`: the 4x4 matrix is
read off the constrained three-dimensional Newton-Euler equations, evaluated in mpmath
(reaction force as Lagrange multiplier, cross products, a 3x3 linear solve), and the
eigenvalues and the solution come from mpmath's eigensolver and matrix exponential.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import mpmath
import numpy as np
from numpy.typing import ArrayLike, NDArray

from turntable.reference.slipping import mp_system_matrix

#: Decimal digits of the references of the rolling model.
DPS = 50


def _mp_cross(a: list, b: list) -> list:
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def _rolling_planar_rhs(xyv: list, delta: mpmath.mpf, k: mpmath.mpf) -> list:
    """d(x, y, vx, vy)/dt of the constrained 3-D equations at a no-slip state."""
    gamma = [mpmath.mpf(0), mpmath.mpf(0), mpmath.mpf(1)]
    r = [xyv[0], xyv[1], mpmath.mpf(1)]
    v = [xyv[2], xyv[3], mpmath.mpf(0)]
    # the constraint v + gamma x w - gamma x r = 0 fixes the horizontal w
    w = [r[0] - v[1], r[1] + v[0], mpmath.mpf(0)]
    gw, gr = _mp_cross(gamma, w), _mp_cross(gamma, r)
    if any(v[i] + gw[i] - gr[i] != 0 for i in range(3)):  # pragma: no cover - by construction
        raise ArithmeticError("the state is not on the no-slip constraint")
    moment = [-delta * w[0], -delta * w[1], mpmath.mpf(0)]
    g = mpmath.mpf(9.81)
    # d/dt constraint: (F - g gamma) + gamma x ((-gamma x F + M) / k) - gamma x v = 0
    cols = []
    for j in range(3):
        e = [mpmath.mpf(int(i == j)) for i in range(3)]
        ge = _mp_cross(gamma, [-c for c in _mp_cross(gamma, e)])
        cols.append([e[i] + ge[i] / k for i in range(3)])
    a = mpmath.matrix([[cols[j][i] for j in range(3)] for i in range(3)])
    gm = _mp_cross(gamma, moment)
    gv = _mp_cross(gamma, v)
    b = mpmath.matrix([g * gamma[i] + gv[i] - gm[i] / k for i in range(3)])
    f = mpmath.lu_solve(a, b)
    dv = [f[i] - g * gamma[i] for i in range(3)]
    return [v[0], v[1], dv[0], dv[1]]


def matrix(delta: float, k: float) -> mpmath.matrix:
    """Return the rolling model's 4x4 matrix on (x, y, vx, vy) at `DPS` digits.

    Parameters
    ----------
    delta, k : float
        Rolling-resistance coefficient and inertia ratio (exact doubles).

    Returns
    -------
    mpmath.matrix
        Column j is the right-hand side of the constrained 3-D Newton-Euler equations
        (torque -delta w on the horizontal spin) at the j-th unit state.
    """
    with mpmath.workdps(DPS):
        d, kk = mpmath.mpf(delta), mpmath.mpf(k)
        m = mpmath.matrix(4, 4)
        for j in range(4):
            col = _rolling_planar_rhs([mpmath.mpf(int(i == j)) for i in range(4)], d, kk)
            for i in range(4):
                m[i, j] = col[i]
        return m


class MpRollingSpectrum(NamedTuple):
    """(sigma_g, nu_g, sigma_c, nu_c) as floats, from the high-precision eigenvalues."""

    sigma_g: float
    nu_g: float
    sigma_c: float
    nu_c: float


def spectrum(delta: float, k: float) -> MpRollingSpectrum:
    """Return the rolling model's eigenvalues from mpmath.eig of `matrix`.

    Parameters
    ----------
    delta, k : float
        Rolling-resistance coefficient and inertia ratio.

    Returns
    -------
    MpRollingSpectrum
        The growing root lambda_g (Re > 0, the larger imaginary part) and the centre's
        root lambda_c (Re < 0, the smaller imaginary part) of the real 4x4 system, whose
        eigenvalues are these two and their conjugates.
    """
    with mpmath.workdps(DPS):
        ev = mpmath.eig(matrix(delta, k), left=False, right=False)
        grow = max((e for e in ev if mpmath.re(e) > 0), key=lambda e: mpmath.im(e))
        cent = min((e for e in ev if mpmath.re(e) < 0), key=lambda e: mpmath.im(e))
        return MpRollingSpectrum(
            float(mpmath.re(grow)),
            float(mpmath.im(grow)),
            float(mpmath.re(cent)),
            float(mpmath.im(cent)),
        )


def solution(z0: ArrayLike, t: ArrayLike, delta: float, k: float) -> NDArray[np.float64]:
    """Return the rolling motion from z0 at the times t, shape (len(t), 6).

    Parameters
    ----------
    z0 : array_like
        Initial state (x, y, vx, vy, wx, wy); only (x, y, vx, vy) is used.
    t : array_like
        Times.
    delta, k : float
        Rolling-resistance coefficient and inertia ratio.

    Returns
    -------
    numpy.ndarray
        exp(M t) (x, y, vx, vy) with M = `matrix`, by mpmath.expm at
        `DPS` digits; w = (x - vy, y + vx) from the no-slip constraint.
    """
    z0 = np.asarray(z0, dtype=float)
    out = []
    with mpmath.workdps(DPS):
        m = matrix(delta, k)
        x0 = mpmath.matrix([mpmath.mpf(float(c)) for c in z0[:4]])
        for ti in np.asarray(t, dtype=float):
            x = mpmath.expm(m * mpmath.mpf(float(ti))) * x0
            out.append([float(c) for c in (x[0], x[1], x[2], x[3], x[0] - x[3], x[1] + x[2])])
    return np.array(out)


def equal_decay_delta(mu0: float, k: float) -> float:
    """Return delta with |Re lambda_c(delta)| = |alpha2(mu0)|, at `DPS` digits.

    Parameters
    ----------
    mu0, k : float
        Slipping friction coefficient and inertia ratio.

    Returns
    -------
    float
        The root found by mpmath.findroot; |alpha2| from the textbook roots (2.4) of the
        slipping model, Re lambda_c from the roots of the quadratic
        (k+1) l^2 + (delta - i k) l - i delta.
    """
    with mpmath.workdps(DPS):
        kk, m = mpmath.mpf(k), mpmath.mpf(mu0)
        mu = m * (kk + 1) / (2 * kk)
        eps = 4 * kk**2 / (m * (kk + 1) ** 2)
        alpha2 = mu * (-1 - mpmath.re(mpmath.sqrt(1 + 1j * eps)))

        def re_centre(d: mpmath.mpf) -> mpmath.mpf:
            roots = mpmath.polyroots(
                [kk + 1, d - 1j * kk, -1j * d], maxsteps=200, extraprec=2 * DPS
            )
            return min(mpmath.re(r) for r in roots)

        bracket = (-alpha2 * kk / 2, -alpha2 * 4 * (kk + 1))
        return float(mpmath.findroot(lambda d: re_centre(d) - alpha2, bracket, solver="anderson"))


def equal_power_delta(mu0: float, k: float) -> float:
    """Return delta at which rolling along the slipping path dissipates the slipping power.

    Parameters
    ----------
    mu0, k : float
        Slipping friction coefficient and inertia ratio.

    Returns
    -------
    float
        mu0 |u|^2 / |w_roll|^2 on the slipping model's growing mode, at `DPS`
        digits (plus those the slip loses to cancellation for large mu0).

    Notes
    -----
    The mode is an eigenvector of L (`mp_system_matrix`), as the 3x3 complex matrix of its
    a I + b J blocks (see `mp_spectrum`), for the eigenvalue of largest real part: a state
    (r, v, w) whose motion is e^{lambda_+ t} (r, v, w).  From its real components, the
    slip u = v + gamma x w - gamma x r with cross products, and the spin of a ball that
    rolls along the same path from the no-slip constraint,
    w_roll = (x - vy, y + vx).  Both powers scale with e^{2 alpha1 t}, so their ratio at
    t = 0 is the ratio at every instant.  Nothing of the closed forms is used.
    """
    lost = max(0, math.ceil(2.0 * math.log10(max(mu0, 1.0) / k)))
    with mpmath.workdps(DPS + lost + 10):
        big = mp_system_matrix(mu0, k)
        blocks = mpmath.matrix(3, 3)
        for i in range(3):
            for j in range(3):
                blocks[i, j] = mpmath.mpc(big[2 * i, 2 * j], big[2 * i + 1, 2 * j])
        ev, vecs = mpmath.eig(blocks)
        j = max(range(3), key=lambda n: mpmath.re(ev[n]))
        r, v, w = (vecs[n, j] for n in range(3))
        gamma = [mpmath.mpf(0), mpmath.mpf(0), mpmath.mpf(1)]
        rr = [mpmath.re(r), mpmath.im(r), mpmath.mpf(0)]
        vv = [mpmath.re(v), mpmath.im(v), mpmath.mpf(0)]
        ww = [mpmath.re(w), mpmath.im(w), mpmath.mpf(0)]
        gw, gr = _mp_cross(gamma, ww), _mp_cross(gamma, rr)
        u = [vv[n] + gw[n] - gr[n] for n in range(3)]
        w_roll = [rr[0] - vv[1], rr[1] + vv[0]]
        slip2 = u[0] ** 2 + u[1] ** 2
        spin2 = w_roll[0] ** 2 + w_roll[1] ** 2
        return float(mpmath.mpf(mu0) * slip2 / spin2)
