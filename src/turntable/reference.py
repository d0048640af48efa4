"""Independent reference computations, used by the claims checks, the tests and the benchmarks.

Nothing here uses the closed forms of `turntable` (`spectrum`, `solution`, ...).  Each
quantity is recomputed another way, most of them at high precision:

- the matrix L of (1.7): from the vector equations (1.6) with cross products
  (`matrix_from_equations`), from the block form typed in sympy (`symbolic`,
  `reference_matrix`) and typed in mpmath from the exact doubles mu0, k
  (`mp_system_matrix`);
- its eigenvalues: mpmath's QR algorithm at `DPS` digits (`mp_spectrum`), the roots of
  the sympy characteristic polynomial at `ROOTS_DPS` digits (`exact_roots`), the textbook
  formula (2.4) at a precision that absorbs its cancellation (`textbook_spectrum`), and
  numpy's eigensolver (`float_spectrum`);
- the solution exp(L t) z0: mpmath's matrix exponential (`expm_trajectories`) and
  scipy's (`expm_solution`);
- the spiral centre and the modal parts: a least-squares solve (`kernel_projection`)
  and the eigendecomposition (`eig_kernel_part`, `eig_mode_part`);
- the slip velocity and the conserved quantities written out from their definitions,
  and the no-slip rate from the constraint;
- the rolling-resistance model of `turntable.rolling`: its 4x4 matrix read off the
  constrained three-dimensional Newton-Euler equations in mpmath (`rolling_matrix`), its
  eigenvalues (`rolling_spectrum`), its solution (`rolling_solution`), the coefficients
  of equal decay (`rolling_equal_decay_delta`) and of equal power on the same path
  (`rolling_equal_power_delta`, from an eigenvector of L) at `ROLLING_DPS` digits; `rolling` holds
  them under the names of `turntable.rolling` (``rolling.spectrum``, ...).

Every function is deterministic: the same input gives the same output bit for bit.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any, NamedTuple

import mpmath
import numpy as np
import scipy.linalg
import sympy as sp
from numpy.typing import ArrayLike, NDArray

#: Inertia ratio of a homogeneous ball.
K_BALL = 2.0 / 5.0

#: Digits of the mpmath eigenvalue computations (`mp_spectrum`).
DPS = 40

#: Digits of the roots of the characteristic polynomial (`exact_roots`).
ROOTS_DPS = 60

_GAMMA = np.array([0.0, 0.0, 1.0])


# --------------------------------------------------------------------------------------
# The matrix L, from the equations and from its block form
# --------------------------------------------------------------------------------------


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


@dataclass(frozen=True)
class Symbolic:
    """The matrix L of (1.7) and its characteristic polynomial, in sympy."""

    mu0: sp.Symbol
    k: sp.Symbol
    lam: sp.Symbol
    L: sp.Matrix
    char_poly: sp.Expr
    quartic: sp.Poly


@functools.cache
def symbolic() -> Symbolic:
    """Build L from the block structure of (1.7) and expand det(lambda I - L).

    ``quartic`` is det(lambda I - L) / lambda^2 as a polynomial in lambda
    (the division is exact; `tests/test_spectrum.py` checks it).
    """
    mu0, k, lam = sp.symbols("mu0 k lambda", positive=True)
    i2 = sp.eye(2)
    j = sp.Matrix([[0, -1], [1, 0]])
    o = sp.zeros(2)
    L = sp.Matrix(
        sp.BlockMatrix(
            [
                [o, i2, o],
                [mu0 * j, -mu0 * i2, -mu0 * j],
                [mu0 / k * i2, mu0 / k * j, -mu0 / k * i2],
            ]
        )
    )
    char_poly = sp.expand((lam * sp.eye(6) - L).det(method="berkowitz"))
    quartic, _ = sp.div(sp.Poly(char_poly, lam), sp.Poly(lam**2, lam))
    return Symbolic(mu0, k, lam, L, char_poly, quartic)


def symbolic_matrix() -> tuple[sp.Matrix, sp.Symbol, sp.Symbol]:
    """Return the sympy matrix L typed from the block form (1.7), and its symbols (mu0, k)."""
    s = symbolic()
    return s.L, s.mu0, s.k


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


@functools.cache
def _matrix_function() -> Any:
    s = symbolic()
    return sp.lambdify((s.mu0, s.k), s.L, modules="numpy")


def reference_matrix(mu0: float, k: float) -> NDArray[np.float64]:
    """L of (1.7) evaluated from the sympy matrix of `symbolic`."""
    return np.asarray(_matrix_function()(mu0, k), dtype=float)


def mp_system_matrix(mu0: float, k: float) -> mpmath.matrix:
    """Build L of (1.7) in the current mpmath precision from the exact doubles mu0, k.

    Built entry by entry from the paper's block form, so that its entry mu0 / k
    carries the working precision (in double precision it is rounded).
    """
    m = mpmath.mpf(mu0)
    q = m / mpmath.mpf(k)
    L = mpmath.zeros(6, 6)
    L[0, 2] = L[1, 3] = 1
    # rows of v: mu0 J r - mu0 v - mu0 J w, with J = [[0, -1], [1, 0]]
    L[2, 1], L[3, 0] = -m, m
    L[2, 2] = L[3, 3] = -m
    L[2, 5], L[3, 4] = m, -m
    # rows of w: (mu0/k) (r + J v - w)
    L[4, 0] = L[5, 1] = q
    L[4, 3], L[5, 2] = -q, q
    L[4, 4] = L[5, 5] = -q
    return L


# --------------------------------------------------------------------------------------
# Eigenvalues
# --------------------------------------------------------------------------------------


class MpSpectrum(NamedTuple):
    """Nonzero eigenvalues of L from mpmath, as floats and as mpmath numbers."""

    alpha1: float
    alpha2: float
    beta: float
    roots: tuple[mpmath.mpc, ...]


@functools.lru_cache(maxsize=512)
def mp_spectrum(mu0: float, k: float) -> MpSpectrum:
    """Eigenvalues of L computed by mpmath's QR algorithm with `DPS` digits.

    The 6x6 matrix is `mp_system_matrix` at `DPS` digits.  Each of its 2x2
    blocks is checked to be of the form a I + b J; J squares to -I, so L is
    the real form of the complex 3x3 matrix with entries a + i b, and the
    spectrum of L is the spectrum of that matrix together with its complex
    conjugate.  The 3x3 problem is solved (six times faster than the 6x6
    one); of its eigenvalues the one of smallest modulus (the kernel) is
    dropped, the other two are alpha1 + i beta and alpha2 - i beta.
    """
    with mpmath.workdps(DPS):
        big = mp_system_matrix(mu0, k)
        blocks = [[None] * 3 for _ in range(3)]
        for i in range(3):
            for j in range(3):
                a, mb = big[2 * i, 2 * j], big[2 * i, 2 * j + 1]
                b, a2 = big[2 * i + 1, 2 * j], big[2 * i + 1, 2 * j + 1]
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


@functools.cache
def _quartic_coefficients() -> Any:
    s = symbolic()
    return sp.lambdify((s.mu0, s.k), s.quartic.all_coeffs(), modules="mpmath")


def exact_roots(mu0: float, k: float) -> list[mpmath.mpc]:
    """The four nonzero roots of det(lambda I - L) (sympy) to `ROOTS_DPS` digits.

    Returned in the order of `turntable.eigenvalues`: (alpha1 + i beta,
    alpha1 - i beta, alpha2 + i beta, alpha2 - i beta), i.e. by decreasing
    real part, then decreasing imaginary part.
    """
    with mpmath.workdps(ROOTS_DPS):
        coeffs = _quartic_coefficients()(mpmath.mpf(mu0), mpmath.mpf(k))
        roots = mpmath.polyroots(coeffs, maxsteps=400, extraprec=4 * ROOTS_DPS)
        return sorted(roots, key=lambda z: (-z.real, -z.imag))


def reference_dps(mu0: float, k: float, digits: int = 50) -> int:
    """Return the mpmath precision that leaves ``digits`` correct digits in (2.4).

    In mu (-1 + sqrt(1 + i eps)) the real part of sqrt(1 + i eps) is
    1 + eps^2/8 + O(eps^4) when eps -> 0 (mu0 -> infinity), so the sum
    -1 + Re sqrt(...) cancels about log10(8 / eps^2) leading digits.  Adding
    that many digits (plus 10 guard digits) to the working precision keeps
    ``digits`` correct digits in alpha1; alpha2 and beta never cancel.
    """
    eps = 4.0 * k * k / (mu0 * (k + 1.0) ** 2)
    lost = max(0, math.ceil(math.log10(8.0) - 2.0 * math.log10(eps)))
    return digits + lost + 10


def textbook_spectrum(mu0: float, k: float, dps: int) -> tuple[mpmath.mpf, ...]:
    """Return (alpha1, alpha2, beta) from the textbook roots (2.4), in mpmath.

    lambda_1 = mu (-1 + sqrt(1 + i eps)), lambda_3 = mu (-1 - sqrt(1 + i eps)),
    with mu and eps of (2.2) computed from the exact double values of mu0, k.
    This is the plain formula of the paper, not the rewritten one of
    `turntable.spectrum`; the cancellation is absorbed by the precision
    (see `reference_dps`).
    """
    with mpmath.workdps(dps):
        m, kk = mpmath.mpf(mu0), mpmath.mpf(k)
        mu = m * (kk + 1) / (2 * kk)
        eps = 4 * kk**2 / (m * (kk + 1) ** 2)
        root = mpmath.sqrt(mpmath.mpc(1, eps))
        lam1 = mu * (-1 + root)
        lam3 = mu * (-1 - root)
        return +lam1.real, +lam3.real, +lam1.imag


# --------------------------------------------------------------------------------------
# Solutions and projections
# --------------------------------------------------------------------------------------


def expm_trajectories(
    z0s: Sequence[Sequence[float]], t: Sequence[float], mu0: float, k: float, dps: int
) -> NDArray[np.object_]:
    """Return exp(L t) z0 in mpmath for every z0 and t, shape (len(z0s), len(t), 6).

    ``mpmath.expm`` (scaling and squaring of a Taylor series) of L t with L
    built by `mp_system_matrix` at ``dps`` digits; t and z0 are taken as exact
    doubles.  The entries are mpmath numbers.
    """
    out = np.empty((len(z0s), len(t), 6), dtype=object)
    with mpmath.workdps(dps):
        L = mp_system_matrix(mu0, k)
        vecs = [mpmath.matrix([mpmath.mpf(float(c)) for c in z0]) for z0 in z0s]
        for j, tj in enumerate(t):
            E = mpmath.expm(L * mpmath.mpf(float(tj)))
            for i, v in enumerate(vecs):
                out[i, j] = list(E * v)
    return out


def expm_solution(matrix: NDArray[np.float64], z0: ArrayLike, t: ArrayLike) -> NDArray[np.float64]:
    """Return exp(L t) z0 for each t, shape (len(t), 6), in double precision.

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


