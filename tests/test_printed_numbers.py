"""A second route for every number the article prints from results/claims.json.

Each number the article reads (``rep``, ``val``, ``vb``, ``at-k``, ``about`` and ``cmp`` in
paper/paper.typ) has a record of what it is (`turntable.claims.Quantity`: what it measures,
the parameters held fixed, the set it is reduced over and how). The routes below recompute
each number from that record with code of their own (numpy, scipy, mpmath; the matrix of
the complex equations assembled here), so that a number computed at another parameter than
its record names, reduced the other way, or with a sign flipped, fails its test. A number
at the level of rounding (an error against a reference) is held to its defining property
instead: recomputed here, it is of the same size, below the check's bound.
"""

from __future__ import annotations

import functools
import math
import re
from collections.abc import Callable
from pathlib import Path
from typing import Any

import mpmath
import numpy as np
import pytest
import scipy.integrate
import scipy.linalg
import scipy.optimize

from ci_build import full_config
from turntable import claims

ROOT = Path(__file__).resolve().parents[1]
J = np.array([[0.0, -1.0], [1.0, 0.0]])
I2, O2 = np.eye(2), np.zeros((2, 2))


@functools.cache
def params() -> dict[str, Any]:
    return claims.resolve_params(full_config()["claims"])


@pytest.fixture(scope="session")
def evaluated(computed: Any) -> Callable[[str], dict[str, Any]]:
    """One claim evaluated with the workflow's parameters, once per test run."""
    p = full_config()["claims"]
    return functools.cache(
        lambda cid: computed("claims", [cid], lambda c: claims.evaluate(c, p))[cid]
    )


def printed() -> set[tuple[str, str]]:
    """Every (claim, key) the article reads from results/claims.json."""
    text = (ROOT / "paper" / "paper.typ").read_text()
    pairs = set(re.findall(r'(?:rep|val|vb|at-k|about)\(\s*"([^"]+)",\s*"([^"]+)"', text))
    pairs |= {
        ("comparison.rolling_resistance", key) for key in re.findall(r'cmp\("([^"]+)"\)', text)
    }
    pairs |= {
        ("comparison.rolling_resistance", key) for key in re.findall(r'let x = "([^"]+)"', text)
    }
    if "#decider(id)" in text:  # the appendix: every claim's deciding value
        pairs |= {(c.id, c.decisive) for c in claims.registered()}
    return pairs


# --- the model, assembled here from the complex equations: r' = v,
# v' = mu0 (i r - v - i w), w' = mu0/k (r + i v - w), with i acting as J.
def big(mu0: float, k: float) -> np.ndarray:
    return np.block(
        [[O2, I2, O2], [mu0 * J, -mu0 * I2, -mu0 * J], [mu0 / k * I2, mu0 / k * J, -mu0 / k * I2]]
    )


def slip(z: np.ndarray) -> np.ndarray:
    """u = v + J w - J r."""
    return z[..., 2:4] + z[..., 4:6] @ J.T - z[..., 0:2] @ J.T


def mp_big(mu0: float, k: float) -> mpmath.matrix:
    """L at the working precision, from the exact mu0 and k."""
    m, kp = mpmath.mpf(mu0), mpmath.mpf(k)
    rows = big(1.0, 1.0)  # the pattern: which entries carry mu0 and mu0/k
    out = mpmath.matrix(6, 6)
    for i in range(6):
        for j in range(6):
            scale = 1 if i < 2 else (m if i < 4 else m / kp)
            out[i, j] = rows[i, j] * scale
    return out


@functools.cache
def mp_roots(mu0: float, k: float) -> tuple[complex, ...]:
    """The four nonzero eigenvalues of L at 40 digits, by real part, largest first."""
    with mpmath.workdps(40):
        ev = mpmath.eig(mp_big(mu0, k), left=False, right=False)
        nonzero = sorted((e for e in ev if abs(e) > mpmath.mpf(10) ** -20), key=lambda e: -e.real)
        return tuple(complex(e) for e in nonzero)


def rates(mu0: float, k: float) -> tuple[float, float, float]:
    """(alpha1, alpha2, beta) from the eigenvalues."""
    r = mp_roots(mu0, k)
    return r[0].real, r[-1].real, abs(r[0].imag)


def rates_double(mu0: float, k: float) -> tuple[float, float, float]:
    """`rates` from numpy's eigenvalues of L (the two of least modulus are its double zero):
    to 1e-12 where mu0 is of order one, fast enough for a search over mu0."""
    ev = np.linalg.eigvals(big(mu0, k))
    r = sorted(ev[np.argsort(np.abs(ev))[2:]], key=lambda e: -e.real)
    return r[0].real, r[-1].real, abs(r[0].imag)


def random_states(p: dict[str, Any]) -> np.ndarray:
    """The draw the article states: uniform on [-1, 1], |vx| moved to [0.25, 1]."""
    z = np.random.default_rng(p["seed"]).uniform(-1.0, 1.0, size=(p["n_states"], 6))
    z[:, 2] = np.sign(z[:, 2]) * 0.25 + 0.75 * z[:, 2]
    return z


def no_slip_state(z: np.ndarray, k: float) -> np.ndarray:
    """Same r, same c = v - i k w, u = 0: w' = (r + i c)/(k+1), v' = i (r - w')."""
    r, v, w = (complex(z[i], z[i + 1]) for i in (0, 2, 4))
    c = v - 1j * k * w
    w2 = (r + 1j * c) / (k + 1)
    v2 = 1j * (r - w2)
    return np.array([r.real, r.imag, v2.real, v2.imag, w2.real, w2.imag])


def reduce(values: list[float], how: str) -> Any:
    return {"min": min, "max": max, "each": list, "set": lambda v: sorted(set(v))}[how](values)


def over(q: dict[str, Any], name: str) -> list[Any]:
    return list(q["over"][name])


