"""Claims of Section 2 about L: characteristic polynomial, kernel, roots, stability.

References: the sympy matrix built from the block structure of (1.7) and its
characteristic polynomial, roots of that polynomial found by mpmath at 60
digits, and numpy's eigenvalues of L.
"""

from __future__ import annotations

import mpmath
import numpy as np
import pytest
import sympy as sp
from hypothesis import given
from hypothesis import strategies as st
from numpy.testing import assert_allclose

import turntable as tt
from turntable.reference import (
    exact_roots,
    reference_matrix,
    slip_by_definition,
    symbolic,
)

K_ROOTS = [
    pytest.param(0.05, id="k=0.05"),
    pytest.param(0.4, id="k=0.4"),
    pytest.param(2.0 / 3.0, id="k=2/3"),
    pytest.param(1.0, id="k=1"),
]
MU0_WIDE = [pytest.param(m, id=f"mu0=1e{e:+d}") for e in range(-6, 7) for m in [10.0**e]]
MU0_MODERATE = [pytest.param(m, id=f"mu0={m:.3g}") for m in np.logspace(-2, 2, 9)]

E1 = np.array([1.0, 0.0, 0.0, 0.0, 1.0, 0.0])
E2 = np.array([0.0, 1.0, 0.0, 0.0, 0.0, 1.0])

log10_mu0 = st.floats(min_value=-6.0, max_value=6.0)
# k in (0, 1]; below ~1e-100 alpha1 ~ (k/(k+1))^3 / mu0 underflows a double.
k_unit = st.floats(min_value=1e-6, max_value=1.0)


def test_spectrum_char_poly() -> None:
    """spectrum.char_poly: det(lambda I - L) = lambda^2 mu^4 P4(lambda), (2.1)-(2.2)."""
    s = symbolic()
    mu0, k, lam = s.mu0, s.k, s.lam
    mu = mu0 * (k + 1) / (2 * k)
    eps = 4 * k**2 / (mu0 * (k + 1) ** 2)
    p4 = (lam / mu) ** 4 + 4 * (lam / mu) ** 3 + 4 * (lam / mu) ** 2 + eps**2
    assert sp.simplify(s.char_poly - lam**2 * mu**4 * p4) == 0
    # The factorisation: lambda^2 splits off exactly, and the quartic is
    # mu^4 P4 = (lambda^2 + 2 mu lambda)^2 + mu0^2, which has no root at 0.
    _, remainder = sp.div(sp.Poly(s.char_poly, lam), sp.Poly(lam**2, lam))
    assert remainder.is_zero
    assert sp.simplify(s.quartic.as_expr() - ((lam**2 + 2 * mu * lam) ** 2 + mu0**2)) == 0
    assert sp.simplify(s.quartic.as_expr().subs(lam, 0) - mu0**2) == 0
    assert lam**2 in sp.Mul.make_args(sp.factor(s.char_poly))


@pytest.mark.parametrize(
    ("mu0", "k"),
    [
        pytest.param(0.37, 0.4, id="mu0=0.37-k=0.4"),
        pytest.param(2.9, 2.0 / 3.0, id="mu0=2.9-k=2/3"),
        pytest.param(1e-3, 1.0, id="mu0=1e-3-k=1"),
        pytest.param(1e4, 0.05, id="mu0=1e4-k=0.05"),
    ],
)
def test_system_matrix_matches_symbolic(mu0: float, k: float) -> None:
    """turntable.system_matrix is the block matrix (1.7) built in sympy."""
    assert_allclose(tt.system_matrix(mu0, k), reference_matrix(mu0, k), rtol=1e-15, atol=0)


def test_system_matrix_random_values() -> None:
    """system_matrix equals the sympy matrix at random (mu0, k)."""
    rng = np.random.default_rng(20190206)
    for mu0, k in zip(10.0 ** rng.uniform(-4, 4, 20), rng.uniform(0.01, 2.0, 20), strict=True):
        assert_allclose(tt.system_matrix(mu0, k), reference_matrix(mu0, k), rtol=1e-15, atol=0)


def test_spectrum_kernel() -> None:
    """spectrum.kernel: ker L = span(e1, e2), (2.3), from sympy's nullspace."""
    s = symbolic()
    basis = s.L.nullspace()
    assert len(basis) == 2
    e12 = sp.Matrix.hstack(sp.Matrix(E1.astype(int)), sp.Matrix(E2.astype(int)))
    # The nullspace and span(e1, e2) are the same 2-D space.
    assert sp.Matrix.hstack(*basis, e12).rank() == 2
    assert sp.simplify(s.L * e12) == sp.zeros(6, 2)


@pytest.mark.parametrize(
    "mu0", [pytest.param(m, id=f"mu0={m:g}") for m in (1e-6, 0.1, 1.0, 1e3, 1e6)]
)
def test_kernel_numeric(mu0: float, k: float) -> None:
    """spectrum.kernel: system_matrix annihilates e1 and e2 (exactly, in floats)."""
    L = tt.system_matrix(mu0, k)
    assert_allclose(L @ E1, 0.0, rtol=0, atol=0)
    assert_allclose(L @ E2, 0.0, rtol=0, atol=0)


