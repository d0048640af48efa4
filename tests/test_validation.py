"""Argument checks of every public function, and finite output over the whole range.

Bad input must raise ValueError whose message starts with the argument's
name; good input over mu0 in [1e-12, 1e12] and t up to 1000 must give finite
numbers with no overflow, invalid operation or division by zero.
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

import turntable as tt

Z_GOOD = np.array([1.0, 1.0, 0.3, -0.2, 0.1, 0.5])
T_GOOD = np.linspace(0.0, 1.0, 5)
GOOD: dict[str, Any] = {"mu0": 1.0, "k": 0.4, "z0": Z_GOOD, "t": T_GOOD, "z": Z_GOOD}

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
    tt.small_friction_expansion,
    tt.nonholonomic_period,
]

#: Functions of states (as opposed to an initial state of a trajectory): they accept
#: any array whose last axis has length 6, as `conserved` does.
OF_STATES: list[Callable[..., Any]] = [
    tt.conserved,
    tt.spiral_centre,
    tt.slip_velocity,
    tt.no_slip_state,
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


def _cases() -> list[Any]:
    cases = []
    for func in PUBLIC:
        names = [
            p.name
            for p in inspect.signature(func).parameters.values()
            if p.kind is p.POSITIONAL_OR_KEYWORD
        ]
        for name in names:
            for bad in BAD[name]:
                if func in OF_STATES and bad.id == "2-D":
                    continue  # a batch of states: accepted (test_functions_of_states_...)
                cases.append(
                    pytest.param(
                        func, names, name, bad.values[0], id=f"{func.__name__}-{name}-{bad.id}"
                    )
                )
    return cases


def test_every_public_function_is_checked() -> None:
    """validation: the list above holds every public function of the package."""
    public = {n for n in tt.__all__ if inspect.isfunction(getattr(tt, n))}
    assert public == {f.__name__ for f in PUBLIC}


@pytest.mark.parametrize(("func", "names", "name", "bad"), _cases())
def test_validation(func: Callable[..., Any], names: list[str], name: str, bad: Any) -> None:
    """validation: bad input raises ValueError naming the argument."""
    kwargs = {n: GOOD[n] for n in names}
    kwargs[name] = bad
    with pytest.raises(ValueError, match=rf"^{name}\b"):
        func(**kwargs)


@pytest.mark.parametrize("func", [pytest.param(f, id=f.__name__) for f in OF_STATES])
@pytest.mark.parametrize("shape", [(), (1,), (4,), (2, 3)], ids=lambda s: f"batch{s}")
def test_functions_of_states_accept_the_same_shapes(func: Callable[..., Any], shape: tuple) -> None:
    """validation: every function of states takes one state or a batch, row by row."""
    rng = np.random.default_rng(7)
    z = rng.normal(size=(*shape, 6))
    args = (0.4,) if "k" in inspect.signature(func).parameters else ()
    out = func(z, *args)
    rows = z.reshape(-1, 6)
    expected = np.array([func(row, *args) for row in rows])
    assert out.shape == (*shape, expected.shape[-1])
    np.testing.assert_array_equal(out.reshape(expected.shape), expected)


@pytest.mark.parametrize("func", [pytest.param(f, id=f.__name__) for f in OF_STATES])
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
    args = (0.4,) if "k" in inspect.signature(func).parameters else ()
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


@pytest.mark.parametrize("name", ["wz0", "g"])
@pytest.mark.parametrize("bad", [np.nan, np.inf, "abc", 1j])
def test_newton_euler_extra_arguments(name: str, bad: Any) -> None:
    """validation: newton_euler rejects a non-finite spin wz0 or gravity g."""
    with pytest.raises(ValueError, match=rf"^{name}\b"):
        tt.newton_euler(Z_GOOD, T_GOOD, 1.0, 0.4, **{name: bad})


def test_newton_euler_times_must_increase() -> None:
    """validation: newton_euler needs increasing output times."""
    with pytest.raises(ValueError, match=r"^t\b"):
        tt.newton_euler(Z_GOOD, [0.0, 2.0, 1.0], 1.0, 0.4)


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
