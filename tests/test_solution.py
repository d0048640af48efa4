"""Claims of Section 2 about the solution: decomposition, spiral centre, damping.

References: spectral projectors from numpy's eigendecomposition of the sympy
matrix L, the matrix exponential of that matrix (scipy), roots of the
characteristic polynomial at 60 digits (mpmath), and the reference table of
the project's notes (values re-derived at high precision; the paper does not print them).
"""

from __future__ import annotations

import mpmath
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from numpy.testing import assert_allclose
from scipy.linalg import expm
from scipy.optimize import brentq

import turntable as tt
from turntable.reference import (
    K_BALL,
    conserved_by_definition,
    eig_kernel_part,
    eig_mode_part,
    exact_roots,
    expm_solution,
    expm_trajectories,
    reference_matrix,
    slip_by_definition,
)

finite = st.floats(min_value=-10.0, max_value=10.0)
states = st.lists(finite, min_size=6, max_size=6).map(np.array)
k_unit = st.floats(min_value=1e-6, max_value=1.0)
k_moderate = st.floats(min_value=0.05, max_value=1.0)

STATES = [
    pytest.param(np.array([1.0, 1.0, 0.0, 0.0, 0.0, 0.0]), id="fig3"),
    pytest.param(np.array([1.0, 1.0, 0.0, 0.0, 0.0, 1.0]), id="fig4"),
    pytest.param(np.array([1.0, 1.0, 0.3, -0.2, 0.1, 0.5]), id="generic"),
]


def _exact_alpha_beta(mu0: float, k: float) -> tuple[float, float, float]:
    """(alpha1, alpha2, beta) from the 60-digit roots of the char poly."""
    roots = exact_roots(mu0, k)
    return float(roots[0].real), float(roots[2].real), float(roots[0].imag)


def _zeros(t: np.ndarray, f: np.ndarray, g) -> np.ndarray:
    """Zeros of g located by the sign changes of its samples f on t, refined with brentq."""
    idx = np.flatnonzero(np.sign(f[:-1]) * np.sign(f[1:]) < 0)
    return np.array([brentq(g, t[i], t[i + 1], xtol=1e-14, rtol=1e-15) for i in idx])


# --- solution.decomposition ------------------------------------------------------------


@pytest.mark.parametrize("z0", STATES)
def test_solution_decomposition(z0: np.ndarray, mu0: float, k: float) -> None:
    """solution.decomposition: z = z0 + z+ + z-, (2.7), terms are the spectral parts.

    The three terms sum to `solve`; at t = 0 the centre, growing and
    decaying terms are the projections of z(0) on ker L and on the
    invariant subspaces of alpha1 +- i beta and alpha2 +- i beta, computed
    from numpy's eigenvectors of L.
    """
    t = np.linspace(0.0, 20.0, 201)
    parts = tt.modal_terms(z0, t, mu0, k)
    total = parts.centre + parts.plus + parts.minus
    scale = np.max(np.abs(parts.centre) + np.abs(parts.plus) + np.abs(parts.minus))
    assert_allclose(total, tt.solve(z0, t, mu0, k), rtol=0, atol=1e-13 * scale)

    norm0 = np.linalg.norm(z0)
    assert_allclose(parts.centre[0], eig_kernel_part(z0, mu0, k), rtol=0, atol=1e-12 * norm0)
    assert_allclose(
        parts.plus[0], eig_mode_part(z0, mu0, k, growing=True), rtol=0, atol=1e-11 * norm0
    )
    assert_allclose(
        parts.minus[0], eig_mode_part(z0, mu0, k, growing=False), rtol=0, atol=1e-11 * norm0
    )
    # The centre term does not move.
    assert_allclose(parts.centre, np.tile(parts.centre[0], (t.size, 1)), rtol=0, atol=0)


@pytest.mark.parametrize("z0", STATES)
def test_growing_and_decaying_rates(z0: np.ndarray, mu0: float, k: float) -> None:
    """solution.decomposition: |z+| grows exactly like e^{alpha1 t}, |z-| decays like e^{alpha2 t}.

    alpha1, alpha2 are the 60-digit roots of the characteristic polynomial.
    Each term is one complex mode, so the ratio holds at every t, and in
    particular over one period T = 2 pi / beta.
    """
    alpha1, alpha2, beta = _exact_alpha_beta(mu0, k)
    period = 2.0 * np.pi / beta
    t = np.linspace(0.0, 2.0 * period, 101)
    plus = tt.modal_terms(z0, t, mu0, k).plus
    ratio = np.linalg.norm(plus, axis=1) / np.linalg.norm(plus[0])
    assert_allclose(ratio, np.exp(alpha1 * t), rtol=1e-12, atol=0)

    t_minus = np.linspace(0.0, min(2.0 * period, 300.0 / abs(alpha2)), 101)
    minus = tt.modal_terms(z0, t_minus, mu0, k).minus
    ratio = np.linalg.norm(minus, axis=1) / np.linalg.norm(minus[0])
    assert_allclose(ratio, np.exp(alpha2 * t_minus), rtol=1e-12, atol=0)


