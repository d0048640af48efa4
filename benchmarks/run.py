"""Accuracy and speed benchmark of the closed forms in `turntable`.

Three sections, each a function that returns a JSON-ready dictionary:

``eigenvalues``
    Worst relative error of alpha1, alpha2 and beta over a (mu0, k) grid,
    for `turntable.eigenvalues`, for ``numpy.linalg.eigvals`` of the matrix
    L and for the textbook double-precision form mu (-1 +- sqrt(1 + i eps)),
    against a high-precision mpmath evaluation of (2.4).
``solution``
    Worst error of `turntable.solve` against the mpmath matrix exponential
    exp(L t) z0; robustness (no NaN, inf or floating-point exception) over
    mu0 in [1e-12, 1e12] and t in [0, 1000]; consistency of
    `turntable.modal_terms` with `turntable.solve`.
``speed``
    Run time of `turntable.solve` on 10^4 time points against
    ``scipy.integrate.solve_ivp`` (DOP853 and Radau) and against
    ``scipy.linalg.expm`` at each time point, with each method's error.

Run ``python benchmarks/run.py`` (or ``make bench``); ``--quick`` uses
smaller grids.  A table is printed and the sections are merged into the
JSON file given by ``--out`` (other top-level keys in it are kept).
"""

from __future__ import annotations

import argparse
import math
import os
import platform
import shlex
import sys
import timeit
import warnings
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

# One BLAS thread: every matrix here is 6x6, and on a shared machine idle
# BLAS worker threads left spinning by one method (Radau's LU) slow down the
# next one (batched expm) by up to 10x.  Set only when this file is run as a
# script (before numpy is first imported); an explicit setting wins.
BLAS_THREAD_VARIABLES = ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")
if __name__ == "__main__":
    for _var in BLAS_THREAD_VARIABLES:
        os.environ.setdefault(_var, "1")

import mpmath  # noqa: E402
import numpy as np  # noqa: E402
import scipy  # noqa: E402
import scipy.integrate  # noqa: E402
import scipy.linalg  # noqa: E402
from numpy.typing import NDArray  # noqa: E402

import turntable as tt  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from results_file import merge_results  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
SECTIONS = ("eigenvalues", "solution", "speed")

#: Relative error that `turntable.eigenvalues` must reach for every grid point.
EIGENVALUE_TARGET = 1e-14
#: Error of `turntable.solve`, relative to max(1, size of the trajectory).
SOLUTION_TARGET = 1e-12
#: Disagreement of `modal_terms` with `solve`, relative to max(1, size of the terms).
MODAL_TARGET = 1e-12
#: Required speed-up of `solve` over the faster solve_ivp method, by mu0.
SPEED_TARGETS = {1.0: 20.0, 100.0: 100.0, 1e4: 100.0}
#: Required ratio (solve_ivp error) / (solve error).
ACCURACY_RATIO_TARGET = 1000.0

K_BALL = 2.0 / 5.0
K_SHELL = 2.0 / 3.0

#: Initial states: Fig. 3 of the paper, Fig. 4 of the paper, and a generic one.
INITIAL_STATES = {
    "fig3 (x=y=1, v=w=0)": (1.0, 1.0, 0.0, 0.0, 0.0, 0.0),
    "fig4 (x=y=1, v=0, w=(0,1))": (1.0, 1.0, 0.0, 0.0, 0.0, 1.0),
    "generic": (0.3, -1.2, 0.7, 0.25, -0.4, 0.9),
}

ERROR_MEASURE = (
    "max over times and components of |z - z_ref|, divided by "
    "max(1, max |z_ref| over the trajectory)"
)


# --------------------------------------------------------------------------------------
# helpers
# --------------------------------------------------------------------------------------


def _num(x: Any) -> float | str:
    """Return ``x`` as a JSON-safe float ('inf' / 'nan' as strings)."""
    x = float(x)
    return x if math.isfinite(x) else str(x)


def _fmt(x: float | str) -> str:
    return f"{x:9.1e}" if isinstance(x, float) else f"{x:>9}"


def _command(argv: Sequence[str]) -> str:
    """Return the command line that runs this script, relative to the checkout."""

    def rel(path: str) -> str:
        try:
            return os.path.relpath(path, ROOT) if Path(path).is_absolute() else path
        except ValueError:
            return path

    exe = rel(sys.executable)
    script = os.path.relpath(Path(__file__).resolve(), ROOT)
    return shlex.join([exe, script, *argv])


