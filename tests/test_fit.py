"""Fitting the friction models to a film (`turntable.fit`, `turntable.film`).

The films are made by integrating the three-dimensional Newton-Euler equations
(`turntable.newton_euler` for the slipping ball, `turntable.rolling.newton_euler` for the
ball rolling against a resistance torque), not from the closed forms that the fit uses:
a wrong sign or factor in `turntable.solve` or `turntable.rolling.solve` makes the fit
miss the truth.  The true parameters (ball, turntable, coefficient, initial state) are
drawn at random from a fixed seed; the fit sees only the positions.

Statistics over seeds: 2 models x 2 truths x 50 noise seeds = 200 films.  If the
standard errors are right, the truth lies within 2 of them with probability 0.9545, so
the fraction of the 200 films has standard deviation sqrt(0.9545 0.0455 / 200) = 0.0147;
the test accepts 0.9545 +- 3 of those, [0.910, 0.999].  A standard error 1.5 times too
small gives a coverage of 0.82, 1.5 times too large 0.995 (the z-score test below catches
that: the standard deviation of 200 z-scores is 1 +- 0.05).
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from numpy.testing import assert_allclose

import turntable as tt
from turntable import film, fit, rolling

#: Ranges of the random truths (log-uniform coefficients).
RANGES = {"slipping": (0.05, 20.0), "rolling_resistance": (0.003, 0.3)}
#: The camera of the statistical tests: 30 frames/s, 0.3 mm noise, 6 s (2.5 to 5 turns).
CAMERA = film.Camera(fps=30.0, noise=3e-4, duration=6.0)
N_TRUTHS = 2
N_SEEDS = 50
COVERAGE_P = 0.9545
N_FILMS = len(fit.MODELS) * N_TRUTHS * N_SEEDS
COVERAGE_SD = math.sqrt(COVERAGE_P * (1 - COVERAGE_P) / N_FILMS)


def draw_truth(rng: np.random.Generator, model: str) -> tuple[film.Setup, float, np.ndarray]:
    """A random ball, turntable, coefficient and initial state (on the constraint if rolling).

    Radius 3-8 mm, 30-50 rpm, k = 2/5 or 2/3, axis within 5 cm of the origin; the ball 4-8
    cm from the axis, moving at up to 2 cm/s and spinning at up to 2 rad/s.
    """
    setup = film.Setup(
        radius=rng.uniform(3e-3, 8e-3),
        omega=film.rpm_to_omega(rng.uniform(30.0, 50.0)),
        k=float(rng.choice([0.4, 2.0 / 3.0])),
        axis=tuple(rng.uniform(-0.05, 0.05, 2)),
    )
    lo, hi = RANGES[model]
    c = float(np.exp(rng.uniform(np.log(lo), np.log(hi))))
    angle = rng.uniform(0.0, 2.0 * np.pi)
    position = np.asarray(setup.axis) + rng.uniform(0.04, 0.08) * np.array(
        [np.cos(angle), np.sin(angle)]
    )
    z0 = film.state_from_si(position, rng.uniform(-0.02, 0.02, 2), rng.uniform(-2, 2, 2), setup)
    if model == "rolling_resistance":
        z0 = tt.no_slip_state(z0, setup.k)
    return setup, c, z0


def newton_euler_positions(
    model: str, c: float, z0: np.ndarray, setup: film.Setup, t: np.ndarray
) -> np.ndarray:
    """Positions (m) at times t (s) from the 3-D Newton-Euler equations (no closed form)."""
    tau = setup.omega * t
    if model == "slipping":
        z = tt.newton_euler(z0, tau, c, setup.k).z
    else:
        z = rolling.newton_euler(z0, tau, c, setup.k).z
    return setup.radius * z[:, :2] + np.asarray(setup.axis)


class Truth:
    """A random truth and its noiseless film from the Newton-Euler equations."""

    def __init__(self, model: str, rng: np.random.Generator, camera: film.Camera = CAMERA):
        self.model = model
        self.setup, self.c, self.z0 = draw_truth(rng, model)
        self.camera = camera
        self.t = film.frame_times(camera)
        self.xy = newton_euler_positions(model, self.c, self.z0, self.setup, self.t)

    def noisy(self, seed: int) -> film.Film:
        noise = self.camera.noise * np.random.default_rng(seed).standard_normal(self.xy.shape)
        xy = self.xy + noise
        return film.Film(self.t, xy[:, 0], xy[:, 1])


@pytest.fixture(scope="module")
def truths() -> list[Truth]:
    rng = np.random.default_rng(20261123)
    return [Truth(model, rng) for model in fit.MODELS for _ in range(N_TRUTHS)]


@pytest.fixture(scope="module")
def fits(truths: list[Truth], computed: Any) -> list[list[fit.ModelFit]]:
    """The true model fitted to every noisy film: fits[i][seed] for truths[i].

    Computed once per test run, the truths shared out between the xdist workers."""

    def row(i: str) -> list[fit.ModelFit]:
        tr = truths[int(i)]
        return [fit.fit_model(tr.noisy(seed), tr.setup, tr.model) for seed in range(N_SEEDS)]

    rows = computed("fit-coverage", [str(i) for i in range(len(truths))], row)
    return list(rows.values())


# --------------------------------------------------------------------------- recovery
def test_noiseless_film_gives_back_the_truth(truths: list[Truth]) -> None:
    """Without noise the fit returns the coefficient and the initial state of the
    Newton-Euler film (to the integrator's accuracy), and misses by far with the other
    model's physics."""
    for tr in truths:
        data = film.Film(tr.t, tr.xy[:, 0], tr.xy[:, 1])
        f = fit.fit_model(data, tr.setup, tr.model)
        assert f.converged
        assert f.coefficient == pytest.approx(tr.c, rel=1e-6), tr.model
        assert_allclose(f.state0, tr.z0, atol=1e-5 * (1 + np.abs(tr.z0).max()))
        assert f.rms_residual < 1e-9
        other = fit.fit_model(data, tr.setup, next(m for m in fit.MODELS if m != tr.model))
        assert other.rms_residual > 1e3 * f.rms_residual


@pytest.mark.slow  # the coverage campaign (N_TRUTHS x N_SEEDS films): CI runs it
def test_coverage_of_two_standard_errors(truths: list[Truth], fits: list) -> None:
    z = np.array(
        [
            (f.coefficient - tr.c) / f.stderr
            for tr, row in zip(truths, fits, strict=True)
            for f in row
        ]
    )
    assert z.size == N_FILMS
    inside = float(np.mean(np.abs(z) < 2.0))
    assert abs(inside - COVERAGE_P) <= 3 * COVERAGE_SD, inside
    # the z-scores are standard normal: mean 0 +- 3/sqrt(N), standard deviation 1 +- 3/sqrt(2N)
    assert abs(z.mean()) < 3 / math.sqrt(N_FILMS), z.mean()
    assert abs(z.std(ddof=1) - 1.0) < 3 / math.sqrt(2 * N_FILMS), z.std(ddof=1)


@pytest.mark.slow  # the coverage campaign (N_TRUTHS x N_SEEDS films): CI runs it
def test_predicted_stderr_is_the_scatter_of_the_fits(truths: list[Truth], fits: list) -> None:
    """The Cramer-Rao prediction (no data used) equals the scatter over seeds and the
    standard error each fit reports."""
    scaled = []
    for tr, row in zip(truths, fits, strict=True):
        pred = fit.predicted_stderr(tr.model, tr.c, tr.z0, tr.setup, tr.camera)
        est = np.array([f.coefficient for f in row])
        reported = np.array([f.stderr for f in row])
        scaled.append((est - tr.c) / pred)
        # the reported errors scatter by about 1/sqrt(N - p) around the prediction
        assert np.mean(reported) == pytest.approx(pred, rel=0.05), tr.model
    # mean square of the scaled errors: chi-square / N, 1 +- 3 sqrt(2 / N)
    ms = float(np.mean(np.concatenate(scaled) ** 2))
    assert abs(ms - 1.0) < 3 * math.sqrt(2.0 / N_FILMS), ms


#: Films per truth on which the selection is checked (the other model is fitted too).
N_SELECTION = 15


@pytest.mark.slow  # the coverage campaign (N_TRUTHS x N_SEEDS films): CI runs it
def test_the_model_of_the_data_is_selected(truths: list[Truth], fits: list) -> None:
    """On films of 2.5 to 5 turns, AICc prefers the model the film was made with, every
    time (15 seeds of each of the 4 truths); for the slipping truths `distinguishability`
    predicts as much."""
    for tr, row in zip(truths, fits, strict=True):
        if tr.model == "slipping":
            d = fit.distinguishability(tr.c, tr.z0, tr.setup, tr.camera)
            assert d.selection_probability > 0.999
        other = next(m for m in fit.MODELS if m != tr.model)
        for seed, own in enumerate(row[:N_SELECTION]):
            alternative = fit.fit_model(tr.noisy(seed), tr.setup, other)
            assert own.aicc < alternative.aicc, (tr.model, seed)


@pytest.mark.slow  # 120 films, both models fitted to each: CI runs it
@pytest.mark.parametrize(
    ("mu0", "regime"),
    [(2.5, (3.0, 10.0)), (1.0, (80.0, 200.0))],
    ids=["lambda~5", "lambda~120"],
)
def test_selection_is_predicted(mu0: float, regime: tuple[float, float]) -> None:
    """Where the two models are close, the fraction of films that select the slipping model
    and the mean AICc difference agree with `distinguishability`.

    A short noisy film (4 s at 30 frames/s, 1 mm) of a slipping ball: noncentrality
    lambda about 5 (selection in about 3 of 4 films) and about 120, where the mean AICc
    difference (about 100) is well below lambda - 2 because there are only 242
    coordinates.  60 seeds: the fraction to 3 binomial standard deviations, the mean to 3
    standard errors.
    """
    setup = film.Setup(0.005, film.rpm_to_omega(100.0 / 3.0), 0.4)
    camera = film.Camera(fps=30.0, noise=1e-3, duration=4.0)
    z0 = film.state_from_si([0.05, 0.0], [0.0, 0.0], [0.0, 0.0], setup)
    d = fit.distinguishability(mu0, z0, setup, camera)
    assert regime[0] < d.noncentrality < regime[1], d
    t = film.frame_times(camera)
    xy = newton_euler_positions("slipping", mu0, z0, setup, t)
    n = 60
    rng = np.random.default_rng(7)
    diffs = []
    for _ in range(n):
        noisy = xy + camera.noise * rng.standard_normal(xy.shape)
        f = fit.fit_film(film.Film(t, noisy[:, 0], noisy[:, 1]), setup)
        diffs.append(f.fits["rolling_resistance"].aicc - f.fits["slipping"].aicc)
    diffs = np.array(diffs)
    p = d.selection_probability
    assert abs(np.mean(diffs > 0) - p) <= 3 * math.sqrt(p * (1 - p) / n) + 1 / n
    assert abs(diffs.mean() - d.expected_aicc_difference) < 3 * diffs.std(ddof=1) / math.sqrt(n)


def test_measurability_limits() -> None:
    """Where the friction is large the slipping ball rolls without slipping: the two
    models coincide (selection probability e^-2, AIC difference -2) and mu0 is poorly
    known; where it is moderate they are far apart."""
    setup = film.Setup(0.005, film.rpm_to_omega(100.0 / 3.0), 0.4)
    camera = film.Camera(fps=240.0, noise=2e-4, duration=10.0)
    z0 = film.state_from_si([0.05, 0.0], [0.0, 0.0], [0.0, 0.0], setup)
    m = fit.measurability([0.3, 3e3], z0, setup, camera)
    rel = m.mu0_stderr / m.mu0
    assert rel[0] < 1e-3 < 0.1 < rel[1]
    assert m.expected_aicc_difference[0] > 1e4
    assert m.expected_aicc_difference[1] == pytest.approx(-2.0, abs=0.05)
    assert m.selection_probability[1] == pytest.approx(math.exp(-2.0), abs=0.01)
    assert m.rms_distance[1] < 1e-3 * camera.noise


def test_predicted_stderr_is_the_inverse_fisher_information() -> None:
    """se(mu0) = mu0 sqrt([F^-1]_cc) with F = J^T J / sigma^2 built here by finite
    differences of the positions over all seven parameters (state and ln mu0)."""
    setup = film.Setup(0.004, 3.0, 0.4, (0.01, 0.02))
    camera = film.Camera(fps=20.0, noise=5e-4, duration=5.0)
    z0 = np.array([8.0, -3.0, 0.5, 0.2, -0.3, 1.0])
    t = film.frame_times(camera)
    for model, c, z in [
        ("slipping", 0.7, z0),
        ("rolling_resistance", 0.05, tt.no_slip_state(z0, setup.k)),
    ]:
        n_state = 6 if model == "slipping" else 4

        def pos(theta: np.ndarray, model: str = model, n_state: int = n_state) -> np.ndarray:
            state = theta[:n_state] if n_state == 6 else rolling.state_on_constraint(theta[:4])
            return fit.positions(model, math.exp(theta[-1]), state, t, setup).ravel()

        theta = np.append(z[:n_state], math.log(c))
        h = 1e-6
        jac = np.column_stack(
            [(pos(theta + h * e) - pos(theta - h * e)) / (2 * h) for e in np.eye(theta.size)]
        )
        cov = np.linalg.inv(jac.T @ jac / camera.noise**2)
        expected = c * math.sqrt(cov[-1, -1])
        got = fit.predicted_stderr(model, c, z, setup, camera)
        assert got == pytest.approx(expected, rel=1e-4), model


# --------------------------------------------------------------------------- the fit itself
@pytest.mark.parametrize("seed", range(8))
def test_start_values_from_the_data_alone(seed: int) -> None:
    """Noiseless films from random truths over wide ranges (mu0 1e-3 to 1e2, delta 1e-4 to
    1): the fit finds the truth from its own start values."""
    rng = np.random.default_rng(seed)
    model = fit.MODELS[seed % 2]
    setup, _, z0 = draw_truth(rng, model)
    c = float(10 ** rng.uniform(*((-3, 2) if model == "slipping" else (-4, 0))))
    t = film.frame_times(film.Camera(fps=25.0, noise=0.0, duration=8.0))
    xy = fit.positions(model, c, z0, t, setup)
    f = fit.fit_model(film.Film(t, xy[:, 0], xy[:, 1]), setup, model)
    assert f.coefficient == pytest.approx(c, rel=1e-5), (model, c)
    assert f.rms_residual < 1e-9


def test_fit_does_not_depend_on_the_clock_or_the_origin() -> None:
    """Starting the film at t = 1000 s, or moving the origin of the coordinates (with the
    axis), changes nothing but state0's time and the recorded axis."""
    rng = np.random.default_rng(3)
    setup, c, z0 = draw_truth(rng, "slipping")
    data = fit.simulate_film("slipping", c, z0, setup, CAMERA, seed=5)
    a = fit.fit_model(data, setup, "slipping")
    shift = np.array([0.3, -0.7])
    moved = film.Film(data.t + 1000.0, data.x + shift[0], data.y + shift[1])
    setup_b = setup._replace(axis=tuple(np.asarray(setup.axis) + shift))
    b = fit.fit_model(moved, setup_b, "slipping")
    assert b.coefficient == pytest.approx(a.coefficient, rel=1e-6)
    assert b.stderr == pytest.approx(a.stderr, rel=1e-4)
    assert_allclose(b.state0, a.state0, rtol=1e-5, atol=1e-6)
    assert b.t0 == 1000.0


def test_rolling_fit_starts_on_the_constraint() -> None:
    rng = np.random.default_rng(4)
    setup, c, z0 = draw_truth(rng, "rolling_resistance")
    data = fit.simulate_film("rolling_resistance", c, z0, setup, CAMERA, seed=1)
    f = fit.fit_model(data, setup, "rolling_resistance")
    assert_allclose(rolling.slip_velocity(f.state0), 0.0, atol=1e-12)
    assert f.n_parameters == 5
    assert fit.fit_model(data, setup, "slipping").n_parameters == 7


def test_aicc_and_weights() -> None:
    """AIC = N ln(RSS/N) + 2 K and AICc = AIC + 2 K (K + 1) / (N - K - 1), K = p + 1; the
    selection and the weights exp(-Delta/2), normalised, use AICc."""
    rng = np.random.default_rng(8)
    setup, c, z0 = draw_truth(rng, "slipping")
    data = fit.simulate_film("slipping", c, z0, setup, CAMERA, seed=2)
    r = fit.fit_film(data, setup)
    n = 2 * data.t.size
    for f in r.fits.values():
        k = f.n_parameters + 1
        assert f.n_observations == n
        assert f.aic == pytest.approx(n * math.log(f.rss / n) + 2 * k)
        assert f.aicc == pytest.approx(f.aic + 2 * k * (k + 1) / (n - k - 1))
        assert f.rms_residual == pytest.approx(math.sqrt(f.rss / n))
    a_s, a_r = r.fits["slipping"].aicc, r.fits["rolling_resistance"].aicc
    assert r.selected == ("slipping" if a_s < a_r else "rolling_resistance")
    assert r.aicc_difference == pytest.approx(abs(a_s - a_r))
    w_s = 1.0 / (1.0 + math.exp(-(a_r - a_s) / 2.0))
    assert r.akaike_weights["slipping"] == pytest.approx(w_s)
    assert sum(r.akaike_weights.values()) == pytest.approx(1.0)
    # undefined with too few coordinates: N <= K + 1
    assert fit.aicc(1.0, 9, 7) == math.inf
    assert math.isfinite(fit.aicc(1.0, 10, 7))


def test_dimensional_coefficients() -> None:
    """A steel ball (4.1 g, R = 5 mm) on 45 rpm with mu0_dim = 0.02 kg/s and, rolling,
    delta_dim = 2e-9 kg m^2/s: result_json gives them back from the fitted mu0 and delta."""
    mass, radius, omega = 4.1e-3, 5e-3, film.rpm_to_omega(45.0)
    setup = film.Setup(radius, omega, 0.4)
    z0 = film.state_from_si([0.05, 0.01], [0.0, 0.0], [0.0, 0.0], setup)
    truth = {
        "slipping": 0.02 / (mass * omega),
        "rolling_resistance": 2e-9 / (mass * radius**2 * omega),
    }
    dims = {
        "slipping": ("mu0", 0.02, "kg_per_s"),
        "rolling_resistance": ("delta", 2e-9, "kg_m2_per_s"),
    }
    for model, c in truth.items():
        z = z0 if model == "slipping" else tt.no_slip_state(z0, 0.4)
        data = fit.simulate_film(model, c, z, setup, CAMERA, seed=9)
        out = fit.result_json(fit.fit_film(data, setup), setup, data, mass=mass)
        name, value, unit = dims[model]
        entry = out[model]
        assert abs(entry[f"{name}_dim_{unit}"] - value) < 4 * entry[f"{name}_dim_stderr_{unit}"]
        assert entry[f"{name}_dim_{unit}"] / entry[name] == pytest.approx(value / c)


def test_fitted_positions_from_the_json() -> None:
    rng = np.random.default_rng(12)
    setup, c, z0 = draw_truth(rng, "slipping")
    data = fit.simulate_film("slipping", c, z0, setup, CAMERA, seed=3)
    r = fit.fit_film(data, setup)
    out = fit.result_json(r, setup, data)
    for model in fit.MODELS:
        xy = fit.fitted_positions(out, model, data.t)
        assert_allclose(np.column_stack([data.x, data.y]) - xy, r.fits[model].residuals, atol=1e-12)


def test_too_few_frames_is_refused() -> None:
    setup = film.Setup(0.005, 3.0)
    t = np.arange(3) * 0.1
    with pytest.raises(ValueError, match="at least 4 frames"):
        fit.fit_model(film.Film(t, t, t), setup, "slipping")
    with pytest.raises(ValueError, match="model must be one of"):
        fit.fit_model(film.Film(t, t, t), setup, "sliding")


# --------------------------------------------------------------------------- films
def test_state_from_si() -> None:
    """A ball at rest 5 cm from the axis is (10, 0, 0, 0, 0, 0) for R = 5 mm; a ball
    carried round with the plane, v = Omega gamma x r, without spin, does not slip."""
    setup = film.Setup(0.005, 2.0, 0.4, (0.01, 0.02))
    assert_allclose(film.state_from_si([0.06, 0.02], [0, 0], [0, 0], setup), [10, 0, 0, 0, 0, 0])
    r = np.array([0.03, -0.01])
    v = setup.omega * np.array([-(r[1] - 0.02), r[0] - 0.01])
    z = film.state_from_si(r, v, [0.0, 0.0], setup)
    assert_allclose(tt.slip_velocity(z), 0.0, atol=1e-12)
    si = film.state_to_si(z, setup)
    assert_allclose(si["position_m"], r)
    assert_allclose(si["velocity_m_s"], v)
    with pytest.raises(ValueError, match="radius"):
        film.state_from_si(r, v, [0, 0], setup._replace(radius=-1.0))


def test_rpm() -> None:
    assert film.rpm_to_omega(60.0) == pytest.approx(2 * math.pi)
    assert film.rpm_to_omega(100.0 / 3.0) == pytest.approx(3.4906585039886591)


def test_simulated_film(tmp_path: Path) -> None:
    """Exact positions plus N(0, noise^2) per coordinate, reproducible from the seed,
    written with a SYNTHETIC header that read_film skips."""
    setup = film.Setup(0.005, 3.0, 0.4, (0.1, 0.0))
    camera = film.Camera(fps=100.0, noise=2e-4, duration=20.0)
    z0 = np.array([10.0, 0.0, 0.0, 0.0, 0.0, 0.0])
    a = fit.simulate_film("slipping", 0.5, z0, setup, camera, seed=1)
    assert_allclose(np.diff(a.t), 0.01)
    assert a.t[-1] == pytest.approx(20.0)
    exact = fit.positions("slipping", 0.5, z0, a.t, setup)
    err = np.column_stack([a.x, a.y]) - exact
    assert abs(err.std() / 2e-4 - 1) < 3 / math.sqrt(2 * err.size)
    assert abs(err.mean()) < 3 * 2e-4 / math.sqrt(err.size)
    b = fit.simulate_film("slipping", 0.5, z0, setup, camera, seed=1)
    c = fit.simulate_film("slipping", 0.5, z0, setup, camera, seed=2)
    assert np.array_equal(a.x, b.x)
    assert not np.array_equal(a.x, c.x)
    path = tmp_path / "film.csv"
    header = fit.synthetic_header("slipping", 0.5, z0, setup, camera, 1)
    film.write_film(path, a, header)
    text = path.read_text()
    assert text.startswith("# SYNTHETIC")
    assert "mu0 = 0.5" in text
    assert "seed = 1" in text
    back = film.read_film(path)
    assert_allclose(back.t, a.t, rtol=1e-9)
    assert_allclose(back.x, a.x, rtol=1e-9)
    with pytest.raises(ValueError, match="no-slip constraint"):
        fit.simulate_film("rolling_resistance", 0.1, z0, setup, camera, seed=1)


def test_read_film_accepts_the_documented_variations(tmp_path: Path) -> None:
    """Comments anywhere, blank lines, other columns in any order, spaces, CRLF, a BOM."""
    text = (
        "\ufeff# tracked with some program\r\n"
        "frame, y ,t,x,quality\r\n"
        "\r\n"
        "1, 0.5, 0.0, 0.25, good\r\n"
        "   # a comment between frames\r\n"
        "2, 0.6, 0.1, 0.35, bad\r\n"
    )
    path = tmp_path / "a.csv"
    path.write_bytes(text.encode())
    f = film.read_film(path)
    assert_allclose(f.t, [0.0, 0.1])
    assert_allclose(f.x, [0.25, 0.35])
    assert_allclose(f.y, [0.5, 0.6])


def test_max_time_of_long_films() -> None:
    """A film longer than turntable.max_time at the peak of alpha1 (Omega t = 8400 beyond
    about 8300: 40 minutes at 33 rpm) fits without overflow or NaN: the search for start
    values scales each exponential to the film, and a trial coefficient at which the
    solution would overflow gets a huge residual instead of an error."""
    setup = film.Setup(0.005, film.rpm_to_omega(100.0 / 3.0), 0.4)
    t = np.linspace(0.0, 8400.0 / setup.omega, 12001)
    assert setup.omega * t[-1] > float(tt.max_time(tt.alpha1_peak(0.4).mu0, 0.4))
    z0 = np.array([10.0, 0.0, 0.0, 0.0, 0.0, 0.0])
    mu0 = 1e4  # alpha1 ~ 7e-6: the spiral grows by a factor 1.06 over the film
    xy = fit.positions("slipping", mu0, z0, t, setup)
    f = fit.fit_model(film.Film(t, xy[:, 0], xy[:, 1]), setup, "slipping")
    assert f.coefficient == pytest.approx(mu0, rel=1e-4)


def test_indistinguishable_above() -> None:
    """The crossing of the selection probability with the level, linear in ln mu0 after
    the last grid point at or above the level."""
    mu0 = np.array([0.1, 1.0, 10.0, 100.0])

    def table(sel: list[float]) -> fit.Measurability:
        z = np.zeros(4)
        return fit.Measurability(mu0, z, z, z, z, z, np.array(sel))

    # 0.99 at mu0 = 1, 0.5 at mu0 = 10: 0.95 is crossed at ln mu0 = ln 1 + (0.04/0.49) ln 10
    got = fit.indistinguishable_above(table([1.0, 0.99, 0.5, 0.2]), 0.95)
    assert got == pytest.approx(10 ** (0.04 / 0.49))
    # a dip that recovers: the last crossing counts
    assert fit.indistinguishable_above(table([1.0, 0.5, 0.99, 0.2]), 0.95) > 10.0
    assert fit.indistinguishable_above(table([1.0, 1.0, 1.0, 0.99]), 0.95) == math.inf
    assert fit.indistinguishable_above(table([0.5, 0.4, 0.3, 0.2]), 0.95) == 0.1
    rig = film.Rig(film.Setup(0.005, 3.0), film.Camera(240.0, 2e-4, 10.0), np.ones(6), 0.004)
    out = fit.measurability_json(table([1.0, 0.99, 0.5, 0.2]), 0.95, rig)
    assert out["indistinguishable_above_mu0"] == pytest.approx(10 ** (0.04 / 0.49))
    assert out["table"]["mu0"] == list(mu0)
    assert out["setup"]["fps"] == 240.0


# --------------------------------------------------------------------------- what can go wrong
#: The ball of the configuration (1 cm, 33 1/3 rpm), put down at rest 5 cm from the axis.
RIG = film.Setup(0.005, film.rpm_to_omega(100.0 / 3.0), 0.4)
START = film.state_from_si([0.05, 0.0], [0.0, 0.0], [0.0, 0.0], RIG)
TRUE = {"slipping": 3.0, "rolling_resistance": 0.02}


def rig_film(model: str, camera: film.Camera, seed: int, setup: film.Setup = RIG) -> film.Film:
    """A film of the configured ball (mu0 = 3 or delta = 0.02) with ``setup``'s Omega and axis."""
    z0 = film.state_from_si([0.05, 0.0], [0.0, 0.0], [0.0, 0.0], setup)
    if model == "rolling_resistance":
        z0 = tt.no_slip_state(z0, setup.k)
    return fit.simulate_film(model, TRUE[model], z0, setup, camera, seed)


def test_whiteness() -> None:
    """Independent noise: lag-1 autocorrelation within 4 of its spread 1/sqrt(2 (n - 1));
    a smooth error on top of the noise: far beyond."""
    rng = np.random.default_rng(0)
    n = 2000
    noise = rng.standard_normal((n, 2))
    rho, sd = fit.whiteness(noise)
    assert sd == pytest.approx(1.0 / math.sqrt(2 * (n - 1)))
    assert abs(rho) < 4 * sd
    smooth = np.column_stack([np.sin(np.linspace(0, 6, n)), np.cos(np.linspace(0, 6, n))])
    rho, sd = fit.whiteness(noise + smooth)
    assert rho > 10 * sd
    # the share of the smooth part in the variance: 0.5 / 1.5
    assert rho == pytest.approx(0.5 / 1.5, abs=4 * sd)
    assert fit.whiteness(np.zeros((5, 2)))[0] == 0.0


@pytest.mark.parametrize("model", fit.MODELS)
def test_wrong_omega_is_detected_and_fit_omega_recovers(model: str) -> None:
    """A film of a turntable 0.4 % faster than the given rate.  With the given Omega, the
    check with Omega free (`consistency`) warns (the whiteness of the residuals alone does
    not: the rolling model absorbs the error of the slipping film, and is selected): the
    slipping film selects slipping again, decisively, with Omega free, and the rolling
    film's Omega is more than 4 standard errors off.  With ``fit_omega`` the right model is
    selected and the coefficient and Omega lie within 3 standard errors of the truth; the
    correct rate gives no warning."""
    camera = film.Camera(fps=60.0, noise=2e-4, duration=6.0)
    true = RIG._replace(omega=RIG.omega * 1.004)
    data = rig_film(model, camera, 3, true)
    wrong = fit.fit_film(data, RIG)
    check = fit.consistency(data, RIG, wrong)
    assert check is not None
    assert check.freed == ("omega", "axis")
    if model == "slipping":
        assert wrong.selected == "rolling_resistance"
        assert wrong.fits["rolling_resistance"].white
        assert check.selection_changed
        assert check.refit.selected == "slipping"
    else:
        assert check.omega_z > fit.CONSISTENCY_Z
    warnings = fit.problems(wrong, data, RIG, check)
    assert any("--fit-omega" in w for w in warnings), warnings
    freed = fit.fit_film(data, RIG, fit_omega=True)
    assert freed.selected == model
    assert freed.decisive
    f = freed.fits[model]
    assert abs(f.coefficient - TRUE[model]) < 3 * f.stderr
    assert abs(f.omega - true.omega) < 3 * f.omega_stderr
    assert f.white
    # checked with Omega known exactly: nothing to report
    right = fit.fit_film(data, true)
    assert fit.problems(right, data, true, fit.consistency(data, true, right)) == []


@pytest.mark.slow  # a coverage campaign: CI runs it
@pytest.mark.parametrize("model", fit.MODELS)
def test_correlated_noise_gets_wider_standard_errors_that_cover(model: str) -> None:
    """Noise correlated from frame to frame (AR(1), lag-1 correlation 0.6, as a tracker's
    can be): the residuals are at the noise level, so the model still describes the film,
    and the coefficient lies within 2 of its standard errors in at least 85 % of 40 films
    (the white-noise formula's, half as large, cover in about 70 %)."""
    camera = film.Camera(fps=120.0, noise=2e-4, duration=5.0)
    t = np.arange(0.0, camera.duration, 1.0 / camera.fps)
    z0 = START if model == "slipping" else tt.no_slip_state(START, RIG.k)
    xy = fit.positions(model, TRUE[model], z0, t, RIG)
    rng = np.random.default_rng(7)
    z = []
    for _ in range(40):
        e = rng.normal(0.0, camera.noise * math.sqrt(1 - 0.6**2), (t.size, 2))
        for i in range(1, t.size):
            e[i] += 0.6 * e[i - 1]
        data = film.Film(t, xy[:, 0] + e[:, 0], xy[:, 1] + e[:, 1])
        f = fit.fit_model(data, RIG, model)
        assert not f.white
        assert f.describes
        z.append((f.coefficient - TRUE[model]) / f.stderr)
    z = np.abs(z)
    assert np.mean(z < 2) >= 0.85


@pytest.mark.parametrize("n", [1, 2, 7, 400])
@pytest.mark.parametrize("a", [0.0, 0.5, 0.999])
def test_drift_kernel_is_the_dense_matrix_product(n: int, a: float) -> None:
    from turntable.fit.parameters import _kernel_times

    v = np.random.default_rng(n).normal(size=(n, 2, 3))
    dense = a ** np.abs(np.subtract.outer(np.arange(n), np.arange(n)))
    assert_allclose(_kernel_times(v, a), np.einsum("ij,jkl->ikl", dense, v), rtol=0, atol=1e-12)


@pytest.mark.slow  # a coverage campaign: CI runs it
@pytest.mark.parametrize("model", fit.MODELS)
def test_slowly_drifting_errors_get_standard_errors_that_cover(model: str) -> None:
    """White noise plus errors that drift as a tracker's do (exponentially correlated over
    0.3 s, as large as the white part): the fit absorbs part of the drift, and the
    coefficient lies within 2 of its standard errors in at least 85 % of 40 films (the
    white and Newey-West formulas alone cover in about 70 %)."""
    camera = film.Camera(fps=120.0, noise=2e-4, duration=5.0)
    t = np.arange(0.0, camera.duration, 1.0 / camera.fps)
    z0 = START if model == "slipping" else tt.no_slip_state(START, RIG.k)
    xy = fit.positions(model, TRUE[model], z0, t, RIG)
    rng = np.random.default_rng(11)
    a = math.exp(-1.0 / (camera.fps * 0.3))
    z = []
    for _ in range(40):
        drift = rng.normal(0.0, camera.noise * math.sqrt(1 - a**2), (t.size, 2))
        drift[0] = rng.normal(0.0, camera.noise, 2)
        for i in range(1, t.size):
            drift[i] += a * drift[i - 1]
        e = drift + rng.normal(0.0, camera.noise, (t.size, 2))
        data = film.Film(t, xy[:, 0] + e[:, 0], xy[:, 1] + e[:, 1])
        f = fit.fit_model(data, RIG, model)
        z.append((f.coefficient - TRUE[model]) / f.stderr)
    assert np.mean(np.abs(z) < 2) >= 0.85


def test_frame_noise_of_white_noise_is_its_standard_deviation() -> None:
    """On a straight path with independent Gaussian noise of sd s, the median of the
    squared normalised third differences over the median of chi-square(1) is s^2."""
    rng = np.random.default_rng(5)
    t = np.arange(200_000) / 60.0
    xy = np.c_[0.1 * t, -0.2 * t] + rng.normal(0.0, 2e-3, (t.size, 2))
    assert fit.frame_noise(t, xy) == pytest.approx(2e-3, rel=0.01)


def test_the_normal_quantiles_are_those_of_scipy() -> None:
    from scipy.stats import norm

    two_sided, one_sided = fit.Z95, fit.Z95_ONE_SIDED
    assert two_sided == pytest.approx(norm.ppf(0.975), rel=1e-15)
    assert one_sided == pytest.approx(norm.ppf(0.95), rel=1e-15)


def test_frame_noise_of_uneven_frames_and_of_a_film_without_noise() -> None:
    """The noise is measured with the frame times as they are (a variable frame rate is no
    noise); a ball tracked to whole millimetres that hardly moves has next to none, and
    the warnings of a fit come out even with none."""
    rng = np.random.default_rng(3)
    t = (np.arange(600) + 0.5 + rng.uniform(-0.4, 0.4, 600)) / 60.0
    z0 = film.state_from_si([0.05, 0.0], [0.05, 0.0], [0.0, 0.0], RIG)
    xy = fit.positions("slipping", 3.0, z0, t, RIG)
    assert fit.frame_noise(t, xy) < 1e-6
    assert fit.frame_noise(np.arange(600) / 60.0, xy) > 1e-4  # the same steps taken as even
    t = np.arange(300) / 30.0
    data = film.Film(t, np.round(0.05 + 4e-4 * t, 3), np.round(0.02 - 3e-4 * t, 3))
    r = fit.fit_film(data, RIG)
    f = r.fits["slipping"]
    assert f.noise < 1e-12
    assert not f.white
    assert not f._replace(noise=0.0).describes
    assert f._replace(noise=0.0).noise_ratio == math.inf
    zero = r._replace(fits={m: g._replace(noise=0.0) for m, g in r.fits.items()})
    assert any("inf times" in w for w in fit.problems(zero, data, RIG))


def test_wrong_omega_on_the_configured_camera_leaves_structure() -> None:
    """On the configured camera (240 frames/s, 10 s, 0.2 mm), 33.2 rpm given for 33 1/3
    selects the wrong model by thousands of AICc, with residuals far from white though only
    1.3 times the noise (as a tracker's correlated errors can be): the warning names the
    rate, and the check with Omega free withdraws the selection."""
    camera = film.Camera(fps=240.0, noise=2e-4, duration=10.0)
    data = rig_film("slipping", camera, 1)
    given = RIG._replace(omega=film.rpm_to_omega(33.2))
    r = fit.fit_film(data, given)
    assert r.selected == "rolling_resistance"
    assert r.aicc_difference > 1000
    assert not r.fits["rolling_resistance"].white
    assert r.fits["rolling_resistance"].describes  # 1.3 times the noise
    assert any("a small misfit (check --omega" in w for w in fit.problems(r, data, given))
    check = fit.consistency(data, given, r)
    assert not fit.checked_selection(r, check).decisive
    assert abs(check.omega_z) > fit.CONSISTENCY_Z


def test_axis_off_is_detected_and_fit_axis_recovers() -> None:
    """A rolling film about an axis 0.5 mm from the given one: delta is biased by several
    standard errors with the given axis, the check with the axis free warns, and
    ``fit_axis`` recovers delta and the axis within 3 standard errors.  The slipping model
    does not depend on the axis: its fit is the same with it moved."""
    camera = film.Camera(fps=60.0, noise=2e-4, duration=6.0)
    true = RIG._replace(axis=(5e-4, 0.0))
    data = rig_film("rolling_resistance", camera, 4, true)
    biased = fit.fit_model(data, RIG, "rolling_resistance")
    assert abs(biased.coefficient - 0.02) > 3 * biased.stderr
    r = fit.fit_film(data, RIG)
    check = fit.consistency(data, RIG, r)
    assert max(abs(v) for v in check.axis_z) > fit.CONSISTENCY_Z
    assert any("--fit-axis" in w for w in fit.problems(r, data, RIG, check))
    f = fit.fit_model(data, RIG, "rolling_resistance", fit_axis=True)
    assert f.n_parameters == 7
    assert abs(f.coefficient - 0.02) < 3 * f.stderr
    for got, want, se in zip(f.axis, true.axis, f.axis_stderr, strict=True):
        assert abs(got - want) < 3 * se
    a = fit.fit_model(data, RIG, "slipping")
    b = fit.fit_model(data, RIG, "slipping", fit_axis=True)
    assert b.n_parameters == a.n_parameters == 7
    assert b.coefficient == pytest.approx(a.coefficient, rel=1e-9)


def test_coefficient_at_a_bound_is_a_limit() -> None:
    """A slipping ball with mu0 = 3000, far beyond what 30 frames/s over 6 s can measure
    (predicted relative error about 10): the fit runs into the upper end of the search
    range.  It is reported as a one-sided 95 % lower limit below the truth, not as a value,
    with a warning; the profile of the RSS at the limit has risen by z_0.95^2 s^2."""
    camera = film.Camera(fps=30.0, noise=3e-4, duration=6.0)
    z0 = START
    assert fit.predicted_stderr("slipping", 3000.0, z0, RIG, camera) / 3000.0 > 5
    data = fit.simulate_film("slipping", 3000.0, z0, RIG, camera, seed=1)
    f = fit.fit_model(data, RIG, "slipping")
    assert f.at_bound
    assert f.bound == "upper"
    assert f.coefficient == pytest.approx(fit.BOUNDS["slipping"][1])
    assert 1.0 < f.limit < 3000.0
    # the RSS profile at the limit, the state refitted (linear in it): up by 1.645^2 s^2
    tau, xy = fit.lsq._dimensionless(data, RIG)
    r = xy[:, 0] + 1j * xy[:, 1]
    profile = float(fit.start._residual_sums("slipping", np.float64(f.limit), tau, r, RIG.k))
    s2 = f.rss / (f.n_observations - f.n_parameters)
    rise = RIG.radius**2 * profile - f.rss
    assert rise == pytest.approx(fit.Z95_ONE_SIDED**2 * s2, rel=0.05)
    out = fit.result_json(fit.fit_film(data, RIG), RIG, data)
    entry = out["slipping"]
    assert entry["mu0"] is None
    assert entry["mu0_stderr"] is None
    assert entry["mu0_ci95"] is None
    assert entry["mu0_lower_limit"] == pytest.approx(f.limit)
    assert entry["at_bound"] is True
    assert any("mu0 ran into the upper end" in w and "mu0 >" in w for w in out["warnings"])
    # the path is still drawn, at the bound
    assert fit.fitted_coefficient(out, "slipping") == pytest.approx(f.coefficient)


@pytest.mark.slow  # films of every length, both models fitted to each: CI runs it
def test_few_frames_refuse_a_selection_or_select_right() -> None:
    """Films of a few frames at 240 frames/s, where the two motions cannot differ: with 5
    frames plain AIC selected the slipping model for a rolling film with a difference above
    10 (seed 16); AICc refuses any selection below `min_frames` (15) frames and says why.
    From 15 frames on it selects, but never decisively the wrong model (20 seeds of each)."""
    five = rig_film("rolling_resistance", film.Camera(240.0, 2e-4, 4 / 240), 16)
    r = fit.fit_film(five, RIG)
    aic = {m: f.aic for m, f in r.fits.items()}
    assert aic["rolling_resistance"] - aic["slipping"] > 10  # AIC: decisive and wrong
    assert r.selected is None
    assert not r.decisive
    assert "no model selected" in r.reason
    assert "5 frames" in r.reason
    assert fit.min_frames() == 15
    out = fit.result_json(r, RIG, five)
    assert out["selected"] is None
    assert out["selection"]["decisive"] is False
    assert out["selection"]["reason"] == r.reason
    assert r.reason in out["warnings"]
    short = fit.fit_film(rig_film("slipping", film.Camera(240.0, 2e-4, 13 / 240), 0), RIG)
    assert short.selected is None
    for seed in range(20):
        for model in fit.MODELS:
            data = rig_film(model, film.Camera(240.0, 2e-4, 14 / 240), seed)
            assert data.t.size == 15
            r = fit.fit_film(data, RIG)
            assert r.selected is not None
            assert r.selected == model or not r.decisive, (model, seed, r)


def test_penalty_alone_is_not_decisive(monkeypatch: pytest.MonkeyPatch) -> None:
    """On 10 frames the AICc penalty on the slipping model's two extra parameters exceeds 10
    by itself (2 q + 2 K_s (K_s + 1) / (N - K_s - 1) - 2 K_r (K_r + 1) / (N - K_r - 1) with
    K = p + 1 = 8 and 6, N = 20); with the selection threshold lowered to let 10 frames
    through, a rolling selection that rests on that penalty alone (the slipping fit has
    the smaller RSS) is not decisive, one with the smaller RSS is."""
    n, k_s, k_r = 20, 8, 6
    penalty = 4 + 2 * k_s * (k_s + 1) / (n - k_s - 1) - 2 * k_r * (k_r + 1) / (n - k_r - 1)
    assert penalty > 10
    monkeypatch.setattr(fit.lsq, "MIN_DOF", 1)

    def fake(rss: dict[str, float]):
        def fit_model(film_: film.Film, setup: film.Setup, model: str, **_: bool) -> fit.ModelFit:
            p = fit.n_parameters(model)
            return fit.ModelFit(
                model, 1.0, 0.1, 0.1, np.zeros(6), 0.0, rss[model], 0.0,
                fit.aic(rss[model], n, p), p, n, True, False, np.zeros((10, 2)),
                aicc=fit.aicc(rss[model], n, p),
            )  # fmt: skip

        return fit_model

    monkeypatch.setattr(fit.lsq, "fit_model", fake({"slipping": 0.98, "rolling_resistance": 1.0}))
    r = fit.fit_film(film.Film(np.arange(10.0), np.zeros(10), np.zeros(10)), RIG)
    assert r.selected == "rolling_resistance"
    assert r.aicc_difference > 10
    assert not r.decisive
    assert "penalty" in r.reason
    monkeypatch.setattr(fit.lsq, "fit_model", fake({"slipping": 1.0, "rolling_resistance": 0.99}))
    r = fit.fit_film(film.Film(np.arange(10.0), np.zeros(10), np.zeros(10)), RIG)
    assert r.selected == "rolling_resistance"
    assert r.decisive


def test_distinguishability_needs_enough_frames() -> None:
    """A film of 0.01 s (3 frames) cannot compare the models: a ValueError that says so,
    not a math domain error."""
    camera = film.Camera(fps=240.0, noise=2e-4, duration=0.01)
    with pytest.raises(ValueError, match=r"too few frames.*7 parameters.*at least 15 frames"):
        fit.distinguishability(3.0, START, RIG, camera)
    with pytest.raises(ValueError, match="too few frames"):
        fit.measurability([3.0], START, RIG, camera)


@pytest.mark.slow  # seeds of short films: CI runs it
@pytest.mark.parametrize("model", fit.MODELS)
def test_film_under_one_turn(model: str) -> None:
    """1.2 s at 60 frames/s, two thirds of a turn of the turntable and a fifth of a turn of
    the ball: the fit of the true model is honest (its 95 % interval holds the truth in at
    least 25 of 30 films, 3 binomial standard deviations below 28.5; over 100 films 92 and
    93 %) and the selection is never decisive and wrong."""
    camera = film.Camera(fps=60.0, noise=2e-4, duration=1.2)
    assert RIG.omega * camera.duration / (2 * math.pi) < 1
    inside = 0
    for seed in range(30):
        data = rig_film(model, camera, seed)
        r = fit.fit_film(data, RIG)
        f = r.fits[model]
        lo, hi = f.ci95
        inside += lo < TRUE[model] < hi
        assert r.selected == model or not r.decisive, (seed, r.selected, r.aicc_difference)
        out = fit.result_json(r, RIG, data)
        assert out["data"]["turntable_turns"] < 1
        assert out[model]["orbital_turns"] < 0.3
    assert inside >= 25, inside


def test_log_interval() -> None:
    """mu0_ci95 = exp(ln mu0 -+ 1.96 se(ln mu0)): positive and asymmetric even where the
    relative error is large (where value - 1.96 stderr < 0)."""
    camera = film.Camera(fps=30.0, noise=3e-4, duration=6.0)
    data = fit.simulate_film("slipping", 200.0, START, RIG, camera, seed=1)
    f = fit.fit_model(data, RIG, "slipping")
    assert f.bound is None
    assert f.log_stderr > 0.6
    lo, hi = f.ci95
    assert lo == pytest.approx(f.coefficient * math.exp(-1.959964 * f.log_stderr))
    assert hi == pytest.approx(f.coefficient * math.exp(1.959964 * f.log_stderr))
    assert 0 < lo < f.coefficient < hi
    assert f.coefficient - 1.96 * f.stderr < 0
    out = fit.result_json(fit.fit_film(data, RIG), RIG, data)
    assert out["slipping"]["mu0_ci95"] == pytest.approx([lo, hi])
    assert out["slipping"]["mu0_relative_stderr"] == pytest.approx(f.stderr / f.coefficient)
    from turntable.fit.plot import value_with_error

    text = value_with_error(f.coefficient, f.stderr, [lo, hi])
    assert "95 %" in text
    assert "±" not in text
    assert value_with_error(3.0, 0.01, [2.98, 3.02]) == "3.000 ± 0.010"
    # beyond the locally linear regime the command says the interval is only indicative
    warnings = fit.problems(fit.fit_film(data, RIG), data, RIG)
    assert any("only indicative" in w for w in warnings), warnings


@pytest.mark.slow  # fits across the grid of coefficients: CI runs it
def test_bound_is_reached_only_below_the_reliable_level() -> None:
    """Fig. 8 draws the Cramer-Rao bound solid where the predicted relative error is below
    reliable_relative_error (configuration, 0.2).  Checked on 40 films at a point below
    (predicted 0.05: the scatter of ln mu0 is the bound within 3/sqrt(2 n)) and one above
    (predicted 0.6: the scatter exceeds it by more than half)."""
    from ci_build import full_config

    level = full_config()["fig8_measurability"]["reliable_relative_error"]
    camera = film.Camera(fps=30.0, noise=3e-4, duration=6.0)
    n = 40
    for mu0, reached in ((13.0, True), (150.0, False)):
        predicted = fit.predicted_stderr("slipping", mu0, START, RIG, camera) / mu0
        assert (predicted < level) == reached, predicted
        logs = [
            math.log(
                fit.fit_model(
                    fit.simulate_film("slipping", mu0, START, RIG, camera, seed), RIG, "slipping"
                ).coefficient
            )
            for seed in range(n)
        ]
        ratio = float(np.std(logs, ddof=1)) / predicted
        if reached:
            assert abs(ratio - 1) < 3 / math.sqrt(2 * n), ratio
        else:
            assert ratio > 1.5, ratio
    span = fit.reliable_range([1.0, 10.0, 100.0, 1000.0], [0.5, 0.1, 0.1, 0.5], 0.2)
    # log-log interpolation: ln(0.4) / ln(0.2) of the decade from 1, ln 2 / ln 5 of that from 100
    low, high = 10 ** (math.log(0.4) / math.log(0.2)), 10 ** (2 + math.log(2) / math.log(5))
    assert span == pytest.approx((low, high))
    assert fit.reliable_range([1.0, 10.0], [0.5, 0.4], 0.2) is None


def test_frames_too_far_apart() -> None:
    """Times in ms read as s: the turntable turns 14 rad between frames; the warning names
    the time unit."""
    data = rig_film("slipping", film.Camera(fps=60.0, noise=2e-4, duration=2.0), 0)
    slow = film.Film(data.t * 1000.0, data.x, data.y)
    warnings = fit.problems(fit.fit_film(slow, RIG), slow, RIG)
    assert any("between frames" in w and "seconds" in w for w in warnings), warnings
    assert not any("between frames" in w for w in fit.problems(fit.fit_film(data, RIG), data, RIG))


def test_synthetic_flag(tmp_path: Path) -> None:
    """A film whose comments say SYNTHETIC is marked so when read, and so is its fit; a
    film without is not (nor one that only mentions the word in lower case)."""
    data = rig_film("slipping", film.Camera(fps=30.0, noise=3e-4, duration=3.0), 0)
    assert data.synthetic
    marked, plain, lower = tmp_path / "a.csv", tmp_path / "b.csv", tmp_path / "c.csv"
    film.write_film(marked, data, fit.synthetic_header("slipping", 3.0, START, RIG, CAMERA, 0))
    film.write_film(plain, data, ["tracked by hand"])
    film.write_film(lower, data, ["not synthetic at all"])
    assert film.read_film(marked).synthetic
    assert not film.read_film(plain).synthetic
    assert not film.read_film(lower).synthetic
    for path, expected in ((marked, True), (plain, False)):
        read = film.read_film(path)
        out = fit.result_json(fit.fit_film(read, RIG), RIG, read)
        assert out["data"]["synthetic"] is expected


def test_turns_in_the_json() -> None:
    """data.turntable_turns = Omega T / (2 pi); each model's orbital_turns, and the selected
    one's as data.ball_turns, = beta Omega T / (2 pi) for slipping (Im lambda_g for
    rolling); the ambiguous key "turns" is gone."""
    camera = film.Camera(fps=30.0, noise=3e-4, duration=6.0)
    data = rig_film("slipping", camera, 0)
    out = fit.result_json(fit.fit_film(data, RIG), RIG, data)
    assert "turns" not in out["data"]
    assert out["data"]["turntable_turns"] == pytest.approx(RIG.omega * 6.0 / (2 * math.pi))
    beta = float(tt.spectrum(out["slipping"]["mu0"], RIG.k).beta)
    assert out["slipping"]["orbital_turns"] == pytest.approx(beta * RIG.omega * 6.0 / (2 * math.pi))
    assert out["data"]["ball_turns"] == out["slipping"]["orbital_turns"]
    delta = out["rolling_resistance"]["delta"]
    nu = float(rolling.eigenvalues(delta, RIG.k)[0].imag)
    assert out["rolling_resistance"]["orbital_turns"] == pytest.approx(
        nu * RIG.omega * 6.0 / (2 * math.pi)
    )


@pytest.mark.parametrize(
    "mu0", [1.0e-3, 0.3, 3.0, 1.0e4], ids=["delta at its bound", "far", "near", "close"]
)
def test_distinguishability_is_the_rolling_fit_of_the_noiseless_film(mu0: float) -> None:
    """`distinguishability` fits without the standard errors and the limit at a bound that
    `fit_model` adds: its delta and rms distance are those of `fit_model`, bit for bit, and
    its selection probability is scipy.stats.ncf's survival function."""
    from scipy.stats import ncf

    camera = film.Camera(fps=30.0, noise=2e-4, duration=10.0)
    d = fit.distinguishability(mu0, START, RIG, camera)
    t = film.frame_times(camera)
    xy = fit.positions("slipping", mu0, START, t, RIG)
    full = fit.fit_model(film.Film(t, xy[:, 0], xy[:, 1]), RIG, "rolling_resistance")
    assert (d.delta, d.rms_distance) == (full.coefficient, full.rms_residual)
    assert d.noncentrality == full.rss / camera.noise**2
    n, p_s, q = full.n_observations, fit.n_parameters("slipping"), 2
    k_s, k_r = p_s + 1, p_s - 1
    penalty = 2 * q + 2 * k_s * (k_s + 1) / (n - k_s - 1) - 2 * k_r * (k_r + 1) / (n - k_r - 1)
    threshold = math.expm1(penalty / n) * (n - p_s) / q
    expected = ncf.sf(threshold, q, n - p_s, d.noncentrality)
    assert d.selection_probability == pytest.approx(expected, rel=1e-12, abs=1e-15)