@pytest.mark.parametrize("z0", STATES)
def test_both_terms_oscillate_at_beta(z0: np.ndarray, mu0: float, k: float) -> None:
    """solution.decomposition: z+ and z- both turn at the angular rate beta.

    The planar part (x, y) of z+ turns counter-clockwise and that of z-
    clockwise, each at the rate beta of the 60-digit roots; x+ changes sign
    every pi / beta.
    """
    _, alpha2, beta = _exact_alpha_beta(mu0, k)
    half = np.pi / beta
    t = np.linspace(0.0, 4.2 * half, 841)
    plus = tt.modal_terms(z0, t, mu0, k).plus
    angle = np.unwrap(np.arctan2(plus[:, 1], plus[:, 0]))
    assert_allclose(angle - angle[0], beta * t, rtol=0, atol=1e-10)

    zeros = _zeros(t, plus[:, 0], lambda s: tt.modal_terms(z0, [s], mu0, k).plus[0, 0])
    assert zeros.size >= 4
    assert_allclose(np.diff(zeros), half, rtol=1e-10, atol=0)

    # z- shrinks by e^{|alpha2| t}: follow it while it stays far from underflow.
    t = np.linspace(0.0, min(4.2 * half, 300.0 / abs(alpha2)), 841)
    minus = tt.modal_terms(z0, t, mu0, k).minus
    angle = np.unwrap(np.arctan2(minus[:, 1], minus[:, 0]))
    assert_allclose(angle - angle[0], -beta * t, rtol=0, atol=1e-10)


# --- solution.centre ------------------------------------------------------------------


@pytest.mark.parametrize("z0", STATES)
def test_solution_centre(z0: np.ndarray, mu0: float, k: float) -> None:
    """solution.centre: (x0, y0) of (2.8) is the kernel component of z(0).

    The kernel component comes from numpy's eigendecomposition of L; it is
    x0 e1 + y0 e2, so its position and spin parts both equal (x0, y0).  The
    fixed point has the same conserved quantities as z(0).
    """
    centre = tt.spiral_centre(z0, k)
    proj = eig_kernel_part(z0, mu0, k)
    scale = np.linalg.norm(z0) / k
    assert_allclose(centre, proj[:2], rtol=0, atol=1e-12 * scale)
    assert_allclose(centre, proj[4:], rtol=0, atol=1e-12 * scale)
    assert_allclose(proj[2:4], 0.0, rtol=0, atol=1e-12 * scale)
    fixed = np.array([centre[0], centre[1], 0.0, 0.0, centre[0], centre[1]])
    assert_allclose(
        conserved_by_definition(fixed, k), conserved_by_definition(z0, k), rtol=1e-14, atol=1e-14
    )


@pytest.mark.parametrize("k", [pytest.param(K_BALL, id="k=2/5"), pytest.param(1.0, id="k=1")])
def test_centre_sign_of_vx_term(k: float) -> None:
    """solution.centre: y0 = wy(0) + vx(0)/k, with a plus sign (the OCR shows a minus).

    A ball pushed along +x with no spin: the kernel component from numpy's
    eigenvectors has y0 = +1/k, and the no-slip orbit (mu0 = 1e3, matrix
    exponential of L) circles about (0, +1/k), not (0, -1/k).
    """
    z0 = np.array([0.0, 0.0, 1.0, 0.0, 0.0, 0.0])
    assert_allclose(tt.spiral_centre(z0, k), [0.0, 1.0 / k], rtol=1e-15, atol=0)
    assert_allclose(eig_kernel_part(z0, 1.0, k)[:2], [0.0, 1.0 / k], rtol=0, atol=1e-12 / k)

    mu0 = 1e3
    period = 2.0 * np.pi * (k + 1.0) / k
    t = np.linspace(0.0, period, 401)[:-1]
    L = reference_matrix(mu0, k)
    orbit = np.array([expm(L * s) @ z0 for s in t])
    # After the initial layer the centre moves on a circle traversed at a
    # uniform rate: its mean over one period is the circle's centre.
    assert_allclose(orbit[:, :2].mean(axis=0), [0.0, 1.0 / k], rtol=0, atol=1e-2)
    radius = np.linalg.norm(orbit[:, :2] - [0.0, 1.0 / k], axis=1)
    assert_allclose(radius[10:], 1.0 / k, rtol=1e-2)


