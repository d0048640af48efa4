"""Argument checks of every public function, and finite output over the whole range.

Every public function of `turntable` and of `turntable.rolling` is checked: bad input
must raise ValueError whose message starts with the argument's name; good input over
mu0 (or delta) in [1e-12, 1e12] and t up to 1000 must give finite numbers with no
overflow, invalid operation or division by zero.
"""

from __future__ import annotations

import inspect
import re
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose

import turntable as tt
from turntable import rolling

Z_GOOD = np.array([1.0, 1.0, 0.3, -0.2, 0.1, 0.5])
T_GOOD = np.linspace(0.0, 1.0, 5)
GOOD: dict[str, Any] = {
    "mu0": 1.0,
    "k": 0.4,
    "z0": Z_GOOD,
    "t": T_GOOD,
    "z": Z_GOOD,
    "delta": 0.3,
    "xyv": Z_GOOD[:4],
    "comparison": "equal_power",
    "t_end": 5.0,
}
#: A good initial state of the rolling model (on its no-slip constraint).
Z_ROLL = rolling.state_on_constraint(Z_GOOD[:4])

PUBLIC: list[Callable[..., Any]] = [
    tt.system_matrix,
    tt.eigenvalues,
    tt.spectrum,
    tt.log_damping_ratio,
    tt.log_growth_per_turn,
    tt.alpha1_peak,
    tt.large_friction_expansion,
    tt.spiral_centre,
    tt.conserved,
    tt.solve,
    tt.modal_terms,
    tt.no_slip_state,
    tt.slip_velocity,
    tt.nonholonomic,
    tt.newton_euler,
    tt.max_time,
    tt.limit_error,
    tt.limit_error_fit,
    tt.small_friction_expansion,
    tt.nonholonomic_period,
]

#: Every public function of turntable.rolling (`test_every_public_function_is_checked`).
PUBLIC_ROLLING: list[Callable[..., Any]] = [
    rolling.system_matrix,
    rolling.spectrum,
    rolling.eigenvalues,
    rolling.growth_rate,
    rolling.log_growth_per_turn,
    rolling.centre_decay_rate,
    rolling.state_on_constraint,
    rolling.modal_terms,
    rolling.solve,
    rolling.spiral_centre,
    rolling.power_rolling,
    rolling.power_slipping,
    rolling.equal_power_delta,
    rolling.own_spin_power_delta,
    rolling.equal_decay_delta,
    rolling.matched_delta,
    rolling.growth_per_turn_ratio,
    rolling.newton_euler,
    rolling.slip_velocity,
]

#: Functions of states (as opposed to an initial state of a trajectory): they accept
#: any array whose last axis has length 6, as `conserved` does.
OF_STATES: list[Callable[..., Any]] = [
    tt.conserved,
    tt.spiral_centre,
    tt.slip_velocity,
    tt.no_slip_state,
    rolling.power_rolling,
    rolling.power_slipping,
]

