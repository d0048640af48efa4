"""Fitting a film: time of one fit, coverage of the standard errors, selection accuracy.

Time: `turntable.fit.fit_film` (both models) and each `fit_model` on the film of the
configured rig (config/config.yaml, section film: 240 frames/s for 10 s, 2401 frames),
best of repeats; and the wall-clock time of the command ``turntable fit`` on that film,
interpreter start included.

Statistics over random films: for each seed a random truth (model alternating; radius
3-8 mm, 30-50 rpm, k = 2/5 or 2/3, the ball 4-8 cm from the axis with random velocity and
spin; mu0 log-uniform in [0.05, 20], delta in [0.003, 0.3]), filmed at 60 frames/s for 10 s
with 0.2 mm noise (exact solution plus Gaussian noise, `turntable.film.simulate_film`),
fitted with both models.  Coverage: the fraction of films whose true coefficient lies
within 2 reported standard errors of the fit of the true model (0.9545 expected; its
binomial standard deviation is given).  Selection accuracy: the fraction of films for
which AIC selects the true model, with, for the slipping films, the accuracy that
`turntable.fit.distinguishability` predicts.

Run ``python benchmarks/fit.py`` (``--quick``: 40 seeds instead of 200), or all
benchmarks with ``python benchmarks/run.py`` (``make bench``); the result is merged into
``results/benchmarks.json`` under the key ``fit``.
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from blas_threads import one_blas_thread

if __name__ == "__main__":
    one_blas_thread()

import math
import shutil
import subprocess
import tempfile
import time
from collections.abc import Sequence
from typing import Any

import numpy as np
import yaml

import _common
import turntable as tt
from _common import best_time
from turntable import film, fit

NAME = "fit"
ROOT = Path(__file__).resolve().parents[1]

#: The camera of the statistics.
CAMERA = film.Camera(fps=60.0, noise=2e-4, duration=10.0)
#: Log-uniform ranges of the random coefficients.
RANGES = {"slipping": (0.05, 20.0), "rolling_resistance": (0.003, 0.3)}
#: Coverage expected of 2 standard errors.
COVERAGE_P = 0.9545


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


def bench_time(repeat: int) -> dict[str, Any]:
    """Time of one fit on the film of the configured rig."""
    config = yaml.safe_load((ROOT / "config" / "config.yaml").read_text())
    rig = film.rig_from_config(config["film"])
    (spec,) = [f for f in config["synthetic_film"]["films"] if f["name"] == "slipping"]
    data = film.simulate_film(
        spec["model"], spec["coefficient"], rig.state0, rig.setup, rig.camera, spec["seed"]
    )
    times = {"fit_film (both models)": best_time(lambda: fit.fit_film(data, rig.setup), repeat, 1)}
    for model in fit.MODELS:
        times[f"fit_model {model}"] = best_time(
            lambda model=model: fit.fit_model(data, rig.setup, model), repeat, 1
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
    times["command turntable fit (wall clock)"] = min(walls)
    return {
        "what": (
            f"one fit of a film of {data.t.size} frames (section film of config/config.yaml: "
            f"{rig.camera.fps:g} frames/s, {rig.camera.duration:g} s; the synthetic film "
            f"'slipping'); best of {repeat}"
        ),
        "n_frames": int(data.t.size),
        "time_s": times,
    }


def bench_statistics(n_seeds: int) -> dict[str, Any]:
    """Coverage and selection accuracy over ``n_seeds`` random films."""
    rng = np.random.default_rng(2026)
    rows = []
    start = time.perf_counter()
    for seed in range(n_seeds):
        model = fit.MODELS[seed % 2]
        setup, c, z0 = random_truth(rng, model)
        data = film.simulate_film(model, c, z0, setup, CAMERA, seed)
        result = fit.fit_film(data, setup)
        own = result.fits[model]
        predicted = (
            fit.distinguishability(c, z0, setup, CAMERA).selection_probability
            if model == "slipping"
            else math.nan
        )
        rows.append(
            {
                "model": model,
                "z": (own.coefficient - c) / own.stderr,
                "selected": result.selected == model,
                "predicted_selection": predicted,
            }
        )
    elapsed = time.perf_counter() - start
    z = np.array([r["z"] for r in rows])
    inside = np.abs(z) < 2.0
    out: dict[str, Any] = {
        "what": (
            f"{n_seeds} random films (models alternating), {CAMERA.fps:g} frames/s, "
            f"{CAMERA.duration:g} s, noise {CAMERA.noise:g} m; exact solution plus noise"
        ),
        "n_films": n_seeds,
        "coverage_2se": float(inside.mean()),
        "coverage_expected": COVERAGE_P,
        "coverage_binomial_sd": math.sqrt(COVERAGE_P * (1 - COVERAGE_P) / n_seeds),
        "z_mean": float(z.mean()),
        "z_std": float(z.std(ddof=1)),
        "selection_accuracy": float(np.mean([r["selected"] for r in rows])),
        "per_model": {},
        "seconds": elapsed,
    }
    for model in fit.MODELS:
        mine = [r for r in rows if r["model"] == model]
        entry = {
            "n_films": len(mine),
            "coverage_2se": float(np.mean([abs(r["z"]) < 2.0 for r in mine])),
            "selection_accuracy": float(np.mean([r["selected"] for r in mine])),
        }
        if model == "slipping":
            entry["predicted_selection_accuracy"] = float(
                np.mean([r["predicted_selection"] for r in mine])
            )
        out["per_model"][model] = entry
    out["pass"] = bool(abs(out["coverage_2se"] - COVERAGE_P) <= 3 * out["coverage_binomial_sd"])
    return out


def print_result(res: dict[str, Any]) -> None:
    """Print the fit section."""
    t = res["time"]
    print(f"\n== fit: {t['what']}")
    for name, seconds in t["time_s"].items():
        print(f"  {name:<40}{1e3 * seconds:10.1f} ms")
    s = res["statistics"]
    print(f"  statistics: {s['what']} ({s['seconds']:.0f} s)")
    print(
        f"  coverage of 2 standard errors: {s['coverage_2se']:.3f} (expected "
        f"{s['coverage_expected']} +- {s['coverage_binomial_sd']:.3f}: {_common.pf(s['pass'])}); "
        f"z-scores mean {s['z_mean']:+.3f}, standard deviation {s['z_std']:.3f}"
    )
    print(f"  selection accuracy: {s['selection_accuracy']:.3f}")
    for model, entry in s["per_model"].items():
        extra = ""
        if "predicted_selection_accuracy" in entry:
            extra = f" (predicted {entry['predicted_selection_accuracy']:.3f})"
        print(
            f"    {model:<20} {entry['n_films']} films: coverage {entry['coverage_2se']:.3f}, "
            f"selection accuracy {entry['selection_accuracy']:.3f}{extra}"
        )


def run(quick: bool) -> dict[str, Any]:
    """Time (best of 5, or 2 if ``quick``) and statistics over 200 (or 40) films."""
    return {
        "time": bench_time(2 if quick else 5),
        "statistics": bench_statistics(40 if quick else 200),
    }


def main(argv: Sequence[str] | None = None) -> int:
    """Run this benchmark alone; return 0 (the pass/fail verdicts are in the output)."""
    argv = sys.argv[1:] if argv is None else argv
    return _common.main([sys.modules[__name__]], __file__, __doc__.splitlines()[0], argv)


if __name__ == "__main__":
    sys.exit(main())