def eig_kernel_part(z0: NDArray[np.float64], mu0: float, k: float) -> NDArray[np.float64]:
    """Component of z0 on ker L along the invariant subspace of the nonzero roots.

    Spectral projection from numpy's eigendecomposition of `reference_matrix`:
    write z0 in the eigenbasis and keep the coordinates of the two
    eigenvalues that vanish.
    """
    lam, vec = np.linalg.eig(reference_matrix(mu0, k))
    coords = np.linalg.solve(vec, np.asarray(z0, dtype=complex))
    scale = np.abs(lam).max()
    keep = np.abs(lam) < 1e-8 * scale
    if keep.sum() != 2:  # pragma: no cover - L has a double zero eigenvalue
        raise ArithmeticError(f"expected two zero eigenvalues, got {lam}")
    return np.real(vec[:, keep] @ coords[keep])


def eig_mode_part(
    z0: NDArray[np.float64], mu0: float, k: float, growing: bool
) -> NDArray[np.float64]:
    """Component of z0 on the growing (Re > 0) or decaying (Re < 0, nonzero) modes."""
    lam, vec = np.linalg.eig(reference_matrix(mu0, k))
    coords = np.linalg.solve(vec, np.asarray(z0, dtype=complex))
    scale = np.abs(lam).max()
    nonzero = np.abs(lam) >= 1e-8 * scale
    keep = nonzero & ((lam.real > 0) if growing else (lam.real < 0))
    if keep.sum() != 2:  # pragma: no cover - two modes of each kind by (2.6)
        raise ArithmeticError(f"expected two modes, got {lam}")
    return np.real(vec[:, keep] @ coords[keep])