BAD: dict[str, list[Any]] = {
    "mu0": [
        pytest.param(0.0, id="zero"),
        pytest.param(-1.0, id="negative"),
        pytest.param(np.nan, id="nan"),
        pytest.param(np.inf, id="inf"),
        pytest.param("abc", id="str"),
        pytest.param(None, id="None"),
        pytest.param(1.0 + 0.0j, id="complex"),
        pytest.param(1.0 + 1.0j, id="complex-imag"),
    ],
    "z0": [
        pytest.param(np.ones(5), id="len5"),
        pytest.param(np.ones(7), id="len7"),
        pytest.param(np.ones((1, 6)), id="2-D"),
        pytest.param(np.array([1.0, np.nan, 0, 0, 0, 0]), id="nan"),
        pytest.param(np.array([1.0, np.inf, 0, 0, 0, 0]), id="inf"),
        pytest.param("abcdef", id="str"),
        pytest.param(Z_GOOD + 0.5j, id="complex"),
        pytest.param(Z_GOOD.astype(complex), id="complex-real"),
    ],
    "t": [
        pytest.param(np.zeros((2, 2)), id="2-D"),
        pytest.param(np.array([0.0, np.nan]), id="nan"),
        pytest.param(np.array([0.0, np.inf]), id="inf"),
        pytest.param(np.array([-1.0, 0.0]), id="negative"),
        pytest.param("abc", id="str"),
        pytest.param(T_GOOD + 1j, id="complex"),
        pytest.param([0.0, 1.0 + 0.0j], id="complex-real"),
    ],
    "z": [
        pytest.param(np.ones(5), id="len5"),
        pytest.param(np.array([1.0, np.nan, 0, 0, 0, 0]), id="nan"),
        pytest.param(np.full((3, 6), np.inf), id="inf"),
        pytest.param("abc", id="str"),
        pytest.param(np.ones((3, 6)) * 1j, id="complex"),
    ],
}
BAD["k"] = BAD["mu0"]
BAD["t_end"] = BAD["mu0"]
BAD["delta"] = BAD["mu0"]
BAD["xyv"] = [
    pytest.param(np.ones(3), id="len3"),
    pytest.param(np.ones(6), id="len6"),
    pytest.param(np.array([1.0, np.nan, 0.0, 0.0]), id="nan"),
    pytest.param(np.array([1.0, np.inf, 0.0, 0.0]), id="inf"),
    pytest.param("abcd", id="str"),
    pytest.param(None, id="None"),
    pytest.param(Z_GOOD[:4] + 0.5j, id="complex"),
    pytest.param(Z_GOOD[:4].astype(complex), id="complex-real"),
]
BAD["comparison"] = [
    pytest.param("equal_speed", id="unknown"),
    pytest.param(None, id="None"),
    pytest.param(1.0, id="float"),
]


def _label(func: Callable[..., Any]) -> str:
    """``solve`` for turntable.solve, ``rolling.solve`` for turntable.rolling.solve."""
    return f"rolling.{func.__name__}" if func.__module__ == rolling.__name__ else func.__name__


def _cases() -> list[Any]:
    cases = []
    # dict.fromkeys: rolling.slip_velocity is tt.slip_velocity, checked once
    for func in dict.fromkeys(PUBLIC + PUBLIC_ROLLING):
        names = [
            p.name
            for p in inspect.signature(func).parameters.values()
            if p.kind is p.POSITIONAL_OR_KEYWORD
        ]
        good = {**GOOD, "z0": Z_ROLL} if func.__module__ == rolling.__name__ else GOOD
        for name in names:
            for bad in BAD[name]:
                if func in OF_STATES and bad.id == "2-D":
                    continue  # a batch of states: accepted (test_functions_of_states_...)
                kwargs = {n: good[n] for n in names} | {name: bad.values[0]}
                cases.append(pytest.param(func, kwargs, name, id=f"{_label(func)}-{name}-{bad.id}"))
    return cases


@pytest.mark.parametrize(
    ("module", "listed"),
    [pytest.param(tt, PUBLIC, id="turntable"), pytest.param(rolling, PUBLIC_ROLLING, id="rolling")],
)
def test_every_public_function_is_checked(module: Any, listed: list[Callable[..., Any]]) -> None:
    """validation: the lists above hold every public function of the package and of rolling.

    A public function is one named in ``__all__``; every function a module defines
    without a leading underscore must be named there.
    """
    public = {n for n in module.__all__ if inspect.isfunction(getattr(module, n))}
    assert public == {f.__name__ for f in listed}
    defined = {
        name
        for name, f in inspect.getmembers(module, inspect.isfunction)
        if f.__module__ == module.__name__ and not name.startswith("_")
    }
    assert defined <= public


@pytest.mark.parametrize(("func", "kwargs", "name"), _cases())
def test_validation(func: Callable[..., Any], kwargs: dict[str, Any], name: str) -> None:
    """validation: bad input raises ValueError naming the argument."""
    with pytest.raises(ValueError, match=rf"^{name}\b"):
        func(**kwargs)


