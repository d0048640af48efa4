"""The error bars themselves: the coefficient's standard error against the spread of fits.

Over `N_FILMS` SYNTHETIC films of white noise (`turntable.fit.simulate_film`, a fixed seed
each), the z-scores (fitted - true) / SE are standard normal when the standard errors are
right: their standard deviation is 1 +- 1 / sqrt(2 N) = 1 +- 0.041.  The test accepts
1 +- `SPREAD_TOLERANCE` (2.4 of those spreads): a standard error 20 % too small makes it
1.25, one 20 % too large 0.83, and both fail.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import turntable as tt
from turntable import film, fit

#: Films of the coverage test, and the tolerance on the spread of their z-scores.
N_FILMS = 300
SPREAD_TOLERANCE = 0.1
#: Two truths of the paper's model: (model, coefficient, position (m), velocity (m/s),
#: spin (rad/s)).
TRUTHS = [
    ("slipping", 3.0, (0.05, 0.0), (0.0, 0.0), (0.0, 0.0)),
    ("slipping", 0.4, (0.0, 0.06), (0.01, 0.0), (1.0, 0.0)),
]
#: A short film: 20 frames/s for 3 s (61 frames), 0.2 mm of white noise per coordinate.
CAMERA = film.Camera(fps=20.0, noise=2e-4, duration=3.0)
SETUP = film.Setup(radius=0.01, omega=film.rpm_to_omega(33.3), k=0.4)


def z_scores() -> np.ndarray:
    """(fitted - true) / SE of every film, the truths taken in turn."""
    z = []
    for i in range(N_FILMS):
        model, c, position, velocity, spin = TRUTHS[i % len(TRUTHS)]
        z0 = film.state_from_si(position, velocity, spin, SETUP)
        data = fit.simulate_film(model, c, z0, SETUP, CAMERA, seed=i)
        f = fit.fit_model(data, SETUP, model)
        z.append((f.coefficient - c) / f.stderr)
    return np.array(z)


@pytest.fixture(scope="module")
def z() -> np.ndarray:
    return z_scores()


@pytest.mark.slow  # the fits of N_FILMS films: CI runs it
def test_spread_of_z_scores_is_one(z: np.ndarray) -> None:
    """The reported standard error is the spread of the fitted coefficients."""
    spread = float(z.std(ddof=1))
    assert abs(spread - 1.0) < SPREAD_TOLERANCE, spread


@pytest.mark.slow  # the fits of N_FILMS films: CI runs it
def test_z_scores_are_centred_and_cover(z: np.ndarray) -> None:
    """Mean 0 +- 3 / sqrt(N); within 2 SE in 95.45 % +- 3 sd of a binomial share."""
    assert abs(z.mean()) < 3 / math.sqrt(N_FILMS), z.mean()
    inside = float(np.mean(np.abs(z) < 2.0))
    assert abs(inside - 0.9545) < 3 * math.sqrt(0.9545 * 0.0455 / N_FILMS), inside


@pytest.mark.parametrize("model", fit.MODELS)
def test_the_linear_response_of_the_coefficient_is_that_of_a_refit(model: str) -> None:
    """`coefficient_response` (one Gauss-Newton step) against fitting again: a film whose
    positions are stretched by 0.2 % with an Omega 0.05 % off, and one whose times are
    delayed by up to 1 ms in proportion to y (a rolling shutter), move ln c as a new fit
    does, within 5 % of the change."""
    from turntable.fit.response import coefficient_response

    c = 3.0 if model == "slipping" else 0.05
    z0 = film.state_from_si((0.05, 0.0), (0.0, 0.0), (0.0, 0.0), SETUP)
    if model == "rolling_resistance":
        z0 = tt.no_slip_state(z0, SETUP.k)
    data = fit.simulate_film(model, c, z0, SETUP, CAMERA, seed=1)
    stretched = data._replace(x=1.002 * data.x, y=1.002 * data.y)
    delayed = data._replace(t=data.t + 0.001 * (data.y - data.y.min()) / np.ptp(data.y))
    variants = [(stretched, SETUP._replace(omega=1.0005 * SETUP.omega)), (delayed, SETUP)]
    options = {"fit_axis": model != "slipping"}
    base = math.log(fit.fit_model(data, SETUP, model, **options).coefficient)
    got = coefficient_response(data, SETUP, model, variants, **options)
    for change, (other, setup) in zip(got, variants, strict=True):
        refit = math.log(fit.fit_model(other, setup, model, **options).coefficient) - base
        assert change == pytest.approx(refit, rel=0.05, abs=1e-6)


def test_the_output_says_where_the_calibration_dominates() -> None:
    """A warning names the calibration's largest part where it exceeds the statistical
    standard error, and there is none where it does not."""
    from turntable.video.uncertainty import CalibrationPart, dominance_warning

    data = fit.simulate_film(
        "slipping", 3.0, film.state_from_si((0.05, 0.0), (0, 0), (0, 0), SETUP), SETUP, CAMERA, 1
    )
    f = fit.fit_model(data, SETUP, "slipping")
    small = CalibrationPart(0.5 * f.log_stderr, {"tilt": 0.5 * f.log_stderr, "readout": 0.0})
    large = CalibrationPart(
        2.0 * f.log_stderr, {"tilt": 0.1 * f.log_stderr, "lens_k1": 2.0 * f.log_stderr}
    )
    assert dominance_warning("slipping", f, small) is None
    line = dominance_warning("slipping", f, large)
    assert "dominates" in line
    assert "lens k1" in line
    assert "\n" not in line