def mp_decaying_distance_ratio(z0: ArrayLike, mu0: float, k: float, t: float) -> float:
    """Distance from the equilibrium after time ``t`` over that at 0, on the decaying subspace.

    The decaying part of ``z0`` (the modes with negative real part, from mpmath's
    eigendecomposition of `mp_system_matrix` at `DPS` digits) is evolved with
    ``mpmath.expm`` at the same precision, so that rounding does not seed the growing
    modes (which grow by exp(alpha1 t)); the ratio of its norms at t and 0 is returned.
    In the complex form the decaying part is one mode c exp(lambda_- t) q, so the ratio is
    exp(alpha2 t) exactly.
    """
    with mpmath.workdps(DPS):
        L = mp_system_matrix(mu0, k)
        lam, vec = mpmath.eig(L)
        coords = mpmath.lu_solve(vec, mpmath.matrix([mpmath.mpf(float(c)) for c in z0]))
        scale = max(abs(x) for x in lam)
        keep = [i for i, x in enumerate(lam) if mpmath.re(x) < -(mpmath.mpf(10) ** -20) * scale]
        if len(keep) != 2:  # pragma: no cover - two decaying modes by (2.6)
            raise ArithmeticError(f"expected two decaying modes, got {lam}")
        part = sum((vec[:, i] * coords[i] for i in keep), mpmath.matrix(6, 1))
        part = mpmath.matrix([mpmath.re(x) for x in part])
        later = mpmath.expm(L * mpmath.mpf(float(t))) * part
        return float(mpmath.norm(later) / mpmath.norm(part))


