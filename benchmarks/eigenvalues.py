"""Accuracy of the eigenvalues: worst relative error of alpha1, alpha2, beta over a grid.

For `turntable.eigenvalues`, for ``numpy.linalg.eigvals`` of the matrix L and for the
textbook double-precision form mu (-1 +- sqrt(1 + i eps)), over a (mu0, k) grid, against
the high-precision evaluation of (2.4) of `turntable.reference` (`textbook_spectrum` at
`reference_dps` digits), itself checked against ``mpmath.eig`` of L.

Run ``python benchmarks/eigenvalues.py`` (``--quick``: smaller grid), or all benchmarks
with ``python benchmarks/run.py`` (``make bench``); the result is merged into
``results/benchmarks.json`` under the key ``eigenvalues``.
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from collections.abc import Callable, Sequence
from typing import Any

import mpmath
import numpy as np

import _common
import turntable as tt
from _common import fmt, num, pf
from turntable import reference
from turntable._blas import one_blas_thread

NAME = "eigenvalues"

#: Relative error that `turntable.eigenvalues` must reach for every grid point.
EIGENVALUE_TARGET = 1e-14


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
            dps = reference.reference_dps(mu0, k)
            ref = reference.textbook_spectrum(mu0, k, dps)
            with mpmath.workdps(dps):
                if crosscheck:
                    finer = reference.textbook_spectrum(mu0, k, dps + 40)
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
            "worst": {q: num(err[:, :, n].max()) for n, q in enumerate(QUANTITIES)},
            "worst_at_mu0": {
                q: mu0s[int(np.unravel_index(err[:, :, n].argmax(), err.shape[:2])[0])]
                for n, q in enumerate(QUANTITIES)
            },
            "by_decade": {
                f"1e{d}": {q: num(err[i, :, n].max()) for n, q in enumerate(QUANTITIES)}
                for d, i in decade_rows.items()
            },
        }

    eig_agree = None
    if crosscheck:
        eig_agree = 0.0
        for i in decade_rows.values():
            for k in ks:
                mu0 = mu0s[i]
                dps = reference.reference_dps(mu0, k)
                ref = reference.textbook_spectrum(mu0, k, dps)
                # eig loses about log10(||L|| / alpha1) digits: give it 40 more.
                with mpmath.workdps(dps + 40):
                    ev = mpmath.eig(reference.mp_system_matrix(mu0, k), left=False, right=False)
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
                f"{min(reference.reference_dps(m, k) for m in mu0s for k in ks)} to "
                f"{max(reference.reference_dps(m, k) for m in mu0s for k in ks)} digits"
            ),
            "max_relative_change_with_40_more_digits": num(ref_change) if crosscheck else None,
            "max_relative_difference_to_mpmath_eig_of_L_at_decades": (
                num(eig_agree) if crosscheck else None
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


def print_result(res: dict[str, Any]) -> None:
    """Print the eigenvalue section as two tables."""
    print("\n== eigenvalues: worst relative error over", res["grid"]["mu0"], "x k =", end=" ")
    print(", ".join(f"{k:.3g}" for k in res["grid"]["k"]))
    print(f"{'method':<26}{'alpha1':>10}{'alpha2':>10}{'beta':>10}")
    for name, m in res["methods"].items():
        print(f"{name:<26}" + "".join(f" {fmt(m['worst'][q])}" for q in QUANTITIES))
    decs = list(next(iter(res["methods"].values()))["by_decade"])
    print("\n  worst over k at mu0 =")
    print(f"{'method':<26}{'':7}" + "".join(f"{d:>10}" for d in decs))
    for name, m in res["methods"].items():
        for q in QUANTITIES:
            row = "".join(f" {fmt(m['by_decade'][d][q])}" for d in decs)
            print(f"{name:<26}{q:<7}{row}")
    ref = res["reference"]
    print(f"reference: {ref['precision']}")
    print(
        "  change with 40 more digits:",
        ref["max_relative_change_with_40_more_digits"],
        "| vs mpmath.eig(L) at decades:",
        ref["max_relative_difference_to_mpmath_eig_of_L_at_decades"],
    )
    print(f"target turntable.eigenvalues <= {EIGENVALUE_TARGET:g}:", pf(res["pass"]))


def run(quick: bool) -> dict[str, Any]:
    """The benchmark on its full grid (97 mu0 x 8 k), or a smaller one if ``quick``."""
    mu0s = 10.0 ** np.linspace(-12, 12, 25 if quick else 97)
    ks = [0.05, 0.4, 1.0] if quick else [0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 2 / 3, 1.0]
    return bench_eigenvalues(mu0s, ks)


def main(argv: Sequence[str] | None = None) -> int:
    """Run this benchmark alone; return 0 (the pass/fail verdicts are in the output)."""
    argv = sys.argv[1:] if argv is None else argv
    return _common.main([sys.modules[__name__]], __file__, __doc__.splitlines()[0], argv)


if __name__ == "__main__":
    one_blas_thread()
    sys.exit(main())