def _mp_system_matrix(mu0: float, k: float) -> mpmath.matrix:
    """Build L of (1.7) in the current mpmath precision from the exact doubles mu0, k.

    Built entry by entry from the paper's block form, independently of
    `turntable.system_matrix` (whose entry mu0 / k is rounded to a double).
    """
    m = mpmath.mpf(mu0)
    q = m / mpmath.mpf(k)
    L = mpmath.zeros(6, 6)
    L[0, 2] = L[1, 3] = 1
    # rows of v: mu0 J r - mu0 v - mu0 J w, with J = [[0, -1], [1, 0]]
    L[2, 1], L[3, 0] = -m, m
    L[2, 2] = L[3, 3] = -m
    L[2, 5], L[3, 4] = m, -m
    # rows of w: (mu0/k) (r + J v - w)
    L[4, 0] = L[5, 1] = q
    L[4, 3], L[5, 2] = -q, q
    L[4, 4] = L[5, 5] = -q
    return L


def _mp_error(z: NDArray[np.float64], zref: NDArray[np.object_]) -> float:
    """Error of ``z`` against the mpmath array ``zref`` (see ERROR_MEASURE)."""
    diff = max(abs(mpmath.mpf(float(a)) - b) for a, b in zip(z.ravel(), zref.ravel(), strict=True))
    scale = max(mpmath.mpf(1), max(abs(b) for b in zref.ravel()))
    return float(diff / scale)


def best_time(fn: Callable[[], object], repeat: int, number: int | None = None) -> float:
    """Return the best time of one call of ``fn``, in seconds (timeit, best of ``repeat``).

    If ``number`` is None it is chosen by ``timeit.Timer.autorange`` so that
    each repeat lasts at least 0.2 s.
    """
    timer = timeit.Timer(fn)
    if number is None:
        number, _ = timer.autorange()
    return min(timer.repeat(repeat=repeat, number=number)) / number


# --------------------------------------------------------------------------------------
# 1. eigenvalues
# --------------------------------------------------------------------------------------


def reference_dps(mu0: float, k: float, digits: int = 50) -> int:
    """Return the mpmath precision that leaves ``digits`` correct digits in (2.4).

    In mu (-1 + sqrt(1 + i eps)) the real part of sqrt(1 + i eps) is
    1 + eps^2/8 + O(eps^4) when eps -> 0 (mu0 -> infinity), so the sum
    -1 + Re sqrt(...) cancels about log10(8 / eps^2) leading digits.  Adding
    that many digits (plus 10 guard digits) to the working precision keeps
    ``digits`` correct digits in alpha1; alpha2 and beta never cancel.
    """
    eps = 4.0 * k * k / (mu0 * (k + 1.0) ** 2)
    lost = max(0, math.ceil(math.log10(8.0) - 2.0 * math.log10(eps)))
    return digits + lost + 10


def reference_spectrum(mu0: float, k: float, dps: int) -> tuple[mpmath.mpf, ...]:
    """Return (alpha1, alpha2, beta) from the textbook roots (2.4), in mpmath.

    lambda_1 = mu (-1 + sqrt(1 + i eps)), lambda_3 = mu (-1 - sqrt(1 + i eps)),
    with mu and eps of (2.2) computed from the exact double values of mu0, k.
    This is the plain formula of the paper, not the rewritten one of
    `turntable.spectrum`; the cancellation is absorbed by the precision
    (see `reference_dps`).
    """
    with mpmath.workdps(dps):
        m, kk = mpmath.mpf(mu0), mpmath.mpf(k)
        mu = m * (kk + 1) / (2 * kk)
        eps = 4 * kk**2 / (m * (kk + 1) ** 2)
        root = mpmath.sqrt(mpmath.mpc(1, eps))
        lam1 = mu * (-1 + root)
        lam3 = mu * (-1 - root)
        return +lam1.real, +lam3.real, +lam1.imag