def invariant_residual(
    matrix: NDArray[np.float64], z: NDArray[np.float64], alpha: float, beta: float
) -> float:
    """Return max |(L^2 - 2 alpha L + alpha^2 + beta^2) z| / max |z| over the rows of z.

    Zero exactly when every row of z lies in the real invariant subspace of
    the eigenvalue pair alpha +- i beta.
    """
    q = matrix @ matrix - 2.0 * alpha * matrix + (alpha**2 + beta**2) * np.eye(6)
    return float(np.abs(z @ q.T).max() / np.abs(z).max())


# --------------------------------------------------------------------------------------
# Definitions written out
# --------------------------------------------------------------------------------------


def slip_by_definition(z: NDArray[np.float64]) -> NDArray[np.float64]:
    """u = v + gamma x w - gamma x r, planar part, from 3-D cross products; shape (n, 2)."""
    z = np.atleast_2d(z)
    zeros = np.zeros(z.shape[0])
    r = np.column_stack([z[:, 0], z[:, 1], zeros])
    v = np.column_stack([z[:, 2], z[:, 3], zeros])
    w = np.column_stack([z[:, 4], z[:, 5], zeros])
    u = v + np.cross(_GAMMA, w) - np.cross(_GAMMA, r)
    return u[:, :2]


def conserved_by_definition(z: NDArray[np.float64], k: float) -> NDArray[np.float64]:
    """(k wx - vy, k wy + vx) written out from the state components; shape (n, 2)."""
    z = np.atleast_2d(z)
    return np.column_stack([k * z[:, 4] - z[:, 3], k * z[:, 5] + z[:, 2]])


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


# --------------------------------------------------------------------------------------
# The rolling-resistance model (`turntable.rolling`)
# --------------------------------------------------------------------------------------
#
# Nothing here uses the reduction (R4) or the closed forms of `turntable.rolling`: the 4x4
# matrix is read off the constrained three-dimensional Newton-Euler equations, evaluated in
# mpmath (reaction force as Lagrange multiplier, cross products, a 3x3 linear solve), and
# the eigenvalues and the solution come from mpmath's eigensolver and matrix exponential.

#: Decimal digits of the references of the rolling model.
ROLLING_DPS = 50


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


