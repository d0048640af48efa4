"""The rolling-resistance comparison model (`turntable.rolling`).

References: eigenvalues and matrix exponential at 50 digits of the 4x4 matrix
read off the constrained 3-D Newton-Euler equations (`turntable.reference.rolling`:
``spectrum``, ``solution``, ``equal_decay_delta``, and ``equal_power_delta`` from a
high-precision eigenvector of L), and a direct numerical integration of
those equations (`rolling.newton_euler`, DOP853).
"""

from __future__ import annotations

import numpy as np
import pytest
from numpy.testing import assert_allclose

import turntable as tt
from turntable import rolling
from turntable.reference import rolling as ref

DELTAS = [1e-8, 1e-5, 1e-2, 0.3, 1.0, 30.0, 1e4]
KS = [
    pytest.param(0.05, id="k=0.05"),
    pytest.param(0.4, id="k=2/5"),
    pytest.param(2 / 3, id="k=2/3"),
    pytest.param(1.0, id="k=1"),
]
Z_ROLL = rolling.state_on_constraint([1.0, 1.0, 0.3, -0.2])


@pytest.mark.parametrize("k", KS)
@pytest.mark.parametrize("delta", DELTAS, ids=lambda d: f"delta={d:g}")
def test_spectrum_matches_50_digit_reference(delta: float, k: float) -> None:
    """Each real and imaginary part to 1e-13 relative, delta in [1e-8, 1e4]."""
    s = rolling.spectrum(delta, k)
    r = ref.spectrum(delta, k)
    for name in ("sigma_g", "nu_g", "sigma_c", "nu_c"):
        assert_allclose(float(getattr(s, name)), getattr(r, name), rtol=1e-13, atol=0, err_msg=name)


def test_eigenvalues_are_those_of_the_system_matrix() -> None:
    ev = rolling.eigenvalues(0.3, 0.4)
    assert_allclose(
        np.sort_complex(ev),
        np.sort_complex(np.linalg.eigvals(rolling.system_matrix(0.3, 0.4))),
        rtol=1e-13,
    )
    assert ev.shape == (4,)
    assert rolling.eigenvalues([0.1, 1.0], 0.4).shape == (2, 4)


@pytest.mark.parametrize("k", KS)
def test_limits(k: float) -> None:
    """Small delta: sigma_g = delta/(k(k+1)), sigma_c = -delta/k, nu_g = k/(k+1).

    Large delta: nu_g -> 1, sigma_g -> 1/delta, sigma_c -> -delta/(k+1).
    """
    d = 1e-7
    s = rolling.spectrum(d, k)
    assert_allclose(s.sigma_g, d / (k * (k + 1)), rtol=1e-5)
    assert_allclose(s.sigma_c, -d / k, rtol=1e-5)
    assert_allclose(s.nu_g, k / (k + 1), rtol=1e-5)
    assert_allclose(rolling.centre_decay_rate(d, k) / rolling.growth_rate(d, k), k + 1, rtol=1e-5)
    assert_allclose(rolling.log_growth_per_turn(d, k), 2 * np.pi * d / k**2, rtol=1e-5)
    big = rolling.spectrum(1e7, k)
    assert_allclose(big.nu_g, 1.0, rtol=1e-6)
    assert_allclose(big.sigma_g * 1e7, 1.0, rtol=1e-5)
    assert_allclose(big.sigma_c, -1e7 / (k + 1), rtol=1e-6)


def test_growth_positive_centre_decays_everywhere() -> None:
    d, k = np.meshgrid(np.logspace(-12, 12, 97), np.linspace(0.01, 1.0, 23))
    s = rolling.spectrum(d, k)
    assert np.all(s.sigma_g > 0)
    assert np.all(s.sigma_c < 0)
    assert np.all(np.isfinite(s.sigma_g))
    assert np.all(np.isfinite(s.nu_c))


@pytest.mark.parametrize("k", KS)
@pytest.mark.parametrize("delta", [1e-8, 1e-2, 1.0, 1e4], ids=lambda d: f"delta={d:g}")
def test_solve_matches_50_digit_matrix_exponential(delta: float, k: float) -> None:
    t = np.array([0.0, 0.5, 3.0, 17.0, 60.0])
    z = rolling.solve(Z_ROLL, t, delta, k)
    zr = ref.solution(Z_ROLL, t, delta, k)
    scale = np.max(np.abs(zr), axis=1, keepdims=True)
    assert np.max(np.abs(z - zr) / scale) < 1e-13