@pytest.mark.parametrize("func", [pytest.param(f, id=_label(f)) for f in OF_STATES])
@pytest.mark.parametrize("shape", [(), (1,), (4,), (2, 3)], ids=lambda s: f"batch{s}")
def test_functions_of_states_accept_the_same_shapes(func: Callable[..., Any], shape: tuple) -> None:
    """validation: every function of states takes one state or a batch, row by row."""
    rng = np.random.default_rng(7)
    z = rng.normal(size=(*shape, 6))
    args = tuple(GOOD[n] for n in list(inspect.signature(func).parameters)[1:])
    out = func(z, *args)
    rows = z.reshape(-1, 6)
    expected = np.array([func(row, *args) for row in rows])
    assert out.shape == (*shape, *expected.shape[1:])
    np.testing.assert_array_equal(out.reshape(expected.shape), expected)


@pytest.mark.parametrize("func", [pytest.param(f, id=_label(f)) for f in OF_STATES])
@pytest.mark.parametrize(
    "bad",
    [
        pytest.param(np.ones((2, 5)), id="last-axis-5"),
        pytest.param(np.ones((0, 7)), id="last-axis-7"),
        pytest.param(np.ones(()), id="scalar"),
    ],
)
def test_functions_of_states_refuse_the_same_shapes(func: Callable[..., Any], bad: Any) -> None:
    """validation: every function of states refuses a last axis other than 6."""
    args = tuple(GOOD[n] for n in list(inspect.signature(func).parameters)[1:])
    with pytest.raises(ValueError, match=r"^z0?\b.*shape"):
        func(bad, *args)


@pytest.mark.parametrize(
    ("mu0", "k"),
    [
        pytest.param(0.0793, 0.4, id="mu0=0.0793-k=2/5"),
        pytest.param(1.0, 1.0, id="mu0=1-k=1"),
        pytest.param(1e-6, 0.05, id="mu0=1e-6-k=0.05"),
    ],
)
@pytest.mark.parametrize("func", [tt.solve, tt.modal_terms], ids=lambda f: f.__name__)
def test_overflow_is_refused_with_the_largest_time(
    func: Callable[..., Any], mu0: float, k: float
) -> None:
    """validation: a time where e^(alpha1 t) overflows is refused, naming the largest t.

    The named time is within a few units of ln(DBL_MAX) / alpha1 (written out here from
    the largest double and alpha1 of `spectrum`), the solution there is finite, and
    twice that time is refused before any work (no overflow warning).
    """
    z0 = np.array([1.0, 1.0, 0.0, 0.0, 0.0, 1.0])
    alpha1 = float(tt.spectrum(mu0, k).alpha1)
    bound = np.log(np.finfo(float).max) / alpha1
    assert float(tt.max_time(mu0, k)) == pytest.approx(bound, rel=1e-12)
    with (
        np.errstate(all="raise"),
        pytest.raises(ValueError, match=r"^t must be at most [0-9.e+]+") as info,
    ):
        func(z0, [0.0, 2.0 * bound], mu0, k)
    named = float(re.match(r"^t must be at most ([0-9.e+]+)", str(info.value)).group(1))
    assert 0.9 * bound < named <= bound
    assert float(tt.max_time(mu0, k, z0)) <= named
    with np.errstate(over="raise", invalid="raise", divide="raise", under="ignore"):
        z = np.asarray(func(z0, [0.0, named], mu0, k))
    assert np.all(np.isfinite(z))
    with pytest.raises(ValueError, match=r"^t must be at most"):
        func(z0, [0.0, np.nextafter(named, np.inf) * (1 + 1e-12)], mu0, k)


def test_max_time_broadcasts_without_an_initial_state() -> None:
    """validation: max_time(mu0, k) over a grid is ln(DBL_MAX) / alpha1 elementwise.

    (Less a margin of 1e-10 in the exponent, which keeps exp(alpha1 t) finite when
    alpha1 t is rounded up: a relative 1.4e-13.)
    """
    mu0 = np.array([[1e-3], [1.0], [1e3]])
    k = np.array([0.05, 0.4, 1.0])
    expected = np.log(np.finfo(float).max) / tt.spectrum(mu0, k).alpha1
    np.testing.assert_allclose(tt.max_time(mu0, k), expected, rtol=2e-13)
    assert np.all(tt.max_time(mu0, k) < expected)


