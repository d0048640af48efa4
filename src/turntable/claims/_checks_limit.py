"""Checks of Section 3: the limit of infinite friction, (3.1)-(3.3)."""

from __future__ import annotations

from typing import Any

import mpmath
import numpy as np

import turntable as tt
from turntable import reference as ref
from turntable.claims._core import Outcome, Quantity, Where, all_within, decide, register, sig


@register(
    "limit.expansion",
    where=Where("Sec. 3", "(3.1)-(3.2)"),
    claim=(
        "For large mu0 the roots are +-i k/(k+1) + k^3/(mu0 (k+1)^3) and "
        "-mu0 (k+1)/k -+ i k/(k+1) - k^3/(mu0 (k+1)^3), up to O(mu0^-2)."
    ),
    paper_value={"text": "remainder O(mu0^-2)", "order": -2.0},
    expected="confirmed",
    decisive="remainder_order_alpha1",
    gist="the large-friction expansion (3.2) of the paper",
    method=(
        "Compare the expansion with the 40-digit eigenvalues of L at the large mu0 values for "
        "every k, and fit the order of the remainder of alpha1, alpha2 and beta in mu0; "
        "check the sign of the signed remainder of beta and that mu0^2 times it tends to "
        "-2 k^5/(k+1)^5."
    ),
)
def _expansion(p: dict[str, Any]) -> Outcome:
    mu0s = sorted(p["mu0_limit"])
    orders: dict[str, list[float]] = {"alpha1": [], "alpha2": [], "beta": []}
    beta_coeff_err, pkg_err = 0.0, 0.0
    beta_negative = True
    beta_coeffs: list[float] = []
    for k in p["k_values"]:
        err: dict[str, list[float]] = {"alpha1": [], "alpha2": [], "beta": []}
        for mu0 in mu0s:
            e = ref.mp_spectrum(mu0, k)
            with mpmath.workdps(ref.DPS):
                kk = mpmath.mpf(k) / (mpmath.mpf(k) + 1)
                corr = kk**3 / mu0
                printed = {"alpha1": corr, "alpha2": -mu0 / kk - corr, "beta": kk}
                exact = {
                    "alpha1": e.roots[0].real,
                    "alpha2": e.roots[2].real,
                    "beta": e.roots[0].imag,
                }
                for name in err:
                    err[name].append(float(abs(printed[name] - exact[name])))
                beta_remainder = float(exact["beta"] - printed["beta"])
            beta_negative = beta_negative and beta_remainder < 0
            x = tt.large_friction_expansion(mu0, k)._asdict()
            pkg_err = max(pkg_err, *(abs(float(x[n]) / float(printed[n]) - 1) for n in printed))
        for name, values in err.items():
            orders[name].append(ref.log_log_slope(mu0s, values))
        # Signed remainder of beta at the largest mu0: mu0^2 times it -> -2 k^5/(k+1)^5.
        beta_coeff = beta_remainder * mu0s[-1] ** 2
        beta_coeffs.append(beta_coeff)
        beta_coeff_err = max(beta_coeff_err, abs(beta_coeff / (-2 * (k / (k + 1)) ** 5) - 1))
    worst = {name: max(v) for name, v in orders.items()}
    tol = {
        "remainder_order_alpha1": -3.0 + 0.05,
        "remainder_order_alpha2": -3.0 + 0.05,
        "remainder_order_beta": -2.0 + 0.05,
        "beta_remainder_negative": {"==": True},
        "beta_remainder_coefficient_error_rel": 1e-6,
        "max_package_error_rel": 1e-14,
    }
    reproduced = {
        "mu0_limit": mu0s,
        "remainder_order_alpha1": worst["alpha1"],
        "remainder_order_alpha2": worst["alpha2"],
        "remainder_order_beta": worst["beta"],
        "beta_remainder_negative": beta_negative,
        "beta_remainder_times_mu0_squared_per_k": beta_coeffs,
        "beta_remainder_coefficient_error_rel": beta_coeff_err,
        "max_package_error_rel": pkg_err,
        "k_values": p["k_values"],
    }
    ok = all_within(reproduced, tol)
    return Outcome(
        verdict=decide(ok),
        reproduced=reproduced,
        tolerance=tol,
        summary=(
            "largest fitted order over the k tried: remainder ~ "
            f"mu0^{sig(worst['alpha1'], 3)} (alpha1), "
            f"mu0^{sig(worst['alpha2'], 3)} (alpha2), mu0^{sig(worst['beta'], 3)} (beta)"
        ),
        evidence=(
            "The expansion holds with remainder O(mu0^-2) for every k tried; the real parts "
            "are even accurate to O(mu0^-3) (largest fitted order over the k tried "
            f"{sig(max(worst['alpha1'], worst['alpha2']), 5)}), and the imaginary "
            "part's remainder is negative, mu0^2 times it within a relative "
            f"{sig(beta_coeff_err, 2)} of -2 k^5/(k+1)^5 at mu0 = {sig(mu0s[-1])} (largest "
            "over the k tried)."
            if ok
            else "The expansion does not approach the eigenvalues at the stated order."
        ),
        quantities={
            f"remainder_order_{name}": Quantity(
                f"order in mu0 of |{name} - (3.2)|, fitted over mu0 in "
                f"{{{', '.join(f'{m:g}' for m in mu0s)}}}, against 40-digit eigenvalues",
                over={"k": p["k_values"]},
                reduce="max",
            )
            for name in ("alpha1", "beta")
        },
    )


