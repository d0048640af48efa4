"""High-precision references for the rolling-resistance model (`turntable.rolling`).

Nothing here uses the reduction (R4) or the closed forms of `turntable.rolling`:
the 4x4 matrix is read off the constrained three-dimensional Newton-Euler
equations, evaluated in mpmath (reaction force as Lagrange multiplier, cross
products, a 3x3 linear solve), and the eigenvalues and the solution come from
mpmath's eigensolver and matrix exponential at ``DPS`` digits.
"""

from __future__ import annotations

from typing import NamedTuple

import mpmath
import numpy as np
from numpy.typing import ArrayLike, NDArray

#: Decimal digits of the references.
DPS = 50


def _cross(a: list, b: list) -> list:
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def _planar_rhs(xyv: list, delta: mpmath.mpf, k: mpmath.mpf) -> list:
    """d(x, y, vx, vy)/dt of the constrained 3-D equations at a no-slip state."""
    gamma = [mpmath.mpf(0), mpmath.mpf(0), mpmath.mpf(1)]
    r = [xyv[0], xyv[1], mpmath.mpf(1)]
    v = [xyv[2], xyv[3], mpmath.mpf(0)]
    # the constraint v + gamma x w - gamma x r = 0 fixes the horizontal w
    w = [r[0] - v[1], r[1] + v[0], mpmath.mpf(0)]
    assert all(
        abs(c) == 0 for c in [v[i] + _cross(gamma, w)[i] - _cross(gamma, r)[i] for i in range(3)]
    )
    moment = [-delta * w[0], -delta * w[1], mpmath.mpf(0)]
    g = mpmath.mpf(9.81)
    # d/dt constraint: (F - g gamma) + gamma x ((-gamma x F + M) / k) - gamma x v = 0
    cols = []
    for j in range(3):
        e = [mpmath.mpf(int(i == j)) for i in range(3)]
        ge = _cross(gamma, [-c for c in _cross(gamma, e)])
        cols.append([e[i] + ge[i] / k for i in range(3)])
    a = mpmath.matrix([[cols[j][i] for j in range(3)] for i in range(3)])
    gm = _cross(gamma, moment)
    gv = _cross(gamma, v)
    b = mpmath.matrix([g * gamma[i] + gv[i] - gm[i] / k for i in range(3)])
    f = mpmath.lu_solve(a, b)
    dv = [f[i] - g * gamma[i] for i in range(3)]
    return [v[0], v[1], dv[0], dv[1]]


def matrix(delta: float, k: float) -> mpmath.matrix:
    """The 4x4 matrix on (x, y, vx, vy), read off the 3-D equations at ``DPS`` digits."""
    with mpmath.workdps(DPS):
        d, kk = mpmath.mpf(delta), mpmath.mpf(k)
        m = mpmath.matrix(4, 4)
        for j in range(4):
            col = _planar_rhs([mpmath.mpf(int(i == j)) for i in range(4)], d, kk)
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
    """Eigenvalues of `matrix` (mpmath.eig): growing root with Im > 0, centre root Im < 0.

    The real 4x4 system has the roots lambda_g, lambda_c of the complex
    equation and their conjugates; lambda_g is the one with Re > 0 and the
    larger imaginary part, lambda_c the one with Re < 0 and Im <= 0.
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
    """exp(M t) applied to (x, y, vx, vy) of z0 at ``DPS`` digits; w from the constraint."""
    z0 = np.asarray(z0, dtype=float)
    out = []
    with mpmath.workdps(DPS):
        m = matrix(delta, k)
        x0 = mpmath.matrix([mpmath.mpf(float(c)) for c in z0[:4]])
        for ti in np.asarray(t, dtype=float):
            x = mpmath.expm(m * mpmath.mpf(float(ti))) * x0
            out.append(
                [
                    float(x[0]),
                    float(x[1]),
                    float(x[2]),
                    float(x[3]),
                    float(x[0] - x[3]),
                    float(x[1] + x[2]),
                ]
            )
    return np.array(out)


def equal_decay_delta(mu0: float, k: float) -> float:
    """delta with |Re lambda_c(delta)| = |alpha2(mu0)|, by mpmath.findroot at ``DPS`` digits.

    |alpha2| from the 50-digit roots of the slipping model's char. poly.
    (2.1); Re lambda_c from the quadratic (k+1) l^2 + (delta - i k) l - i delta.
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

        bracket = (-alpha2 * kk, -alpha2 * 2 * (kk + 1))
        return float(mpmath.findroot(lambda d: re_centre(d) - alpha2, bracket, solver="anderson"))
