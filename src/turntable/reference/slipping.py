"""Independent references of the slipping ball: the matrix L, its spectrum, the solution.

Nothing here uses the closed forms of `turntable` (`spectrum`, `solution`, ...); see
`turntable.reference` for what each function recomputes and how.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, NamedTuple

import mpmath
import numpy as np
from numpy.typing import ArrayLike, NDArray

if TYPE_CHECKING:
    import sympy as sp

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
    import sympy as sp

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
    import sympy as sp

    big, mu0, k = symbolic_matrix()
    lam = sp.Symbol("lambda")
    det = (lam * sp.eye(6) - big).det(method="berkowitz")
    mu = mu0 * (k + 1) / (2 * k)
    eps = 4 * k**2 / (mu0 * (k + 1) ** 2)
    p4 = (lam / mu) ** 4 + 4 * (lam / mu) ** 3 + 4 * (lam / mu) ** 2 + eps**2
    return str(sp.cancel(det - lam**2 * mu**4 * p4))


@functools.cache
def _matrix_function() -> Any:
    import sympy as sp

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
    import sympy as sp

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
    import scipy.linalg

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