def _nonzero_spectrum(ev: Sequence[Any]) -> tuple[Any, Any, Any]:
    """Return (alpha1, alpha2, beta) from the six eigenvalues of L.

    The two eigenvalues of smallest modulus are the (numerical) kernel of L
    and are dropped first: for large mu0 their rounding noise (about
    1e-16 ||L||) exceeds alpha1, so "largest real part of all six" would
    return a kernel eigenvalue.  Of the other four, alpha1 is the largest
    real part, alpha2 the most negative and beta the largest imaginary part.
    """
    four = sorted(ev, key=abs)[2:]
    return (
        max(e.real for e in four),
        min(e.real for e in four),
        max(e.imag for e in four),
    )


def _eig_numpy(mu0: float, k: float) -> tuple[float, float, float]:
    """alpha1, alpha2, beta from numpy.linalg.eigvals(turntable.system_matrix(mu0, k))."""
    return _nonzero_spectrum(list(np.linalg.eigvals(tt.system_matrix(mu0, k))))


def _eig_textbook(mu0: float, k: float) -> tuple[float, float, float]:
    """alpha1, alpha2, beta from mu (-1 +- sqrt(1 + i eps)) in complex128."""
    mu = mu0 * (k + 1.0) / (2.0 * k)
    eps = 4.0 * k * k / (mu0 * (k + 1.0) ** 2)
    root = np.sqrt(1.0 + 1j * eps)
    lam1 = mu * (-1.0 + root)
    lam3 = mu * (-1.0 - root)
    return float(lam1.real), float(lam3.real), float(lam1.imag)


def _eig_turntable(mu0: float, k: float) -> tuple[float, float, float]:
    """alpha1, alpha2, beta from turntable.eigenvalues (lambda_1 and lambda_3)."""
    ev = tt.eigenvalues(mu0, k)
    return float(ev[0].real), float(ev[2].real), float(ev[0].imag)


EIGEN_METHODS: dict[str, Callable[[float, float], tuple[float, float, float]]] = {
    "turntable.eigenvalues": _eig_turntable,
    "numpy.linalg.eigvals(L)": _eig_numpy,
    "textbook complex128": _eig_textbook,
}
QUANTITIES = ("alpha1", "alpha2", "beta")