# --- the routes: route(record of the quantity, params) -> the number.
ROUTES: dict[tuple[str, str], Callable[[dict[str, Any], dict[str, Any]], Any]] = {}
#: Relative tolerance of each route's agreement (default 1e-6).
RTOL: dict[tuple[str, str], float] = {}
#: Absolute tolerance where a number is read off a grid (default 0).
ATOL: dict[tuple[str, str], float] = {
    ("solution.fast_transient", key): 2e-3
    for key in (
        "last_time_above_threshold_fig3_periods_k_paper",
        "last_time_above_threshold_fig3_periods",
        "last_time_above_threshold_generic_periods",
    )
}
#: Numbers at the level of rounding: (route's bound, factor within which both agree).
RESIDUAL: dict[tuple[str, str], float] = {}


def route(cid: str, key: str, rtol: float = 1e-6) -> Callable:
    def wrap(fn: Callable) -> Callable:
        ROUTES[(cid, key)] = fn
        RTOL[(cid, key)] = rtol
        return fn

    return wrap


def parameter(cid: str, key: str, name: str, pick: Callable = lambda x: x) -> None:
    """A number that is a configured parameter, printed as such."""
    ROUTES[(cid, key)] = lambda q, p: pick(p[name])
    RTOL[(cid, key)] = 1e-11  # the report keeps 12 significant digits


parameter("model.scaling", "ball_radius", "ball_radius")
parameter("model.scaling", "friction_viscous", "friction_viscous")
parameter("model.scaling", "turntable_rpm", "turntable_rpm", sorted)
parameter("comparison.rolling_resistance", "k", "k_paper")
parameter("comparison.rolling_resistance", "much_faster_factor", "much_faster_factor")
parameter("limit.convergence", "t_end", "t_limit")


@route("spectrum.kernel", "dimensional_ball")
def _ball(q: dict[str, Any], p: dict[str, Any]) -> list[float]:
    d = claims.DEFAULT_PARAMS
    return [d["ball_radius"], d["turntable_rpm"][0], 2 * math.pi * d["turntable_rpm"][0] / 60]


@route("solution.fast_transient", "threshold")
def _threshold(q: dict[str, Any], p: dict[str, Any]) -> float:
    return 0.01


@route("solution.fast_transient", "near_decaying_initial_ratio")
def _near_ratio(q: dict[str, Any], p: dict[str, Any]) -> float:
    return 1e9


@route("intro.no_slip_motion", "orbital_rate", rtol=1e-6)
def _orbital_rate(q: dict[str, Any], p: dict[str, Any]) -> float:
    """beta at a very large mu0: the rolling ball's rate."""
    return rates(1e7, q["at"]["k"])[2]


@route("intro.no_slip_motion", "spin_vector", rtol=1e-3)
def _spin_vector(q: dict[str, Any], p: dict[str, Any]) -> float:
    """Rolling, w = r_c + (r - r_c)/(k+1) on a circle of radius rho about r_c: over two turns
    w changes by 2 rho/(k+1) at most, and |w| is at most |r_c| + rho/(k+1)."""
    values = []
    states = [np.asarray(p["state_fig4"]), *random_states(p)]
    for k in over(q, "k"):
        lam = k / (k + 1)
        for z in states:
            z = no_slip_state(z, k)
            r0, v0 = complex(z[0], z[1]), complex(z[2], z[3])
            rc, rho = r0 + 1j * v0 / lam, abs(v0) / lam
            values.append((2 * rho / (k + 1)) / (abs(rc) + rho / (k + 1)))
    return reduce(values, q["reduce"])


def _ball_mass(p: dict[str, Any]) -> float:
    return 4 / 3 * math.pi * p["ball_radius"] ** 3 * p["ball_density"]


@route("model.scaling", "ball_mass")
def _mass(q: dict[str, Any], p: dict[str, Any]) -> float:
    return 4 / 3 * math.pi * q["at"]["R"] ** 3 * q["at"]["rho"]


@route("model.scaling", "mu0")
def _mu0(q: dict[str, Any], p: dict[str, Any]) -> list[float]:
    return [p["friction_viscous"] / (_ball_mass(p) * 2 * math.pi * r / 60) for r in over(q, "rpm")]


def _persistent_slip(mu0: float, k: float) -> float:
    """|u|/|v| on the growing eigenvector of L."""
    w, vecs = np.linalg.eig(big(mu0, k))
    z = vecs[:, np.argmax(w.real)]
    u = z[2:4] + J @ z[4:6] - J @ z[0:2]
    return float(np.linalg.norm(u) / np.linalg.norm(z[2:4]))


@route("model.scaling", "persistent_slip", rtol=1e-4)
def _slip(q: dict[str, Any], p: dict[str, Any]) -> list[float]:
    return [_persistent_slip(m, q["at"]["k"]) for m in _mu0(q, p)]


@route("model.scaling", "persistent_slip_fast_over_slow", rtol=1e-4)
def _slip_ratio(q: dict[str, Any], p: dict[str, Any]) -> float:
    rpm = sorted(p["turntable_rpm"])
    mu0 = _mu0({"over": {"rpm": [rpm[0], rpm[-1]]}}, p)
    return _persistent_slip(mu0[1], q["at"]["k"]) / _persistent_slip(mu0[0], q["at"]["k"])


@route("spectrum.alpha1_peak", "mu0_peak", rtol=1e-6)
@route("trajectory.untwisting_slows", "mu0_peak", rtol=1e-6)
def _mu0_peak(q: dict[str, Any], p: dict[str, Any]) -> float:
    """The maximiser of the largest real part of the eigenvalues of L."""
    k = q["at"]["k"]
    res = scipy.optimize.minimize_scalar(
        lambda x: -np.linalg.eigvals(big(math.exp(x), k)).real.max(),
        bounds=(math.log(1e-4), math.log(10.0)),
        method="bounded",
        options={"xatol": 1e-12},
    )
    return math.exp(res.x)


@route("spectrum.alpha1_peak", "alpha1_max", rtol=1e-9)
def _alpha1_max(q: dict[str, Any], p: dict[str, Any]) -> float:
    return rates(_mu0_peak(q, p), q["at"]["k"])[0]


