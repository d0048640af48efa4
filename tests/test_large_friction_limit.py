"""Claims of Section 3: the limit of large friction mu0 -> infinity.

What is tested: the expansion (3.2) (`turntable.large_friction_expansion`, of
turntable.spectrum) and the convergence to the no-slip motion (`turntable.nonholonomic`,
`turntable.no_slip_state`, of turntable.solution).  The module turntable.limits (small
friction, the no-slip period, the limit's error) is tested in tests/test_limits.py.

References: the 60-digit roots of the characteristic polynomial (mpmath),
the expansion (3.2) written out in mpmath, and the no-slip motion checked
against its defining properties (no slip, conserved quantities, dr/dt = v).
"""

from __future__ import annotations

import mpmath
import numpy as np
import pytest
from numpy.testing import assert_allclose

import turntable as tt
from turntable.reference import (
    K_BALL,
    ROOTS_DPS,
    conserved_by_definition,
    exact_roots,
    log_log_slope,
    slip_by_definition,
)

MU0_LARGE = np.logspace(2, 5, 7)
K_EXPANSION = [
    pytest.param(0.05, id="k=0.05"),
    pytest.param(0.4, id="k=0.4"),
    pytest.param(2.0 / 3.0, id="k=2/3"),
    pytest.param(1.0, id="k=1"),
]


def _mp_remainders(mu0: float, k: float) -> tuple[float, float, float]:
    """Exact roots minus (3.2), all in 60-digit arithmetic: (alpha1, alpha2, beta)."""
    roots = exact_roots(mu0, k)
    with mpmath.workdps(ROOTS_DPS):
        m, kk = mpmath.mpf(mu0), mpmath.mpf(k)
        ratio = kk / (kk + 1)
        corr = ratio**3 / m
        return (
            float(roots[0].real - corr),
            float(roots[2].real - (-m / ratio - corr)),
            float(roots[0].imag - ratio),
        )


# --- limit.expansion ------------------------------------------------------------------


@pytest.mark.parametrize("k", K_EXPANSION)
def test_limit_expansion(k: float) -> None:
    """limit.expansion: the roots minus (3.2) are O(1/mu0^2), mu0 in 1e2..1e5.

    eigenvalues - large_friction_expansion in double precision: the beta
    remainder has log-log slope <= -1.95, and mu0^2 |remainder| of alpha1
    and alpha2 stays bounded (allowing 4 ulp of alpha2 for rounding).
    """
    lam = tt.eigenvalues(MU0_LARGE, k)
    exp = tt.large_friction_expansion(MU0_LARGE, k)
    rem_beta = lam[:, 0].imag - exp.beta
    rem_alpha1 = lam[:, 0].real - exp.alpha1
    rem_alpha2 = lam[:, 2].real - exp.alpha2
    assert log_log_slope(MU0_LARGE, rem_beta) <= -2.0 + 0.05
    assert np.all(MU0_LARGE**2 * np.abs(rem_alpha1) <= 1.0)
    rounding = 4.0 * np.spacing(np.abs(exp.alpha2))
    assert np.all(np.abs(rem_alpha2) <= 1.0 / MU0_LARGE**2 + rounding)
    # The expansion's other roots are the conjugates of lambda_1 and lambda_3.
    assert_allclose(lam[:, 1], np.conj(lam[:, 0]), rtol=0, atol=0)
    assert_allclose(lam[:, 3], np.conj(lam[:, 2]), rtol=0, atol=0)


@pytest.mark.parametrize("k", K_EXPANSION)
def test_expansion_remainders_at_high_precision(k: float) -> None:
    """limit.expansion: in 60-digit arithmetic the remainders of (3.2) shrink as predicted.

    beta: slope -2 and mu0^2 remainder -> -2 (k/(k+1))^5 (next term of (3.2));
    alpha1, alpha2: slope -3 (one order better than O(1/mu0^2)).
    """
    rem = np.array([_mp_remainders(m, k) for m in MU0_LARGE])
    kk = k / (k + 1.0)
    assert abs(log_log_slope(MU0_LARGE, rem[:, 2]) + 2.0) < 0.05
    assert abs(log_log_slope(MU0_LARGE, rem[:, 0]) + 3.0) < 0.05
    assert abs(log_log_slope(MU0_LARGE, rem[:, 1]) + 3.0) < 0.05
    assert_allclose(MU0_LARGE[-1] ** 2 * rem[-1, 2], -2.0 * kk**5, rtol=1e-3)
    # The double-precision remainder of beta matches the 60-digit one.
    lam = tt.eigenvalues(MU0_LARGE, k)
    exp = tt.large_friction_expansion(MU0_LARGE, k)
    rounding = 4.0 * np.spacing(kk)
    assert_allclose(lam[:, 0].imag - exp.beta, rem[:, 2], rtol=1e-2, atol=rounding)