def bench_eigenvalues(
    mu0s: Sequence[float],
    ks: Sequence[float],
    decades: Sequence[int] = (-12, -6, 0, 3, 6, 9, 12),
    crosscheck: bool = True,
) -> dict[str, Any]:
    """Worst relative errors of alpha1, alpha2, beta on the grid ``mu0s`` x ``ks``.

    Parameters
    ----------
    mu0s, ks : sequence of float
        The grid.
    decades : sequence of int
        Powers of ten of mu0 for which the worst error over ``ks`` is listed
        separately (only those present in ``mu0s``).
    crosscheck : bool
        Also compare the reference with ``mpmath.eig`` of L (built in mpmath)
        at the decade points, and with itself at 40 more digits everywhere.

    Returns
    -------
    dict
        JSON-ready results, with ``pass`` for the target of
        `turntable.eigenvalues`.
    """
    mu0s = [float(m) for m in mu0s]
    ks = [float(k) for k in ks]
    errors = {name: np.zeros((len(mu0s), len(ks), 3)) for name in EIGEN_METHODS}
    ref_change = 0.0
    for i, mu0 in enumerate(mu0s):
        for j, k in enumerate(ks):
            dps = reference_dps(mu0, k)
            ref = reference_spectrum(mu0, k, dps)
            with mpmath.workdps(dps):
                if crosscheck:
                    finer = reference_spectrum(mu0, k, dps + 40)
                    ref_change = max(
                        ref_change,
                        *(float(abs(a - b) / abs(b)) for a, b in zip(ref, finer, strict=True)),
                    )
                for name, method in EIGEN_METHODS.items():
                    got = method(mu0, k)
                    errors[name][i, j] = [
                        float(abs(mpmath.mpf(g) - r) / abs(r))
                        for g, r in zip(got, ref, strict=True)
                    ]

    logm = np.log10(mu0s)
    decade_rows = {
        d: int(np.argmin(abs(logm - d))) for d in decades if np.min(abs(logm - d)) < 1e-9
    }
    methods: dict[str, Any] = {}
    for name, err in errors.items():
        methods[name] = {
            "worst": {q: _num(err[:, :, n].max()) for n, q in enumerate(QUANTITIES)},
            "worst_at_mu0": {
                q: mu0s[int(np.unravel_index(err[:, :, n].argmax(), err.shape[:2])[0])]
                for n, q in enumerate(QUANTITIES)
            },
            "by_decade": {
                f"1e{d}": {q: _num(err[i, :, n].max()) for n, q in enumerate(QUANTITIES)}
                for d, i in decade_rows.items()
            },
        }

    eig_agree = None
    if crosscheck:
        eig_agree = 0.0
        for i in decade_rows.values():
            for k in ks:
                mu0 = mu0s[i]
                dps = reference_dps(mu0, k)
                ref = reference_spectrum(mu0, k, dps)
                # eig loses about log10(||L|| / alpha1) digits: give it 40 more.
                with mpmath.workdps(dps + 40):
                    ev = mpmath.eig(_mp_system_matrix(mu0, k), left=False, right=False)
                    got = _nonzero_spectrum(ev)
                    eig_agree = max(
                        eig_agree,
                        *(float(abs(g - r) / abs(r)) for g, r in zip(got, ref, strict=True)),
                    )

    worst_tt = max(v for v in methods["turntable.eigenvalues"]["worst"].values())
    return {
        "what": (
            "worst relative error |x - x_ref| / |x_ref| over the grid, for x = alpha1, "
            "alpha2, beta separately; by_decade: worst over k at that mu0"
        ),
        "grid": {
            "mu0": f"{len(mu0s)} log-spaced values from {min(mu0s):g} to {max(mu0s):g}",
            "k": ks,
        },
        "reference": {
            "formula": "mu (-1 +- sqrt(1 + i eps)) of (2.4) with mu, eps of (2.2), in mpmath",
            "precision": (
                "mp.dps = 50 + log10(8/eps^2) (digits cancelled in alpha1) + 10, per point; "
                f"{min(reference_dps(m, k) for m in mu0s for k in ks)} to "
                f"{max(reference_dps(m, k) for m in mu0s for k in ks)} digits"
            ),
            "max_relative_change_with_40_more_digits": _num(ref_change) if crosscheck else None,
            "max_relative_difference_to_mpmath_eig_of_L_at_decades": (
                _num(eig_agree) if crosscheck else None
            ),
        },
        "numpy_eigvals_extraction": (
            "drop the two eigenvalues of smallest modulus (kernel of L); alpha1 = largest real "
            "part, alpha2 = most negative real part, beta = largest imaginary part of the rest"
        ),
        "methods": methods,
        "target": {"method": "turntable.eigenvalues", "max_relative_error": EIGENVALUE_TARGET},
        "pass": bool(worst_tt <= EIGENVALUE_TARGET),
    }


def print_eigenvalues(res: dict[str, Any]) -> None:
    """Print the eigenvalue section as two tables."""
    print("\n== eigenvalues: worst relative error over", res["grid"]["mu0"], "x k =", end=" ")
    print(", ".join(f"{k:.3g}" for k in res["grid"]["k"]))
    print(f"{'method':<26}{'alpha1':>10}{'alpha2':>10}{'beta':>10}")
    for name, m in res["methods"].items():
        print(f"{name:<26}" + "".join(f" {_fmt(m['worst'][q])}" for q in QUANTITIES))
    decs = list(next(iter(res["methods"].values()))["by_decade"])
    print("\n  worst over k at mu0 =")
    print(f"{'method':<26}{'':7}" + "".join(f"{d:>10}" for d in decs))
    for name, m in res["methods"].items():
        for q in QUANTITIES:
            row = "".join(f" {_fmt(m['by_decade'][d][q])}" for d in decs)
            print(f"{name:<26}{q:<7}{row}")
    ref = res["reference"]
    print(f"reference: {ref['precision']}")
    print(
        "  change with 40 more digits:",
        ref["max_relative_change_with_40_more_digits"],
        "| vs mpmath.eig(L) at decades:",
        ref["max_relative_difference_to_mpmath_eig_of_L_at_decades"],
    )
    print(f"target turntable.eigenvalues <= {EIGENVALUE_TARGET:g}:", _pf(res["pass"]))


def _pf(ok: bool) -> str:
    return "PASS" if ok else "FAIL"


# --------------------------------------------------------------------------------------
# 2. solution
# --------------------------------------------------------------------------------------