@register(
    "limit.frequency",
    where=Where("Sec. 3", "(3.2)-(3.3)"),
    claim=(
        "As mu0 -> infinity the growth rate alpha1 tends to 0 and the frequency beta to "
        "k/(k+1), the rate of rolling without slipping (2/7 of the plane's rate for k = 2/5)."
    ),
    paper_value={
        "text": "in the limit closed circles at a constant frequency fixed by the radius of "
        "inertia alone; the expansion (3.2) gives beta -> k/(k+1), alpha1 -> 0"
    },
    expected="confirmed",
    decisive="beta_error_order",
    gist="the limit beta -> k/(k+1), alpha1 -> 0",
    method=(
        "Derive the no-slip rate independently from the constrained Newton-Euler equations "
        "(solve for the contact force, eigenvalues of the resulting 2x2 matrix) and compare "
        "with beta at the large mu0 values (40-digit eigenvalues), fitting the order at which "
        "the difference vanishes; check that alpha1 mu0 tends to k^3/(k+1)^3 and that the "
        "package's no-slip motion turns at that rate."
    ),
)
def _frequency(p: dict[str, Any]) -> Outcome:
    mu0s = sorted(p["mu0_limit"])
    beta_order, a1_order, a1_coeff_err, beta_last, nh_err = [], [], [], 0.0, 0.0
    t = np.linspace(0.0, 10.0, 101)
    for k in p["k_values"]:
        omega = ref.no_slip_frequency(k)
        spectra = [ref.mp_spectrum(mu0, k) for mu0 in mu0s]
        beta_err = [abs(e.beta - omega) / omega for e in spectra]
        beta_order.append(ref.log_log_slope(mu0s, beta_err))
        a1_order.append(ref.log_log_slope(mu0s, [e.alpha1 for e in spectra]))
        a1_coeff_err.append(abs(spectra[-1].alpha1 * mu0s[-1] / (k / (k + 1)) ** 3 - 1))
        beta_last = max(beta_last, beta_err[-1])
        z = tt.nonholonomic(p["state_fig4"], t, k)
        rc = tt.spiral_centre(p["state_fig4"], k)
        ang = np.unwrap(np.angle((z[:, 0] - rc[0]) + 1j * (z[:, 1] - rc[1])))
        nh_err = max(nh_err, abs(np.polyfit(t, ang, 1)[0] / omega - 1))
    k0 = p["k_paper"]
    omega0 = ref.no_slip_frequency(k0)
    e_last = ref.mp_spectrum(mu0s[-1], k0)
    tol = {
        "beta_error_order": -1.9,
        "alpha1_order": -0.95,
        "max_alpha1_mu0_coefficient_error_rel": 0.1,
        "max_no_slip_rate_error_rel": 1e-12,
    }
    reproduced = {
        "k": k0,
        "no_slip_frequency": omega0,
        "beta_at_largest_mu0": e_last.beta,
        "alpha1_at_largest_mu0": e_last.alpha1,
        "largest_mu0": mu0s[-1],
        "beta_error_order": max(beta_order),
        "alpha1_order": max(a1_order),
        "max_beta_error_rel_at_largest_mu0": beta_last,
        "max_alpha1_mu0_coefficient_error_rel": max(a1_coeff_err),
        "max_no_slip_rate_error_rel": nh_err,
    }
    ok = all_within(reproduced, tol)
    return Outcome(
        verdict=decide(ok),
        reproduced=reproduced,
        tolerance=tol,
        summary=(
            f"no-slip rate {sig(omega0, 6)} (k = {sig(k0)}); beta = {sig(e_last.beta, 8)}, "
            f"alpha1 = {sig(e_last.alpha1, 3)} at mu0 = {sig(mu0s[-1])}; "
            f"beta error ~ mu0^{sig(max(beta_order), 3)} (largest order over the k tried)"
        ),
        evidence=(
            "beta tends to the rate of rolling without slipping (error ~ mu0^-2) and alpha1 to "
            "0 like k^3/((k+1)^3 mu0), for every k tried."
            if ok
            else "beta or alpha1 does not tend to the no-slip values at the expected rate."
        ),
        quantities={
            "beta_error_order": Quantity(
                "order in mu0 of |beta - k/(k+1)| / (k/(k+1)), fitted over mu0 in "
                f"{{{', '.join(f'{m:g}' for m in mu0s)}}}, against 40-digit eigenvalues",
                over={"k": p["k_values"]},
                reduce="max",
            ),
        },
    )


