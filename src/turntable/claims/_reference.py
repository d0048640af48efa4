"""Independent reference computations for the claims checks.

Nothing here uses the closed forms of `turntable`: the matrix of the planar
equations is rebuilt from the vector equations (1.6) with cross products,
its eigenvalues come from mpmath at high precision, the solution from the
matrix exponential, the kernel projection from a least-squares solve, and
the characteristic polynomial from sympy.
"""

from __future__ import annotations

import functools
from typing import NamedTuple

import mpmath
import numpy as np
import scipy.linalg
import sympy as sp
from numpy.typing import ArrayLike, NDArray

#: Digits of the mpmath eigenvalue computations.
DPS = 40

_GAMMA = np.array([0.0, 0.0, 1.0])


def planar_rhs(z: NDArray[np.float64], mu0: float, k: float) -> NDArray[np.float64]:
    """Right-hand side of (1.6) for a planar state, written with cross products.

    Parameters
    ----------
    z : numpy.ndarray
        State (x, y, vx, vy, wx, wy); z-components of r, v, w are set to 0
        (contact kept; the spin about the vertical drops out of the planar part).
    mu0, k : float
        Friction coefficient and inertia ratio.

    Returns
    -------
    numpy.ndarray
        d/dt of (x, y, vx, vy, wx, wy).
    """
    r = np.array([z[0], z[1], 0.0])
    v = np.array([z[2], z[3], 0.0])
    w = np.array([z[4], z[5], 0.0])
    g = _GAMMA
    dv = -mu0 * (v + np.cross(g, w) - np.cross(g, r))
    dw = (mu0 / k) * (np.cross(g, v) - w + g * (g @ w) + r - g * (g @ r))
    return np.array([v[0], v[1], dv[0], dv[1], dw[0], dw[1]])


def matrix_from_equations(mu0: float, k: float) -> NDArray[np.float64]:
    """Return the 6x6 matrix of the planar equations, column by column.

    Column j is `planar_rhs` applied to the j-th unit vector; the right-hand
    side is linear, so this is the matrix of the reduced system.
    """
    return np.column_stack([planar_rhs(e, mu0, k) for e in np.eye(6)])


class MpSpectrum(NamedTuple):
    """Nonzero eigenvalues of L from mpmath, as floats and as mpmath numbers."""

    alpha1: float
    alpha2: float
    beta: float
    roots: tuple[mpmath.mpc, ...]


@functools.lru_cache(maxsize=512)
def mp_spectrum(mu0: float, k: float) -> MpSpectrum:
    """Eigenvalues of L computed by mpmath's QR algorithm with `DPS` digits.

    The 6x6 matrix is built in mpmath arithmetic from the block form (1.7),
    so that its entries mu0 and mu0/k carry `DPS` digits.  Each of its 2x2
    blocks is checked to be of the form a I + b J; J squares to -I, so L is
    the real form of the complex 3x3 matrix with entries a + i b, and the
    spectrum of L is the spectrum of that matrix together with its complex
    conjugate.  The 3x3 problem is solved (six times faster than the 6x6
    one); of its eigenvalues the one of smallest modulus (the kernel) is
    dropped, the other two are alpha1 + i beta and alpha2 - i beta.
    """
    with mpmath.workdps(DPS):
        m = mpmath.mpf(mu0)
        c = m / mpmath.mpf(k)
        rows = [
            [0, 0, 1, 0, 0, 0],
            [0, 0, 0, 1, 0, 0],
            [0, -m, -m, 0, 0, m],
            [m, 0, 0, -m, -m, 0],
            [c, 0, 0, -c, -c, 0],
            [0, c, c, 0, 0, -c],
        ]
        blocks = [[None] * 3 for _ in range(3)]
        for i in range(3):
            for j in range(3):
                (a, mb), (b, a2) = (
                    rows[2 * i][2 * j : 2 * j + 2],
                    rows[2 * i + 1][2 * j : 2 * j + 2],
                )
                if a != a2 or mb != -b:
                    raise ArithmeticError(f"block ({i}, {j}) of L is not of the form a I + b J")
                blocks[i][j] = mpmath.mpc(a, b)
        ev = mpmath.eig(mpmath.matrix(blocks), left=False, right=False)
        ev = sorted(ev, key=lambda z: abs(z))[1:]
        plus, minus = sorted(ev, key=lambda z: -z.real)
        roots = (plus, mpmath.conj(plus), mpmath.conj(minus), minus)
        if not plus.imag > 0 > minus.imag:  # pragma: no cover - would contradict (2.4)
            raise ArithmeticError("unexpected signs of the imaginary parts")
        beta = (plus.imag - minus.imag) / 2
        return MpSpectrum(float(plus.real), float(minus.real), float(beta), roots)


def float_spectrum(matrix: NDArray[np.float64]) -> MpSpectrum:
    """alpha1, alpha2, beta from numpy's eigensolver (accurate for mu0 up to about 10).

    Same selection as `mp_spectrum`; ``roots`` holds the four nonzero eigenvalues.
    """
    ev = np.linalg.eigvals(matrix)
    ev = ev[np.argsort(np.abs(ev))][2:]
    ev = ev[np.argsort(-ev.real)]
    return MpSpectrum(
        float(ev[:2].real.mean()),
        float(ev[2:].real.mean()),
        float(np.abs(ev.imag).mean()),
        tuple(complex(z) for z in ev),
    )


