"""Checks of the solution (2.9)-(2.10) and Fig. 3: the damping ratio, the fast transient."""

from __future__ import annotations

from typing import Any

import mpmath
import numpy as np

import turntable as tt
from turntable import reference as ref
from turntable.claims._checks_solution import _states
from turntable.claims._core import Outcome, Quantity, Where, all_within, decide, register, sig
from turntable.claims._params import mu0_grid, random_states


@register(
    "solution.damping_ratio",
    where=Where("Sec. 2", "(2.9)-(2.10)"),
    claim=(
        "The decaying part shrinks by a factor N = exp(2 pi |alpha2|/beta) per period with "
        "|alpha2|/beta > 1, so N > exp(2 pi), about 535, for every mu0 and k."
    ),
    paper_value={"text": "N > exp(2 pi) ~= 535", "N_bound": 535.0},
    expected="confirmed",
    decisive="min_ratio_alpha2_over_beta",
    gist=(
        "the damping factor per period exceeds exp(2 pi), a sharp bound approached only "
        "as the friction vanishes"
    ),
    method=(
        "The closed form decides it: with a = cosh s, b = sinh s (a^2 - b^2 = 1, "
        "a^2 + b^2 = sqrt(1 + eps^2), so s = arsinh(eps)/2), |alpha2|/beta = (a + 1)/b = "
        "coth(arsinh(eps)/4), which decreases strictly in eps = 4k^2/(mu0 (k+1)^2), so ln N "
        "increases strictly with mu0, from 2 pi as mu0 -> 0, where ln N - 2 pi = "
        "sqrt(2) pi (k+1)/k sqrt(mu0) (1 + o(1)). Checked: the printed ratio (2.10) and the "
        "closed form against |alpha2|/beta from the 40-digit eigenvalues at the probes, the "
        "package's ln N against them; ln N on the mu0 grid (increasing, as the closed form "
        "says) and at very small mu0 against the leading term, for every k."
    ),
)
def _damping(p: dict[str, Any]) -> Outcome:
    grid = mu0_grid(p)
    min_ratio, monotone, formula_err, coth_err, pkg_err = np.inf, True, 0.0, 0.0, 0.0
    small = sorted(p["mu0_small"], reverse=True)
    excess: list[np.ndarray] = []
    slopes: list[float] = []
    lead_err = 0.0
    for k in p["k_values"]:
        log_n = tt.log_damping_ratio(grid, k)
        min_ratio = min(min_ratio, float((log_n / (2 * np.pi)).min()))
        monotone = monotone and bool(np.all(np.diff(log_n) > 0))
        ex = tt.log_damping_ratio(np.array(small), k) - 2 * np.pi
        excess.append(ex)
        slopes.append(ref.log_log_slope(small, ex))
        lead = np.sqrt(2) * np.pi * (k + 1) / k * np.sqrt(small[-1])
        lead_err = max(lead_err, abs(float(ex[-1]) / lead - 1))
        min_ratio = min(min_ratio, float((1 + ex / (2 * np.pi)).min()))
        for mu0 in p["mu0_probe"]:
            e = ref.mp_spectrum(mu0, k)
            with mpmath.workdps(ref.DPS):
                kp = mpmath.mpf(k)
                eps = 4 * kp**2 / (mpmath.mpf(mu0) * (kp + 1) ** 2)
                h = mpmath.sqrt(1 + eps**2)
                printed = (mpmath.sqrt(2) + mpmath.sqrt(h + 1)) / mpmath.sqrt(h - 1)
                closed = mpmath.coth(mpmath.asinh(eps) / 4)
                exact = abs(e.roots[2].real) / abs(e.roots[2].imag)
                formula_err = max(formula_err, float(abs(printed - exact) / exact))
                coth_err = max(coth_err, float(abs(closed - exact) / exact))
                ln_n = 2 * mpmath.pi * exact
            pkg = float(tt.log_damping_ratio(mu0, k))
            pkg_err = max(pkg_err, abs(pkg - float(ln_n)) / float(ln_n))
    k0 = p["k_paper"]
    bound = float(mpmath.exp(2 * mpmath.pi))
    n_small = float(np.exp(tt.log_damping_ratio(small[0], k0)))
    n_smallest = float(np.exp(tt.log_damping_ratio(small[-1], k0)))
    log10_n = [float(tt.log_damping_ratio(m, k0) / np.log(10)) for m in p["mu0_reference"]]
    reproduced = {
        "exp_2pi": bound,
        "min_ratio_alpha2_over_beta": min_ratio,
        "ln_n_increasing_in_mu0": monotone,
        "max_printed_ratio_error_rel": formula_err,
        "max_closed_form_ratio_error_rel": coth_err,
        "max_package_ln_n_error_rel": pkg_err,
        "mu0_small": small,
        "k_values": p["k_values"],
        "ln_n_excess_at_small_mu0_per_k": excess,
        "excess_slope": max(slopes, key=lambda x: abs(x - 0.5)),  # farthest from 1/2
        "excess_slope_per_k": slopes,
        "max_excess_leading_term_error_rel": lead_err,
        "excess_at_smallest_mu0": max(float(v[-1]) for v in excess),
        "k": k0,
        "n_at_mu0_small_first": n_small,
        "n_at_mu0_small_last": n_smallest,
        "mu0_reference": p["mu0_reference"],
        "log10_n_at_reference_mu0": log10_n,
    }
    tol = {
        "min_ratio_alpha2_over_beta": {">": 1.0},
        "max_printed_ratio_error_rel": 1e-20,
        "max_closed_form_ratio_error_rel": 1e-20,
        "max_package_ln_n_error_rel": 1e-12,
    }
    # The bound is sharp (an infimum, approached as mu0 -> 0): what the closed form says, so
    # a grid that disagrees means a wrong model.
    tol |= {
        "ln_n_increasing_in_mu0": {"==": True},
        "excess_at_smallest_mu0": 1e-3,
        "max_excess_leading_term_error_rel": 1e-3,
    }
    verdict = decide(all_within(reproduced, tol))
    evidence = {
        "failed": (
            "The ratio |alpha2|/beta falls to 1 or below somewhere, (2.10) or its closed form "
            "is wrong, the package's ln N disagrees with 2 pi |alpha2|/beta from the 40-digit "
            "eigenvalues, or ln N does not fall to 2 pi as the closed form says."
        ),
        "confirmed": (
            "The bound holds as printed, for every mu0 and k. The reproduction adds that it is "
            "sharp: an infimum that is never reached. The closed form "
            "|alpha2|/beta = coth(arsinh(eps)/4) (equal to (2.10) and to the 40-digit "
            "eigenvalues at every probe) decreases strictly in eps, so ln N increases strictly "
            "with mu0 for every k > 0, and tends to 2 pi only as mu0 -> 0, where "
            "ln N - 2 pi = sqrt(2) pi (k+1)/k sqrt(mu0) (1 + o(1)). The grid agrees: ln N "
            "increases on it for every k tried, and at the smallest mu0 the excess matches the "
            f"leading term to {sig(lead_err, 2)} for every k tried (fitted order of the excess "
            f"{sig(max(slopes, key=lambda x: abs(x - 0.5)), 3)} at the farthest from the closed "
            "form's 1/2). At moderate friction N is astronomically larger than 535."
        ),
    }[verdict]
    return Outcome(
        verdict=verdict,
        reproduced=reproduced,
        tolerance=tol,
        summary=(
            f"k = {sig(k0)}: N = {sig(n_small, 6)} at mu0 = {sig(small[0])}, "
            f"{sig(n_smallest, 6)} at mu0 = {sig(small[-1])} (exp(2 pi) = {sig(bound, 7)}); "
            f"min |alpha2|/beta = {sig(min_ratio, 6)} > 1 (smallest over every k and mu0 "
            "tried); closed form ln N = 2 pi coth(arsinh(eps)/4), increasing in mu0"
        ),
        evidence=evidence,
        quantities={
            "exp_2pi": Quantity("the paper's bound e^(2 pi) on N"),
            "min_ratio_alpha2_over_beta": Quantity(
                "the smallest |alpha2| / beta = ln N / (2 pi)",
                over={"k": p["k_values"], "mu0": ["the grid of mu0_range", *small]},
                reduce="min",
            ),
            "n_at_mu0_small_last": Quantity(
                "N = exp(2 pi |alpha2| / beta)", at={"k": k0, "mu0": small[-1]}
            ),
            "log10_n_at_reference_mu0": Quantity(
                "log10 N", at={"k": k0}, over={"mu0": p["mu0_reference"]}, reduce="each"
            ),
        },
    )