@route("trajectory.untwisting_slows", "alpha1_around_peak_k_paper", rtol=1e-9)
def _around(q: dict[str, Any], p: dict[str, Any]) -> list[float]:
    k = q["at"]["k"]
    m = _mu0_peak(q, p)
    return [rates(m / 2, k)[0], rates(m, k)[0], rates(2 * m, k)[0]]


@route("trajectory.untwisting_slows", "min_alpha1_rise_to_peak", rtol=1e-6)
def _rise(q: dict[str, Any], p: dict[str, Any]) -> float:
    values = []
    for k in over(q, "k"):
        below, top, _ = _around({"at": {"k": k}}, p)
        values.append(1 - below / top)
    return reduce(values, q["reduce"])


def _grid(p: dict[str, Any]) -> np.ndarray:
    lo, hi = p["mu0_range"]
    return np.logspace(math.log10(lo), math.log10(hi), p["n_points"])


@route("spectrum.unstable_focus", "max_alpha2", rtol=1e-8)
def _max_alpha2(q: dict[str, Any], p: dict[str, Any]) -> float:
    """alpha2, the most negative real part of the eigenvalues of L, at every grid point."""
    values = []
    for k in over(q, "k"):
        for m in _grid(p):
            values.append(min(e.real for e in np.linalg.eigvals(big(m, k)) if abs(e) > 1e-9 * m))
    return reduce(values, q["reduce"])


@route("solution.damping_ratio", "exp_2pi", rtol=1e-12)
def _exp_2pi(q: dict[str, Any], p: dict[str, Any]) -> float:
    return float(mpmath.exp(2 * mpmath.pi))


def _ln_n(mu0: float, k: float) -> float:
    _, a2, b = rates(mu0, k)
    return 2 * math.pi * abs(a2) / b


@route("solution.damping_ratio", "n_at_mu0_small_last", rtol=1e-9)
def _n_small(q: dict[str, Any], p: dict[str, Any]) -> float:
    return math.exp(_ln_n(q["at"]["mu0"], q["at"]["k"]))


@route("solution.damping_ratio", "log10_n_at_reference_mu0", rtol=1e-9)
def _log10_n(q: dict[str, Any], p: dict[str, Any]) -> list[float]:
    return [_ln_n(m, q["at"]["k"]) / math.log(10) for m in over(q, "mu0")]


@route("solution.damping_ratio", "min_ratio_alpha2_over_beta", rtol=1e-9)
def _min_ratio(q: dict[str, Any], p: dict[str, Any]) -> float:
    """|alpha2|/beta falls towards 1 as mu0 -> 0: its least is at the smallest mu0."""
    small = [m for m in over(q, "mu0") if not isinstance(m, str)]
    values = [_ln_n(m, k) / (2 * math.pi) for k in over(q, "k") for m in small]
    return reduce(values, q["reduce"])


def _modal(z0: np.ndarray, t: np.ndarray, mu0: float, k: float) -> tuple[np.ndarray, np.ndarray]:
    """(z+, z-) by spectral projection with the eigenvectors of L."""
    w, vecs = np.linalg.eig(big(mu0, k))
    coeff = np.linalg.solve(vecs, z0.astype(complex))
    grow = w.real > 1e-12 * mu0
    decay = w.real < -1e-12 * mu0 - 1e-300
    decay &= np.abs(w) > 1e-9 * mu0
    parts = []
    for mask in (grow, decay):
        zt = (vecs[:, mask] * coeff[mask]) @ np.exp(np.outer(w[mask], t))
        parts.append(zt.real.T)
    return parts[0], parts[1]


def _last_above(z0: np.ndarray, mu0: float, k: float, periods: float) -> float:
    beta = rates(mu0, k)[2]
    period = 2 * math.pi / beta
    t = np.linspace(0.0, periods * period, int(1000 * periods) + 1)
    plus, minus = _modal(z0, t, mu0, k)
    late = np.nonzero(np.linalg.norm(minus, axis=1) > 0.01 * np.linalg.norm(plus, axis=1))[0]
    return float(t[late[-1]] / period) if late.size else 0.0


@route("solution.fast_transient", "last_time_above_threshold_fig3_periods_k_paper", rtol=5e-3)
def _fig3_k(q: dict[str, Any], p: dict[str, Any]) -> list[float]:
    z = np.asarray(p["state_fig3"])
    return [_last_above(z, m, q["at"]["k"], 2.0) for m in over(q, "mu0")]


@route("solution.fast_transient", "last_time_above_threshold_fig3_periods", rtol=5e-3)
def _fig3(q: dict[str, Any], p: dict[str, Any]) -> float:
    z = np.asarray(p["state_fig3"])
    values = [_last_above(z, m, k, 2.0) for k in over(q, "k") for m in over(q, "mu0")]
    return reduce(values, q["reduce"])


@route("solution.fast_transient", "last_time_above_threshold_generic_periods", rtol=5e-3)
def _generic(q: dict[str, Any], p: dict[str, Any]) -> float:
    values = [
        _last_above(z, m, k, 2.0)
        for k in over(q, "k")
        for m in over(q, "mu0")
        for z in random_states(p)
    ]
    return reduce(values, q["reduce"])


@route("solution.fast_transient", "last_time_above_threshold_near_decaying_periods", rtol=0.3)
def _near(q: dict[str, Any], p: dict[str, Any]) -> float:
    """The prediction ln(rho / theta) / (2 pi (alpha1 + |alpha2|)/beta), rho = 1e9."""
    values = []
    for k in over(q, "k"):
        for m in over(q, "mu0"):
            a1, a2, b = rates(m, k)
            values.append(math.log(1e9 / 0.01) / (2 * math.pi * (a1 - a2) / b))
    return reduce(values, q["reduce"])