def test_solve_many_times_against_reference() -> None:
    """More than one block of times, the last ones checked against the 50-digit reference."""
    t = np.linspace(0.0, 200.0, 5001)
    z = rolling.solve(Z_ROLL, t, 0.05, 0.4)
    zr = ref.solution(Z_ROLL, t[[0, 2500, 5000]], 0.05, 0.4)
    assert_allclose(z[[0, 2500, 5000]], zr, rtol=1e-12, atol=1e-12 * np.abs(zr).max())


@pytest.mark.parametrize("delta", [0.02, 0.5, 5.0], ids=lambda d: f"delta={d:g}")
def test_solve_matches_constrained_newton_euler(delta: float) -> None:
    t = np.linspace(0.0, 15.0, 31)
    ne = rolling.newton_euler(Z_ROLL, t, delta, 0.4)
    z = rolling.solve(Z_ROLL, t, delta, 0.4)
    assert np.max(np.abs(ne.z - z)) < 1e-9 * np.max(np.abs(z))
    assert_allclose(ne.r[:, 2], 1.0, atol=1e-12)
    assert_allclose(ne.v[:, 2], 0.0, atol=1e-12)
    assert np.max(np.abs(rolling.slip_velocity(ne.z))) < 1e-9


def test_torque_components_do_not_change_the_planar_motion() -> None:
    """M = -delta w_h, -delta w or -delta (w - gamma): the same planar z; only wz differs."""
    t = np.linspace(0.0, 10.0, 21)
    delta, k, wz0 = 0.3, 0.4, 0.7
    runs = {
        tq: rolling.newton_euler(Z_ROLL, t, delta, k, torque=tq, wz0=wz0) for tq in rolling.TORQUES
    }
    base = runs["horizontal"].z
    for tq, run in runs.items():
        assert np.max(np.abs(run.z - base)) < 1e-10, tq
    assert_allclose(runs["horizontal"].w[:, 2], wz0, atol=1e-12)
    assert_allclose(runs["full"].w[:, 2], wz0 * np.exp(-delta * t / k), atol=1e-10)
    assert_allclose(
        runs["relative"].w[:, 2], 1.0 + (wz0 - 1.0) * np.exp(-delta * t / k), atol=1e-10
    )


def test_modes_sum_and_centre_moves_to_axis() -> None:
    delta, k = 0.05, 0.4
    t = np.linspace(0.0, 80.0, 9)
    spiral, centre = rolling.modal_terms(Z_ROLL, t, delta, k)
    assert_allclose(spiral + centre, rolling.solve(Z_ROLL, t, delta, k), atol=1e-14)
    s = rolling.spectrum(delta, k)
    rc = np.hypot(*rolling.spiral_centre(Z_ROLL, t, delta, k).T)
    assert_allclose(rc, rc[0] * np.exp(s.sigma_c * t), rtol=1e-12)
    rad = np.hypot(spiral[:, 0], spiral[:, 1])
    assert_allclose(rad, rad[0] * np.exp(s.sigma_g * t), rtol=1e-12)
    # each mode is a solution of the linear system on its own
    from scipy.linalg import expm

    m = rolling.system_matrix(delta, k)
    for part in (spiral, centre):
        assert_allclose(part[-1, :4], expm(m * t[-1]) @ part[0, :4], atol=1e-12)


def test_slip_is_rejected_with_a_message_naming_it() -> None:
    with pytest.raises(ValueError, match="slip"):
        rolling.solve([1.0, 1.0, 0.0, 0.0, 0.0, 1.0], [0.0, 1.0], 0.1, 0.4)
    with pytest.raises(ValueError, match="slip"):
        rolling.newton_euler([1.0, 1.0, 0.0, 0.0, 0.0, 1.0], [0.0, 1.0], 0.1, 0.4)


@pytest.mark.parametrize(
    ("args", "name"),
    [
        pytest.param((Z_ROLL, [0.0, 1.0], 0.0, 0.4), "delta", id="delta=0"),
        pytest.param((Z_ROLL, [0.0, 1.0], np.nan, 0.4), "delta", id="delta=nan"),
        pytest.param((Z_ROLL, [0.0, 1.0], 0.1, -1.0), "k", id="k<0"),
        pytest.param((Z_ROLL, [0.0, -1.0], 0.1, 0.4), "t", id="t<0"),
        pytest.param((Z_ROLL[:5], [0.0, 1.0], 0.1, 0.4), "z0", id="short-state"),
        pytest.param((Z_ROLL, [0.0, 1e6], 1.0, 0.4), "t", id="overflow"),
    ],
)
def test_bad_input(args: tuple, name: str) -> None:
    with pytest.raises(ValueError, match=rf"^{name}\b"):
        rolling.solve(*args)