@pytest.mark.parametrize(
    ("xc", "yc"),
    [pytest.param(0.0, 1.0, id="(0,1)"), pytest.param(-2.5, 0.75, id="(-2.5,0.75)")],
)
def test_fixed_point_rolls_without_slip(xc: float, yc: float, mu0: float, k: float) -> None:
    """spectrum.kernel: at z_c = xc e1 + yc e2 the slip is 0, w = (xc, yc), z stays put."""
    zc = xc * E1 + yc * E2
    assert_allclose(slip_by_definition(zc), 0.0, rtol=0, atol=0)
    assert_allclose(tt.slip_velocity(zc), 0.0, rtol=0, atol=0)
    assert_allclose(zc[4:], [xc, yc], rtol=0, atol=0)
    t = np.linspace(0.0, 50.0, 11)
    assert_allclose(tt.solve(zc, t, mu0, k), np.tile(zc, (t.size, 1)), rtol=0, atol=1e-14)


@pytest.mark.parametrize("k", K_ROOTS)
@pytest.mark.parametrize("mu0", MU0_WIDE)
def test_spectrum_roots(mu0: float, k: float) -> None:
    """spectrum.roots: eigenvalues are the roots of the sympy char poly, rtol 1e-13.

    The roots are found by mpmath.polyroots at 60 digits from the
    coefficients of det(lambda I - L) / lambda^2; real and imaginary parts
    are compared separately (alpha1 is tiny next to |alpha2| at large mu0).
    """
    exact = exact_roots(mu0, k)
    ours = tt.eigenvalues(mu0, k)
    assert_allclose(ours.real, [float(z.real) for z in exact], rtol=1e-13, atol=0)
    assert_allclose(ours.imag, [float(z.imag) for z in exact], rtol=1e-13, atol=0)


@pytest.mark.parametrize("k", K_ROOTS)
@pytest.mark.parametrize("mu0", MU0_MODERATE)
def test_roots_match_numpy_eigvals(mu0: float, k: float) -> None:
    """spectrum.roots: numpy.linalg.eigvals(system_matrix) agrees at moderate mu0.

    LAPACK's error is absolute, about 1e-16 ||L||, so the tolerance is
    atol = 1e-13 ||L|| on each part (plus rtol 1e-12).
    """
    L = tt.system_matrix(mu0, k)
    lam = np.linalg.eigvals(L)
    norm = np.linalg.norm(L, 2)
    order = np.argsort(np.abs(lam))
    assert_allclose(lam[order[:2]], 0.0, rtol=0, atol=1e-13 * norm)
    nonzero = sorted(lam[order[2:]], key=lambda z: (-z.real, -z.imag))
    ours = tt.eigenvalues(mu0, k)
    assert_allclose(ours.real, np.real(nonzero), rtol=1e-12, atol=1e-13 * norm)
    assert_allclose(ours.imag, np.imag(nonzero), rtol=1e-12, atol=1e-13 * norm)


def test_closed_forms_of_alpha_beta() -> None:
    """spectrum.roots: (2.5) alpha1 = mu(a-1), alpha2 = -mu(a+1), beta = mu b, at 60 digits."""
    with mpmath.workdps(60):
        for mu0, k in [(1e-4, 0.4), (0.3, 2.0 / 3.0), (7.0, 1.0), (3e5, 0.05)]:
            m, kk = mpmath.mpf(mu0), mpmath.mpf(k)
            mu = m * (kk + 1) / (2 * kk)
            eps = 4 * kk**2 / (m * (kk + 1) ** 2)
            a = mpmath.sqrt((mpmath.sqrt(1 + eps**2) + 1) / 2)
            b = mpmath.sqrt((mpmath.sqrt(1 + eps**2) - 1) / 2)
            s = tt.spectrum(mu0, k)
            expected = [mu * (a - 1), -mu * (a + 1), mu * b, mu, eps, a, b]
            got = [s.alpha1, s.alpha2, s.beta, s.mu, s.eps, s.a, s.b]
            assert_allclose(got, [float(x) for x in expected], rtol=1e-14, atol=0)
            # and (2.4): mu(-1 + sqrt(1 + i eps)) is the root alpha1 + i beta
            lam1 = mu * (-1 + mpmath.sqrt(1 + 1j * eps))
            assert mpmath.almosteq(lam1, mpmath.mpc(mu * (a - 1), mu * b), rel_eps=1e-30)


def test_quartic_has_no_imaginary_root() -> None:
    """spectrum.unstable_focus (symbolic): the lambda^1 term of mu^4 P4 vanishes.

    mu^4 P4 = lambda^4 + 4 mu lambda^3 + 4 mu^2 lambda^2 + mu0^2 has zero
    linear coefficient, so it is not Hurwitz and some root has Re >= 0; on
    the imaginary axis its imaginary part -4 mu w^3 vanishes only at w = 0,
    where its value is mu0^2 > 0.  Hence some root has Re > 0, and since the
    roots sum to -4 mu < 0 some root has Re < 0.
    """
    s = symbolic()
    coeffs = s.quartic.all_coeffs()
    assert len(coeffs) == 5
    assert sp.simplify(coeffs[3]) == 0
    w = sp.symbols("w", real=True)
    on_axis = sp.expand(s.quartic.as_expr().subs(s.lam, sp.I * w))
    mu = s.mu0 * (s.k + 1) / (2 * s.k)
    assert sp.simplify(sp.im(on_axis) + 4 * mu * w**3) == 0
    assert sp.simplify(coeffs[1] - 4 * mu) == 0


@given(log10_mu0=log10_mu0, k=k_unit)
def test_spectrum_unstable_focus(log10_mu0: float, k: float) -> None:
    """spectrum.unstable_focus: alpha2 < 0 < alpha1 for every mu0 > 0 and k > 0, (2.6)."""
    s = tt.spectrum(10.0**log10_mu0, k)
    assert s.alpha2 < 0.0 < s.alpha1
    assert s.beta > 0.0