@settings(max_examples=300, deadline=None)
@given(
    log10_mu0=st.floats(min_value=-12.0, max_value=12.0),
    log10_k=st.floats(min_value=-6.0, max_value=0.0),
    direction=st.lists(st.floats(min_value=-1.0, max_value=1.0), min_size=6, max_size=6),
    log10_size=st.floats(min_value=-6.0, max_value=6.0),
)
def test_max_time_is_accepted_by_solve_and_modal_terms(
    log10_mu0: float, log10_k: float, direction: list[float], log10_size: float
) -> None:
    """validation: at t = max_time(mu0, k, z0) solve and modal_terms both give finite values,
    and a later time is refused by one of them (the workflow's configuration check relies on
    this bound for every figure that draws the solution).
    """
    mu0, k = 10.0**log10_mu0, 10.0**log10_k
    z0 = np.array(direction) * 10.0**log10_size
    t_max = float(tt.max_time(mu0, k, z0))
    assume(np.isfinite(t_max) and t_max > 0)
    with np.errstate(over="raise", invalid="raise", divide="raise", under="ignore"):
        for func in (tt.solve, tt.modal_terms):
            assert np.all(np.isfinite(np.asarray(func(z0, [0.0, t_max], mu0, k))))
    later = np.nextafter(t_max, np.inf) * (1 + 1e-12)
    refused = 0
    for func in (tt.solve, tt.modal_terms):
        try:
            func(z0, [later], mu0, k)
        except ValueError:
            refused += 1
    assert refused >= 1


#: The two integrators of the 3-D equations, each with an initial state it accepts.
NEWTON_EULER = [
    pytest.param(tt.newton_euler, Z_GOOD, id="newton_euler"),
    pytest.param(rolling.newton_euler, Z_ROLL, id="rolling.newton_euler"),
]

NOT_FINITE = [
    pytest.param(np.nan, id="nan"),
    pytest.param(np.inf, id="inf"),
    pytest.param("abc", id="str"),
    pytest.param(1j, id="complex"),
    pytest.param(1.0 + 0.0j, id="complex-real"),
]


@pytest.mark.parametrize(("func", "z0"), NEWTON_EULER)
@pytest.mark.parametrize("name", ["wz0", "g"])
@pytest.mark.parametrize("bad", NOT_FINITE)
def test_newton_euler_extra_arguments(
    func: Callable[..., Any], z0: np.ndarray, name: str, bad: Any
) -> None:
    """validation: newton_euler rejects a non-finite spin wz0 or gravity g."""
    with pytest.raises(ValueError, match=rf"^{name}\b"):
        func(z0, T_GOOD, 1.0, 0.4, **{name: bad})


@pytest.mark.parametrize(
    ("name", "bad"),
    [
        pytest.param("g", 0.0, id="g=0"),
        pytest.param("g", -9.81, id="g<0"),
        pytest.param("rtol", 0.0, id="rtol=0"),
        pytest.param("rtol", np.nan, id="rtol=nan"),
        pytest.param("atol", -1e-13, id="atol<0"),
        pytest.param("atol", 1j, id="atol=complex"),
    ],
)
def test_rolling_newton_euler_needs_a_ball_pressed_onto_the_plane(name: str, bad: Any) -> None:
    """validation: the rolling integrator needs g > 0 (normal force m g > 0) and tolerances > 0."""
    with pytest.raises(ValueError, match=rf"^{name}\b"):
        rolling.newton_euler(Z_ROLL, T_GOOD, 1.0, 0.4, **{name: bad})


@pytest.mark.parametrize(("func", "z0"), NEWTON_EULER)
def test_newton_euler_times_must_increase(func: Callable[..., Any], z0: np.ndarray) -> None:
    """validation: newton_euler needs increasing output times."""
    with pytest.raises(ValueError, match=r"^t\b"):
        func(z0, [0.0, 2.0, 1.0], 1.0, 0.4)