def test_overflow_message_names_largest_time() -> None:
    """In the package's format (`turntable.solve`): the largest t, with 17 digits."""
    with pytest.raises(ValueError, match=r"^t must be at most (\S+), the largest time") as info:
        rolling.solve(Z_ROLL, [0.0, 1e6], 1.0, 0.4)
    named = str(info.value).split()[5].rstrip(",")  # "t must be at most <t_max>, ..."
    assert named == f"{float(named):.17g}"
    assert float(named) < 1e6
    assert str(info.value).endswith("got max(t) = 1000000")


def test_zero_state_is_zero_for_ever() -> None:
    """At rest on the axis: z = 0 at every t, however large (no overflow error)."""
    z = rolling.solve(np.zeros(6), [0.0, 1e8], 0.1, 0.4)
    assert np.all(z == 0.0)
    assert z.shape == (2, 6)


def _slipping_spiral(mu0: float, k: float, turns: float = 1.0) -> np.ndarray:
    """The slipping motion on its growing mode about the axis, from tt.solve."""
    lam = complex(tt.eigenvalues(mu0, k)[0])
    rho, v = 1.0 + 0j, lam
    w = -1j * lam * rho / k  # c = v - i k w = 0 on a mode with lambda != 0
    z0 = np.array([rho.real, rho.imag, v.real, v.imag, w.real, w.imag])
    t = np.linspace(0.0, turns * 2 * np.pi / lam.imag, 65)
    z = tt.solve(z0, t, mu0, k)
    # z0 is on the growing mode: the slipping motion from it is e^{lambda t} z0
    assert_allclose(np.hypot(z[:, 0], z[:, 1]), np.exp(lam.real * t), rtol=1e-10)
    return z


@pytest.mark.parametrize("mu0", [1e-3, 0.1, 1.0, 10.0, 1e4], ids=lambda m: f"mu0={m:g}")
def test_equal_power_delta_on_the_same_path(mu0: float) -> None:
    """Comparison (b): the same path of the centre, each ball with its own kinematics.

    The slipping ball dissipates mu0 |u|^2 with its own slip; a ball rolling along the same
    path spins with w = r + i v (the no-slip constraint) and dissipates delta |w|^2."""
    k = 0.4
    z = _slipping_spiral(mu0, k)
    rolling_on_path = rolling.state_on_constraint(z[:, :4])
    assert_allclose(rolling.slip_velocity(rolling_on_path), 0.0, atol=1e-12)
    slipping = np.mean(rolling.power_slipping(z, mu0))
    ratio = slipping / np.mean(rolling.power_rolling(rolling_on_path, 1.0))
    assert_allclose(rolling.equal_power_delta(mu0, k), ratio, rtol=1e-8)
    # Charging the torque on the slipping ball's own spin is the other matching.
    own = slipping / np.mean(rolling.power_rolling(z, 1.0))
    assert_allclose(rolling.own_spin_power_delta(mu0, k), own, rtol=1e-8)


@pytest.mark.parametrize("k", KS)
@pytest.mark.parametrize(
    "mu0", [1e-12, 1e-6, 1e-3, 0.1, 1.0, 10.0, 1e3, 1e6, 1e12], ids=lambda m: f"mu0={m:g}"
)
def test_equal_power_delta_matches_the_eigenvector_reference(mu0: float, k: float) -> None:
    """Against mu0 |u|^2 / |w_roll|^2 on a high-precision eigenvector of L, to 1e-13 relative
    for mu0 in [1e-12, 1e12] (no cancellation in the package's evaluation)."""
    assert_allclose(rolling.equal_power_delta(mu0, k), ref.equal_power_delta(mu0, k), rtol=1e-13)


def test_equal_power_delta_large_friction_asymptote() -> None:
    k = 0.4
    assert_allclose(rolling.equal_power_delta(1e8, k) * 1e8, k**4 / (k + 1) ** 2, rtol=1e-7)
    assert_allclose(rolling.own_spin_power_delta(1e8, k) * 1e8, k**4 / (k + 1) ** 2, rtol=1e-7)


@pytest.mark.parametrize("mu0", [1e-100, 1e-20, 1e-4, 0.1, 1.0, 100.0], ids=lambda m: f"mu0={m:g}")
def test_equal_decay_delta(mu0: float) -> None:
    k = 0.4
    d = float(rolling.equal_decay_delta(mu0, k))
    assert_allclose(rolling.centre_decay_rate(d, k), -tt.spectrum(mu0, k).alpha2, rtol=1e-14)
    assert_allclose(d, ref.equal_decay_delta(mu0, k), rtol=1e-13)


def test_powers() -> None:
    z = np.array([[0.0, 0.0, 1.0, 0.0, 0.0, 2.0]])
    assert_allclose(rolling.power_rolling(z, 0.5), [2.0])
    assert_allclose(rolling.power_slipping(z, 0.5), [0.5 * ((1.0 - 2.0) ** 2)])
    assert_allclose(rolling.slip_velocity(Z_ROLL), [0.0, 0.0], atol=1e-16)


