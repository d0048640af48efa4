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


def one_film(model: str) -> film.Film:
    """A film of ``model`` (mu0 = 3 or delta = 0.05) from 5 cm, at rest (rolling: on the
    no-slip constraint), seed 1."""
    c = 3.0 if model == "slipping" else 0.05
    z0 = film.state_from_si((0.05, 0.0), (0.0, 0.0), (0.0, 0.0), SETUP)
    if model == "rolling_resistance":
        z0 = tt.no_slip_state(z0, SETUP.k)
    return fit.simulate_film(model, c, z0, SETUP, CAMERA, seed=1)


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
    """`fit_response`'s ln c (one Gauss-Newton step) against fitting again: a film whose
    positions are stretched by 0.2 % with an Omega 0.05 % off, and one whose times are
    delayed by up to 1 ms in proportion to y (a rolling shutter), move ln c as a new fit
    does, within 5 % of the change."""
    from turntable.fit.response import fit_response

    data = one_film(model)
    stretched = data._replace(x=1.002 * data.x, y=1.002 * data.y)
    delayed = data._replace(t=data.t + 0.001 * (data.y - data.y.min()) / np.ptp(data.y))
    variants = [(stretched, SETUP._replace(omega=1.0005 * SETUP.omega)), (delayed, SETUP)]
    options = {"fit_axis": model != "slipping"}
    base = math.log(fit.fit_model(data, SETUP, model, **options).coefficient)
    got, _ = fit_response(data, SETUP, model, variants, **options)
    for change, (other, setup) in zip(got, variants, strict=True):
        refit = math.log(fit.fit_model(other, setup, model, **options).coefficient) - base
        assert change == pytest.approx(refit, rel=0.05, abs=1e-6)


@pytest.mark.parametrize("model", fit.MODELS)
def test_the_linear_response_of_the_residuals_is_that_of_a_refit(model: str) -> None:
    """`fit_response`'s ln RSS against fitting again, on films whose positions are moved
    by 0.3 mm (1.5 times the noise) by a smooth field over the platter, or over time:
    within 5 % of the change of ln RSS, which is above 0.1."""
    from turntable.fit.response import fit_response

    data = one_film(model)
    fields = [(np.sin(40 * data.y), np.cos(30 * data.x)), (np.sin(10 * data.t), np.cos(7 * data.t))]
    variants = [(data._replace(x=data.x + 3e-4 * u, y=data.y + 3e-4 * v), SETUP) for u, v in fields]
    options = {"fit_axis": model != "slipping"}
    base = math.log(fit.fit_model(data, SETUP, model, **options).rss)
    _, got = fit_response(data, SETUP, model, variants, **options)
    for change, (other, setup) in zip(got, variants, strict=True):
        refit = math.log(fit.fit_model(other, setup, model, **options).rss) - base
        assert abs(refit) > 0.1
        assert change == pytest.approx(refit, rel=0.05)


def test_a_selection_the_camera_could_undo_is_not_decisive() -> None:
    """The AICc difference's spread from the calibration, N |H_a - H_b| se for one
    parameter: a decisive selection stays so where 2 of it leave 10, and not otherwise."""
    from turntable.video.uncertainty import CalibrationPart, _selection_checked, selection_spread

    data = one_film("slipping")
    result = fit.fit_film(data, SETUP)
    assert result.decisive
    assert result.aicc_difference > 20
    n, se = result.fits["slipping"].n_observations, 0.01
    cov = np.diag([se**2, 0.0])
    track = type("Track", (), {"calibration": type("Cal", (), {"covariance": cov})})
    for h, decisive in ((0.2, True), (2.0, False)):
        gap = (result.aicc_difference - 10) / (2 * n * se) * h  # h of the room below 10
        parts = {
            "slipping": CalibrationPart(0.0, {}, np.array([gap, 0.3])),
            "rolling_resistance": CalibrationPart(0.0, {}, np.array([0.0, 0.3])),
        }
        spread = selection_spread(track, result, parts)
        assert spread == pytest.approx(n * gap * se)
        checked = _selection_checked(result, spread)
        assert checked.decisive is decisive
        assert ("calibration" in checked.reason) is not decisive


