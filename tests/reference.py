"""Independent reference computations and parameter grids shared by the tests.

The references here do not call `turntable`: the matrix L is rebuilt with
sympy from its block structure (1.7), its characteristic polynomial and
kernel come from sympy, its roots from mpmath at high precision, and the
spectral projectors from numpy's eigendecomposition of that sympy matrix.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Any

import mpmath
import numpy as np
import pytest
import sympy as sp
from numpy.typing import NDArray

#: Inertia ratio of a homogeneous ball.
K_BALL = 2.0 / 5.0

#: Digits used by the mpmath references.
DPS = 60


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


@functools.cache
def _matrix_function() -> Any:
    s = symbolic()
    return sp.lambdify((s.mu0, s.k), s.L, modules="numpy")


def reference_matrix(mu0: float, k: float) -> NDArray[np.float64]:
    """L of (1.7) evaluated from the sympy matrix (not from `turntable`)."""
    return np.asarray(_matrix_function()(mu0, k), dtype=float)


@functools.cache
def _quartic_coefficients() -> Any:
    s = symbolic()
    return sp.lambdify((s.mu0, s.k), s.quartic.all_coeffs(), modules="mpmath")


def exact_roots(mu0: float, k: float) -> list[mpmath.mpc]:
    """The four nonzero roots of det(lambda I - L) to ``DPS`` digits.

    Returned in the order of `turntable.eigenvalues`: (alpha1 + i beta,
    alpha1 - i beta, alpha2 + i beta, alpha2 - i beta), i.e. by decreasing
    real part, then decreasing imaginary part.
    """
    with mpmath.workdps(DPS):
        coeffs = _quartic_coefficients()(mpmath.mpf(mu0), mpmath.mpf(k))
        roots = mpmath.polyroots(coeffs, maxsteps=400, extraprec=4 * DPS)
        return sorted(roots, key=lambda z: (-z.real, -z.imag))


def kernel_projection(z0: NDArray[np.float64], mu0: float, k: float) -> NDArray[np.float64]:
    """Component of z0 on ker L along the invariant subspace of the nonzero roots.

    Spectral projection from numpy's eigendecomposition of `reference_matrix`:
    write z0 in the eigenbasis and keep the coordinates of the two
    eigenvalues that vanish.
    """
    lam, vec = np.linalg.eig(reference_matrix(mu0, k))
    coords = np.linalg.solve(vec, np.asarray(z0, dtype=complex))
    scale = np.abs(lam).max()
    keep = np.abs(lam) < 1e-8 * scale
    assert keep.sum() == 2, lam
    return np.real(vec[:, keep] @ coords[keep])


def mode_projection(
    z0: NDArray[np.float64], mu0: float, k: float, growing: bool
) -> NDArray[np.float64]:
    """Component of z0 on the growing (Re > 0) or decaying (Re < 0, nonzero) modes."""
    lam, vec = np.linalg.eig(reference_matrix(mu0, k))
    coords = np.linalg.solve(vec, np.asarray(z0, dtype=complex))
    scale = np.abs(lam).max()
    nonzero = np.abs(lam) >= 1e-8 * scale
    keep = nonzero & ((lam.real > 0) if growing else (lam.real < 0))
    assert keep.sum() == 2, lam
    return np.real(vec[:, keep] @ coords[keep])


def slip_by_definition(z: NDArray[np.float64]) -> NDArray[np.float64]:
    """u = v + gamma x w - gamma x r, planar part, from 3-D cross products."""
    z = np.atleast_2d(z)
    zeros = np.zeros(z.shape[0])
    r = np.column_stack([z[:, 0], z[:, 1], zeros])
    v = np.column_stack([z[:, 2], z[:, 3], zeros])
    w = np.column_stack([z[:, 4], z[:, 5], zeros])
    gamma = np.array([0.0, 0.0, 1.0])
    u = v + np.cross(gamma, w) - np.cross(gamma, r)
    return u[:, :2]


def conserved_by_definition(z: NDArray[np.float64], k: float) -> NDArray[np.float64]:
    """(k wx - vy, k wy + vx) written out from the state components."""
    z = np.atleast_2d(z)
    return np.column_stack([k * z[:, 4] - z[:, 3], k * z[:, 5] + z[:, 2]])


def log_log_slope(x: NDArray[np.float64], y: NDArray[np.float64]) -> float:
    """Least-squares slope of log|y| against log x."""
    return float(np.polyfit(np.log(x), np.log(np.abs(y)), 1)[0])


# Parametrized grids shared by several modules -------------------------------

K_PARAMS = [
    pytest.param(2.0 / 5.0, id="k=2/5"),
    pytest.param(2.0 / 3.0, id="k=2/3"),
    pytest.param(1.0, id="k=1"),
]
MU0_PARAMS = [
    pytest.param(0.1, id="mu0=0.1"),
    pytest.param(1.0, id="mu0=1"),
    pytest.param(10.0, id="mu0=10"),
]