#: Initial ratio |z-(0)| / |z+(0)| of the state built close to the decaying subspace.
NEAR_DECAYING_RATIO = 1e9

#: The fraction of |z+| below which |z-| counts as negligible (solution.fast_transient; the
#: report of Fig. 3 and the article refer to it, as ``threshold`` of that claim).
TRANSIENT_THRESHOLD = 0.01
_PERCENT = f"{100 * TRANSIENT_THRESHOLD:g}%"


def _periods_above(
    z0: np.ndarray, mu0: float, k: float, threshold: float, n_periods: float
) -> float:
    """Last time, in periods, at which |z-(t)| > threshold |z+(t)| (0 if never)."""
    period = 2 * np.pi / float(tt.spectrum(mu0, k).beta)
    t = np.linspace(0.0, n_periods * period, int(1000 * n_periods) + 1)
    m = tt.modal_terms(z0, t, mu0, k)
    late = np.nonzero(np.linalg.norm(m.minus, axis=1) > threshold * np.linalg.norm(m.plus, axis=1))
    return float(t[late[0][-1]] / period) if late[0].size else 0.0


def _transient_quantities(p: dict[str, Any], mu0_all: list[float]) -> dict[str, Quantity]:
    last = f"the last time, in periods 2 pi / beta, at which |z-| > {_PERCENT} of |z+|"
    states = len(random_states(p))
    return {
        "threshold": Quantity("the fraction of |z+| below which |z-| counts as negligible"),
        "last_time_above_threshold_fig3_periods_k_paper": Quantity(
            last + ", state of Fig. 3",
            at={"k": p["k_paper"]},
            over={"mu0": p["mu0_fig3"]},
            reduce="each",
        ),
        "last_time_above_threshold_fig3_periods": Quantity(
            last + ", state of Fig. 3",
            over={"k": p["k_values"], "mu0": p["mu0_fig3"]},
            reduce="max",
        ),
        "last_time_above_threshold_generic_periods": Quantity(
            last + f", {states} random states",
            over={"k": p["k_values"], "mu0": mu0_all},
            reduce="max",
        ),
        "near_decaying_initial_ratio": Quantity(
            "|z-(0)| / |z+(0)| of the state built close to the decaying subspace"
        ),
        "mu0_near_decaying": Quantity("the values of mu0 of the generic and near states"),
        "last_time_above_threshold_near_decaying_periods": Quantity(
            last + f", from |z-(0)| / |z+(0)| = {NEAR_DECAYING_RATIO:g}",
            over={"k": p["k_values"], "mu0": mu0_all},
            reduce="max",
        ),
    }


