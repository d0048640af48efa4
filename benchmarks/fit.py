"""Fitting a film: time of one fit, coverage of the standard errors, selection accuracy.

Time: `turntable.fit.fit_film` (both models), each `fit_model`, the fit with Omega free,
the check with Omega and the axis free (`turntable.fit.consistency`, which the command
runs too), on the film of the configured rig (the workflow's configuration, section film: 240
frames/s for 10 s, 2401 frames), best of repeats; and the wall-clock time of the command
``turntable fit`` on that film, interpreter start included.

Statistics over random films, in four regimes:

``easy``
    for each seed a random truth (model alternating; radius 3-8 mm, 30-50 rpm, k = 2/5 or
    2/3, the ball 4-8 cm from the axis with random velocity and spin; mu0 log-uniform in
    [0.05, 20], delta in [0.003, 0.3]), filmed at 60 frames/s for 10 s with 0.2 mm noise;
``limit``
    the same random balls, but the slipping ones with mu0 log-uniform within a factor 3 of
    the mu0 above which that camera can no longer tell slipping from rolling
    (`turntable.fit.indistinguishable_above` at selection probability 0.95), the rolling
    ones with the delta of the rolling path closest to such a slipping ball: the two
    motions nearly coincide;
``short``
    the random truths of ``easy`` filmed for 1 s at 60 frames/s (61 frames, under one turn
    of the turntable);
``few_frames``
    the same filmed at 240 frames/s for 15 to 20 frames (the fewest with which a model is
    selected, `turntable.fit.min_frames`);
``wrong_omega``
    the random truths of ``easy`` on a turntable 0.4 % faster than the rate given to the
    fit (the same ball in SI units): how often the command warns, and how often it selects
    the wrong model without any warning.

Films are the exact solution plus Gaussian noise (`turntable.fit.simulate_film`), fitted
with both models, the check with Omega and the axis free included.  Coverage: the fraction
of films whose true coefficient lies within 2 reported standard errors of the fit of the
true model (0.9545 expected; its binomial standard deviation is given), and the fraction
within the 95 % interval on the log scale; fits at a bound count as misses there, and their
one-sided limit is checked on its own; and the coverage among the fits that the command
does not flag (not at a bound, relative error at most
`turntable.fit.LINEAR_RELATIVE_ERROR`).  Selection accuracy: the fraction of films for
which AICc selects the true model, with how many selections were decisive, decisive and
wrong, or refused; for the slipping films, the accuracy that
`turntable.fit.distinguishability` predicts.  False alarms: films of the true Omega and axis
for which a warning says that neither model fits or that the film prefers another Omega
or axis.

Also, on the configured rig: the Cramer-Rao bound against the scatter of the fitted ln mu0
over seeds at one mu0 where its predicted relative error is below the reliable level of
Fig. 8 (config ``fig8_measurability.reliable_relative_error``) and one above; the one-sided
limits of fits at the bound; and a film of 33 1/3 rpm fitted as 33.2 rpm, then with Omega
free.

Run ``python benchmarks/fit.py`` (``--quick``: 40 seeds instead of 200 in the easy regime,
20 instead of 100 in the others), or all benchmarks with ``python benchmarks/run.py``
(``make bench``); the result is merged into ``results/benchmarks.json`` under the key
``fit``.
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import math
import shutil
import subprocess
import tempfile
import time
from collections.abc import Sequence
from typing import Any

import numpy as np

import _common
import turntable as tt
from _common import best_time
from turntable import film, fit
from turntable._blas import one_blas_thread
from turntable.config import validate

NAME = "fit"
ROOT = Path(__file__).resolve().parents[1]

#: The camera of the easy and the limit regimes.
CAMERA = film.Camera(fps=60.0, noise=2e-4, duration=10.0)
#: The camera of each regime (few_frames: the duration is set per film).
CAMERAS = {
    "easy": CAMERA,
    "limit": CAMERA,
    "short": film.Camera(fps=60.0, noise=2e-4, duration=1.0),
    "few_frames": film.Camera(fps=240.0, noise=2e-4, duration=14 / 240),
    "wrong_omega": CAMERA,
}
#: In regime wrong_omega, the turntable turns this much faster than the rate the fit is given.
OMEGA_ERROR = 1.004
#: Log-uniform ranges of the random coefficients.
RANGES = {"slipping": (0.05, 20.0), "rolling_resistance": (0.003, 0.3)}
#: Coverage expected of 2 standard errors.
COVERAGE_P = 0.9545
#: Selection probability that defines the limit of the ``limit`` regime.
LIMIT_PROBABILITY = 0.95


def _config() -> dict[str, Any]:
    """The reference configuration: the defaults of the workflow's schema."""
    config: dict[str, Any] = {}
    validate(config, ROOT / "workflow" / "schemas" / "config.schema.yaml")
    return config


