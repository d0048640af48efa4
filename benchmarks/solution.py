"""Accuracy and robustness of the solution: `turntable.solve` against exp(L t) z0.

Worst error of `turntable.solve` against the mpmath matrix exponential of
`turntable.reference` (`expm_trajectories`); robustness (no NaN, inf or floating-point
exception) over mu0 in [1e-12, 1e12] and t in [0, 1000]; consistency of
`turntable.modal_terms` with `turntable.solve`.

Run ``python benchmarks/solution.py`` (``--quick``: smaller grids), or all benchmarks
with ``python benchmarks/run.py`` (``make bench``); the result is merged into
``results/benchmarks.json`` under the key ``solution``.
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import warnings
from collections.abc import Sequence
from typing import Any

import mpmath
import numpy as np
from numpy.typing import NDArray

import _common
import turntable as tt
from _common import ERROR_MEASURE, INITIAL_STATES, K_BALL, K_SHELL, fmt, mp_error, num, pf
from turntable import reference
from turntable._blas import one_blas_thread

NAME = "solution"

#: Error of `turntable.solve`, relative to max(1, size of the trajectory).
SOLUTION_TARGET = 1e-12
#: Disagreement of `modal_terms` with `solve`, relative to max(1, size of the terms).
MODAL_TARGET = 1e-12


def _robustness(
    mu0s: Sequence[float],
    ks: Sequence[float],
    t: NDArray[np.float64],
    z0s: dict[str, Sequence[float]],
) -> dict[str, Any]:
    """Check solve and modal_terms for NaN/inf and floating-point exceptions."""
    levels = {
        "all": {"all": "raise"},
        "over_divide_invalid (underflow ignored)": {
            "over": "raise",
            "divide": "raise",
            "invalid": "raise",
            "under": "ignore",
        },
    }
    out: dict[str, Any] = {}
    modal_vs_terms = 0.0
    modal_vs_solution = 0.0
    for level, errstate in levels.items():
        failures: list[str] = []
        failing_mu0: list[float] = []
        for mu0 in mu0s:
            for k in ks:
                for label, z0 in z0s.items():
                    for name in ("solve", "modal_terms"):
                        try:
                            with warnings.catch_warnings(), np.errstate(**errstate):
                                warnings.simplefilter("error")
                                if name == "solve":
                                    z = tt.solve(z0, t, mu0, k)
                                    parts = None
                                else:
                                    parts = tt.modal_terms(z0, t, mu0, k)
                                    z = parts.centre + parts.plus + parts.minus
                            problem = None if np.all(np.isfinite(z)) else "non-finite output"
                        except (FloatingPointError, Warning) as exc:
                            problem = str(exc)
                        if problem is not None:
                            failures.append(f"{name} mu0={mu0:g} k={k:g} z0={label}: {problem}")
                            failing_mu0.append(float(mu0))
                            continue
                        if parts is not None and level != "all":
                            ref = tt.solve(z0, t, mu0, k)
                            diff = float(np.max(np.abs(z - ref)))
                            size = max(float(np.max(np.abs(p))) for p in parts)
                            modal_vs_terms = max(modal_vs_terms, diff / max(1.0, size))
                            modal_vs_solution = max(
                                modal_vs_solution, diff / max(1.0, float(np.max(np.abs(ref))))
                            )
        out[level] = {
            "pass": not failures,
            "n_failures": len(failures),
            "mu0_range_of_failures": [min(failing_mu0), max(failing_mu0)] if failing_mu0 else None,
            "first_failures": failures[:4],
        }
    return {
        "errstate_levels": out,
        "modal": {
            "what": (
                "max |centre + plus + minus - solve| divided by max(1, largest |term|) "
                "(and by max(1, max |solve|)), over the same grid"
            ),
            "relative_to_terms": num(modal_vs_terms),
            "relative_to_solution": num(modal_vs_solution),
            "target_relative_to_terms": MODAL_TARGET,
            "pass": bool(modal_vs_terms <= MODAL_TARGET),
        },
    }


def bench_solution(
    mu0s: Sequence[float],
    ks: Sequence[float],
    times: Sequence[float],
    robust_mu0s: Sequence[float],
    robust_times: NDArray[np.float64],
    dps: int = 50,
    check_dps: int = 70,
) -> dict[str, Any]:
    """Error of `turntable.solve` against the mpmath matrix exponential, and robustness.

    Parameters
    ----------
    mu0s, ks, times : sequence of float
        Grid of the accuracy test; every initial state of INITIAL_STATES is used.
    robust_mu0s, robust_times : array_like
        Grid of the NaN / inf / floating-point-exception check and of the
        modal_terms consistency check (same ks and initial states).
    dps, check_dps : int
        Precision of the reference, and the precision it is compared with on
        the stiffest case (largest mu0 / k, all times).

    Returns
    -------
    dict
        JSON-ready results.
    """
    z0s = list(INITIAL_STATES.values())
    t = np.asarray(times, dtype=float)
    worst: dict[str, float] = {}
    cases = []
    for k in ks:
        for mu0 in mu0s:
            ref = reference.expm_trajectories(z0s, t, mu0, k, dps)
            for (label, z0), zref in zip(INITIAL_STATES.items(), ref, strict=True):
                err = mp_error(tt.solve(z0, t, mu0, k), zref)
                cases.append({"mu0": mu0, "k": k, "z0": label, "error": num(err)})
                key = f"k={k:.4g}"
                worst[key] = max(worst.get(key, 0.0), err)

    stiff_mu0, stiff_k = max(mu0s), min(ks)
    ref_lo = reference.expm_trajectories(z0s, t, stiff_mu0, stiff_k, dps)
    ref_hi = reference.expm_trajectories(z0s, t, stiff_mu0, stiff_k, check_dps)
    with mpmath.workdps(check_dps):
        conv = max(
            float(
                max(abs(a - b) for a, b in zip(lo.ravel(), hi.ravel(), strict=True))
                / max(mpmath.mpf(1), max(abs(b) for b in hi.ravel()))
            )
            for lo, hi in zip(ref_lo, ref_hi, strict=True)
        )

    worst_all = max(worst.values())
    robust = _robustness(robust_mu0s, ks, robust_times, INITIAL_STATES)
    return {
        "error_measure": ERROR_MEASURE,
        "grid": {
            "mu0": [float(m) for m in mu0s],
            "k": [float(k) for k in ks],
            "t": [float(x) for x in t],
            "z0": INITIAL_STATES,
        },
        "reference": {
            "method": "mpmath.expm(L t) z0, L built in mpmath from (1.7)",
            "dps": dps,
            "convergence": {
                "case": {"mu0": stiff_mu0, "k": stiff_k, "t": "all", "z0": "all"},
                "compared_with_dps": check_dps,
                "max_difference": num(conv),
            },
        },
        "worst_error_by_k": {key: num(v) for key, v in worst.items()},
        "worst_error": num(worst_all),
        "cases": cases,
        "target": SOLUTION_TARGET,
        "pass": bool(worst_all <= SOLUTION_TARGET),
        "robustness": {
            "grid": {
                "mu0": (
                    f"{len(robust_mu0s)} log-spaced values from {min(robust_mu0s):g} "
                    f"to {max(robust_mu0s):g}"
                ),
                "k": [float(k) for k in ks],
                "t": (
                    f"{len(robust_times)} equally spaced values from {robust_times[0]:g} "
                    f"to {robust_times[-1]:g}"
                ),
                "z0": "all of grid.z0",
            },
            "check": (
                "finite output and no floating-point exception under np.errstate(...) "
                "with warnings turned into errors, for solve and modal_terms"
            ),
            **robust,
        },
    }


def print_result(res: dict[str, Any]) -> None:
    """Print the solution section."""
    g = res["grid"]
    print(
        f"\n== solution: turntable.solve vs mpmath expm (dps {res['reference']['dps']}), "
        f"{len(g['mu0'])} mu0 in [{min(g['mu0']):g}, {max(g['mu0']):g}], "
        f"{len(g['t'])} t in [0, {max(g['t']):g}], {len(g['z0'])} initial states"
    )
    print(f"  error = {res['error_measure']}")
    by_mu0: dict[float, float] = {}
    for c in res["cases"]:
        by_mu0[c["mu0"]] = max(by_mu0.get(c["mu0"], 0.0), float(c["error"]))
    print("  worst by mu0: " + "  ".join(f"{m:g}: {e:.1e}" for m, e in by_mu0.items()))
    print(
        "  worst by k:   "
        + "  ".join(f"{k}: {float(e):.1e}" for k, e in res["worst_error_by_k"].items())
    )
    conv = res["reference"]["convergence"]
    print(
        f"  worst error {fmt(res['worst_error']).strip()}  target {res['target']:g}: "
        f"{pf(res['pass'])}   (reference dps {res['reference']['dps']} vs "
        f"{conv['compared_with_dps']} at mu0={conv['case']['mu0']:g}, k={conv['case']['k']:.3g}: "
        f"{float(conv['max_difference']):.1e})"
    )
    rob = res["robustness"]
    print(f"  robustness over mu0 {rob['grid']['mu0']}, t {rob['grid']['t']}:")
    for level, r in rob["errstate_levels"].items():
        extra = ""
        if r["first_failures"]:
            lo, hi = r["mu0_range_of_failures"]
            extra = f" for mu0 in [{lo:.3g}, {hi:.3g}], e.g. {r['first_failures'][0]}"
        print(f"    errstate {level:<40} {pf(r['pass'])} ({r['n_failures']} failing runs){extra}")
    m = rob["modal"]
    print(
        f"  modal_terms sum vs solve: {float(m['relative_to_terms']):.1e} relative to the terms, "
        f"{float(m['relative_to_solution']):.1e} relative to the solution; "
        f"target {m['target_relative_to_terms']:g}: {pf(m['pass'])}"
    )


def run(quick: bool) -> dict[str, Any]:
    """The benchmark on its full grids, or smaller ones if ``quick``."""
    return bench_solution(
        mu0s=10.0 ** np.linspace(-3, 3, 3 if quick else 7),
        ks=[K_BALL, K_SHELL],
        times=np.linspace(0.0, 50.0, 6 if quick else 11),
        robust_mu0s=10.0 ** np.linspace(-12, 12, 13 if quick else 49),
        robust_times=np.linspace(0.0, 1000.0, 1001 if quick else 4001),
    )


def main(argv: Sequence[str] | None = None) -> int:
    """Run this benchmark alone; return 0 (the pass/fail verdicts are in the output)."""
    argv = sys.argv[1:] if argv is None else argv
    return _common.main([sys.modules[__name__]], __file__, __doc__.splitlines()[0], argv)


if __name__ == "__main__":
    one_blas_thread()
    sys.exit(main())