@route("solution.centre", "min_minus_sign_error", rtol=1e-9)
def _minus(q: dict[str, Any], p: dict[str, Any]) -> float:
    """The printed sign is off by 2 |vx(0)|/k in y0 (the conserved k wy + vx fixes y0)."""
    values = [2 * abs(z[2]) / k for k in over(q, "k") for z in random_states(p)]
    return reduce(values, q["reduce"])


@route("limit.convergence", "initial_slip", rtol=1e-12)
def _initial_slip(q: dict[str, Any], p: dict[str, Any]) -> float:
    return float(np.abs(slip(np.asarray(p["state_fig4"]))).max())


def _jump(k: float, p: dict[str, Any]) -> tuple[float, float]:
    """|dv| = k |u0|/(k+1), |dw| = |u0|/(k+1) across the layer, in the limit."""
    u0 = np.linalg.norm(slip(np.asarray(p["state_fig4"])))
    return k * u0 / (k + 1), u0 / (k + 1)


@route("limit.convergence", "speed_change_across_layer_k_paper", rtol=2e-3)
def _speed(q: dict[str, Any], p: dict[str, Any]) -> list[float]:
    """The jump at each mu0: the slipping solution after the layer, layer_decay_times/|alpha2|."""
    return [_crossed(m, q["at"]["k"], p)[0] for m in over(q, "mu0")]


@route("limit.convergence", "spin_change_across_layer_k_paper", rtol=2e-3)
def _spin(q: dict[str, Any], p: dict[str, Any]) -> list[float]:
    return [_crossed(m, q["at"]["k"], p)[1] for m in over(q, "mu0")]


def _crossed(mu0: float, k: float, p: dict[str, Any]) -> tuple[float, float]:
    z0 = np.asarray(p["state_fig4"])
    t = p["layer_decay_times"] / abs(rates(mu0, k)[1])
    z = scipy.linalg.expm(big(mu0, k) * t) @ z0
    d = z[2:] - z0[2:]
    return float(np.hypot(*d[:2])), float(np.hypot(*d[2:]))


def _evolve(z0: np.ndarray, t: np.ndarray, mu0: float, k: float) -> np.ndarray:
    """z(t) = V exp(Lambda t) V^-1 z0, one row per time (the fast modes underflow to 0)."""
    lam, vecs = np.linalg.eig(big(mu0, k))
    coeff = np.linalg.solve(vecs, z0.astype(complex))
    return (vecs @ (coeff[:, None] * np.exp(np.outer(lam, t)))).real.T


def _rolling(z0: np.ndarray, t: float, k: float) -> np.ndarray:
    """The rolling ball from the no-slip state with the same r and c: r(t) on its circle."""
    z = no_slip_state(z0, k)
    lam = k / (k + 1)
    r0, v0 = complex(z[0], z[1]), complex(z[2], z[3])
    return r0 + v0 * (np.exp(1j * lam * t) - 1) / (1j * lam)


@route("limit.convergence", "min_position_error_at_t_over_alpha1", rtol=1e-5)
def _far(q: dict[str, Any], p: dict[str, Any]) -> float:
    z0 = np.asarray(p["state_fig4"])
    values = []
    for k in over(q, "k"):
        for m in over(q, "mu0"):
            with mpmath.workdps(40):
                ev, vecs = mpmath.eig(mp_big(m, k))
                t = 1 / max(e.real for e in ev)
                coeff = mpmath.lu_solve(vecs, mpmath.matrix(z0.tolist()))
                z = sum((vecs[:, j] * coeff[j] * mpmath.exp(ev[j] * t) for j in range(6)),
                        mpmath.matrix(6, 1))  # fmt: skip
                lam = mpmath.mpf(k) / (k + 1)
                zn = [mpmath.mpf(x) for x in no_slip_state(z0, k)]
                r0, v0 = mpmath.mpc(zn[0], zn[1]), mpmath.mpc(zn[2], zn[3])
                rolling = r0 + v0 * (mpmath.exp(1j * lam * t) - 1) / (1j * lam)
                values.append(float(abs(mpmath.mpc(z[0].real, z[1].real) - rolling)))
    return reduce(values, q["reduce"])


@route("limit.convergence", "position_order_k_paper", rtol=2e-3)
def _position_order(q: dict[str, Any], p: dict[str, Any]) -> float:
    z0, k = np.asarray(p["state_fig4"]), q["at"]["k"]
    mu0s = sorted(p["mu0_limit"])
    t = np.linspace(0.0, p["t_limit"], 2001)
    err = []
    for m in mu0s:
        z = _evolve(z0, t, m, k).T
        err.append(np.abs(z[0] + 1j * z[1] - _rolling(z0, t, k)).max())
    return float(np.polyfit(np.log(mu0s), np.log(err), 1)[0])


def _expansion_order(name: str, k: float, mu0s: list[float]) -> float:
    kk = k / (k + 1)
    err = []
    for m in mu0s:
        a1, _, b = rates(m, k)
        err.append(abs(a1 - kk**3 / m) if name == "alpha1" else abs(b - kk))
    return float(np.polyfit(np.log(mu0s), np.log(err), 1)[0])


@route("limit.expansion", "remainder_order_alpha1", rtol=1e-3)
def _order_a1(q: dict[str, Any], p: dict[str, Any]) -> float:
    mu0s = sorted(p["mu0_limit"])
    return reduce([_expansion_order("alpha1", k, mu0s) for k in over(q, "k")], q["reduce"])


@route("limit.expansion", "remainder_order_beta", rtol=1e-3)
def _order_beta(q: dict[str, Any], p: dict[str, Any]) -> float:
    mu0s = sorted(p["mu0_limit"])
    return reduce([_expansion_order("beta", k, mu0s) for k in over(q, "k")], q["reduce"])


# --- infinite friction: the limit's map, the other maps onto u = 0, the slow subspace.
def _limit_map(k: float) -> np.ndarray:
    return np.column_stack([no_slip_state(e, k) for e in np.eye(6)])


def _slip_matrix() -> np.ndarray:
    return np.column_stack([slip(e) for e in np.eye(6)])