def expm_solution(matrix: NDArray[np.float64], z0: ArrayLike, t: ArrayLike) -> NDArray[np.float64]:
    """Return exp(L t) z0 for each t, shape (len(t), 6).

    Uses scipy's Pade scaling-and-squaring ``expm``: once per time, or, on a
    uniform grid, once for the first time and once for the step, which is
    then applied repeatedly.
    """
    z0 = np.asarray(z0, dtype=float)
    t = np.asarray(t, dtype=float)
    steps = np.diff(t)
    if t.size > 2 and np.allclose(steps, steps[0], rtol=1e-12, atol=0.0):
        step = scipy.linalg.expm(matrix * steps[0])
        out = np.empty((t.size, 6))
        out[0] = scipy.linalg.expm(matrix * t[0]) @ z0
        for i in range(1, t.size):
            out[i] = step @ out[i - 1]
        return out
    return np.array([scipy.linalg.expm(matrix * ti) @ z0 for ti in t])


def kernel_projection(matrix: NDArray[np.float64], z0: ArrayLike) -> NDArray[np.float64]:
    """Return (x0, y0) with z0 = x0 e1 + y0 e2 + L q for some q.

    Since 0 is a semisimple eigenvalue, R^6 = ker L + range L and (x0, y0) is
    unique; it is found from the least-squares solution of the 6x8 system
    [e1 e2 L] (x0, y0, q) = z0.
    """
    e1 = np.array([1.0, 0.0, 0.0, 0.0, 1.0, 0.0])
    e2 = np.array([0.0, 1.0, 0.0, 0.0, 0.0, 1.0])
    a = np.column_stack([e1, e2, matrix])
    sol, *_ = np.linalg.lstsq(a, np.asarray(z0, dtype=float), rcond=None)
    return sol[:2]


def invariant_residual(
    matrix: NDArray[np.float64], z: NDArray[np.float64], alpha: float, beta: float
) -> float:
    """Return max |(L^2 - 2 alpha L + alpha^2 + beta^2) z| / max |z| over the rows of z.

    Zero exactly when every row of z lies in the real invariant subspace of
    the eigenvalue pair alpha +- i beta.
    """
    q = matrix @ matrix - 2.0 * alpha * matrix + (alpha**2 + beta**2) * np.eye(6)
    return float(np.abs(z @ q.T).max() / np.abs(z).max())


@functools.cache
def symbolic_matrix() -> tuple[sp.Matrix, sp.Symbol, sp.Symbol]:
    """Return the sympy matrix L typed from the block form (1.7), and its symbols (mu0, k)."""
    mu0, k = sp.symbols("mu0 k", positive=True)
    i2, j2, z2 = sp.eye(2), sp.Matrix([[0, -1], [1, 0]]), sp.zeros(2)
    big = sp.BlockMatrix(
        [
            [z2, i2, z2],
            [mu0 * j2, -mu0 * i2, -mu0 * j2],
            [mu0 / k * i2, mu0 / k * j2, -mu0 / k * i2],
        ]
    ).as_explicit()
    return big, mu0, k


@functools.cache
def symbolic_char_poly_residual() -> str:
    """Return det(lambda I - L) - lambda^2 mu^4 P4(lambda), simplified, as a string.

    L is `symbolic_matrix`; P4, mu and eps are typed from (2.1)-(2.2).  The
    result is ``"0"`` exactly when (2.1) holds for every mu0 > 0 and k > 0.
    """
    big, mu0, k = symbolic_matrix()
    lam = sp.Symbol("lambda")
    det = (lam * sp.eye(6) - big).det(method="berkowitz")
    mu = mu0 * (k + 1) / (2 * k)
    eps = 4 * k**2 / (mu0 * (k + 1) ** 2)
    p4 = (lam / mu) ** 4 + 4 * (lam / mu) ** 3 + 4 * (lam / mu) ** 2 + eps**2
    return str(sp.cancel(det - lam**2 * mu**4 * p4))


def no_slip_frequency(k: float) -> float:
    """Angular rate of the centre for rolling without slipping, from the constraint.

    With u = v + gamma x w - gamma x r = 0 kept by a contact force F
    (dv/dt = F, k dw/dt = -gamma x F), differentiating the constraint gives
    (I - (gamma x)^2 / k) F = gamma x v.  The velocity then obeys
    dv/dt = M v with M solved for numerically here; its eigenvalues are
    +- i omega and omega is returned.
    """
    jmat = np.array([[0.0, -1.0], [1.0, 0.0]])  # gamma x (.) on horizontal vectors
    a = np.eye(2) - (jmat @ jmat) / k
    m = np.linalg.solve(a, jmat)
    ev = np.linalg.eigvals(m)
    return float(np.abs(ev.imag).max())


def log_log_slope(x: ArrayLike, y: ArrayLike) -> float:
    """Least-squares slope of log |y| against log x."""
    x = np.asarray(x, dtype=float)
    y = np.abs(np.asarray(y, dtype=float))
    return float(np.polyfit(np.log(x), np.log(y), 1)[0])
