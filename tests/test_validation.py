"""Argument checks of every public function, and finite output over the whole range.

Bad input must raise ValueError whose message starts with the argument's
name; good input over mu0 in [1e-12, 1e12] and t up to 1000 must give finite
numbers with no overflow, invalid operation or division by zero.
"""

from __future__ import annotations

import inspect
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest

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
]

BAD: dict[str, list[Any]] = {
    "mu0": [
        pytest.param(0.0, id="zero"),
        pytest.param(-1.0, id="negative"),
        pytest.param(np.nan, id="nan"),
        pytest.param(np.inf, id="inf"),
        pytest.param("abc", id="str"),
        pytest.param(None, id="None"),
    ],
    "z0": [
        pytest.param(np.ones(5), id="len5"),
        pytest.param(np.ones(7), id="len7"),
        pytest.param(np.ones((1, 6)), id="2-D"),
        pytest.param(np.array([1.0, np.nan, 0, 0, 0, 0]), id="nan"),
        pytest.param(np.array([1.0, np.inf, 0, 0, 0, 0]), id="inf"),
        pytest.param("abcdef", id="str"),
    ],
    "t": [
        pytest.param(np.zeros((2, 2)), id="2-D"),
        pytest.param(np.array([0.0, np.nan]), id="nan"),
        pytest.param(np.array([0.0, np.inf]), id="inf"),
        pytest.param(np.array([-1.0, 0.0]), id="negative"),
        pytest.param("abc", id="str"),
    ],
    "z": [
        pytest.param(np.ones(5), id="len5"),
        pytest.param(np.array([1.0, np.nan, 0, 0, 0, 0]), id="nan"),
        pytest.param(np.full((3, 6), np.inf), id="inf"),
        pytest.param("abc", id="str"),
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
                cases.append(
                    pytest.param(
                        func, names, name, bad.values[0], id=f"{func.__name__}-{name}-{bad.id}"
                    )
                )
    return cases


@pytest.mark.parametrize(("func", "names", "name", "bad"), _cases())
def test_validation(func: Callable[..., Any], names: list[str], name: str, bad: Any) -> None:
    """validation: bad input raises ValueError naming the argument."""
    kwargs = {n: GOOD[n] for n in names}
    kwargs[name] = bad
    with pytest.raises(ValueError, match=rf"^{name}\b"):
        func(**kwargs)


@pytest.mark.parametrize("name", ["wz0", "g"])
@pytest.mark.parametrize("bad", [np.nan, np.inf, "abc"])
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