def _other_maps() -> list[np.ndarray]:
    """Orthogonal projection onto u = 0; keep (r, v), w = r + J v; keep (r, w), v = J r - J w."""
    basis = scipy.linalg.null_space(_slip_matrix())
    keep_rv = np.block([[I2, O2, O2], [O2, I2, O2], [I2, J, O2]])
    keep_rw = np.block([[I2, O2, O2], [J, O2, -J], [O2, O2, I2]])
    return [basis @ basis.T, keep_rv, keep_rw]


def _slow_projector(mu0: float, k: float) -> np.ndarray:
    """The spectral projector on the kernel and lambda_{1,2} along lambda_{3,4}."""
    lam, vecs = np.linalg.eig(big(mu0, k))
    keep = lam.real > -mu0 * (k + 1) / (2 * k)
    return (vecs[:, keep] @ np.linalg.inv(vecs)[keep]).real


def _rolling_matrix(k: float) -> np.ndarray:
    """The no-slip dynamics on u = 0: r' = v, (k+1) v' = k J v, w = r + J v."""
    lam = k / (k + 1)
    return np.block([[O2, I2, O2], [O2, lam * J, O2], [O2, I2 + lam * J @ J, O2]])


@route("limit.realization", "other_maps_per_k", rtol=1e-6)
def _others_per_k(q: dict[str, Any], p: dict[str, Any]) -> list[float]:
    m = q["at"]["mu0"]
    return [
        min(np.linalg.norm(_slow_projector(m, k) - o, 2) for o in _other_maps())
        for k in over(q, "k")
    ]


@route("limit.realization", "other_maps_min", rtol=1e-6)
def _others_min(q: dict[str, Any], p: dict[str, Any]) -> float:
    return reduce(_others_per_k(q, p), q["reduce"])


@route("limit.realization", "free_motion_per_k", rtol=1e-6)
def _free_per_k(q: dict[str, Any], p: dict[str, Any]) -> list[float]:
    m = q["at"]["mu0"]
    return [
        np.linalg.norm(big(m, k) @ (_slow_projector(m, k) - _limit_map(k)), 2) for k in over(q, "k")
    ]


@route("limit.realization", "free_motion_min", rtol=1e-6)
def _free_min(q: dict[str, Any], p: dict[str, Any]) -> float:
    return reduce(_free_per_k(q, p), q["reduce"])


@route("limit.realization", "dynamics_order", rtol=2e-3)
def _dynamics_order(q: dict[str, Any], p: dict[str, Any]) -> float:
    mu0s = sorted(p["mu0_limit"])
    orders = []
    for k in over(q, "k"):
        rolling = _rolling_matrix(k) @ _limit_map(k)
        err = [np.linalg.norm(big(m, k) @ _slow_projector(m, k) - rolling, 2) for m in mu0s]
        orders.append(float(np.polyfit(np.log(mu0s), np.log(err), 1)[0]))
    return reduce(orders, q["reduce"])


# --- the rolling ball with a resisting moment: (k+1) v' = (i k - delta) v + i delta r.
def _rolling_rates(delta: float, k: float) -> tuple[float, float]:
    """(growth rate, angular rate) of the growing root of (k+1) s^2 - (ik - delta) s - i delta."""
    s = np.roots([k + 1, -(1j * k - delta), -1j * delta])
    g = s[np.argmax(s.real)]
    return g.real, abs(g.imag)


def _equal_power_delta(mu0: float, k: float, rates: Callable = rates) -> float:
    a1, _, b = rates(mu0, k)
    lam = complex(a1, b)
    return mu0 * abs((k + 1) * lam - 1j * k) ** 2 / (k**2 * abs(1 + 1j * lam) ** 2)


def _ratio(mu0: float, k: float, basis: str, measure: str, rates: Callable = rates) -> float:
    a1, _, b = rates(mu0, k)
    delta = _equal_power_delta(mu0, k, rates) if basis == "equal_power" else mu0
    sg, ng = _rolling_rates(delta, k)
    return a1 / b / (sg / ng) if measure == "per_turn" else a1 / sg


@route("comparison.rolling_resistance", "centre_drift_over_growth", rtol=1e-3)
def _drift(q: dict[str, Any], p: dict[str, Any]) -> float:
    """The rolling centre's decay rate over the radius's growth rate, small delta."""
    k, delta = q["at"]["k"], 1e-6
    s = np.roots([k + 1, -(1j * k - delta), -1j * delta])
    return abs(s[np.argmin(np.abs(s))].real) / s[np.argmax(s.real)].real


@route("comparison.rolling_resistance", "mu0_example_ball")
def _example(q: dict[str, Any], p: dict[str, Any]) -> list[float]:
    return sorted(_mu0({"over": {"rpm": over(q, "rpm")}}, p))


@route("comparison.rolling_resistance", "ratio_range_at_example_ball_equal_power_per_turn", 1e-6)
def _example_ratios(q: dict[str, Any], p: dict[str, Any]) -> list[float]:
    values = [_ratio(m, q["at"]["k"], "equal_power", "per_turn") for m in over(q, "mu0")]
    return [min(values), max(values)]


@route("comparison.rolling_resistance", "ratio_minus_1_times_mu0_squared_equal_power_per_turn")
def _excess(q: dict[str, Any], p: dict[str, Any]) -> float:
    m = q["at"]["mu0"]
    return (_ratio(m, q["at"]["k"], "equal_power", "per_turn") - 1) * m**2


RTOL[("comparison.rolling_resistance", "ratio_minus_1_times_mu0_squared_equal_power_per_turn")] = (
    1e-3
)


for _m in ("per_turn", "per_time"):
    ROUTES[("comparison.rolling_resistance", f"ratio_at_fig3_mu0_equal_power_{_m}")] = (
        lambda q, p, m=_m: [_ratio(mu, q["at"]["k"], "equal_power", m) for mu in over(q, "mu0")]
    )
    RTOL[("comparison.rolling_resistance", f"ratio_at_fig3_mu0_equal_power_{_m}")] = 1e-6