@register(
    "solution.fast_transient",
    where=Where("Sec. 2", "(2.9)", "Fig. 3"),
    claim=(
        "The decaying part matters only during the first period of oscillation; afterwards "
        "it is negligible next to the growing part, for the state of Fig. 3 and in general."
    ),
    paper_value={
        "text": "negligible within one period (Fig. 3: mu0 = 0.1 and 1, k = 2/5)",
        "periods": 1.0,
    },
    expected="refined",
    decisive="last_time_above_threshold_near_decaying_periods",
    gist=(
        "the decaying part is negligible after one period for the states of the paper and "
        "for generic states, not for states close to the decaying subspace"
    ),
    method=(
        "For the state of Fig. 3 and generic states, every k and the mu0 of Fig. 3 and the "
        f"reference mu0, find the last time at which |z-| exceeds {_PERCENT} of |z+|, in "
        "periods; repeat for a state close to the decaying subspace (its growing part scaled "
        f"so that |z-(0)|/|z+(0)| = {NEAR_DECAYING_RATIO:g}) and compare with the prediction "
        f"ln({NEAR_DECAYING_RATIO:g}/{TRANSIENT_THRESHOLD:g}) / (2 pi (alpha1 + |alpha2|)/beta)."
    ),
)
def _fast_transient(p: dict[str, Any]) -> Outcome:
    threshold = TRANSIENT_THRESHOLD
    worst_fig3, worst_generic, worst_near, predicted_near = 0.0, 0.0, 0.0, 0.0
    fig3_k_paper: list[float] = []
    near_k_paper: list[float] = []
    mu0_all = sorted(set(p["mu0_fig3"]) | set(p["mu0_reference"]))
    min_log_contraction = np.inf
    for k in p["k_values"]:
        for mu0 in mu0_all:
            log_contraction = float(tt.log_growth_per_turn(mu0, k) + tt.log_damping_ratio(mu0, k))
            min_log_contraction = min(min_log_contraction, log_contraction)
            for i, z0 in enumerate(_states(p)[1:]):
                last = _periods_above(z0, mu0, k, threshold, 2.0)
                if i == 0 and mu0 in p["mu0_fig3"]:
                    worst_fig3 = max(worst_fig3, last)
                    if k == p["k_paper"]:
                        fig3_k_paper.append(last)
                elif i > 0:
                    worst_generic = max(worst_generic, last)
            m0 = tt.modal_terms(_states(p)[2], np.array([0.0]), mu0, k)
            scale = np.linalg.norm(m0.minus) / np.linalg.norm(m0.plus) / NEAR_DECAYING_RATIO
            z_near = (m0.centre + m0.minus + scale * m0.plus)[0]
            prediction = np.log(NEAR_DECAYING_RATIO / threshold) / log_contraction
            if k == p["k_paper"]:
                near_k_paper.append(_periods_above(z_near, mu0, k, threshold, prediction + 1.0))
            if prediction > worst_near:
                worst_near = _periods_above(z_near, mu0, k, threshold, prediction + 1.0)
                predicted_near = float(prediction)
    reproduced = {
        "threshold": threshold,
        "k": p["k_paper"],
        "last_time_above_threshold_fig3_periods_k_paper": fig3_k_paper,
        "last_time_above_threshold_fig3_periods": worst_fig3,
        "last_time_above_threshold_generic_periods": worst_generic,
        "near_decaying_initial_ratio": NEAR_DECAYING_RATIO,
        "mu0_near_decaying": mu0_all,
        "last_time_above_threshold_near_decaying_periods_k_paper": near_k_paper,
        "last_time_above_threshold_near_decaying_periods": worst_near,
        "predicted_near_decaying_periods": predicted_near,
        "near_decaying_prediction_error_periods": abs(worst_near - predicted_near),
        "min_log_contraction_per_period": min_log_contraction,
        "mu0_fig3": p["mu0_fig3"],
        "k_values": p["k_values"],
    }
    tol = {
        "last_time_above_threshold_fig3_periods": {"<": 1.0},
        "near_decaying_prediction_error_periods": 0.5,
    }
    # What makes it refined: some state keeps its transient longer than a period.
    longer = {
        key: {">=": 1.0}
        for key in (
            "last_time_above_threshold_generic_periods",
            "last_time_above_threshold_near_decaying_periods",
        )
        if not all_within(reproduced, {key: {"<": 1.0}})
    }
    holds = all_within(reproduced, tol)
    verdict = decide(holds and not longer, "refined" if holds else "failed")
    if verdict == "refined":
        tol |= longer
        if "last_time_above_threshold_generic_periods" not in longer:
            tol["last_time_above_threshold_generic_periods"] = {"<": 1.0}
    generic_text = (
        f" and for the generic states tried (at most {sig(worst_generic, 2)})"
        if worst_generic < 1.0
        else f" but not for every generic state tried (up to {sig(worst_generic, 2)} periods)"
    )
    evidence = {
        "failed": f"The decaying part is still above {_PERCENT} of the growing one after a "
        "period, or "
        "its decay relative to the growing part is not the predicted one.",
        "confirmed": "The decaying part is negligible within one period for every state tried.",
        "refined": (
            f"True for the state of Fig. 3 (for k = {sig(p['k_paper'])}: below {_PERCENT} after "
            f"{', '.join(sig(x, 2) for x in fig3_k_paper)} of a period at mu0 = "
            f"{', '.join(sig(m) for m in p['mu0_fig3'])}; at most {sig(worst_fig3, 2)} over "
            f"every k tried){generic_text}, but not for every initial state: |z-|/|z+| shrinks by "
            "exp(-2 pi (alpha1 + |alpha2|)/beta) per period, so the transient lasts about "
            f"ln(|z-(0)|/({threshold:g} |z+(0)|)) / (2 pi (alpha1 + |alpha2|)/beta) periods. For "
            f"a state with |z-(0)|/|z+(0)| = {NEAR_DECAYING_RATIO:g} and k = "
            f"{sig(p['k_paper'])} it lasts "
            f"{', '.join(sig(x, 3) for x in near_k_paper)} periods at mu0 = "
            f"{', '.join(sig(m) for m in mu0_all)}, and at most {sig(worst_near, 3)} periods "
            "over every k and mu0 tried (the longest where the contraction per period is "
            "weakest); on the decaying subspace z+ = 0 it lasts forever, and the ball spirals "
            "into the centre."
        ),
    }[verdict]
    return Outcome(
        verdict=verdict,
        reproduced=reproduced,
        tolerance=tol,
        summary=(
            f"k = {sig(p['k_paper'])}: |z-| < {_PERCENT} of |z+| after "
            f"{', '.join(sig(x, 2) for x in fig3_k_paper)} of a period (Fig. 3, mu0 = "
            f"{', '.join(sig(m) for m in p['mu0_fig3'])}), after "
            f"{', '.join(sig(x, 3) for x in near_k_paper)} periods from |z-|/|z+| = "
            f"{NEAR_DECAYING_RATIO:g} "
            f"(mu0 = {', '.join(sig(m) for m in mu0_all)}); largest over every k and mu0 "
            f"tried: {sig(worst_fig3, 2)} (Fig. 3), {sig(worst_generic, 2)} (generic states), "
            f"{sig(worst_near, 3)} (|z-|/|z+| = {NEAR_DECAYING_RATIO:g})"
        ),
        evidence=evidence,
        quantities=_transient_quantities(p, mu0_all),
    )