@given(z0=states, shift=st.tuples(finite, finite), k=k_moderate)
def test_centre_independent_of_position(z0: np.ndarray, shift: tuple, k: float) -> None:
    """solution.centre: (x0, y0) does not depend on r(0)."""
    moved = z0.copy()
    moved[:2] += shift
    assert_allclose(tt.spiral_centre(moved, k), tt.spiral_centre(z0, k), rtol=0, atol=0)


# --- solution.damping_ratio -----------------------------------------------------------


@given(log10_mu0=st.floats(min_value=-12.0, max_value=12.0), k=k_unit)
def test_solution_damping_ratio(log10_mu0: float, k: float) -> None:
    """solution.damping_ratio: |alpha2|/beta > 1, so ln N > 2 pi, (2.9)-(2.10)."""
    mu0 = 10.0**log10_mu0
    s = tt.spectrum(mu0, k)
    assert abs(s.alpha2) / s.beta > 1.0
    log_n = tt.log_damping_ratio(mu0, k)
    assert np.isfinite(log_n)
    assert log_n > 2.0 * np.pi


@pytest.mark.parametrize(
    "mu0", [pytest.param(m, id=f"mu0={m:g}") for m in (1e-9, 1e-3, 0.5, 20.0, 1e5)]
)
def test_damping_ratio_closed_form(mu0: float, k: float) -> None:
    """solution.damping_ratio: ln N = 2 pi (sqrt 2 + sqrt(h + 1)) / sqrt(h - 1), 60 digits."""
    with mpmath.workdps(60):
        m, kk = mpmath.mpf(mu0), mpmath.mpf(k)
        eps = 4 * kk**2 / (m * (kk + 1) ** 2)
        h = mpmath.sqrt(1 + eps**2)
        expected = 2 * mpmath.pi * (mpmath.sqrt(2) + mpmath.sqrt(h + 1)) / mpmath.sqrt(h - 1)
    assert_allclose(tt.log_damping_ratio(mu0, k), float(expected), rtol=1e-14, atol=0)
    alpha1, alpha2, beta = _exact_alpha_beta(mu0, k)
    assert_allclose(tt.log_damping_ratio(mu0, k), 2 * np.pi * abs(alpha2) / beta, rtol=1e-13)
    assert_allclose(tt.log_growth_per_turn(mu0, k), 2 * np.pi * alpha1 / beta, rtol=1e-13)


def test_damping_ratio_tends_to_two_pi(k: float) -> None:
    """solution.damping_ratio: ln N decreases to 2 pi as mu0 -> 0, never reaching it."""
    mu0 = np.logspace(-12, 12, 97)
    log_n = tt.log_damping_ratio(mu0, k)
    assert np.all(np.isfinite(log_n))
    assert np.all(np.diff(log_n) > 0.0)
    assert np.all(log_n > 2.0 * np.pi)
    assert log_n[0] - 2.0 * np.pi < 1e-4


def test_damping_ratio_value_near_zero_friction() -> None:
    """solution.damping_ratio: N = 543.89 at mu0 = 1e-6, k = 2/5; e^{2 pi} = 535.49."""
    assert_allclose(np.exp(tt.log_damping_ratio(1e-6, K_BALL)), 543.89, rtol=0, atol=0.01)
    assert_allclose(np.exp(2.0 * np.pi), 535.4916555, rtol=0, atol=1e-7)


@pytest.mark.parametrize("mu0", [pytest.param(m, id=f"mu0={m:g}") for m in (1e-3, 0.1, 1.0)])
def test_decaying_term_falls_by_n_per_period(mu0: float, k: float) -> None:
    """solution.damping_ratio: over T = 2 pi / beta, |z-| falls by the factor N."""
    z0 = np.array([1.0, 1.0, 0.0, 0.0, 0.0, 0.0])
    _, _, beta = _exact_alpha_beta(mu0, k)
    period = 2.0 * np.pi / beta
    minus = tt.modal_terms(z0, [0.3, 0.3 + period], mu0, k).minus
    log_ratio = np.log(np.linalg.norm(minus[0]) / np.linalg.norm(minus[1]))
    assert_allclose(log_ratio, tt.log_damping_ratio(mu0, k), rtol=1e-12)


# Reference table of the project's notes (k = 2/5, re-derived at high precision), with the
# digits given there: (mu0, alpha1, alpha2, beta, log10 N).
TABLE = [
    pytest.param(0.1, "0.0850090103", "-0.4350090103", "0.1923010281", "6.1728", id="mu0=0.1"),
    pytest.param(1.0, "0.0225872323", "-3.5225872323", "0.2820735651", "34.077", id="mu0=1"),
    pytest.param(10.0, "0.00233158482", "-35.0023315848", "0.285676224", "334.3", id="mu0=10"),
]