@pytest.mark.parametrize("k", KS)
@pytest.mark.parametrize(
    ("comparison", "limit"),
    [
        pytest.param("equal_coefficient", lambda k: k**2 / (k + 1) ** 2, id="a"),
        pytest.param("equal_power", lambda k: 1.0, id="b"),
        pytest.param("equal_decay", lambda k: k, id="c"),
    ],
)
def test_growth_ratio_large_coefficient_limits(comparison: str, limit, k: float) -> None:
    """Slipping over rolling growth per turn for mu0 -> infinity: k^2/(k+1)^2, 1, k."""
    ratio = rolling.growth_per_turn_ratio(1e8, k, comparison)
    assert_allclose(ratio, limit(k), rtol=1e-6)


def test_equal_power_delta_small_friction_limit() -> None:
    """As mu0 -> 0, lambda_+ ~ sqrt(i mu0): u ~ -i r and w_roll ~ r, so delta_P / mu0 -> 1;
    the slipping spin -i lambda_+ r / k vanishes, so the own-spin matching tends to k^2."""
    for k in (0.05, 0.4, 1.0):
        assert_allclose(rolling.equal_power_delta(1e-12, k) / 1e-12, 1.0, rtol=5e-5)
        assert_allclose(rolling.own_spin_power_delta(1e-12, k), k**2, rtol=5e-5)


@pytest.mark.parametrize("k", KS)
@pytest.mark.parametrize("mu0", [1e-100, 1e-200, 1e-300], ids=lambda m: f"mu0={m:g}")
def test_matched_deltas_at_very_small_friction(mu0: float, k: float) -> None:
    """Far below 1e-12 the matched coefficients are their leading terms to rounding.

    delta_P = mu0 (1 + O(sqrt(mu0) / k)), delta_S = k^2 (1 + O(sqrt(mu0) / k)) and
    delta_c = k sqrt(mu0 / 2) (1 + O(sqrt(mu0) / k)) (|sigma_c| = delta / k (1 - O(delta)),
    |alpha2| = sqrt(mu0 / 2) + O(mu0 / k)): at mu0 <= 1e-100 the corrections are below
    1e-48, so each must equal its leading term to
    a few units in the last place (no overflow to inf, no failed bracket).
    """
    with np.errstate(over="raise", invalid="raise", divide="raise"):
        power = rolling.equal_power_delta(mu0, k)
        own = rolling.own_spin_power_delta(mu0, k)
        decay = rolling.equal_decay_delta(mu0, k)
    assert_allclose(power, mu0, rtol=1e-14)
    assert_allclose(own, k**2, rtol=1e-14)
    assert_allclose(decay, k * np.sqrt(mu0 / 2.0), rtol=1e-14)


@pytest.mark.parametrize("k", KS)
def test_equal_power_delta_at_very_large_friction(k: float) -> None:
    """delta_P and delta_S = k^4 / (mu0 (k + 1)^2) (1 + O(1 / mu0)), here to rounding."""
    for mu0 in (1e100, 1e300):
        for fn in (rolling.equal_power_delta, rolling.own_spin_power_delta):
            assert_allclose(fn(mu0, k) * mu0, k**4 / (k + 1) ** 2, rtol=1e-14)


def test_matched_delta() -> None:
    assert_allclose(rolling.matched_delta([0.1, 2.0], 0.4, "equal_coefficient"), [0.1, 2.0])
    assert_allclose(
        rolling.matched_delta(2.0, 0.4, "equal_power"), rolling.equal_power_delta(2.0, 0.4)
    )
    with pytest.raises(ValueError, match="comparison"):
        rolling.matched_delta(1.0, 0.4, "equal_speed")


def test_one_slip_velocity_and_states_in_batches() -> None:
    """The rolling model uses the package's slip velocity (one definition of u), and builds
    states on the constraint for a batch as for one."""
    assert rolling.slip_velocity is tt.slip_velocity
    xyv = np.array([[1.0, 1.0, 0.3, -0.2], [0.5, -2.0, 0.0, 1.0]])
    batch = rolling.state_on_constraint(xyv[None])
    assert batch.shape == (1, 2, 6)
    for i in range(2):
        assert_allclose(batch[0, i], rolling.state_on_constraint(xyv[i]))
    assert_allclose(rolling.slip_velocity(batch), 0.0, atol=1e-15)
    with pytest.raises(ValueError, match="xyv"):
        rolling.state_on_constraint([1.0, 2.0, 3.0])
    with pytest.raises(ValueError, match="xyv"):
        rolling.state_on_constraint(1.0)