def reference_trajectories(
    z0s: Sequence[Sequence[float]], t: Sequence[float], mu0: float, k: float, dps: int
) -> NDArray[np.object_]:
    """Return exp(L t) z0 in mpmath for every z0 and t, shape (len(z0s), len(t), 6).

    ``mpmath.expm`` (scaling and squaring of a Taylor series) of L t with L
    built by `_mp_system_matrix`; t and z0 are taken as exact doubles.
    """
    out = np.empty((len(z0s), len(t), 6), dtype=object)
    with mpmath.workdps(dps):
        L = _mp_system_matrix(mu0, k)
        vecs = [mpmath.matrix([mpmath.mpf(float(c)) for c in z0]) for z0 in z0s]
        for j, tj in enumerate(t):
            E = mpmath.expm(L * mpmath.mpf(float(tj)))
            for i, v in enumerate(vecs):
                out[i, j] = list(E * v)
    return out


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
            "relative_to_terms": _num(modal_vs_terms),
            "relative_to_solution": _num(modal_vs_solution),
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
            ref = reference_trajectories(z0s, t, mu0, k, dps)
            for (label, z0), zref in zip(INITIAL_STATES.items(), ref, strict=True):
                err = _mp_error(tt.solve(z0, t, mu0, k), zref)
                cases.append({"mu0": mu0, "k": k, "z0": label, "error": _num(err)})
                key = f"k={k:.4g}"
                worst[key] = max(worst.get(key, 0.0), err)

    stiff_mu0, stiff_k = max(mu0s), min(ks)
    ref_lo = reference_trajectories(z0s, t, stiff_mu0, stiff_k, dps)
    ref_hi = reference_trajectories(z0s, t, stiff_mu0, stiff_k, check_dps)
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
                "max_difference": _num(conv),
            },
        },
        "worst_error_by_k": {key: _num(v) for key, v in worst.items()},
        "worst_error": _num(worst_all),
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


def print_solution(res: dict[str, Any]) -> None:
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
        f"  worst error {_fmt(res['worst_error']).strip()}  target {res['target']:g}: "
        f"{_pf(res['pass'])}   (reference dps {res['reference']['dps']} vs "
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
        print(f"    errstate {level:<40} {_pf(r['pass'])} ({r['n_failures']} failing runs){extra}")
    m = rob["modal"]
    print(
        f"  modal_terms sum vs solve: {float(m['relative_to_terms']):.1e} relative to the terms, "
        f"{float(m['relative_to_solution']):.1e} relative to the solution; "
        f"target {m['target_relative_to_terms']:g}: {_pf(m['pass'])}"
    )