def random_truth(rng: np.random.Generator, model: str) -> tuple[film.Setup, float, np.ndarray]:
    """A random ball, turntable, coefficient and start (see the module docstring)."""
    setup = film.Setup(
        radius=float(rng.uniform(3e-3, 8e-3)),
        omega=film.rpm_to_omega(float(rng.uniform(30.0, 50.0))),
        k=float(rng.choice([0.4, 2.0 / 3.0])),
        axis=(float(rng.uniform(-0.05, 0.05)), float(rng.uniform(-0.05, 0.05))),
    )
    c = float(np.exp(rng.uniform(*np.log(RANGES[model]))))
    angle = rng.uniform(0.0, 2.0 * np.pi)
    position = np.asarray(setup.axis) + rng.uniform(0.04, 0.08) * np.array(
        [np.cos(angle), np.sin(angle)]
    )
    z0 = film.state_from_si(position, rng.uniform(-0.02, 0.02, 2), rng.uniform(-2, 2, 2), setup)
    if model == "rolling_resistance":
        z0 = tt.no_slip_state(z0, setup.k)
    return setup, c, z0


def limit_truth(
    rng: np.random.Generator, model: str, camera: film.Camera
) -> tuple[film.Setup, float, np.ndarray]:
    """A random ball near the limit of what ``camera`` can tell apart (module docstring)."""
    setup, _, z0 = random_truth(rng, "slipping")
    grid = np.geomspace(0.3, 3000.0, 25)
    table = fit.measurability(grid, z0, setup, camera)
    limit = fit.indistinguishable_above(table, LIMIT_PROBABILITY)
    limit = min(max(limit, grid[0]), grid[-1])
    mu0 = float(limit * np.exp(rng.uniform(-math.log(3.0), math.log(3.0))))
    if model == "slipping":
        return setup, mu0, z0
    delta = fit.distinguishability(mu0, z0, setup, camera).delta
    return setup, float(delta), tt.no_slip_state(z0, setup.k)


def bench_time(repeat: int) -> dict[str, Any]:
    """Time of one fit on the film of the configured rig."""
    config = _config()
    rig = film.rig_from_config(config["film"])
    (spec,) = [f for f in config["synthetic_film"]["films"] if f["name"] == "slipping"]
    data = fit.simulate_film(
        spec["model"], spec["coefficient"], rig.state0, rig.setup, rig.camera, spec["seed"]
    )
    result = fit.fit_film(data, rig.setup)
    times = {"fit_film (both models)": best_time(lambda: fit.fit_film(data, rig.setup), repeat, 1)}
    for model in fit.MODELS:
        times[f"fit_model {model}"] = best_time(
            lambda model=model: fit.fit_model(data, rig.setup, model), repeat, 1
        )
    times["fit_film, Omega free"] = best_time(
        lambda: fit.fit_film(data, rig.setup, fit_omega=True), repeat, 1
    )
    times["consistency (both models, Omega and axis free)"] = best_time(
        lambda: fit.consistency(data, rig.setup, result), repeat, 1
    )
    command = shutil.which("turntable") or str(Path(sys.executable).with_name("turntable"))
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "film.csv"
        film.write_film(path, data)
        args = [command, "fit", str(path), "--radius", repr(rig.setup.radius)]
        args += ["--omega", repr(rig.setup.omega), "--k", repr(rig.setup.k)]
        walls = []
        for _ in range(repeat):
            start = time.perf_counter()
            subprocess.run(args, check=True, capture_output=True)
            walls.append(time.perf_counter() - start)
    times["command turntable fit (wall clock, with the check)"] = min(walls)
    return {
        "what": (
            f"one fit of a film of {data.t.size} frames (section film of the configuration: "
            f"{rig.camera.fps:g} frames/s, {rig.camera.duration:g} s; the synthetic film "
            f"'slipping'); best of {repeat}"
        ),
        "n_frames": int(data.t.size),
        "time_s": times,
    }