@pytest.mark.parametrize("mu0", [pytest.param(m, id=f"mu0={m:g}") for m in (1e2, 1e4, 1e8)])
def test_expansion_formula(mu0: float, k: float) -> None:
    """limit.expansion: large_friction_expansion is (3.2) written out."""
    exp = tt.large_friction_expansion(mu0, k)
    kk = k / (k + 1.0)
    assert_allclose(exp.alpha1, k**3 / (mu0 * (k + 1.0) ** 3), rtol=1e-14)
    assert_allclose(exp.alpha2, -mu0 * (k + 1.0) / k - kk**3 / mu0, rtol=1e-14)
    assert_allclose(exp.beta, kk, rtol=1e-15)


# --- limit.frequency ------------------------------------------------------------------


@pytest.mark.parametrize("k", K_EXPANSION)
def test_limit_frequency(k: float) -> None:
    """limit.frequency: beta -> k/(k+1) and alpha1 -> 0 as mu0 -> infinity, (3.2)-(3.3)."""
    kk = k / (k + 1.0)
    # Up to mu0 = 1e5 the gap kk - beta ~ 2 kk^5 / mu0^2 is well above rounding.
    mu0 = np.logspace(1, 5, 9)
    s = tt.spectrum(mu0, k)
    gap = kk - s.beta
    assert np.all(gap > 0.0)
    assert np.all(np.diff(gap) < 0.0)
    assert np.all(s.alpha1 > 0.0)
    assert np.all(np.diff(s.alpha1) < 0.0)
    far = tt.spectrum(1e12, k)
    assert_allclose(far.beta, kk, rtol=0, atol=2.0 * np.spacing(kk))
    assert 0.0 < far.alpha1 < 1e-12


def test_frequency_homogeneous_ball() -> None:
    """limit.frequency: for the homogeneous ball the limiting rate is 2/7 of the turntable's."""
    assert_allclose(tt.spectrum(1e10, K_BALL).beta, 2.0 / 7.0, rtol=1e-15)


# --- limit.convergence ----------------------------------------------------------------


def _constrained_state(k: float) -> np.ndarray:
    """A no-slip state built by hand: r = 1 + i, centre 0.3 - 0.5 i.

    u = v + i (w - r) = 0 and c = v - i k w = -i k r_c give
    v = i k (r - r_c) / (k + 1), w = r + i v.
    """
    r, rc = 1.0 + 1.0j, 0.3 - 0.5j
    v = 1j * k / (k + 1.0) * (r - rc)
    w = r + 1j * v
    return np.array([r.real, r.imag, v.real, v.imag, w.real, w.imag])


SLIPPING = np.array([1.0, 1.0, 0.0, 0.0, 0.0, 0.0])


def test_nonholonomic_is_the_no_slip_motion(k: float) -> None:
    """Supporting: nonholonomic has u = 0, constant c, dr/dt = v, and starts from r(0).

    Started from a slipping state it starts from the state with the same
    r(0) and conserved quantities and no slip (the end of the initial layer).
    """
    h = 1e-5
    t = np.linspace(1.0, 30.0, 59)
    for z0 in (_constrained_state(k), SLIPPING):
        z = tt.nonholonomic(z0, t, k)
        assert_allclose(slip_by_definition(z), 0.0, rtol=0, atol=1e-14)
        c0 = conserved_by_definition(z0, k)
        assert_allclose(conserved_by_definition(z, k), np.tile(c0, (t.size, 1)), rtol=0, atol=1e-14)
        drdt = (tt.nonholonomic(z0, t + h, k) - tt.nonholonomic(z0, t - h, k))[:, :2] / (2 * h)
        assert_allclose(drdt, z[:, 2:4], rtol=0, atol=1e-9)
        start = tt.nonholonomic(z0, [0.0], k)[0]
        assert_allclose(start[:2], z0[:2], rtol=0, atol=1e-15)
        assert_allclose(slip_by_definition(start), 0.0, rtol=0, atol=1e-15)
    z = tt.nonholonomic(_constrained_state(k), [0.0], k)[0]
    assert_allclose(z, _constrained_state(k), rtol=0, atol=1e-15)