def _crossover(basis: str, measure: str, level: float) -> Callable:
    def fn(q: dict[str, Any], p: dict[str, Any]) -> float:
        k = q["at"]["k"]
        f = lambda x: _ratio(10.0**x, k, basis, measure, rates_double) - level  # noqa: E731
        xs = np.linspace(-4, 4, 33)
        signs = np.sign([f(x) for x in xs])
        i = int(np.nonzero(np.diff(signs))[0][0])
        return 10.0 ** scipy.optimize.brentq(f, xs[i], xs[i + 1], xtol=1e-13)

    return fn


_F = 2.0
for _key, _args in {
    "crossover_factor_equal_power_per_turn": ("equal_power", "per_turn", _F),
    "crossover_factor_equal_power_per_time": ("equal_power", "per_time", _F),
    "crossover_inverse_factor_equal_coefficient_per_turn": (
        "equal_coefficient",
        "per_turn",
        1 / _F,
    ),
}.items():
    ROUTES[("comparison.rolling_resistance", _key)] = _crossover(*_args)
    RTOL[("comparison.rolling_resistance", _key)] = 1e-6


# --- numbers at the level of rounding: recomputed here, of the same size, below the bound.
def residual(cid: str, key: str, bound: float) -> Callable:
    def wrap(fn: Callable) -> Callable:
        ROUTES[(cid, key)] = fn
        RESIDUAL[(cid, key)] = bound
        return fn

    return wrap


@residual("intro.no_slip_motion", "rate", 1e-9)
def _rate_residual(q: dict[str, Any], p: dict[str, Any]) -> float:
    values = []
    for k in over(q, "k"):
        t = np.linspace(0, 4 * math.pi * (k + 1) / k, 401)
        for z in [np.asarray(p["state_fig4"]), *random_states(p)]:
            zn = no_slip_state(z, k)
            zt = np.array([scipy.linalg.expm(_rolling_matrix(k) * ti) @ zn for ti in t])
            r0, v0 = complex(zn[0], zn[1]), complex(zn[2], zn[3])
            rho = zt[:, 0] + 1j * zt[:, 1] - (r0 + 1j * v0 * (k + 1) / k)
            v = zt[:, 2] + 1j * zt[:, 3]
            values.append(float(np.max(np.abs((v / (1j * rho)).real / (k / (k + 1)) - 1))))
    return reduce(values, q["reduce"])


@residual("spectrum.unstable_focus", "decaying_subspace_vs_exp_alpha2_t_rel", 1e-10)
def _decaying(q: dict[str, Any], p: dict[str, Any]) -> float:
    """The decaying part of the first random state, evolved at 40 digits until exp(alpha2 t)
    is 1e-6: its distance over the initial one, against 1e-6."""
    z0 = random_states(p)[0]
    err = 0.0
    for k in over(q, "k"):
        for m in over(q, "mu0"):
            with mpmath.workdps(40):
                ev, vecs = mpmath.eig(mp_big(m, k))
                coeff = mpmath.lu_solve(vecs, mpmath.matrix(z0.tolist()))
                keep = [j for j in range(6) if ev[j].real < -(mpmath.mpf(10) ** -20) * m]
                a2 = ev[keep[0]].real
                t = mpmath.log(10**6) / abs(a2)
                start = sum((vecs[:, j] * coeff[j] for j in keep), mpmath.matrix(6, 1))
                later = sum(
                    (vecs[:, j] * coeff[j] * mpmath.exp(ev[j] * t) for j in keep),
                    mpmath.matrix(6, 1),
                )
                ratio = mpmath.norm(later.apply(mpmath.re)) / mpmath.norm(start.apply(mpmath.re))
                err = max(err, float(abs(ratio / mpmath.mpf("1e-6") - 1)))
    return err


@residual("solution.decomposition", "max_one_period_error_rel", 1e-10)
def _one_period(q: dict[str, Any], p: dict[str, Any]) -> float:
    """The package's z+ and z- one period later against exp(alpha T) times themselves."""
    import turntable as tt

    err = 0.0
    for k in over(q, "k"):
        for m in over(q, "mu0"):
            a1, a2, b = rates(m, k)
            period = 2 * math.pi / b
            t = np.linspace(0.0, 2 * period, 13)
            for z0 in [np.asarray(p["state_fig3"]), *random_states(p)]:
                now, later = tt.modal_terms(z0, t, m, k), tt.modal_terms(z0, t + period, m, k)
                for part, shifted, alpha in (
                    (now.plus, later.plus, a1),
                    (now.minus, later.minus, a2),
                ):
                    want = part * math.exp(alpha * period)
                    if np.abs(want).max() > 1e-250:
                        err = max(err, float(np.abs(shifted - want).max() / np.abs(want).max()))
    return err


@residual("solution.centre", "max_plus_sign_error", 1e-10)
def _plus(q: dict[str, Any], p: dict[str, Any]) -> float:
    """(2.8) with the plus sign against the projection on the kernel along the range of L
    (the spectral projector of the zero eigenvalue, from the eigenvectors)."""
    err = 0.0
    for k in over(q, "k"):
        for z0 in [np.asarray(p["state_fig4"]), np.asarray(p["state_fig3"]), *random_states(p)]:
            plus = np.array([(k * z0[4] - z0[3]) / k, (k * z0[5] + z0[2]) / k])
            for m in p["mu0_reference"]:
                lam, vecs = np.linalg.eig(big(m, k))
                zero = np.abs(lam) < 1e-9 * m
                proj = (vecs[:, zero] @ np.linalg.inv(vecs)[zero] @ z0).real
                err = max(err, float(np.abs(plus - proj[:2]).max()))
    return err


