"""Speed of `turntable.solve` against scipy, with each method's error.

Run time of `turntable.solve` on 10^4 time points against ``scipy.integrate.solve_ivp``
(DOP853 and Radau) and against ``scipy.linalg.expm`` at each time point; errors against
the mpmath matrix exponential of `turntable.reference` (`expm_trajectories`).

Run ``python benchmarks/speed.py`` (``--quick``: fewer repeats), or all benchmarks with
``python benchmarks/run.py`` (``make bench``); the result is merged into
``results/benchmarks.json`` under the key ``speed``.
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from collections.abc import Sequence
from typing import Any

import numpy as np
import scipy.integrate
import scipy.linalg
from numpy.typing import NDArray

import _common
import turntable as tt
from _common import ERROR_MEASURE, INITIAL_STATES, K_BALL, best_time, fmt, mp_error, num, pf
from turntable import reference
from turntable._blas import one_blas_thread

NAME = "speed"

#: Required speed-up of `solve` over the faster solve_ivp method, by mu0.
SPEED_TARGETS = {1.0: 20.0, 100.0: 100.0, 1e4: 100.0}
#: Required ratio (solve_ivp error) / (solve error).
ACCURACY_RATIO_TARGET = 1000.0


def _ivp(L: NDArray[np.float64], z0: NDArray[np.float64], t: NDArray[np.float64], method: str):
    kwargs: dict[str, Any] = {"jac": L} if method == "Radau" else {}
    sol = scipy.integrate.solve_ivp(
        lambda _t, y: L @ y,
        (0.0, float(t[-1])),
        z0,
        method=method,
        t_eval=t,
        rtol=1e-10,
        atol=1e-12,
        **kwargs,
    )
    if not sol.success:
        raise RuntimeError(f"solve_ivp {method} failed: {sol.message}")
    return sol.y.T


def _expm_points(L: NDArray[np.float64], z0: NDArray[np.float64], t: NDArray[np.float64]):
    return scipy.linalg.expm(L[None, :, :] * t[:, None, None]) @ z0


def bench_speed(
    mu0s: Sequence[float] = (1.0, 100.0, 1e4),
    k: float = K_BALL,
    n_points: int = 10_000,
    t_end: float = 50.0,
    n_ref: int = 101,
    repeat: int = 3,
    expm_stride: int = 10,
    probe_end: float = 0.5,
    probe_budget: float = 0.1,
    dps: int = 50,
) -> dict[str, Any]:
    """Time solve, solve_ivp (DOP853, Radau) and scipy expm per point; compare errors.

    Parameters
    ----------
    mu0s, k : float
        Cases; the initial state is that of Fig. 4.
    n_points, t_end : int, float
        ``t = linspace(0, t_end, n_points)``.
    n_ref : int
        Errors are measured at ``n_ref`` of the points (equally spaced
        indices, first and last included) against mpmath expm at ``dps``.
    repeat : int
        Timings are the best of ``repeat`` runs (the solve timing of
        ``repeat`` autoranged batches).
    expm_stride : int
        expm is timed on every ``expm_stride``-th point and the time scaled
        by the ratio of point counts.
    probe_end, probe_budget : float
        DOP853 is first timed on [0, probe_end]; if that takes more than
        ``probe_budget`` seconds the full run is not made and the time is
        scaled by t_end / probe_end (explicit steps are stability-limited,
        so their number grows linearly with the interval).

    Returns
    -------
    dict
        JSON-ready results with pass/fail per target.
    """
    z0 = np.array(INITIAL_STATES["fig4 (x=y=1, v=0, w=(0,1))"])
    t = np.linspace(0.0, t_end, n_points)
    idx = np.unique(np.linspace(0, n_points - 1, n_ref).round().astype(int))
    cases = []
    for mu0 in mu0s:
        L = tt.system_matrix(mu0, k)
        zref = reference.expm_trajectories([z0], t[idx], mu0, k, dps)[0]
        row: dict[str, Any] = {"mu0": mu0, "methods": {}}

        t_solve = best_time(lambda mu0=mu0: tt.solve(z0, t, mu0, k), repeat=max(repeat, 5))
        err = mp_error(tt.solve(z0, t, mu0, k)[idx], zref)
        row["methods"]["turntable.solve"] = {"time_s": t_solve, "error": num(err)}

        for method in ("DOP853", "Radau"):
            if method == "DOP853":
                tp = t[t <= probe_end]
                t_probe = best_time(lambda L=L, tp=tp: _ivp(L, z0, tp, "DOP853"), repeat, 1)
                if t_probe > probe_budget:
                    # error over the probe interval, at a few of its points
                    ip = np.unique(np.linspace(0, len(tp) - 1, 6).round().astype(int))
                    zp = reference.expm_trajectories([z0], tp[ip], mu0, k, dps)[0]
                    e = mp_error(_ivp(L, z0, tp, method)[ip], zp)
                    row["methods"][method] = {
                        "time_s": t_probe * t_end / probe_end,
                        "error": num(e),
                        "note": (
                            f"timed on [0, {probe_end:g}] ({len(tp)} points) and scaled by "
                            f"{t_end / probe_end:g}; error at {len(ip)} points of [0, "
                            f"{probe_end:g}] only"
                        ),
                    }
                    continue
            elapsed = best_time(lambda L=L, method=method: _ivp(L, z0, t, method), repeat, 1)
            e = mp_error(_ivp(L, z0, t, method)[idx], zref)
            row["methods"][method] = {"time_s": elapsed, "error": num(e)}

        sub = t[::expm_stride]
        t_expm = best_time(lambda L=L, sub=sub: _expm_points(L, z0, sub), repeat, 1)
        e = mp_error(_expm_points(L, z0, t[idx]), zref)
        row["methods"]["scipy.linalg.expm per point"] = {
            "time_s": t_expm * n_points / len(sub),
            "error": num(e),
            "note": (
                f"expm(L t_i) z0 on the stacked times; timed on every {expm_stride}th "
                f"point ({len(sub)} points) and scaled by {n_points / len(sub):g}"
            ),
        }

        ivp = {m: row["methods"][m] for m in ("DOP853", "Radau")}
        fastest = min(ivp, key=lambda m: ivp[m]["time_s"])
        speedup = ivp[fastest]["time_s"] / t_solve
        acc_ratio = float(ivp[fastest]["error"]) / max(err, np.finfo(float).tiny)
        need = SPEED_TARGETS.get(float(mu0), 100.0)
        row["faster_solve_ivp"] = fastest
        row["speedup_vs_faster_solve_ivp"] = speedup
        row["speedup_vs_expm"] = row["methods"]["scipy.linalg.expm per point"]["time_s"] / t_solve
        row["error_ratio_faster_solve_ivp_over_solve"] = num(acc_ratio)
        row["target_speedup"] = need
        row["pass_speed"] = bool(speedup >= need)
        row["target_error_ratio"] = ACCURACY_RATIO_TARGET
        row["pass_accuracy"] = bool(acc_ratio >= ACCURACY_RATIO_TARGET)
        cases.append(row)

    return {
        "what": (
            f"time of one call on t = linspace(0, {t_end:g}, {n_points}), k = {k:g}, "
            "z0 = x=y=1, v=0, w=(0,1); timeit best of repeats"
        ),
        "solve_ivp_options": "rtol=1e-10, atol=1e-12, t_eval=t; Radau with jac=L (exact)",
        "error_measure": ERROR_MEASURE
        + f"; at {len(idx)} equally spaced indices of t (first and last included)",
        "reference": f"mpmath.expm(L t) z0 at dps {dps}",
        "repeat": repeat,
        "cases": cases,
        "pass": bool(all(c["pass_speed"] and c["pass_accuracy"] for c in cases)),
    }


def print_result(res: dict[str, Any]) -> None:
    """Print the speed section."""
    print(f"\n== speed: {res['what']}")
    print(f"  solve_ivp: {res['solve_ivp_options']}")
    print(f"  error: {res['error_measure']}, against {res['reference']}")
    print(f"{'mu0':>8}  {'method':<30}{'time [ms]':>11}{'error':>10}  note")
    for c in res["cases"]:
        for name, m in c["methods"].items():
            note = m.get("note", "")
            print(f"{c['mu0']:8g}  {name:<30}{1e3 * m['time_s']:11.3f} {fmt(m['error'])}  {note}")
        print(
            f"{'':8}  speed-up vs {c['faster_solve_ivp']}: {c['speedup_vs_faster_solve_ivp']:.0f}x"
            f" (target {c['target_speedup']:g}x: {pf(c['pass_speed'])}); "
            f"error ratio {float(c['error_ratio_faster_solve_ivp_over_solve']):.1e} "
            f"(target {c['target_error_ratio']:g}: {pf(c['pass_accuracy'])}); "
            f"speed-up vs expm: {c['speedup_vs_expm']:.0f}x"
        )


# --------------------------------------------------------------------------------------
# main
# --------------------------------------------------------------------------------------


def run(quick: bool) -> dict[str, Any]:
    """The benchmark with 101 reference points and 3 repeats, or 26 and 2 if ``quick``."""
    return bench_speed(n_ref=26 if quick else 101, repeat=2 if quick else 3)


def main(argv: Sequence[str] | None = None) -> int:
    """Run this benchmark alone; return 0 (the pass/fail verdicts are in the output)."""
    argv = sys.argv[1:] if argv is None else argv
    return _common.main([sys.modules[__name__]], __file__, __doc__.splitlines()[0], argv)


if __name__ == "__main__":
    one_blas_thread()
    sys.exit(main())