@register(
    "limit.convergence",
    where=Where("Sec. 3", "(3.3)"),
    claim=(
        "On each fixed time interval the solution tends, as mu0 -> infinity, to the motion "
        "without slipping (circles at constant rate)."
    ),
    paper_value={
        "text": "on each fixed time interval the solution tends to the no-slip one as "
        "mu0 -> infinity (no rate stated)"
    },
    expected="refined",
    decisive="min_velocity_change_across_layer",
    gist=(
        "the convergence to rolling without slipping holds on fixed intervals, for the "
        "positions uniformly, for the velocities only outside an initial layer across which "
        "they jump by a finite amount"
    ),
    method=(
        "For the slipping state of Fig. 4, its no-slip counterpart and every k, measure on "
        "[0, T] the largest position error and the largest velocity error outside an initial "
        "layer of width layer_decay_times/|alpha2| against the no-slip motion, fit their "
        "order in mu0, and the distance between the two centres at t = 1/alpha1. Across the "
        "layer the "
        "velocities jump: compare the change of v and w of the slipping ball from t = 0 to the "
        "end of the layer (and the Euclidean norm of the change of (vx, vy, wx, wy)) with "
        "the closed-form jump, -k u0/(k+1) in v and i u0/(k+1) in w (complex form, u0 the initial "
        "slip), fitting the order in mu0 of the difference, and the package's no-slip state "
        "with the same closed form."
    ),
)
def _convergence(p: dict[str, Any]) -> Outcome:
    mu0s = sorted(p["mu0_limit"])
    t_end = p["t_limit"]
    pos_order, vel_order, pos_last, vel_last = [], [], 0.0, 0.0
    start_err, long_err = np.inf, np.inf
    start_err_k0 = np.inf
    crossed_min = np.inf
    speed_k0: list[float] = []
    spin_k0: list[float] = []
    jump_order_k0 = 0.0
    jump_order, jump_last, jump_pkg = [], 0.0, 0.0
    slipping = np.asarray(p["state_fig4"])
    for k in p["k_values"]:
        jump = _velocity_jump(slipping, k)
        jump_pkg = max(
            jump_pkg, float(np.abs(tt.no_slip_state(slipping, k)[2:] - slipping[2:] - jump).max())
        )
        layer_err = []
        for mu0 in mu0s:
            t_layer = np.array([p["layer_decay_times"] / abs(float(tt.spectrum(mu0, k).alpha2))])
            crossed = tt.solve(slipping, t_layer, mu0, k)[0, 2:] - slipping[2:]
            layer_err.append(float(np.abs(crossed - jump).max()))
            # the change of the four velocities (vx, vy, wx, wy), Euclidean norm
            crossed_min = min(crossed_min, float(np.linalg.norm(crossed)))
            if k == p["k_paper"]:
                speed_k0.append(float(np.hypot(*crossed[:2])))
                spin_k0.append(float(np.hypot(*crossed[2:])))
        jump_order.append(ref.log_log_slope(mu0s, layer_err))
        if k == p["k_paper"]:
            jump_order_k0 = jump_order[-1]
        jump_last = max(jump_last, layer_err[-1])
        for z0 in (slipping, tt.no_slip_state(slipping, k)):
            pos, vel = [], []
            for mu0 in mu0s:
                s = tt.spectrum(mu0, k)
                layer = p["layer_decay_times"] / abs(float(s.alpha2))
                t = np.union1d(np.linspace(0.0, t_end, 1001), np.linspace(layer, t_end, 1001))
                z = tt.solve(z0, t, mu0, k)
                zn = tt.nonholonomic(z0, t, k)
                pos.append(float(np.abs(z[:, :2] - zn[:, :2]).max()))
                vel.append(float(np.abs(z[t >= layer, 2:] - zn[t >= layer, 2:]).max()))
                if z0 is slipping:
                    start_err = min(start_err, float(np.abs(z[0, 2:] - zn[0, 2:]).max()))
                    if k == p["k_paper"]:
                        start_err_k0 = min(start_err_k0, float(np.abs(z[0, 2:] - zn[0, 2:]).max()))
                    t_long = np.array([1.0 / float(s.alpha1)])
                    far = (
                        tt.solve(z0, t_long, mu0, k)[:, :2] - tt.nonholonomic(z0, t_long, k)[:, :2]
                    )
                    long_err = min(long_err, float(np.hypot(*far[0])))
            pos_order.append(ref.log_log_slope(mu0s, pos))
            vel_order.append(ref.log_log_slope(mu0s, vel))
            pos_last, vel_last = max(pos_last, pos[-1]), max(vel_last, vel[-1])
    # The paper's ball and the state of Fig. 4: the one fit Fig. 6(b) draws.
    fit_k0 = tt.limit_error_fit(slipping, t_end, mu0s, p["k_paper"])
    initial_slip = float(np.abs(tt.slip_velocity(p["state_fig4"])).max())
    jump_k0 = _velocity_jump(slipping, p["k_paper"])
    reproduced = {
        "t_end": t_end,
        "mu0_limit": mu0s,
        "position_order": max(pos_order),
        "velocity_order_outside_layer": max(vel_order),
        "max_position_error_at_largest_mu0": pos_last,
        "max_velocity_error_at_largest_mu0": vel_last,
        "position_order_k_paper": fit_k0.order,
        "position_errors_k_paper": fit_k0.error,
        "k": p["k_paper"],
        # identities: at t = 0 the error is the jump, whatever mu0 (not measured)
        "identity_velocity_error_at_t0_k_paper": (
            start_err_k0 if np.isfinite(start_err_k0) else -1.0
        ),
        "identity_velocity_error_at_t0": start_err,
        "min_velocity_change_across_layer": crossed_min,
        "speed_change_across_layer_k_paper": speed_k0,
        "spin_change_across_layer_k_paper": spin_k0,
        "initial_slip": initial_slip,
        "initial_distance_from_spiral_centre": float(
            np.hypot(*(slipping[:2] - tt.spiral_centre(slipping, p["k_paper"])))
        ),
        "velocity_jump_closed_form_k_paper": jump_k0,
        "no_slip_state_vs_closed_form_jump": jump_pkg,
        "layer_jump_error_order": max(jump_order),
        "layer_jump_error_order_k_paper": jump_order_k0,
        "layer_jump_error_at_largest_mu0": jump_last,
        "min_position_error_at_t_over_alpha1": long_err,
    }
    tol = {
        "position_order": -1.0 + 0.05,
        "velocity_order_outside_layer": -1.0 + 0.05,
        "max_position_error_at_largest_mu0": 1e-2,
        "max_velocity_error_at_largest_mu0": 1e-2,
        "no_slip_state_vs_closed_form_jump": 1e-14,
        "layer_jump_error_order": -1.0 + 0.05,
    }
    # What makes it refined, measured on the slipping solution: its velocities change by
    # O(1) across a layer that shrinks like 1/mu0, for every mu0 (not uniform on [0, T]).
    # Only the layer restricts the statement, which is made on fixed intervals: that the
    # convergence is not uniform in time (the distance of the centres at t = 1/alpha1) is an
    # addition.
    layer = {"min_velocity_change_across_layer": {">=": 0.1}}
    converges = all_within(reproduced, tol)
    shown = all_within(reproduced, layer)
    verdict = decide(converges and not shown, "refined" if converges else "failed")
    if verdict == "refined":
        tol |= layer
    evidence = {
        "failed": "The solution does not approach the no-slip motion at rate 1/mu0.",
        "confirmed": "The solution approaches the no-slip motion uniformly on [0, T].",
        "refined": (
            "Holds on each fixed interval, with error O(1/mu0) for the positions uniformly on "
            f"[0, T] (fitted order {sig(fit_k0.order, 4)} for k = {sig(p['k_paper'])} and the "
            f"state of Fig. 4, the fit drawn in the reproduction's Figure 6(b); largest over "
            "every k tried and both starts "
            f"{sig(max(pos_order), 3)}); the velocities converge at the same rate only outside "
            "an initial layer of width ~1/mu0 when z(0) slips, and the limit starts from the "
            "no-slip state with the same position and angular momentum. Across the layer the "
            "velocities jump by -k u0/(k+1) in v and by i u0/(k+1) in w (complex form; u0 the "
            "initial slip), whatever mu0: for the state of Fig. 4 and k = "
            f"{sig(p['k_paper'])}, the jumps of (vx, vy, wx, wy) are "
            f"({', '.join(sig(x, 3) for x in jump_k0)}). At t = 0 the velocity error is this "
            "jump by construction (both motions start from their own initial state: "
            f"{sig(start_err, 3)}, the largest component of the jump, the smallest over every "
            "k), an identity, not a measurement, and no bound rests on it; what is measured is "
            "that the slipping ball does cross the layer with it, to O(1/mu0) (fitted order "
            f"{sig(jump_order_k0, 3)} for k = {sig(p['k_paper'])}, largest over every k "
            f"{sig(max(jump_order), 3)}; error {sig(jump_last, 2)} at mu0 = {sig(mu0s[-1])}), "
            "the change of (vx, vy, wx, wy) across the layer having a Euclidean norm of at "
            f"least {sig(crossed_min, 3)} for every k and mu0 tried (for k = "
            f"{sig(p['k_paper'])}: |dv| = {sig(min(speed_k0), 3)} and |dw| = "
            f"{sig(min(spin_k0), 3)} at the least). "
            "Added: the convergence is not uniform in time; at t = 1/alpha1 the two centres "
            f"are still at least {sig(long_err, 3)} apart (smallest over every k and mu0 tried; "
            "the spiral's radius has grown by e)."
        ),
    }[verdict]
    return Outcome(
        verdict=verdict,
        reproduced=reproduced,
        tolerance=tol,
        summary=(
            f"on [0, {sig(t_end)}], k = {sig(p['k_paper'])} (the reproduction's Figure 6(b)): "
            "position error ~ "
            f"mu0^{sig(fit_k0.order, 4)}; velocities jump across the initial layer by the "
            f"closed form (largest component {sig(float(np.abs(jump_k0).max()), 3)}, whatever "
            f"mu0), crossed to O(mu0^{sig(jump_order_k0, 3)}). Largest orders over every k "
            f"tried: mu0^{sig(max(pos_order), 3)} (positions), mu0^{sig(max(jump_order), 3)} "
            f"(layer). Distance of the centres at t = 1/alpha1 at least {sig(long_err, 3)}"
        ),
        evidence=evidence,
        quantities=_convergence_quantities(p, mu0s),
    )