def _one_film(regime: str, seed: int, rng: np.random.Generator) -> dict[str, Any]:
    """Fit one random film of ``regime``; return what the statistics need."""
    model = fit.MODELS[seed % 2]
    camera = CAMERAS[regime]
    if regime == "limit":
        setup, c, z0 = limit_truth(rng, model, camera)
    else:
        setup, c, z0 = random_truth(rng, model)
    if regime == "few_frames":
        camera = camera._replace(duration=float(rng.integers(14, 20)) / camera.fps)
    if regime == "wrong_omega":
        # filmed at a rate 0.4 % above the one given to the fit, the ball started with the
        # same position, velocity and spin in SI units (on the no-slip constraint if rolling)
        true = setup._replace(omega=setup.omega * OMEGA_ERROR)
        z_true = z0.copy()
        z_true[2:] /= OMEGA_ERROR
        if model == "rolling_resistance":
            z_true = tt.no_slip_state(z_true, setup.k)
        data = fit.simulate_film(model, c, z_true, true, camera, seed)
    else:
        data = fit.simulate_film(model, c, z0, setup, camera, seed)
    result = fit.fit_film(data, setup)
    check = fit.consistency(data, setup, result)
    warnings = fit.problems(result, data, setup, check)
    shown = fit.checked_selection(result, check)  # "decisive" as the command reports it
    own = result.fits[model]
    lo, hi = own.ci95 if own.bound is None else (math.nan, math.nan)
    predicted = math.nan
    if model == "slipping" and data.t.size >= fit.min_frames():
        predicted = fit.distinguishability(c, z0, setup, camera).selection_probability
    return {
        "model": model,
        "z": (own.coefficient - c) / own.stderr if own.bound is None else math.nan,
        "in_interval": bool(lo < c < hi),
        # a value the command does not flag: not at a bound, relative error <= 0.2
        "linear": own.bound is None and own.log_stderr <= fit.LINEAR_RELATIVE_ERROR,
        "at_bound": own.bound is not None,
        "limit_holds": bool(
            (own.bound == "upper" and own.limit < c) or (own.bound == "lower" and own.limit > c)
        ),
        "selected": result.selected == model,
        "decisive": shown.decisive,
        "refused": result.selected is None,
        "decisive_wrong": bool(shown.decisive and result.selected != model),
        "predicted_selection": predicted,
        "false_alarm": any(
            "neither model fits" in w or "the film prefers" in w or "rests on the given" in w
            for w in warnings
        ),
        "warned": bool(warnings),
        "wrong_unwarned": bool(result.selected not in (None, model) and not warnings),
        "n_frames": int(data.t.size),
    }


def bench_statistics(regime: str, n_seeds: int) -> dict[str, Any]:
    """Coverage and selection accuracy over ``n_seeds`` random films of ``regime``."""
    seeds = {"easy": 2026, "limit": 2027, "short": 2028, "few_frames": 2029, "wrong_omega": 2030}
    rng = np.random.default_rng(seeds[regime])
    start = time.perf_counter()
    rows = [_one_film(regime, seed, rng) for seed in range(n_seeds)]
    elapsed = time.perf_counter() - start

    def fraction(key: str, among: list[dict[str, Any]] = rows) -> float:
        return float(np.mean([r[key] for r in among])) if among else math.nan

    z = np.array([r["z"] for r in rows])
    finite = z[np.isfinite(z)]
    bound = [r for r in rows if r["at_bound"]]
    camera = CAMERAS[regime]
    frames = sorted({r["n_frames"] for r in rows})
    out: dict[str, Any] = {
        "what": (
            f"{n_seeds} random films (models alternating), {camera.fps:g} frames/s, "
            f"{frames[0]}-{frames[-1]} frames, noise {camera.noise:g} m; exact solution plus "
            "noise"
        ),
        "n_films": n_seeds,
        "coverage_2se": float(np.mean(np.abs(z) < 2.0)),  # nan (at a bound) counts as a miss
        "coverage_ci95_log": fraction("in_interval"),
        "n_linear": int(sum(r["linear"] for r in rows)),
        "coverage_2se_linear": float(np.mean([abs(r["z"]) < 2.0 for r in rows if r["linear"]]))
        if any(r["linear"] for r in rows)
        else math.nan,
        "coverage_expected": COVERAGE_P,
        "coverage_binomial_sd": math.sqrt(COVERAGE_P * (1 - COVERAGE_P) / n_seeds),
        "z_mean": float(finite.mean()) if finite.size else math.nan,
        "z_std": float(finite.std(ddof=1)) if finite.size > 1 else math.nan,
        "n_at_bound": len(bound),
        "limits_that_hold": int(sum(r["limit_holds"] for r in bound)),
        "selection_accuracy": fraction("selected"),
        "decisive": fraction("decisive"),
        "decisive_and_wrong": int(sum(r["decisive_wrong"] for r in rows)),
        "refused": int(sum(r["refused"] for r in rows)),
        # with the true Omega and axis, warnings that say they are wrong (false alarms);
        # in regime wrong_omega, the same warnings are the detections
        "false_alarms": int(sum(r["false_alarm"] for r in rows)),
        "warned": int(sum(r["warned"] for r in rows)),
        "wrong_and_unwarned": int(sum(r["wrong_unwarned"] for r in rows)),
        "per_model": {},
        "seconds": elapsed,
    }
    for model in fit.MODELS:
        mine = [r for r in rows if r["model"] == model]
        entry = {
            "n_films": len(mine),
            "coverage_2se": float(np.mean([abs(r["z"]) < 2.0 for r in mine])),
            "coverage_ci95_log": fraction("in_interval", mine),
            "selection_accuracy": fraction("selected", mine),
            "decisive_and_wrong": int(sum(r["decisive_wrong"] for r in mine)),
        }
        predicted = [
            r["predicted_selection"] for r in mine if math.isfinite(r["predicted_selection"])
        ]
        if predicted:
            entry["predicted_selection_accuracy"] = float(np.mean(predicted))
        out["per_model"][model] = entry
    out["pass"] = bool(abs(out["coverage_2se"] - COVERAGE_P) <= 3 * out["coverage_binomial_sd"])
    return out