# --------------------------------------------------------------------------------------
# 3. speed
# --------------------------------------------------------------------------------------


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
        zref = reference_trajectories([z0], t[idx], mu0, k, dps)[0]
        row: dict[str, Any] = {"mu0": mu0, "methods": {}}

        t_solve = best_time(lambda mu0=mu0: tt.solve(z0, t, mu0, k), repeat=max(repeat, 5))
        err = _mp_error(tt.solve(z0, t, mu0, k)[idx], zref)
        row["methods"]["turntable.solve"] = {"time_s": t_solve, "error": _num(err)}

        for method in ("DOP853", "Radau"):
            if method == "DOP853":
                tp = t[t <= probe_end]
                t_probe = best_time(lambda L=L, tp=tp: _ivp(L, z0, tp, "DOP853"), repeat, 1)
                if t_probe > probe_budget:
                    # error over the probe interval, at a few of its points
                    ip = np.unique(np.linspace(0, len(tp) - 1, 6).round().astype(int))
                    zp = reference_trajectories([z0], tp[ip], mu0, k, dps)[0]
                    e = _mp_error(_ivp(L, z0, tp, method)[ip], zp)
                    row["methods"][method] = {
                        "time_s": t_probe * t_end / probe_end,
                        "error": _num(e),
                        "note": (
                            f"timed on [0, {probe_end:g}] ({len(tp)} points) and scaled by "
                            f"{t_end / probe_end:g}; error at {len(ip)} points of [0, "
                            f"{probe_end:g}] only"
                        ),
                    }
                    continue
            elapsed = best_time(lambda L=L, method=method: _ivp(L, z0, t, method), repeat, 1)
            e = _mp_error(_ivp(L, z0, t, method)[idx], zref)
            row["methods"][method] = {"time_s": elapsed, "error": _num(e)}

        sub = t[::expm_stride]
        t_expm = best_time(lambda L=L, sub=sub: _expm_points(L, z0, sub), repeat, 1)
        e = _mp_error(_expm_points(L, z0, t[idx]), zref)
        row["methods"]["scipy.linalg.expm per point"] = {
            "time_s": t_expm * n_points / len(sub),
            "error": _num(e),
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
        row["error_ratio_faster_solve_ivp_over_solve"] = _num(acc_ratio)
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


def print_speed(res: dict[str, Any]) -> None:
    """Print the speed section."""
    print(f"\n== speed: {res['what']}")
    print(f"  solve_ivp: {res['solve_ivp_options']}")
    print(f"  error: {res['error_measure']}, against {res['reference']}")
    print(f"{'mu0':>8}  {'method':<30}{'time [ms]':>11}{'error':>10}  note")
    for c in res["cases"]:
        for name, m in c["methods"].items():
            note = m.get("note", "")
            print(f"{c['mu0']:8g}  {name:<30}{1e3 * m['time_s']:11.3f} {_fmt(m['error'])}  {note}")
        print(
            f"{'':8}  speed-up vs {c['faster_solve_ivp']}: {c['speedup_vs_faster_solve_ivp']:.0f}x"
            f" (target {c['target_speedup']:g}x: {_pf(c['pass_speed'])}); "
            f"error ratio {float(c['error_ratio_faster_solve_ivp_over_solve']):.1e} "
            f"(target {c['target_error_ratio']:g}: {_pf(c['pass_accuracy'])}); "
            f"speed-up vs expm: {c['speedup_vs_expm']:.0f}x"
        )


# --------------------------------------------------------------------------------------
# main
# --------------------------------------------------------------------------------------


def meta() -> dict[str, str]:
    """Versions of the software the numbers depend on (no dates)."""
    return {
        "python": platform.python_version(),
        "numpy": np.__version__,
        "scipy": scipy.__version__,
        "mpmath": mpmath.__version__,
        "turntable": tt.__version__,
        "machine": f"{platform.system()} {platform.machine()}",
        "blas_threads": ", ".join(f"{v}={os.environ.get(v, '')}" for v in BLAS_THREAD_VARIABLES),
    }


def write_results(path: Path, sections: dict[str, Any]) -> None:
    """Merge ``sections`` into the JSON file at ``path`` (atomically), keeping other keys."""
    merge_results(path, sections)


def main(argv: Sequence[str] | None = None) -> int:
    """Run the benchmark; return 0 (the pass/fail verdicts are in the output)."""
    argv = list(sys.argv[1:] if argv is None else argv)
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="smaller grids, fewer repeats")
    parser.add_argument("--out", default="results/benchmarks.json", help="JSON file to update")
    parser.add_argument(
        "--sections", nargs="+", choices=SECTIONS, default=list(SECTIONS), help="what to run"
    )
    args = parser.parse_args(argv)
    command = _command(argv)
    quick = args.quick
    results: dict[str, Any] = {}

    if "eigenvalues" in args.sections:
        mu0s = 10.0 ** np.linspace(-12, 12, 25 if quick else 97)
        ks = [0.05, 0.4, 1.0] if quick else [0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 2 / 3, 1.0]
        res = bench_eigenvalues(mu0s, ks)
        res["command"] = command
        print_eigenvalues(res)
        results["eigenvalues"] = res

    if "solution" in args.sections:
        res = bench_solution(
            mu0s=10.0 ** np.linspace(-3, 3, 3 if quick else 7),
            ks=[K_BALL, K_SHELL],
            times=np.linspace(0.0, 50.0, 6 if quick else 11),
            robust_mu0s=10.0 ** np.linspace(-12, 12, 13 if quick else 49),
            robust_times=np.linspace(0.0, 1000.0, 1001 if quick else 4001),
        )
        res["command"] = command
        print_solution(res)
        results["solution"] = res

    if "speed" in args.sections:
        res = bench_speed(n_ref=26 if quick else 101, repeat=2 if quick else 3)
        res["command"] = command
        print_speed(res)
        results["speed"] = res

    results["meta"] = meta()
    out = Path(args.out)
    write_results(out, results)
    print(f"\nwrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