def test_initial_layer_lands_on_no_slip_state(k: float) -> None:
    """Supporting: after t = 30/mu0 the slipping solution is at no_slip_state (O(1/mu0))."""
    for mu0 in (1e4, 1e6):
        z = tt.solve(SLIPPING, [30.0 / mu0], mu0, k)[0]
        assert_allclose(z, tt.no_slip_state(SLIPPING, k), rtol=0, atol=100.0 / mu0)
    end = tt.no_slip_state(SLIPPING, k)
    assert_allclose(slip_by_definition(end), 0.0, rtol=0, atol=1e-15)
    assert_allclose(
        conserved_by_definition(end, k), conserved_by_definition(SLIPPING, k), rtol=0, atol=1e-15
    )


def _errors(z0: np.ndarray, k: float, t_min: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """Max position and velocity error of solve vs nonholonomic over [t_min, T]."""
    period = 2.0 * np.pi * (k + 1.0) / k
    pos, vel = [], []
    for mu0 in MU0_LARGE:
        t = np.linspace(t_min / mu0, period, 2001)
        diff = tt.solve(z0, t, mu0, k) - tt.nonholonomic(z0, t, k)
        pos.append(np.abs(diff[:, :2]).max())
        vel.append(np.abs(diff[:, 2:]).max())
    return np.array(pos), np.array(vel)


def test_limit_convergence(k: float) -> None:
    """limit.convergence: on one no-slip period, solve -> nonholonomic at rate 1/mu0, (3.3).

    From a no-slip state: positions and velocities, uniformly on [0, T],
    T = 2 pi (k + 1)/k.  From a slipping state: positions uniformly on
    [0, T]; velocities on [20/mu0, T], outside the initial layer, while at
    t = 0 the velocity error does not shrink at all.
    """
    pos, vel = _errors(_constrained_state(k), k)
    assert abs(log_log_slope(MU0_LARGE, pos) + 1.0) < 0.05
    assert abs(log_log_slope(MU0_LARGE, vel) + 1.0) < 0.05
    assert pos[-1] < 1e-3

    pos, _ = _errors(SLIPPING, k)
    assert abs(log_log_slope(MU0_LARGE, pos) + 1.0) < 0.05
    _, vel = _errors(SLIPPING, k, t_min=20.0)
    assert abs(log_log_slope(MU0_LARGE, vel) + 1.0) < 0.05
    jump = [
        np.abs(tt.solve(SLIPPING, [0.0], m, k) - tt.nonholonomic(SLIPPING, [0.0], k))[0, 2:].max()
        for m in MU0_LARGE
    ]
    assert min(jump) > 0.1


@pytest.mark.parametrize(
    "mu0", [pytest.param(10.0, id="mu0=10"), pytest.param(100.0, id="mu0=100")]
)
def test_convergence_not_uniform_in_time(mu0: float) -> None:
    """limit.convergence: for fixed mu0 the error grows without bound (alpha1 > 0).

    At t = n T for n = 1, 10, 100, 1000 the position error increases and
    ends larger than the orbit itself, following |r - r_c| ~ e^{alpha1 t}.
    """
    k = K_BALL
    period = 2.0 * np.pi * (k + 1.0) / k
    t = period * np.array([1.0, 10.0, 100.0, 1000.0])
    z = tt.solve(SLIPPING, t, mu0, k)
    err = np.abs(z[:, :2] - tt.nonholonomic(SLIPPING, t, k)[:, :2]).max(axis=1)
    radius0 = np.abs(SLIPPING[:2] - tt.spiral_centre(SLIPPING, k)).max()
    assert np.all(np.diff(err) > 0.0)
    assert err[-1] > 10.0 * radius0
    alpha1 = float(exact_roots(mu0, k)[0].real)
    radius = np.linalg.norm(z[:, :2] - tt.spiral_centre(SLIPPING, k), axis=1)
    assert_allclose(np.diff(np.log(radius)), alpha1 * np.diff(t), rtol=1e-6)