def bench_reliable_level(n_seeds: int) -> dict[str, Any]:
    """Cramer-Rao bound against the scatter of ln mu0 on the configured rig, inside and
    outside the reliable range of Fig. 8."""
    config = _config()
    rig = film.rig_from_config(config["film"])
    level = config["fig8_measurability"]["reliable_relative_error"]
    points = []
    for target in (level / 2, 3 * level):
        # the mu0 (above the minimum of the error) where the predicted error is the target
        grid = np.geomspace(1.0, 1e4, 30)
        rel = [
            fit.predicted_stderr("slipping", m, rig.state0, rig.setup, rig.camera) / m for m in grid
        ]
        mu0 = float(np.exp(np.interp(math.log(target), np.log(rel), np.log(grid))))
        predicted = fit.predicted_stderr("slipping", mu0, rig.state0, rig.setup, rig.camera) / mu0
        logs, at_bound = [], 0
        for seed in range(n_seeds):
            data = fit.simulate_film("slipping", mu0, rig.state0, rig.setup, rig.camera, seed)
            f = fit.fit_model(data, rig.setup, "slipping")
            logs.append(math.log(f.coefficient))
            at_bound += f.at_bound
        scatter = float(np.std(logs, ddof=1))
        points.append(
            {
                "mu0": mu0,
                "predicted_relative_error": predicted,
                "scatter_of_ln_mu0": scatter,
                "ratio": scatter / predicted,
                "ratio_sd_if_reached": 1 / math.sqrt(2 * (n_seeds - 1)),
                "n_at_bound": at_bound,
                "inside_reliable_level": bool(predicted < level),
            }
        )
    return {
        "what": (
            f"configured rig ({rig.camera.fps:g} frames/s, {rig.camera.duration:g} s), "
            f"{n_seeds} seeds at each mu0; reliable_relative_error = {level:g}"
        ),
        "reliable_relative_error": level,
        "points": points,
    }


def bench_wrong_rate() -> dict[str, Any]:
    """The synthetic film 'slipping' of the configured rig fitted with 33.2 rpm for its
    33 1/3: the selection and warnings, then with Omega free."""
    config = _config()
    rig = film.rig_from_config(config["film"])
    (spec,) = [f for f in config["synthetic_film"]["films"] if f["name"] == "slipping"]
    data = fit.simulate_film(
        spec["model"], spec["coefficient"], rig.state0, rig.setup, rig.camera, spec["seed"]
    )
    given = rig.setup._replace(omega=film.rpm_to_omega(33.2))
    out: dict[str, Any] = {"true_omega_rad_s": rig.setup.omega, "given_omega_rad_s": given.omega}
    for name, free in (("given_rate", False), ("fit_omega", True)):
        r = fit.fit_film(data, given, fit_omega=free)
        check = fit.consistency(data, given, r, fit_omega=free)
        f = r.fits["slipping"]
        out[name] = {
            "selected": r.selected,
            "aicc_difference": r.aicc_difference,
            "decisive": fit.checked_selection(r, check).decisive,
            "mu0": f.coefficient,
            "mu0_stderr": f.stderr,
            "omega_rad_s": f.omega,
            "omega_stderr_rad_s": f.omega_stderr,
            "warnings": fit.problems(r, data, given, check),
        }
    return out


