"""Hypothesis settings and fixtures shared by the tests.

Independent reference computations (sympy, mpmath, numpy) live in
``tests/reference.py``.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import settings
from numpy.typing import NDArray

from reference import K_PARAMS, MU0_PARAMS

settings.register_profile("turntable", deadline=None, max_examples=60, derandomize=True)
settings.load_profile("turntable")


@pytest.fixture(scope="module", params=K_PARAMS)
def k(request: pytest.FixtureRequest) -> float:
    """Inertia ratios: homogeneous ball, thin shell, and k = 1."""
    return request.param


@pytest.fixture(scope="module", params=MU0_PARAMS)
def mu0(request: pytest.FixtureRequest) -> float:
    """Friction coefficients below, at and above the turntable's rate."""
    return request.param


@pytest.fixture(scope="module")
def z_generic() -> NDArray[np.float64]:
    """A state with every component nonzero and slipping (u != 0)."""
    return np.array([1.0, 1.0, 0.3, -0.2, 0.1, 0.5])


@pytest.fixture(scope="module")
def z_fig4() -> NDArray[np.float64]:
    """The initial state of Fig. 4: x = y = 1, v = 0, wx = 0, wy = 1."""
    return np.array([1.0, 1.0, 0.0, 0.0, 0.0, 1.0])
