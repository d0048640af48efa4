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
def fits(truths: list[Truth]) -> list[list[fit.ModelFit]]:
    """The true model fitted to every noisy film: fits[i][seed] for truths[i]."""
    return [
        [fit.fit_model(tr.noisy(seed), tr.setup, tr.model) for seed in range(N_SEEDS)]
        for tr in truths
    ]


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


def test_the_model_of_the_data_is_selected(truths: list[Truth], fits: list) -> None:
    """On films of 2.5 to 5 turns, AIC prefers the model the film was made with, every
    time (15 seeds of each of the 4 truths); for the slipping truths `distinguishability`
    predicts as much."""
    for tr, row in zip(truths, fits, strict=True):
        if tr.model == "slipping":
            d = fit.distinguishability(tr.c, tr.z0, tr.setup, tr.camera)
            assert d.selection_probability > 0.999
        other = next(m for m in fit.MODELS if m != tr.model)
        for seed, own in enumerate(row[:N_SELECTION]):
            alternative = fit.fit_model(tr.noisy(seed), tr.setup, other)
            assert own.aic < alternative.aic, (tr.model, seed)


@pytest.mark.parametrize(
    ("mu0", "regime"),
    [(2.5, (3.0, 10.0)), (1.0, (80.0, 200.0))],
    ids=["lambda~5", "lambda~120"],
)
def test_selection_is_predicted(mu0: float, regime: tuple[float, float]) -> None:
    """Where the two models are close, the fraction of films that select the slipping model
    and the mean AIC difference agree with `distinguishability`.

    A short noisy film (4 s at 30 frames/s, 1 mm) of a slipping ball: noncentrality
    lambda about 5 (selection in about 3 of 4 films) and about 120, where the mean AIC
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
        diffs.append(f.fits["rolling_resistance"].aic - f.fits["slipping"].aic)
    diffs = np.array(diffs)
    p = d.selection_probability
    assert abs(np.mean(diffs > 0) - p) <= 3 * math.sqrt(p * (1 - p) / n) + 1 / n
    assert abs(diffs.mean() - d.expected_aic_difference) < 3 * diffs.std(ddof=1) / math.sqrt(n)


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
    assert m.expected_aic_difference[0] > 1e4
    assert m.expected_aic_difference[1] == pytest.approx(-2.0, abs=0.05)
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
    data = film.simulate_film("slipping", c, z0, setup, CAMERA, seed=5)
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
    data = film.simulate_film("rolling_resistance", c, z0, setup, CAMERA, seed=1)
    f = fit.fit_model(data, setup, "rolling_resistance")
    assert_allclose(rolling.slip_velocity(f.state0), 0.0, atol=1e-12)
    assert f.n_parameters == 5
    assert fit.fit_model(data, setup, "slipping").n_parameters == 7


def test_aic_and_weights() -> None:
    """AIC = N ln(RSS/N) + 2 (p + 1); weights are exp(-Delta/2) normalised."""
    rng = np.random.default_rng(8)
    setup, c, z0 = draw_truth(rng, "slipping")
    data = film.simulate_film("slipping", c, z0, setup, CAMERA, seed=2)
    r = fit.fit_film(data, setup)
    n = 2 * data.t.size
    for f in r.fits.values():
        assert f.n_observations == n
        assert f.aic == pytest.approx(n * math.log(f.rss / n) + 2 * (f.n_parameters + 1))
        assert f.rms_residual == pytest.approx(math.sqrt(f.rss / n))
    a_s, a_r = r.fits["slipping"].aic, r.fits["rolling_resistance"].aic
    assert r.aic_difference == pytest.approx(abs(a_s - a_r))
    w_s = 1.0 / (1.0 + math.exp(-(a_r - a_s) / 2.0))
    assert r.akaike_weights["slipping"] == pytest.approx(w_s)
    assert sum(r.akaike_weights.values()) == pytest.approx(1.0)


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
        data = film.simulate_film(model, c, z, setup, CAMERA, seed=9)
        out = fit.result_json(fit.fit_film(data, setup), setup, data, mass=mass)
        name, value, unit = dims[model]
        entry = out[model]
        assert abs(entry[f"{name}_dim_{unit}"] - value) < 4 * entry[f"{name}_dim_stderr_{unit}"]
        assert entry[f"{name}_dim_{unit}"] / entry[name] == pytest.approx(value / c)


def test_fitted_positions_from_the_json() -> None:
    rng = np.random.default_rng(12)
    setup, c, z0 = draw_truth(rng, "slipping")
    data = film.simulate_film("slipping", c, z0, setup, CAMERA, seed=3)
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
    a = film.simulate_film("slipping", 0.5, z0, setup, camera, seed=1)
    assert_allclose(np.diff(a.t), 0.01)
    assert a.t[-1] == pytest.approx(20.0)
    exact = fit.positions("slipping", 0.5, z0, a.t, setup)
    err = np.column_stack([a.x, a.y]) - exact
    assert abs(err.std() / 2e-4 - 1) < 3 / math.sqrt(2 * err.size)
    assert abs(err.mean()) < 3 * 2e-4 / math.sqrt(err.size)
    b = film.simulate_film("slipping", 0.5, z0, setup, camera, seed=1)
    c = film.simulate_film("slipping", 0.5, z0, setup, camera, seed=2)
    assert np.array_equal(a.x, b.x)
    assert not np.array_equal(a.x, c.x)
    path = tmp_path / "film.csv"
    header = film.synthetic_header("slipping", 0.5, z0, setup, camera, 1)
    film.write_film(path, a, header)
    text = path.read_text()
    assert text.startswith("# SYNTHETIC")
    assert "mu0 = 0.5" in text
    assert "seed = 1" in text
    back = film.read_film(path)
    assert_allclose(back.t, a.t, rtol=1e-9)
    assert_allclose(back.x, a.x, rtol=1e-9)
    with pytest.raises(ValueError, match="no-slip constraint"):
        film.simulate_film("rolling_resistance", 0.1, z0, setup, camera, seed=1)


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