def _json_safe(value: Any) -> Any:
    """``value`` with every non-finite float replaced by None (the results file is JSON)."""
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    if isinstance(value, dict):
        return {k: _json_safe(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [_json_safe(v) for v in value]
    return value


def _g(value: float | None, spec: str) -> str:
    """``value`` formatted with ``spec``, "n/a" for None."""
    return "n/a" if value is None else format(value, spec)


def print_result(res: dict[str, Any]) -> None:
    """Print the fit section."""
    t = res["time"]
    print(f"\n== fit: {t['what']}")
    for name, seconds in t["time_s"].items():
        print(f"  {name:<52}{1e3 * seconds:10.1f} ms")
    for regime, s in res["statistics"].items():
        print(f"  {regime}: {s['what']} ({s['seconds']:.0f} s)")
        print(
            f"    coverage of 2 standard errors: {s['coverage_2se']:.3f} (expected "
            f"{s['coverage_expected']} +- {s['coverage_binomial_sd']:.3f}: "
            f"{_common.pf(s['pass'])}); of the 95 % log interval {s['coverage_ci95_log']:.3f}; "
            f"z-scores mean {_g(s['z_mean'], '+.3f')}, standard deviation "
            f"{_g(s['z_std'], '.3f')}; "
            f"{s['n_at_bound']} at a bound, limit holds in {s['limits_that_hold']}; "
            f"{s['n_linear']} with a relative error <= {fit.LINEAR_RELATIVE_ERROR:g} (no "
            f"warning), their coverage {_g(s['coverage_2se_linear'], '.3f')}"
        )
        print(
            f"    selection accuracy {s['selection_accuracy']:.3f}, decisive {s['decisive']:.3f}, "
            f"decisive and wrong {s['decisive_and_wrong']}, refused {s['refused']}; "
            f"Omega/axis/fit warnings {s['false_alarms']}, any warning {s['warned']}, wrong "
            f"selection without any warning {s['wrong_and_unwarned']}"
        )
        for model, entry in s["per_model"].items():
            extra = ""
            if "predicted_selection_accuracy" in entry:
                extra = f" (predicted {entry['predicted_selection_accuracy']:.3f})"
            print(
                f"      {model:<20} {entry['n_films']} films: "
                f"coverage {entry['coverage_2se']:.3f}, "
                f"selection accuracy {entry['selection_accuracy']:.3f}{extra}"
            )
    r = res["reliable_level"]
    print(f"  Cramer-Rao bound against scatter: {r['what']}")
    for p in r["points"]:
        print(
            f"    mu0 = {p['mu0']:.4g}: predicted {p['predicted_relative_error']:.3g}, scatter of "
            f"ln mu0 {p['scatter_of_ln_mu0']:.3g} (ratio {p['ratio']:.3g} +- "
            f"{p['ratio_sd_if_reached']:.2g} if reached), {p['n_at_bound']} at a bound"
        )
    w = res["wrong_rate"]
    for name in ("given_rate", "fit_omega"):
        e = w[name]
        print(
            f"  33.2 rpm for 33 1/3, {name}: selected {e['selected']} (AICc difference "
            f"{_g(e['aicc_difference'], '.4g')}), mu0 = {e['mu0']:.5g} +- {e['mu0_stderr']:.2g}, "
            f"Omega = {e['omega_rad_s']:.6g}; {len(e['warnings'])} warnings"
        )
        for line in e["warnings"]:
            print(f"      {line}")


def run(quick: bool) -> dict[str, Any]:
    """Time (best of 5, or 2 if ``quick``) and statistics over 200 easy films and 100 of
    each harder regime (or 40 and 20)."""
    easy, hard = (40, 20) if quick else (200, 100)
    return _json_safe(
        {
            "time": bench_time(2 if quick else 5),
            "statistics": {
                "easy": bench_statistics("easy", easy),
                "limit": bench_statistics("limit", hard),
                "short": bench_statistics("short", hard),
                "few_frames": bench_statistics("few_frames", hard),
                "wrong_omega": bench_statistics("wrong_omega", hard // 2),
            },
            "reliable_level": bench_reliable_level(10 if quick else 30),
            "wrong_rate": bench_wrong_rate(),
        }
    )


def main(argv: Sequence[str] | None = None) -> int:
    """Run this benchmark alone; return 0 (the pass/fail verdicts are in the output)."""
    argv = sys.argv[1:] if argv is None else argv
    return _common.main([sys.modules[__name__]], __file__, __doc__.splitlines()[0], argv)


if __name__ == "__main__":
    one_blas_thread()
    sys.exit(main())
