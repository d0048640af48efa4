"""The parameter study: turntable.study and rules study_k / study (workflow/rules/study.smk).

Expected values come from the high-precision roots of the characteristic polynomial
(turntable.reference, sympy + mpmath) and from the reference table of the project's notes
(values re-derived at high precision, not printed in the paper); each check
of `section2_checks` is also shown to fail on a deliberately wrong input.
"""

from __future__ import annotations

from pathlib import Path

import mpmath
import numpy as np
import pytest

import turntable.study as study
from turntable import Spectrum
from turntable.reference import K_BALL, exact_roots

ROOT = Path(__file__).resolve().parents[1]
Z_FIG4 = [1.0, 1.0, 0.0, 0.0, 0.0, 1.0]
T = np.linspace(0.0, 20.0, 50)
MU0 = np.geomspace(1e-4, 1e4, 33)


@pytest.fixture(scope="module")
def ball() -> dict:
    return study.section2_checks(K_BALL, MU0, Z_FIG4, T)


def test_all_checks_hold_on_a_wide_grid(ball: dict) -> None:
    assert ball["checks"] == dict.fromkeys(ball["checks"], True)
    assert set(ball["checks"]) == {
        "unstable_focus",
        "damping_bound",
        "roots",
        "centre",
        "conservation",
        "per_turn_decreasing",
        "peak_bound",
    }


@pytest.mark.parametrize("i", [0, 8, 16, 24, 32])
def test_values_match_high_precision_roots(ball: dict, i: int) -> None:
    """alpha1, alpha2, beta and ln N against mpmath roots of det(lambda I - L)."""
    roots = exact_roots(MU0[i], K_BALL)
    alpha1, beta = float(roots[0].real), float(roots[0].imag)
    alpha2 = float(roots[2].real)
    assert ball["alpha1"][i] == pytest.approx(alpha1, rel=1e-12)
    assert ball["alpha2"][i] == pytest.approx(alpha2, rel=1e-12)
    assert ball["beta"][i] == pytest.approx(beta, rel=1e-12)
    log_n = float(2 * mpmath.pi * abs(roots[2].real) / roots[2].imag)
    assert ball["log_N"][i] == pytest.approx(log_n, rel=1e-12)
    assert ball["decay_ratio"][i] == pytest.approx(abs(alpha2) / beta, rel=1e-12)


def test_reference_table_values() -> None:
    """The reference table at k = 2/5 for mu0 = 0.1, 1, 10 (10 digits)."""
    r = study.section2_checks(K_BALL, [0.1, 1.0, 10.0], Z_FIG4, T)
    np.testing.assert_allclose(r["alpha1"], [0.0850090103, 0.0225872323, 0.00233158482], 1e-8)
    np.testing.assert_allclose(r["alpha2"], [-0.4350090103, -3.5225872323, -35.0023315848], 1e-9)
    np.testing.assert_allclose(r["beta"], [0.1923010281, 0.2820735651, 0.285676224], 1e-8)
    log10_n = np.asarray(r["log_N"]) / np.log(10.0)
    np.testing.assert_allclose(log10_n, [6.1728, 34.077, 334.3], rtol=2e-4)


def test_spiral_centre_of_fig4(ball: dict) -> None:
    assert ball["centre"] == [0.0, 1.0]  # (x0, y0) = (0, 1), the heavy dot of Fig. 4


def test_centre_check_fails_with_the_other_sign(monkeypatch: pytest.MonkeyPatch) -> None:
    """With y0 = (k wy - vx)/k (the minus sign the OCR of (2.8) suggests) the check fails."""

    def minus_sign(z0: list[float], k: float) -> np.ndarray:
        return np.array([(k * z0[4] - z0[3]) / k, (k * z0[5] - z0[2]) / k])

    monkeypatch.setattr(study, "spiral_centre", minus_sign)
    z0 = [1.0, 1.0, 0.3, -0.2, 0.1, 0.5]  # vx != 0, so the two signs differ
    r = study.section2_checks(K_BALL, MU0[:5], z0, T)
    assert r["checks"]["centre"] is False
    assert r["centre_residual"] > 0.01


def test_conservation_check_fails_on_a_wrong_solution(monkeypatch: pytest.MonkeyPatch) -> None:
    """A 'solution' whose velocity is off by 1e-6 of its size breaks conservation."""
    solve = study.solve

    def perturbed(z0: list[float], t: np.ndarray, mu0: float, k: float) -> np.ndarray:
        z = solve(z0, t, mu0, k)
        z[:, 2] *= 1.0 + 1e-6
        return z

    monkeypatch.setattr(study, "solve", perturbed)
    z0 = [1.0, 1.0, 0.3, -0.2, 0.1, 0.5]
    r = study.section2_checks(K_BALL, MU0[:5], z0, T)
    assert r["checks"]["conservation"] is False


