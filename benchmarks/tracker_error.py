"""The size of the tracker's smooth error (`turntable.video.uncertainty.TRACKER_ERROR`),
estimated from the benchmark's videos, and the coverage it gives.

Each tracked video i of ``benchmarks/video.py``, ``unseen.py`` and ``raycast.py`` (their rows
in ``results/benchmarks.json``, the coefficient not at a bound) gives d_i = ln(fitted / true),
its statistical and calibration parts s_i (of ln c) and its tracker's part per unit of the
field's rms, u_i.  d_i ~ N(0, s_i^2 + sigma^2 u_i^2); sigma is estimated by maximum
likelihood, with its upper one-sided 90 % limit (the profile of -2 ln L up by 1.28^2).  With
sigma, the coverage (true coefficient within 2 SE) and the largest |z| are given over all the
videos, each video's with sigma estimated without it (leave one out), and each renderer's
videos' with sigma estimated on the other renderers' alone (out of sample).

Run ``python benchmarks/tracker_error.py`` after them; the result is merged into
``results/benchmarks.json`` under ``tracker_error``.
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import json
import math

import numpy as np
from scipy.optimize import brentq, minimize_scalar

from results_file import ROOT, merge_results
from turntable.video.uncertainty import TRACKER_ERROR

#: Range of sigma searched, ball radii.
SIGMA_RANGE = (1e-6, 0.05)


def videos(results: dict) -> dict[str, tuple[float, float, float, float]]:
    """name: (d, s, u, true / fitted) of every tracked video whose coefficient is not at a
    bound, u from the field's rms the benchmark ran with."""
    rows = {f"{r['family']}_{i}": r for i, r in enumerate(results["video"]["rows"])}
    rows |= {r["case"]: r for r in results["unseen"]["rows"]}
    rows |= raycast_rows(results)
    out = {}
    for name, r in rows.items():
        if not r["tracked"] or r.get("at_bound", True) or "tracker_error" not in r:
            continue
        stat, cal = r["stderr_statistical"] / r["fitted"], r["stderr_calibration"] / r["fitted"]
        u = r["stderr_tracker"] / r["fitted"] / r["tracker_error"]
        out[name] = (math.log(r["fitted"] / r["coefficient"]), math.hypot(stat, cal), u,
                     r["coefficient"] / r["fitted"])  # fmt: skip
    return out


def raycast_rows(results: dict) -> dict[str, dict]:
    """The ray caster's scenes (``benchmarks/raycast.py``) tracked and fitted, without seeds
    or with them, right or wrong, in the rows' form of the other two benchmarks."""
    out = {}
    for r in results.get("raycast", {}).get("rows", []):
        run = r if r.get("fit_exit") == 0 else r.get("seeded") or {}
        if run.get("fit_exit") == 0 and run.get("mu0") is not None and "tracker_error" in run:
            out[r["scene"]] = run | {"tracked": True, "fitted": run["mu0"],
                                     "coefficient": run["mu0_true"]}  # fmt: skip
    return out


def minus_two_log_l(sigma: float, data) -> float:
    return sum(math.log(s**2 + (sigma * u) ** 2) + d**2 / (s**2 + (sigma * u) ** 2)
               for d, s, u, _ in data)  # fmt: skip


def estimate(data) -> tuple[float, float]:
    """The maximum-likelihood sigma and its upper one-sided 90 % limit."""
    lo, hi = (math.log(v) for v in SIGMA_RANGE)
    best = minimize_scalar(lambda x: minus_two_log_l(math.exp(x), data), bounds=(lo, hi),
                           method="bounded").x  # fmt: skip
    level = minus_two_log_l(math.exp(best), data) + 1.2816**2
    excess = lambda x: minus_two_log_l(math.exp(x), data) - level  # noqa: E731
    upper = math.exp(brentq(excess, best, hi)) if excess(hi) > 0 else SIGMA_RANGE[1]
    return math.exp(best), upper


def across_renderers(data, renderer: dict[str, str]) -> dict[str, dict]:
    """Each renderer's videos judged with sigma sized on the other renderers' alone."""
    out = {}
    for tested_on in sorted(set(renderer.values())):
        sized = [v for n, v in data.items() if renderer[n] != tested_on]
        tested = {n: v for n, v in data.items() if renderer[n] == tested_on}
        if len(sized) < 2 or not tested:
            continue
        sigma = estimate(sized)[0]
        zs = np.array([z(v, sigma) for v in tested.values()])
        out[f"tested_on_{tested_on}"] = {
            "sized_on": sorted({renderer[n] for n in data} - {tested_on}),
            "sigma_ml": sigma, "videos_tested": len(tested),
            "coverage_2se": float(np.mean(np.abs(zs) < 2)),
            "largest_abs_z": float(np.max(np.abs(zs))),
            "beyond_4se": sorted(n for n, v in zip(tested, zs, strict=True) if abs(v) > 4),
        }  # fmt: skip
    return out


def by_renderer(data, renderer: dict[str, str]) -> dict[str, dict]:
    """Sigma of each renderer's videos alone: most likely, and its upper 90 % limit."""
    out = {}
    for name in sorted(set(renderer.values())):
        own = [v for n, v in data.items() if renderer[n] == name]
        if len(own) >= 2:
            sigma, upper = estimate(own)
            out[name] = {"videos": len(own), "sigma_ml": sigma, "sigma_upper_90": upper}
    return out


def z(video, sigma: float) -> float:
    """(fitted - true) / SE, as the benchmarks count it."""
    _, s, u, ratio = video
    return (1 - ratio) / math.hypot(s, sigma * u)


def main() -> None:
    results = json.loads((ROOT / "results/benchmarks.json").read_text())
    data = videos(results)
    renderer = {f"{r['family']}_{i}": r["renderer"] for i, r in enumerate(results["video"]["rows"])}
    renderer |= {r["case"]: "mujoco" for r in results["unseen"]["rows"]}
    renderer |= dict.fromkeys(raycast_rows(results), "raycast")
    if len(data) < 2:
        sys.exit(
            "tracker_error.py: fewer than 2 videos with the tracker's part in "
            "results/benchmarks.json: run benchmarks/video.py and benchmarks/unseen.py"
        )
    sigma, upper = estimate(list(data.values()))
    inside = np.array([z(v, TRACKER_ERROR) for v in data.values()])
    alone = {n: z(v, estimate([w for m, w in data.items() if m != n])[0]) for n, v in data.items()}
    out = np.array(list(alone.values()))
    res = {
        "synthetic": True, "videos": len(data), "sigma_ml": sigma, "sigma_upper_90": upper,
        "tracker_error": TRACKER_ERROR,
        "coverage_2se": float(np.mean(np.abs(inside) < 2)),
        "largest_abs_z": float(np.max(np.abs(inside))),
        "rms_z": float(np.sqrt(np.mean(inside**2))),
        "coverage_2se_leave_one_out": float(np.mean(np.abs(out) < 2)),
        "largest_abs_z_leave_one_out": float(np.max(np.abs(out))),
        "beyond_4se_leave_one_out": sorted(n for n, v in alone.items() if abs(v) > 4),
        "across_renderers": across_renderers(data, renderer),
        "by_renderer": by_renderer(data, renderer),
    }  # fmt: skip
    merge_results(ROOT / "results/benchmarks.json", {"tracker_error": res})
    print(json.dumps(res, indent=1))


if __name__ == "__main__":
    main()