@pytest.mark.parametrize(
    ("delta", "k"),
    [
        pytest.param(0.05, 0.4, id="delta=0.05-k=2/5"),
        pytest.param(1.0, 1.0, id="delta=1-k=1"),
        pytest.param(1e-6, 0.05, id="delta=1e-6-k=0.05"),
        pytest.param(1e4, 0.4, id="delta=1e4-k=2/5"),
    ],
)
@pytest.mark.parametrize("func", [rolling.solve, rolling.modal_terms], ids=_label)
def test_rolling_overflow_is_refused_with_the_largest_time(
    func: Callable[..., Any], delta: float, k: float
) -> None:
    """validation: rolling refuses a time where e^(sigma_g t) overflows, naming the largest t.

    As for the slipping model: the named time is within a few units of
    ln(DBL_MAX) / sigma_g, the solution there is finite, a later time is refused.
    """
    sigma_g = float(rolling.growth_rate(delta, k))
    bound = np.log(np.finfo(float).max) / sigma_g
    with (
        np.errstate(all="raise"),
        pytest.raises(ValueError, match=r"^t must be at most [0-9.e+]+") as info,
    ):
        func(Z_ROLL, [0.0, 2.0 * bound], delta, k)
    named = float(re.match(r"^t must be at most ([0-9.e+]+)", str(info.value)).group(1))
    assert 0.9 * bound < named <= bound
    with np.errstate(over="raise", invalid="raise", divide="raise", under="ignore"):
        z = np.asarray(func(Z_ROLL, [0.0, named], delta, k))
    assert np.all(np.isfinite(z))
    with pytest.raises(ValueError, match=r"^t must be at most"):
        func(Z_ROLL, [0.0, np.nextafter(named, np.inf) * (1 + 1e-12)], delta, k)


#: The message of a refused time, the same for every solution of the package.
OVERFLOW_MESSAGE = re.compile(
    r"^t must be at most (?P<t_max>\S+), the largest time this solution can represent "
    r"\(for (?P<coefficient>mu0|delta)=\S+, k=\S+, e\^\((?P<rate>alpha1|sigma_g) t\) times the "
    r"size of the solution overflows a double beyond it\); got max\(t\) = (?P<t>\S+)$"
)


@pytest.mark.parametrize(
    ("func", "z0"),
    [
        pytest.param(tt.solve, Z_GOOD, id="solve"),
        pytest.param(tt.modal_terms, Z_GOOD, id="modal_terms"),
        pytest.param(rolling.solve, Z_ROLL, id="rolling.solve"),
        pytest.param(rolling.modal_terms, Z_ROLL, id="rolling.modal_terms"),
        pytest.param(rolling.spiral_centre, Z_ROLL, id="rolling.spiral_centre"),
    ],
)
def test_overflow_messages_have_one_format(func: Callable[..., Any], z0: np.ndarray) -> None:
    """validation: every solution names its largest time in one format, with 17 digits.

    The largest time and the time asked for are printed so that they read back as the
    same doubles (``repr`` precision), whichever model refuses them.
    """
    with pytest.raises(ValueError, match=r"^t\b") as info:
        func(z0, [0.0, 1e6], 1.0, 0.4)
    match = OVERFLOW_MESSAGE.match(str(info.value))
    assert match, str(info.value)
    for key in ("t_max", "t"):
        assert match[key] == f"{float(match[key]):.17g}"
    assert float(match["t"]) == 1e6
    assert float(match["t_max"]) < 1e6


def _centre_only_state(delta: float, k: float) -> np.ndarray:
    """A state on the rolling model's decaying mode alone (no growing part: A_g = 0)."""
    lam_c = complex(rolling.eigenvalues(delta, k)[2])
    return rolling.state_on_constraint([1.0, 0.0, lam_c.real, lam_c.imag])