def rolling_matrix(delta: float, k: float) -> mpmath.matrix:
    """Return the rolling model's 4x4 matrix on (x, y, vx, vy) at `ROLLING_DPS` digits.

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
    with mpmath.workdps(ROLLING_DPS):
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


def rolling_spectrum(delta: float, k: float) -> MpRollingSpectrum:
    """Return the rolling model's eigenvalues from mpmath.eig of `rolling_matrix`.

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
    with mpmath.workdps(ROLLING_DPS):
        ev = mpmath.eig(rolling_matrix(delta, k), left=False, right=False)
        grow = max((e for e in ev if mpmath.re(e) > 0), key=lambda e: mpmath.im(e))
        cent = min((e for e in ev if mpmath.re(e) < 0), key=lambda e: mpmath.im(e))
        return MpRollingSpectrum(
            float(mpmath.re(grow)),
            float(mpmath.im(grow)),
            float(mpmath.re(cent)),
            float(mpmath.im(cent)),
        )


def rolling_solution(z0: ArrayLike, t: ArrayLike, delta: float, k: float) -> NDArray[np.float64]:
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
        exp(M t) (x, y, vx, vy) with M = `rolling_matrix`, by mpmath.expm at
        `ROLLING_DPS` digits; w = (x - vy, y + vx) from the no-slip constraint.
    """
    z0 = np.asarray(z0, dtype=float)
    out = []
    with mpmath.workdps(ROLLING_DPS):
        m = rolling_matrix(delta, k)
        x0 = mpmath.matrix([mpmath.mpf(float(c)) for c in z0[:4]])
        for ti in np.asarray(t, dtype=float):
            x = mpmath.expm(m * mpmath.mpf(float(ti))) * x0
            out.append([float(c) for c in (x[0], x[1], x[2], x[3], x[0] - x[3], x[1] + x[2])])
    return np.array(out)


def rolling_equal_decay_delta(mu0: float, k: float) -> float:
    """Return delta with |Re lambda_c(delta)| = |alpha2(mu0)|, at `ROLLING_DPS` digits.

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
    with mpmath.workdps(ROLLING_DPS):
        kk, m = mpmath.mpf(k), mpmath.mpf(mu0)
        mu = m * (kk + 1) / (2 * kk)
        eps = 4 * kk**2 / (m * (kk + 1) ** 2)
        alpha2 = mu * (-1 - mpmath.re(mpmath.sqrt(1 + 1j * eps)))

        def re_centre(d: mpmath.mpf) -> mpmath.mpf:
            roots = mpmath.polyroots(
                [kk + 1, d - 1j * kk, -1j * d], maxsteps=200, extraprec=2 * ROLLING_DPS
            )
            return min(mpmath.re(r) for r in roots)

        bracket = (-alpha2 * kk / 2, -alpha2 * 4 * (kk + 1))
        return float(mpmath.findroot(lambda d: re_centre(d) - alpha2, bracket, solver="anderson"))


def rolling_equal_power_delta(mu0: float, k: float) -> float:
    """Return delta at which rolling along the slipping path dissipates the slipping power.

    Parameters
    ----------
    mu0, k : float
        Slipping friction coefficient and inertia ratio.

    Returns
    -------
    float
        mu0 |u|^2 / |w_roll|^2 on the slipping model's growing mode, at `ROLLING_DPS`
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
    with mpmath.workdps(ROLLING_DPS + lost + 10):
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


@dataclass(frozen=True)
class RollingReferences:
    """The references of the rolling model under the names of `turntable.rolling`.

    ``from turntable.reference import rolling as ref`` gives ``ref.spectrum``,
    ``ref.solution``, ... next to the functions they check.
    """

    DPS: int
    matrix: Callable[[float, float], mpmath.matrix]
    spectrum: Callable[[float, float], MpRollingSpectrum]
    solution: Callable[[ArrayLike, ArrayLike, float, float], NDArray[np.float64]]
    equal_decay_delta: Callable[[float, float], float]
    equal_power_delta: Callable[[float, float], float]


#: The rolling model's references: `rolling_matrix`, `rolling_spectrum`, ...
rolling = RollingReferences(
    DPS=ROLLING_DPS,
    matrix=rolling_matrix,
    spectrum=rolling_spectrum,
    solution=rolling_solution,
    equal_decay_delta=rolling_equal_decay_delta,
    equal_power_delta=rolling_equal_power_delta,
)