@residual("spectrum.roots", "max_package_error_rel", 1e-13)
def _package_roots(q: dict[str, Any], p: dict[str, Any]) -> float:
    """The package's alpha1, alpha2, beta against the 40-digit eigenvalues found here."""
    import turntable as tt

    err = 0.0
    for k in over(q, "k"):
        for m in over(q, "mu0"):
            s = tt.spectrum(m, k)
            for got, want in zip((s.alpha1, s.alpha2, s.beta), rates(m, k), strict=True):
                err = max(err, abs(float(got) / want - 1))
    return err


def _dimensional(p: dict[str, Any], k: float, radius: float, mass: float, omega: float):
    """The SI matrix of r' = v, m v' = -F u, I w' = F R gamma x u, u = v + R gamma x w -
    Omega gamma x r (F = mu0_dim), assembled here."""
    f, inertia = p["friction_viscous"], k * mass * radius**2
    slip_si = np.hstack([-omega * J, I2, radius * J])
    top = np.hstack([O2, I2, O2])
    return np.vstack([top, -f / mass * slip_si, f * radius / inertia * J @ slip_si])


@residual("model.scaling", "scaling_error_rel", 1e-9)
def _scaling(q: dict[str, Any], p: dict[str, Any]) -> float:
    """The SI solution against the dimensionless one at mu0 = mu0_dim/(m Omega), at the end
    of twenty turns, relative to its largest component."""
    mass, radius, k = _ball_mass(p), p["ball_radius"], q["at"]["k"]
    z_si = np.asarray(p["state_si"])
    err = 0.0
    for rpm in over(q, "rpm"):
        omega = 2 * math.pi * rpm / 60
        units = np.array([radius, radius, radius * omega, radius * omega, omega, omega])
        t = 2 * math.pi * 20 / omega
        z_dim = scipy.linalg.expm(_dimensional(p, k, radius, mass, omega) * t) @ z_si / units
        mu0 = p["friction_viscous"] / (mass * omega)
        z = scipy.linalg.expm(big(mu0, k) * omega * t) @ (z_si / units)
        err = max(err, float(np.abs(z - z_dim).max() / np.abs(z_dim).max()))
    return err


@residual("spectrum.kernel", "max_spin_vs_omega_over_r_error_rel", 1e-12)
def _spin_at_rest(q: dict[str, Any], p: dict[str, Any]) -> float:
    """The spin w = S r at which a ball at rest at r stays there, from the SI equations."""
    d = claims.DEFAULT_PARAMS
    radius, rpm = d["ball_radius"], d["turntable_rpm"][0]
    mass, omega = 4 / 3 * math.pi * radius**3 * d["ball_density"], 2 * math.pi * rpm / 60
    err = 0.0
    for k in over(q, "k"):
        mat = _dimensional(d, k, radius, mass, omega)
        spin = -np.linalg.lstsq(mat[:, 4:], mat[:, :2], rcond=None)[0]
        err = max(err, float(np.abs(spin * radius / omega - I2).max()))
    return err


@residual("trajectory.spiral", "max_growth_rate_error_rel", 1e-6)
def _spiral(q: dict[str, Any], p: dict[str, Any]) -> float:
    """The growth rate fitted to ln |r - r0| over turns 2 to 5, against alpha1."""
    z0 = np.asarray(p["state_fig4"])
    err = 0.0
    for k in over(q, "k"):
        for m in over(q, "mu0"):
            a1, _, b = rates(m, k)
            t = np.linspace(4 * math.pi / b, 10 * math.pi / b, 301)
            z = _evolve(z0, t, m, k)
            r0 = np.array([(k * z0[4] - z0[3]) / k, (k * z0[5] + z0[2]) / k])
            rate = np.polyfit(t, np.log(np.hypot(z[:, 0] - r0[0], z[:, 1] - r0[1])), 1)[0]
            err = max(err, abs(rate / a1 - 1))
    return err


@residual("model.reduction", "max_state_error_rel", 1e-7)
def _reduction(q: dict[str, Any], p: dict[str, Any]) -> float:
    """The nine equations (r, v, w in three dimensions, contact force from the slip, the
    normal force balancing gravity) integrated here with DOP853, against exp(L t) z0."""
    z0, g = random_states(p)[0], np.array([0.0, 0.0, 1.0])
    mu0, t_end = q["at"]["mu0"], q["at"]["T"]
    err = 0.0
    for k in over(q, "k"):

        def rhs(_t: float, y: np.ndarray, k: float = k) -> np.ndarray:
            r, v, w = y[0:3], y[3:6], y[6:9]
            u = v + np.cross(g, w) - np.cross(g, r)
            force = -mu0 * u
            return np.r_[v, force, np.cross(-g, force) / k]

        y0 = np.r_[z0[0:2], 0.0, z0[2:4], 0.0, z0[4:6], 0.7]
        t = np.linspace(0.0, t_end, 9)
        sol = scipy.integrate.solve_ivp(rhs, (0, t_end), y0, "DOP853", t, rtol=1e-12, atol=1e-12)
        planar = sol.y[[0, 1, 3, 4, 6, 7]].T
        exact = np.array([scipy.linalg.expm(big(mu0, k) * ti) @ z0 for ti in t])
        err = max(err, float(np.abs(planar - exact).max() / np.abs(exact).max()))
    return err


@route("spectrum.char_poly", "symbolic_residual")
def _char_poly(q: dict[str, Any], p: dict[str, Any]) -> str:
    """det(lambda - L) of the matrix assembled here, symbolically, minus lambda^2 mu^4 P4."""
    import sympy as sp

    lam, m, k = sp.symbols("lambda mu0 k", positive=True)
    pattern = big(1.0, 1.0).astype(int)
    scale = [1, 1, m, m, m / k, m / k]
    mat = sp.Matrix(6, 6, lambda i, j: pattern[i, j] * scale[i])
    mu, eps = m * (k + 1) / (2 * k), 4 * k**2 / (m * (k + 1) ** 2)
    x = lam / mu
    p4 = x**4 + 4 * x**3 + 4 * x**2 + eps**2
    return str(sp.simplify((lam * sp.eye(6) - mat).det() - lam**2 * mu**4 * p4))