@pytest.mark.parametrize(
    "z0",
    [
        pytest.param(np.zeros(6), id="at-rest-on-the-axis"),
        pytest.param(_centre_only_state(0.1, 0.4), id="centre-mode-only"),
    ],
)
@pytest.mark.parametrize(
    "func", [rolling.solve, rolling.modal_terms, rolling.spiral_centre], ids=_label
)
def test_rolling_without_a_growing_part_has_no_time_limit(
    func: Callable[..., Any], z0: np.ndarray
) -> None:
    """validation: the overflow check looks at the growing amplitude, not at the time alone.

    From rest on the axis the solution is 0 for ever; on the centre's mode alone it decays
    to 0.  Neither overflows at t = 1e8 (where e^(sigma_g t) would), nor at the largest
    double, and neither is refused.
    """
    t = np.array([0.0, 1.0, 1e8, np.finfo(float).max])
    with np.errstate(over="raise", invalid="raise", divide="raise", under="ignore"):
        out = np.asarray(func(z0, t, 0.1, 0.4))
    assert np.all(np.isfinite(out))
    exact = rolling.solve(z0, t[:2], 0.1, 0.4)
    assert_allclose(rolling.solve(z0, t, 0.1, 0.4)[:2], exact, rtol=0, atol=0)
    assert np.all(rolling.solve(z0, t, 0.1, 0.4)[2:] == 0.0)


MU0_ALL = np.logspace(-12, 12, 25)
K_ALL = [pytest.param(k, id=f"k={k:g}") for k in (0.05, 0.4, 2.0 / 3.0, 1.0)]


@pytest.mark.parametrize("k", K_ALL)
def test_finite_output_everywhere(k: float) -> None:
    """validation: finite output for mu0 in 1e-12..1e12, t up to 1000 (over/invalid/divide raise).

    Underflow (e.g. e^{alpha2 t} -> 0 for the decaying modes) is harmless and
    is not trapped.
    """
    t = np.linspace(0.0, 1000.0, 201)
    z0 = np.array([1.0, 1.0, 0.0, 0.0, 0.0, 1.0])
    with np.errstate(over="raise", invalid="raise", divide="raise"):
        for value in (
            tt.spectrum(MU0_ALL, k),
            tt.eigenvalues(MU0_ALL, k),
            tt.log_damping_ratio(MU0_ALL, k),
            tt.log_growth_per_turn(MU0_ALL, k),
            tt.large_friction_expansion(MU0_ALL, k),
            tt.alpha1_peak(k),
        ):
            assert np.all(np.isfinite(np.asarray(value, dtype=complex)))
        for mu0 in MU0_ALL:
            assert np.all(np.isfinite(tt.system_matrix(mu0, k)))
            assert np.all(np.isfinite(tt.solve(z0, t, mu0, k)))
            assert np.all(np.isfinite(np.asarray(tt.modal_terms(z0, t, mu0, k))))
        assert np.all(np.isfinite(tt.nonholonomic(z0, t, k)))


DELTA_ALL = np.logspace(-12, 12, 25)
MU0_EXTREME = np.logspace(-300, 300, 61)


@pytest.mark.parametrize("k", K_ALL)
def test_rolling_finite_output_everywhere(k: float) -> None:
    """validation: the rolling model is finite for delta in 1e-12..1e12 and t up to 1000,
    and its matched coefficients for mu0 in 1e-300..1e300 (over/invalid/divide raise).
    """
    t = np.linspace(0.0, 1000.0, 201)
    z0 = rolling.state_on_constraint([1.0, 1.0, 0.0, 0.0])
    with np.errstate(over="raise", invalid="raise", divide="raise"):
        for value in (
            rolling.spectrum(DELTA_ALL, k),
            rolling.eigenvalues(DELTA_ALL, k),
            rolling.growth_rate(DELTA_ALL, k),
            rolling.log_growth_per_turn(DELTA_ALL, k),
            rolling.centre_decay_rate(DELTA_ALL, k),
            rolling.growth_per_turn_ratio(DELTA_ALL, k, "equal_coefficient"),
        ):
            assert np.all(np.isfinite(np.asarray(value, dtype=complex)))
        for delta in DELTA_ALL:
            assert np.all(np.isfinite(rolling.system_matrix(delta, k)))
            assert np.all(np.isfinite(rolling.solve(z0, t, delta, k)))
            assert np.all(np.isfinite(np.asarray(rolling.modal_terms(z0, t, delta, k))))
        for matched in (
            rolling.equal_power_delta,
            rolling.own_spin_power_delta,
            rolling.equal_decay_delta,
        ):
            delta = matched(MU0_EXTREME, k)
            assert np.all(np.isfinite(delta)), matched.__name__
            assert np.all(delta > 0), matched.__name__