def test_root_check_fails_on_a_wrong_root(monkeypatch: pytest.MonkeyPatch) -> None:
    spectrum = study.spectrum

    def shifted(mu0: np.ndarray, k: float) -> Spectrum:
        s = spectrum(mu0, k)
        return s._replace(beta=s.beta * (1.0 + 1e-6))

    monkeypatch.setattr(study, "spectrum", shifted)
    r = study.section2_checks(K_BALL, MU0, Z_FIG4, T)
    assert r["checks"]["roots"] is False


# Each check of section2_checks must report failure on a wrong model ---------------------


def _checks_with(monkeypatch: pytest.MonkeyPatch, name: str, wrong: object) -> dict[str, bool]:
    """Run section2_checks with study.<name> replaced by ``wrong``; return its checks."""
    monkeypatch.setattr(study, name, wrong)
    return study.section2_checks(K_BALL, MU0, Z_FIG4, T)["checks"]


@pytest.mark.parametrize(
    "factor",
    [pytest.param(0.75, id="ln-N-three-quarters"), pytest.param(1.0 - 1e-6, id="ln-N-just-low")],
)
def test_damping_bound_fails_when_ln_n_is_below_2pi(
    monkeypatch: pytest.MonkeyPatch, factor: float
) -> None:
    """ln N = factor * 2 pi (above pi, below 2 pi) on the whole grid must break the bound."""
    checks = _checks_with(
        monkeypatch, "log_damping_ratio", lambda mu0, k: np.full(np.shape(mu0), factor * 2 * np.pi)
    )
    assert checks["damping_bound"] is False


def test_damping_bound_fails_when_the_decay_is_slower_than_beta(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """abs(alpha2) / beta = 0.9 at one grid point (ln N left right) must break the bound."""
    spectrum = study.spectrum

    def slow_decay(mu0: np.ndarray, k: float) -> Spectrum:
        s = spectrum(mu0, k)
        return s._replace(alpha2=np.where(mu0 == mu0[3], -0.9 * s.beta, s.alpha2))

    assert _checks_with(monkeypatch, "spectrum", slow_decay)["damping_bound"] is False


@pytest.mark.parametrize("field", ["alpha1", "alpha2"])
def test_unstable_focus_fails_on_one_wrong_sign(
    monkeypatch: pytest.MonkeyPatch, field: str
) -> None:
    """alpha1 < 0 or alpha2 > 0 at one grid point (the last) breaks the check."""
    spectrum = study.spectrum

    def flipped(mu0: np.ndarray, k: float) -> Spectrum:
        s = spectrum(mu0, k)
        values = getattr(s, field)
        return s._replace(**{field: np.where(mu0 == mu0[-1], -values, values)})

    assert _checks_with(monkeypatch, "spectrum", flipped)["unstable_focus"] is False


def test_per_turn_check_fails_on_the_growth_per_unit_time(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """2 pi alpha1 (per unit time, rising below the peak) in place of 2 pi alpha1/beta."""
    spectrum = study.spectrum
    wrong = lambda mu0, k: 2 * np.pi * spectrum(mu0, k).alpha1  # noqa: E731
    assert _checks_with(monkeypatch, "log_growth_per_turn", wrong)["per_turn_decreasing"] is False


def test_per_turn_check_fails_on_one_rise(monkeypatch: pytest.MonkeyPatch) -> None:
    per_turn = study.log_growth_per_turn

    def bump(mu0: np.ndarray, k: float) -> np.ndarray:
        values = per_turn(mu0, k).copy()
        values[10] = values[9] * (1.0 + 1e-9)
        return values

    assert _checks_with(monkeypatch, "log_growth_per_turn", bump)["per_turn_decreasing"] is False


def test_peak_check_fails_on_a_peak_just_below_the_grid_maximum(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """A closed-form peak 1e-6 (relative) below the largest alpha1 on the grid."""
    grid_max = float(np.max(study.spectrum(MU0, K_BALL).alpha1))
    peak = study.alpha1_peak

    def low(k: float) -> object:
        return peak(k)._replace(alpha1=np.float64(grid_max * (1.0 - 1e-6)))

    assert _checks_with(monkeypatch, "alpha1_peak", low)["peak_bound"] is False


def test_summary_lists_failures(ball: dict) -> None:
    bad = dict(ball, checks=dict(ball["checks"], damping_bound=False))
    s = study.summarize([ball, bad])
    assert s["all_passed"] is False
    assert s["failed"] == [f"k={K_BALL}: damping_bound"]
    assert study.summarize([ball])["all_passed"] is True
    per_k = s["per_k"][0]
    # the grid maximum of alpha1 lies below the closed-form peak, and close to it
    assert per_k["max_alpha1"] <= per_k["peak"]["alpha1"]
    assert per_k["max_alpha1"] == pytest.approx(per_k["peak"]["alpha1"], rel=0.05)
    assert per_k["min_log_N_over_2pi"] > 1.0


@pytest.mark.parametrize(
    ("mu0", "message"),
    [([1.0, 0.5], "increasing"), ([0.0, 1.0], "mu0"), ([1.0], "increasing")],
)
def test_bad_grid_raises(mu0: list[float], message: str) -> None:
    with pytest.raises(ValueError, match=message):
        study.section2_checks(K_BALL, mu0, Z_FIG4, T)
