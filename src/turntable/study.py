"""Checks of the Section 2 claims over a grid of friction coefficients, for one k.

Used by the parameter study of the workflow (workflow/rules/study.smk): one call per
inertia ratio k, each returning plain JSON-ready values, then `summarize` over all k.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from turntable import _validate
from turntable.solution import conserved, solve, spiral_centre
from turntable.spectrum import (
    alpha1_peak,
    log_damping_ratio,
    log_growth_per_turn,
    spectrum,
    system_matrix,
)

#: Tolerance of the rounding-level checks (relative).
TOL = 1e-9


def section2_checks(k: float, mu0: ArrayLike, z0: ArrayLike, t: ArrayLike) -> dict[str, Any]:
    """Evaluate the spectrum and the claims of Section 2 at each mu0, for one k.

    Parameters
    ----------
    k : float
        Inertia ratio, finite and > 0.
    mu0 : array_like
        1-D grid of friction coefficients, finite and > 0, increasing.
    z0 : array_like
        Initial state (x, y, vx, vy, wx, wy) of the trajectory checks.
    t : array_like
        1-D array of non-negative times on which the trajectory checks sample `solve`.

    Returns
    -------
    dict
        JSON-ready (lists and floats). Per mu0 (lists): ``alpha1``, ``alpha2``, ``beta``,
        ``log_N`` (ln N), ``decay_ratio`` (abs(alpha2)/beta), ``log_growth_per_turn``,
        ``root_residual``, ``conservation_drift``. Per k: ``peak`` (closed-form maximum of
        alpha1), ``centre`` (x0, y0), ``centre_residual``, and ``checks``, a dict of
        booleans, each true when the claim holds on the whole grid.

    Notes
    -----
    The checks, with the equations of the paper:

    - ``unstable_focus`` (2.6): alpha2 < 0 < alpha1.
    - ``damping_bound`` (2.9)-(2.10): abs(alpha2)/beta > 1, i.e. ln N > 2 pi.
    - ``roots`` (2.1)-(2.5): lambda = alpha1 + i beta and alpha2 + i beta are roots of
      P4, i.e. (lambda^2 + 2 mu lambda)^2 = -mu0^2, so lambda^2 + 2 mu lambda = +- i mu0;
      ``root_residual`` is the smaller of abs(lambda^2 + 2 mu lambda -+ i mu0), relative
      to the size abs(lambda)^2 + 2 mu abs(lambda) + mu0 of the terms, the worse of the
      two roots.
    - ``centre`` (2.3), (2.8): z_c = (x0, y0, 0, 0, x0, y0), with (x0, y0) from
      `spiral_centre`, is a fixed point (L z_c = 0) with the same conserved quantities
      as z0; ``centre_residual`` is the larger of max abs(L z_c) over all mu0 and of the
      difference of the conserved quantities, relative to 1 + max abs(z0).
    - ``conservation`` (Section 2): k wx - vy and k wy + vx are constant along `solve`;
      ``conservation_drift`` is their largest change over `t`, relative to the largest
      abs(z(t)).
    - ``per_turn_decreasing`` (Fig. 4, refined claim): 2 pi alpha1/beta decreases with mu0.
    - ``peak_bound``: no alpha1 on the grid exceeds the closed-form maximum `alpha1_peak`.
    """
    k = _validate.positive_scalar("k", k)
    mu0 = _validate.positive("mu0", mu0)
    if mu0.ndim != 1 or mu0.size < 2 or np.any(np.diff(mu0) <= 0):
        raise ValueError("mu0 must be a 1-D increasing grid of at least two values")
    z0 = _validate.state("z0", z0)
    t = _validate.times("t", t)

    s = spectrum(mu0, k)
    log_n = log_damping_ratio(mu0, k)
    ratio = -s.alpha2 / s.beta
    per_turn = log_growth_per_turn(mu0, k)

    root_residual = np.zeros_like(mu0)
    for alpha in (s.alpha1, s.alpha2):
        lam = alpha + 1j * s.beta
        q = lam * lam + 2.0 * s.mu * lam
        size = abs(lam) ** 2 + 2.0 * s.mu * abs(lam) + mu0  # size of the terms summed
        res = np.minimum(abs(q - 1j * mu0), abs(q + 1j * mu0)) / size
        root_residual = np.maximum(root_residual, res)

    x0, y0 = spiral_centre(z0, k)
    z_c = np.array([x0, y0, 0.0, 0.0, x0, y0])
    scale = 1.0 + np.max(np.abs(z0))
    fixed = max(float(np.max(np.abs(system_matrix(m, k) @ z_c))) for m in mu0)
    same_c = float(np.max(np.abs(conserved(z_c, k) - conserved(z0, k))))
    centre_residual = max(fixed, same_c) / scale

    c0 = conserved(z0, k)
    drift = np.empty_like(mu0)
    for i, m in enumerate(mu0):
        z = solve(z0, t, m, k)
        drift[i] = np.max(np.abs(conserved(z, k) - c0)) / max(1.0, np.max(np.abs(z)))

    peak = alpha1_peak(k)
    checks = {
        "unstable_focus": bool(np.all((s.alpha2 < 0.0) & (s.alpha1 > 0.0))),
        "damping_bound": bool(np.all(ratio > 1.0) and np.all(log_n > 2.0 * np.pi)),
        "roots": bool(np.all(root_residual < TOL)),
        "centre": bool(centre_residual < TOL),
        "conservation": bool(np.all(drift < TOL)),
        "per_turn_decreasing": bool(np.all(np.diff(per_turn) < 0.0)),
        "peak_bound": bool(np.max(s.alpha1) <= float(peak.alpha1) * (1.0 + TOL)),
    }
    return {
        "k": k,
        "mu0": mu0.tolist(),
        "alpha1": s.alpha1.tolist(),
        "alpha2": s.alpha2.tolist(),
        "beta": s.beta.tolist(),
        "log_N": log_n.tolist(),
        "decay_ratio": ratio.tolist(),
        "log_growth_per_turn": per_turn.tolist(),
        "root_residual": root_residual.tolist(),
        "conservation_drift": drift.tolist(),
        "peak": {"mu0": float(peak.mu0), "alpha1": float(peak.alpha1)},
        "centre": [float(x0), float(y0)],
        "centre_residual": centre_residual,
        "checks": checks,
    }


def summarize(results: Sequence[dict[str, Any]]) -> dict[str, Any]:
    """Condense the results of `section2_checks` for several k into one summary.

    Parameters
    ----------
    results : sequence of dict
        Return values of `section2_checks`, one per inertia ratio.

    Returns
    -------
    dict
        ``all_passed`` (every check for every k), ``failed`` (list of "k=<k>: <check>"),
        and ``per_k``: for each k the checks, the extreme values over the grid (largest
        alpha1 and where, largest alpha2, smallest abs(alpha2)/beta and ln N, largest
        residuals) and the closed-form peak of alpha1.

    Notes
    -----
    ``min_log_N`` is compared with 2 pi, the bound of (2.10), in ``min_log_N_over_2pi``.
    """
    per_k = []
    failed = []
    for r in results:
        alpha1 = np.asarray(r["alpha1"])
        i = int(np.argmax(alpha1))
        per_k.append(
            {
                "k": r["k"],
                "n_mu0": len(r["mu0"]),
                "mu0_range": [r["mu0"][0], r["mu0"][-1]],
                "checks": r["checks"],
                "max_alpha1": float(alpha1[i]),
                "mu0_at_max_alpha1": r["mu0"][i],
                "peak": r["peak"],
                "max_alpha2": float(np.max(r["alpha2"])),
                "min_decay_ratio": float(np.min(r["decay_ratio"])),
                "min_log_N": float(np.min(r["log_N"])),
                "min_log_N_over_2pi": float(np.min(r["log_N"]) / (2.0 * np.pi)),
                "max_root_residual": float(np.max(r["root_residual"])),
                "centre_residual": r["centre_residual"],
                "max_conservation_drift": float(np.max(r["conservation_drift"])),
            }
        )
        failed += [f"k={r['k']}: {name}" for name, ok in r["checks"].items() if not ok]
    return {"all_passed": not failed, "failed": failed, "per_k": per_k}