@route("spectrum.kernel", "ranks")
def _ranks(q: dict[str, Any], p: dict[str, Any]) -> list[int]:
    ranks = [np.linalg.matrix_rank(big(m, k)) for k in over(q, "k") for m in over(q, "mu0")]
    return reduce([int(r) for r in ranks], q["reduce"])


@route("limit.frequency", "beta_error_order", rtol=1e-3)
def _beta_order(q: dict[str, Any], p: dict[str, Any]) -> float:
    return _order_beta(q, p)


@route("limit.convergence", "min_velocity_change_across_layer", rtol=1e-6)
def _layer(q: dict[str, Any], p: dict[str, Any]) -> float:
    values = [float(np.hypot(*_crossed(m, k, p))) for k in over(q, "k") for m in over(q, "mu0")]
    return reduce(values, q["reduce"])


@residual("model.rubber_ball", "max_planar_difference_rel", 1e-8)
def _rubber(q: dict[str, Any], p: dict[str, Any]) -> float:
    """The planar right-hand side of the 3-D equations with w_z and without: u involves
    gamma x w, which has no w_z, so they are equal."""
    g = np.array([0.0, 0.0, 1.0])
    z = random_states(p)[0]
    rhs = []
    for wz in (0.0, 3.0):
        w = np.array([z[4], z[5], wz])
        u = np.r_[z[2:4], 0.0] + np.cross(g, w) - np.cross(g, np.r_[z[0:2], 0.0])
        rhs.append(np.r_[-u, np.cross(g, u)])
    return float(np.abs(rhs[0] - rhs[1]).max())


@residual("spectrum.alpha1_peak", "max_location_error_rel", 1e-5)
def _location(q: dict[str, Any], p: dict[str, Any]) -> float:
    """mu0* = 2 k^2 / ((k+1)^2 phi^(3/2)) against the maximiser found here."""
    phi = (1 + math.sqrt(5)) / 2
    return max(
        abs(2 * k**2 / ((k + 1) ** 2 * phi**1.5) / _mu0_peak({"at": {"k": k}}, p) - 1)
        for k in over(q, "k")
    )


@residual("spectrum.growth_decay_identity", "max_identity_error_high_precision", 1e-20)
def _identity(q: dict[str, Any], p: dict[str, Any]) -> float:
    err = 0.0
    for k in over(q, "k"):
        for m in over(q, "mu0"):
            with mpmath.workdps(40):
                ev = sorted(mpmath.eig(mp_big(m, k), left=False, right=False), key=lambda e: e.real)
                a2, a1 = ev[0], ev[-1]
                err = max(err, float(abs(a1.real * a2.real / a1.imag**2 + 1)))
    return err


@residual("spectrum.roots", "max_closed_form_error_rel", 1e-20)
def _closed_form(q: dict[str, Any], p: dict[str, Any]) -> float:
    """(2.5) at 40 digits against mpmath's eigenvalues of the matrix assembled here."""
    err = 0.0
    for k in over(q, "k"):
        for m in over(q, "mu0"):
            with mpmath.workdps(40):
                ev = mpmath.eig(mp_big(m, k), left=False, right=False)
                top = max(ev, key=lambda e: e.real)
                kp, mp = mpmath.mpf(k), mpmath.mpf(m)
                mu, eps = mp * (kp + 1) / (2 * kp), 4 * kp**2 / (mp * (kp + 1) ** 2)
                a = mpmath.sqrt((mpmath.sqrt(1 + eps**2) + 1) / 2)
                err = max(err, float(abs(mu * (a - 1) - top.real) / abs(top.real)))
    return err


def test_every_printed_number_has_a_record_and_a_second_route(evaluated: Callable) -> None:
    missing_route = sorted(printed() - set(ROUTES))
    assert not missing_route, f"printed without a second route: {missing_route}"
    no_record = [
        (cid, key) for cid, key in sorted(printed()) if key not in evaluated(cid)["quantities"]
    ]
    assert not no_record, f"printed without a record of what it is: {no_record}"


def _as_list(x: Any) -> list[float]:
    if isinstance(x, dict):
        return [float(v) for v in x.values()]
    return [float(v) for v in np.ravel(x)]


@pytest.mark.parametrize(
    ("cid", "key"), sorted(ROUTES), ids=[f"{c}:{k}" for c, k in sorted(ROUTES)]
)
def test_printed_number_agrees_with_its_second_route(
    cid: str, key: str, evaluated: Callable
) -> None:
    record = evaluated(cid)
    value = record["reproduced"][key]
    q = record["quantities"].get(key, {"at": {}, "over": {}, "reduce": None})
    mine = ROUTES[(cid, key)](q, params())
    if (cid, key) in RESIDUAL:
        bound = RESIDUAL[(cid, key)]
        assert 0 <= value <= bound, f"{value} is not a residual below {bound}"
        assert 0 <= mine <= bound, f"recomputed, {mine} is not below {bound}"
        if min(value, mine) > 1e-15:  # both above rounding noise: of the same size
            assert abs(math.log10(value / mine)) <= 3, (value, mine)
        return
    got = _as_list(value)
    want = _as_list(mine)
    if key == "dimensional_ball":
        got = [value["R"], value["rpm"], value["Omega"]]
    assert len(got) == len(want), (got, want)
    np.testing.assert_allclose(got, want, rtol=RTOL[(cid, key)], atol=ATOL.get((cid, key), 0.0))


def test_the_maps_the_article_calls_onto_u0_send_states_to_zero_slip() -> None:
    from hypothesis import given, settings
    from hypothesis import strategies as st

    from turntable.claims._checks_realization import other_maps

    maps = list(other_maps().values())

    @settings(max_examples=50, deadline=None)
    @given(st.lists(st.floats(-10, 10), min_size=6, max_size=6))
    def check(z: list[float]) -> None:
        for m in maps:
            assert np.abs(slip(m @ np.asarray(z))).max() <= 1e-12 * (1 + np.abs(z).max())

    check()
