"""Check of Section 3: how the limit of infinite friction is realised, (3.3)."""

from __future__ import annotations

from typing import Any

import numpy as np

import turntable as tt
from turntable import reference as ref
from turntable.claims import _constrained as con
from turntable.claims._core import Outcome, Quantity, Where, all_within, decide, register, sig
from turntable.claims._params import random_states

#: The other maps onto u = 0 that the limit's projector is measured against.
OTHER_MAPS = ("orthogonal projection", "keep (r, v), solve for w", "keep (r, w), solve for v")


def other_maps() -> dict[str, np.ndarray]:
    """Return the maps of `OTHER_MAPS`, each sending every state onto u = 0."""
    import scipy.linalg

    constraint = scipy.linalg.null_space(con.slip_matrix())
    maps = dict(
        zip(
            OTHER_MAPS,
            (
                constraint @ constraint.T,
                con.keep_and_solve(("r", "v"), "w"),
                con.keep_and_solve(("r", "w"), "v"),
            ),
            strict=True,
        )
    )
    for name, m in maps.items():
        if np.abs(con.slip_matrix() @ m).max() > 1e-12:
            raise RuntimeError(f"the map '{name}' does not send states onto u = 0")
    return maps


def _slow_projector(big: np.ndarray, mu: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Return (slow basis, spectral projector onto it, slow eigenvalues) of L.

    The slow invariant subspace holds the eigenvalues with real part above -mu (the kernel
    and lambda_{1,2}); the fast one those below (lambda_{3,4}, real part ~ -2 mu). Both come
    from ordered real Schur forms; the projector is along the fast subspace.
    """
    import scipy.linalg

    t_slow, z_slow, n_slow = scipy.linalg.schur(big, output="real", sort=lambda x, _y: x > -mu)
    _, z_fast, n_fast = scipy.linalg.schur(big, output="real", sort=lambda x, _y: x <= -mu)
    slow, fast = z_slow[:, :n_slow], z_fast[:, :n_fast]
    coords = np.linalg.inv(np.hstack([slow, fast]))[:n_slow]
    return slow, slow @ coords, np.linalg.eigvals(t_slow[:n_slow, :n_slow])


@register(
    "limit.realization",
    where=Where("Sec. 3", "(3.3)"),
    claim=(
        "The nonholonomic constraint of rolling on the rotating plane is realised by viscous "
        "friction with an infinite coefficient."
    ),
    paper_value={
        "text": "constraint realised as mu0 -> infinity (qualitative, after Fufaev 1964 and "
        "Eldering 2016)"
    },
    method=(
        "For every k and the large mu0, split L (rebuilt from the vector equations) into its "
        "slow invariant subspace (kernel and lambda_{1,2}) and its fast one (lambda_{3,4}) by "
        "ordered Schur forms. Fit the order in mu0 of the largest angle between the slow "
        "subspace and the constraint subspace u = 0, of the distance between the spectral "
        "projector along the fast subspace and the map to the no-slip state with the same "
        "position and angular momentum, and of the distance between L on the slow subspace and "
        "the constrained Newton-Euler dynamics; measure how far other maps onto the constraint "
        "and the motion on it without contact force stay, and the growth rate on the slow "
        "subspace (40-digit alpha1). The time-domain convergence itself is limit.convergence."
    ),
    expected="confirmed",
    decisive="dynamics_order",
    gist=(
        "infinite friction realises the constraint: the slipping ball's slow dynamics tends to "
        "the nonholonomic one, from the rolling state with the same position and angular "
        "momentum"
    ),
)
def _realization(p: dict[str, Any]) -> Outcome:
    import scipy.linalg

    mu0s = sorted(p["mu0_limit"])
    slip = con.slip_matrix()
    constraint = scipy.linalg.null_space(slip)
    orders = {"angle": [], "projector": [], "dynamics": []}
    growth_min, pkg_err = np.inf, 0.0
    others_per_k, free_per_k = [], []
    angle_last = proj_last = dyn_last = 0.0
    others = other_maps().values()
    for k in p["k_values"]:
        limit = con.no_slip_projection(k)
        rolling = con.no_slip_matrix(k) @ limit
        for z in random_states(p):
            pkg_err = max(pkg_err, float(np.max(np.abs(tt.no_slip_state(z, k) - limit @ z))))
        errs: dict[str, list[float]] = {name: [] for name in orders}
        for mu0 in mu0s:
            big = ref.matrix_from_equations(mu0, k)
            slow, proj, _ = _slow_projector(big, mu0 * (k + 1.0) / (2.0 * k))
            errs["angle"].append(float(np.sin(scipy.linalg.subspace_angles(slow, constraint)[0])))
            errs["projector"].append(float(np.linalg.norm(proj - limit, 2)))
            errs["dynamics"].append(float(np.linalg.norm(big @ proj - rolling, 2)))
            growth_min = min(growth_min, ref.mp_spectrum(mu0, k).alpha1)  # 40 digits
        for name in orders:
            orders[name].append(ref.log_log_slope(mu0s, errs[name]))
        others_per_k.append(min(float(np.linalg.norm(proj - o, 2)) for o in others))
        free_per_k.append(float(np.linalg.norm(big @ proj - big @ limit, 2)))
        angle_last = max(angle_last, errs["angle"][-1])
        proj_last = max(proj_last, errs["projector"][-1])
        dyn_last = max(dyn_last, errs["dynamics"][-1])
    worst = {name: max(v) for name, v in orders.items()}
    others_min, free_min = min(others_per_k), min(free_per_k)
    growth_k0 = ref.mp_spectrum(mu0s[-1], p["k_paper"]).alpha1
    reproduced = {
        "mu0_limit": mu0s,
        "angle_order": worst["angle"],
        "projector_order": worst["projector"],
        "dynamics_order": worst["dynamics"],
        "angle_at_largest_mu0": angle_last,
        "projector_at_largest_mu0": proj_last,
        "dynamics_at_largest_mu0": dyn_last,
        # at the largest mu0, spectral norms (largest singular value) of 6x6 differences:
        # the other maps onto u = 0 against the projector, the motion on u = 0 without the
        # contact force (L on the no-slip states) against L on the slow subspace
        "other_limits": min(others_min, free_min),
        "other_maps_min": others_min,
        "free_motion_min": free_min,
        "other_maps_per_k": others_per_k,
        "free_motion_per_k": free_per_k,
        "k_values": p["k_values"],
        "package": pkg_err,
        "slow_growth_rate": growth_min,
        "k": p["k_paper"],
        "slow_growth_rate_k_paper_at_largest_mu0": growth_k0,
        "time_domain_claim": "limit.convergence",
    }
    tol: dict[str, Any] = {
        "angle_order": -1.0 + 0.05,
        "projector_order": -1.0 + 0.05,
        "dynamics_order": -1.0 + 0.05,
        "other_limits": {">=": 0.1},
        "package": 1e-12,
    }
    # The paper states the realisation on fixed intervals (its (3.3)); that it is not uniform
    # in time (the slow subspace still grows) is an addition, bounded like the rest.
    tol["slow_growth_rate"] = {">": 0.0}
    verdict = decide(all_within(reproduced, tol))
    evidence = {
        "failed": (
            "The slow dynamics of the slipping ball does not tend to the constrained (no-slip) "
            "dynamics, or the state after the initial layer is not the one with the same "
            "position and angular momentum."
        ),
        "confirmed": (
            "Holds in the sense of a singular limit, on finite time intervals. The slow "
            "invariant subspace of L (kernel and lambda_{1,2}) tends to the constraint "
            f"subspace u = 0 (largest angle ~ mu0^{sig(worst['angle'], 3)}), L on it tends to "
            "the nonholonomic dynamics of the constrained Newton-Euler equations, contact force "
            f"included (~ mu0^{sig(worst['dynamics'], 3)}; the motion on u = 0 without that "
            f"force stays {sig(free_min, 3)} away, the least over every k), and a slipping "
            "initial state is carried along the fast subspace to the no-slip state with the "
            "same position and the same "
            f"angular momentum about the contact point (~ mu0^{sig(worst['projector'], 3)}; the "
            "orthogonal projection and the maps that keep v or w stay at least "
            f"{sig(others_min, 3)} away at mu0 = {sig(mu0s[-1])}, the least over them and every k "
            "tried). So the limit selects the nonholonomic (not a "
            "projected or free) motion, started after an initial layer of width ~1/mu0 from that "
            "state; in time this is limit.convergence: positions uniformly on [0, T], "
            "velocities outside the layer. Added: it is not uniform in time; the slow "
            f"subspace still grows at rate alpha1 > 0 ({sig(growth_k0, 3)} for k = "
            f"{sig(p['k_paper'])} at "
            f"mu0 = {sig(mu0s[-1])}; at least {sig(growth_min, 3)} over every k and mu0 "
            "tried), so the "
            "realisation holds on intervals short compared with 1/alpha1 ~ mu0 (k+1)^3/k^3."
        ),
    }[verdict]
    return Outcome(
        verdict=verdict,
        reproduced=reproduced,
        tolerance=tol,
        summary=(
            f"slow subspace -> u = 0 like mu0^{sig(worst['angle'], 3)}, projector -> no-slip "
            f"state like mu0^{sig(worst['projector'], 3)}, dynamics -> nonholonomic like "
            f"mu0^{sig(worst['dynamics'], 3)} (largest orders over the k tried); slow growth "
            f"rate {sig(growth_k0, 3)} > 0 (k = {sig(p['k_paper'])}, mu0 = {sig(mu0s[-1])}; "
            f"smallest over every k: {sig(growth_min, 3)})"
        ),
        evidence=evidence,
        quantities=_quantities(p, mu0s),
    )


def _quantities(p: dict[str, Any], mu0s: list[float]) -> dict[str, Quantity]:
    norm = "largest singular value of the difference of the 6x6 matrices"
    other = "the limit's projector against the other maps onto u = 0 (" + norm + ")"
    free = "L on the slow subspace against L on the no-slip states, no contact force (" + norm
    return {
        "dynamics_order": Quantity(
            "order in mu0 of |L P - M P_ns|, fitted over mu0 in "
            f"{{{', '.join(f'{m:g}' for m in mu0s)}}}",
            over={"k": p["k_values"]},
            reduce="max",
        ),
        "other_maps_min": Quantity(
            other,
            at={"mu0": mu0s[-1]},
            over={"k": p["k_values"], "map": list(OTHER_MAPS)},
            reduce="min",
        ),
        "other_maps_per_k": Quantity(
            other, at={"mu0": mu0s[-1]}, over={"k": p["k_values"]}, reduce="each"
        ),
        "free_motion_min": Quantity(
            free + ")", at={"mu0": mu0s[-1]}, over={"k": p["k_values"]}, reduce="min"
        ),
        "free_motion_per_k": Quantity(
            free + ")", at={"mu0": mu0s[-1]}, over={"k": p["k_values"]}, reduce="each"
        ),
    }