def _check_rounded(value: float, table: str) -> None:
    """Assert that value rounds to the table's decimal (half a unit in its last place)."""
    decimals = len(table.split(".")[1])
    assert_allclose(value, float(table), rtol=0, atol=0.5 * 10.0**-decimals)


@pytest.mark.parametrize(("mu0", "alpha1", "alpha2", "beta", "log10_n"), TABLE)
def test_reference_table(mu0: float, alpha1: str, alpha2: str, beta: str, log10_n: str) -> None:
    """solution.damping_ratio and spectrum.roots: the reference table at k = 2/5."""
    s = tt.spectrum(mu0, K_BALL)
    _check_rounded(s.alpha1, alpha1)
    _check_rounded(s.alpha2, alpha2)
    _check_rounded(s.beta, beta)
    _check_rounded(tt.log_damping_ratio(mu0, K_BALL) / np.log(10.0), log10_n)


# --- conserved quantities -------------------------------------------------------------


@given(z0=states, log10_mu0=st.floats(min_value=-3.0, max_value=3.0), k=k_moderate)
def test_conserved_along_solve(z0: np.ndarray, log10_mu0: float, k: float) -> None:
    """Conserved quantities: k wx - vy and k wy + vx are constant along solve."""
    t = np.linspace(0.0, 20.0, 41)
    z = tt.solve(z0, t, 10.0**log10_mu0, k)
    c = conserved_by_definition(z, k)
    scale = max(1.0, float(np.abs(z).max()))
    assert_allclose(c, np.tile(c[0], (t.size, 1)), rtol=0, atol=1e-12 * scale)
    assert_allclose(c[0], conserved_by_definition(z0, k)[0], rtol=0, atol=1e-13 * scale)
    assert_allclose(tt.conserved(z, k), c, rtol=0, atol=0)


# --- solve on many times ---------------------------------------------------------------


@pytest.mark.parametrize(
    "mu0", [pytest.param(0.0793, id="mu0=0.0793"), pytest.param(1.0, id="mu0=1")]
)
def test_solve_on_more_times_than_one_block(mu0: float, z_fig4: np.ndarray) -> None:
    """solve: 5000 samples to t = 45 (three blocks of evaluation) against exp(L t) z0.

    `solve` evaluates its times in blocks; every block must use its own times.  Reference:
    mpmath's matrix exponential at 30 digits at the first and last time of each block and
    at 16 times in between, and scipy's expm stepped over all 5000 times.  Error relative
    to max(1, size of the trajectory): 1e-12 against mpmath, 1e-9 against the stepped
    expm (its rounding accumulates over the steps).
    """
    t = np.linspace(0.0, 45.0, 5000)
    block = tt.solution._BLOCK
    assert t.size > 2 * block, "the test must span more than two blocks"
    z = tt.solve(z_fig4, t, mu0, K_BALL)
    scale = max(1.0, float(np.abs(z).max()))

    ends = [i for b in range(0, t.size, block) for i in (b, min(b + block, t.size) - 1)]
    idx = np.unique(np.r_[np.linspace(0, t.size - 1, 16).round().astype(int), ends])
    ref = expm_trajectories([z_fig4], t[idx], mu0, K_BALL, dps=30)[0]
    exact = np.array([[float(c) for c in row] for row in ref])
    assert np.abs(z[idx] - exact).max() / scale < 1e-12

    stepped = expm_solution(reference_matrix(mu0, K_BALL), z_fig4, t)
    assert np.abs(z - stepped).max() / scale < 1e-9


# --- slip velocity ------------------------------------------------------------------------


@given(z=st.lists(states, min_size=1, max_size=5).map(np.array))
def test_slip_velocity_by_definition(z: np.ndarray) -> None:
    """slip_velocity: u = v + gamma x w - gamma x r at any state, fixed point or not.

    Reference: the cross products written out in 3-D (`slip_by_definition`).
    """
    assert_allclose(tt.slip_velocity(z), slip_by_definition(z), rtol=0, atol=1e-15)


@pytest.mark.parametrize("z0", STATES)
def test_slip_velocity_drives_the_friction(z0: np.ndarray, mu0: float, k: float) -> None:
    """slip_velocity: the friction force of (1.6) is -mu0 u, so dv/dt = -mu0 u.

    dv/dt from the sympy matrix of (1.7), at a slipping state (u != 0) and at the states
    of its trajectory.
    """
    z = tt.solve(z0, np.linspace(0.0, 3.0, 7), mu0, k)
    u = tt.slip_velocity(z)
    assert np.abs(u).max() > 0.1
    dv = (z @ reference_matrix(mu0, k).T)[:, 2:4]
    assert_allclose(-mu0 * u, dv, rtol=0, atol=1e-13 * mu0 * np.abs(z).max())
