"""Checks of the Introduction: rolling without slipping and the scaling of the friction."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import NDArray

import turntable as tt
from turntable import reference as ref
from turntable.claims import _constrained as con
from turntable.claims._core import Outcome, Quantity, Where, all_within, decide, register, sig
from turntable.claims._params import random_states

#: Tolerance of the quantities that are constant, or equal, up to rounding (relative).
ROUNDING = 1e-9


def _variation(values: NDArray[np.float64]) -> float:
    """Return (max - min) / max of non-negative values (0 for all zeros)."""
    top = float(np.max(values))
    return 0.0 if top == 0.0 else float((top - np.min(values)) / top)


def _no_slip_run(z0: NDArray[np.float64], k: float, t: NDArray[np.float64]) -> dict[str, float]:
    """Sample the no-slip motion from z0 with the matrix exponential and measure it.

    Returns the relative variations of the distance from the centre, of the speed, of the
    ball's angular velocity vector (max |w(t) - w(0)| / max |w|) and of its magnitude, and
    the largest relative deviation of the orbital rate from k/(k+1).
    """
    import scipy.linalg

    big = con.no_slip_matrix(k)
    z = scipy.linalg.expm(big * t[:, None, None]) @ z0  # one exponential per time
    rc = (con.momentum_matrix(k) @ z0) / k  # at rest (v = 0) the momentum is k w = k r_c
    rho = z[:, :2] - rc
    dist = np.hypot(*rho.T)
    rate = (rho[:, 0] * z[:, 3] - rho[:, 1] * z[:, 2]) / dist**2
    spin = np.hypot(*z[:, 4:].T)
    return {
        "radius": _variation(dist),
        "rate": float(np.max(np.abs(rate / (k / (k + 1.0)) - 1.0))),
        "speed": _variation(np.hypot(*z[:, 2:4].T)),
        "spin_vector": float(np.max(np.hypot(*(z[:, 4:] - z[0, 4:]).T))) / float(np.max(spin)),
        "spin_magnitude": _variation(spin),
        "package": float(np.max(np.abs(tt.nonholonomic(z0, t, k) - z))),
    }


@register(
    "intro.no_slip_motion",
    where=Where("Introduction"),
    claim=(
        "Without slipping the centre of the ball moves on circles, and the ball moves with a "
        "constant angular velocity that depends only on the plane's rate Omega and the "
        "ball's radius of inertia."
    ),
    paper_value={
        "text": (
            "circles; a constant angular velocity depending only on Omega and the radius of "
            "inertia (qualitative)"
        )
    },
    method=(
        "Build the no-slip dynamics from the Newton-Euler equations with the contact force "
        "that keeps u = 0, and sample exp(M t) z0 over two turns for the no-slip states of "
        "Fig. 4, of a ball put down at rest where Fig. 4 starts, and of random states, for "
        "every k. Measure the variation of the distance from the centre, of the speed, of the "
        "orbital rate (against "
        "k/(k+1)), of the ball's angular velocity vector and of its magnitude; compare the "
        "package's no-slip motion with the same samples."
    ),
    expected="refined",
    decisive="spin_vector",
    gist=(
        "without slipping the centre circles at the constant rate k/(k+1), which depends "
        "only on Omega and k; the ball's own angular velocity is not constant, it turns with "
        "the centre"
    ),
)
def _no_slip_motion(p: dict[str, Any]) -> Outcome:
    worst = {"radius": 0.0, "rate": 0.0, "speed": 0.0, "package": 0.0}
    spin_vector_min, fig4_spin_vector, fig4_magnitude, rest_magnitude = np.inf, 0.0, 0.0, 0.0
    fig4_rate = 0.0
    for k in p["k_values"]:
        proj = con.no_slip_projection(k)
        t = np.linspace(0.0, 2.0 * 2.0 * np.pi * (k + 1.0) / k, 401)
        fig4 = proj @ np.asarray(p["state_fig4"])
        rest = proj @ np.r_[p["state_fig4"][:2], 0.0, 0.0, 0.0, 0.0]  # put down at rest
        generic = [fig4, *(proj @ z for z in random_states(p))]
        for z0 in generic:
            m = _no_slip_run(z0, k, t)
            for key in worst:
                worst[key] = max(worst[key], m[key])
            spin_vector_min = min(spin_vector_min, m["spin_vector"])
            if z0 is fig4 and k == p["k_paper"]:
                fig4_spin_vector, fig4_magnitude = m["spin_vector"], m["spin_magnitude"]
                fig4_rate = m["rate"]
        m = _no_slip_run(rest, k, t)
        worst = {key: max(worst[key], m[key]) for key in worst}
        rest_magnitude = max(rest_magnitude, m["spin_magnitude"])
    k0 = p["k_paper"]
    tol = {
        "radius": ROUNDING,
        "rate": ROUNDING,
        "speed": ROUNDING,
        "package": ROUNDING,
        "spin_vector": ROUNDING,
        "rest_spin_magnitude": ROUNDING,
    }
    # "Moves with a constant angular velocity" holds when read as the rate at which the
    # centre circles (the paper's Sec. 2 restates it so, "closed circles with a constant
    # frequency"), and fails when read literally: the ball's own angular velocity turns
    # with the centre, for every state tried. Holding under one reading only, it is refined.
    literal = spin_vector_min <= ROUNDING
    tol["spin_vector"] = {"<=" if literal else ">": ROUNDING}
    measured = {**worst, "spin_vector": spin_vector_min, "rest_spin_magnitude": rest_magnitude}
    verdict = decide(literal, otherwise="refined") if all_within(measured, tol) else "failed"
    evidence = {
        "failed": (
            "The no-slip motion does not keep a constant distance from the centre, a constant "
            "speed and the orbital rate k/(k+1), the package's no-slip motion disagrees, or "
            "the ball's angular velocity does not turn as its closed form says."
        ),
        "refined": (
            "Holds when 'angular velocity' is read as the rate at which the centre circles, "
            "as the paper's Sec. 2 restates it ('closed circles with a constant frequency'); "
            "read as the ball's own angular velocity, it does not hold. "
            "The centre circles about (x0, y0) with constant radius and speed at the orbital "
            "rate k/(k+1) (in units of Omega; 2/7 for k = 2/5), the same for every state "
            f"(largest relative deviation {sig(worst['rate'], 2)}), so it depends only on Omega "
            "and the radius of inertia in units of the ball's radius (k = (radius of inertia / "
            "R)^2). The ball's own angular velocity is not constant: its horizontal part "
            "w = r_c + (r - r_c)/(k+1) turns with the centre (relative change "
            f"{sig(fig4_spin_vector, 3)} for the state of Fig. 4 at k = {sig(k0)}, at least "
            f"{sig(spin_vector_min, 3)} over every k and state tried), and its magnitude is "
            "constant only when the circle is centred on the plane's axis, as for a ball put "
            f"down at rest (variation {sig(rest_magnitude, 2)})."
        ),
    }[verdict]
    return Outcome(
        verdict=verdict,
        reproduced={
            "k": k0,
            "orbital_rate": k0 / (k0 + 1.0),
            "radius": worst["radius"],
            "rate": worst["rate"],
            "speed": worst["speed"],
            "package": worst["package"],
            "rate_fig4": fig4_rate,
            "spin_vector": spin_vector_min,
            "spin_vector_fig4": fig4_spin_vector,
            "spin_magnitude_fig4": fig4_magnitude,
            "rest_spin_magnitude": rest_magnitude,
        },
        tolerance=tol,
        summary=(
            f"state of Fig. 4, k = {sig(k0)}: orbital rate k/(k+1) = "
            f"{sig(k0 / (k0 + 1.0), 6)}, constant to {sig(fig4_rate, 2)}; the angular velocity "
            f"vector changes by {sig(fig4_spin_vector, 3)}, its magnitude by "
            f"{sig(fig4_magnitude, 3)} (relative). Over every k and state tried: rate constant "
            f"to {sig(worst['rate'], 2)} (largest deviation), vector change at least "
            f"{sig(spin_vector_min, 3)} (smallest)"
        ),
        evidence=evidence,
        quantities={
            "orbital_rate": Quantity(
                "the rate k/(k+1) at which the rolling ball's centre circles", at={"k": k0}
            ),
            "spin_vector": Quantity(
                "max |w(t) - w(0)| / max |w| of the ball's angular velocity over two turns",
                over={"k": p["k_values"], "state": ["Fig. 4", "random"]},
                reduce="min",
            ),
            "rate": Quantity(
                "relative deviation of the orbital rate from k/(k+1) over two turns",
                over={"k": p["k_values"], "state": ["Fig. 4", "at rest", "random"]},
                reduce="max",
            ),
        },
    )


def ball_mass(radius: float, density: float) -> float:
    """Return the mass 4/3 pi R^3 rho of a homogeneous ball (kg, from m and kg/m^3)."""
    return 4.0 / 3.0 * math.pi * radius**3 * density


def plane_rate(rpm: float) -> float:
    """Return the angular velocity in rad/s of a plane turning ``rpm`` times a minute."""
    return 2.0 * math.pi * rpm / 60.0


def dimensionless_friction(friction: float, mass: float, omega: float) -> float:
    """Return mu0 = mu0_dim / (m Omega), the friction coefficient in the units of (1.6)."""
    return friction / (mass * omega)


def dimensional_matrix(
    friction: float, mass: float, inertia: float, radius: float, omega: float
) -> NDArray[np.float64]:
    """Return the 6x6 matrix of the dimensional planar equations (SI units).

    Notes
    -----
    Section 1, (1.3)-(1.4): u = v + R gamma x w - Omega gamma x r,
    m dv/dt = -mu0_dim u, I dw/dt = mu0_dim R gamma x u (the torque of the friction
    applied at -R gamma), built column by column with cross products.
    """
    g = np.array([0.0, 0.0, 1.0])

    def rhs(z: NDArray[np.float64]) -> NDArray[np.float64]:
        r, v, w = (np.array([z[i], z[i + 1], 0.0]) for i in (0, 2, 4))
        u = v + radius * np.cross(g, w) - omega * np.cross(g, r)
        dv = -friction * u / mass
        dw = np.cross(-radius * g, -friction * u) / inertia
        return np.array([v[0], v[1], dv[0], dv[1], dw[0], dw[1]])

    return np.column_stack([rhs(e) for e in np.eye(6)])


def _persistent_slip(mu0: float, k: float) -> float:
    """Return |u| / |v| of the growing mode lambda = alpha1 + i beta (complex form).

    In complex form the mode has v = lambda rho, w = -i lambda rho / k, so
    u = v + i (w - r) with r = r_c + rho gives u = (lambda (k + 1) / k - i) rho.
    """
    s = tt.spectrum(mu0, k)
    lam = complex(float(s.alpha1), float(s.beta))
    return abs(lam * (k + 1.0) / k - 1j) / abs(lam)


@register(
    "model.scaling",
    where=Where("Introduction", "(1.6)"),
    claim=(
        "Slipping is to be expected on a fast rotating plane: the friction enters the "
        "dimensionless equations only as mu0 = mu0_dim/(m Omega)."
    ),
    paper_value={
        "text": "slipping on a fast rotating plane (qualitative); mu0 stands for mu0_dim/(m Omega)"
    },
    method=(
        "For a concrete ball and turntable (claims parameters ball_radius, ball_density, "
        "friction_viscous, turntable_rpm; the friction is illustrative, the paper gives none) "
        "solve the dimensional equations, built with cross products in SI units, from the same "
        "physical state at each plane rate, with the matrix exponential; compare with the "
        "package's dimensionless solution at mu0 = mu0_dim/(m Omega) and at the mu0 of the other "
        "rates; after the transient measure the slip relative to the velocity and compare with "
        "the growing mode; follow the growth per turn and the slip as mu0 -> 0."
    ),
    expected="confirmed",
    decisive="persistent_slip_fast_over_slow",
    gist=(
        "the friction enters only as mu0 = mu0_dim/(m Omega): a faster plane means a "
        "smaller mu0, farther from rolling without slipping"
    ),
)
def _scaling(p: dict[str, Any]) -> Outcome:
    import scipy.linalg

    k = p["k_paper"]
    radius = p["ball_radius"]
    mass = ball_mass(radius, p["ball_density"])
    inertia = k * mass * radius**2
    rpms = sorted(p["turntable_rpm"])
    omegas = [plane_rate(r) for r in rpms]
    mu0s = [dimensionless_friction(p["friction_viscous"], mass, om) for om in omegas]
    z_si = np.asarray(p["state_si"])
    runs = []
    for om, mu0 in zip(omegas, mu0s, strict=True):
        alpha2 = abs(float(tt.spectrum(mu0, k).alpha2))
        t_end = max(2.0 * np.pi * p["scaling_turns"] / om, 40.0 / (alpha2 * om))
        t = np.linspace(0.0, t_end, 201)
        big = dimensional_matrix(p["friction_viscous"], mass, inertia, radius, om)
        z_dim = np.array([scipy.linalg.expm(big * ti) @ z_si for ti in t])
        units = np.array([radius, radius, radius * om, radius * om, om, om])  # R, R Omega, Omega
        runs.append((om, mu0, t, z_dim / units, z_si / units))
    scaling_err, cross_err, slip_err, slip = 0.0, np.inf, 0.0, []
    for i, (om, mu0, t, z, z0) in enumerate(runs):
        size = float(np.max(np.abs(z)))
        right = tt.solve(z0, om * t, mu0, k)
        scaling_err = max(scaling_err, float(np.max(np.abs(right - z))) / size)
        for other in mu0s[:i] + mu0s[i + 1 :]:
            wrong = tt.solve(z0, om * t, other, k)
            cross_err = min(cross_err, float(np.max(np.abs(wrong - z))) / size)
        u = con.slip_matrix() @ z[-1]
        slip.append(float(np.hypot(*u) / np.hypot(*z[-1, 2:4])))
        slip_err = max(slip_err, abs(slip[-1] / _persistent_slip(mu0, k) - 1.0))
    per_turn = [float(tt.log_growth_per_turn(m, k)) / (2.0 * np.pi) for m in mu0s]
    decay_turns = [1.0 / (2.0 * np.pi * abs(float(tt.spectrum(m, k).alpha2))) for m in mu0s]
    small = sorted(p["mu0_small"], reverse=True)
    small_per_turn = [float(tt.log_growth_per_turn(m, k)) / (2.0 * np.pi) for m in small]
    small_slip = [_persistent_slip(m, k) for m in small]
    slip_order = ref.log_log_slope(small, small_slip)
    trends = (
        bool(np.all(np.diff(slip) > 0))
        and bool(np.all(np.diff(per_turn) > 0))
        and bool(np.all(np.diff(decay_turns) > 0))
        and bool(np.all(np.diff(small_per_turn) > 0))
        and max(small_per_turn) < 1.0
    )
    tol = {
        "scaling_error_rel": ROUNDING,
        "cross_error_rel": {">=": 0.1},
        "persistent_slip_rel": 1e-6,
        "growth_per_turn_gap_at_smallest_mu0": 1e-3,
        "slip_order_error": 0.05,
        "slip_and_growth_per_turn_increase_with_plane_rate": {"==": True},
        # the paper's statement: the faster plane, the more the ball slips
        "persistent_slip_fast_over_slow": {">": 1.0},
    }
    faster = rpms[-1]
    reproduced = {
        "k": k,
        "ball_radius": radius,
        "ball_mass": mass,
        "friction_viscous": p["friction_viscous"],
        "turntable_rpm": rpms,
        "plane_rate": omegas,
        "mu0": mu0s,
        "scaling_error_rel": scaling_err,
        "cross_error_rel": cross_err,
        "persistent_slip": slip,
        "persistent_slip_rel": slip_err,
        "persistent_slip_fast_over_slow": slip[-1] / slip[0],
        "growth_per_turn_over_2pi": per_turn,
        "slip_decay_turns": decay_turns,
        "mu0_small": small,
        "growth_per_turn_gap_at_smallest_mu0": 1.0 - small_per_turn[-1],
        "slip_order_in_mu0": slip_order,
        "slip_order_error": abs(slip_order + 0.5),
        "slip_and_growth_per_turn_increase_with_plane_rate": trends,
    }
    ok = all_within(reproduced, tol)
    return Outcome(
        verdict=decide(ok),
        reproduced=reproduced,
        tolerance=tol,
        summary=(
            f"ball of R = {sig(radius)} m, m = {sig(mass, 3)} kg, "
            f"mu0_dim = {sig(p['friction_viscous'])} N s/m: "
            f"mu0 = {sig(mu0s[0], 3)} at {sig(rpms[0])} rpm, {sig(mu0s[-1], 3)} at "
            f"{sig(faster)} rpm; dimensional vs dimensionless {sig(scaling_err, 2)}; "
            f"persistent slip/velocity {sig(slip[0], 3)} -> {sig(slip[-1], 3)}"
        ),
        evidence=(
            "The dimensional solutions of the ball at every plane rate coincide with the "
            f"dimensionless one at mu0 = mu0_dim/(m Omega) (relative {sig(scaling_err, 2)}) and "
            f"differ from those at the other rates' mu0 by at least {sig(cross_err, 2)}: only "
            "mu0_dim/(m Omega) matters. A faster plane therefore means a smaller mu0 and moves "
            "the motion away from rolling without slipping (mu0 -> infinity, Sec. 3) towards the "
            "small-friction limit mu0 -> 0: the slip that survives the transient grows relative "
            f"to the velocity (from {sig(slip[0], 3)} at {sig(rpms[0])} rpm to "
            f"{sig(slip[-1], 3)} at {sig(faster)} rpm, like mu0^{sig(slip_order, 3)} as "
            "mu0 -> 0), an initial slip lasts more turns of the plane, and the spiral's growth "
            "per turn rises towards its supremum e^(2 pi)."
            if ok
            else "The dimensional and dimensionless solutions disagree, or a faster plane does "
            "not mean more slip."
        ),
        quantities={
            "ball_radius": Quantity("the example ball's radius R (m)"),
            "ball_mass": Quantity(
                "the example ball's mass 4/3 pi R^3 rho (kg)",
                at={"R": radius, "rho": p["ball_density"]},
            ),
            "friction_viscous": Quantity("the example ball's mu0_dim (N s/m), illustrative"),
            "turntable_rpm": Quantity("the plane's rates (revolutions per minute)"),
            "mu0": Quantity(
                "mu0 = mu0_dim / (m Omega), Omega = 2 pi rpm / 60",
                over={"rpm": rpms},
                reduce="each",
            ),
            "persistent_slip": Quantity(
                "|u| / |v| at the end of the dimensional run, after the transient",
                at={"k": k},
                over={"rpm": rpms},
                reduce="each",
            ),
            "persistent_slip_fast_over_slow": Quantity(
                "persistent slip on the fastest plane over that on the slowest", at={"k": k}
            ),
            "scaling_error_rel": Quantity(
                "largest difference of the dimensional and dimensionless solutions, relative to "
                "the largest component",
                at={"k": k},
                over={"rpm": rpms},
                reduce="max",
            ),
        },
    )