def _convergence_quantities(p: dict[str, Any], mu0s: list[float]) -> dict[str, Quantity]:
    k0, fig4 = p["k_paper"], "from the state of Fig. 4"
    return {
        "t_end": Quantity("the end of the interval [0, T] of the convergence"),
        "initial_slip": Quantity("the largest component of the initial slip u0, " + fig4),
        "position_order_k_paper": Quantity(
            "order in mu0 of max |r - r_ns| on [0, T], fitted over mu0 in "
            f"{{{', '.join(f'{m:g}' for m in mu0s)}}}, " + fig4,
            at={"k": k0},
        ),
        "speed_change_across_layer_k_paper": Quantity(
            "|v(T) - v(0)|, T the end of the initial layer, " + fig4,
            at={"k": k0},
            over={"mu0": mu0s},
            reduce="each",
        ),
        "spin_change_across_layer_k_paper": Quantity(
            "|w(T) - w(0)|, T the end of the initial layer, " + fig4,
            at={"k": k0},
            over={"mu0": mu0s},
            reduce="each",
        ),
        "min_velocity_change_across_layer": Quantity(
            "|(dvx, dvy, dwx, dwy)| from t = 0 to the end of the initial layer, t = "
            f"{p['layer_decay_times']:g}/|alpha2|, " + fig4,
            over={"k": p["k_values"], "mu0": mu0s},
            reduce="min",
        ),
        "min_position_error_at_t_over_alpha1": Quantity(
            "|r - r_ns| at t = 1/alpha1, " + fig4,
            over={"k": p["k_values"], "mu0": mu0s},
            reduce="min",
        ),
    }


def _velocity_jump(z0: np.ndarray, k: float) -> np.ndarray:
    """The change (dvx, dvy, dwx, dwy) of the velocities across the initial layer.

    Notes
    -----
    In the complex form, the limit keeps r and c = v - i k w and ends on u = 0, with
    u = v + i w - i r; so dv = i k dw and u0 + dv + i dw = 0, whence
    dv = -k u0/(k+1) and dw = i u0/(k+1), with u0 the initial slip: independent of mu0.
    """
    r, v, w = (complex(z0[i], z0[i + 1]) for i in (0, 2, 4))
    u0 = v + 1j * w - 1j * r
    dv, dw = -k * u0 / (k + 1.0), 1j * u0 / (k + 1.0)
    return np.array([dv.real, dv.imag, dw.real, dw.imag])
