"""turntable.limits, the functions behind Figs. 2 and 6, against independent computations.

References (`turntable.reference`): the textbook roots mu (-1 +- sqrt(1 + i eps)) of (2.4)
in mpmath with 50 correct digits (no use of a, b of (2.5)); the flow of dz/dt = L z from
scipy.linalg.expm of the sympy matrix (1.7); the no-slip circle (3.3) written out here
from the conserved quantities (2.8).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import turntable
from turntable.reference import (
    expm_solution,
    reference_dps,
    reference_matrix,
    textbook_spectrum,
)

K_VALUES = [0.05, 0.4, 2.0 / 3.0, 1.0]


def _roots(mu0: float, kk: float) -> tuple[float, float, float]:
    """Return (alpha1, alpha2, beta) from the textbook roots (2.4) to 50 correct digits."""
    return tuple(float(x) for x in textbook_spectrum(mu0, kk, reference_dps(mu0, kk)))


@pytest.mark.parametrize("kk", K_VALUES)
def test_small_friction_expansion_error_is_order_three_halves(kk: float) -> None:
    mu0_values = [1e-6, 1e-8]
    errors = []
    for m in mu0_values:
        exact = np.array(_roots(m, kk))
        approx = np.array(turntable.small_friction_expansion(m, kk), dtype=float)
        errors.append(np.abs(approx - exact))
        # leading order: every rate is sqrt(mu0/2) in size
        assert np.allclose(np.abs(exact), math.sqrt(m / 2), rtol=10 * math.sqrt(m) / kk**2)
    slopes = np.log(errors[0] / errors[1]) / np.log(mu0_values[0] / mu0_values[1])
    assert np.all((slopes > 1.45) & (slopes < 1.55)), slopes


def test_small_friction_expansion_broadcasts_and_validates() -> None:
    out = turntable.small_friction_expansion(np.array([1e-6, 1e-5]), 0.4)
    assert all(np.shape(part) == (2,) for part in out)
    with pytest.raises(ValueError, match="mu0"):
        turntable.small_friction_expansion(0.0, 0.4)
    with pytest.raises(ValueError, match="k"):
        turntable.small_friction_expansion(1e-3, -1.0)


@pytest.mark.parametrize(
    ("kk", "period"), [(0.4, 7 * math.pi), (2 / 3, 5 * math.pi), (1, 4 * math.pi)]
)
def test_nonholonomic_period_closed_form(kk: float, period: float) -> None:
    assert turntable.nonholonomic_period(kk) == pytest.approx(period, rel=1e-15)
    # the frequency of the growing modes tends to the no-slip rate as mu0 -> infinity
    beta = _roots(1e12, kk)[2]
    assert 2 * math.pi / beta == pytest.approx(period, rel=1e-12)


def _error_by_expm(z0: np.ndarray, t: np.ndarray, mu0: float, kk: float) -> float:
    """Largest |r - r_nh| on the grid t (uniform, from 0), from expm of (1.7)."""
    z = expm_solution(reference_matrix(mu0, kk), z0, t)
    r0 = complex(z0[0], z0[1])
    centre = complex((kk * z0[4] - z0[3]) / kk, (kk * z0[5] + z0[2]) / kk)  # (2.8)
    r_nh = centre + (r0 - centre) * np.exp(1j * kk / (kk + 1) * t)  # (3.3)
    return float(np.max(np.abs(z[:, 0] + 1j * z[:, 1] - r_nh)))


@pytest.mark.parametrize("z0", [[1.0, 1.0, 0.0, 0.0, 0.0, 1.0], [1.0, 1.0, 0.0, 0.0, 0.0, 0.0]])
def test_limit_error_matches_expm(z0: list[float]) -> None:
    kk = 0.4
    t = np.linspace(0.0, 7 * math.pi, 401)
    mu0_values = np.array([30.0, 300.0])
    got = turntable.limit_error(z0, t, mu0_values, kk)
    want = [_error_by_expm(np.array(z0), t, m, kk) for m in mu0_values]
    np.testing.assert_allclose(got, want, rtol=1e-7)


def test_limit_error_decays_like_one_over_mu0() -> None:
    """Section 3: positions converge uniformly on a fixed interval at rate O(1/mu0)."""
    t = np.linspace(0.0, 7 * math.pi, 601)
    mu0_values = np.geomspace(1e2, 1e4, 5)
    err = turntable.limit_error([1.0, 1.0, 0.0, 0.0, 0.0, 1.0], t, mu0_values, 0.4)
    assert err.shape == mu0_values.shape
    slope = np.polyfit(np.log(mu0_values), np.log(err), 1)[0]
    assert slope == pytest.approx(-1.0, abs=0.01)


def test_limit_error_fit_is_the_least_squares_order_of_limit_error() -> None:
    """One fit for the claim and Fig. 6(b): limit_error on [0, t_end] and its log-log line."""
    z0, mu0 = [1.0, 1.0, 0.0, 0.0, 0.0, 1.0], [1e4, 10.0, 1e3, 100.0]
    fit = turntable.limit_error_fit(z0, 10.0, mu0, 0.4)
    np.testing.assert_array_equal(fit.mu0, sorted(mu0))
    t = np.linspace(0.0, 10.0, 1001)
    np.testing.assert_allclose(fit.error, turntable.limit_error(z0, t, fit.mu0, 0.4), rtol=0)
    slope, offset = np.polyfit(np.log(fit.mu0), np.log(fit.error), 1)
    assert fit.order == pytest.approx(slope, rel=1e-14)
    assert fit.prefactor == pytest.approx(np.exp(offset), rel=1e-14)
    assert fit.order == pytest.approx(-1.0, abs=0.01)
    with pytest.raises(ValueError, match=r"^mu0 must hold at least two"):
        turntable.limit_error_fit(z0, 10.0, [10.0, 10.0], 0.4)