@pytest.mark.parametrize("model", fit.MODELS)
def test_the_influence_of_each_position_is_that_of_a_refit(model: str) -> None:
    """`coefficient_influence` against fitting again: positions moved by a smooth field of
    0.1 mm (a tracker's slow error) move ln c by sum(influence * move), within 5 % of the
    change."""
    from turntable.fit.response import coefficient_influence

    data = one_film(model)
    options = {"fit_axis": model != "slipping"}
    move = 1e-4 * np.column_stack([np.sin(40 * data.y), np.cos(30 * data.x)])
    moved = data._replace(x=data.x + move[:, 0], y=data.y + move[:, 1])
    influence = coefficient_influence(data, SETUP, model, **options)
    assert influence.shape == (data.t.size, 2)
    base = math.log(fit.fit_model(data, SETUP, model, **options).coefficient)
    refit = math.log(fit.fit_model(moved, SETUP, model, **options).coefficient) - base
    assert float(np.sum(influence * move)) == pytest.approx(refit, rel=0.05)


def test_the_output_says_where_the_calibration_dominates() -> None:
    """A warning names the calibration's largest part where it exceeds the statistical
    standard error, and there is none where it does not."""
    from turntable.video.uncertainty import CalibrationPart, dominance_warning

    data = fit.simulate_film(
        "slipping", 3.0, film.state_from_si((0.05, 0.0), (0, 0), (0, 0), SETUP), SETUP, CAMERA, 1
    )
    f = fit.fit_model(data, SETUP, "slipping")
    flat = np.zeros(3)
    small = CalibrationPart(0.5 * f.log_stderr, {"tilt": 0.5 * f.log_stderr, "readout": 0.0}, flat)
    large = CalibrationPart(
        2.0 * f.log_stderr, {"tilt": 0.1 * f.log_stderr, "lens_k1": 2.0 * f.log_stderr}, flat
    )
    assert dominance_warning("slipping", f, small) is None
    assert dominance_warning("slipping", f, small, tracker=0.9 * f.log_stderr) is None
    line = dominance_warning("slipping", f, large)
    assert "dominates" in line
    assert "lens k1" in line
    assert "\n" not in line
    line = dominance_warning("slipping", f, small, tracker=1.5 * f.log_stderr)
    assert "tracker's error" in line
    assert "dominates" in line


@pytest.mark.parametrize("model", fit.MODELS)
def test_the_tracker_s_part_is_the_spread_of_refits_over_its_fields(model: str) -> None:
    """Second route to the tracker's part of the standard error: the fit repeated on films
    whose positions are moved by 80 fields drawn from its random field (fixed seed) scatters
    in ln c by the propagated se_track, within 25 % (the spread of 80 draws: 8 %)."""
    from types import SimpleNamespace

    from scipy.spatial.distance import cdist

    from turntable.fit.response import coefficient_influence
    from turntable.video import uncertainty as u

    data = one_film(model)
    track = SimpleNamespace(film=data, ball_radius=SETUP.radius, platter_radius=0.15)
    options = {"fit_axis": model != "slipping"}
    se = u.tracker_part(track, coefficient_influence(data, SETUP, model, **options))
    assert se > 0
    xy = np.column_stack([data.x, data.y])
    length = u.TRACKER_LENGTH * track.platter_radius
    cov = (u.TRACKER_ERROR * SETUP.radius) ** 2 * np.exp(
        -cdist(xy, xy, "sqeuclidean") / (2 * length**2)
    )
    rng = np.random.default_rng(36)
    fields = rng.multivariate_normal(np.zeros(len(xy)), cov, size=(80, 2), method="eigh")
    base = math.log(fit.fit_model(data, SETUP, model, **options).coefficient)
    changes = [
        math.log(fit.fit_model(data._replace(x=data.x + fx, y=data.y + fy), SETUP, model,
                               **options).coefficient) - base
        for fx, fy in fields
    ]  # fmt: skip
    assert np.std(changes, ddof=1) == pytest.approx(se, rel=0.25)
